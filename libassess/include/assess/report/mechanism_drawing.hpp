// mechanism_drawing.hpp: an SVG drawing of a kinematic chain (report layer;
// draws what the chain and its analysis hold, computes nothing).
#pragma once

#include "assess/kinematic/chain.hpp"
#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/report/messages.hpp"

#include <string>

namespace assess {

/// The section of the wall in the x-z plane (x outward, z up, to scale):
/// every block (shaded), hinges (circles, labelled with their z), sliders,
/// carried weights, thrusts, ties and friction as arrows labelled with their
/// value in kN, the self weight of each block (arrow at its centroid; one
/// label with the total when there are more than 6 blocks), the control point
/// of the analysis, the foundation level z = 0, the floor levels (levels of
/// the carried weights) and the hinge level, and the direction of the seismic
/// action. Labels in `lang`.
/// @param r the analysis of this chain (control point); may be a default
///          result (no control point drawn when r.control_block < 0)
std::string mechanism_svg(const Chain& chain, const KinematicResult& r, Lang lang);

}  // namespace assess

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
/// carried weights Q, thrusts S, ties T (drawn as the push of the anchor plate
/// on the outer face, on the tie's line of action) and friction F as arrows
/// with their value in kN, the self weight P of each block (arrow at its
/// centroid; one arrow at the resultant, labelled with the total, when there
/// are more than 6 blocks), the control point of the analysis, the foundation
/// level z = 0, the floor levels (levels of the carried weights), the hinge
/// level and the direction of the seismic action; a legend (dimensions in m,
/// the load symbols). Labels in `lang`.
///
/// Dimension lines (quote), architectural style (thin lines, 45-degree ticks,
/// values in m with 2 decimals, outside the blocks, never crossing them):
///  - on the outer side, in columns: the chain of levels (foundation, base
///    and top of the blocks, hinges, loads, steps of the thickness), the
///    foundation-to-hinge distance when the chain does not show it as one
///    segment, the overall height;
///  - above the wall (or below it, whichever needs the shorter extension
///    lines without crossing a block): the thickness of every band of
///    constant section (each distinct value once), the width of a block that
///    is not a stack of such bands (a wedge), and the distance of each
///    carried weight from the inner face of the wall under it; a distance
///    that cannot be dimensioned outside the wall (a floor under the storey
///    above) is written by its load ("d = 0.20 m", explained in the legend).
/// Each value is a <text class="dim" data-kind="K">, K = level (bottom to
/// top, in document order), hinge, total, thickness, width, offset or
/// offset-note.
///
/// Labels are placed last by a deterministic greedy placer: no two label
/// boxes overlap (box estimate: 0.6 em per character, 0.95 em above the
/// baseline to 0.25 em below, by text-anchor), labels avoid lines, symbols
/// and block outlines where they can, a label moved away from its anchor has
/// a leader line, and the viewBox is the extent of everything drawn (at
/// least 640 px wide). Test: unit/mechanism_drawing.
/// @param r the analysis of this chain (control point); may be a default
///          result (no control point drawn when r.control_block < 0)
std::string mechanism_svg(const Chain& chain, const KinematicResult& r, Lang lang);

}  // namespace assess

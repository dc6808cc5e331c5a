// mechanism_catalogue.hpp: generators of kinematic chains for the classic
// out-of-plane mechanisms of masonry walls (simple overturning, vertical
// flexure, composite overturning with a side-wall wedge, gable overturning,
// corner overturning), from a few parameters. See docs/catalogue.md for the
// sketches.
//
// Geometry of every generator: the wall's OUTER face is the plane x = 0, the
// wall lies at x < 0 (x positive outward), z is the height above the
// foundation (m). Inputs are SI: m, N, N/m^3.
#pragma once

#include "assess/kinematic/chain.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// One generated mechanism. `Z` is the height above the foundation of the
/// centroid of the constraints that tie the moving blocks to the rest of the
/// building (C8A.4.9-10: psi(Z) = Z/H); 0 for a ground-level mechanism.
struct MechanismCandidate {
  std::string label;      ///< e.g. "hinge at z = 3.50 m"
  Chain chain;
  double Z = 0.0;         ///< m
  double parameter = 0.0; ///< the searched quantity (hinge z in m, wedge angle in deg ...)
};

/// The candidates of one catalogue entry. When a parameter (hinge level, hinge
/// height, wedge angle) was not given, every value tried is a candidate; the
/// governing one is chosen by the assessment (largest D/C over its checks,
/// run_kinematic_case); governing_candidate gives the smallest alpha0.
struct MechanismSet {
  std::string type;             ///< "simple_overturning", ...
  std::string parameter_name;   ///< "hinge z (m)", "wedge angle (deg)" ...
  bool searched = false;        ///< the parameter was searched
  std::vector<MechanismCandidate> candidates;
};

/// alpha0 of a chain in its undeformed configuration [C8A.4.1]/[C8.7.1.1].
double activation_multiplier(const Chain& chain);
/// Index of the candidate with the smallest alpha0 (ties: the first).
std::size_t governing_candidate(const MechanismSet& set);

/// One storey of a façade (bottom to top).
struct Storey {
  double height = 0.0;      ///< storey height (m), > 0
  double thickness = 0.0;   ///< wall thickness (m), > 0; the outer faces are aligned
  /// Floor (or roof) at the TOP of the storey: weight carried by the wall (N),
  /// its horizontal distance from the wall's inner face (m, 0..thickness),
  /// whether it bears on the wall (false: only its mass pushes, C8A.4.1 "m"),
  /// outward horizontal thrust (N) and the force of a tie at that level (N).
  double floor_weight = 0.0;
  double floor_distance_from_inner_face = 0.0;
  bool floor_bears = true;
  double thrust = 0.0;
  double tie = 0.0;
};

/// Simple overturning of a façade of one or more storeys about a horizontal
/// hinge at the outer edge of the wall at the base of storey `hinge_level`.
struct SimpleOverturningParams {
  std::vector<Storey> storeys;   ///< bottom to top, >= 1
  double unit_weight = 0.0;      ///< N/m^3
  double length = 1.0;           ///< façade width (out-of-plane) (m)
  std::optional<int> hinge_level;  ///< 0 = ground; none: every level is a candidate
  double hinge_setback = 0.0;    ///< hinge set back from the outer edge (m), >= 0
};
MechanismSet simple_overturning(const SimpleOverturningParams& p);

/// Vertical flexure of a wall restrained horizontally at the bottom and top
/// (floors): two blocks, hinge at the outer edge of the base, hinge at the
/// inner edge at height `hinge_height` above the base, outer top edge sliding
/// vertically.
struct VerticalFlexureParams {
  double height = 0.0;        ///< between the restraints (m)
  double thickness = 0.0;     ///< m
  double unit_weight = 0.0;   ///< N/m^3
  double length = 1.0;        ///< m
  double base_z = 0.0;        ///< height of the bottom restraint above the foundation (m)
  double top_load = 0.0;      ///< vertical load on the top of the wall (N), e.g. upper storeys
  double top_load_distance_from_inner_face = 0.0;  ///< m, 0..thickness
  /// Hinge height above the base (m), 0 < h < height; none: searched.
  std::optional<double> hinge_height;
  int search_points = 19;     ///< grid of the search (then refined by golden section)
};
MechanismSet vertical_flexure(const VerticalFlexureParams& p);

/// Composite overturning: the façade overturns with a wedge of the side
/// wall(s) bounded by a crack at angle beta from the vertical.
struct CompositeOverturningParams {
  double height = 0.0;          ///< façade height above the hinge (m)
  double thickness = 0.0;       ///< façade thickness (m)
  double length = 0.0;          ///< façade width (m)
  double unit_weight = 0.0;     ///< N/m^3 (façade and side walls)
  double side_thickness = 0.0;  ///< side wall thickness (m)
  int side_walls = 2;           ///< number of side walls dragged (1 or 2)
  double side_length = 0.0;     ///< available length of the side wall (m), bounds the wedge
  double base_z = 0.0;          ///< hinge height above the foundation (m)
  double top_weight = 0.0;      ///< roof/floor weight on the façade top (N) at mid-thickness
  double tie = 0.0;             ///< tie at the top (N)
  /// Wedge angle from the vertical (deg); else from the texture tan(beta) =
  /// (unit_length / 2) / course_height; else searched on a grid in
  /// [beta_min_deg, beta_max_deg].
  std::optional<double> beta_deg;
  std::optional<double> unit_length;     ///< m
  std::optional<double> course_height;   ///< m
  double beta_min_deg = 10.0, beta_max_deg = 60.0;
  int search_points = 6;
};
MechanismSet composite_overturning(const CompositeOverturningParams& p);

/// Gable (timpano) overturning about a hinge at its base: a triangle of base
/// width `width` and height `height` on the eaves level base_z, modelled as
/// `slices` rigidly joined horizontal slices (their weight matches the
/// triangle's slice by slice).
struct GableParams {
  double width = 0.0;       ///< base width of the gable (m)
  double height = 0.0;      ///< height of the apex above the base (m)
  double thickness = 0.0;   ///< m
  double unit_weight = 0.0; ///< N/m^3
  double base_z = 0.0;      ///< height of the base above the foundation (m)
  double ridge_weight = 0.0;  ///< weight of the ridge beam on the apex (N)
  double ridge_thrust = 0.0;  ///< outward thrust of the ridge beam (N)
  double tie = 0.0;           ///< tie at the apex (N)
  int slices = 24;
};
MechanismSet gable_overturning(const GableParams& p);

/// Corner overturning (ribaltamento del cantonale), symmetric corner: two
/// orthogonal walls of equal thickness, each cracked along a line at angle
/// beta from the vertical that starts at the inner face of the other wall at
/// the hinge level; the wedge rotates about the horizontal axis through the
/// outer corner edge at the hinge level, normal to the corner's bisector, under
/// a horizontal action along the bisector. The chain is the exact planar
/// reduction in the bisector's vertical plane (x = outward distance along the
/// bisector from the hinge axis), docs/theory/kinematic.md §5: a corner pillar
/// (plan t x t) and the two arms (triangles, or trapezoids where the wall ends).
struct CornerOverturningParams {
  double height = 0.0;       ///< wedge height above the hinge (m)
  double thickness = 0.0;    ///< thickness of both walls (m)
  double unit_weight = 0.0;  ///< N/m^3
  /// Length of each wall beyond the other wall's inner face (m): bounds the arm.
  double wall_length = 0.0;
  double base_z = 0.0;       ///< hinge height above the foundation (m)
  /// Weight carried on top of the corner (hip rafter, floor) at the pillar's
  /// centre (N), bearing and seismic.
  double top_weight = 0.0;
  /// Horizontal thrust at the top along the bisector, outward (N) (hip rafter).
  double thrust = 0.0;
  /// Force of EACH of the two tie rods along the walls anchored at the corner
  /// top (N); their resultant along the bisector is sqrt(2) tie, inward.
  double tie = 0.0;
  /// Crack angle from the vertical (deg), as CompositeOverturningParams.
  std::optional<double> beta_deg;
  std::optional<double> unit_length;     ///< m
  std::optional<double> course_height;   ///< m
  double beta_min_deg = 10.0, beta_max_deg = 60.0;
  int search_points = 6;
};
MechanismSet corner_overturning(const CornerOverturningParams& p);

}  // namespace assess

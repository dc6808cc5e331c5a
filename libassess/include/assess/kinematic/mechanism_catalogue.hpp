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
#include "assess/kinematic/roof_thrust.hpp"

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace assess {

/// A quantity of a mechanism's derivation printed in the reports (issue 33):
/// the arch thrust and its limit, the roof's thrust, alpha0 without a term,
/// the friction of the side walls... Report-ready: `value` is in `unit`
/// ("kN", "kN/m", "m", "°", "MPa", "rad" or "-"), converted from SI where
/// the row is made (the edge of the library, as CheckRow's values).
struct MechanismQuantity {
  std::string label;   ///< English; Italian through localise() (report/messages.cpp)
  double value = 0.0;
  std::string unit;
  std::string source;  ///< formula and certainty, e.g. "docs/theory/mechanisms.md (1.2) [D]"
};

/// One generated mechanism. `Z` is the height above the foundation of the
/// centroid of the constraints that tie the moving blocks to the rest of the
/// building (C8A.4.9-10: psi(Z) = Z/H); 0 for a ground-level mechanism.
struct MechanismCandidate {
  MechanismCandidate(std::string label_, Chain chain_, double Z_, double parameter_,
                     std::vector<MechanismQuantity> quantities_ = {})
      : label(std::move(label_)), chain(std::move(chain_)), Z(Z_), parameter(parameter_),
        quantities(std::move(quantities_)) {}
  std::string label;      ///< e.g. "hinge at z = 3.50 m"
  Chain chain;
  double Z = 0.0;         ///< m
  double parameter = 0.0; ///< the searched quantity (hinge z in m, wedge angle in deg ...)
  /// Issue 33: the quantities of this candidate's derivation (reports).
  std::vector<MechanismQuantity> quantities;
  /// Issue 33: a bound on the rotation of a one-body mechanism (rad;
  /// KinematicOptions::rotation_cap), infinity = none, and why it holds
  /// (English). Issues 33, 38: the corner and the composite wedges, whose
  /// rigid chain gives no bound of its own: bearing_part_rotation().
  double rotation_bound = std::numeric_limits<double>::infinity();
  std::string rotation_bound_reason;
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
  /// Issue 33: the mechanism's true geometry for the report's data table,
  /// where the chain's blocks are a reduction (a plan, a projection) whose
  /// bounding boxes are no wall dimension; empty: the blocks are sections.
  std::vector<MechanismQuantity> data;
};

/// alpha0 of a chain in its undeformed configuration [C8A.4.1]/[C8.7.1.1].
double activation_multiplier(const Chain& chain);

/// Issue 38: the displacement bound of a one-body mechanism made of pieces
/// held together by the masonry's interlocking only (the corner's arms on
/// its pier, the side walls' wedges on the façade), which bears on its
/// ground hinge through one part (docs/theory/mechanisms.md §5 [I]): the
/// rotation at which that part's own weight and the weights bearing on it
/// pass over the hinge,
///   tan theta_b = sum W (x_O - x) / sum W (z - z_O)
/// over the part's self weight and its bearing weight loads (Load::vertical;
/// held or moving alike), O the chain's ground hinge. Beyond theta_b the
/// part would have to be held up by its wedges through the interlocking
/// (C8.7.1.2.1: the rigid-block model holds while the masonry does not
/// disintegrate [V-T]). The one place where the bound is computed; the
/// caller sets MechanismCandidate::rotation_bound and its reason.
/// @throws InputError without exactly one ground hinge or with a part that
///   is not a block of the chain
double bearing_part_rotation(const Chain& chain, int part);
/// Index of the candidate with the smallest alpha0 (ties: the first).
std::size_t governing_candidate(const MechanismSet& set);

/// One storey of a façade (bottom to top).
struct Storey {
  double height = 0.0;      ///< storey height (m), > 0
  double thickness = 0.0;   ///< wall thickness (m), > 0; the outer faces are aligned
  /// Floor (or roof) at the TOP of the storey: weight carried by the wall (N),
  /// its horizontal distance from the wall's inner face (m, 0..thickness),
  /// whether it bears on the wall (false: only its mass pushes, C8A.4.1 "m"),
  /// whether its mass is held by the rest of the building (true: it bears
  /// but does not push; issue 38, default false: it moves with the wall,
  /// docs/theory/mechanisms.md §0), outward horizontal thrust (N) and the
  /// force of a tie at that level (N).
  double floor_weight = 0.0;
  double floor_distance_from_inner_face = 0.0;
  bool floor_bears = true;
  bool floor_held = false;
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
  /// Issue 33: a pitched roof on the top of the last storey: its weight and
  /// thrust from its geometry (roof_thrust.hpp), totals over `length`.
  std::optional<RoofSpec> roof;
};
MechanismSet simple_overturning(const SimpleOverturningParams& p);
/// Issue 33: simple overturning of a façade carrying a pitched roof
/// ("spinta della copertura"): as simple_overturning with `roof` required;
/// type "roof_thrust". Each candidate reports V, H and alpha0 with and
/// without the thrust and without the roof (docs/theory/mechanisms.md §3).
MechanismSet roof_thrust_overturning(const SimpleOverturningParams& p);

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
  /// Vertical load on the top of the wall (N), e.g. upper storeys: it bears
  /// on the upper block at the top restraint, which takes its horizontal
  /// force (its point does not move horizontally, dx = 0): its mass is the
  /// building's, not the mechanism's (issue 38; docs/theory/mechanisms.md §0).
  double top_load = 0.0;
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
  /// Issue 38: its mass held by the rest of the building (bears, does not
  /// push); default false: it moves with the façade.
  bool top_weight_held = false;
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
  /// Issue 38: its mass held by the rest of the building (bears, does not
  /// push); default false: it moves with the gable.
  bool ridge_weight_held = false;
  double ridge_thrust = 0.0;  ///< outward thrust of the ridge beam (N)
  double tie = 0.0;           ///< tie at the apex (N)
  int slices = 24;
};
MechanismSet gable_overturning(const GableParams& p);

/// An opening in a wall of the corner (issue 33), in the wall's own
/// coordinates: `from`..`to` along the wall from the corner's outer face (m),
/// `bottom`..`top` above the foundation (m). It must lie beyond the corner
/// pier (from >= the other wall's thickness).
struct CornerOpening {
  double from = 0.0, to = 0.0, bottom = 0.0, top = 0.0;
};

/// One wall of the corner (issue 33); an unset value takes the corner's
/// common one (CornerOverturningParams::thickness, wall_length, beta...).
struct CornerWall {
  std::optional<double> thickness;      ///< m
  /// Length available beyond the other wall's inner face (m): bounds the arm.
  std::optional<double> length;
  /// The crack: angle from the vertical (deg), or the texture, or the reach
  /// of the crack at the top of the wedge from the other wall's inner face (m).
  std::optional<double> beta_deg;
  std::optional<double> unit_length, course_height;  ///< m
  std::optional<double> crack_reach;    ///< m
  std::vector<CornerOpening> openings;
};

/// Corner overturning (ribaltamento del cantonale) about a horizontal axis
/// through the outer corner edge at the hinge level (issues 33, 38;
/// docs/theory/mechanisms.md §4, docs/catalogue.md). Wall A runs along x
/// (thickness t_A across it), wall B along y (thickness t_B); the corner pier
/// is t_B x t_A in plan; each wall is cracked along a line at beta from the
/// vertical that starts at the other wall's inner face at the hinge level and
/// reaches min(h tan beta, length) at the top (openings cut out of the arms).
/// The wedge rotates about the horizontal axis at `axis` degrees from wall A
/// (0: the axis along wall A's outer face, the action normal to wall A; 90:
/// along wall B's; 45: the classical reduction, normal to the bisector)
/// under a horizontal action normal to the axis; each candidate is the exact
/// planar reduction on the plane normal to its axis (weights, centroids,
/// height distribution and rotational inertia exact). Issue 38: the wedge
/// stands on its pier's footprint and tips about one of its outer edges, the
/// axes at 0 and 90 deg: alpha0 about an axis through the outer vertex at
/// psi is (a sin psi + b cos psi)/D, never below both ends (§4.2), so those
/// two axes are the candidates unless `axis_deg` fixes one. The
/// displacement capacity is bounded by the corner pier's own overturning
/// (MechanismCandidate::rotation_bound, bearing_part_rotation).
struct CornerOverturningParams {
  double height = 0.0;       ///< wedge height above the hinge (m)
  double thickness = 0.0;    ///< thickness of both walls (m), unless given per wall
  double unit_weight = 0.0;  ///< N/m^3
  /// Length of each wall beyond the other wall's inner face (m): bounds the arm.
  double wall_length = 0.0;
  double base_z = 0.0;       ///< hinge height above the foundation (m)
  /// Weight carried on top of the corner (hip rafter, floor) at the pier's
  /// centre (N), bearing; seismic unless `top_weight_held` (issue 38).
  double top_weight = 0.0;
  bool top_weight_held = false;
  /// Horizontal thrust at the top along the bisector, outward (N) (hip rafter);
  /// its component normal to the axis, cos(axis - 45 deg) of it, acts.
  double thrust = 0.0;
  /// Force of EACH of the two tie rods along the walls anchored at the corner
  /// top (N); the rod along wall A restrains with sin(axis) of it, along B with cos(axis).
  double tie = 0.0;
  /// Crack angle from the vertical (deg), as CompositeOverturningParams (both walls).
  std::optional<double> beta_deg;
  std::optional<double> unit_length;     ///< m
  std::optional<double> course_height;   ///< m
  double beta_min_deg = 10.0, beta_max_deg = 60.0;
  int search_points = 6;
  CornerWall wall_a, wall_b;   ///< issue 33: per-wall values and openings
  /// The rotation axis (deg from wall A, 0..90); none: the two axes along the
  /// walls' outer faces, 0 and 90 deg (issue 38).
  std::optional<double> axis_deg;
};
MechanismSet corner_overturning(const CornerOverturningParams& p);

}  // namespace assess

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
  /// KinematicOptions::rotation_cap), infinity = none, and why it holds (English).
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

/// Corner overturning (ribaltamento del cantonale) about any horizontal axis
/// through the outer corner edge at the hinge level (issue 33; docs/theory/
/// kinematic.md §5, docs/catalogue.md). Wall A runs along x (thickness t_A
/// across it), wall B along y (thickness t_B); the corner pier is t_B x t_A in
/// plan; each wall is cracked along a line at beta from the vertical that
/// starts at the other wall's inner face at the hinge level and reaches
/// min(h tan beta, length) at the top (openings cut out of the arms). The
/// wedge rotates about the horizontal axis at `axis` degrees from wall A
/// (0: the axis along wall A's outer face, the action normal to wall A; 90:
/// along wall B's; 45: the classical reduction, normal to the bisector)
/// under a horizontal action normal to the axis; each candidate is the exact
/// planar reduction on the plane normal to its axis (weights, centroids,
/// height distribution and rotational inertia exact). The axis is scanned
/// on [axis_min_deg, axis_max_deg] (axis_points, then a golden-section
/// refinement of an interior minimum of alpha0) unless given. The
/// displacement capacity is bounded by the corner pier's own overturning
/// (MechanismCandidate::rotation_bound).
struct CornerOverturningParams {
  double height = 0.0;       ///< wedge height above the hinge (m)
  double thickness = 0.0;    ///< thickness of both walls (m), unless given per wall
  double unit_weight = 0.0;  ///< N/m^3
  /// Length of each wall beyond the other wall's inner face (m): bounds the arm.
  double wall_length = 0.0;
  double base_z = 0.0;       ///< hinge height above the foundation (m)
  /// Weight carried on top of the corner (hip rafter, floor) at the pier's
  /// centre (N), bearing and seismic.
  double top_weight = 0.0;
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
  /// Issue 33: the rotation axis (deg from wall A); none: scanned.
  std::optional<double> axis_deg;
  double axis_min_deg = 0.0, axis_max_deg = 90.0;
  int axis_points = 7;
};
MechanismSet corner_overturning(const CornerOverturningParams& p);

}  // namespace assess

// tie.hpp: a tie rod (catena, tirante) holding a mechanism back (issue 23):
// where it acts, the rod, its anchor and the masonry the anchor bears on; and
// the restraint law it puts on a chain: a one-sided (tension-only), elastic-
// perfectly-plastic spring in the elongation of the rod, capped by the
// weakest of its checks (kinematic/tie_checks.hpp). docs/theory/ties.md.
//
// Units: SI (m, N, Pa). The rod's direction is the direction of the pull on
// the wall, from the anchor towards the rod's far end: (-1, 0) (inward,
// horizontal) for the usual tie of an outward mechanism.
#pragma once

#include "assess/kinematic/chain.hpp"

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace assess {

/// How the rod's ends take the nut (issue 29): threaded on the rod itself
/// (the default: the thread's stress area is smaller than the rod's), or an
/// end of larger section, upset (ringrossata: hot-forged to a larger
/// diameter, then threaded) or welded (a threaded bar of larger diameter
/// butt-welded to the rod; the weld taken as full strength [I]).
enum class TieEnds { Threaded, Upset, Welded };
const char* to_string(TieEnds e);  ///< "threaded", "upset", "welded"

/// The rod (tondo, barra).
struct TieRod {
  double diameter = 0.0;   ///< m (0 when the area is given)
  double area = 0.0;       ///< gross area A (m^2), > 0; pi d^2 / 4 when the diameter is given
  std::string grade = "S275";
  double fyk = 275e6;      ///< characteristic yield strength (Pa)
  double ftk = 430e6;      ///< characteristic tensile strength (Pa)
  double eps_uk = 0.0196;  ///< characteristic uniform elongation of the grade (fraction; tie_catalogue, issue 37)
  double gamma_M0 = 1.05;  ///< partial factor (-), NTC 2018 §4.2.4.1.1
  double E = 210e9;        ///< elastic modulus (Pa)
  TieEnds ends = TieEnds::Threaded;
  double thread_diameter = 0.0;  ///< nominal diameter of the end's ISO metric thread (m; 0: only its area given)
  double thread_area = 0.0;      ///< stress area A_res of the end (m^2), > 0
  double nut_width = 0.0;        ///< width across flats of the end's nut (m), > 0 (tie_catalogue::Thread::s)
  /// Corrosion allowance (issue 37): loss of thickness on every face (m), >= 0;
  /// the rod and thread checks use the reduced sections (tie_catalogue::corrosion_loss).
  double corrosion = 0.0;
  /// Gross and thread stress areas after the corrosion allowance (m^2).
  double corroded_area() const;
  double corroded_thread_area() const;
};

enum class AnchorType {
  Plate,  ///< capochiave a piastra: a x b plate of thickness t
  Bar,    ///< capochiave a paletto: a bar of length a and diameter b
};

/// The anchor (capochiave).
struct TieAnchor {
  AnchorType type = AnchorType::Plate;
  double a = 0.0;      ///< Plate: side along the wall (m); Bar: length, laid horizontally along the wall (m)
  double b = 0.0;      ///< Plate: vertical side (m); Bar: diameter (m)
  double t = 0.0;      ///< Plate: thickness (m); unused for a bar
  std::string grade = "S275";
  double fyk = 275e6;  ///< Pa
  /// Its footprint on the wall's outer face (m): width along the wall and
  /// height (issue 37: the punched wedge spreads from its edges).
  double width() const { return a; }
  double height() const { return b; }
};

/// The masonry behind the anchor.
struct TieMasonry {
  double fm = 0.0;         ///< mean compressive strength (Pa), > 0 (Circ. 2019 Tab. C8.5.I)
  double tau = 0.0;        ///< shear strength of the punched wedge (Pa), > 0 (tau0 of Tab. C8.5.I)
  double thickness = 0.0;  ///< depth of the punched wedge: the wall's thickness at the anchor (m), > 0
  double FC = 1.35;        ///< confidence factor (-), >= 1
  double gamma_M = 2.0;    ///< partial factor (-), >= 1 (tie_catalogue::masonry_gamma_M)
  /// Issue 37: the sliding of the masonry above the anchor on the bed joint at
  /// its lower edge: cohesion f_v0 (Pa; 0: tau), friction coefficient mu (-),
  /// and the unit weight of the masonry (N/m^3) that makes its overburden.
  double fv0 = 0.0;
  double mu = 0.4;
  double unit_weight = 18e3;
};

/// An opening of the wall (window, door, niche through the wall) in its
/// elevation (issue 37): x along the wall from its first end, z as the
/// mechanism's (m). The punched wedges are cut by it.
struct WallOpening {
  double x0 = 0.0, x1 = 0.0, z0 = 0.0, z1 = 0.0;
};

/// The layout of a tie level along its wall (issue 29): `count` ties on a
/// wall of length `wall_length`, the first and last at `edge_distance` from
/// the wall's ends, the others evenly spaced between them.
struct TieLayout {
  double wall_length = 0.0;    ///< m, > 0
  int count = 1;               ///< ties on the wall, >= 1
  double edge_distance = 0.0;  ///< m, > 0 (default wall_length / (2 count))
  /// Issue 37: the wall around the anchors, in its elevation: the z of its
  /// crown above them (m; infinity: none, the wall goes on up), its base (m),
  /// the vertical load on the crown (N per metre of wall, >= 0: the overburden
  /// of the sliding check with the masonry above the anchor), its openings.
  double crown = std::numeric_limits<double>::infinity();
  double base = 0.0;
  double crown_load = 0.0;
  std::vector<WallOpening> openings;
  /// Centre-to-centre distance of adjacent ties (m); wall_length for one tie.
  double centre_spacing() const;
  /// Position of tie j (0 .. count - 1) along the wall (m).
  double position(int j) const;
};

/// One tie level of the mechanism: identical ties laid along the wall.
struct Tie {
  std::string name;
  bool existing = false;               ///< part of the building as it is (stato di fatto), not the intervention
  int block = -1;                      ///< block of the chain it holds; -1: the moving block containing `point`
  Eigen::Vector2d point{0.0, 0.0};     ///< anchor point (x, z) (m)
  Eigen::Vector2d direction{-1.0, 0.0};  ///< direction of the pull on the wall (unit after validation)
  TieRod rod;
  double free_length = 0.0;            ///< free length of the rod L (m), > 0: stiffness E A / L
  TieAnchor anchor;
  TieMasonry masonry;
  TieLayout layout;                    ///< how many ties, where
  double spacing = 1.0;                ///< tributary length of each tie: wall_length / count (m), > 0
  double pretension = 0.0;             ///< pretension of each tie (N), >= 0, below the tie's strength
  /// Issue 37: the uniform temperature variation the rod, restrained by the
  /// walls at its ends, undergoes (K, >= 0; tie_catalogue::delta_T).
  double delta_T = 15.0;
  /// Throws InputError naming the field (its unit and the expected range),
  /// and for an anchor that does not lie within the wall (above its crown,
  /// beyond its ends, over an opening, overlapping its neighbour).
  void validate() const;
};

/// The restraint law a tie level puts on a chain (the whole level: every tie
/// the chain's out-of-plane length holds, count = length / spacing).
struct TieRestraint {
  std::string name;
  int block = -1;
  Eigen::Vector2d point{0.0, 0.0};       ///< m
  Eigen::Vector2d direction{-1.0, 0.0};  ///< unit, pull on the wall
  double count = 1.0;                    ///< ties on the chain (-)
  double stiffness = 0.0;                ///< k = count E A / L (N/m); 0: rigid-plastic
  double capacity = 0.0;                 ///< T_Rd of the level (N) = count x the weakest check
  double pretension = 0.0;               ///< N, level
  /// Issue 29: a ductile tie yields at `capacity` (the rod governs with the
  /// hierarchy of strengths) and breaks when its elongation reaches
  /// `ultimate_elongation`; a tie that is not ductile breaks when its force
  /// reaches `capacity` (its weakest component, `governing`).
  bool ductile = true;                   ///< default: the elastic-perfectly-plastic restraint of issue 23
  double ultimate_elongation = std::numeric_limits<double>::infinity();  ///< m (ductile)
  std::string governing;                 ///< component of the capacity ("rod", "thread", "bearing", ...)
  /// Elongation (m) at which the level reaches its strength: (capacity - pretension) / k.
  double yield_elongation() const;
  /// Elongation (m) at which the level fails: ultimate_elongation (ductile), yield_elongation() otherwise.
  double failure_elongation() const;
};

/// Force of the level (N, >= 0) at elongation `e` (m): one-sided elastic-
/// perfectly-plastic, min(max(P0 + k e, 0), T_Rd); rigid-plastic (k = 0):
/// T_Rd when e > 0, min(P0, T_Rd) otherwise.
double tie_force(const TieRestraint& r, double elongation);

/// Elongation of the rod (m) in configuration q: the anchor point's
/// displacement along the rod, away from its far end: -direction . (p(q) - p0).
double tie_elongation(const Chain& chain, const TieRestraint& r, const Eigen::VectorXd& q);

/// The block of `chain` a tie at `point` holds: `block` if >= 0 (checked),
/// else the block containing the point that moves most in the mechanism; -1
/// when no block contains it or it does not move (a tie below the hinge).
int tie_block(const Chain& chain, int block, const Eigen::Vector2d& point);

}  // namespace assess

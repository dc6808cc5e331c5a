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

#include <string>
#include <vector>

namespace assess {

/// The rod (tondo, barra).
struct TieRod {
  double diameter = 0.0;   ///< m (0 when the area is given)
  double area = 0.0;       ///< gross area A (m^2), > 0; pi d^2 / 4 when the diameter is given
  std::string grade = "S275";
  double fyk = 275e6;      ///< characteristic yield strength (Pa)
  double gamma_M0 = 1.05;  ///< partial factor (-), NTC 2018 §4.2.4.1.1
  double E = 210e9;        ///< elastic modulus (Pa)
};

enum class AnchorType {
  Plate,  ///< capochiave a piastra: a x b plate of thickness t
  Bar,    ///< capochiave a paletto: a bar of length a and diameter b
};

/// The anchor (capochiave).
struct TieAnchor {
  AnchorType type = AnchorType::Plate;
  double a = 0.0;      ///< Plate: side along the wall (m); Bar: length (m)
  double b = 0.0;      ///< Plate: other side (m); Bar: diameter (m)
  double t = 0.0;      ///< Plate: thickness (m); unused for a bar
  std::string grade = "S275";
  double fyk = 275e6;  ///< Pa
};

/// The masonry behind the anchor.
struct TieMasonry {
  double fm = 0.0;         ///< mean compressive strength (Pa), > 0 (Circ. 2019 Tab. C8.5.I)
  double tau = 0.0;        ///< shear strength of the punched wedge (Pa), > 0 (tau0 of Tab. C8.5.I)
  double thickness = 0.0;  ///< depth of the punched wedge: the wall's thickness at the anchor (m), > 0
  double FC = 1.35;        ///< confidence factor (-), >= 1
  double gamma_M = 2.0;    ///< partial factor (-), >= 1 (tie_catalogue::masonry_gamma_M)
};

/// One tie level of the mechanism: identical ties at `spacing` along the wall.
struct Tie {
  std::string name;
  int block = -1;                      ///< block of the chain it holds; -1: the moving block containing `point`
  Eigen::Vector2d point{0.0, 0.0};     ///< anchor point (x, z) (m)
  Eigen::Vector2d direction{-1.0, 0.0};  ///< direction of the pull on the wall (unit after validation)
  TieRod rod;
  double free_length = 0.0;            ///< free length of the rod L (m), > 0: stiffness E A / L
  TieAnchor anchor;
  TieMasonry masonry;
  double spacing = 1.0;                ///< tributary length of each tie along the wall (m), > 0
  double pretension = 0.0;             ///< pretension of each tie (N), >= 0
  /// Throws InputError naming the field (its unit and the expected range).
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
  /// Elongation (m) at which the rod yields: (capacity - pretension) / k.
  double yield_elongation() const;
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

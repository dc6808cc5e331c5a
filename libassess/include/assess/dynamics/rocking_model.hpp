// rocking_model.hpp: the physics of a rocking wall (rigid Housner block or
// smooth block on a no-tension Winkler foundation), knowing nothing of the
// integrator.
//
// Sign convention: theta (rotation) and the ground acceleration ug'' are
// positive outward, so a negative ug'' drives theta positive (seed paper
// Eq. 1: right-hand side -(W/g) ug'' R cos(alpha sgn(theta) - theta)).
// theta > 0 is rotation about the outer toe, theta < 0 about the inner toe.
#pragma once

#include "assess/dynamics/rocking_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace assess {

/// The base: rigid (Housner) or a no-tension Winkler bed of modulus k.
struct Foundation {
  double k = std::numeric_limits<double>::infinity();  ///< subgrade modulus (N/m^3); inf = rigid

  static Foundation rigid() { return Foundation{}; }
  /// @param k_N_m3 Winkler modulus (N/m^3), > 0 and finite
  static Foundation winkler(double k_N_m3) { return Foundation{k_N_m3}; }
  bool is_rigid() const { return !(k < std::numeric_limits<double>::infinity()); }
};

/// Two-sided rocking (pivot switches at theta = 0) or one-sided (facade
/// against transverse walls: theta >= 0 only, rebound at theta = 0).
enum class Sidedness { two_sided, one_sided };

/// Coefficient of restitution at theta = 0: ratio of the angular velocities
/// after/before the impact (velocity ratio; the energy ratio is e^2).
struct Restitution {
  enum class Kind {
    value,             ///< a given e in [-1, 1] (seed convention: negative = one-sided rebound)
    housner,           ///< two-sided, 1 - 2 m b^2 / I0 (= 1 - 1.5 sin^2 alpha for a rectangle)
    one_sided_theory,  ///< one-sided, 1 - 2 m z_G^2 / I0 (= 1 - 1.5 cos^2 alpha for a rectangle)
    none               ///< no velocity jump (smooth model only)
  };
  Kind kind = Kind::housner;
  double e = 0.0;  ///< the value for Kind::value

  static Restitution given(double e) { return {Kind::value, e}; }
  static Restitution housner() { return {Kind::housner, 0.0}; }
  static Restitution one_sided_theory() { return {Kind::one_sided_theory, 0.0}; }
  static Restitution none() { return {Kind::none, 0.0}; }
};

/// An immutable rocking model: body + foundation + sidedness + restitution.
/// Moments are per unit depth (N m/m), rotations in rad.
class RockingModel {
 public:
  /// @throws InputError for an invalid body, k <= 3 W z_G / (2 b^3) (no
  ///   restoring branch), a restitution outside [-1, 1] or inconsistent with
  ///   the sidedness, `none` on a rigid base, a two-sided body whose centroid
  ///   is off the base centreline, or an external moment above the peak
  ///   restoring moment.
  RockingModel(const RockingBody& body, Foundation foundation, Sidedness sidedness,
               Restitution restitution);

  const RockingBody& body() const { return body_; }
  const Foundation& foundation() const { return foundation_; }
  Sidedness sidedness() const { return sidedness_; }
  Restitution::Kind restitution_kind() const { return restitution_kind_; }
  /// Resolved coefficient e (velocity ratio); 1 when the kind is `none`.
  double restitution() const { return e_; }
  bool has_restitution() const { return restitution_kind_ != Restitution::Kind::none; }

  /// theta_cr = W / (2 b^2 k) (rad): end of full contact (seed Eq. 1); 0 for a rigid base.
  double theta_cr() const { return theta_cr_; }
  /// Ultimate rotation (rad, > 0) on side s = +1 (outward) or -1: where the net
  /// restoring moment s (M(s a) - M_ext) vanishes; alpha for a rigid block
  /// without external moment.
  double theta_u(int side = +1) const { return side >= 0 ? theta_u_[0] : theta_u_[1]; }
  /// Rotation magnitude of the peak net restoring moment on side s (rad).
  double theta_peak(int side = +1) const { return side >= 0 ? theta_pk_[0] : theta_pk_[1]; }
  /// Peak net restoring moment on side s (N m/m).
  double peak_moment(int side = +1) const { return net_side(theta_peak(side), side); }

  /// Restoring moment M(theta) of gravity and foundation about the active toe
  /// (N m/m, seed Eq. 1 left-hand side without inertia), excluding M_ext.
  double restoring_moment(double theta) const;
  /// Same, for an explicit pivot side s and branch (partial = beyond theta_cr):
  /// the form used by the equation of motion (each branch extends smoothly).
  double restoring_moment(double theta, int pivot, bool partial) const;

  /// The moment-rotation curve of the seed's Fig. 2a on side s: `points`
  /// rotations evenly spaced on [0, theta_u] plus theta_cr and theta_peak, sorted
  /// (rad), with the net restoring moment s (M(s theta) - M_ext) (N m/m).
  struct Curve {
    std::vector<double> theta;   ///< rotation magnitude (rad)
    std::vector<double> moment;  ///< net restoring moment (N m/m)
  };
  Curve moment_rotation_curve(std::size_t points = 200, int side = +1) const;

  /// Work of the net restoring moment from 0 to a on side s (J/m):
  /// closed form of the integral of s (M(s x) - M_ext) dx over [0, a].
  double work(double a, int side = +1) const;
  /// Energy capacity C = work(theta_u) on the outward side (J/m), seed §3.2.
  double capacity() const { return work(theta_u(+1), +1); }
  /// Energy demand for a peak rotation magnitude a on side s (J/m), seed §3.2
  /// Fig. 3: the area under the moment-rotation curve up to a (capped at theta_u).
  double energy_demand(double a, int side = +1) const;

  /// Angular acceleration theta'' (rad/s^2) for pivot side s, branch and
  /// ground acceleration ug (m/s^2, positive outward), seed Eq. 1:
  /// I0 theta'' = -M(theta) + M_ext - (W/g) ug R cos(alpha s - theta).
  /// Inline: the integrator evaluates it ~10^5 times per record.
  double angular_acceleration(double theta, int pivot, bool partial, double ug) const;
  /// True if, at rest at theta = 0, the excitation ug drives the body off the
  /// base about pivot s (s theta'' > 0); one-sided: only s = +1.
  bool lifts(int pivot, double ug) const;
  /// At rest at theta = 0 on pivot s: s theta''(0) (rad/s^2) with the static
  /// moment from the geometry (exactly 0 for a centred smooth block at ug = 0,
  /// where angular_acceleration leaves a rounding residue); lifts() is
  /// margin > 0 (one-sided: s = +1 only). The lift-off event function at rest.
  double lift_margin(int pivot, double ug) const;
  /// Post-impact angular velocity at theta = 0 (rad/s): e * omega_minus.
  double impact(double omega_minus) const { return e_ * omega_minus; }

 private:
  double net_side(double a, int side) const;  // s (M(s a) - M_ext), a >= 0
  double dnet_side(double a, int side) const;  // derivative in a

  RockingBody body_;
  Foundation foundation_;
  Sidedness sidedness_;
  Restitution::Kind restitution_kind_;
  double e_ = 1.0;
  double theta_cr_ = 0.0;
  double theta_u_[2] = {0.0, 0.0};
  double theta_pk_[2] = {0.0, 0.0};
  // cached constants
  double WR_ = 0.0, kb3_ = 0.0, c_partial_ = 0.0, cos_a_ = 0.0;
  // the same per unit I0, for angular_acceleration: W R sin(alpha), W R cos(alpha), M_ext, W b,
  // kb3_, c_partial_ (1/s^2) and m R cos(alpha), m R sin(alpha) (1/m)
  double g_sin_ = 0.0, g_cos_ = 0.0, ext_ = 0.0, wb_ = 0.0, kb3_i_ = 0.0, cp_ = 0.0, u_cos_ = 0.0, u_sin_ = 0.0;
};

namespace detail {

/// sin and cos of x. For |x| <= 1/4 (every rotation of a rocking wall short of
/// collapse) truncated Taylor series whose remainders are below 1e-20, i.e.
/// exact to rounding: to x^7 / x^8 for |x| <= 1/64 (remainders x^9/9!, x^10/10!)
/// and to x^13 / x^14 for |x| <= 1/4 (x^15/15!, x^16/16!). They cost a fraction
/// of the library calls. Written x + x^3 p(x^2) and 1 + x^2 q(x^2) (the last
/// addition rounds a small correction, as in Horner's rule), with p and q by
/// Estrin's scheme (pairs of terms, then powers x^4, x^8): a shorter chain of
/// dependent operations than Horner's rule.
inline void sin_cos(double x, double& sn, double& cs) {
  const double ax = std::fabs(x), x2 = x * x, x4 = x2 * x2;
  if (ax <= 1.0 / 64) {
    sn = x + (x * x2) * ((-1.0 / 6 + x2 * (1.0 / 120)) + x4 * (-1.0 / 5040));
    cs = 1.0 + x2 * ((-0.5 + x2 * (1.0 / 24)) + x4 * (-1.0 / 720 + x2 * (1.0 / 40320)));
  } else if (ax <= 0.25) {
    const double x8 = x4 * x4;
    sn = x + (x * x2) * (((-1.0 / 6 + x2 * (1.0 / 120)) + x4 * (-1.0 / 5040 + x2 * (1.0 / 362880))) +
                         x8 * (-1.0 / 39916800 + x2 * (1.0 / 6227020800.0)));
    cs = 1.0 + x2 * (((-0.5 + x2 * (1.0 / 24)) + x4 * (-1.0 / 720 + x2 * (1.0 / 40320))) +
                     x8 * ((-1.0 / 3628800 + x2 * (1.0 / 479001600.0)) + x4 * (-1.0 / 87178291200.0)));
  } else {
    sn = std::sin(x);
    cs = std::cos(x);
  }
}

}  // namespace detail

// Seed Eq. 1: I0 theta'' = -M(theta) + M_ext - (W/g) ug R cos(alpha s - theta), with
// M = W R sin(alpha s - theta) [- s W b + (2/3) k b^3 theta (full contact)]
//                              [- s (W/3) sqrt(2W/(k |theta|)) (partial contact)].
// Expanding sin and cos(alpha s - theta) by the angle-difference formulas:
// theta'' = P cos(theta) + Q sin(theta) + F(theta), with
//   P = -(s W R sin(alpha) + m R cos(alpha) ug) / I0,  Q = (W R cos(alpha) - s m R sin(alpha) ug) / I0,
//   F = M_ext / I0 + [s W b - (2/3) k b^3 theta] / I0 (full) or + s (W/3) sqrt(2W/(k s theta)) / I0 (partial);
// P and Q do not depend on theta, which keeps the chain of operations after
// sin(theta), cos(theta) and the square root short.
//
// Partial contact: s cp / sqrt(x), x = s theta, is evaluated as sqrt(x) (cp / x)
// (the same value to within 2 ulp: three correctly rounded operations). The
// square root and the division do not wait for each other, so the latency from
// theta to theta'' is one sqrt and one multiply instead of a sqrt followed by a
// division (issue 15: perf annotate put the partial branch's time on that
// chain; callgrind/perf figures in docs/theory/rocking.md, "Speed"). x is floored
// at 1e-200 (a stage that strays to theta <= 0 in the partial branch gets a huge
// finite value, as before, which the error control rejects): cp / 1e-200 stays
// finite for any cp below 1e108 1/s^2 (cp is of order 1e-2 for masonry walls).
// Its term is added last, after the theta-independent M_ext / I0, so the
// square root's chain ends in a single addition.
inline double RockingModel::angular_acceleration(double theta, int pivot, bool partial, double ug) const {
  const double s = pivot >= 0 ? 1.0 : -1.0;
  const double P = -(s * g_sin_ + u_cos_ * ug), Q = g_cos_ - s * u_sin_ * ug;
  double st, ct;
  detail::sin_cos(theta, st, ct);
  const double gravity = (P * ct + Q * st) + ext_;
  if (!(kb3_ > 0.0)) return gravity;  // rigid base
  if (!partial) return gravity + (s * wb_ - kb3_i_ * theta);  // full contact
  const double x = std::max(s * theta, 1e-200);
  return gravity + s * (std::sqrt(x) * (cp_ / x));  // partial contact
}

}  // namespace assess

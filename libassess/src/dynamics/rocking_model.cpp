// rocking_model.cpp: restoring moment, ultimate rotation, energy capacity and
// equation of motion of the rigid and smooth (Winkler) rocking blocks.
//
// Notation (seed paper Lipo & de Felice 2017 Eq. 1; research notes rocking.md §1):
//   theta            rotation (rad), positive outward; s = pivot side (+1 outer toe)
//   a = s theta      rotation magnitude on the active side (rad)
//   W, R, alpha, b   weight (N/m), toe-centroid distance (m), slenderness (rad), half base (m)
//   I0               inertia about the toe (kg m^2/m); m = W/g
//   k                Winkler modulus (N/m^3); theta_cr = W/(2 b^2 k)  (seed Eq. 1)
//   kb3_             (2/3) k b^3, stiffness of the full-contact reaction (N m/m)
//   c_partial_       (W/3) sqrt(2W/k): partial contact moment W c/3 = c_partial_/sqrt(a),
//                    with c = sqrt(2W/(k a)) the contact length (rocking.md §1.4)
//   M_ext            constant external moment about the toe, positive outward (N m/m)
#include "assess/dynamics/rocking_model.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"
#include "support/bracket_root.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace assess {
namespace {

constexpr double kRootTol = 1e-15;  // rad: theta_u and theta_peak to machine precision

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

RockingModel::RockingModel(const RockingBody& body, Foundation foundation, Sidedness sidedness,
                           Restitution restitution)
    : body_(body), foundation_(foundation), sidedness_(sidedness),
      restitution_kind_(restitution.kind) {
  body_.validate();
  const double W = body_.W, b = body_.b, m = body_.mass();
  if (!(foundation_.k > 0.0))
    throw InputError("Winkler modulus k must be positive (N/m^3), got " + num(foundation_.k));
  if (!foundation_.is_rigid()) {
    // Initial stiffness (2/3) k b^3 - W z_G > 0 (rocking.md §1.4, "existence of a restoring branch").
    const double k_min = 3.0 * W * body_.z_G() / (2.0 * b * b * b);
    if (!(foundation_.k > k_min))
      throw InputError("Winkler modulus k = " + num(foundation_.k / units::kN) +
                       " kN/m^3 is too small: the block has no restoring branch unless k > "
                       "3 W h / (2 b^3) = " + num(k_min / units::kN) + " kN/m^3");
  }
  if (sidedness_ == Sidedness::two_sided && std::fabs(body_.x_G() - b) > 1e-9 * b)
    throw InputError("two-sided rocking needs the centroid on the base centreline (x_G = b); got x_G = " +
                     num(body_.x_G()) + " m, b = " + num(b) + " m");

  switch (restitution_kind_) {
    case Restitution::Kind::value:
      if (!(std::isfinite(restitution.e) && restitution.e >= -1.0 && restitution.e <= 1.0))
        throw InputError("restitution must be in [-1, 1] (ratio of angular velocities after/before impact), got " +
                         num(restitution.e));
      if (sidedness_ == Sidedness::one_sided && restitution.e > 0.0)
        throw InputError("one-sided restitution must be in [-1, 0] (a rebound reverses the velocity), got " +
                         num(restitution.e));
      e_ = restitution.e;
      break;
    case Restitution::Kind::housner:
      if (sidedness_ != Sidedness::two_sided)
        throw InputError("restitution 'housner' applies to two-sided rocking; use 'one-sided-theory' or a value");
      e_ = 1.0 - 2.0 * m * b * b / body_.I0;  // rocking.md §1.2: 1 - 1.5 sin^2 alpha for a rectangle
      break;
    case Restitution::Kind::one_sided_theory:
      if (sidedness_ != Sidedness::one_sided)
        throw InputError("restitution 'one-sided-theory' applies to one-sided rocking; use 'housner' or a value");
      e_ = 1.0 - 2.0 * m * body_.z_G() * body_.z_G() / body_.I0;  // rocking.md §1.3: 1 - 1.5 cos^2 alpha
      break;
    case Restitution::Kind::none:
      if (foundation_.is_rigid())
        throw InputError("restitution 'none' applies only to the smooth (Winkler) model");
      if (sidedness_ == Sidedness::one_sided)
        throw InputError("one-sided rocking needs a restitution coefficient (the rebound at theta = 0)");
      e_ = 1.0;
      break;
  }

  WR_ = W * body_.R;
  cos_a_ = std::cos(body_.alpha);
  if (!foundation_.is_rigid()) {
    const double k = foundation_.k;
    theta_cr_ = W / (2.0 * b * b * k);  // seed Eq. 1
    kb3_ = 2.0 / 3.0 * k * b * b * b;
    c_partial_ = W / 3.0 * std::sqrt(2.0 * W / k);
  }
  const double sin_a = std::sin(body_.alpha), I0 = body_.I0;
  g_sin_ = WR_ * sin_a / I0;
  g_cos_ = WR_ * cos_a_ / I0;
  ext_ = body_.M_ext / I0;
  wb_ = W * b / I0;
  kb3_i_ = kb3_ / I0;
  cp_ = c_partial_ / I0;
  u_cos_ = m * body_.R * cos_a_ / I0;
  u_sin_ = m * body_.R * sin_a / I0;

  // Peak and zero of the net restoring moment on each side. On [0, alpha] each
  // branch is concave, so the derivative decreases and the peak is unique.
  const double half_pi = 0.5 * units::pi;
  const int nsides = sidedness_ == Sidedness::two_sided ? 2 : 1;
  for (int i = 0; i < nsides; ++i) {
    const int s = i == 0 ? +1 : -1;
    double a_pk = 0.0;
    if (dnet_side(0.0, s) > 0.0) {
      double hi = body_.alpha;
      while (dnet_side(hi, s) > 0.0 && hi < half_pi) hi = std::min(half_pi, 2.0 * hi);
      if (dnet_side(hi, s) > 0.0) {
        a_pk = half_pi;
      } else {
        auto d = [&](double x) { return dnet_side(x, s); };
        const auto br = detail::shrink_bracket(d, {0.0, dnet_side(0.0, s), hi, dnet_side(hi, s)}, kRootTol);
        a_pk = 0.5 * (br.a + br.b);
      }
    }
    const double f_pk = net_side(a_pk, s);
    if (!(f_pk > 0.0))
      throw InputError("the external moment M_ext = " + num(body_.M_ext) +
                       " N m/m exceeds the peak restoring moment on side " + (s > 0 ? "+" : "-") +
                       ": the body cannot stand");
    double a_u = half_pi;
    if (net_side(half_pi, s) < 0.0) {
      auto f = [&](double x) { return net_side(x, s); };
      const auto br = detail::shrink_bracket(f, {a_pk, f_pk, half_pi, net_side(half_pi, s)}, kRootTol);
      a_u = 0.5 * (br.a + br.b);
    }
    theta_pk_[i] = a_pk;
    theta_u_[i] = a_u;
  }
  if (nsides == 1) theta_pk_[1] = theta_pk_[0], theta_u_[1] = theta_u_[0];
}

double RockingModel::restoring_moment(double theta, int pivot, bool partial) const {
  const double s = pivot >= 0 ? 1.0 : -1.0;
  const double gravity = WR_ * std::sin(body_.alpha * s - theta);
  if (foundation_.is_rigid()) return gravity;  // Housner: k -> infinity
  if (!partial) return gravity - s * body_.W * body_.b + kb3_ * theta;  // seed Eq. 1, theta <= theta_cr
  const double a = std::max(s * theta, 1e-300);
  return gravity - s * c_partial_ / std::sqrt(a);  // seed Eq. 1, theta > theta_cr
}

double RockingModel::restoring_moment(double theta) const {
  const int s = theta >= 0.0 ? +1 : -1;
  return restoring_moment(theta, s, std::fabs(theta) > theta_cr_);
}

double RockingModel::net_side(double a, int side) const {
  const double s = side >= 0 ? 1.0 : -1.0;
  return s * (restoring_moment(s * a, side, a > theta_cr_) - body_.M_ext);
}

double RockingModel::dnet_side(double a, int side) const {
  (void)side;  // the derivative of s M(s a) does not depend on s; M_ext is constant
  const double gravity = -WR_ * std::cos(body_.alpha - a);
  if (foundation_.is_rigid()) return gravity;
  if (a <= theta_cr_) return gravity + kb3_;
  return gravity + 0.5 * c_partial_ / (a * std::sqrt(a));
}

RockingModel::Curve RockingModel::moment_rotation_curve(std::size_t points, int side) const {
  Curve c;
  const double tu = theta_u(side);
  const std::size_t n = std::max<std::size_t>(points, 2);
  for (std::size_t i = 0; i < n; ++i) c.theta.push_back(tu * double(i) / double(n - 1));
  if (theta_cr_ > 0.0 && theta_cr_ < tu) c.theta.push_back(theta_cr_);
  c.theta.push_back(theta_peak(side));
  std::sort(c.theta.begin(), c.theta.end());
  c.theta.erase(std::unique(c.theta.begin(), c.theta.end()), c.theta.end());
  for (double a : c.theta) c.moment.push_back(net_side(a, side));
  return c;
}

double RockingModel::work(double a, int side) const {
  const double s = side >= 0 ? 1.0 : -1.0;
  // Integral of W R sin(alpha - x) over [0, a]
  double w = WR_ * (std::cos(body_.alpha - a) - cos_a_);
  if (!foundation_.is_rigid()) {
    const double a1 = std::min(a, theta_cr_);
    w += -body_.W * body_.b * a1 + 0.5 * kb3_ * a1 * a1;  // full contact
    if (a > theta_cr_) w -= 2.0 * c_partial_ * (std::sqrt(a) - std::sqrt(theta_cr_));  // partial contact
  }
  return w - s * body_.M_ext * a;
}

double RockingModel::energy_demand(double a, int side) const {
  return work(std::min(std::fabs(a), theta_u(side)), side);
}

// At rest, theta = 0 on pivot s (seed Eq. 1): I0 theta'' = -M(0) + M_ext -
// (W/g) ug R cos(alpha), with the static moment M(0) = s W x_G (rigid base)
// or s W (x_G - b) (Winkler base: zero for a body centred on its base). M(0)
// is taken from the geometry, not from sin/cos of alpha, so that a centred
// smooth block at rest does not lift off on a rounding error at ug = 0, and
// so that its margin is exactly 0 at ug = 0: the lift-off event of the
// integration (rising through 0) then fires as soon as ug takes the right
// sign, also at t = 0 (docs/theory/rocking.md, "Lift-off from rest").
double RockingModel::lift_margin(int pivot, double ug) const {
  const double s = pivot >= 0 ? 1.0 : -1.0;
  const double arm = foundation_.is_rigid() ? body_.x_G() : body_.x_G() - body_.b;
  const double M0 = std::fabs(arm) <= 1e-12 * body_.R ? 0.0 : s * body_.W * arm;
  return s * (body_.M_ext - M0 - body_.mass() * body_.R * cos_a_ * ug) / body_.I0;
}

bool RockingModel::lifts(int pivot, double ug) const {
  if (sidedness_ == Sidedness::one_sided && pivot < 0) return false;
  return lift_margin(pivot, ug) > 0.0;
}

}  // namespace assess

// chain_dynamics.cpp: Lagrangian of a 1-DOF chain of rigid blocks
// (docs/theory/chain-dynamics.md; Mauro, de Felice & DeJong 2015 for the
// single-coordinate formulation, seed Eq. 1 for the Winkler bed).
//
// Notation:
//   Q(q)              chain coordinates (x_i, z_i, phi_i per block; Chain)
//   Q', Q'', Q'''     derivatives in q; A = [J(Q); e_ref^T] with e_ref picking
//                     phi of the reference block, q = sigma phi_ref
//   A Q' = [0; sigma],  A Q'' = [-h2; 0],  A Q''' = [-h3; 0]
//   where h2, h3 are the constraint rows applied to the second- and third-order
//   terms of a material point p = c + u + R(phi) r (r = p0 - c, R' = dR/dphi,
//   R'' = -R):
//     p'   = u'   + R' r phi'
//     p''  = u''  + R' r phi''  - R r phi'^2
//     p''' = u''' + R' r phi''' - 3 R r phi' phi'' - R' r phi'^3
//   m = W/g (g = units::g), I_G = m rho^2 (rho^2 = Chain::polar_gyration_sq)
//   N, b, L, k        Winkler: vertical load on the bed (N), half base (m),
//                     out-of-plane length (m), modulus (N/m^3); n = N/L
#include "assess/dynamics/chain_dynamics.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace assess {
namespace {

constexpr double kGridStep = 1.0 / 1024.0;  // rad: quintic Hermite error ~ h^6 f^(6) / 46080 << 1e-12
constexpr double kMaxQ = 0.5 * units::pi;    // rad: no chain is followed beyond a right angle

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

Eigen::Matrix2d rot(double phi) {
  Eigen::Matrix2d R;
  R << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return R;
}
Eigen::Matrix2d drot(double phi) {
  Eigen::Matrix2d R;
  R << -std::sin(phi), -std::cos(phi), std::cos(phi), -std::sin(phi);
  return R;
}

// Derivatives 1..3 of a material point of `block` from the chain derivatives.
struct PointDerivs {
  Eigen::Vector2d d0, d1, d2, d3;  // displacement p - p0 and its q-derivatives
};

PointDerivs point_derivs(const Chain& ch, int block, const Eigen::Vector2d& p0, const Eigen::VectorXd& Q,
                         const Eigen::VectorXd& dQ, const Eigen::VectorXd& d2Q, const Eigen::VectorXd& d3Q) {
  const Eigen::Index j = 3 * block;
  const Eigen::Vector2d r = p0 - ch.centroid(block);
  const double phi = Q(j + 2), f1 = dQ(j + 2), f2 = d2Q(j + 2), f3 = d3Q(j + 2);
  const Eigen::Matrix2d R = rot(phi), Rp = drot(phi);
  const Eigen::Vector2d Rr = R * r, Rpr = Rp * r;
  PointDerivs d;
  d.d0 = Eigen::Vector2d(Q(j), Q(j + 1)) + Rr - r;
  d.d1 = Eigen::Vector2d(dQ(j), dQ(j + 1)) + Rpr * f1;
  d.d2 = Eigen::Vector2d(d2Q(j), d2Q(j + 1)) + Rpr * f2 - Rr * (f1 * f1);
  d.d3 = Eigen::Vector2d(d3Q(j), d3Q(j + 1)) + Rpr * f3 - Rr * (3.0 * f1 * f2) - Rpr * (f1 * f1 * f1);
  return d;
}

// The constraint rows applied to a per-point vector term T(block, p0).
template <class Term>
Eigen::VectorXd constraint_terms(const Chain& ch, Eigen::Index rows, Term T) {
  Eigen::VectorXd h(rows);
  Eigen::Index k = 0;
  for (const Constraint& c : ch.constraints()) {
    switch (c.type) {
      case ConstraintType::GroundHinge: h.segment<2>(k) = T(c.block, c.point); k += 2; break;
      case ConstraintType::Hinge:
      case ConstraintType::Weld: h.segment<2>(k) = T(c.block, c.point) - T(c.other, c.point); k += 2; break;
      case ConstraintType::Slider: {
        const Eigen::Vector2d nrm = Eigen::Vector2d(-c.direction.y(), c.direction.x()).normalized();
        h(k++) = nrm.dot(T(c.block, c.point));
        break;
      }
    }
  }
  return h;
}

// Quintic Hermite on [0, h] from (f, f', f'') at both ends: power coefficients in t.
void quintic(double h, double f0, double g0, double s0, double f1, double g1, double s1, double* c) {
  c[0] = f0;
  c[1] = g0;
  c[2] = 0.5 * s0;
  const double d = f1 - (c[0] + h * (c[1] + h * c[2]));
  const double d1 = (g1 - (c[1] + 2.0 * c[2] * h)) * h;
  const double d2 = (s1 - 2.0 * c[2]) * h * h;
  const double a3 = 10.0 * d - 4.0 * d1 + 0.5 * d2, a4 = -15.0 * d + 7.0 * d1 - d2, a5 = 6.0 * d - 3.0 * d1 + 0.5 * d2;
  c[3] = a3 / (h * h * h);
  c[4] = a4 / (h * h * h * h);
  c[5] = a5 / (h * h * h * h * h);
}

// True if the polygons a and b are mirror images about x = xs (same vertices
// up to order), to tol.
bool mirrored_polygon(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double xs,
                      double tol) {
  if (a.size() != b.size()) return false;
  for (const auto& p : a) {
    const Eigen::Vector2d m(2.0 * xs - p.x(), p.y());
    bool found = false;
    for (const auto& q : b) found = found || (q - m).norm() <= tol;
    if (!found) return false;
  }
  return true;
}

// Blocks and loads invariant under the mirror x -> 2 xs - x (forces: Fx -> -Fx).
bool mirror_symmetric(const Chain& ch, double xs) {
  const double tol = 1e-9 * std::max(1.0, ch.size());
  const auto& bl = ch.blocks();
  for (std::size_t i = 0; i < bl.size(); ++i) {
    bool found = false;
    for (std::size_t j = 0; j < bl.size() && !found; ++j)
      found = mirrored_polygon(bl[i].polygon, bl[j].polygon, xs, tol) && bl[i].unit_weight == bl[j].unit_weight &&
              bl[i].length == bl[j].length;
    if (!found) return false;
  }
  for (const Load& l : ch.loads()) {
    if (l.type == LoadType::SelfWeight) continue;
    const Eigen::Vector2d m(2.0 * xs - l.point.x(), l.point.y());
    bool found = false;
    for (const Load& k : ch.loads()) {
      if (k.type != l.type || (k.point - m).norm() > tol) continue;
      if (l.type == LoadType::Weight)
        found = found || (k.weight == l.weight && k.vertical == l.vertical && k.seismic == l.seismic);
      else
        found = found || (std::fabs(k.force.x() + l.force.x()) <= 1e-12 * (1.0 + std::fabs(l.force.x())) &&
                          std::fabs(k.force.y() - l.force.y()) <= 1e-12 * (1.0 + std::fabs(l.force.y())));
    }
    if (!found) return false;
  }
  return true;
}

}  // namespace

bool ChainDynamics::solve(double q, const Eigen::VectorXd& guess, Eigen::VectorXd& Q) const {
  const Eigen::Index n = Eigen::Index(chain_.n_coordinates());
  const Eigen::Index m = chain_.jacobian(guess).rows();
  const Eigen::Index iref = 3 * ref_block_ + 2;
  const double tol = 1e-14 * std::max(chain_.size(), 1.0);
  Q = guess;
  Eigen::VectorXd r(m + 1);
  Eigen::MatrixXd A(m + 1, n);
  for (int it = 0; it < 50; ++it) {
    r.head(m) = chain_.residual(Q);
    r(m) = Q(iref) - sigma_ * q;
    if (r.cwiseAbs().maxCoeff() <= tol) return true;
    A.topRows(m) = chain_.jacobian(Q);
    A.row(m).setZero();
    A(m, iref) = 1.0;
    const Eigen::VectorXd dq = A.completeOrthogonalDecomposition().solve(-r);
    if (!dq.allFinite()) return false;
    Q += dq;
  }
  r.head(m) = chain_.residual(Q);
  r(m) = Q(iref) - sigma_ * q;
  return r.cwiseAbs().maxCoeff() <= 1e2 * tol;
}

ChainState ChainDynamics::derive(double q, const Eigen::VectorXd& Q) const {
  const Eigen::Index n = Eigen::Index(chain_.n_coordinates());
  const Eigen::MatrixXd J = chain_.jacobian(Q);
  const Eigen::Index m = J.rows();
  const Eigen::Index iref = 3 * ref_block_ + 2;
  Eigen::MatrixXd A(m + 1, n);
  A.topRows(m) = J;
  A.row(m).setZero();
  A(m, iref) = 1.0;
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  ChainState s;
  s.q = q;
  s.Q = Q;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
  rhs(m) = sigma_;
  s.dQ = cod.solve(rhs);
  // Second order: rows of h2 = -R r phi'^2 per point.
  rhs.head(m) = -constraint_terms(chain_, m, [&](int b, const Eigen::Vector2d& p0) -> Eigen::Vector2d {
    const Eigen::Index j = 3 * b;
    const double f1 = s.dQ(j + 2);
    return -(rot(Q(j + 2)) * (p0 - chain_.centroid(b))) * (f1 * f1);
  });
  rhs(m) = 0.0;
  s.d2Q = cod.solve(rhs);
  rhs.head(m) = -constraint_terms(chain_, m, [&](int b, const Eigen::Vector2d& p0) -> Eigen::Vector2d {
    const Eigen::Index j = 3 * b;
    const Eigen::Vector2d r = p0 - chain_.centroid(b);
    const double f1 = s.dQ(j + 2), f2 = s.d2Q(j + 2);
    return -(rot(Q(j + 2)) * r) * (3.0 * f1 * f2) - (drot(Q(j + 2)) * r) * (f1 * f1 * f1);
  });
  s.d3Q = cod.solve(rhs);

  const double g = units::g;
  for (const Load& l : chain_.loads()) {
    const PointDerivs p = point_derivs(chain_, l.block, l.point, s.Q, s.dQ, s.d2Q, s.d3Q);
    switch (l.type) {
      case LoadType::SelfWeight: {
        const double mass = l.weight / g, I = mass * chain_.polar_gyration_sq(l.block);
        const Eigen::Index j = 3 * l.block + 2;
        const double f1 = s.dQ(j), f2 = s.d2Q(j), f3 = s.d3Q(j);
        s.M += mass * p.d1.squaredNorm() + I * f1 * f1;
        s.dM += 2.0 * (mass * p.d1.dot(p.d2) + I * f1 * f2);
        s.d2M += 2.0 * (mass * (p.d2.squaredNorm() + p.d1.dot(p.d3)) + I * (f2 * f2 + f1 * f3));
        s.V += l.weight * p.d0.y();
        s.dV += l.weight * p.d1.y();
        s.d2V += l.weight * p.d2.y();
        s.d3V += l.weight * p.d3.y();
        s.B += mass * p.d1.x();
        s.dB += mass * p.d2.x();
        s.d2B += mass * p.d3.x();
        break;
      }
      case LoadType::Weight: {
        const double mass = l.weight / g;
        if (l.seismic) {  // its mass moves horizontally with the chain
          s.M += mass * p.d1.x() * p.d1.x();
          s.dM += 2.0 * mass * p.d1.x() * p.d2.x();
          s.d2M += 2.0 * mass * (p.d2.x() * p.d2.x() + p.d1.x() * p.d3.x());
          s.B += mass * p.d1.x();
          s.dB += mass * p.d2.x();
          s.d2B += mass * p.d3.x();
        }
        if (l.vertical) {  // it bears on the chain: rises with its point
          s.M += mass * p.d1.y() * p.d1.y();
          s.dM += 2.0 * mass * p.d1.y() * p.d2.y();
          s.d2M += 2.0 * mass * (p.d2.y() * p.d2.y() + p.d1.y() * p.d3.y());
          s.V += l.weight * p.d0.y();
          s.dV += l.weight * p.d1.y();
          s.d2V += l.weight * p.d2.y();
          s.d3V += l.weight * p.d3.y();
        }
        break;
      }
      case LoadType::Force:
      case LoadType::Tie:
        s.V -= l.force.dot(p.d0);
        s.dV -= l.force.dot(p.d1);
        s.d2V -= l.force.dot(p.d2);
        s.d3V -= l.force.dot(p.d3);
        break;
      case LoadType::Friction:
        break;  // rejected by the constructor
    }
  }
  return s;
}

ChainDynamics::ChainDynamics(const Chain& chain, Foundation foundation) : chain_(chain), foundation_(foundation) {
  if (chain_.plan())
    throw InputError("dynamic analysis: the chain is drawn in plan (horizontal flexure): gravity does not restore it, "
                     "the rocking equation does not apply");
  for (const Load& l : chain_.loads())
    if (l.type == LoadType::Friction)
      throw InputError("dynamic analysis: load '" + l.name +
                       "': interlocking friction is not part of the dynamic model; remove it from the mechanism "
                       "for the dynamic analysis");
  if (!(foundation_.k > 0.0)) throw InputError("Winkler modulus k must be positive (N/m^3), got " + num(foundation_.k));
  const Eigen::Index n = Eigen::Index(chain_.n_coordinates());
  const Eigen::VectorXd Q0 = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd v = chain_.virtual_displacement(Q0);

  // Mirror symmetry about the vertical axis through the middle of the chain's extent.
  {
    double lo = 1e300, hi = -1e300;
    for (const Block& b : chain_.blocks())
      for (const auto& p : b.polygon) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
    x_axis_ = 0.5 * (lo + hi);
    symmetric_ = mirror_symmetric(chain_, x_axis_);
  }

  // Reference block: the first block on a ground hinge that rotates, else the largest rotation.
  ref_block_ = -1;
  const Constraint* ground = nullptr;
  int ground_hinges = 0;
  for (const Constraint& c : chain_.constraints())
    if (c.type == ConstraintType::GroundHinge) {
      ++ground_hinges;
      if (ref_block_ < 0 && std::fabs(v(3 * c.block + 2)) > 1e-9) ref_block_ = c.block, ground = &c;
    }
  if (ref_block_ < 0) {
    double best = -1.0;
    for (std::size_t b = 0; b < chain_.blocks().size(); ++b)
      if (std::fabs(v(Eigen::Index(3 * b + 2))) > best) best = std::fabs(v(Eigen::Index(3 * b + 2))), ref_block_ = int(b);
  }
  sigma_ = v(3 * ref_block_ + 2) >= 0.0 ? 1.0 : -1.0;

  // Winkler bed under the ground-hinge block (seed Eq. 1 with the chain's vertical load N).
  if (!foundation_.is_rigid()) {
    if (ground_hinges != 1 || !ground)
      throw InputError("dynamic analysis: the smooth (Winkler) model needs exactly one ground hinge, the toe of the "
                       "block on the bed; this chain has " + std::to_string(ground_hinges) + "; use \"model\": \"rigid\"");
    for (const Constraint& c : chain_.constraints())
      if (c.type == ConstraintType::Slider && std::fabs(c.direction.x()) > 1e-9 * c.direction.norm())
        throw InputError("dynamic analysis: the smooth (Winkler) model needs every vertical load to reach the bed "
                         "through the ground hinge, but constraint '" + c.name +
                         "' is a slider that takes a vertical reaction; use \"model\": \"rigid\"");
    for (const Load& l : chain_.loads()) {
      if (l.type == LoadType::SelfWeight || (l.type == LoadType::Weight && l.vertical)) N_ += l.weight;
      if (l.type == LoadType::Force || l.type == LoadType::Tie) N_ -= l.force.y();
    }
    const Block& blk = chain_.blocks()[std::size_t(ground->block)];
    double xmin = 1e300, xmax = -1e300;
    const double tol = 1e-6 * chain_.size();
    for (const auto& p : blk.polygon)
      if (std::fabs(p.y() - ground->point.y()) <= tol) xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    if (!(xmax > xmin))
      throw InputError("dynamic analysis: the block on the ground hinge has no base edge at the hinge level z = " +
                       num(ground->point.y()) + " m (the Winkler bed needs one)");
    if (!(N_ > 0.0)) throw InputError("dynamic analysis: the Winkler bed carries no vertical load");
    b_ = 0.5 * (xmax - xmin);
    L_ = blk.length;
    const double k = foundation_.k, w = N_ / L_;
    q_cr_ = w / (2.0 * b_ * b_ * k);                       // seed Eq. 1
    kb3L_ = 2.0 / 3.0 * k * b_ * b_ * b_ * L_;             // full contact stiffness (N m/rad)
    cpL_ = L_ * w / 3.0 * std::sqrt(2.0 * w / k);          // partial contact: moment cpL / sqrt(q)
  }

  // Grid: nodes until the net restoring force has vanished (q_u) plus two intervals.
  h_ = kGridStep;
  inv_h_ = 1.0 / h_;
  std::vector<ChainState> nodes;
  Eigen::VectorXd Q = Q0;
  bool found = false;
  std::size_t extra = 0;
  for (int k = 0; double(k) * h_ <= kMaxQ; ++k) {
    const double q = double(k) * h_;
    Eigen::VectorXd guess = Q;
    if (!nodes.empty()) guess = nodes.back().Q + h_ * nodes.back().dQ + 0.5 * h_ * h_ * nodes.back().d2Q;
    if (!solve(q, guess, Q)) break;
    nodes.push_back(derive(q, Q));
    if (!std::isfinite(nodes.back().M) || !std::isfinite(nodes.back().d3V)) {
      nodes.pop_back();
      break;
    }
    if (k == 0) {
      if (!(nodes[0].M > 0.0)) throw InputError("dynamic analysis: the chain has no mass that moves");
      if (!foundation_.is_rigid() && !(nodes[0].d2V + kb3L_ > 0.0))
        throw InputError("Winkler modulus k = " + num(foundation_.k / units::kN) +
                         " kN/m^3 is too small: the chain has no restoring branch unless (2/3) k b^3 L > -V''(0) = " +
                         num(-nodes[0].d2V / units::kN) + " kN m");
      continue;
    }
    const double net = nodes.back().dV + foundation_moment(q, q > q_cr_);
    if (!found && net <= 0.0) found = true;
    if (found && ++extra > 2) break;
  }
  if (!found || nodes.size() < 2)
    throw InputError("dynamic analysis: the chain's net restoring force does not vanish before its configuration can "
                     "no longer be found (q = " + num(double(nodes.size()) * h_) +
                     " rad): the chain locks; the dynamic model does not apply");
  n_ = nodes.size() - 1;
  coefs_.assign(n_ * 18, 0.0);
  cum_.assign(n_ + 1, 0.0);
  for (std::size_t k = 0; k < n_; ++k) {
    const ChainState &a = nodes[k], &b = nodes[k + 1];
    double* c = &coefs_[k * 18];
    quintic(h_, a.M, a.dM, a.d2M, b.M, b.dM, b.d2M, c);
    quintic(h_, a.dV, a.d2V, a.d3V, b.dV, b.d2V, b.d3V, c + 6);
    quintic(h_, a.B, a.dB, a.d2B, b.B, b.dB, b.d2B, c + 12);
    double integral = 0.0, hp = h_;
    for (int i = 0; i < 6; ++i, hp *= h_) integral += c[6 + i] * hp / double(i + 1);
    cum_[k + 1] = cum_[k] + integral;
  }
  for (const ChainState& s : nodes) nodes_Q_.push_back(s.Q), nodes_dQ_.push_back(s.dQ);

  // Static net force at rest (rounding residue of a centred block on its bed -> 0).
  const double f0 = nodes[0].dV + foundation_moment(0.0, false);
  const double scale0 = std::fabs(nodes[0].dV) + N_ * b_;
  static0_ = std::fabs(f0) <= 1e-12 * scale0 ? 0.0 : f0;
  if (static0_ < 0.0)
    throw InputError("dynamic analysis: the chain cannot stand at rest: its net restoring force at q = 0 is " +
                     num(static0_ / units::kN) + " kN m (outward)");

  // q_u: the net restoring force changes sign in the last-but-two interval or earlier.
  std::size_t k = 1;
  while (k <= n_ && net_restoring(double(k) * h_) > 0.0) ++k;
  double lo = double(k - 1) * h_, hi = double(std::min(k, n_)) * h_;
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    (net_restoring(mid) > 0.0 ? lo : hi) = mid;
  }
  q_u_ = 0.5 * (lo + hi);
}

double ChainDynamics::foundation_moment(double q, bool partial) const {
  if (foundation_.is_rigid()) return 0.0;
  if (!partial) return -N_ * b_ + kb3L_ * q;                  // seed Eq. 1, q <= q_cr
  return -cpL_ / std::sqrt(std::max(q, 1e-300));              // seed Eq. 1, q > q_cr
}

double ChainDynamics::work(double q) const {
  double t;
  const std::size_t k = locate(q, t);
  const double* c = &coefs_[k * 18 + 6];
  double w = cum_[k], tp = t;
  for (int i = 0; i < 6; ++i, tp *= t) w += c[i] * tp / double(i + 1);
  if (!foundation_.is_rigid()) {
    const double a1 = std::min(q, q_cr_);
    w += -N_ * b_ * a1 + 0.5 * kb3L_ * a1 * a1;                                  // full contact
    if (q > q_cr_) w -= 2.0 * cpL_ * (std::sqrt(q) - std::sqrt(q_cr_));          // partial contact
  }
  return w;
}

ChainState ChainDynamics::exact(double q) const {
  double t;
  std::size_t k = locate(q, t);
  if (t > 0.5 * h_ && k + 1 < nodes_Q_.size()) ++k, t -= h_;
  Eigen::VectorXd Q;
  if (!solve(q, nodes_Q_[k] + t * nodes_dQ_[k], Q))
    throw InputError("dynamic analysis: the chain's configuration at q = " + num(q) + " rad cannot be found");
  return derive(q, Q);
}

double ChainDynamics::horizontal_displacement(int block, const Eigen::Vector2d& p0, double q) const {
  if (q < 0.0) {
    // Mirror image: the mirrored point of a mirrored block moves outward at |q|.
    const Eigen::Vector2d m(2.0 * x_axis_ - p0.x(), p0.y());
    const std::vector<int> bs = chain_.blocks_containing(m);
    if (!symmetric_ || bs.empty())
      throw InputError("dynamic analysis: inward motion (q < 0) of a chain that is not mirror-symmetric");
    return -horizontal_displacement(bs.front(), m, -q);
  }
  const ChainState s = exact(q);
  return chain_.position(block, p0, s.Q).x() - p0.x();
}

}  // namespace assess

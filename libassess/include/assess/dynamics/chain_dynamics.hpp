// chain_dynamics.hpp: the equation of motion of any 1-DOF kinematic chain of
// rigid blocks (Lagrange's equation in the chain's single coordinate q), rigid
// or with the seed's Winkler bed under the ground-hinge block, knowing
// nothing of the integrator (docs/theory/chain-dynamics.md).
//
//   M(q) q'' + 1/2 M'(q) q'^2 + V'(q) + Mf(q) = -ug''(t) B(q)
//
//   M(q) = sum_blocks (m_i |dx_Gi/dq|^2 + I_Gi (dphi_i/dq)^2)
//        + sum_carried m_j ((dx_j/dq)^2 [seismic] + (dz_j/dq)^2 [bearing])   (kg m^2 per rad^2)
//   V(q) = sum W z (blocks, bearing carried weights) - sum F . x (forces, ties)  (J)
//   B(q) = sum m dx/dq over the block masses and the seismic carried masses  (kg m / rad)
//   Mf(q) Winkler moment about the ground hinge (seed Eq. 1, with the vertical
//         load N of the chain in place of W); 0 on a rigid base      (N m)
//
// q is the rotation (rad) of the reference block (the block on the ground
// hinge, else the block with the largest rotation), signed so that q > 0
// moves the seismic masses outward (Chain::virtual_displacement). For one
// block rotating about its toe q is the rocking model's theta and the
// equation is seed Eq. 1.
//
// Mass, potential slope and ground coupling come from the chain's own
// finite-displacement configuration Q(q) and its derivatives dQ/dq, d2Q/dq2,
// d3Q/dq3, obtained from the constraint Jacobian (exact, no finite
// differences), tabulated at grid nodes and interpolated between them by
// quintic Hermite polynomials (value, first and second derivative at both
// ends); interpolation error below 1e-12 of each function's scale (tested).
#pragma once

#include "assess/dynamics/rocking_model.hpp"
#include "assess/kinematic/chain.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

namespace assess {

/// Exact values at one q (Newton solve of the configuration + Jacobian solves).
struct ChainState {
  double q = 0.0;     ///< rad
  double M = 0.0;     ///< generalised mass (kg m^2)
  double dM = 0.0;    ///< dM/dq (kg m^2/rad)
  double d2M = 0.0;   ///< d2M/dq2
  double V = 0.0;     ///< potential energy relative to q = 0 (J)
  double dV = 0.0;    ///< dV/dq (N m)
  double d2V = 0.0;   ///< d2V/dq2
  double d3V = 0.0;   ///< d3V/dq3
  double B = 0.0;     ///< ground coupling sum m dx/dq (kg m)
  double dB = 0.0;    ///< dB/dq
  double d2B = 0.0;   ///< d2B/dq2
  Eigen::VectorXd Q, dQ, d2Q, d3Q;  ///< configuration and its q-derivatives (chain coordinates)
};

/// The equation of motion of a 1-DOF chain. Immutable once built.
class ChainDynamics {
 public:
  /// @param chain       a valid 1-DOF chain (copied)
  /// @param foundation  rigid, or a Winkler bed (N/m^3) under the ground-hinge block's base
  /// @throws InputError for friction loads (not part of the dynamic model), a
  ///   Winkler bed without a single ground hinge, with a slider that takes a
  ///   vertical reaction, with no base edge at the hinge level or too soft to
  ///   restore (k <= 3 N z_G / (2 b^3 L) as for one block), or a chain whose
  ///   net restoring force does not vanish before its configuration can no
  ///   longer be found (locking).
  ChainDynamics(const Chain& chain, Foundation foundation);

  const Chain& chain() const { return chain_; }
  const Foundation& foundation() const { return foundation_; }
  bool smooth() const { return !foundation_.is_rigid(); }
  int reference_block() const { return ref_block_; }

  /// Exact evaluation at q (rad): Newton for the configuration, then the
  /// derivatives from the constraint Jacobian. Slow (tests, set-up, results).
  ChainState exact(double q) const;

  /// Interpolated M(q) (kg m^2), dM/dq, dV/dq (N m), B(q) (kg m).
  double mass(double q) const { return eval(0, q); }
  double dmass(double q) const { return eval_d(0, q); }
  double dpotential(double q) const { return eval(1, q); }
  double coupling(double q) const { return eval(2, q); }

  /// Winkler moment about the ground hinge, restoring sense (N m): full
  /// contact -N b + (2/3) k L b^3 q (q <= q_cr), partial contact
  /// -(N/3) sqrt(2 n / (k q)) (q > q_cr), n = N/L (seed Eq. 1); 0 if rigid.
  double foundation_moment(double q, bool partial) const;
  /// q_cr = n / (2 b^2 k) (rad): end of full contact (seed Eq. 1); 0 if rigid.
  double q_cr() const { return q_cr_; }
  /// Vertical load on the Winkler bed N (N), half base b (m), length L (m).
  double N() const { return N_; }
  double half_base() const { return b_; }

  /// Generalised acceleration q'' (rad/s^2) at (q, q') under ug (m/s^2,
  /// positive outward) on side `side` (+1 outward; -1 inward, two-sided
  /// mirror-symmetric chains only: the mirror image, M(q) = M(-q), M', V', Mf
  /// odd in q, B even; docs/theory/chain-dynamics.md §3); `partial` selects the
  /// Winkler branch. The side comes from the integrator's mode, not from the
  /// sign of q, so each side's equation extends smoothly across q = 0.
  double acceleration(double q, double qd, bool partial, double ug, int side = +1) const {
    // A trial stage of a step that the error control will reject can lie far
    // off (the partial branch's 1/sqrt(q) extended to q <= 0 gives ~1e148
    // rad/s^2): the coordinate is held within +-(grid end) and the speed in
    // the q'^2 term within kStageSpeedMax, so such a stage stays finite and the
    // step is rejected, where an overflow ended the analysis with a GSL error
    // (docs/theory/chain-dynamics.md). Values on the grid are unchanged.
    const double s = side >= 0 ? 1.0 : -1.0, q_end = double(n_) * h_;
    const double a = std::min(std::max(s * q, -q_end), q_end);
    const double w = std::min(std::fabs(qd), kStageSpeedMax);
    double t;
    const double* c = &coefs_[locate(a, t) * 18];
    const double M = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
    const double dM = c[1] + t * (2 * c[2] + t * (3 * c[3] + t * (4 * c[4] + t * 5 * c[5])));
    const double* v = c + 6;
    const double dV = v[0] + t * (v[1] + t * (v[2] + t * (v[3] + t * (v[4] + t * v[5]))));
    const double* b = c + 12;
    const double B = b[0] + t * (b[1] + t * (b[2] + t * (b[3] + t * (b[4] + t * b[5]))));
    return (s * (-0.5 * dM * w * w - dV - foundation_moment(a, partial)) - ug * B) / M;
  }
  /// Net restoring force -(V' + Mf) at q (N m), restoring sense positive.
  double net_restoring(double q) const { return dpotential(q) + foundation_moment(q, q > q_cr_); }

  /// Net generalised force at rest at q = 0 under ug (N m), towards side s
  /// (+1 outward, -1 inward, mirror image): -(V'(0) + Mf(0)) - s ug B(0).
  double rest_force(double ug, int side = +1) const { return -static0_ - (side >= 0 ? ug : -ug) * coefs_[12]; }
  /// True if at rest at q = 0 the excitation ug drives the chain towards side s.
  bool lifts(double ug, int side = +1) const { return rest_force(ug, side) > 0.0; }
  /// True if the blocks and loads are mirror images of themselves about a
  /// vertical axis: the inward mechanism is then the mirror image of the
  /// outward one and the chain can rock on both sides.
  bool symmetric() const { return symmetric_; }
  /// The vertical axis x = x_s of the symmetry (m).
  double symmetry_axis() const { return x_axis_; }
  /// Ultimate coordinate q_u (rad): where the net restoring force V' + Mf
  /// vanishes after its peak (the chain's theta_u; dk0 of the kinematic curve).
  double q_u() const { return q_u_; }
  /// Work of the net restoring force from 0 to q (J): V(q) - V(0) + foundation work.
  double work(double q) const;
  double capacity() const { return work(q_u_); }
  /// Energy demand for a peak q (J), capped at q_u (seed §3.2 extended to chains).
  double energy_demand(double q) const { return work(std::min(std::max(q, 0.0), q_u_)); }

  /// Horizontal displacement (m) of the material point p0 of `block` at q (exact);
  /// for q < 0 (symmetric chains) the mirror image of the mirrored point's at |q|.
  double horizontal_displacement(int block, const Eigen::Vector2d& p0, double q) const;

  /// Grid of the interpolation: nodes q_k = k h, k = 0..n.
  double grid_step() const { return h_; }
  std::size_t grid_intervals() const { return n_; }

 private:
  static constexpr double kStageSpeedMax = 1e4;  // rad/s, far above any wall's motion
  // Interval holding q (clamped to the grid) and the offset t = q - q_k.
  std::size_t locate(double q, double& t) const {
    const double x = q * inv_h_;
    // No conversion of an out-of-range double to long (undefined behaviour).
    const long k = !(x > 0.0) ? 0 : x >= double(n_) ? static_cast<long>(n_) - 1 : static_cast<long>(x);
    t = q - double(k) * h_;
    return std::size_t(k);
  }
  double eval(int f, double q) const {
    double t;
    const double* c = &coefs_[(locate(q, t) * 3 + std::size_t(f)) * 6];
    return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
  }
  double eval_d(int f, double q) const {
    double t;
    const double* c = &coefs_[(locate(q, t) * 3 + std::size_t(f)) * 6];
    return c[1] + t * (2 * c[2] + t * (3 * c[3] + t * (4 * c[4] + t * 5 * c[5])));
  }
  bool solve(double q, const Eigen::VectorXd& guess, Eigen::VectorXd& Q) const;
  ChainState derive(double q, const Eigen::VectorXd& Q) const;

  Chain chain_;
  Foundation foundation_;
  int ref_block_ = 0;
  double sigma_ = 1.0;  // q = sigma * phi_ref
  double h_ = 0.0, inv_h_ = 0.0;
  std::size_t n_ = 0;
  std::vector<double> coefs_;   // per interval: 3 functions x 6 power coefficients in (q - q_k)
  std::vector<double> cum_;     // integral of V' from 0 to q_k
  std::vector<Eigen::VectorXd> nodes_Q_, nodes_dQ_;  // configuration at the nodes (Newton guesses)
  // Winkler
  double N_ = 0.0, b_ = 0.0, L_ = 1.0, q_cr_ = 0.0, kb3L_ = 0.0, cpL_ = 0.0;
  double static0_ = 0.0;  // V'(0) + Mf(0), 0 when it is a rounding residue
  double q_u_ = 0.0;
  bool symmetric_ = false;
  double x_axis_ = 0.0;
};

}  // namespace assess

// floor_motion.cpp: first-mode floor motions (Circ. 2019 §C7.2.3 model; see
// floor_motion.hpp and docs/theory/chain-dynamics.md §4).
//
// Notation: w = 2 pi / T1 (rad/s), xi damping ratio, dt record step (s).
// Over a step the excitation is f(s) = a0 + (a1 - a0) s / dt (linear between
// samples). The augmented state z = (u, v, f, f') obeys z' = A z with
//   u' = v,  v' = -w^2 u - 2 xi w v - f,  f' = f',  f'' = 0,
// so z(dt) = exp(A dt) z(0) exactly; the relative acceleration is
// ur'' = -w^2 u - 2 xi w v - f.
#include "assess/records/floor_motion.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <string>

namespace assess {

void FloorFilter::validate() const {
  if (!(T1 > 0.0 && std::isfinite(T1))) throw InputError("floor filter: the period T1 must be > 0 s");
  if (!(xi >= 0.0 && xi < 1.0)) throw InputError("floor filter: the damping ratio must be in [0, 1) (-)");
  if (!(gamma_psi >= 0.0 && std::isfinite(gamma_psi)))
    throw InputError("floor filter: gamma psi(Z) must be >= 0 (-)");
}

std::vector<double> oscillator_relative_acceleration(const Record& ground, double T1_s, double xi) {
  if (!(ground.dt > 0.0)) throw InputError("record '" + ground.name + "': time step must be positive (s)");
  const double w = 2.0 * units::pi / T1_s;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A(0, 1) = 1.0;
  A(1, 0) = -w * w;
  A(1, 1) = -2.0 * xi * w;
  A(1, 2) = -1.0;
  A(2, 3) = 1.0;
  const Eigen::Matrix4d E = (A * ground.dt).exp();
  std::vector<double> out(ground.acc.size(), 0.0);
  double u = 0.0, v = 0.0;
  if (!out.empty()) out[0] = -ground.acc[0];
  for (std::size_t i = 0; i + 1 < ground.acc.size(); ++i) {
    const double a0 = ground.acc[i], a1 = ground.acc[i + 1], slope = (a1 - a0) / ground.dt;
    const double un = E(0, 0) * u + E(0, 1) * v + E(0, 2) * a0 + E(0, 3) * slope;
    const double vn = E(1, 0) * u + E(1, 1) * v + E(1, 2) * a0 + E(1, 3) * slope;
    u = un, v = vn;
    out[i + 1] = -w * w * u - 2.0 * xi * w * v - a1;
  }
  return out;
}

Record floor_motion(const Record& ground, const FloorFilter& filter) {
  filter.validate();
  const std::vector<double> ur = oscillator_relative_acceleration(ground, filter.T1, filter.xi);
  Record r = ground;
  r.name = ground.name + " @Z";
  for (std::size_t i = 0; i < r.acc.size(); ++i) r.acc[i] = ground.acc[i] + filter.gamma_psi * ur[i];
  return r;
}

}  // namespace assess

// quintic.hpp (private to dynamics): the quintic Hermite interpolant of a
// second-order equation's coordinate over one integration step, from its
// value, velocity and acceleration at both ends, and the peak of the
// coordinate inside a step (the rocking body, the chain and the tied
// analyses find their peak rotation with it).
#pragma once

#include "support/bracket_root.hpp"

namespace assess::detail {

/// Quintic Hermite interpolation on a step of length h from the values, first
/// and second derivatives at both ends; s in [0, 1].
struct Quintic {
  double p0, m0, a0, p1, m1, a1, h;
  double value(double s) const {
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
    return (1 - 10 * s3 + 15 * s4 - 6 * s5) * p0 + (s - 6 * s3 + 8 * s4 - 3 * s5) * h * m0 +
           (0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5) * h * h * a0 + (0.5 * s3 - s4 + 0.5 * s5) * h * h * a1 +
           (-4 * s3 + 7 * s4 - 3 * s5) * h * m1 + (10 * s3 - 15 * s4 + 6 * s5) * p1;
  }
  double slope(double s) const {  // d/ds
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
    return (-30 * s2 + 60 * s3 - 30 * s4) * p0 + (1 - 18 * s2 + 32 * s3 - 15 * s4) * h * m0 +
           (s - 4.5 * s2 + 6 * s3 - 2.5 * s4) * h * h * a0 + (1.5 * s2 - 4 * s3 + 2.5 * s4) * h * h * a1 +
           (-12 * s2 + 28 * s3 - 15 * s4) * h * m1 + (30 * s2 - 60 * s3 + 30 * s4) * p1;
  }
};

/// The extremum of the coordinate inside a step from t0 to t1 (state y = (q, q', ...),
/// derivative f = (q', q'', ...)): when q' changes sign inside it, true with its
/// time t (s) and value q; false otherwise.
inline bool extremum_in_step(double t0, const double* y0, const double* f0, double t1, const double* y1,
                             const double* f1, double& t, double& q) {
  if (!(y0[1] * y1[1] < 0.0)) return false;
  const Quintic p{y0[0], f0[0], f0[1], y1[0], f1[0], f1[1], t1 - t0};
  const double d0 = p.slope(0.0), d1 = p.slope(1.0);
  if (!(d0 * d1 < 0.0)) return false;
  auto slope = [&](double s) { return p.slope(s); };
  const auto br = shrink_bracket(slope, {0.0, d0, 1.0, d1}, 1e-13);
  const double s = 0.5 * (br.a + br.b);
  t = t0 + s * (t1 - t0);
  q = p.value(s);
  return true;
}

}  // namespace assess::detail

// bracket_root.hpp (private): a bracketing root finder shared by the rocking
// model (theta_u, peak moment) and the event locator of the hybrid
// integrator. Illinois variant of regula falsi (Dowell & Jarratt 1971) with
// a bisection safeguard: superlinear on smooth functions, and the bracket
// width at least halves every three iterations whatever the function.
#pragma once

#include <algorithm>
#include <cmath>

namespace assess::detail {

/// A bracket [a, b] (a may be greater than b) with fb != 0 and f(a) on the
/// other side: a point x is on the "b side" iff f(x) * sign(fb) > 0.
/// A zero value is therefore on the a side: the caller chooses the sign
/// convention so that b is the side it wants to end on.
struct Bracket {
  double a, fa, b, fb;
};

/// Shrinks `br` until |b - a| <= tol (or max_iter evaluations of f).
template <class F>
Bracket shrink_bracket(F&& f, Bracket br, double tol, int max_iter = 300) {
  const double sb = br.fb > 0.0 ? 1.0 : -1.0;
  double fa = br.fa, fb = br.fb;  // Illinois-scaled copies
  int last = 0;                   // +1: b moved last, -1: a moved last
  double width_ref = std::fabs(br.b - br.a);
  int since_ref = 0;
  for (int it = 0; it < max_iter && std::fabs(br.b - br.a) > tol; ++it) {
    const double w = std::fabs(br.b - br.a);
    double c;
    if (since_ref >= 3) {  // slow progress: bisect
      c = 0.5 * (br.a + br.b);
    } else {
      c = (fb != fa) ? br.b - fb * (br.b - br.a) / (fb - fa) : 0.5 * (br.a + br.b);
      // keep c strictly inside, at least 1% of the width from either end
      const double lo = std::min(br.a, br.b), hi = std::max(br.a, br.b);
      const double margin = std::min(0.01 * w, 0.5 * tol);
      if (!(c > lo + margin)) c = lo + std::max(margin, 0.01 * w);
      if (!(c < hi - margin)) c = hi - std::max(margin, 0.01 * w);
    }
    const double fc = f(c);
    if (fc * sb > 0.0) {
      br.b = c, br.fb = fc, fb = fc;
      if (last == +1) fa *= 0.5;
      last = +1;
    } else {
      br.a = c, br.fa = fc, fa = fc;
      if (last == -1) fb *= 0.5;
      last = -1;
    }
    if (std::fabs(br.b - br.a) <= 0.5 * width_ref) {
      width_ref = std::fabs(br.b - br.a);
      since_ref = 0;
    } else {
      ++since_ref;
    }
  }
  return br;
}

}  // namespace assess::detail

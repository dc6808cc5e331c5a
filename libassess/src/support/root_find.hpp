// root_find.hpp (private): Brent's method on a bracketing interval (GSL
// gsl_root_fsolver_brent), for any callable double(double).
#pragma once

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <functional>
#include <memory>

namespace assess::detail {

/// Root of f in [lo, hi], where f(lo) and f(hi) have opposite signs (or one is
/// zero). Converges to |hi - lo| <= abs_tol + rel_tol |x|. Returns NaN when
/// the interval does not bracket a root or GSL fails.
inline double brent_root(const std::function<double(double)>& f, double lo, double hi,
                         double abs_tol, double rel_tol = 1e-14, int max_iter = 200) {
  const double flo = f(lo), fhi = f(hi);
  if (flo == 0.0) return lo;
  if (fhi == 0.0) return hi;
  if (!std::isfinite(flo) || !std::isfinite(fhi) || (flo > 0.0) == (fhi > 0.0)) return std::nan("");
  gsl_set_error_handler_off();  // process-global: GSL must never abort (see docs)
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> s(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_function F;
  F.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  F.params = const_cast<std::function<double(double)>*>(&f);
  if (gsl_root_fsolver_set(s.get(), &F, lo, hi) != GSL_SUCCESS) return std::nan("");
  for (int it = 0; it < max_iter; ++it) {
    if (gsl_root_fsolver_iterate(s.get()) != GSL_SUCCESS) return std::nan("");
    const double a = gsl_root_fsolver_x_lower(s.get()), b = gsl_root_fsolver_x_upper(s.get());
    if (gsl_root_test_interval(a, b, abs_tol, rel_tol) == GSL_SUCCESS) return gsl_root_fsolver_root(s.get());
  }
  return gsl_root_fsolver_root(s.get());
}

}  // namespace assess::detail

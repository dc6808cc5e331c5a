// check_close.hpp: tolerance-explicit comparisons for tests.
//
// Every comparison names its tolerance, with absolute plus relative semantics:
//   |a - b| <= abs_tol + rel_tol * max(|a|, |b|)
// Tolerances are data: each test file defines one constant per quantity, with
// its unit and the reason for its value (see docs/verification.md).
#pragma once

#include <doctest/doctest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace assess::test {

struct Tol {
  double abs = 0.0;  ///< absolute tolerance, in the unit of the quantity
  double rel = 0.0;  ///< relative tolerance (dimensionless)
};

inline Tol abs_tol(double a) { return Tol{a, 0.0}; }
inline Tol rel_tol(double r) { return Tol{0.0, r}; }

inline bool is_close(double a, double b, Tol t) {
  if (!std::isfinite(a) || !std::isfinite(b)) return false;
  return std::fabs(a - b) <= t.abs + t.rel * std::max(std::fabs(a), std::fabs(b));
}

inline std::string describe(double a, double b, Tol t) {
  std::ostringstream os;
  os.precision(12);
  os << a << " vs " << b << " (diff " << std::fabs(a - b) << ", abs tol " << t.abs << ", rel tol "
     << t.rel << ")";
  return os.str();
}

template <typename A, typename B>
bool is_close(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, Tol t) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!is_close(a.derived().coeff(i), b.derived().coeff(i), t)) return false;
  return true;
}

}  // namespace assess::test

/// CHECK_CLOSE(actual, expected, tol): doctest CHECK with a named tolerance.
#define CHECK_CLOSE(actual, expected, tol)                                              \
  do {                                                                                  \
    const double check_close_a_ = (actual);                                             \
    const double check_close_b_ = (expected);                                           \
    INFO(#actual " = " << ::assess::test::describe(check_close_a_, check_close_b_, tol)); \
    CHECK(::assess::test::is_close(check_close_a_, check_close_b_, tol));              \
  } while (0)

#define REQUIRE_CLOSE(actual, expected, tol)                                            \
  do {                                                                                  \
    const double check_close_a_ = (actual);                                             \
    const double check_close_b_ = (expected);                                           \
    INFO(#actual " = " << ::assess::test::describe(check_close_a_, check_close_b_, tol)); \
    REQUIRE(::assess::test::is_close(check_close_a_, check_close_b_, tol));            \
  } while (0)

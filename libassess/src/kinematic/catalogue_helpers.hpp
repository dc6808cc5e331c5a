// catalogue_helpers.hpp: private helpers of the mechanism generators
// (mechanism_catalogue.cpp and the generators of issue 33): input checks,
// constraint and load constructors, a golden-section minimum. SI inside.
#pragma once

#include "assess/kinematic/chain.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace assess {
namespace catalogue {

using V = Eigen::Vector2d;

inline void require_positive(double v, const std::string& what, const char* unit) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(what + " = " + std::to_string(v) + ": must be > 0 " + unit);
}
inline void require_non_negative(double v, const std::string& what, const char* unit) {
  if (!(v >= 0.0) || !std::isfinite(v))
    throw InputError(what + " = " + std::to_string(v) + ": must be >= 0 " + unit);
}

inline std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

inline Constraint ground_hinge(const std::string& name, int block, V p) {
  Constraint c;
  c.type = ConstraintType::GroundHinge;
  c.name = name;
  c.block = block;
  c.point = p;
  return c;
}
inline Constraint hinge(const std::string& name, int a, int b, V p) {
  Constraint c = ground_hinge(name, a, p);
  c.type = ConstraintType::Hinge;
  c.other = b;
  return c;
}
inline Constraint weld(const std::string& name, int a, int b, V p) {
  Constraint c = hinge(name, a, b, p);
  c.type = ConstraintType::Weld;
  return c;
}
inline Constraint slider(const std::string& name, int block, V p, V direction) {
  Constraint c = ground_hinge(name, block, p);
  c.type = ConstraintType::Slider;
  c.direction = direction;
  return c;
}
inline Load weight(const std::string& name, int block, V p, double W, bool vertical = true) {
  Load l;
  l.type = LoadType::Weight;
  l.name = name;
  l.block = block;
  l.point = p;
  l.weight = W;
  l.vertical = vertical;
  return l;
}
inline Load force(LoadType type, const std::string& name, int block, V p, V F) {
  Load l;
  l.type = type;
  l.name = name;
  l.block = block;
  l.point = p;
  l.force = F;
  return l;
}

// Minimises f on [a, b] by golden-section search (unimodal f), to |b - a| <= tol.
template <class F>
double golden_minimum(F f, double a, double b, double tol) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = f(c), fd = f(d);
  while (b - a > tol) {
    if (fc < fd) {
      b = d; d = c; fd = fc; c = b - r * (b - a); fc = f(c);
    } else {
      a = c; c = d; fc = fd; d = a + r * (b - a); fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

// The wedge angles to analyse (deg): beta_deg; else from the texture,
// tan beta = (unit_length / 2) / course_height; else a grid in
// [beta_min_deg, beta_max_deg] (`searched` set).
template <class P>
inline std::vector<double> wedge_angles(const std::string& lab, const P& p, bool& searched) {
  std::vector<double> betas;
  if (p.beta_deg) {
    betas.push_back(*p.beta_deg);
  } else if (p.unit_length || p.course_height) {
    if (!p.unit_length || !p.course_height)
      throw InputError(lab + "the texture needs both unit_length and course_height (m)");
    require_positive(*p.unit_length, lab + "unit_length", "m");
    require_positive(*p.course_height, lab + "course_height", "m");
    betas.push_back(std::atan(0.5 * *p.unit_length / *p.course_height) / units::deg);
  } else {
    searched = true;
    if (!(p.beta_min_deg > 0.0 && p.beta_max_deg > p.beta_min_deg && p.beta_max_deg < 90.0))
      throw InputError(lab + "expected 0 < beta_min_deg < beta_max_deg < 90 deg");
    if (p.search_points < 2) throw InputError(lab + "search_points must be >= 2");
    for (int i = 0; i < p.search_points; ++i)
      betas.push_back(p.beta_min_deg + (p.beta_max_deg - p.beta_min_deg) * i / (p.search_points - 1));
  }
  for (double beta : betas)
    if (!(beta > 0.0 && beta < 90.0)) throw InputError(lab + "beta_deg must lie in (0, 90) deg");
  return betas;
}

}  // namespace catalogue
}  // namespace assess

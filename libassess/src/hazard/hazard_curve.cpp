// hazard_curve.cpp: lambda(IM) by log-log interpolation of the return
// periods of the hazard data (docs/theory/fragility.md §2).
#include "assess/hazard/hazard_curve.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <string>

namespace assess {

HazardCurve::HazardCurve(std::vector<HazardPoint> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw InputError("hazard curve: at least 2 points are needed");
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const HazardPoint& p = points_[i];
    if (!(p.im > 0.0) || !(p.lambda > 0.0) || !std::isfinite(p.im) || !std::isfinite(p.lambda))
      throw InputError("hazard curve: point " + std::to_string(i) + " needs im > 0 (m/s^2) and lambda > 0 (1/year)");
    if (i > 0 && !(p.im > points_[i - 1].im && p.lambda < points_[i - 1].lambda))
      throw InputError("hazard curve: the intensity must increase strictly as the annual frequency decreases (point " +
                       std::to_string(i) + ": im " + std::to_string(p.im) + " m/s^2 after " +
                       std::to_string(points_[i - 1].im) + " m/s^2)");
  }
}

std::size_t HazardCurve::segment(double im) const {
  // First segment below the first point, last above the last point.
  std::size_t i = 0;
  while (i + 2 < points_.size() && im > points_[i + 1].im) ++i;
  return i;
}

double HazardCurve::slope(double im) const {
  const std::size_t i = segment(im);
  const HazardPoint &a = points_[i], &b = points_[i + 1];
  return -std::log(b.lambda / a.lambda) / std::log(b.im / a.im);
}

double HazardCurve::lambda(double im) const {
  if (!(im > 0.0)) throw InputError("hazard curve: lambda(im) needs im > 0 (m/s^2)");
  const std::size_t i = segment(im);
  const HazardPoint& a = points_[i];
  // ln lambda = ln lambda_a - k (ln im - ln im_a): log-log line through a and b.
  return a.lambda * std::exp(-slope(im) * std::log(im / a.im));
}

double HazardCurve::im_at_tr(double tr_years) const {
  if (!(tr_years > 0.0)) throw InputError("hazard curve: the return period must be > 0 (years)");
  const double lam = 1.0 / tr_years;
  std::size_t i = 0;
  while (i + 2 < points_.size() && lam < points_[i + 1].lambda) ++i;
  const HazardPoint &a = points_[i], &b = points_[i + 1];
  const double k = -std::log(b.lambda / a.lambda) / std::log(b.im / a.im);
  return a.im * std::exp(-std::log(lam / a.lambda) / k);
}

HazardCurve site_pga_hazard_curve(const Site& site) {
  if (!site.spec().given.empty())
    throw InputError("site: the hazard is given per limit state, not as the grid's nine return periods: no hazard "
                     "curve (give \"lat\"/\"lon\" or \"island\")");
  std::vector<HazardPoint> pts;
  for (double tr : grid_return_periods) {
    const HazardParams h = site.hazard_at_tr(tr);
    // Se(0) = ag S (NTC 2018 [3.2.2] at T = 0): the PGA on the site's ground.
    const double pga = ElasticSpectrum(h, site.spec().conditions, 5.0).Se(0.0);
    pts.push_back({pga, 1.0 / tr, tr});
  }
  try {
    return HazardCurve(std::move(pts));
  } catch (const InputError& e) {
    throw InputError("site " + site.describe() + ": " + e.what());
  }
}

HazardCurve site_ag_hazard_curve(const Site& site) {
  if (!site.spec().given.empty())
    throw InputError("site: the hazard is given per limit state, not as the grid's nine return periods: no hazard "
                     "curve (give \"lat\"/\"lon\" or \"island\")");
  std::vector<HazardPoint> pts;
  for (double tr : grid_return_periods) pts.push_back({site.hazard_at_tr(tr).ag_g * units::g, 1.0 / tr, tr});
  try {
    return HazardCurve(std::move(pts));
  } catch (const InputError& e) {
    throw InputError("site " + site.describe() + ": " + e.what());
  }
}

}  // namespace assess

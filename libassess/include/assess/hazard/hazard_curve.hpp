// hazard_curve.hpp: the site's hazard curve lambda(IM), the mean annual
// frequency of exceeding an intensity IM, from the return periods of the NTC
// hazard data (NTC 2008 Allegato A/B: nine return periods 30..2475 years),
// with log-log interpolation between the points and log-log (power-law)
// extrapolation beyond them (docs/theory/fragility.md §2).
#pragma once

#include "assess/hazard/site.hpp"

#include <vector>

namespace assess {

/// A point of a hazard curve.
struct HazardPoint {
  double im = 0.0;      ///< intensity measure (here PGA on the site's ground, m/s^2)
  double lambda = 0.0;  ///< mean annual frequency of exceedance (1/year) = 1/TR
  double TR = 0.0;      ///< return period (years)
};

/// lambda(im) through points with increasing im and decreasing lambda.
/// Between two points ln(lambda) is linear in ln(im) (the same log-log rule
/// Allegato A eq. 2 uses between return periods); below the first and above
/// the last point the end segments' power laws lambda = k0 im^-k continue.
class HazardCurve {
 public:
  /// @throws InputError unless there are >= 2 points, im > 0 strictly
  ///   increasing and lambda > 0 strictly decreasing.
  explicit HazardCurve(std::vector<HazardPoint> points);

  /// Mean annual frequency of exceeding im (1/year), im > 0 (m/s^2).
  double lambda(double im) const;
  /// Local log-log slope k = -d ln(lambda) / d ln(im) at im (-), > 0.
  double slope(double im) const;
  /// |d lambda / d im| at im (1/year per m/s^2) = k lambda / im.
  double density(double im) const { return slope(im) * lambda(im) / im; }
  /// The intensity whose return period is TR (years): the inverse of lambda.
  double im_at_tr(double tr_years) const;

  const std::vector<HazardPoint>& points() const { return points_; }

 private:
  std::vector<HazardPoint> points_;
  std::size_t segment(double im) const;  // index i of the segment [i, i+1] used for im
};

/// The hazard curve of PGA on the site's ground, IM = Se(T = 0) = ag S (m/s^2)
/// (NTC 2018 [3.2.2]-[3.2.4]: S = SS ST from the site's subsoil and
/// topography), at the nine return periods of the grid (or of an island):
/// lambda = 1/TR. A site with hazard "given" per limit state cannot give a
/// curve. @throws InputError naming the reason.
HazardCurve site_pga_hazard_curve(const Site& site);

/// The hazard curve of ag on rock (m/s^2) at the nine return periods, for
/// the return period of an ag capacity of the code's checks. @throws InputError
HazardCurve site_ag_hazard_curve(const Site& site);

}  // namespace assess

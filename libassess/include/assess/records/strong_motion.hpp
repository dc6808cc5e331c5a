// strong_motion.hpp: Arias intensity of an accelerogram and the times that
// bound its strong motion (significant duration, end of strong motion).
#pragma once

#include "assess/records/record.hpp"

#include <vector>

namespace assess {

/// Cumulative Arias intensity I(t_i) = pi/(2 g) * integral_0^t_i a^2 dt (m/s),
/// Arias (1970); trapezoidal on the piecewise-linear record, exact for a^2
/// integrated as the square of a linear function per step. One value per sample.
std::vector<double> cumulative_arias(const Record& record);

/// Total Arias intensity (m/s).
double arias_intensity(const Record& record);

/// First time (s) at which the cumulative Arias intensity reaches `fraction`
/// (0..1) of its total, linear between samples. 0 for a zero record.
double arias_time(const Record& record, double fraction);

/// Significant duration D_{lo-hi} = t(hi) - t(lo) (s), Trifunac & Brady (1975);
/// default 5-95 %.
double significant_duration(const Record& record, double lo = 0.05, double hi = 0.95);

}  // namespace assess

namespace assess {

/// The record up to the end of its strong motion: the first sample at or
/// after arias_time(record, fraction) (default 99.9 % of the Arias
/// intensity), inclusive. Same dt, name and metadata; never empty.
Record strong_motion_part(const Record& record, double fraction = 0.999);

}  // namespace assess

// response_spectrum.cpp: exact SDOF response to a piecewise-linear record.
//
// Notation (Nigam & Jennings 1969, BSSA 59(2):909-922; Chopra, Dynamics of
// Structures, §5.2):
//   T, w = 2 pi / T   natural period (s) and circular frequency (rad/s)
//   xi                damping ratio (fraction of critical)
//   u, v              relative displacement (m) and velocity (m/s)
//   p = -ag           effective load per unit mass (m/s^2), linear in a step
//   h                 time step of the recurrence (s); wh = w h (-)
//   SD = max|u|, PSA = w^2 SD, PSV = w SD, SA = max|u'' + ag|
//
// Equation of motion: u'' + 2 xi w u' + w^2 u = p(t), p(t) = p0 + s t in a step.
// With tau = w t and the scaled state y = [u, v/w, p/w^2, s/w^3] it becomes
// the autonomous linear system dy/dtau = K y,
//   K = [[0, 1, 0, 0], [-1, -2 xi, 1, 0], [0, 0, 0, 1], [0, 0, 0, 0]],
// so y(h) = exp(K w h) y(0) exactly (the Nigam-Jennings recurrence is this
// exponential written out in closed form). Evaluating exp by scaling and
// squaring of its Taylor series keeps every coefficient to near machine
// precision for w h -> 0 (long periods), where the closed forms of Chopra
// Tab. 5.2.1 lose digits to cancellation, and for w h >> 1 (short periods).
#include "assess/records/response_spectrum.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

namespace assess {

namespace {

/// exp(X) of a 4x4 matrix: halve X until ||X||_1 <= 1/2, sum 20 Taylor terms
/// (truncation < 0.5^20/20! ~ 4e-25 relative), then square back.
Eigen::Matrix4d expm(Eigen::Matrix4d X) {
  const double norm = X.cwiseAbs().colwise().sum().maxCoeff();
  int squarings = 0;
  if (norm > 0.5) squarings = static_cast<int>(std::ceil(std::log2(norm / 0.5)));
  X /= std::ldexp(1.0, squarings);
  Eigen::Matrix4d E = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d term = Eigen::Matrix4d::Identity();
  for (int k = 1; k <= 20; ++k) {
    term = (term * X) / double(k);
    E += term;
  }
  for (int i = 0; i < squarings; ++i) E = E * E;
  return E;
}

void check_record(const Record& r) {
  if (!(r.dt > 0.0) || !std::isfinite(r.dt))
    throw InputError("record '" + r.name + "': dt must be a positive time step (s)");
  if (r.acc.empty()) throw InputError("record '" + r.name + "': no acceleration samples");
  for (double a : r.acc)
    if (!std::isfinite(a))
      throw InputError("record '" + r.name + "': non-finite acceleration sample (m/s^2)");
}

void check_period(double T) {
  if (!(T >= 0.0) || !std::isfinite(T))
    throw InputError("period T must be finite and >= 0 (s), got " + std::to_string(T));
}

/// Extremum of the cubic Hermite interpolant of u on a step of length h
/// where v changes sign (v0 * v1 < 0): returns |u| at the stationary point.
double hermite_peak(double u0, double v0, double u1, double v1, double h) {
  // du/ds = a s^2 + b s + c on s in [0, 1]; one root in (0, 1) since c and
  // a + b + c = h v1 have opposite signs.
  const double a = 6.0 * (u0 - u1) + 3.0 * h * (v0 + v1);
  const double b = 6.0 * (u1 - u0) - h * (4.0 * v0 + 2.0 * v1);
  const double c = h * v0;
  double s;
  if (std::fabs(a) <= 1e-12 * (std::fabs(b) + std::fabs(c))) {
    s = -c / b;
  } else {
    const double disc = std::sqrt(std::max(0.0, b * b - 4.0 * a * c));
    const double q = -0.5 * (b + std::copysign(disc, b));
    const double s1 = q / a, s2 = (q != 0.0) ? c / q : s1;
    s = (s1 >= 0.0 && s1 <= 1.0) ? s1 : s2;
  }
  s = std::clamp(s, 0.0, 1.0);
  const double s2 = s * s, s3 = s2 * s;
  return std::fabs((2 * s3 - 3 * s2 + 1) * u0 + (s3 - 2 * s2 + s) * h * v0 +
                   (-2 * s3 + 3 * s2) * u1 + (s3 - s2) * h * v1);
}

}  // namespace

void ResponseOptions::validate() const {
  if (!(damping_ratio >= 0.0) || !std::isfinite(damping_ratio))
    throw InputError("damping_ratio must be a finite fraction >= 0 (0.05 = 5 %)");
  if (min_steps_per_period < 1) throw InputError("min_steps_per_period must be >= 1");
}

SdofRecurrence sdof_recurrence(double T, double damping_ratio, double h) {
  if (!(T > 0.0) || !std::isfinite(T)) throw InputError("sdof_recurrence: period T must be > 0 (s)");
  if (!(h > 0.0) || !std::isfinite(h)) throw InputError("sdof_recurrence: step h must be > 0 (s)");
  if (!(damping_ratio >= 0.0) || !std::isfinite(damping_ratio))
    throw InputError("sdof_recurrence: damping_ratio must be >= 0 (fraction)");
  const double w = 2.0 * units::pi / T;
  const double wh = w * h;
  Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
  K(0, 1) = 1.0;
  K(1, 0) = -1.0;
  K(1, 1) = -2.0 * damping_ratio;
  K(1, 2) = 1.0;
  K(2, 3) = 1.0;
  const Eigen::Matrix4d E = expm(K * wh);
  // Back to physical variables: u0, v0/w, p0/w^2, (p1 - p0)/(h w^3).
  SdofRecurrence c;
  c.a_uu = E(0, 0);
  c.a_uv = E(0, 1) / w;
  c.a_up0 = (E(0, 2) - E(0, 3) / wh) / (w * w);
  c.a_up1 = E(0, 3) / wh / (w * w);
  c.a_vu = w * E(1, 0);
  c.a_vv = E(1, 1);
  c.a_vp0 = (E(1, 2) - E(1, 3) / wh) / w;
  c.a_vp1 = E(1, 3) / wh / w;
  return c;
}

SdofHistory sdof_response(const Record& record, double T, double damping_ratio) {
  check_record(record);
  const SdofRecurrence c = sdof_recurrence(T, damping_ratio, record.dt);
  const double w = 2.0 * units::pi / T;
  const std::size_t n = record.size();
  SdofHistory hist;
  hist.u.assign(n, 0.0);
  hist.v.assign(n, 0.0);
  hist.a_abs.assign(n, 0.0);
  hist.a_abs[0] = 0.0;  // at rest: u'' = -ag, so u'' + ag = 0
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double p0 = -record.acc[i], p1 = -record.acc[i + 1];
    const double u = hist.u[i], v = hist.v[i];
    hist.u[i + 1] = c.a_uu * u + c.a_uv * v + c.a_up0 * p0 + c.a_up1 * p1;
    hist.v[i + 1] = c.a_vu * u + c.a_vv * v + c.a_vp0 * p0 + c.a_vp1 * p1;
    hist.a_abs[i + 1] = -2.0 * damping_ratio * w * hist.v[i + 1] - w * w * hist.u[i + 1];
  }
  return hist;
}

namespace {

/// Largest |s^3 - 2 s^2 + s| and |s^3 - s^2| on [0, 1]: 4/27 (at s = 1/3, 2/3),
/// the slope weights of the cubic Hermite interpolant (hermite_peak).
constexpr double hermite_slope_bound = 4.0 / 27.0;
/// Relative margin on that bound for the rounding of hermite_peak's sums
/// (a few ulps): a peak within it is computed, never skipped.
constexpr double hermite_bound_margin = 1.0 + 1e-9;

/// Sub-steps per record step at period T > 0: h = dt/m <= T/min_steps_per_period.
int substeps(double dt, double T, const ResponseOptions& opts) {
  const double m_real = std::ceil(dt * opts.min_steps_per_period / T);
  return static_cast<int>(std::max(1.0, m_real));
}

/// The ordinates at L periods T[0..L-1] > 0 that share the same number of
/// sub-steps m, integrated side by side (lock-step): each lane is the
/// recurrence of one period, with exactly the arithmetic of a single period,
/// so the results are those of one period at a time, bit for bit; the lanes
/// only let the processor overlap L independent chains of dependent
/// multiplications (the recurrence is latency-bound, §1 of
/// docs/theory/record-selection.md).
template <int L>
void ordinates_lanes(const Record& record, const double* T, int m, const ResponseOptions& opts,
                     SpectralOrdinates* out) {
  const double xi = opts.damping_ratio;
  const double h = record.dt / m;
  double auu[L], auv[L], aup0[L], aup1[L], avu[L], avv[L], avp0[L], avp1[L], w[L], w2[L], cv[L];
  double u[L], v[L], sd[L], sv[L], sa[L];
  for (int l = 0; l < L; ++l) {
    const SdofRecurrence c = sdof_recurrence(T[l], xi, h);
    auu[l] = c.a_uu, auv[l] = c.a_uv, aup0[l] = c.a_up0, aup1[l] = c.a_up1;
    avu[l] = c.a_vu, avv[l] = c.a_vv, avp0[l] = c.a_vp0, avp1[l] = c.a_vp1;
    w[l] = 2.0 * units::pi / T[l];
    w2[l] = w[l] * w[l];
    cv[l] = 2.0 * xi * w[l];
    u[l] = v[l] = sd[l] = sv[l] = sa[l] = 0.0;
  }
  const std::size_t n = record.size();
  const double* acc = record.acc.data();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double pa = -acc[i], dp = (acc[i] - acc[i + 1]) / m;
    for (int k = 0; k < m; ++k) {
      const double p0 = pa + k * dp, p1 = pa + (k + 1) * dp;
      double u1[L], v1[L];
      for (int l = 0; l < L; ++l) {
        u1[l] = auu[l] * u[l] + auv[l] * v[l] + aup0[l] * p0 + aup1[l] * p1;
        v1[l] = avu[l] * u[l] + avv[l] * v[l] + avp0[l] * p0 + avp1[l] * p1;
      }
      for (int l = 0; l < L; ++l) {
        sd[l] = std::max(sd[l], std::fabs(u1[l]));
        sv[l] = std::max(sv[l], std::fabs(v1[l]));
        sa[l] = std::max(sa[l], std::fabs(cv[l] * v1[l] + w2[l] * u1[l]));
      }
      // A turning point of u inside the sub-step: its peak on the cubic Hermite
      // interpolant, computed only when it can exceed sd. The interpolant is
      // bounded by max(|u0|, |u1|) + (4/27) h (|v0| + |v1|) (the position
      // weights are a convex pair; each slope weight is at most 4/27 in
      // magnitude on [0, 1]), so a skipped peak could not have changed sd:
      // the ordinates are those of computing every peak, bit for bit.
      for (int l = 0; l < L; ++l)
        if (((v[l] > 0.0 && v1[l] < 0.0) || (v[l] < 0.0 && v1[l] > 0.0)) &&
            (std::max(std::fabs(u[l]), std::fabs(u1[l])) + hermite_slope_bound * h * (std::fabs(v[l]) + std::fabs(v1[l]))) *
                    hermite_bound_margin >
                sd[l])
          sd[l] = std::max(sd[l], hermite_peak(u[l], v[l], u1[l], v1[l], h));
      for (int l = 0; l < L; ++l) u[l] = u1[l], v[l] = v1[l];
    }
  }
  for (int l = 0; l < L; ++l) {
    out[l].T = T[l];
    out[l].SD = sd[l];
    out[l].SV = sv[l];
    out[l].PSA = w2[l] * sd[l];
    out[l].PSV = w[l] * sd[l];
    out[l].SA = sa[l];
  }
}

/// spectral_ordinates() for an already validated record and options.
SpectralOrdinates ordinates_of(const Record& record, double T, const ResponseOptions& opts) {
  check_period(T);
  SpectralOrdinates out;
  out.T = T;
  if (T == 0.0) {  // rigid oscillator follows the ground: u = 0, u'' + ag = ag
    out.PSA = out.SA = record.pga();
    return out;
  }
  ordinates_lanes<1>(record, &T, substeps(record.dt, T, opts), opts, &out);
  return out;
}

}  // namespace

SpectralOrdinates spectral_ordinates(const Record& record, double T, const ResponseOptions& opts) {
  opts.validate();
  check_record(record);
  return ordinates_of(record, T, opts);
}

ResponseSpectrum response_spectrum(const Record& record, const std::vector<double>& periods,
                                   const ResponseOptions& opts) {
  opts.validate();
  check_record(record);
  ResponseSpectrum rs;
  rs.damping_ratio = opts.damping_ratio;
  rs.ordinates.resize(periods.size());
  // Periods with the same number of sub-steps go through the recurrence four
  // at a time (ordinates_lanes: the same numbers as one at a time).
  std::vector<std::pair<int, std::size_t>> order;  // (sub-steps, position)
  for (std::size_t j = 0; j < periods.size(); ++j) {
    check_period(periods[j]);
    if (periods[j] == 0.0) rs.ordinates[j] = ordinates_of(record, 0.0, opts);
    else order.emplace_back(substeps(record.dt, periods[j], opts), j);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  constexpr int L = 4;
  for (std::size_t g = 0; g < order.size();) {
    std::size_t e = g;
    while (e < order.size() && e - g < std::size_t(L) && order[e].first == order[g].first) ++e;
    double T[L];
    SpectralOrdinates o[L];
    for (std::size_t k = g; k < e; ++k) T[k - g] = periods[order[k].second];
    if (e - g == std::size_t(L)) ordinates_lanes<L>(record, T, order[g].first, opts, o);
    else
      for (std::size_t k = g; k < e; ++k) ordinates_lanes<1>(record, &T[k - g], order[g].first, opts, &o[k - g]);
    for (std::size_t k = g; k < e; ++k) rs.ordinates[order[k].second] = o[k - g];
    g = e;
  }
  return rs;
}

std::vector<double> ResponseSpectrum::periods() const {
  std::vector<double> x;
  for (const auto& o : ordinates) x.push_back(o.T);
  return x;
}
std::vector<double> ResponseSpectrum::psa() const {
  std::vector<double> x;
  for (const auto& o : ordinates) x.push_back(o.PSA);
  return x;
}
std::vector<double> ResponseSpectrum::sd() const {
  std::vector<double> x;
  for (const auto& o : ordinates) x.push_back(o.SD);
  return x;
}

std::vector<double> log_spaced_periods(double T_min, double T_max, int n) {
  if (!(T_min > 0.0) || !(T_max > T_min) || !std::isfinite(T_max) || n < 2)
    throw InputError("log_spaced_periods: need 0 < T_min < T_max (s) and n >= 2");
  std::vector<double> T(static_cast<std::size_t>(n));
  const double r = std::log(T_max / T_min) / (n - 1);
  for (int i = 0; i < n; ++i) T[std::size_t(i)] = T_min * std::exp(r * i);
  T.back() = T_max;
  return T;
}

}  // namespace assess

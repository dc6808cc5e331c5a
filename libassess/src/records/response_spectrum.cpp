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

/// spectral_ordinates() for an already validated record and options.
SpectralOrdinates ordinates_of(const Record& record, double T, const ResponseOptions& opts) {
  check_period(T);
  SpectralOrdinates out;
  out.T = T;
  if (T == 0.0) {  // rigid oscillator follows the ground: u = 0, u'' + ag = ag
    out.PSA = out.SA = record.pga();
    return out;
  }
  const double xi = opts.damping_ratio;
  const double w = 2.0 * units::pi / T;
  // Sub-steps m per record step so that h = dt/m <= T/min_steps_per_period.
  const double m_real = std::ceil(record.dt * opts.min_steps_per_period / T);
  const int m = static_cast<int>(std::max(1.0, m_real));
  const double h = record.dt / m;
  const SdofRecurrence c = sdof_recurrence(T, xi, h);

  double u = 0.0, v = 0.0, sd = 0.0, sv = 0.0, sa = 0.0;
  const std::size_t n = record.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double pa = -record.acc[i], dp = (record.acc[i] - record.acc[i + 1]) / m;
    for (int k = 0; k < m; ++k) {
      const double p0 = pa + k * dp, p1 = pa + (k + 1) * dp;
      const double u1 = c.a_uu * u + c.a_uv * v + c.a_up0 * p0 + c.a_up1 * p1;
      const double v1 = c.a_vu * u + c.a_vv * v + c.a_vp0 * p0 + c.a_vp1 * p1;
      sd = std::max(sd, std::fabs(u1));
      if ((v > 0.0 && v1 < 0.0) || (v < 0.0 && v1 > 0.0))
        sd = std::max(sd, hermite_peak(u, v, u1, v1, h));
      sv = std::max(sv, std::fabs(v1));
      sa = std::max(sa, std::fabs(2.0 * xi * w * v1 + w * w * u1));
      u = u1;
      v = v1;
    }
  }
  out.SD = sd;
  out.SV = sv;
  out.PSA = w * w * sd;
  out.PSV = w * sd;
  out.SA = sa;
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
  rs.ordinates.reserve(periods.size());
  for (double T : periods) rs.ordinates.push_back(ordinates_of(record, T, opts));
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

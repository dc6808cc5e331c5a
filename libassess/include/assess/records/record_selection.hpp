// record_selection.hpp: choose N records and linear scale factors whose mean
// 5 %-damped spectrum stays within a tolerance band (-10 %/+30 % by default,
// NTC 2018 §3.2.3.6; REXEL, Iervolino, Galasso & Cosenza 2010) of a target
// elastic spectrum over a period range.
#pragma once

#include "assess/records/record.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/hazard/spectrum.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace assess {

/// How each candidate record is scaled before the combination is chosen.
enum class ScaleRule {
  /// f minimises sum_j ln^2(f S(T_j)/Se(T_j)) over the check periods (least
  /// squares in log space): f = exp(-mean_j ln rho_j), so the geometric mean
  /// of the scaled ratio is 1 and its arithmetic mean >= 1, toward the wider
  /// (+30 %) side of the band. A linear least-squares fit of the ratio would
  /// give mean ratio mean(rho)^2/mean(rho^2) <= 1, toward the -10 % limit.
  LeastSquares,
  /// f = Se(0) / PGA: the record's PGA matches the target's (ag S).
  Pga,
};

/// A period range [T_min, T_max] (s).
struct PeriodRange {
  double T_min = 0.15;  ///< s
  double T_max = 2.0;   ///< s
};

/// Default range for a rocking mechanism: [0.5 T_first, 1.5 T_last] clipped
/// to [0.1, 4] s, where T_first is the shortest and T_last the longest
/// secant period of interest (e.g. Ts at SLD and T_SLC of Circ. 2019
/// [C8.7.1.11]); see docs/theory/record-selection.md.
/// @param T_first shortest mechanism period (s) > 0
/// @param T_last longest mechanism period (s) >= T_first
PeriodRange rocking_period_range(double T_first, double T_last);

/// Settings of the selection. Defaults: 7 records, REXEL band -10 %/+30 %,
/// scale factors <= 5, least-squares scaling, 40 log-spaced check periods.
struct SelectionOptions {
  int n_records = 7;                 ///< N (>= 1)
  PeriodRange range{};               ///< check range (s), 0 < T_min < T_max
  double lower_tol = 0.10;           ///< mean >= (1 - lower_tol) Se over the range (-)
  double upper_tol = 0.30;           ///< mean <= (1 + upper_tol) Se over the range (-)
  double max_scale = 5.0;            ///< records needing f > max_scale are rejected (-)
  ScaleRule scale_rule = ScaleRule::LeastSquares;
  int n_periods = 40;                ///< log-spaced check periods in the range (>= 2)
  double damping_ratio = 0.05;       ///< xi of the record spectra (fraction)
  /// Exhaustive search when C(n_eligible, N) <= this; otherwise greedy
  /// forward selection followed by best-swap improvement.
  double max_combinations = 2e6;

  /// Throws InputError naming the field when a value is out of range.
  void validate() const;
};

/// One chosen record.
struct SelectedRecord {
  std::size_t index = 0;      ///< position in the candidate vector
  std::string name;           ///< Record::name
  double scale = 1.0;         ///< linear scale factor f (-)
  std::vector<double> psa;    ///< f * PSA at the check periods (m/s^2)
};

/// A candidate that cannot be used.
struct RejectedRecord {
  std::size_t index = 0;
  std::string name;
  double scale = 0.0;   ///< the factor it would need (-)
  std::string reason;
};

/// Outcome of select_records().
struct SelectionResult {
  enum class Status {
    Compatible,          ///< N records, band satisfied
    NotCompatible,       ///< N records, the best set violates the band
    FewerThanRequested,  ///< fewer than N eligible candidates; all are returned
  };
  Status status = Status::NotCompatible;
  std::vector<SelectedRecord> records;   ///< in candidate order
  std::vector<RejectedRecord> rejected;
  std::vector<double> periods;   ///< check periods (s)
  std::vector<double> target;    ///< Se at the check periods (m/s^2)
  std::vector<double> mean_psa;  ///< mean of the scaled record spectra (m/s^2)
  double min_ratio = 0.0;        ///< min over the range of mean/Se (-)
  double max_ratio = 0.0;        ///< max over the range of mean/Se (-)
  double rms_deviation = 0.0;    ///< sqrt(mean_j (mean/Se - 1)^2) (-)
  /// sum_j of the excursions of mean/Se outside the band (-); 0 if satisfied
  double band_violation = 0.0;
  bool band_satisfied = false;   ///< 1 - lower_tol <= mean/Se <= 1 + upper_tol everywhere
  bool exhaustive = false;       ///< true if every combination was examined
  double combinations = 0.0;     ///< number of sets evaluated
  std::string message;           ///< one line for the report
};

std::string to_string(SelectionResult::Status s);

/// Chooses the N candidates (and their scale factors) whose mean scaled
/// spectrum is closest (RMS of mean/Se - 1) to the target among the sets
/// that satisfy the band; if none does, the set with the smallest band
/// violation. Deterministic: ties go to the first set in lexicographic order.
/// @param target elastic spectrum T (s) -> Se (m/s^2), > 0 on the range
/// @param candidates records (dt in s, acc in m/s^2)
SelectionResult select_records(const std::function<double(double)>& target,
                               const std::vector<Record>& candidates,
                               const SelectionOptions& opts = {});

/// The check periods of a selection: opts.n_periods log-spaced in opts.range (s).
std::vector<double> selection_periods(const SelectionOptions& opts);

/// Same as select_records(target, candidates, opts) with the candidates'
/// spectra at selection_periods(opts) and opts.damping_ratio given (computed
/// once for several selections with the same options, e.g. the stripes of a
/// fragility analysis). @throws InputError if the sizes do not match.
SelectionResult select_records(const std::function<double(double)>& target, const std::vector<Record>& candidates,
                               const SelectionOptions& opts, const std::vector<ResponseSpectrum>& spectra);

/// Same, with the horizontal elastic spectrum Se(T) of a site as target.
inline SelectionResult select_records(const ElasticSpectrum& target, const std::vector<Record>& candidates,
                                      const SelectionOptions& opts = {}) {
  return select_records([&target](double T) { return target.Se(T); }, candidates, opts);
}

}  // namespace assess

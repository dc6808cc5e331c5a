// record_selection.hpp: choose N records and linear scale factors whose mean
// 5 %-damped spectrum stays within a tolerance band (-10 %/+30 % by default,
// NTC 2018 §3.2.3.6; REXEL, Iervolino, Galasso & Cosenza 2010) of a target
// elastic spectrum over a period range.
#pragma once

#include "assess/records/record.hpp"
#include "assess/records/record_catalogue.hpp"
#include "assess/hazard/spectrum.hpp"
#include "assess/support/number_rules.hpp"

#include <cstddef>
#include <functional>
#include <limits>
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

/// Factors and bounds of rocking_period_range (s, record-selection.md §2.3).
inline constexpr double rocking_range_lower_factor = 0.5, rocking_range_upper_factor = 1.5;
inline constexpr double rocking_range_floor_s = 0.1, rocking_range_cap_s = 4.0;

/// Default range for a rocking mechanism: [0.5 T_first, 1.5 T_last] clipped
/// to [0.1, 4] s, where T_first is the shortest and T_last the longest
/// secant period of interest (e.g. Ts at SLD and T_SLC of Circ. 2019
/// [C8.7.1.11]); see docs/theory/record-selection.md.
/// @param T_first shortest mechanism period (s) > 0
/// @param T_last longest mechanism period (s) >= T_first
PeriodRange rocking_period_range(double T_first, double T_last);

/// The ranges of a selection's settings, in their units: one place for the
/// case file's /dynamic/select, `assess records select` and `assess
/// fragility` (issue 39: the command line took a near-fault distance of -1 km,
/// a PGA guard of 0 or 1e308).
namespace selection_rules {
inline constexpr int count_max = 50;  ///< records of a set (and --count, per_event, per_station)
inline constexpr NumberRule max_scale{"-", 1.0, 100.0, false, false,
                                      "largest scale factor of a record; NTC practice keeps it near 2-3"};
inline constexpr NumberRule max_mean_scale{"-", 0.1, 100.0, false, false, "largest mean scale factor of a set"};
inline constexpr NumberRule max_pga_ratio{"-", 0.5, 10.0, false, false,
                                          "the guard on a scaled record's PGA, as a multiple of ag S"};
inline constexpr NumberRule Mw{"-", 2.0, 10.0, false, false, "a moment magnitude"};
inline constexpr NumberRule distance_km{"km", 0.0, 1000.0, false, false, "a source-to-site distance"};
inline constexpr NumberRule near_fault_km{"km", 0.0, 100.0, false, false,
                                          "the distance below which a record is near-fault (10 km by default)"};
inline constexpr NumberRule max_misfit{"-", 0.01, 10.0, false, false, "RMS of f S/Se - 1 over the range"};
inline constexpr NumberRule period_s{"s", 0.01, 10.0, false, false,
                                     "a period of the check range, within the library's spectra (0.01-10 s)"};
}  // namespace selection_rules

/// Settings of the selection (docs/theory/record-selection.md §2). Defaults:
/// 7 records, band -10 %/+30 %, each scale factor <= 3, mean scale factor
/// <= 2, scaled PGA <= 2.5 Se(0) (= 2.5 ag S), at most 1 component per
/// station and 3 per event, least-squares scaling, 40 log-spaced periods.
struct SelectionOptions {
  int n_records = 7;                 ///< N (>= 1)
  PeriodRange range{};               ///< check range (s), 0 < T_min < T_max
  double lower_tol = 0.10;           ///< mean >= (1 - lower_tol) Se over the range (-)
  double upper_tol = 0.30;           ///< mean <= (1 + upper_tol) Se over the range (-)
  /// Records needing f > max_scale are rejected (-): 3, record-selection.md §2.4.
  double max_scale = 3.0;
  double max_mean_scale = 2.0;       ///< sets whose mean f exceeds this are not formed (-)
  /// Guard: a record whose scaled PGA exceeds max_pga_ratio * Se(0) (= ag S
  /// for an NTC spectrum) is rejected (-). 0 disables (not recommended).
  double max_pga_ratio = 2.5;
  int max_per_event = 3;             ///< components of one event in the set (>= 1)
  int max_per_station = 1;           ///< components of one station (same event) in the set (>= 1)
  ScaleRule scale_rule = ScaleRule::LeastSquares;
  int n_periods = 40;                ///< log-spaced check periods in the range (>= 2)
  double damping_ratio = 0.05;       ///< xi of the record spectra (fraction)
  /// Exhaustive search when C(n_eligible, N) <= this; otherwise the
  /// candidates are ranked by their individual deviation and every
  /// combination of the best `pool_size` is examined (REXEL-style); if that
  /// is still too many, greedy forward selection plus best swaps on the pool.
  double max_combinations = 2e6;
  int pool_size = 28;                ///< ranked candidates combined (>= N); C(28, 7) = 1.18e6
  /// A chosen record whose individual misfit (`SelectedRecord::deviation`)
  /// exceeds this is flagged (-, record-selection.md §2.4); it is not excluded.
  double max_misfit = 0.5;

  /// Throws InputError naming the field when a value is out of range.
  void validate() const;
};

/// What the selection needs to know of a candidate besides its samples.
struct CandidateInfo {
  std::string event;    ///< grouping key for max_per_event ("" = its own event)
  std::string station;  ///< grouping key for max_per_station (with the event)
  /// Longest usable period 1/f_low (s); +inf if unknown. A record is
  /// rejected when it is shorter than the range's T_max.
  double max_usable_period_s = std::numeric_limits<double>::infinity();
};

/// One chosen record.
struct SelectedRecord {
  std::size_t index = 0;      ///< position in the candidate vector
  std::string name;           ///< Record::name
  double scale = 1.0;         ///< linear scale factor f (-)
  double scaled_pga = 0.0;    ///< f * PGA (m/s^2)
  double deviation = 0.0;     ///< individual RMS of f S/Se - 1 over the range (-)
  int rank = 0;               ///< 1 = closest individual match among the eligible
  bool misfit_flag = false;   ///< deviation > SelectionOptions::max_misfit
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
  std::size_t eligible = 0;      ///< candidates passing the per-record limits
  std::size_t pool = 0;          ///< candidates combined (the best `pool` by deviation)
  double mean_scale = 0.0;       ///< mean f of the set (-)
  double max_scaled_pga = 0.0;   ///< largest f * PGA of the set (m/s^2)
  double target_pga = 0.0;       ///< Se(0) of the target (m/s^2)
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

/// Same, with event/station grouping and usable period of each candidate
/// (info.size() == candidates.size()).
SelectionResult select_records(const std::function<double(double)>& target,
                               const std::vector<Record>& candidates, const std::vector<CandidateInfo>& info,
                               const SelectionOptions& opts);

/// Filters of the catalogue applied before any file is read
/// (docs/theory/record-selection.md §2.1). Windows are inclusive.
struct CatalogueFilters {
  double Mw_min = 5.5, Mw_max = 7.5;          ///< default window (-), a DEFAULT: see warnings
  double R_min_km = 0.0, R_max_km = 50.0;     ///< default window (km), any distance kind
  bool Mw_given = false, R_given = false;     ///< false: the defaults were used (warned)
  /// Accepted site classes; empty = any. The caller usually passes the site's class.
  std::vector<std::string> site_classes;
  /// If fewer than min_candidates remain, widen the site classes to the
  /// neighbours (A-B-C-D; E with C, D), then to any class, with a warning.
  bool relax_site_class = true;
  std::size_t min_candidates = 21;            ///< 3 N for N = 7
  std::vector<std::string> countries;         ///< empty = any
};

/// Result of filter_catalogue().
struct CatalogueFilterResult {
  std::vector<CatalogueEntry> kept;
  std::vector<RejectedRecord> rejected;  ///< index = position in the input
  std::vector<std::string> site_classes;  ///< classes finally accepted (empty = any)
  std::vector<std::string> warnings;
};

/// The site classes tried in turn (docs/theory/record-selection.md §2.2):
/// `classes`; if `relax`, then with their neighbours (A-B-C-D; E with C and
/// D); then any class (an empty list). Empty `classes`: one step, any class.
std::vector<std::vector<std::string>> site_class_ladder(const std::vector<std::string>& classes, bool relax);

/// Applies the filters to the design candidates (usable_for_design) of a catalogue.
CatalogueFilterResult filter_catalogue(const std::vector<CatalogueEntry>& entries, const CatalogueFilters& f);

/// CandidateInfo of a catalogue entry (event + date as event key, station
/// code or name as station key, 1/lowest_usable_hz).
CandidateInfo candidate_info(const CatalogueEntry& e);

/// Same, with the horizontal elastic spectrum Se(T) of a site as target.
inline SelectionResult select_records(const ElasticSpectrum& target, const std::vector<Record>& candidates,
                                      const SelectionOptions& opts = {}) {
  return select_records([&target](double T) { return target.Se(T); }, candidates, opts);
}

}  // namespace assess

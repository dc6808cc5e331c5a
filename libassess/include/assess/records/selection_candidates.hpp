// selection_candidates.hpp: the candidate records of a selection with their
// 5 %-damped response spectra at the check periods, computed once and owned
// by the caller, so that several selections over the same candidates (the
// stripes of a fragility study: one target spectrum per return period) do
// not recompute them. A record's spectrum scales linearly with its scale
// factor (the oscillator is linear: S(f a) = f S(a)), so the unscaled PSA is
// all the selection needs (docs/theory/record-selection.md §2).
#pragma once

#include "assess/records/record.hpp"
#include "assess/records/record_selection.hpp"

#include "assess/records/record_spectra.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace assess {

/// Candidates with their spectra at the check periods of a period range.
/// Depends on the options' range, n_periods and damping_ratio only; a
/// selection with other values of these three is refused (InputError).
class SelectionCandidates {
 public:
  SelectionCandidates() = default;
  /// One candidate: what the selection reads of it.
  struct Candidate {
    std::string name;          ///< Record::name
    double pga = 0.0;          ///< max |a| of the record (m/s^2)
    CandidateInfo info;        ///< event/station grouping, usable period
    /// false: shorter usable period than the range's T_max (no spectrum computed)
    bool usable = false;
    std::vector<double> psa;   ///< unscaled PSA at periods() (m/s^2), empty if !usable
  };

  /// Computes the spectra of `records` (dt in s, acc in m/s^2) at the check
  /// periods of `opts` (log-spaced, opts.range, opts.n_periods; damping
  /// opts.damping_ratio), on all cores, skipping records whose usable period
  /// 1/f_low is shorter than opts.range.T_max. info.size() == records.size().
  SelectionCandidates(const std::vector<Record>& records, const std::vector<CandidateInfo>& info,
                      const SelectionOptions& opts);
  /// Same, each record its own event and station ("#i").
  SelectionCandidates(const std::vector<Record>& records, const SelectionOptions& opts);
  /// Candidates whose spectra are precomputed on a period grid (the record
  /// library's, record_spectra.hpp): rows[i] is candidate i's position in
  /// spectra.ids; its PSA at the check periods is interpolated log-log
  /// between grid periods (LibrarySpectra::interpolate), its PGA is the T = 0
  /// ordinate. names, info and rows have one element per candidate.
  /// @throws InputError if the grid lacks opts.damping_ratio or ends before opts.range.T_max
  SelectionCandidates(const LibrarySpectra& spectra, const std::vector<std::size_t>& rows,
                      const std::vector<std::string>& names, const std::vector<CandidateInfo>& info,
                      const SelectionOptions& opts);

  const std::vector<double>& periods() const { return periods_; }  ///< check periods (s)
  const std::vector<Candidate>& candidates() const { return candidates_; }
  std::size_t size() const { return candidates_.size(); }
  const PeriodRange& range() const { return range_; }                ///< s
  int n_periods() const { return n_periods_; }
  double damping_ratio() const { return damping_ratio_; }            ///< fraction
  /// true: the PSA were interpolated on a precomputed grid; false: integrated.
  bool interpolated() const { return interpolated_; }

  /// The candidates at positions `which` (in that order), their spectra
  /// copied: for selections over subsets of one set of candidates.
  SelectionCandidates subset(const std::vector<std::size_t>& which) const;

  /// Throws InputError unless opts has the range, n_periods and damping ratio
  /// these spectra were computed for (compared exactly).
  void check_compatible(const SelectionOptions& opts) const;

 private:
  PeriodRange range_;
  int n_periods_ = 0;
  double damping_ratio_ = 0.0;
  bool interpolated_ = false;
  std::vector<double> periods_;
  std::vector<Candidate> candidates_;
};

/// select_records() over precomputed candidates: the same result, bit for
/// bit, as select_records(target, records, info, opts) on the records and
/// info the candidates were built from (that overload calls this one).
/// Indices in the result are positions in candidates.candidates().
SelectionResult select_records(const std::function<double(double)>& target, const SelectionCandidates& candidates,
                               const SelectionOptions& opts);

}  // namespace assess

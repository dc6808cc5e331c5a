// selection_summary.hpp: how the records of a dynamic analysis were chosen
// (docs/theory/record-selection.md): the period range and why, the rules and
// limits used, the site-class ladder tried, the selection's result, and the
// records that could not be read.
#pragma once

#include "assess/support/note.hpp"
#include "assess/records/record_selection.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace assess {

struct SelectionSummary {
  /// The selection from the record library (empty when the records are listed).
  std::optional<SelectionResult> result;
  PeriodRange range{};             ///< period range of the compatibility (s; also for listed records)
  std::string limit_state = "SLV";  ///< spectrum the records are compatible with
  /// Why the range: the mechanism periods it spans (s), e.g. Ts and T_SLV.
  double T_first = 0.0, T_last = 0.0;
  std::vector<std::string> warnings;     ///< default windows, relaxed site class, ...
  std::size_t candidates = 0;            ///< records passing the catalogue filters
  std::vector<std::string> site_classes;  ///< classes accepted in the end (empty = any)
  double max_pga_ratio = 0.0;             ///< the PGA guard used (-)
  double max_scale = 0.0, max_mean_scale = 0.0;  ///< scale limits used (-)
  double max_misfit = 0.0;                ///< misfit above which a record is flagged (-)
  bool include_near_fault = false;        ///< near-fault / pulse-like records admitted
  double near_fault_km = 0.0;             ///< distance threshold of the near-fault flag (km)
  std::size_t near_fault_excluded = 0;    ///< near-fault / pulse-like records left out
  /// The site-class ladder tried: classes, candidates, outcome (the last is
  /// used): one note each, as data.
  std::vector<NoteText> steps;
  std::string spectra;  ///< "precomputed" (interpolated) or "integrated" candidates' spectra
  /// Why the period range is what it is (computed: the mechanism periods, the
  /// factors, the cap, and the limit-state periods it does not reach): a note as data.
  NoteText range_note;
  /// Several candidates analysed dynamically (issue 24): how their selection
  /// was shared (one set over the union of their ranges, or each its own): a note as data.
  NoteText shared_note;
  std::vector<std::string> record_failures;  ///< "<path>: <message>" of records skipped (--keep-going)
};

}  // namespace assess

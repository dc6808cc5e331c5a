// library_selection.hpp: a selection of N records from the record library
// with the rules an engineer defends (docs/theory/record-selection.md §2):
// the catalogue filters, near-fault and pulse-like records left out unless
// asked for, the site's soil class first and relaxed only when it gives no
// compatible set, the scale cap, each record's misfit flagged. Computed once
// per process for the same library, rules, options and target, whoever asks
// (the mechanisms of a building, the candidates of a mechanism).
#pragma once

#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_library.hpp"
#include "assess/records/record_selection.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace assess {

/// The rules besides SelectionOptions' per-record and set limits.
struct LibrarySelectionRules {
  /// Mw, distance and country windows; site_classes = the classes tried
  /// first (the site's); relax_site_class: widen them (neighbours, then any)
  /// when they give no compatible set. min_candidates is not used here.
  CatalogueFilters filters;
  /// Near-fault and pulse-like records (near_fault_reason) are left out
  /// unless this is true (record-selection.md §2.4).
  bool include_near_fault = false;
  double near_fault_km = near_fault_distance_km;  ///< km
};

/// One step of the site-class ladder and what it gave.
struct SelectionStep {
  std::vector<std::string> site_classes;  ///< accepted classes (empty = any)
  std::size_t candidates = 0;             ///< records of those classes passing every other rule
  SelectionResult::Status status = SelectionResult::Status::FewerThanRequested;
  std::string message;                    ///< the selection's message ("" if no candidate)
};

/// The outcome of select_from_library().
struct LibrarySelection {
  SelectionResult result;                   ///< indices are positions in `candidates`
  std::vector<CatalogueEntry> candidates;   ///< the entries of the step used, in catalogue order
  std::vector<std::string> site_classes;    ///< classes accepted in the end (empty = any)
  std::vector<SelectionStep> steps;         ///< the ladder tried, in order; the last one is used
  /// Records the rules left out before the classes (index = catalogue
  /// position): not usable, outside the windows, near-fault / pulse-like.
  std::vector<RejectedRecord> excluded;
  std::size_t near_fault_excluded = 0;      ///< how many of them are near-fault or pulse-like
  std::vector<std::string> warnings;        ///< default windows, relaxed class, spectra integrated
  /// How the candidates' spectra were obtained: "precomputed" (spectra.bin,
  /// interpolated) or "integrated" (and why, in warnings).
  std::string spectra_source;
};

/// Selects from the library (see the file comment; the ladder and its
/// warnings in record-selection.md §2.2). The result is computed once per
/// process for equal (catalogue, rules, options, target at the check periods
/// and at T = 0) and shared; thread-safe.
/// @throws InputError for bad options or a target that is not > 0
std::shared_ptr<const LibrarySelection> select_from_library(const RecordLibrary& library,
                                                            const LibrarySelectionRules& rules,
                                                            const std::function<double(double)>& target,
                                                            const SelectionOptions& opts);

/// How many selections select_from_library() has computed, and how many it
/// returned from its memo, in this process (for tests and benchmarks).
struct SelectionMemoStats {
  std::size_t computed = 0, reused = 0;
};
SelectionMemoStats selection_memo_stats();

}  // namespace assess

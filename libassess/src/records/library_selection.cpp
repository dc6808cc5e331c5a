// library_selection.cpp: selection from the record library with its rules,
// once per process for the same question (library_selection.hpp;
// docs/theory/record-selection.md §2).
#include "assess/records/library_selection.hpp"

#include "assess/records/response_spectrum.hpp"
#include "assess/records/selection_candidates.hpp"
#include "assess/support/content_hash.hpp"
#include "assess/support/error.hpp"
#include "support/once_value.hpp"
#include "support/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <unordered_map>

namespace assess {

namespace {

std::atomic<std::size_t> memo_computed{0}, memo_reused{0};

/// "C, D" (or "any class").
std::string classes_list(const std::vector<std::string>& c) {
  if (c.empty()) return "any class";
  std::string s;
  for (std::size_t i = 0; i < c.size(); ++i) s += (i ? ", " : "") + c[i];
  return s;
}

/// "class D", "classes C, D" (or "any class").
std::string classes_text(const std::vector<std::string>& c) {
  if (c.empty()) return "any class";
  return (c.size() == 1 ? "class " : "classes ") + classes_list(c);
}

bool in_list(const std::vector<std::string>& list, const std::string& v) {
  return std::find(list.begin(), list.end(), v) != list.end();
}

/// Every input of a selection, as text: the memo's key.
std::string memo_key(const RecordLibrary& lib, const LibrarySelectionRules& r, const SelectionOptions& o,
                     const std::vector<double>& target) {
  std::string k;
  char buf[64];
  auto num = [&](double v) {
    std::snprintf(buf, sizeof buf, "%.17g,", v);
    k += buf;
  };
  auto list = [&](const std::vector<std::string>& v) {
    for (const auto& s : v) k += s + "\x1f";
    k += ";";
  };
  k += lib.catalogue().path + "\x1e" + hash_hex(lib.catalogue().text_hash) + "\x1e";
  const CatalogueFilters& f = r.filters;
  for (double v : {f.Mw_min, f.Mw_max, f.R_min_km, f.R_max_km}) num(v);
  k += std::to_string(f.Mw_given) + std::to_string(f.R_given) + std::to_string(f.relax_site_class);
  list(f.site_classes);
  list(f.countries);
  k += std::to_string(r.include_near_fault);
  num(r.near_fault_km);
  k += std::to_string(o.n_records) + "," + std::to_string(o.max_per_event) + "," + std::to_string(o.max_per_station) +
       "," + std::to_string(int(o.scale_rule)) + "," + std::to_string(o.n_periods) + "," + std::to_string(o.pool_size) + ",";
  for (double v : {o.range.T_min, o.range.T_max, o.lower_tol, o.upper_tol, o.max_scale, o.max_mean_scale,
                   o.max_pga_ratio, o.damping_ratio, o.max_combinations, o.max_misfit})
    num(v);
  for (double v : target) num(v);
  return k;
}

std::shared_ptr<const LibrarySelection> compute(const RecordLibrary& lib, const LibrarySelectionRules& rules,
                                                const std::function<double(double)>& target,
                                                const SelectionOptions& opts) {
  auto out = std::make_shared<LibrarySelection>();
  LibrarySelection& ls = *out;
  const RecordCatalogue& cat = lib.catalogue();
  // 1. Filters other than the site class (record-selection.md §2.2), then
  // the near-fault rule (§2.4).
  CatalogueFilters base = rules.filters;
  base.site_classes.clear();
  base.relax_site_class = false;
  const CatalogueFilterResult fr = filter_catalogue(cat.entries, base);
  ls.warnings = fr.warnings;
  ls.excluded = fr.rejected;
  std::vector<CatalogueEntry> pool;
  {
    std::size_t j = 0;  // position of fr.kept in cat.entries (filter_catalogue keeps the order)
    for (const CatalogueEntry& e : fr.kept) {
      while (cat.entries[j].id != e.id) ++j;
      const std::string nf = near_fault_reason(e, rules.near_fault_km);
      if (!nf.empty() && !rules.include_near_fault) {
        ls.excluded.push_back({j, e.id, 0.0, nf + " (left out by default; \"near_fault\": \"include\" admits it)"});
        ++ls.near_fault_excluded;
      } else {
        pool.push_back(e);
      }
    }
    std::sort(ls.excluded.begin(), ls.excluded.end(),
              [](const RejectedRecord& a, const RejectedRecord& b) { return a.index < b.index; });
  }
  if (pool.empty()) {
    ls.result.status = SelectionResult::Status::FewerThanRequested;
    ls.result.message = "no record of the catalogue passes the filters";
    ls.steps.push_back({rules.filters.site_classes, 0, ls.result.status, ls.result.message});
    ls.site_classes = rules.filters.site_classes;
    return out;
  }
  // 2. The pool's spectra at the check periods: precomputed and interpolated,
  // or integrated when the library has no usable spectra for them.
  std::vector<CandidateInfo> info;
  std::vector<std::string> names;
  for (const CatalogueEntry& e : pool) info.push_back(candidate_info(e)), names.push_back(e.id);
  SelectionCandidates all;
  std::string why_not;
  const LibrarySpectra* sp = lib.spectra();
  if (!sp) why_not = lib.spectra_problem();
  else if (sp->find_damping(opts.damping_ratio) < 0) why_not = "no precomputed spectra at this damping";
  else if (opts.range.T_max > sp->periods.back()) why_not = "the range ends beyond the precomputed grid";
  std::vector<std::size_t> rows;
  if (why_not.empty()) {
    std::unordered_map<std::string, std::size_t> row_of;
    for (std::size_t i = 0; i < sp->ids.size(); ++i) row_of.emplace(sp->ids[i], i);
    for (const CatalogueEntry& e : pool) {
      const auto it = row_of.find(e.id);
      if (it == row_of.end()) {
        why_not = "record " + e.id + " has no precomputed spectrum";
        break;
      }
      rows.push_back(it->second);
    }
  }
  if (why_not.empty()) {
    all = SelectionCandidates(*sp, rows, names, info, opts);
    ls.spectra_source = "precomputed";
  } else {
    std::vector<Record> recs(pool.size());
    detail::parallel_for(pool.size(), [&](std::size_t i) { recs[i] = *lib.record(pool[i]); });
    all = SelectionCandidates(recs, info, opts);
    ls.spectra_source = "integrated";
    ls.warnings.push_back("the library's precomputed spectra were not used (" + why_not + "): the " +
                          std::to_string(pool.size()) +
                          " candidates' spectra were integrated instead (same method, slower); "
                          "`assess records build` rebuilds them");
  }
  // 3. The site-class ladder: the site's classes first, wider only when they
  // give no compatible set (record-selection.md §2.2).
  const std::vector<std::vector<std::string>> ladder =
      site_class_ladder(rules.filters.site_classes, rules.filters.relax_site_class);
  struct Outcome {
    SelectionResult result;
    std::vector<std::size_t> members;  // positions in pool
  };
  std::vector<Outcome> outcomes;
  std::size_t used = 0;
  bool found = false;
  for (std::size_t s = 0; s < ladder.size() && !found; ++s) {
    Outcome o;
    for (std::size_t i = 0; i < pool.size(); ++i)
      if (ladder[s].empty() || in_list(ladder[s], pool[i].site_class)) o.members.push_back(i);
    SelectionStep step{ladder[s], o.members.size(), SelectionResult::Status::FewerThanRequested, ""};
    if (o.members.empty()) {
      o.result.status = SelectionResult::Status::FewerThanRequested;
      o.result.message = "no candidate of " + classes_text(ladder[s]);  // "no candidate of class D"
    } else {
      o.result = select_records(target, all.subset(o.members), opts);
    }
    step.status = o.result.status;
    step.message = o.result.message;
    ls.steps.push_back(step);
    outcomes.push_back(std::move(o));
    if (outcomes.back().result.status == SelectionResult::Status::Compatible) used = s, found = true;
  }
  if (!found) {
    // No step gave a compatible set: the one with N records and the smallest
    // band violation (the first of equals), else the one with most records.
    auto rank = [](const SelectionResult& r) {
      return std::make_pair(r.status == SelectionResult::Status::FewerThanRequested ? 1 : 0,
                            r.status == SelectionResult::Status::FewerThanRequested ? -double(r.records.size())
                                                                                    : r.band_violation);
    };
    for (std::size_t s = 1; s < outcomes.size(); ++s)
      if (rank(outcomes[s].result) < rank(outcomes[used].result)) used = s;
    ls.steps.resize(used + 1);
  }
  ls.site_classes = ladder[used];
  ls.result = std::move(outcomes[used].result);
  for (std::size_t i : outcomes[used].members) ls.candidates.push_back(pool[i]);
  if (used > 0) {
    const SelectionStep& first = ls.steps.front();
    ls.warnings.push_back("site class relaxed from " + classes_list(first.site_classes) + " to " +
                          classes_list(ls.site_classes) + ": " + classes_text(first.site_classes) + " alone (" +
                          std::to_string(first.candidates) + " candidates) gives no compatible set of " +
                          std::to_string(opts.n_records) + " (" + (first.message.empty() ? "none" : first.message) + ")");
  }
  return out;
}

}  // namespace

std::shared_ptr<const LibrarySelection> select_from_library(const RecordLibrary& lib, const LibrarySelectionRules& rules,
                                                            const std::function<double(double)>& target,
                                                            const SelectionOptions& opts) {
  opts.validate();
  std::vector<double> values;
  for (double T : log_spaced_periods(opts.range.T_min, opts.range.T_max, opts.n_periods)) values.push_back(target(T));
  values.push_back(target(0.0));
  // A catalogue held in memory has no content hash to key the memo by.
  if (lib.catalogue().text_hash == 0) {
    ++memo_computed;
    return compute(lib, rules, target, opts);
  }
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<detail::OnceValue<LibrarySelection>>> memo;
  std::shared_ptr<detail::OnceValue<LibrarySelection>> slot;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto& s = memo[memo_key(lib, rules, opts, values)];
    if (!s) s = std::make_shared<detail::OnceValue<LibrarySelection>>();
    slot = s;
  }
  // Computed once; its value or its error (a window Mw_min > Mw_max, a
  // record changed since the build) is every caller's (support/once_value.hpp).
  bool computed_here = false;
  std::shared_ptr<const LibrarySelection> value;
  try {
    value = slot->get([&] {
      computed_here = true;
      return compute(lib, rules, target, opts);
    });
  } catch (...) {
    ++(computed_here ? memo_computed : memo_reused);
    throw;
  }
  ++(computed_here ? memo_computed : memo_reused);
  return value;
}

SelectionMemoStats selection_memo_stats() { return {memo_computed.load(), memo_reused.load()}; }

}  // namespace assess

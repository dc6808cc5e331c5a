// facade_assessment.cpp: kinematic checks + dynamic rocking of a façade.
//
// Notation: d* equivalent SDOF displacement [C8.7.1.4], d_k control-point
// displacement, d_SLV = 0.4 d0* [C8.7.1.2.1.6], e coefficient of
// restitution (velocity ratio), D/C energy demand/capacity (seed §3.2).
// The dynamic acceptance of Circ. 2019 C8.7.1.2.1.9: SLV is satisfied if the
// collapse threshold d0 is not exceeded in any analysis AND the mean over the
// records of the peak displacements does not exceed d_SLV. Choices (docs/
// theory/facade.md): displacements in d* units with the kinematic control
// point; with both polarities, the envelope per record enters the mean; the
// records are selected/compatible with the SLV spectrum, so only SLV is
// judged dynamically.
#include "assess/assessment/facade_assessment.hpp"

#include "assess/support/error.hpp"
#include "assess/records/library_selection.hpp"
#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_library.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/records/strong_motion.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"
#include "assessment/plausibility.hpp"
#include "assess/kinematic/code_rules.hpp"

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace assess {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

std::string directory_of(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? "." : path.substr(0, p);
}

// A record used by the dynamic analysis, with the name, event, station and
// component of its file and the scale factor applied (PGA of the scaled record).
RecordUsed record_used(const Record& r, const std::string& file, double scale) {
  RecordUsed u;
  u.name = r.name;
  u.file = file;
  u.event = r.event;
  u.station = r.station;
  u.component = r.component;
  u.scale = scale;
  u.pga = r.pga() * scale;
  return u;
}

// The catalogue's metadata of a record (selected, or listed from the library).
void describe_from_catalogue(RecordUsed& u, const CatalogueEntry& e, double near_fault_km) {
  u.in_catalogue = true;
  u.event = e.event;  // the catalogue's names
  u.station = e.station;
  u.component = e.component;
  u.date = e.date;
  u.country = e.country;
  u.station_code = e.station_code;
  u.Mw = e.Mw;
  u.distance_km = e.distance_km;
  u.distance_kind = e.distance_kind;
  u.site_class = e.site_class;
  u.site_class_basis = e.site_class_basis;
  u.vs30_class = e.vs30_class;
  u.vs30_m_s = e.vs30_m_s;
  u.positive_direction = e.positive_direction;
  u.pulse = e.pulse;
  u.near_fault = near_fault_reason(e, near_fault_km);
  if (std::isfinite(e.lowest_usable_hz) && e.lowest_usable_hz > 0.0) u.usable_period_s = 1.0 / e.lowest_usable_hz;
}

// Why the period range of the selection is what it is (record-selection.md
// §2.3), with the limit-state periods it does not reach: a note as data
// (note.hpp), its words in the message catalogue.
NoteText range_note(const RecordSelectionSpec& rs, const KinematicResult& kin, const PeriodRange& r, double T1,
                    double T2, bool shared_union) {
  const auto x = [](double v) { return number_arg(v, 3); };
  const auto s = [](double v) { return number_arg(v, 3, "s"); };
  const double lo = rocking_range_lower_factor * T1, hi = rocking_range_upper_factor * T2;
  NoteText n;
  if (shared_union) {
    n.push_back({"range.union", {x(r.T_min), s(r.T_max), x(lo), s(hi), s(kin.Ts), s(kin.T_SLV)}});
  } else if (rs.T_min && rs.T_max) {
    n.push_back({"range.given", {x(r.T_min), s(r.T_max)}});
  } else {
    n.push_back({"range.default", {x(rocking_range_lower_factor), s(lo), x(rocking_range_upper_factor), s(hi),
                                   s(kin.Ts), s(kin.T_SLV)}});
    if (lo < rocking_range_floor_s) n.push_back({"range.raised", {s(rocking_range_floor_s)}});
    if (hi > rocking_range_cap_s) n.push_back({"range.cut", {s(rocking_range_cap_s)}});
  }
  std::vector<NoteArg> beyond;
  if (kin.T_SLV > r.T_max) beyond.insert(beyond.end(), {text_arg("T_SLV"), s(kin.T_SLV)});
  if (kin.T_SLC > r.T_max) beyond.insert(beyond.end(), {text_arg("T_SLC"), s(kin.T_SLC)});
  if (!beyond.empty()) {
    beyond.push_back(s(r.T_max));
    n.push_back({beyond.size() == 3 ? "range.beyond_one" : "range.beyond_two", beyond});
  }
  return n;
}

// What a selection asks the record library (records/library_selection.hpp):
// the case's rules and limits over `range`.
struct SelectionRequest {
  std::shared_ptr<const RecordLibrary> lib;
  LibrarySelectionRules rules;
  SelectionOptions so;
};

SelectionRequest selection_request(const CaseFile& kase, const RecordSelectionSpec& rs, const PeriodRange& range) {
  SelectionRequest q;
  // The process's record library: catalogue, precomputed spectra, records
  // parsed once (records/record_library.hpp); the selection with its rules is
  // computed once for every mechanism and candidate that asks the same.
  q.lib = RecordLibrary::open(rs.catalogue);
  q.rules.filters = catalogue_filters(rs, to_string(kase.site->conditions.soil), rs.count);
  q.rules.include_near_fault = rs.include_near_fault;
  q.rules.near_fault_km = rs.near_fault_km;
  q.so.n_records = rs.count;
  q.so.max_scale = rs.max_scale;
  q.so.max_mean_scale = rs.max_mean_scale;
  q.so.max_pga_ratio = rs.max_pga_ratio;
  q.so.max_per_event = rs.max_per_event;
  q.so.max_per_station = rs.max_per_station;
  q.so.max_misfit = rs.max_misfit;
  q.so.range = range;
  return q;
}

// The records of a dynamic analysis as read: the motions, the record library
// they come from (selected records) and each one's catalogue entry, if any.
struct LoadedRecords {
  std::vector<Record> recs;
  std::shared_ptr<const RecordLibrary> lib;            ///< the library of selected records (null when listed)
  std::vector<std::optional<CatalogueEntry>> entries;  ///< the library's entry of each selected record
};

// The records listed in the case (/dynamic/records); a listed file of the
// shipped record library carries the catalogue's metadata and flags (the
// library is optional here: without it, none).
void listed_records(FacadeAssessment& a, const DynamicSpec& d, const FacadeOptions& opt, LoadedRecords& out) {
  std::shared_ptr<const RecordLibrary> lib;
  std::string lib_dir;
  try {
    lib = RecordLibrary::open(data_dir() + "/spectra/records/catalogue.json");
    lib_dir = std::filesystem::weakly_canonical(lib->catalogue().directory).string();
  } catch (const std::exception&) {
    lib.reset();
  }
  for (const ListedRecord& lr : d.records) {
    try {
      Record r = read_listed_record(lr);
      RecordUsed u = record_used(r, lr.file, lr.scale);
      u.json_path = lr.json_path;
      if (lib && !lr.unit) {
        std::error_code ec;
        const std::string p = std::filesystem::weakly_canonical(lr.file, ec).string();
        for (const CatalogueEntry& e : lib->catalogue().entries)
          if (!ec && p == lib_dir + "/" + e.file) describe_from_catalogue(u, e, near_fault_distance_km);
      }
      a.dynamics.records.push_back(u);
      out.recs.push_back(std::move(r));
      out.entries.emplace_back();
    } catch (const InputError& e) {
      std::string msg = e.what();
      if (msg.find("for a plain file") != std::string::npos)
        msg += " (in a case file: {\"file\": ..., \"dt\": s, \"unit\": \"g\" | \"m/s^2\" | \"cm/s^2\"} for one "
               "column; \"unit\" alone for two columns, time and acceleration)";
      if (!opt.keep_going) throw InputError(a.kase.file + ": " + lr.json_path + "/file: " + msg);
      a.selection.record_failures.push_back(lr.json_path + "/file: " + msg);
    }
  }
  if (out.recs.empty()) throw InputError(a.kase.file + ": /dynamic/records: no record could be read");
}

// The records selected from the library (/dynamic/select) over the range of
// the SLV check: the secant periods the mechanism passes through up to its
// SLV displacement, Ts [C8.7.1.2.1.7] to T_SLV [C8.7.1.10] (docs/theory/
// record-selection.md §2.3); or the range shared by the candidates of the
// mechanism (record-selection.md §2.7). The selection's rules, limits and
// ladder go to a.selection.
void selected_records(FacadeAssessment& a, const RecordSelectionSpec& rs, const FacadeOptions& opt,
                      const ElasticSpectrum& target, const KinematicResult& kin,
                      const std::optional<PeriodRange>& shared, LoadedRecords& out) {
  SelectionSummary& sel = a.selection;
  const double T1 = std::min(kin.Ts, kin.T_SLV), T2 = std::max(kin.Ts, kin.T_SLV);
  sel.T_first = T1;
  sel.T_last = T2;
  const PeriodRange range = shared ? *shared
                            : (rs.T_min && rs.T_max) ? PeriodRange{*rs.T_min, *rs.T_max}
                                                     : rocking_period_range(T1, T2);
  sel.range = range;
  sel.range_note = range_note(rs, kin, range, T1, T2, shared.has_value());
  const SelectionRequest req = selection_request(a.kase, rs, range);
  const std::shared_ptr<const RecordLibrary>& lib = req.lib;
  sel.max_pga_ratio = rs.max_pga_ratio;
  sel.max_scale = rs.max_scale;
  sel.max_mean_scale = rs.max_mean_scale;
  sel.max_misfit = rs.max_misfit;
  sel.include_near_fault = rs.include_near_fault;
  sel.near_fault_km = rs.near_fault_km;
  const std::shared_ptr<const LibrarySelection> ls =
      select_from_library(*lib, req.rules, [&target](double T) { return target.Se(T); }, req.so);
  sel.warnings = ls->warnings;
  sel.site_classes = ls->site_classes;
  sel.candidates = ls->candidates.size();
  sel.near_fault_excluded = ls->near_fault_excluded;
  sel.spectra = ls->spectra_source;
  for (const SelectionStep& st : ls->steps) {
    std::string classes;
    for (const std::string& c : st.site_classes) classes += (classes.empty() ? "" : ", ") + c;
    NoteText step{classes.empty() ? Note{"step.any_class", {}} : Note{"step.classes", {text_arg(classes)}}};
    step.push_back(st.message.empty() ? Note{"step.no_selection", {count_arg(st.candidates)}}
                                      : Note{"step.outcome", {count_arg(st.candidates), generated_arg(st.message)}});
    sel.steps.push_back(std::move(step));
  }
  for (const SelectedRecord& s : ls->result.records) {
    const CatalogueEntry& e = ls->candidates[s.index];
    Record r;
    try {
      r = *lib->record(e);
    } catch (const InputError& err) {
      if (!opt.keep_going) throw InputError(a.kase.file + ": /dynamic/select: catalogue record " + e.file + ": " + err.what());
      sel.record_failures.push_back(e.file + ": " + err.what());
      continue;
    }
    RecordUsed u = record_used(r, lib->catalogue().directory + "/" + e.file, s.scale);
    describe_from_catalogue(u, e, rs.near_fault_km);
    u.deviation = s.deviation;
    u.rank = s.rank;
    u.misfit_flag = s.misfit_flag;
    a.dynamics.records.push_back(u);
    out.recs.push_back(std::move(r));
    out.entries.push_back(e);
  }
  out.lib = lib;
  sel.result = ls->result;
  if (out.recs.empty())
    throw InputError(a.kase.file + ": /dynamic/select: no compatible set in the catalogue: " + sel.result->message);
}

// The records of the dynamic analysis: listed in the case, or selected.
LoadedRecords load_records(FacadeAssessment& a, const DynamicSpec& d, const FacadeOptions& opt,
                           const ElasticSpectrum& target, const KinematicResult& kin,
                           const std::optional<PeriodRange>& shared) {
  LoadedRecords out;
  if (d.selection)
    selected_records(a, *d.selection, opt, target, kin, shared, out);
  else
    listed_records(a, d, opt, out);
  return out;
}

// The caveats of each record used (record-selection.md §2.8), computed from
// its metadata and the selection, shown beside it in every output.
void flag_records(FacadeAssessment& a) {
  const std::string soil = a.kase.site ? to_string(a.kase.site->conditions.soil) : "";
  // The classes the selection was asked for: the case's, else the site's soil.
  std::vector<std::string> asked{soil};
  if (a.dynamics.spec && a.dynamics.spec->selection && !a.dynamics.spec->selection->site_classes.empty())
    asked = a.dynamics.spec->selection->site_classes;
  std::string asked_text;
  for (const std::string& c : asked) asked_text += (asked_text.empty() ? "" : ", ") + c;
  const double default_cap = SelectionOptions{}.max_scale;
  const auto x = [](double v) { return number_arg(v, 3); };
  for (RecordUsed& r : a.dynamics.records) {
    r.flags.clear();
    if (!r.in_catalogue) {
      r.flags.push_back({"flag.not_in_library", {}});
    } else {
      if (!r.near_fault.empty()) r.flags.push_back({"flag.near_fault", {generated_arg(r.near_fault)}});
      if (a.selection.result && !soil.empty() && !r.site_class.empty() &&
          std::find(asked.begin(), asked.end(), r.site_class) == asked.end())
        r.flags.push_back(asked.size() == 1 && asked[0] == soil
                              ? Note{"flag.class_not_site", {text_arg(r.site_class), text_arg(soil)}}
                              : Note{"flag.class_not_asked", {text_arg(r.site_class), text_arg(asked_text)}});
      // Vs30 in whole m/s, truncated as the catalogue gives it.
      if (r.site_class_basis == "stated" && !r.vs30_class.empty() && r.vs30_class != r.site_class)
        r.flags.push_back({"flag.class_vs30", {text_arg(r.site_class),
                                               number_arg(std::floor(std::round(r.vs30_m_s * 1e3) / 1e3), 0, "m/s"),
                                               text_arg(r.vs30_class)}});
    }
    if (r.misfit_flag)
      r.flags.push_back({"flag.misfit", {x(r.deviation), x(a.selection.max_misfit), count_arg(std::size_t(r.rank))}});
    if (r.scale > default_cap * (1.0 + 1e-12))
      r.flags.push_back(a.selection.result
                            ? Note{"flag.scale_raised", {x(r.scale), x(default_cap), x(a.selection.max_scale)}}
                            : Note{"flag.scale_listed", {x(r.scale), x(default_cap)}});
  }
}

// Compatibility of the records' mean scaled 5 % spectrum with the SLV
// spectrum (NTC 2018 §3.2.3.6: -10 %/+30 % over the period range). Selected
// records carry it from the selection; listed records are checked here over
// the same default range as a selection.
void compatibility(FacadeAssessment& a, const std::vector<Record>& recs, const ElasticSpectrum& target,
                   const KinematicResult& kin) {
  SpectrumCompatibility& c = a.dynamics.compatibility;
  const double lo = 1.0 - code_rules::compatibility_lower_tol, hi = 1.0 + code_rules::compatibility_upper_tol;
  if (a.selection.result) {
    c.computed = true;
    c.range = a.selection.range;
    c.min_ratio = a.selection.result->min_ratio;
    c.max_ratio = a.selection.result->max_ratio;
    c.band_satisfied = a.selection.result->band_satisfied;
  } else {
    c.computed = true;
    const double T1 = std::min(kin.Ts, kin.T_SLV), T2 = std::max(kin.Ts, kin.T_SLV);
    c.range = rocking_period_range(T1, T2);
    a.selection.range = c.range;
    const std::vector<double> T = log_spaced_periods(c.range.T_min, c.range.T_max, 40);
    std::vector<double> mean(T.size(), 0.0);
    std::vector<std::vector<double>> psa(recs.size());
    detail::parallel_for(recs.size(), [&](std::size_t i) { psa[i] = response_spectrum(recs[i], T).psa(); });
    for (std::size_t i = 0; i < recs.size(); ++i)
      for (std::size_t j = 0; j < T.size(); ++j) mean[j] += psa[i][j] * a.dynamics.records[i].scale / double(recs.size());
    c.min_ratio = 1e300;
    c.max_ratio = 0.0;
    for (std::size_t j = 0; j < T.size(); ++j) {
      const double r = mean[j] / target.Se(T[j]);
      c.min_ratio = std::min(c.min_ratio, r);
      c.max_ratio = std::max(c.max_ratio, r);
    }
    c.band_satisfied = c.min_ratio >= lo && c.max_ratio <= hi;
  }
  c.message = {{c.band_satisfied ? "compat.within" : "compat.outside",
                {count_arg(recs.size()), number_arg(c.range.T_min, 2), number_arg(c.range.T_max, 2, "s"),
                 number_arg(c.min_ratio, 3), number_arg(c.max_ratio, 3), number_arg(lo, 2), number_arg(hi, 2)}}};
  if (!c.band_satisfied) {
    char buf[320];  // the warning, an English sentence as every warning (localised by the report)
    std::snprintf(buf, sizeof buf,
                  "mean spectrum of the %d records / SLV spectrum (5 %%) over %.2f-%.2f s: %.3f to %.3f, OUTSIDE the "
                  "band %.2f-%.2f (NTC 2018 §3.2.3.6)",
                  int(recs.size()), c.range.T_min, c.range.T_max, c.min_ratio, c.max_ratio, lo, hi);
    a.warnings.push_back(a.kase.file + ": " + (a.selection.result ? "/dynamic/select" : "/dynamic/records") + ": the " +
                         buf + ": the records are not compatible with the site's SLV action and the dynamic "
                         "verdict rests on them");
  }
}

// The summary over every candidate's checks, the dynamic and energy rows.
void finish(FacadeAssessment& a) {
  std::vector<CheckRow> all;
  for (const CandidateResult& cr : a.kinematic.candidates) all.insert(all.end(), cr.checks.begin(), cr.checks.end());
  for (const CheckRow& r : a.checks)
    if (r.kind == "dynamic") all.push_back(r);
  all.insert(all.end(), a.dynamics.energy_rows.begin(), a.dynamics.energy_rows.end());
  a.verdict = build_verdict(all, a.kase.method);
  a.indices = safety_indices(a.kinematic, a.verdict);
}

}  // namespace

std::vector<std::size_t> dynamic_candidates(const KinematicCaseResult& k) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < k.candidates.size(); ++i) {
    if (i == k.governing) continue;
    bool wanted = false;
    for (const auto& [code, g] : k.governing_by_code) wanted = wanted || g == i;
    for (const CheckRow& r : k.candidates[i].checks)
      wanted = wanted || !r.satisfied || r.no_verdict || !std::isfinite(r.dc) || r.dc > 1.0;
    if (wanted) out.push_back(i);
  }
  return out;
}

std::vector<DynamicRun> dynamic_runs(const FacadeAssessment& a, const MechanismDynamics& md, const KinematicResult& kin,
                                     bool histories) {
  const DynamicSpec& d = *a.dynamics.spec;
  std::vector<bool> polarities;
  if (d.polarity != Polarity::reversed) polarities.push_back(false);
  if (d.polarity != Polarity::normal) polarities.push_back(true);
  // Every (restitution, record, polarity) analysis, in this order, on all cores.
  std::vector<DynamicRun> runs;
  for (std::size_t ie = 0; ie < md.e.size(); ++ie)
    for (std::size_t ir = 0; ir < a.dynamics.base_motions.size(); ++ir)
      for (bool rev : polarities) {
        DynamicRun run;
        run.record = ir;
        run.reversed = rev;
        run.restitution = ie;
        run.e = md.e[ie];
        runs.push_back(std::move(run));
      }
  detail::parallel_for(runs.size(), [&](std::size_t i) {
    DynamicRun& run = runs[i];
    RockingOptions ro = d.options;
    ro.record_history = histories;
    ro.scale = a.dynamics.records[run.record].scale;
    ro.reverse = run.reversed;
    run.result = md.analyse(run.restitution, a.dynamics.base_motions[run.record], ro);
    run.theta_ratio = run.result.theta_u > 0 ? run.result.theta_max / run.result.theta_u : 0.0;
    // Peak outward rotation moves the control point outward (one-sided:
    // theta >= 0); for two-sided, |theta| on either side (symmetric body).
    run.d_control = md.control_displacement(kin, run.result.theta_max_side * run.result.theta_max);
    run.d_star = run.d_control * kin.d_star_per_dk;
    // Issue 29: a tie level that breaks leaves the wall bare (the analysis goes
    // on): d0 is then the bare wall's; the rupture is reported, and the ties'
    // checks fail on it (tie_intervention.cpp), the wall's check on its motion.
    run.ruptured = md.ruptured(run.result);
    const double dk0 = run.ruptured && kin.without_ties ? std::min(kin.dk0, kin.without_ties->dk0) : kin.dk0;
    run.collapse = run.result.overturned || run.d_control >= std::min(dk0, kin.dk0_bound);
  });
  return runs;
}

// Issue 37: one displacement capacity per state, the same in the kinematic
// and the dynamic check (the tied wall's, with its levels breaking where they
// fail: docs/theory/ties.md §2).
double dynamic_d_SLV(const KinematicResult& kin) { return kin.d_SLV; }

namespace {

// NTC 2018 §7.3.5 (docs/theory/facade.md §7) on the summary `s` whose
// statistics are in: with at least 7 records the mean of the results, with 3
// to 6 the most unfavourable, with fewer no verdict; any collapse fails the
// check whatever the count (C8.7.1.2.1.9). `kept` are the peak d* of the
// records none of whose analyses collapsed or failed.
void judge_records(RestitutionSummary& s, const std::vector<double>& kept, const KinematicResult& kin) {
  if (s.records >= code_rules::records_for_mean) {
    s.rule = "mean";
    s.d_demand = s.mean_d_star;
  } else if (s.records >= code_rules::records_min) {
    s.rule = "most unfavourable";
    s.d_demand = s.max_d_star;
  } else {
    s.rule = "none";
    s.d_demand = s.max_d_star;
  }
  const double d_SLV = dynamic_d_SLV(kin);
  s.records_survived = int(kept.size());
  if (!kept.empty()) {
    double sum = 0.0, top = 0.0;
    for (double d : kept) sum += d, top = std::max(top, d);
    s.d_demand_survivors = s.rule == "mean" ? sum / double(kept.size()) : top;
    s.dc_survivors = d_SLV > 0 ? s.d_demand_survivors / d_SLV : inf;
  }
  // Issue 28 (docs/theory/facade.md §6.4): a collapse makes the displacement
  // demand unbounded and a failed analysis leaves it unknown: D/C = +inf,
  // so that the D/C printed carries the failure.
  if (s.any_collapse || s.failed > 0) s.d_demand = inf;
  s.no_verdict = s.rule == "none" && !s.any_collapse && s.failed == 0;
  s.dc_slv = d_SLV > 0 ? s.d_demand / d_SLV : inf;
  s.slv_satisfied = check_satisfied(s.dc_slv, s.no_verdict);
  s.energy_dc = s.overturned > 0 || s.failed > 0 ? inf : s.mean_dc;
}

// The analyses of restitution value `ie` summarised: counts, energy D/C
// statistics, the envelope of the polarities per record, then the records' rule.
RestitutionSummary summarise_restitution(const std::vector<DynamicRun>& runs, std::size_t ie, double e,
                                         const KinematicResult& kin) {
  RestitutionSummary s;
  s.restitution = ie;
  s.e = e;
  s.min_dc = 1e300;
  std::map<std::size_t, double> envelope;  // record -> peak d* over polarities
  std::map<std::size_t, bool> spoilt;      // record -> some analysis collapsed or failed
  int survivors = 0;                       // analyses that neither failed nor overturned
  double dc_survivors_sum = 0.0;
  for (const DynamicRun& r : runs) {
    if (r.restitution != ie) continue;
    ++s.analyses;
    if (!succeeded(r.result)) {  // its numbers are not results
      ++s.failed;
      spoilt[r.record] = true;
      continue;
    }
    s.overturned += r.result.overturned ? 1 : 0;
    s.ruptured += r.ruptured ? 1 : 0;
    s.collapsed += r.collapse ? 1 : 0;
    s.mean_dc += r.result.dc;
    s.min_dc = std::min(s.min_dc, r.result.dc);
    s.max_dc = std::max(s.max_dc, r.result.dc);
    s.mean_theta_ratio += r.theta_ratio;
    s.any_collapse = s.any_collapse || r.collapse;
    envelope[r.record] = std::max(envelope[r.record], r.d_star);
    spoilt[r.record] = spoilt[r.record] || r.collapse;
    if (!r.result.overturned) {
      dc_survivors_sum += r.result.dc;
      ++survivors;
    }
  }
  // Failed analyses (step or event limit, integrator error) are left out of
  // the statistics and fail the check (issue 10): their numbers are not results.
  const int trusted = s.analyses - s.failed;
  if (trusted > 0) {
    s.mean_dc /= trusted;
    s.mean_theta_ratio /= trusted;
  } else {
    s.min_dc = 0.0;
  }
  if (survivors > 0) s.mean_dc_survivors = dc_survivors_sum / survivors;
  std::vector<double> kept;  // peak d* of the records none of whose analyses collapsed or failed
  for (const auto& kv : envelope) {
    s.mean_d_star += kv.second;
    s.max_d_star = std::max(s.max_d_star, kv.second);
    if (!spoilt[kv.first]) kept.push_back(kv.second);
  }
  s.records = int(spoilt.size());
  if (!envelope.empty()) s.mean_d_star /= double(envelope.size());
  judge_records(s, kept, kin);
  return s;
}

}  // namespace

std::vector<RestitutionSummary> summarise_runs(const std::vector<DynamicRun>& runs, const std::vector<double>& e,
                                               const KinematicResult& kin) {
  std::vector<RestitutionSummary> out;
  for (std::size_t ie = 0; ie < e.size(); ++ie) out.push_back(summarise_restitution(runs, ie, e[ie], kin));
  return out;
}

namespace {
void add_dynamic_analysis(FacadeAssessment& a, const FacadeOptions& opt);
}  // namespace

std::vector<CaseDefault> assessment_defaults(const FacadeAssessment& a) {
  std::vector<CaseDefault> out = a.kase.defaults;
  if (a.dynamics.spec) out.insert(out.end(), a.dynamics.spec->defaults.begin(), a.dynamics.spec->defaults.end());
  return out;
}

NoteText shared_selection_problem(const CaseFile& kase) {
  const DynamicSpec d = parse_dynamic(kase.dynamic, kase.file, directory_of(kase.file));
  if (!d.selection || !d.selection->T_min || !d.selection->T_max || !kase.site) return {};
  const Site site(*kase.site);
  const ElasticSpectrum target(site.action(LimitState::SLV).hazard, kase.site->conditions, 5.0);
  const PeriodRange range{*d.selection->T_min, *d.selection->T_max};
  const SelectionRequest req = selection_request(kase, *d.selection, range);
  const std::shared_ptr<const LibrarySelection> ls =
      select_from_library(*req.lib, req.rules, [&target](double T) { return target.Se(T); }, req.so);
  if (ls->result.status != SelectionResult::Status::Compatible)
    return {{"sel.no_compatible", {generated_arg(ls->result.message)}}};
  if (!ls->result.band_satisfied) return {{"sel.band_left", {}}};
  return {};
}

namespace {

// The site's action and 5 % elastic spectrum of each limit state it gives
// (all four from the grid; NTC 2018 §3.2), its description and V_R.
SiteHazard site_hazard(const SiteSpec& block) {
  SiteHazard h;
  const Site site(block);
  h.description = site.describe();
  h.VR = site.VR();
  for (LimitState ls : all_limit_states) {
    if (!block.given.empty() && !block.given.count(ls)) continue;
    h.actions[ls] = site.action(ls);
    h.spectra.emplace(ls, ElasticSpectrum(h.actions[ls].hazard, block.conditions, 5.0));
  }
  return h;
}

// The report's site spectra at its periods, and the ADRS demand curves of
// every candidate's displacement checks, each at its damping and location
// (the functions its checks use): the relazione develops each candidate that
// governs a method (issue 28).
void site_curves(FacadeAssessment& a) {
  ReportCurves& c = a.curves;
  c.periods = log_spaced_periods(0.02, 4.0, 48);
  c.periods.insert(c.periods.begin(), 0.0);
  for (const auto& [ls, s] : a.site.spectra)
    for (double T : c.periods) c.site_Se[ls].push_back(s.Se(T));
  if (!a.kinematic.check_input) return;
  CheckInput in = *a.kinematic.check_input;
  c.adrs_periods = log_spaced_periods(0.02, 6.0, 120);
  for (const CandidateResult& cr : a.kinematic.candidates) {
    std::vector<AdrsDemand> curves;
    for (const CheckRow& r : cr.checks) {
      if (r.kind != "displacement") continue;
      in.Z = r.location == "height" ? cr.Z : 0.0;
      AdrsDemand d{r.code, r.limit_state, r.location, r.xi_pct, {}, {}};
      const double w = 2.0 * units::pi;
      for (double T : c.adrs_periods) {
        const double sd = displacement_demand(in, parse_code_edition(r.code), parse_limit_state(r.limit_state), T);
        d.Sd.push_back(sd);
        d.Sa.push_back(sd * (w / T) * (w / T));
      }
      curves.push_back(std::move(d));
    }
    c.candidate_adrs.push_back(std::move(curves));
  }
  c.adrs = c.candidate_adrs[a.kinematic.governing];
}

}  // namespace

FacadeAssessment assess_facade(const CaseFile& kase, const FacadeOptions& opt) {
  if (!kase.site)
    throw InputError(kase.file + ": /site: missing: the assessment checks the mechanism against the site's "
                     "seismic action (give \"lat\"/\"lon\", \"island\" or \"hazard\"); `assess kinematic` "
                     "analyses a mechanism without a site");
  FacadeAssessment a;
  a.kase = kase;
  a.kinematic = opt.kinematic ? *opt.kinematic : run_kinematic_case(kase);
  a.checks = a.kinematic.checks;
  a.warnings = a.kinematic.warnings;
  a.site = site_hazard(*kase.site);
  site_curves(a);
  if (!kase.dynamic.is_null()) add_dynamic_analysis(a, opt);
  finish(a);
  if (opt.sensitivity) a.sensitivity = adopted_sensitivity(a);
  if (opt.review) {  // issue 36: the choices' alternatives, the checks of acceptability, the judgement
    a.choices = modelling_choices(a, opt.review_records);
    a.acceptability = acceptability_checks(a);
    a.judgement = judge(a);
  }
  return a;
}

namespace {

// The dynamic model of the governing candidate (rocking body or chain, and
// its base motion: mechanism_dynamics.hpp) into a.dynamics; false, with the
// reason in a.dynamics.note, where the rocking equation does not apply.
bool add_dynamic_model(FacadeAssessment& a, const CandidateResult& gov, const Chain& chain) {
  const CaseFile& kase = a.kase;
  const DynamicSpec& d = *a.dynamics.spec;
  if (!a.site.actions.count(LimitState::SLV))
    throw InputError(kase.file + ": /site/hazard: the dynamic analysis needs the SLV hazard (records are "
                     "compared with the SLV spectrum)");
  MechanismDynamics md = build_mechanism_dynamics(kase, gov, chain, d);
  if (!md.applies) {
    a.dynamics.note = md.note;
    return false;
  }
  if (d.smooth && !(d.k / units::kN >= plausibility::k_min_kN_m3 && d.k / units::kN <= plausibility::k_max_kN_m3))
    a.warnings.push_back(kase.file + ": /dynamic/k = " + plausibility::number(d.k / units::kN) +
                         " kN/m^3 is outside " + plausibility::number(plausibility::k_min_kN_m3) + "-" +
                         plausibility::number(plausibility::k_max_kN_m3) +
                         " kN/m^3: the seed paper (Fig. 2) uses 5e4-1e7 kN/m^3; below 1e4 a wall has hardly any "
                         "restoring branch, above 1e8 the smooth block is the rigid one (\"model\": \"rigid\"); "
                         "was it typed in N/m^3?");
  a.dynamics.applies = true;
  if (md.single_body()) {
    a.dynamics.body = md.body;
    a.dynamics.model = md.rocking.front();
  }
  a.dynamics.note = md.describe();
  a.dynamics.mechanism = std::move(md);
  return true;
}

// The candidates analysed dynamically besides the governing one (issue 24)
// share one selection over the union of their ranges when it gives a
// compatible set, as the mechanisms of a building do (record-selection.md
// §2.7): that range, or none (each selects over its own); the note says which.
std::optional<PeriodRange> shared_range(FacadeAssessment& a, const CandidateResult& gov,
                                        const std::vector<std::size_t>& others, const ElasticSpectrum& target) {
  const DynamicSpec& d = *a.dynamics.spec;
  if (!d.selection || (d.selection->T_min && d.selection->T_max) || others.empty()) return std::nullopt;
  double lo = std::min(gov.result.Ts, gov.result.T_SLV), hi = std::max(gov.result.Ts, gov.result.T_SLV);
  std::string who = gov.label;
  for (std::size_t i : others) {
    const KinematicResult& k = a.kinematic.candidates[i].result;
    const double t1 = std::min(k.Ts, k.T_SLV), t2 = std::max(k.Ts, k.T_SLV);
    if (!(t1 > 0.0) || !std::isfinite(t2)) continue;
    lo = std::min(lo, t1), hi = std::max(hi, t2);
    who += ", " + a.kinematic.candidates[i].label;
  }
  const PeriodRange u = rocking_period_range(lo, hi);
  const SelectionRequest req = selection_request(a.kase, *d.selection, u);
  const std::shared_ptr<const LibrarySelection> ls =
      select_from_library(*req.lib, req.rules, [&target](double T) { return target.Se(T); }, req.so);
  const NoteArg tmin = number_arg(u.T_min, 3), tmax = number_arg(u.T_max, 3, "s");
  if (ls->result.status == SelectionResult::Status::Compatible) {
    a.selection.shared_note = {{"shared.one_selection",
                                {count_arg(others.size() + 1), generated_arg(who), tmin, tmax}}};
    return u;
  }
  a.selection.shared_note = {{"shared.each_own",
                              {count_arg(others.size() + 1), tmin, tmax, generated_arg(ls->result.message)}}};
  return std::nullopt;
}

// A scaled record beyond recorded ground motions (plausibility.hpp): a warning naming its scale's field.
void warn_record_pga(FacadeAssessment& a) {
  for (const RecordUsed& r : a.dynamics.records)
    if (r.pga / units::g > plausibility::record_pga_max_g)
      a.warnings.push_back(a.kase.file + ": " +
                           (r.json_path.empty() ? std::string("/dynamic/select") : r.json_path + "/scale") +
                           ": the scaled record " + r.name + " has PGA = " + plausibility::number(r.pga / units::g) +
                           " g (scale " + plausibility::number(r.scale) + "), over " +
                           plausibility::number(plausibility::record_pga_max_g) +
                           " g, beyond recorded ground motions: check the scale factor and the record's unit");
}

// Curves for the report: the records' scaled spectra, their mean, and the
// moment-rotation curve of the model. A selected record's spectrum at these
// periods is the library's, integrated once per process for every mechanism
// and candidate that uses the record.
void record_curves(FacadeAssessment& a, const LoadedRecords& in, const MechanismDynamics& md) {
  ReportCurves& c = a.curves;
  const std::size_t n = in.recs.size();
  c.mean_psa.assign(c.periods.size(), 0.0);
  c.record_psa.resize(n);
  detail::parallel_for(n, [&](std::size_t ir) {
    c.record_psa[ir] = in.lib && in.entries[ir] ? *in.lib->psa(*in.entries[ir], c.periods, 0.05)
                                                : response_spectrum(in.recs[ir], c.periods).psa();
    for (double& v : c.record_psa[ir]) v *= a.dynamics.records[ir].scale;
  });
  for (const auto& psa : c.record_psa)
    for (std::size_t j = 0; j < psa.size(); ++j) c.mean_psa[j] += psa[j] / double(n);
  const double th_u = md.q_u();
  constexpr int n_mr = 200;
  for (int i = 0; i <= n_mr; ++i) {
    const double th = th_u * i / n_mr;
    c.mr_theta.push_back(th);
    c.mr_moment.push_back(md.restoring(th));
  }
}

// At height with ground records filtered to the floor: the mean scaled 5 %
// spectrum of the floor motions `inputs` and the code's floor spectrum
// S_eZ(T) [C7.2.6] for the SLV hazard, for the report.
void floor_curves(FacadeAssessment& a, const LoadedRecords& in, const std::vector<Record>& inputs,
                  const MechanismDynamics& md) {
  ReportCurves& c = a.curves;
  c.floor_mean_psa.assign(c.periods.size(), 0.0);
  std::vector<std::vector<double>> psa(inputs.size());
  detail::parallel_for(inputs.size(), [&](std::size_t ir) {
    psa[ir] = in.lib && in.entries[ir] ? *in.lib->psa(*in.entries[ir], c.periods, 0.05, &*md.filter)
                                       : response_spectrum(inputs[ir], c.periods).psa();
  });
  for (std::size_t ir = 0; ir < inputs.size(); ++ir)
    for (std::size_t j = 0; j < c.periods.size(); ++j)
      c.floor_mean_psa[j] += psa[ir][j] * a.dynamics.records[ir].scale / double(inputs.size());
  BuildingModel bm = *a.kase.building;
  bm.T1 = md.filter->T1;
  bm.damping_pct = md.filter_damping_pct;
  const FloorSpectrum fs(a.site.actions.at(LimitState::SLV).hazard, a.kase.site->conditions, bm, std::min(md.Z, bm.H),
                         5.0);
  for (double T : c.periods) c.code_floor_Se.push_back(fs.Se(T));
}

// The motion at the mechanism's base of each record (at height: the floor
// motion, first-mode filter), integrated to its last sample and then the free
// motion up to tail_s (the end rule of every dynamic command,
// dynamics/analysis_end.hpp).
void base_motions(FacadeAssessment& a, const LoadedRecords& in, const MechanismDynamics& md) {
  std::vector<Record> inputs;
  for (const Record& r : in.recs) inputs.push_back(md.input(r));
  if (md.filter && a.kase.building) floor_curves(a, in, inputs, md);
  a.dynamics.free_tail_s = a.dynamics.spec->options.tail_s;
  for (std::size_t ir = 0; ir < in.recs.size(); ++ir) {
    a.dynamics.records[ir].duration_s = in.recs[ir].duration();
    a.dynamics.records[ir].integrated_s = inputs[ir].duration();
  }
  a.dynamics.base_motions = std::move(inputs);
}

// The dynamic check's row of one restitution value (Circ. 2019
// C8.7.1.2.1.9, NTC 2018 §7.3.5 on the records' count): the rule's demand
// against d_SLV, with its note.
CheckRow dynamic_row(const FacadeAssessment& a, std::size_t ie, const CandidateResult& gov) {
  const MechanismDynamics& md = *a.dynamics.mechanism;
  const RestitutionSummary& s = a.dynamics.summaries[ie];
  const std::string e_text = describe(a.dynamics.spec->restitutions[ie]);
  const std::string nrec = std::to_string(s.records) + (s.records == 1 ? " record" : " records");
  CheckRow row;
  row.code = "NTC2018";
  row.limit_state = "SLV";
  row.kind = "dynamic";
  row.location = md.Z > 0.0 ? "height" : "ground";
  row.candidate = gov.label;
  row.clause = "C8.7.1.2.1.9 [V-T], NTC 2018 §7.3.5, " + e_text + (md.single_body() ? "" : ", chain model") +
               (md.tied() ? ", with the tie rods (tied one-sided rocking)" : "") +
               (md.filter ? ", floor motions (first-mode filter)" : md.floor_input ? ", floor motions given" : "");
  row.formula = (s.rule == "mean" ? "mean of peak d* over " : "largest peak d* of ") + nrec;
  int collapses = 0;
  for (const DynamicRun& r : a.dynamics.runs) collapses += r.restitution == ie && r.collapse ? 1 : 0;
  // The note, as data (note.hpp): the collapses, the records' rule, compatibility, failures.
  if (!s.any_collapse)
    row.note.push_back({"check.d0_never", {}});
  else if (md.tied())
    row.note.push_back({"check.d0_exceeded_tied",
                        {count_arg(std::size_t(collapses)), count_arg(std::size_t(s.analyses)),
                         count_arg(std::size_t(s.overturned)), count_arg(std::size_t(s.ruptured))}});
  else
    row.note.push_back({"check.d0_exceeded", {count_arg(std::size_t(collapses)), count_arg(std::size_t(s.analyses)),
                                              count_arg(std::size_t(s.overturned))}});
  row.note.push_back(s.records == 1 ? Note{"check.records_one", {}}
                                    : Note{"check.records", {count_arg(std::size_t(s.records))}});
  row.note.push_back({s.rule == "mean"                ? "check.rule_mean"
                      : s.rule == "most unfavourable" ? "check.rule_worst"
                      : s.any_collapse                ? "check.rule_few_collapse"
                                                      : "check.rule_few",
                      {}});
  if (a.dynamics.compatibility.computed && !a.dynamics.compatibility.band_satisfied)
    row.note.push_back({"check.not_compatible", {}});
  if (s.failed)
    row.note.push_back({"check.failed", {count_arg(std::size_t(s.failed)), count_arg(std::size_t(s.analyses))}});
  row.demand = s.d_demand;
  row.capacity = dynamic_d_SLV(gov.result);
  row.unit = "m";
  row.dc = s.dc_slv;
  row.no_verdict = s.no_verdict;
  row.analyses = s.analyses;
  row.collapsed = s.collapsed;
  row.failed = s.failed;
  row.dc_survivors = s.dc_survivors;
  decide(row);
  return row;
}

// The seed paper's energy measure of one restitution value (seed §3.2): the
// mean over the analyses, never shown as satisfied while any analysis overturned.
CheckRow energy_row(const FacadeAssessment& a, std::size_t ie, const CandidateResult& gov) {
  const RestitutionSummary& s = a.dynamics.summaries[ie];
  CheckRow en;
  en.code = "seed";
  en.limit_state = "SLV";
  en.kind = "dynamic energy";
  en.location = "ground";
  en.candidate = gov.label;
  en.clause = "seed §3.2 energy D/C (not a code check), " + describe(a.dynamics.spec->restitutions[ie]) +
              (a.dynamics.mechanism->tied() ? ", on the tied wall's restoring moment with the ties at their strength"
                                            : "");
  en.formula = "mean over " + std::to_string(s.analyses) + " analyses of the energy demand/capacity";
  en.demand = s.energy_dc;
  en.capacity = 1.0;
  en.unit = "-";
  en.dc = s.energy_dc;
  en.analyses = s.analyses;
  en.collapsed = s.overturned;
  en.failed = s.failed;
  en.dc_survivors = s.mean_dc_survivors;
  decide(en);
  en.note = {{"check.overturned", {count_arg(std::size_t(s.overturned)), count_arg(std::size_t(s.analyses))}}};
  return en;
}

// The other candidates that govern a code or fail a kinematic check (issue
// 24): each analysed as the case restricted to it, as if run alone (over the
// shared range when there is one); their dynamic and energy rows and their
// warnings join the façade's.
void add_other_dynamics(FacadeAssessment& a, const FacadeOptions& opt, const std::vector<std::size_t>& others,
                        const std::optional<PeriodRange>& shared) {
  FacadeOptions sub_opt = opt;  // histories kept as asked: the relazione develops the candidate that governs
  sub_opt.sensitivity = false;
  sub_opt.review = false;       // the review is the whole façade's
  sub_opt.kinematic = nullptr;  // the case restricted to the candidate analyses its own
  for (std::size_t i : others) {
    CaseFile one = a.kase;
    one.mechanism.candidates = {a.kase.mechanism.candidates[i]};
    if (shared) one.dynamic["select"]["period_range_s"] = nlohmann::json::array({shared->T_min, shared->T_max});
    FacadeAssessment sub = assess_facade(one, sub_opt);
    if (shared && sub.selection.result) {
      const KinematicResult& k = a.kinematic.candidates[i].result;
      sub.selection.range_note = range_note(*a.dynamics.spec->selection, k, *shared, std::min(k.Ts, k.T_SLV),
                                            std::max(k.Ts, k.T_SLV), true);
    }
    sub.selection.shared_note = a.selection.shared_note;
    for (const CheckRow& r : sub.checks)
      if (r.kind == "dynamic") a.checks.push_back(r);
    std::vector<CheckRow>& energy = a.dynamics.energy_rows;
    energy.insert(energy.end(), sub.dynamics.energy_rows.begin(), sub.dynamics.energy_rows.end());
    for (const std::string& w : sub.warnings)
      if (std::find(a.warnings.begin(), a.warnings.end(), w) == a.warnings.end()) a.warnings.push_back(w);
    a.other_dynamics.push_back(std::move(sub));
    a.other_dynamics_candidate.push_back(i);
  }
}

// The dynamic part of the assessment (Circ. 2019 C8.7.1.2.1.9): the model of
// the governing candidate, its records (listed or selected), every analysis,
// the dynamic and energy rows, and the other candidates' dynamics (issue 24).
void add_dynamic_analysis(FacadeAssessment& a, const FacadeOptions& opt) {
  const CaseFile& kase = a.kase;
  a.dynamics.spec = parse_dynamic(kase.dynamic, kase.file, directory_of(kase.file));
  const CandidateResult& gov = a.kinematic.candidates[a.kinematic.governing];
  if (!add_dynamic_model(a, gov, kase.mechanism.candidates[a.kinematic.governing].chain)) return;
  const MechanismDynamics& md = *a.dynamics.mechanism;
  const ElasticSpectrum& target = a.site.spectra.at(LimitState::SLV);
  const std::vector<std::size_t> others =
      kase.mechanism.candidates.size() > 1 ? dynamic_candidates(a.kinematic) : std::vector<std::size_t>{};
  const std::optional<PeriodRange> shared = shared_range(a, gov, others, target);
  const LoadedRecords loaded = load_records(a, *a.dynamics.spec, opt, target, gov.result, shared);
  flag_records(a);
  warn_record_pga(a);
  compatibility(a, loaded.recs, target, gov.result);
  record_curves(a, loaded, md);
  base_motions(a, loaded, md);
  // Control point of the kinematic analysis, for the C8.7.1.2.1.9 displacements.
  a.dynamics.runs = dynamic_runs(a, md, gov.result, opt.histories);
  a.dynamics.summaries = summarise_runs(a.dynamics.runs, md.e, gov.result);
  for (std::size_t ie = 0; ie < md.e.size(); ++ie) {
    a.checks.push_back(dynamic_row(a, ie, gov));
    a.dynamics.energy_rows.push_back(energy_row(a, ie, gov));
  }
  add_other_dynamics(a, opt, others, shared);
}

}  // namespace

}  // namespace assess

// fragility_study.cpp: set-up of a fragility analysis (docs/theory/fragility.md §4).
//
// The mechanism part is the one of assess_facade (assessment/facade_assessment.cpp):
// the governing candidate of the kinematic analysis and its dynamic model from
// build_mechanism_dynamics (rocking body, or chain model for several blocks;
// at height the first-mode floor motion, records/floor_motion). The records are chosen per stripe
// with records/record_selection (ScaleRule::Pga: each record's PGA equals the
// stripe's Se(0), so every analysis of a stripe has exactly the stripe's IM).
#include "assess/risk/fragility_study.hpp"

#include "assess/report/note_text.hpp"

#include "assess/hazard/site.hpp"
#include "assess/records/library_selection.hpp"
#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_library.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/selection_candidates.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace assess {

namespace {

std::string fmt(double v, const char* f = "%.4g") {
  char buf[40];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string directory_of(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? "." : path.substr(0, p);
}

}  // namespace

std::string to_string(FragilityMethod m) { return m == FragilityMethod::stripes ? "stripes" : "ida"; }

void FragilityOptions::validate() const {
  for (std::size_t i = 0; i < return_periods.size(); ++i)
    if (!(return_periods[i] >= tr_min_years && return_periods[i] <= tr_max_years))
      throw InputError("--stripes: return period " + std::to_string(i + 1) + " (" + fmt(return_periods[i]) +
                       " years) must lie in [30, 2475] years, the range of the hazard data");
  for (std::size_t i = 0; i < ida_levels.size(); ++i)
    if (!(ida_levels[i] > 0.0) || !std::isfinite(ida_levels[i]))
      throw InputError("--ida-levels: level " + std::to_string(i + 1) + " must be a PGA > 0 (g)");
  if (records < 0 || records > 1000) throw InputError("--records: expected 0 (the case's count) to 1000 records");
  if (bootstrap < 0 || bootstrap > 100000) throw InputError("--bootstrap: expected 0 to 100000 replicates");
  if (!(confidence > 0.0 && confidence < 1.0)) throw InputError("confidence: expected a fraction in (0, 1)");
}

std::uint64_t FragilityStudy::groups() const {
  std::uint64_t n = 0;
  for (const Stripe& s : stripes) n += s.records.size();
  return n;
}

std::pair<std::size_t, std::size_t> FragilityStudy::group(std::uint64_t g) const {
  for (std::size_t i = 0; i < stripes.size(); ++i) {
    if (g < stripes[i].records.size()) return {i, std::size_t(g)};
    g -= stripes[i].records.size();
  }
  throw InputError("fragility: group " + std::to_string(g) + " out of range");
}

namespace {

// The site: its description, nominal and reference life, PGA hazard curve, and
// each limit state's action with its PGA on the site's ground.
void prepare_site(FragilityStudy& st, const CaseFile& kase, const Site& site) {
  st.site_description = site.describe();
  st.VN = kase.site->vn_years;
  st.VR = site.VR();
  try {
    st.hazard = site_pga_hazard_curve(site);
  } catch (const InputError& e) {
    throw InputError(kase.file + ": /site: " + e.what());
  }
  for (LimitState ls : all_limit_states) {
    st.actions[ls] = site.action(ls);
    st.action_pga[ls] = ElasticSpectrum(st.actions[ls].hazard, kase.site->conditions, 5.0).Se(0.0);
  }
}

// The mechanism: the governing candidate, as in the façade assessment, and the
// dynamic model of `assess run` (errors name the file and the JSON path).
void prepare_mechanism(FragilityStudy& st, const CaseFile& kase) {
  const KinematicCaseResult kin = run_kinematic_case(kase);
  st.checks = kin.checks;
  const CandidateResult& gov = kin.candidates[kin.governing];
  st.mechanism = gov.label;
  st.kinematic = gov.result;
  st.dynamic = parse_dynamic(kase.dynamic, kase.file, directory_of(kase.file));
  const DynamicSpec& d = st.dynamic;
  // The IM is the PGA of the ground motion (the hazard curve's): floor motions
  // given by the user have no hazard curve to scale them to.
  if (d.floor_input)
    throw InputError(kase.file + ": /dynamic/input: \"floor\": a fragility scales ground records to the PGA on the "
                     "site's ground (the hazard curve's intensity measure); floor motions given by the user have no "
                     "hazard curve: give ground records (at height they are filtered to the floor by the building's "
                     "first mode, /building)");
  st.dynamics = build_mechanism_dynamics(kase, gov, kase.mechanism.candidates[kin.governing].chain, d);
  if (!st.dynamics.applies)
    throw InputError(kase.file + ": /mechanism: the dynamic model does not apply to the governing mechanism '" +
                     gov.label + "': " + note_text(Lang::en, st.dynamics.note) + "; a fragility needs its dynamic analyses");
  for (const Restitution& r : d.restitutions) st.restitution_labels.push_back(describe(r));
  if (d.polarity != Polarity::reversed) st.polarities.push_back(false);
  if (d.polarity != Polarity::normal) st.polarities.push_back(true);
}

// The case's selection limits, as `assess run` (assessment/facade_assessment.cpp,
// docs/theory/record-selection.md §2): scale, mean scale, PGA guard, records
// per event and per station; the count may be overridden (--records).
SelectionOptions selection_options(const DynamicSpec& d, int count, double max_scale, ScaleRule rule,
                                   const PeriodRange& range) {
  SelectionOptions so;
  so.n_records = count;
  so.scale_rule = rule;
  so.range = range;
  if (d.selection) {
    const RecordSelectionSpec& rs = *d.selection;
    so.max_scale = rs.max_scale;
    so.max_mean_scale = rs.max_mean_scale;
    so.max_pga_ratio = rs.max_pga_ratio;
    so.max_per_event = rs.max_per_event;
    so.max_per_station = rs.max_per_station;
    so.max_misfit = rs.max_misfit;
  } else {
    so.max_scale = max_scale;
  }
  return so;
}

// The records of a study: those the selections choose from the record library
// (read once per process, records/record_library.hpp), each added to the study
// once, or the listed ones (for an IDA).
class RecordPool {
 public:
  RecordPool(FragilityStudy& st, const CaseFile& kase, int count) : st_(st), kase_(kase) {
    const DynamicSpec& d = st.dynamic;
    if (!d.selection) {
      for (const ListedRecord& lr : d.records) {
        try {
          st.records.push_back(read_listed_record(lr));
          st.record_files.push_back(lr.file);
        } catch (const InputError& e) {
          throw InputError(kase.file + ": " + lr.json_path + "/file: " + e.what());
        }
      }
      return;
    }
    const RecordSelectionSpec& rs = *d.selection;
    lib_ = RecordLibrary::open(rs.catalogue);
    // The case's rules, as `assess run` (record-selection.md §2): catalogue
    // filters, site class first, near-fault records left out unless asked.
    rules_.filters = catalogue_filters(rs, to_string(kase.site->conditions.soil), count);
    rules_.include_near_fault = rs.include_near_fault;
    rules_.near_fault_km = rs.near_fault_km;
  }

  // The library's selection for a target spectrum; its warnings kept once ("site
  // class relaxed" with `prefix`, the stripe it belongs to).
  std::shared_ptr<const LibrarySelection> select(const ElasticSpectrum& target, const SelectionOptions& so,
                                                 const std::string& prefix) {
    const std::shared_ptr<const LibrarySelection> sel =
        select_from_library(*lib_, rules_, [&target](double T) { return target.Se(T); }, so);
    for (const std::string& w : sel->warnings) {
      const std::string v = w.rfind("site class relaxed", 0) == 0 ? prefix + w : w;
      if (std::find(st_.selection_warnings.begin(), st_.selection_warnings.end(), v) == st_.selection_warnings.end())
        st_.selection_warnings.push_back(v);
    }
    return sel;
  }

  // The study's index of a selected record, read the first time it is used.
  std::size_t use(const CatalogueEntry& e) {
    const auto it = index_of_.find(e.id);
    if (it != index_of_.end()) return it->second;
    try {
      st_.records.push_back(*lib_->record(e));
    } catch (const InputError& err) {
      throw InputError(kase_.file + ": /dynamic/select/catalogue: " + e.file + ": " + err.what());
    }
    st_.record_files.push_back(lib_->catalogue().directory + "/" + e.file);
    index_of_[e.id] = st_.records.size() - 1;
    return st_.records.size() - 1;
  }

 private:
  FragilityStudy& st_;
  const CaseFile& kase_;
  std::shared_ptr<const RecordLibrary> lib_;
  LibrarySelectionRules rules_;
  std::map<std::string, std::size_t> index_of_;  // catalogue id -> position in st.records
};

// Multiple stripes: at each return period, records selected from the library
// and scaled to the PGA of that period's spectrum.
void add_msa_stripes(FragilityStudy& st, RecordPool& pool, const CaseFile& kase, const Site& site,
                     const SelectionOptions& so, double max_scale) {
  std::vector<double> trs = st.options.return_periods;
  if (trs.empty()) trs.assign(grid_return_periods.begin(), grid_return_periods.end());
  std::sort(trs.begin(), trs.end());
  trs.erase(std::unique(trs.begin(), trs.end()), trs.end());
  // Each stripe selects from the library (precomputed spectra, the same
  // candidates' spectra for every target: records/library_selection.hpp).
  for (double tr : trs) {
    const ElasticSpectrum target(site.hazard_at_tr(tr), kase.site->conditions, 5.0);
    const std::shared_ptr<const LibrarySelection> sel = pool.select(target, so, "stripe " + fmt(tr) + " years: ");
    Stripe s;
    s.im = target.Se(0.0);
    s.TR = tr;
    s.compatible = sel->result.band_satisfied;
    s.selection = sel->result.message;
    for (const SelectedRecord& r : sel->result.records) s.records.push_back({pool.use(sel->candidates[r.index]), r.scale});
    if (s.records.empty())
      throw InputError(kase.file + ": /dynamic/select: no set of " + std::to_string(so.n_records) +
                       " catalogue records for the " + fmt(tr) + "-year stripe (PGA " +
                       fmt(s.im / units::g, "%.3f") + " g, max_scale " + fmt(max_scale) + "): " + sel->result.message +
                       "; ask for fewer records per stripe (--records, select/count)");
    st.stripes.push_back(std::move(s));
  }
}

// Incremental dynamic analysis: one fixed set (the listed records, or the
// selection at SLV with least-squares scaling, as `assess run`) scaled to each level.
void add_ida_stripes(FragilityStudy& st, RecordPool& pool, const CaseFile& kase, const SelectionOptions& so) {
  std::vector<std::size_t> set;
  if (!st.dynamic.selection) {
    for (std::size_t i = 0; i < st.records.size(); ++i) set.push_back(i);
  } else {
    const ElasticSpectrum slv(st.actions.at(LimitState::SLV).hazard, kase.site->conditions, 5.0);
    const std::shared_ptr<const LibrarySelection> sel = pool.select(slv, so, "");
    for (const SelectedRecord& r : sel->result.records) set.push_back(pool.use(sel->candidates[r.index]));
    if (set.empty()) throw InputError(kase.file + ": /dynamic/select: no compatible record in the catalogue");
  }
  std::vector<double> levels = st.options.ida_levels;
  if (levels.empty()) {
    const double lo = 0.5 * st.hazard->points().front().im, hi = 3.0 * st.hazard->points().back().im;
    constexpr int n = 16;
    for (int i = 0; i < n; ++i) levels.push_back(lo * std::pow(hi / lo, double(i) / (n - 1)));
  }
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  for (double im : levels) {
    Stripe s;
    s.im = im;
    s.TR = 1.0 / st.hazard->lambda(im);
    for (std::size_t r : set) {
      const double pga = st.records[r].pga();
      if (!(pga > 0.0)) throw InputError(st.record_files[r] + ": the record's PGA is zero: it cannot be scaled");
      s.records.push_back({r, im / pga});
    }
    st.stripes.push_back(std::move(s));
  }
}

// At height: the floor motion of every record a stripe uses, once (the
// first-mode filter is linear: filter(scale x record) = scale x filter(record)).
void add_floor_inputs(FragilityStudy& st) {
  if (!st.dynamics.filter) return;
  std::vector<bool> used(st.records.size(), false);
  for (const Stripe& s : st.stripes)
    for (const StripeRecord& r : s.records) used[r.record] = true;
  st.floor_inputs.resize(st.records.size());
  for (std::size_t i = 0; i < st.records.size(); ++i)
    if (used[i]) st.floor_inputs[i] = st.dynamics.input(st.records[i]);
}

}  // namespace

FragilityStudy prepare_fragility(const CaseFile& kase, const FragilityOptions& opt) {
  opt.validate();
  FragilityStudy st;
  st.file = kase.file;
  st.project = kase.project;
  st.options = opt;
  if (!kase.site)
    throw InputError(kase.file + ": /site: missing: a fragility analysis needs the site's hazard curve (give "
                     "\"lat\"/\"lon\" or \"island\")");
  if (kase.dynamic.is_null())
    throw InputError(kase.file + ": /dynamic: missing: a fragility analysis needs the dynamic section (model, "
                     "restitution, records or select; docs/user/case-file.md)");
  const Site site(*kase.site);
  prepare_site(st, kase, site);
  prepare_mechanism(st, kase);
  const KinematicResult& k = st.kinematic;  // the governing candidate's
  const DynamicSpec& d = st.dynamic;

  const int count = opt.records > 0 ? opt.records : (d.selection ? d.selection->count : 7);
  const double max_scale = d.selection ? d.selection->max_scale : 5.0;
  const double T1 = std::min(k.Ts, k.T_SLV), T2 = std::max(k.Ts, k.T_SLV);
  const PeriodRange range = (d.selection && d.selection->T_min && d.selection->T_max)
                                ? PeriodRange{*d.selection->T_min, *d.selection->T_max}
                                : rocking_period_range(T1, T2);
  if (!d.selection && opt.method == FragilityMethod::stripes)
    throw InputError(kase.file + ": /dynamic/records: a multiple-stripe analysis selects records at each return "
                     "period from the catalogue: give \"select\" instead of \"records\", or use --ida to scale the "
                     "listed records");
  RecordPool pool(st, kase, count);
  if (opt.method == FragilityMethod::stripes)
    add_msa_stripes(st, pool, kase, site, selection_options(d, count, max_scale, ScaleRule::Pga, range), max_scale);
  else
    add_ida_stripes(st, pool, kase, selection_options(d, count, max_scale, SelectionOptions{}.scale_rule, range));
  add_floor_inputs(st);
  return st;
}

MechanismResponse FragilityStudy::respond(const Record& input, double scale, bool reversed,
                                          std::size_t restitution) const {
  RockingOptions ro = dynamic.options;
  ro.record_history = false;
  ro.scale = scale;
  ro.reverse = reversed;
  const RockingResult r = dynamics.analyse(restitution, input, ro);
  MechanismResponse m;
  m.termination = r.termination;
  if (!m.ok()) {
    m.message = r.message.empty() ? to_string(r.termination) : r.message;
    return m;
  }
  m.theta_max = r.theta_max;
  m.theta_u = r.theta_u;
  // As in the façade assessment: the control point's peak horizontal
  // displacement at the peak coordinate (signed by its side), in the
  // equivalent SDOF [C8.7.1.4].
  const double d_control = dynamics.control_displacement(kinematic, r.theta_max_side * r.theta_max);
  m.d_star = d_control * kinematic.d_star_per_dk;
  m.dc_energy = r.dc;
  m.dc_displacement = kinematic.d_SLV > 0 ? m.d_star / kinematic.d_SLV : 0.0;
  m.overturned = r.overturned;
  return m;
}

}  // namespace assess

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
#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace assess {

namespace {

std::string directory_of(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? "." : path.substr(0, p);
}

void load_records(FacadeAssessment& a, const DynamicSpec& d, const FacadeOptions& opt,
                  const ElasticSpectrum& target, const KinematicResult& kin, std::vector<Record>& recs) {
  if (!d.selection) {
    for (const ListedRecord& lr : d.records) {
      try {
        Record r = read_record(lr.file);
        RecordUsed u{r.name, lr.file, r.event, r.station, r.component, lr.scale, r.pga() * lr.scale, lr.json_path};
        a.records.push_back(u);
        recs.push_back(std::move(r));
      } catch (const InputError& e) {
        if (!opt.keep_going) throw InputError(a.kase.file + ": " + lr.json_path + "/file: " + e.what());
        a.record_failures.push_back(lr.json_path + "/file: " + e.what());
      }
    }
    if (recs.empty()) throw InputError(a.kase.file + ": /dynamic/records: no record could be read");
    return;
  }
  const RecordSelectionSpec& rs = *d.selection;
  const RecordCatalogue cat = read_catalogue(rs.catalogue);
  std::vector<Record> candidates;
  std::vector<CatalogueEntry> entries;
  for (const CatalogueEntry& e : cat.design_candidates()) {
    try {
      candidates.push_back(cat.load(e.id));
      entries.push_back(e);
    } catch (const InputError& err) {
      if (!opt.keep_going) throw;
      a.record_failures.push_back(e.file + ": " + err.what());
    }
  }
  SelectionOptions so;
  so.n_records = rs.count;
  so.max_scale = rs.max_scale;
  // Default range around the mechanism's periods (docs/theory/record-selection.md).
  const double T1 = std::min(kin.Ts, kin.T_SLV), T2 = std::max(kin.Ts, kin.T_SLV);
  so.range = (rs.T_min && rs.T_max) ? PeriodRange{*rs.T_min, *rs.T_max} : rocking_period_range(T1, T2);
  a.selection_range = so.range;
  SelectionResult sel = select_records(target, candidates, so);
  for (const SelectedRecord& s : sel.records) {
    const CatalogueEntry& e = entries[s.index];
    Record r = candidates[s.index];
    a.records.push_back({r.name, cat.directory + "/" + e.file, e.event, e.station, e.component, s.scale,
                         r.pga() * s.scale, ""});
    recs.push_back(std::move(r));
  }
  a.selection = std::move(sel);
  if (recs.empty()) throw InputError(a.kase.file + ": /dynamic/select: no compatible record in the catalogue");
}

}  // namespace

FacadeAssessment assess_facade(const CaseFile& kase, const FacadeOptions& opt) {
  if (!kase.site)
    throw InputError(kase.file + ": /site: missing: the assessment checks the mechanism against the site's "
                     "seismic action (give \"lat\"/\"lon\", \"island\" or \"hazard\"); `assess kinematic` "
                     "analyses a mechanism without a site");
  FacadeAssessment a;
  a.kase = kase;
  a.kinematic = run_kinematic_case(kase);
  a.checks = a.kinematic.checks;
  const Site site(*kase.site);
  a.site_description = site.describe();
  a.VR = site.VR();
  for (LimitState ls : all_limit_states) {
    if (!kase.site->given.empty() && !kase.site->given.count(ls)) continue;
    a.actions[ls] = site.action(ls);
    a.spectra.emplace(ls, ElasticSpectrum(a.actions[ls].hazard, kase.site->conditions, 5.0));
  }
  a.periods = log_spaced_periods(0.02, 4.0, 48);
  a.periods.insert(a.periods.begin(), 0.0);
  for (const auto& [ls, s] : a.spectra)
    for (double T : a.periods) a.site_Se[ls].push_back(s.Se(T));
  if (kase.dynamic.is_null()) return a;

  a.dynamic = parse_dynamic(kase.dynamic, kase.file, directory_of(kase.file));
  const DynamicSpec& d = *a.dynamic;
  const CandidateResult& gov = a.kinematic.candidates[a.kinematic.governing];
  const Chain& chain = kase.mechanism.candidates[a.kinematic.governing].chain;
  if (!a.actions.count(LimitState::SLV))
    throw InputError(kase.file + ": /site/hazard: the dynamic analysis needs the SLV hazard (records are "
                     "compared with the SLV spectrum)");
  MechanismDynamics md = build_mechanism_dynamics(kase, gov, chain, d);
  if (!md.applies) {
    a.dynamic_note = md.note;
    return a;
  }
  a.dynamic_applies = true;
  if (md.single_body()) {
    a.body = md.body;
    a.model = md.rocking.front();
  }
  a.dynamic_note = md.describe();
  a.mechanism_dynamics = md;
  const ElasticSpectrum& target = a.spectra.at(LimitState::SLV);
  std::vector<Record> recs;
  load_records(a, d, opt, target, gov.result, recs);

  // Curves for the report: record spectra and the moment-rotation curve.
  a.mean_psa.assign(a.periods.size(), 0.0);
  a.record_psa.resize(recs.size());
  detail::parallel_for(recs.size(), [&](std::size_t ir) {
    a.record_psa[ir] = response_spectrum(recs[ir], a.periods).psa();
    for (double& v : a.record_psa[ir]) v *= a.records[ir].scale;
  });
  for (const auto& psa : a.record_psa)
    for (std::size_t j = 0; j < psa.size(); ++j) a.mean_psa[j] += psa[j] / double(recs.size());
  const double th_u = md.q_u();
  constexpr int n_mr = 200;
  for (int i = 0; i <= n_mr; ++i) {
    const double th = th_u * i / n_mr;
    a.mr_theta.push_back(th);
    a.mr_moment.push_back(md.restoring(th));
  }
  // The motion at the mechanism's base: floor motions at height (first-mode filter).
  std::vector<Record> inputs;
  for (const Record& r : recs) inputs.push_back(md.input(r));
  if (md.filter && kase.building) {
    a.floor_mean_psa.assign(a.periods.size(), 0.0);
    std::vector<std::vector<double>> psa(inputs.size());
    detail::parallel_for(inputs.size(), [&](std::size_t ir) { psa[ir] = response_spectrum(inputs[ir], a.periods).psa(); });
    for (std::size_t ir = 0; ir < inputs.size(); ++ir)
      for (std::size_t j = 0; j < a.periods.size(); ++j)
        a.floor_mean_psa[j] += psa[ir][j] * a.records[ir].scale / double(inputs.size());
    BuildingModel bm = *kase.building;
    bm.T1 = md.filter->T1;
    bm.damping_pct = md.filter_damping_pct;
    const FloorSpectrum fs(a.actions.at(LimitState::SLV).hazard, kase.site->conditions, bm, std::min(md.Z, bm.H), 5.0);
    for (double T : a.periods) a.code_floor_Se.push_back(fs.Se(T));
  }

  // Control point of the kinematic analysis, for the C8.7.1.2.1.9 displacements.
  const KinematicResult& kin = gov.result;
  std::vector<bool> polarities;
  if (d.polarity != Polarity::reversed) polarities.push_back(false);
  if (d.polarity != Polarity::normal) polarities.push_back(true);
  // Every (restitution, record, polarity) analysis, in this order, on all cores.
  for (std::size_t ie = 0; ie < md.e.size(); ++ie)
    for (std::size_t ir = 0; ir < recs.size(); ++ir)
      for (bool rev : polarities) {
        DynamicRun run;
        run.record = ir;
        run.reversed = rev;
        run.restitution = ie;
        run.e = md.e[ie];
        a.runs.push_back(std::move(run));
      }
  detail::parallel_for(a.runs.size(), [&](std::size_t i) {
    DynamicRun& run = a.runs[i];
    RockingOptions ro = d.options;
    ro.record_history = opt.histories;
    ro.scale = a.records[run.record].scale;
    ro.reverse = run.reversed;
    run.result = md.analyse(run.restitution, inputs[run.record], ro);
    run.theta_ratio = run.result.theta_u > 0 ? run.result.theta_max / run.result.theta_u : 0.0;
    // Peak outward rotation moves the control point outward (one-sided:
    // theta >= 0); for two-sided, |theta| on either side (symmetric body).
    run.d_control = md.control_displacement(kin, run.result.theta_max_side * run.result.theta_max);
    run.d_star = run.d_control * kin.d_star_per_dk;
    run.collapse = run.result.overturned || run.d_control >= kin.dk0;
  });
  // Summaries per restitution value.
  for (std::size_t ie = 0; ie < md.e.size(); ++ie) {
    RestitutionSummary s;
    s.restitution = ie;
    s.e = md.e[ie];
    s.min_dc = 1e300;
    std::map<std::size_t, double> envelope;  // record -> peak d* over polarities
    for (const DynamicRun& r : a.runs) {
      if (r.restitution != ie) continue;
      ++s.analyses;
      s.overturned += r.result.overturned ? 1 : 0;
      s.mean_dc += r.result.dc;
      s.min_dc = std::min(s.min_dc, r.result.dc);
      s.max_dc = std::max(s.max_dc, r.result.dc);
      s.mean_theta_ratio += r.theta_ratio;
      s.any_collapse = s.any_collapse || r.collapse;
      envelope[r.record] = std::max(envelope[r.record], r.d_star);
    }
    s.mean_dc /= s.analyses;
    s.mean_theta_ratio /= s.analyses;
    for (const auto& [rec, dmax] : envelope) s.mean_d_star += dmax;
    s.mean_d_star /= double(envelope.size());
    s.dc_slv = kin.d_SLV > 0 ? s.mean_d_star / kin.d_SLV : 0.0;
    s.slv_satisfied = !s.any_collapse && s.mean_d_star <= kin.d_SLV;
    a.summaries.push_back(s);

    CheckRow row;
    row.code = "NTC2018";
    row.limit_state = "SLV";
    row.kind = "dynamic";
    row.location = md.Z > 0.0 ? "height" : "ground";
    row.clause = "C8.7.1.2.1.9 [V-T], " + describe(d.restitutions[ie]) +
                 (md.single_body() ? "" : ", chain model") +
                 (md.filter ? ", floor motions (first-mode filter)" : md.floor_input ? ", floor motions given" : "");
    row.formula = std::string("mean of peak d* over ") + std::to_string(envelope.size()) + " records" +
                  (s.any_collapse ? "; d0 exceeded in " + std::to_string(s.overturned) + " analyses" : "; d0 never exceeded");
    row.demand = s.mean_d_star;
    row.capacity = kin.d_SLV;
    row.unit = "m";
    row.dc = s.dc_slv;
    row.satisfied = s.slv_satisfied;
    a.checks.push_back(row);
  }
  return a;
}

}  // namespace assess

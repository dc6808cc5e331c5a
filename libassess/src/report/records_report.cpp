// records_report.cpp: the record library as `assess records` shows it
// (report/records_report.hpp), moved from apps/cmd_records.cpp for issue 40
// so that the Python module returns the same.
#include "assess/report/records_report.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <cstdio>

namespace assess {
namespace {

std::string num(double v, const char* f) {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

nlohmann::ordered_json jnum(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

bool RecordFilterOptions::filtering() const {
  return mw_min || mw_max || r_min || r_max || !site_classes.empty() || !countries.empty();
}

CatalogueFilters catalogue_filters(const RecordFilterOptions& o) {
  CatalogueFilters f;
  if (o.mw_min) f.Mw_min = *o.mw_min, f.Mw_given = true;
  if (o.mw_max) f.Mw_max = *o.mw_max, f.Mw_given = true;
  if (o.r_min) f.R_min_km = *o.r_min, f.R_given = true;
  if (o.r_max) f.R_max_km = *o.r_max, f.R_given = true;
  // A window the wrong way round is the options' fault, named here (issue 39:
  // it reached the selection's memo, whose error aborted the process).
  if (f.Mw_given && !(f.Mw_min <= f.Mw_max))
    throw InputError("--mw-min " + num(f.Mw_min, "%.3g") + (o.mw_min ? "" : " (the default)") + " is above --mw-max " +
                     num(f.Mw_max, "%.3g") + (o.mw_max ? "" : " (the default)") + ": expected a window with min <= max");
  if (f.R_given && !(f.R_min_km <= f.R_max_km))
    throw InputError("--r-min " + num(f.R_min_km, "%.3g") + (o.r_min ? "" : " (the default)") + " km is above --r-max " +
                     num(f.R_max_km, "%.3g") + (o.r_max ? "" : " (the default)") + " km: expected a window with min <= max");
  f.site_classes = o.site_classes;
  for (const auto& c : f.site_classes)
    if (c.size() != 1 || std::string("ABCDE").find(c) == std::string::npos)
      throw InputError("--site-class '" + c + "': expected A, B, C, D or E");
  f.countries = o.countries;
  f.relax_site_class = o.relax;
  return f;
}

std::vector<CatalogueEntry> catalogue_listing(const RecordCatalogue& cat, const RecordFilterOptions& o, bool all) {
  if (all && !o.filtering()) return cat.entries;
  CatalogueFilters f = catalogue_filters(o);
  if (!f.Mw_given) f.Mw_min = 0.0, f.Mw_max = 10.0, f.Mw_given = true;  // list: no default window
  if (!f.R_given) f.R_min_km = 0.0, f.R_max_km = 1e9, f.R_given = true;
  f.relax_site_class = false;
  return filter_catalogue(cat.entries, f).kept;
}

nlohmann::ordered_json catalogue_entry_json(const CatalogueEntry& e) {
  nlohmann::ordered_json j;
  j["id"] = e.id;
  j["file"] = e.file;
  j["event"] = e.event;
  j["date"] = e.date;
  j["Mw"] = jnum(e.Mw);
  j["station"] = e.station;
  j["component"] = e.component;
  j["positive_direction"] = e.positive_direction;
  j["distance_km"] = jnum(e.distance_km);
  j["distance_kind"] = e.distance_kind;
  j["vs30_m_s"] = jnum(e.vs30_m_s);
  j["site_class"] = e.site_class;
  j["site_class_basis"] = e.site_class_basis;
  j["vs30_class"] = e.vs30_class;
  j["country"] = e.country;
  j["lowest_usable_hz"] = jnum(e.lowest_usable_hz);
  j["pulse"] = e.pulse;
  j["pulse_period_s"] = jnum(e.pulse_period_s);
  j["near_fault"] = near_fault_reason(e);
  j["pga_g"] = e.pga_g;
  j["significant_duration_s"] = e.significant_duration_s;
  j["usable_for_design"] = e.usable_for_design;
  j["note"] = e.note;
  return j;
}

SiteRecordSelection select_for_site(const Site& site, LimitState ls, const RecordLibrary& library,
                                    LibrarySelectionRules rules, const SelectionOptions& options) {
  SiteRecordSelection s;
  s.limit_state = ls;
  s.site = site.describe();
  s.soil = to_string(site.spec().conditions.soil);
  const ElasticSpectrum target = site.spectrum(ls);
  s.ag_S_g = target.Se(0.0) / units::g_n;
  if (rules.filters.site_classes.empty()) rules.filters.site_classes = {s.soil};
  s.rules = rules;
  s.options = options;
  s.selection = select_from_library(library, s.rules, [&](double T) { return target.Se(T); }, options);
  if (s.selection->candidates.empty())
    throw InputError("no record of the catalogue passes the filters (see `assess records list`)");
  return s;
}

bool parse_near_fault_option(const std::string& text) {
  if (text != "exclude" && text != "include")
    throw InputError("--near-fault '" + text + "': expected exclude or include");
  return text == "include";
}

std::vector<std::string> selection_flags(const SiteRecordSelection& s, const SelectedRecord& r) {
  const CatalogueEntry& e = s.selection->candidates[r.index];
  std::vector<std::string> f;
  const std::string nf = near_fault_reason(e, s.rules.near_fault_km);
  if (!nf.empty()) f.push_back(nf);
  if (r.misfit_flag) f.push_back("misfit " + num(r.deviation, "%.3f") + " > " + num(s.options.max_misfit, "%.2f"));
  if (e.site_class != s.soil) f.push_back("site class " + e.site_class + ", not the site's " + s.soil);
  return f;
}

nlohmann::ordered_json site_selection_json(const SiteRecordSelection& s) {
  const LibrarySelection& sel = *s.selection;
  const SelectionResult& res = sel.result;
  const SelectionOptions& so = s.options;
  nlohmann::ordered_json j;
  j["limit_state"] = to_string(s.limit_state);
  j["site"] = s.site;
  j["ag_S_g"] = s.ag_S_g;
  j["status"] = to_string(res.status);
  j["message"] = res.message;
  j["warnings"] = sel.warnings;
  j["site_classes"] = sel.site_classes;
  j["spectra"] = sel.spectra_source;
  j["near_fault_excluded"] = sel.near_fault_excluded;
  j["period_range_s"] = {so.range.T_min, so.range.T_max};
  j["band"] = {1.0 - so.lower_tol, 1.0 + so.upper_tol};
  j["min_ratio"] = res.min_ratio;
  j["max_ratio"] = res.max_ratio;
  j["mean_scale"] = res.mean_scale;
  j["candidates"] = sel.candidates.size();
  j["eligible"] = res.eligible;
  j["combinations"] = res.combinations;
  j["records"] = nlohmann::ordered_json::array();
  for (const auto& r : res.records) {
    nlohmann::ordered_json e = catalogue_entry_json(sel.candidates[r.index]);
    e["scale"] = r.scale;
    e["scaled_pga_g"] = r.scaled_pga / units::g_n;
    e["deviation"] = r.deviation;
    e["rank"] = r.rank;
    e["flags"] = selection_flags(s, r);
    j["records"].push_back(e);
  }
  j["rejected"] = nlohmann::ordered_json::array();
  for (const auto& r : sel.excluded) j["rejected"].push_back({{"id", r.name}, {"reason", r.reason}});
  for (const auto& r : res.rejected)
    j["rejected"].push_back({{"id", sel.candidates[r.index].id}, {"scale", r.scale}, {"reason", r.reason}});
  j["periods_s"] = res.periods;
  j["target_m_s2"] = res.target;
  j["mean_psa_m_s2"] = res.mean_psa;
  return j;
}

}  // namespace assess

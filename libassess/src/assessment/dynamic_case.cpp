// dynamic_case.cpp: parsing of the "dynamic" section of a case file.
#include "assess/assessment/dynamic_case.hpp"

#include "assess/dynamics/analysis_limits.hpp"

#include "assess/support/error.hpp"
#include "assess/hazard/hazard.hpp"
#include "assess/support/json_input.hpp"
#include "assess/support/units.hpp"

#include <cstdio>
#include <sys/stat.h>

namespace assess {

namespace {

bool exists(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

// A record file: absolute, else relative to the case file, else to the data dir.
std::string resolve(const std::string& f, const std::string& case_dir) {
  if (!f.empty() && f[0] == '/') return f;
  const std::string a = (case_dir.empty() ? std::string(".") : case_dir) + "/" + f;
  if (exists(a)) return a;
  const std::string b = data_dir() + "/" + f;
  if (exists(b)) return b;
  return a;  // reported as missing by the reader, with this path
}

Restitution parse_restitution(const JsonNode& n) {
  if (n.value().is_string()) {
    const std::string s = n.as_string();
    if (s == "housner") return Restitution::housner();
    if (s == "one-sided-theory") return Restitution::one_sided_theory();
    if (s == "none") return Restitution::none();
    n.fail("expected a coefficient of restitution in [-1, 1] (-) or one of \"housner\", \"one-sided-theory\", "
           "\"none\", got \"" + s + "\"");
  }
  return Restitution::given(n.as_number("(-, ratio of angular velocities after/before impact)", -1.0, 1.0));
}

}  // namespace

Record read_listed_record(const ListedRecord& r) {
  if (!r.unit) return read_record(r.file);
  return r.dt ? read_plain_record(r.file, *r.dt, *r.unit) : read_plain_record(r.file, *r.unit);
}

std::string describe(const Restitution& r) {
  switch (r.kind) {
    case Restitution::Kind::value: {
      char buf[32];
      std::snprintf(buf, sizeof buf, "e = %.3g", r.e);
      return buf;
    }
    case Restitution::Kind::housner: return "Housner";
    case Restitution::Kind::one_sided_theory: return "one-sided theory";
    case Restitution::Kind::none: return "none";
  }
  return "?";
}

std::string to_string(Polarity p) {
  switch (p) {
    case Polarity::normal: return "normal";
    case Polarity::reversed: return "reversed";
    case Polarity::both: return "both";
  }
  return "?";
}

DynamicSpec parse_dynamic(const nlohmann::json& doc, const std::string& file, const std::string& case_dir) {
  const JsonNode d(doc, file, "/dynamic");
  if (!d.is_object()) d.fail("expected an object");
  d.allow_only({"model", "k", "sidedness", "restitution", "polarity", "overturn_at", "records", "select",
                "tail_s", "integrator", "whole_record", "free_tail_s", "input", "floor_filter"});
  DynamicSpec s;
  auto assumed = [&](const JsonNode& n, const char* key, std::string value, const char* effect) {
    if (!n.has(key)) s.defaults.push_back({n.path() + "/" + key, std::move(value), effect});
  };
  assumed(d, "model", "smooth", "default.model");
  assumed(d, "sidedness", "one-sided", "default.sidedness");
  assumed(d, "polarity", "normal", "default.polarity");
  s.smooth = d.has("model") ? d.choice("model", {"smooth", "rigid"}) == "smooth" : true;
  if (s.smooth) {
    s.k = d.positive("k", "kN/m3 (Winkler modulus of the base)") * units::kN;
    if (s.k > limits::winkler_k_max_N_m3)
      d.at("k").as_number("kN/m3 (Winkler modulus of the base; a stiffer base is rigid: use \"model\": \"rigid\")", 0.0,
                          limits::winkler_k_max_N_m3 / units::kN);
  } else if (d.has("k")) {
    d.at("k").fail("a Winkler modulus is only used by the smooth model; remove it or set \"model\": \"smooth\"");
  }
  s.sidedness = d.has("sidedness") && d.choice("sidedness", {"one-sided", "two-sided"}) == "two-sided"
                    ? Sidedness::two_sided
                    : Sidedness::one_sided;
  s.restitution_given = d.has("restitution");
  if (d.has("restitution")) {
    const JsonNode r = d.at("restitution");
    if (r.value().is_array()) {
      for (const JsonNode& e : d.array("restitution", 1)) s.restitutions.push_back(parse_restitution(e));
    } else {
      s.restitutions.push_back(parse_restitution(r));
    }
  } else {
    s.restitutions.push_back(s.sidedness == Sidedness::one_sided ? Restitution::one_sided_theory()
                                                                  : Restitution::housner());
    s.defaults.push_back({d.path() + "/restitution", describe(s.restitutions.back()), "default.restitution"});
  }
  if (d.has("polarity")) {
    const std::string p = d.choice("polarity", {"normal", "reversed", "both"});
    s.polarity = p == "both" ? Polarity::both : p == "reversed" ? Polarity::reversed : Polarity::normal;
  }
  if (d.has("overturn_at"))
    s.options.overturn = d.choice("overturn_at", {"theta_u", "half_pi"}) == "half_pi" ? OverturnCriterion::half_pi
                                                                                      : OverturnCriterion::theta_u;
  s.options.tail_s = d.number_or("tail_s", s.options.tail_s,
                                 "s (cap on the free motion after the record; it ends earlier at rest or when its "
                                 "energy has decayed)",
                                 0.0, limits::tail_max_s);
  // Issue 21: every record is integrated to its last sample. "whole_record":
  // true is what always happens (accepted); asking for a cut is an error.
  if (d.has("whole_record") && !d.boolean_or("whole_record", true))
    d.at("whole_record").fail("records are no longer cut at 99.9 % of their Arias intensity: every record is "
                              "integrated to its last sample, then the free motion (cap \"tail_s\", s); remove the "
                              "key");
  if (d.has("free_tail_s"))
    d.at("free_tail_s").fail("no longer used: the free motion after the whole record is capped by \"tail_s\" (s, "
                             "default 30) and ends earlier at rest or when its energy has decayed; rename the key");
  if (auto in = d.find("integrator")) {
    in->allow_only({"stepper", "rel_tol", "abs_tol"});
    if (in->has("stepper")) {
      s.options.stepper = *parse_stepper(in->choice("stepper", {"rk8pd", "rkck", "rkf45"}));
    }
    s.options.rel_tol = in->number_or("rel_tol", s.options.rel_tol, "(-)", limits::rel_tol_min, limits::rel_tol_max);
    s.options.abs_tol = in->number_or("abs_tol", s.options.abs_tol, "rad", limits::abs_tol_min, limits::abs_tol_max);
  }
  if (d.has("input")) s.floor_input = d.choice("input", {"ground", "floor"}) == "floor";
  if (auto ff = d.find("floor_filter")) {
    if (s.floor_input)
      ff->fail("the records are floor motions (\"input\": \"floor\"): they are not filtered; remove \"floor_filter\"");
    ff->allow_only({"T1_s", "damping_pct"});
    if (ff->has("T1_s")) s.filter_T1 = ff->number("T1_s", "s (first-mode period of the building)", 0.01, 10.0);
    if (ff->has("damping_pct"))
      s.filter_damping_pct = ff->number("damping_pct", "% (first-mode damping of the building)", 0.0, 99.0);
  }
  if (s.floor_input && d.has("select"))
    d.at("select").fail("floor motions (\"input\": \"floor\") must be listed in \"records\": the catalogue "
                        "selection matches ground motions to the site spectrum");
  if (d.has("records") == d.has("select"))
    d.fail("give either \"records\" (a list of {\"file\", \"scale\"}) or \"select\" ({\"count\": N}), not both "
           "and not neither");
  if (d.has("records")) {
    const std::vector<JsonNode> recs = d.array("records", 0);
    if (recs.empty()) d.at("records").fail("expected at least one record {\"file\": ..., \"scale\": ...}");
    for (const JsonNode& r : recs) {
      r.allow_only({"file", "scale", "dt", "unit"});
      ListedRecord lr;
      lr.file = resolve(r.string("file"), case_dir);
      // A plain record (REXEL, SIMQKE, site-response output): the unit of the
      // values, and dt (s) for one column; two columns give dt themselves.
      if (r.has("unit")) {
        const std::string u = r.choice("unit", {"g", "m/s^2", "cm/s^2", "m/s2", "cm/s2", "gal"});
        lr.unit = parse_acceleration_unit(u);
      }
      if (r.has("dt")) {
        lr.dt = r.number("dt", "s (time step of a plain one-column record)", record_dt_min_s, record_dt_max_s);
        if (!(*lr.dt > 0.0)) r.at("dt").fail("expected a time step > 0 s");
        if (!lr.unit)
          r.fail("a plain record with \"dt\" needs \"unit\": \"g\", \"m/s^2\" or \"cm/s^2\" (the unit of "
                 "its acceleration values)");
      }
      lr.scale = r.has("scale") ? r.number("scale", "(-, linear scale factor)", 1e-6, limits::scale_max) : 1.0;
      if (!(lr.scale > 0.0)) r.at("scale").fail("expected a scale factor > 0 (-)");
      lr.json_path = r.path();
      s.records.push_back(lr);
    }
  } else {
    const JsonNode sel = d.at("select");
    sel.allow_only({"count", "period_range_s", "max_scale", "max_mean_scale", "max_pga_ratio", "per_event",
                    "per_station", "Mw", "distance_km", "site_classes", "relax_site_class", "countries",
                    "catalogue", "near_fault", "near_fault_km", "max_misfit"});
    RecordSelectionSpec rs;
    auto text = [](double v) {
      char b[32];
      std::snprintf(b, sizeof b, "%g", v);
      return std::string(b);
    };
    const CatalogueFilters filters;  // the default windows (record_selection.hpp)
    assumed(sel, "count", "7", "default.count");
    assumed(sel, "Mw", "[" + text(filters.Mw_min) + ", " + text(filters.Mw_max) + "]", "default.Mw");
    assumed(sel, "distance_km", "[" + text(filters.R_min_km) + ", " + text(filters.R_max_km) + "] km", "default.distance");
    assumed(sel, "max_scale", text(rs.max_scale), "default.max_scale");
    assumed(sel, "max_mean_scale", text(rs.max_mean_scale), "default.max_mean_scale");
    assumed(sel, "max_pga_ratio", text(rs.max_pga_ratio), "default.max_pga_ratio");
    assumed(sel, "near_fault", "exclude", "default.near_fault");
    assumed(sel, "site_classes", "= /site/soil", "default.site_classes");
    // The ranges of record_selection.hpp (selection_rules), shared with the command line.
    namespace SR = selection_rules;
    rs.count = sel.integer_or("count", 7, 1, SR::count_max);
    rs.max_scale = sel.number_or("max_scale", rs.max_scale, SR::max_scale);
    rs.max_mean_scale = sel.number_or("max_mean_scale", rs.max_mean_scale, SR::max_mean_scale);
    rs.max_pga_ratio = sel.number_or("max_pga_ratio", rs.max_pga_ratio, SR::max_pga_ratio);
    rs.max_per_event = sel.integer_or("per_event", rs.max_per_event, 1, SR::count_max);
    rs.max_per_station = sel.integer_or("per_station", rs.max_per_station, 1, SR::count_max);
    auto window = [&](const char* key, const NumberRule& rule, std::optional<double>& a, std::optional<double>& b) {
      if (!sel.has(key)) return;
      const std::vector<JsonNode> w = sel.array(key, 2);
      if (w.size() != 2) sel.at(key).fail(std::string("expected [min, max] in ") + rule.unit);
      a = w[0].as_number(rule);
      b = w[1].as_number(rule);
      if (!(*b >= *a)) sel.at(key).fail(std::string("expected min <= max (") + rule.unit + ")");
    };
    window("Mw", SR::Mw, rs.Mw_min, rs.Mw_max);
    window("distance_km", SR::distance_km, rs.R_min_km, rs.R_max_km);
    if (sel.has("site_classes"))
      for (const JsonNode& c : sel.array("site_classes", 1)) {
        const std::string v = c.as_string();
        if (v.size() != 1 || std::string("ABCDE").find(v) == std::string::npos)
          c.fail("expected a site class \"A\", \"B\", \"C\", \"D\" or \"E\", got \"" + v + "\"");
        rs.site_classes.push_back(v);
      }
    rs.relax_site_class = sel.boolean_or("relax_site_class", true);
    if (sel.has("near_fault")) rs.include_near_fault = sel.choice("near_fault", {"exclude", "include"}) == "include";
    rs.near_fault_km = sel.number_or("near_fault_km", rs.near_fault_km, SR::near_fault_km);
    rs.max_misfit = sel.number_or("max_misfit", rs.max_misfit, SR::max_misfit);
    if (sel.has("countries"))
      for (const JsonNode& c : sel.array("countries", 1)) rs.countries.push_back(c.as_string());
    if (sel.has("period_range_s")) {
      const std::vector<JsonNode> pr = sel.array("period_range_s", 2);
      if (pr.size() != 2) sel.at("period_range_s").fail("expected [T_min, T_max] in s");
      rs.T_min = pr[0].as_number(SR::period_s);
      rs.T_max = pr[1].as_number(SR::period_s);
      if (!(*rs.T_max > *rs.T_min)) sel.at("period_range_s").fail("expected T_min < T_max (s)");
    }
    rs.catalogue = sel.has("catalogue") ? resolve(sel.string("catalogue"), case_dir)
                                        : data_dir() + "/spectra/records/catalogue.json";
    s.selection = rs;
  }
  s.options.validate();
  return s;
}

CatalogueFilters catalogue_filters(const RecordSelectionSpec& rs, const std::string& soil_class, int count) {
  CatalogueFilters filters;
  if (rs.Mw_min) filters.Mw_min = *rs.Mw_min, filters.Mw_max = *rs.Mw_max, filters.Mw_given = true;
  if (rs.R_min_km) filters.R_min_km = *rs.R_min_km, filters.R_max_km = *rs.R_max_km, filters.R_given = true;
  filters.site_classes = rs.site_classes;
  if (filters.site_classes.empty()) filters.site_classes = {soil_class};
  filters.relax_site_class = rs.relax_site_class;
  filters.countries = rs.countries;
  filters.min_candidates = std::size_t(3 * count);
  return filters;
}

}  // namespace assess

// fragility_report.cpp: JSON, CSV, text and HTML outputs of a fragility
// analysis (report layer of the risk module: formats, computes nothing new
// except the curves' values on the plot grids).
#include "assess/risk/fragility_report.hpp"

#include "assess/support/content_hash.hpp"

#include "assess/report/html_report.hpp"
#include "assess/report/note_text.hpp"
#include "assess/report/plot.hpp"
#include "assess/risk/collapse_rate.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/number_rules.hpp"
#include "assess/support/json_input.hpp"
#include "assess/support/output_file.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <limits>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace assess {

namespace {

using nlohmann::json;

std::string fmt(double v, const char* f = "%.4g") {
  if (!std::isfinite(v)) return "-";
  char buf[48];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string g_units(double a) { return fmt(a / units::g, "%.3f"); }

// Every file of the fragility output: whole or not at all (output_file.hpp).
void write_file(const std::string& path, const std::string& text) {
  const auto slash = path.find_last_of('/');
  write_output_file(path, text, "the fragility output", slash == std::string::npos ? "." : path.substr(0, slash));
}

json curve_json(const FragilityStudy& st, const FragilityCurve& c) {
  json j;
  j["restitution"] = st.restitution_labels[c.restitution];
  j["limit_state"] = to_string(c.state);
  j["method"] = c.method;
  j["status"] = to_string(c.fit.status);
  if (c.fit.ok()) {
    j["theta_m_s2"] = c.fit.fragility.theta;
    j["theta_g"] = c.fit.fragility.theta / units::g;
    j["beta"] = c.fit.fragility.beta;
    j["se_ln_theta"] = c.fit.se_ln_theta;
    j["se_beta"] = c.fit.se_beta;
  } else {
    j["message"] = c.fit.message;
  }
  if (c.bounds && c.bounds->fitted > 0) {
    const BootstrapBounds& b = *c.bounds;
    j["bootstrap"] = {{"replicates", b.replicates}, {"fitted", b.fitted}, {"confidence", st.options.confidence},
                      {"theta_m_s2", {b.theta_lo, b.theta_hi}}, {"beta", {b.beta_lo, b.beta_hi}},
                      {"lambda_per_year", {b.lambda_lo, b.lambda_hi}}};
  }
  if (c.has_risk) {
    j["lambda_per_year"] = c.lambda;
    j["return_period_years"] = c.return_period;
    j["probability_in_VN"] = c.p_vn;
  }
  json s = json::array();
  for (const auto& x : c.stripes)
    s.push_back({{"im_m_s2", x.im}, {"TR_years", x.TR}, {"n", x.n}, {"k", x.k}, {"failed", x.failed}});
  j["stripes"] = s;
  if (!c.collapse_im.empty()) j["collapse_im_m_s2"] = c.collapse_im;
  if (!c.note.empty()) j["note"] = c.note;
  return j;
}

// FNV-1a 64-bit hash of a file's bytes, as 16 hex digits ("" if unreadable):
// ties a summary to the case file's content, so that a report does not show
// the fragility of a case edited since (support/content_hash.hpp).
std::string file_fnv1a64(const std::string& path) {
  try {
    return hash_hex(file_content_hash(path, input_kinds::case_file));
  } catch (const InputError&) {
    return "";
  }
}

// The return period (years) at which a check reaches D/C = 1: its own index
// (kinematic/check_index.hpp, issue 41); NaN without one.
double capacity_tr(const CheckRow& c) { return c.index.defined ? c.index.TR_capacity : NAN; }

// P(C|im) at the code's SLV/SLC PGA, from a curve.
double p_at(const FragilityCurve& c, double im) { return c.fit.ok() ? c.fit.fragility.probability(im) : NAN; }

}  // namespace

json fragility_to_json(const FragilityStudy& st, const FragilityResult& r) {
  json j;
  j["case"] = st.file;
  std::error_code ec;
  const auto abs = std::filesystem::absolute(st.file, ec);
  j["case_absolute"] = ec ? st.file : abs.lexically_normal().string();
  if (const std::string h = file_fnv1a64(st.file); !h.empty()) j["case_fnv1a64"] = h;
  j["project"] = st.project;
  j["mechanism"] = st.mechanism;
  j["model"] = note_text(Lang::en, st.dynamics.describe());
  j["selection_warnings"] = st.selection_warnings;
  j["site"] = st.site_description;
  j["method"] = to_string(st.options.method);
  j["intensity_measure"] = "PGA on the site's ground, Se(0) = ag S (m/s^2)";
  j["VN_years"] = st.VN;
  j["VR_years"] = st.VR;
  j["analyses"] = r.analyses;
  j["failed"] = r.failed;
  json code;
  for (LimitState ls : {LimitState::SLV, LimitState::SLC}) {
    const SeismicAction& a = st.actions.at(ls);
    code[to_string(ls)] = {{"TR_years", a.TR}, {"PVR", a.PVR}, {"pga_m_s2", st.action_pga.at(ls)},
                           {"P_overturning_at_pga", p_at(r.curves[r.governing], st.action_pga.at(ls))}};
  }
  json checks = json::array();
  for (const CheckRow& c : st.checks) {
    json jc{{"code", c.code}, {"limit_state", c.limit_state}, {"kind", c.kind}, {"dc", c.dc}, {"satisfied", c.satisfied}};
    const double tr = capacity_tr(c);
    if (std::isfinite(tr)) jc["ag_capacity_g"] = c.index.ag_capacity_g, jc["TR_of_ag_capacity_years"] = tr;
    checks.push_back(jc);
  }
  code["checks"] = checks;
  j["code"] = code;
  json stripes = json::array();
  for (const Stripe& s : st.stripes) {
    json js{{"im_m_s2", s.im}, {"TR_years", s.TR}, {"records", s.records.size()}};
    if (!s.selection.empty()) js["selection"] = s.selection, js["compatible"] = s.compatible;
    stripes.push_back(js);
  }
  j["stripes"] = stripes;
  json curves = json::array();
  for (const auto& c : r.curves) curves.push_back(curve_json(st, c));
  j["curves"] = curves;
  j["governing"] = curve_json(st, r.curves[r.governing]);
  if (st.hazard) {
    json h = json::array();
    for (const auto& p : st.hazard->points()) h.push_back({{"TR_years", p.TR}, {"pga_m_s2", p.im}, {"lambda", p.lambda}});
    j["hazard_curve"] = h;
  }
  return j;
}

std::string fragility_text(const FragilityStudy& st, const FragilityResult& r) {
  std::ostringstream os;
  os << "fragility of '" << st.mechanism << "' (" << st.file << "), site " << st.site_description << "\n";
  os << "model: " << note_text(Lang::en, st.dynamics.describe()) << "\n";
  for (const std::string& w : st.selection_warnings) os << "selection: " << w << "\n";
  os << to_string(st.options.method) << ": " << st.stripes.size() << " levels, " << r.analyses << " analyses ("
     << r.failed << " failed); IM = PGA on the site's ground\n";
  for (std::size_t e = 0; e < st.restitutions(); ++e) {
    os << "restitution " << st.restitution_labels[e] << ":\n";
    for (FragilityState s : all_fragility_states) {
      const FragilityCurve& c = r.curve(e, s);
      os << "  " << to_string(s) << ": ";
      if (!c.fit.ok()) {
        os << "no fit (" << c.note << ")\n";
        continue;
      }
      os << "median " << g_units(c.fit.fragility.theta) << " g, beta " << fmt(c.fit.fragility.beta, "%.3f");
      if (c.bounds && c.bounds->fitted > 0)
        os << " (" << fmt(100 * st.options.confidence, "%.0f") << " %: median " << g_units(c.bounds->theta_lo) << "-"
           << g_units(c.bounds->theta_hi) << " g, beta " << fmt(c.bounds->beta_lo, "%.3f") << "-"
           << fmt(c.bounds->beta_hi, "%.3f") << ")";
      if (c.has_risk)
        os << "; lambda " << fmt(c.lambda, "%.3e") << "/year, return period " << fmt(c.return_period, "%.0f")
           << " years, P in VN=" << fmt(st.VN, "%.0f") << " years " << fmt(100 * c.p_vn, "%.2f") << " %";
      os << "\n";
      if (!c.note.empty()) os << "    note: " << c.note << "\n";
    }
  }
  const FragilityCurve& gov = r.curves[r.governing];
  os << "code: TR SLV " << fmt(st.actions.at(LimitState::SLV).TR, "%.0f") << " years (PGA "
     << g_units(st.action_pga.at(LimitState::SLV)) << " g), TR SLC " << fmt(st.actions.at(LimitState::SLC).TR, "%.0f")
     << " years (PGA " << g_units(st.action_pga.at(LimitState::SLC)) << " g)\n";
  for (const CheckRow& c : st.checks) {
    const double tr = capacity_tr(c);
    if (!std::isfinite(tr)) continue;
    os << "code " << c.code << " " << c.limit_state << " " << c.kind << ": D/C " << fmt(c.dc, "%.2f") << " ("
       << (c.satisfied ? "satisfied" : "not satisfied") << "), ag capacity " << fmt(c.index.ag_capacity_g, "%.3f")
       << " g, reached every " << fmt(tr, "%.0f") << " years"
       << (tr < tr_min_years || tr > tr_max_years ? " (extrapolated beyond the hazard data)" : "") << "\n";
  }
  os << "overturning (governing restitution " << st.restitution_labels[gov.restitution] << "): ";
  if (gov.has_risk)
    os << "return period " << fmt(gov.return_period, "%.0f") << " years; P(overturning | PGA SLV) "
       << fmt(100 * p_at(gov, st.action_pga.at(LimitState::SLV)), "%.1f") << " %\n";
  else
    os << "no risk figure (" << gov.note << ")\n";
  return os.str();
}

FragilityReportFiles write_fragility_report(const FragilityStudy& st, const FragilityResult& r,
                                            const std::string& dir, bool plots) {
  FragilityReportFiles f;
  f.summary = dir + "/summary.json";
  write_file(f.summary, fragility_to_json(st, r).dump(2) + "\n");

  std::ostringstream cc;
  cc << "restitution,limit_state,method,status,theta_m_s2,beta,se_ln_theta,se_beta,theta_lo_m_s2,theta_hi_m_s2,"
        "beta_lo,beta_hi,lambda_per_year,lambda_lo,lambda_hi,return_period_years,probability_in_VN\n";
  for (const auto& c : r.curves) {
    const bool ok = c.fit.ok(), b = c.bounds && c.bounds->fitted > 0;
    cc << "\"" << st.restitution_labels[c.restitution] << "\"," << to_string(c.state) << ",\"" << c.method << "\","
       << to_string(c.fit.status) << "," << (ok ? fmt(c.fit.fragility.theta, "%.6g") : "") << ","
       << (ok ? fmt(c.fit.fragility.beta, "%.6g") : "") << "," << (ok ? fmt(c.fit.se_ln_theta, "%.6g") : "") << ","
       << (ok ? fmt(c.fit.se_beta, "%.6g") : "") << "," << (b ? fmt(c.bounds->theta_lo, "%.6g") : "") << ","
       << (b ? fmt(c.bounds->theta_hi, "%.6g") : "") << "," << (b ? fmt(c.bounds->beta_lo, "%.6g") : "") << ","
       << (b ? fmt(c.bounds->beta_hi, "%.6g") : "") << "," << (c.has_risk ? fmt(c.lambda, "%.6g") : "") << ","
       << (b && c.has_risk ? fmt(c.bounds->lambda_lo, "%.6g") : "") << ","
       << (b && c.has_risk ? fmt(c.bounds->lambda_hi, "%.6g") : "") << ","
       << (c.has_risk ? fmt(c.return_period, "%.6g") : "") << "," << (c.has_risk ? fmt(c.p_vn, "%.6g") : "") << "\n";
  }
  f.curves_csv = dir + "/curves.csv";
  write_file(f.curves_csv, cc.str());

  std::ostringstream sc;
  sc << "restitution,limit_state,stripe,TR_years,im_m_s2,n,k,failed\n";
  for (const auto& c : r.curves)
    for (std::size_t i = 0; i < c.stripes.size(); ++i)
      sc << "\"" << st.restitution_labels[c.restitution] << "\"," << to_string(c.state) << "," << i << ","
         << fmt(c.stripes[i].TR, "%.6g") << "," << fmt(c.stripes[i].im, "%.6g") << "," << c.stripes[i].n << ","
         << c.stripes[i].k << "," << c.stripes[i].failed << "\n";
  f.stripes_csv = dir + "/stripes.csv";
  write_file(f.stripes_csv, sc.str());

  std::ostringstream hc;
  hc << "TR_years,pga_m_s2,lambda_per_year\n";
  if (st.hazard)
    for (const auto& p : st.hazard->points())
      hc << fmt(p.TR, "%.6g") << "," << fmt(p.im, "%.6g") << "," << fmt(p.lambda, "%.6g") << "\n";
  f.hazard_csv = dir + "/hazard.csv";
  write_file(f.hazard_csv, hc.str());

  // HTML page.
  HtmlReport html("Fragility and annual risk of overturning: " + st.project);
  html.add_heading("Summary");
  html.add_paragraph("Case " + st.file + ", mechanism '" + st.mechanism + "' (" + note_text(Lang::en, st.dynamics.describe()) +
                     "), site " + st.site_description +
                     ", VN " + fmt(st.VN, "%.0f") + " years, VR " + fmt(st.VR, "%.0f") + " years. Method: " +
                     (st.options.method == FragilityMethod::stripes
                          ? "multiple-stripe analysis (records compatible with the site spectrum at each return "
                            "period, scaled to its PGA)"
                          : "incremental dynamic analysis (one record set scaled to each PGA level)") +
                     "; intensity measure: PGA on the site's ground, Se(0) = ag S; " + std::to_string(r.analyses) +
                     " analyses, " + std::to_string(r.failed) + " failed (counted as reaching the limit state).");
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : r.curves) {
    const bool ok = c.fit.ok(), b = c.bounds && c.bounds->fitted > 0;
    rows.push_back({st.restitution_labels[c.restitution], to_string(c.state),
                    ok ? g_units(c.fit.fragility.theta) : to_string(c.fit.status),
                    b ? g_units(c.bounds->theta_lo) + " - " + g_units(c.bounds->theta_hi) : "-",
                    ok ? fmt(c.fit.fragility.beta, "%.3f") : "-",
                    b ? fmt(c.bounds->beta_lo, "%.3f") + " - " + fmt(c.bounds->beta_hi, "%.3f") : "-",
                    c.has_risk ? fmt(c.lambda, "%.3e") : "-",
                    c.has_risk ? fmt(c.return_period, "%.0f") : "-",
                    c.has_risk ? fmt(100 * c.p_vn, "%.2f") : "-"});
  }
  html.add_table({"restitution", "limit state", "median (g)", "median band (g)", "beta", "beta band",
                  "lambda (1/year)", "return period (years)", "P in VN (%)"},
                 rows, "Lognormal fragility (Baker 2015) and risk; bands: " +
                           fmt(100 * st.options.confidence, "%.0f") + " % bootstrap over records");
  std::vector<std::vector<std::string>> code_rows;
  const FragilityCurve& gov = r.curves[r.governing];
  for (LimitState ls : {LimitState::SLV, LimitState::SLC}) {
    const SeismicAction& a = st.actions.at(ls);
    code_rows.push_back({to_string(ls), fmt(a.TR, "%.0f"), fmt(100 * a.PVR, "%.0f"), g_units(st.action_pga.at(ls)),
                         gov.fit.ok() ? fmt(100 * p_at(gov, st.action_pga.at(ls)), "%.1f") : "-"});
  }
  html.add_table({"limit state", "TR (years)", "P_VR (%)", "PGA (g)", "P(overturning | PGA) (%)"}, code_rows,
                 "The code's return periods at the site beside the governing overturning curve (restitution " +
                     st.restitution_labels[gov.restitution] + "): its return period is " +
                     (gov.has_risk ? fmt(gov.return_period, "%.0f") + " years" : "not available (" + gov.note + ")"));
  std::vector<std::vector<std::string>> check_rows;
  for (const CheckRow& c : st.checks)
    check_rows.push_back({c.code, c.limit_state, c.kind, fmt(c.dc, "%.3f"), c.satisfied ? "satisfied" : "not satisfied",
                          c.index.defined ? fmt(c.index.ag_capacity_g, "%.3f") : "-", fmt(capacity_tr(c), "%.0f")});
  if (!check_rows.empty())
    html.add_table({"code", "limit state", "check", "D/C", "verdict", "ag capacity (g)", "return period at D/C = 1 (years)"},
                   check_rows, "The code's kinematic checks of the case; the return period at which each check "
                               "reaches D/C = 1 with the site's hazard at that return period (its safety index, "
                               "docs/theory/building.md §4) compares with the return period of overturning above");
  std::vector<std::vector<std::string>> stripe_rows;
  for (const Stripe& s : st.stripes)
    stripe_rows.push_back({fmt(s.TR, "%.0f"), g_units(s.im), std::to_string(s.records.size()),
                           s.selection.empty() ? "fixed set (IDA)" : s.selection});
  html.add_table({"TR (years)", "PGA (g)", "records", "selection"}, stripe_rows, "Intensity levels");

  if (plots) {
    const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c"};
    for (std::size_t e = 0; e < st.restitutions(); ++e) {
      Plot p;
      p.title = "Fragility, restitution " + st.restitution_labels[e];
      p.x_label = "PGA (g)";
      p.y_label = "P(limit state | PGA) (-)";
      p.y_min = 0, p.y_max = 1;
      for (FragilityState s : all_fragility_states) {
        const FragilityCurve& c = r.curve(e, s);
        const std::string col = colours[int(s)];
        PlotSeries pts = plot_series(to_string(s) + " (stripes)", PlotSeries::Style::Points);
        pts.color = col;
        for (const auto& x : c.stripes) pts.x.push_back(x.im / units::g), pts.y.push_back(x.n ? double(x.k) / x.n : NAN);
        p.series.push_back(pts);
        if (c.fit.ok()) {
          PlotSeries fit = plot_series(to_string(s) + " (lognormal)", PlotSeries::Style::Line);
          fit.color = col;
          fit.highlight = s == FragilityState::overturning;
          const auto& grid = c.bounds && c.bounds->fitted > 0 ? c.bounds->band_im : std::vector<double>{};
          std::vector<double> xs = grid;
          if (xs.empty())
            for (int i = 0; i <= 80; ++i)
              xs.push_back(0.5 * st.stripes.front().im * std::pow(4.0 * st.stripes.back().im / st.stripes.front().im, i / 80.0));
          for (double x : xs) fit.x.push_back(x / units::g), fit.y.push_back(c.fit.fragility.probability(x));
          p.series.push_back(fit);
          if (!grid.empty()) {
            PlotSeries lo = plot_series("", PlotSeries::Style::Dashed), hi = plot_series("", PlotSeries::Style::Dashed);
            lo.color = hi.color = col;
            for (std::size_t i = 0; i < grid.size(); ++i) {
              lo.x.push_back(grid[i] / units::g), lo.y.push_back(c.bounds->band_lo[i]);
              hi.x.push_back(grid[i] / units::g), hi.y.push_back(c.bounds->band_hi[i]);
            }
            p.series.push_back(lo);
            p.series.push_back(hi);
          }
        }
      }
      html.add_svg(render_svg(p), "Fragility curves (lines), stripe fractions (points) and the " +
                                      fmt(100 * st.options.confidence, "%.0f") +
                                      " % bootstrap band (dashed), restitution " + st.restitution_labels[e],
                   "fragility" + std::to_string(e));
    }
    if (st.hazard) {
      Plot h;
      h.title = "Hazard curve of the site (PGA on its ground)";
      h.x_label = "PGA (g)";
      h.y_label = "lambda (1/year)";
      h.log_x = h.log_y = true;
      PlotSeries pts = plot_series("grid return periods", PlotSeries::Style::Points), line = plot_series("log-log interpolation/extrapolation", PlotSeries::Style::Line);
      for (const auto& q : st.hazard->points()) pts.x.push_back(q.im / units::g), pts.y.push_back(q.lambda);
      const double a = 0.5 * st.hazard->points().front().im, b = 2.0 * st.hazard->points().back().im;
      for (int i = 0; i <= 60; ++i) {
        const double x = a * std::pow(b / a, i / 60.0);
        line.x.push_back(x / units::g), line.y.push_back(st.hazard->lambda(x));
      }
      h.series = {line, pts};
      html.add_svg(render_svg(h), "Mean annual frequency of exceeding the PGA: the nine return periods of the grid, "
                                  "log-log between them and beyond them",
                   "hazard");
      if (gov.fit.ok()) {
        Plot q;
        q.title = "Integrand of the risk, overturning (restitution " + st.restitution_labels[gov.restitution] + ")";
        q.x_label = "PGA (g)";
        q.y_label = "P(C|PGA) |d lambda / d PGA| (1/year per g)";
        q.log_x = true;
        PlotSeries s = plot_series("integrand", PlotSeries::Style::Line);
        s.highlight = true;
        const double t = gov.fit.fragility.theta, be = std::max(gov.fit.fragility.beta, 0.05);
        std::vector<double> xs;
        for (int i = 0; i <= 120; ++i) xs.push_back(t * std::exp(be * (-4.0 + 8.0 * i / 120.0)));
        const std::vector<double> y = risk_integrand(gov.fit.fragility, *st.hazard, xs);
        for (std::size_t i = 0; i < xs.size(); ++i) s.x.push_back(xs[i] / units::g), s.y.push_back(y[i] * units::g);
        q.series = {s};
        html.add_svg(render_svg(q), "Where the annual frequency of overturning comes from: lambda_c = " +
                                        (gov.has_risk ? fmt(gov.lambda, "%.3e") : std::string("-")) +
                                        "/year is the area under this curve",
                     "integrand");
      }
    }
  } else {
    html.add_paragraph("Plots skipped (--no-plots).");
  }
  f.html = dir + "/report.html";
  write_file(f.html, html.str());
  return f;
}

json read_fragility_summary(const std::string& dir, const std::string& case_file) {
  const std::string path = dir + "/summary.json";
  if (!std::filesystem::exists(path))
    throw InputError("--fragility: cannot open '" + path + "' (run `assess fragility CASE.json --out " + dir + "` first)");
  const json j = parse_json_text(read_input_file(path, input_kinds::own_output), path);
  if (!j.is_object() || !j.contains("case") || !j["case"].is_string() || !j.contains("governing"))
    throw InputError("'" + path + "' is not a fragility summary (keys /case and /governing expected)");
  std::error_code ec;
  const std::string of = j.contains("case_absolute") && j["case_absolute"].is_string()
                             ? j["case_absolute"].get<std::string>()
                             : j["case"].get<std::string>();
  if (!std::filesystem::equivalent(of, case_file, ec))
    throw InputError("'" + path + "': /case is '" + j["case"].get<std::string>() + "', not '" + case_file +
                     "': the fragility belongs to another case");
  if (j.contains("case_fnv1a64") && j["case_fnv1a64"].is_string() &&
      j["case_fnv1a64"].get<std::string>() != file_fnv1a64(case_file))
    throw InputError("'" + path + "': the case file '" + case_file +
                     "' has changed since this fragility was computed (content hash differs): rerun `assess fragility " +
                     case_file + " --out " + dir + "`");
  // The numbers a report prints from it, held to their ranges (issue 39: a
  // summary edited to beta = -1 was printed by `assess run --fragility`).
  const JsonNode root(j, path);
  static constexpr NumberRule pga{"m/s^2", 0.0, 1e3, true, false, "a PGA above 0 and at most 100 g"};
  static constexpr NumberRule beta{"-", 0.0, 10.0, true, false, "the lognormal dispersion: above 0"};
  static constexpr NumberRule rate{"1/year", 0.0, 1e3, false, false, "an annual frequency"};
  static constexpr NumberRule probability{"-", 0.0, 1.0, false, false, "a probability"};
  static constexpr NumberRule years{"years", 0.0, 1e300, true, false, "a return period above 0"};
  root.number("VN_years", rules::nominal_life_years);
  root.at("method").as_string();
  const JsonNode slv = root.at("code").at("SLV");
  slv.number("TR_years", rules::return_period_years);
  slv.number("pga_m_s2", pga);
  if (const auto p = slv.find("P_overturning_at_pga"); p && !p->value().is_null()) p->as_number(probability);
  const JsonNode g = root.at("governing");
  g.at("restitution").as_string();
  if (g.has("return_period_years")) {
    g.number("theta_m_s2", pga);
    g.number("beta", beta);
    g.number("lambda_per_year", rate);
    if (!g.at("return_period_years").value().is_null()) g.number("return_period_years", years);
    g.number("probability_in_VN", probability);
  }
  for (const char* count : {"analyses", "failed"})
    if (root.has(count)) root.integer(count, 0, std::numeric_limits<int>::max());
  return j;
}

std::string fragility_line(const json& s) {
  try {
    const json& g = s.at("governing");
    std::string line = "additional probabilistic result, not a code check: fragility (" +
                       s.at("method").get<std::string>() + ", restitution " +
                       g.at("restitution").get<std::string>() + "): overturning ";
    if (g.contains("return_period_years")) {
      line += "median PGA " + g_units(g.at("theta_m_s2").get<double>()) + " g, beta " +
              fmt(g.at("beta").get<double>(), "%.2f") + ", return period " +
              fmt(g.at("return_period_years").get<double>(), "%.0f") + " years, P in VN = " +
              fmt(s.at("VN_years").get<double>(), "%.0f") + " years " +
              fmt(100 * g.at("probability_in_VN").get<double>(), "%.1f") + " %";
    } else {
      line += "no risk figure (" + g.value("note", g.value("message", std::string("not fitted"))) + ")";
    }
    line += "; code TR SLV " + fmt(s.at("code").at("SLV").at("TR_years").get<double>(), "%.0f") + " years";
    return line;
  } catch (const json::exception& e) {
    throw InputError(std::string("fragility summary: missing or malformed key: ") + e.what());
  }
}

ProbabilisticResult probabilistic_result(const json& s, const std::string& source) {
  ProbabilisticResult r;
  r.source = source;
  try {
    const json& g = s.at("governing");
    r.method = s.at("method").get<std::string>();
    r.model = s.value("model", std::string("rocking body (summary written before the model was recorded)"));
    r.restitution = g.at("restitution").get<std::string>();
    r.analyses = s.at("analyses").get<int>();
    r.failed = s.at("failed").get<int>();
    r.VN = s.at("VN_years").get<double>();
    const json& slv = s.at("code").at("SLV");
    r.TR_SLV = slv.at("TR_years").get<double>();
    r.pga_SLV = slv.at("pga_m_s2").get<double>();
    r.has_risk = g.contains("return_period_years");
    if (r.has_risk) {
      r.median_pga = g.at("theta_m_s2").get<double>();
      r.beta = g.at("beta").get<double>();
      r.lambda = g.at("lambda_per_year").get<double>();
      r.return_period = g.at("return_period_years").get<double>();
      r.p_vn = g.at("probability_in_VN").get<double>();
      // NaN is written as null by nlohmann::json: no value then.
      if (slv.contains("P_overturning_at_pga") && slv.at("P_overturning_at_pga").is_number())
        r.p_at_SLV = slv.at("P_overturning_at_pga").get<double>();
    } else {
      r.note = g.value("note", g.value("message", std::string("not fitted")));
    }
  } catch (const json::exception& e) {
    throw InputError("'" + source + "': fragility summary: missing or malformed key: " + e.what());
  }
  return r;
}

}  // namespace assess

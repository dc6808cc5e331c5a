// relazione_site.cpp: the seismic action (NTC 2018 §2.4, §3.2): the site, the
// limit states' hazard and spectrum parameters, the elastic spectra.
#include "report/relazione_context.hpp"

#include "assess/report/plot.hpp"
#include "assess/support/units.hpp"

namespace assess::relazione {

void add_site(Ctx& c) {
  if (!c.a.kase.site) return;
  const FacadeAssessment& a = c.a;
  c.d.add_heading(c.t("site.heading"));
  const SiteSpec& sp = *a.kase.site;
  c.d.add_paragraph(c.t("site.site") + ": " + c.loc(a.site.description) + "; " + c.t("site.soil") + " " +
                    to_string(sp.conditions.soil) + ", " + c.t("site.topography") + " " +
                    to_string(sp.conditions.topography) + "; " + c.t("site.vn") + " = " + c.n(sp.vn_years, 0) + " " +
                    c.t("site.years") + ", " + c.t("site.cu") + " = " + c.n(sp.cu, 2) + ", " + c.t("site.vr") +
                    " = VN · CU = " + c.n(a.site.VR, 1) + " " + c.t("site.years") + " [2.4.1].");
  if (!sp.comune.empty()) c.d.add_paragraph(c.t("site.comune_note"));
  std::vector<std::vector<Cell>> rows;
  for (const auto& [ls, act] : a.site.actions) {
    const ElasticSpectrum& s = a.site.spectra.at(ls);
    rows.push_back({Cell(to_string(ls)), c.num(act.PVR * 100, 0), c.num(act.TR, 1), c.num(s.ag_g(), 4), c.num(s.F0(), 3),
                    c.num(s.Tc_star(), 3), c.num(s.SS(), 3), c.num(s.CC(), 3), c.num(s.ST(), 2), c.num(s.S(), 3),
                    c.num(s.TB(), 3), c.num(s.TC(), 3), c.num(s.TD(), 3)});
  }
  c.d.add_cell_table({Cell(c.t("site.ls")), numeric_cell("P_VR (%)"), numeric_cell("TR", c.t("site.years")), numeric_cell("ag (g)"), numeric_cell("F0"),
                      numeric_cell("TC* (s)"), numeric_cell("SS"), numeric_cell("CC"), numeric_cell("ST"), numeric_cell("S"), numeric_cell("TB (s)"), numeric_cell("TC (s)"), numeric_cell("TD (s)")},
                     rows, c.t("site.table"));
  c.d.add_paragraph(c.t("site.formulas"), "note");
  Plot p = c.plot();
  p.title = c.t("site.fig_title");
  p.x_label = "T (s)";
  p.y_label = "Se, PSA (g)";
  for (const auto& [ls, se] : a.curves.site_Se) {
    PlotSeries s = plot_series("Se " + to_string(ls), PlotSeries::Style::Line, a.curves.periods);
    for (double v : se) s.y.push_back(v / units::g);
    s.highlight = ls == LimitState::SLV;
    p.series.push_back(s);
  }
  for (std::size_t i = 0; i < a.curves.record_psa.size(); ++i) {
    PlotSeries s = plot_series(i == 0 ? c.t("site.records_scaled") : "", PlotSeries::Style::Dashed, a.curves.periods);
    for (double v : a.curves.record_psa[i]) s.y.push_back(v / units::g);
    s.color = "#999999";
    p.series.push_back(s);
  }
  if (!a.curves.mean_psa.empty()) {
    PlotSeries s = plot_series(c.t("site.records_mean"), PlotSeries::Style::Line, a.curves.periods);
    for (double v : a.curves.mean_psa) s.y.push_back(v / units::g);
    s.highlight = true;
    s.color = "#000000";
    p.series.push_back(s);
  }
  c.d.add_svg(render_svg(p), c.t(a.curves.record_psa.empty() ? "site.fig_norec" : "site.fig"), "fig-spectra");
}

}  // namespace assess::relazione

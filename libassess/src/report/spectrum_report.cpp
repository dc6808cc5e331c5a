// spectrum_report.cpp: the columns and the JSON of `assess spectrum`
// (report/spectrum_report.hpp), moved from apps/cmd_spectrum.cpp for issue 40
// so that the Python module returns the same.
#include "assess/report/spectrum_report.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <cstdio>

namespace assess {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

nlohmann::json column_json(const SpectrumColumn& c, const ElasticSpectrum& s, const std::vector<double>& periods,
                           std::optional<double> q) {
  nlohmann::json j;
  j["limit_state"] = c.ls ? nlohmann::json(to_string(*c.ls)) : nlohmann::json(nullptr);
  j["PVR"] = c.PVR ? nlohmann::json(*c.PVR) : nlohmann::json(nullptr);
  j["TR"] = c.TR ? nlohmann::json(*c.TR) : nlohmann::json(nullptr);
  j["TR_used"] = c.TR ? nlohmann::json(c.hazard.TR) : nlohmann::json(nullptr);
  j["TR_clamped"] = c.hazard.tr_clamped;
  j["ag_g"] = s.ag_g();
  j["F0"] = s.F0();
  j["Tc_star"] = s.Tc_star();
  j["SS"] = s.SS();
  j["CC"] = s.CC();
  j["ST"] = s.ST();
  j["S"] = s.S();
  j["eta"] = s.eta();
  j["damping_pct"] = s.damping_pct();
  j["TB"] = s.TB();
  j["TC"] = s.TC();
  j["TD"] = s.TD();
  j["TE"] = s.TE();
  j["TF"] = s.TF();
  j["Fv"] = s.Fv();
  j["PGA_g"] = s.PGA() / units::g;
  nlohmann::json arr = nlohmann::json::array();
  for (double T : periods) {
    nlohmann::json p{{"T", T}, {"Se_g", s.Se(T) / units::g}, {"SDe_m", s.SDe(T)}, {"Sve_g", s.Sve(T) / units::g}};
    if (q) p["Sd_g"] = s.Sd(T, *q) / units::g;
    arr.push_back(p);
  }
  j["spectrum"] = arr;
  return j;
}

void add_comune(const SiteSpec& spec, nlohmann::json& j) {
  if (spec.comune.empty()) return;
  j["comune"] = spec.comune;
  j["lat"] = *spec.lat;
  j["lon"] = *spec.lon;
  j["note"] = comune_note();
}

}  // namespace

std::vector<double> default_spectrum_periods() {
  return {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0};
}


nlohmann::json spectrum_json(const Site& site, const std::vector<SpectrumColumn>& cols, double damping_pct,
                             const std::vector<double>& periods, std::optional<double> q) {
  const SiteSpec& spec = site.spec();
  if (cols.size() == 1) {
    nlohmann::json j = column_json(cols[0], ElasticSpectrum(cols[0].hazard, spec.conditions, damping_pct), periods, q);
    add_comune(spec, j);
    return j;
  }
  nlohmann::json j;
  j["site"] = site.describe();
  add_comune(spec, j);
  j["VR"] = site.VR();
  nlohmann::json arr = nlohmann::json::array();
  for (const SpectrumColumn& c : cols)
    arr.push_back(column_json(c, ElasticSpectrum(c.hazard, spec.conditions, damping_pct), periods, q));
  j["limit_states"] = arr;
  return j;
}

std::vector<std::string> spectrum_warnings(const std::vector<SpectrumColumn>& cols) {
  std::vector<std::string> w;
  for (const SpectrumColumn& c : cols)
    if (c.hazard.tr_clamped)
      w.push_back(c.label + ": TR = " + fmt("%.2f", c.hazard.tr_requested) +
                  " years is outside the tabulated 30-2475 years; the hazard of TR = " + fmt("%.0f", c.hazard.TR) +
                  " years is used (Circ. 2019 Tab. C3.2.I)");
  return w;
}

}  // namespace assess

// cmd_spectrum.cpp: `assess spectrum`, NTC 2018 elastic spectra of a site.
// Parses the options, builds a Site, prints a Spettri-NTC-like table or JSON.
#include "commands.hpp"

#include <assess/support/error.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/hazard/comuni.hpp>
#include <assess/hazard/site.hpp>
#include <assess/report/spectrum_report.hpp>
#include <assess/support/units.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace assess::cli {

namespace {

struct SpectrumArgs {
  std::optional<double> lat, lon, ag_g, F0, Tc_star, cu, tr, q;
  std::optional<std::string> island, use_class, limit_state, comune, province;
  std::string soil = "A", topography = "T1", periods, grid, islands;
  double h_over_H = 1.0, vn = 50.0, damping = 5.0;
  bool json = false, periods_given = false;
};

// The periods of the table: 0 (the PGA) to 100 s (the spectrum's periods, rules::period_s, and 0).
constexpr NumberRule spectrum_period_s{"s", 1e-3, 100.0, false, true, "0 (the PGA) or a period of 1 ms to 100 s"};

std::vector<double> parse_periods(const std::string& list) {
  if (list.empty()) return default_spectrum_periods();
  return parse_number_list(list, "--periods", spectrum_period_s);
}

SiteSpec make_spec(const SpectrumArgs& a) {
  SiteSpec spec;
  const bool has_ll = a.lat || a.lon, has_given = a.ag_g || a.F0 || a.Tc_star;
  if (int(has_ll) + int(bool(a.island)) + int(has_given) + int(bool(a.comune)) != 1)
    throw InputError(
        "give the site as --lat/--lon, or --comune NAME [--province XX], or --island NAME, or --ag/--F0/--Tc-star "
        "(exactly one)");
  if (a.province && !a.comune) throw InputError("--province goes with --comune (the sigla, e.g. --province AQ)");
  if (a.comune) {
    try {
      const Comune& c = ComuneTable::shipped()->find(*a.comune, a.province ? *a.province : "");
      spec.lat = c.lat;
      spec.lon = c.lon;
      spec.comune = c.describe();
    } catch (const InputError& e) {
      throw InputError(std::string("--comune: ") + e.what());
    }
  }
  if (has_ll) {
    if (!a.lat || !a.lon) throw InputError("--lat and --lon must be given together (decimal degrees)");
    spec.lat = a.lat, spec.lon = a.lon;
  }
  if (a.island) spec.island = a.island;
  if (has_given) {
    if (!a.ag_g || !a.F0 || !a.Tc_star) throw InputError("--ag, --F0 and --Tc-star must be given together");
    const HazardParams h{0.0, *a.ag_g, *a.F0, *a.Tc_star};
    for (LimitState ls : all_limit_states) spec.given[ls] = h;
  }
  try {
    spec.conditions.soil = parse_soil_class(a.soil);
  } catch (const InputError& e) {
    throw InputError(std::string("--soil: ") + e.what());
  }
  try {
    spec.conditions.topography = parse_topography(a.topography);
  } catch (const InputError& e) {
    throw InputError(std::string("--topography: ") + e.what());
  }
  spec.conditions.h_over_H = a.h_over_H;
  spec.vn_years = a.vn;
  if (a.cu && a.use_class) throw InputError("give either --cu or --use-class, not both");
  if (a.cu) spec.cu = *a.cu;
  if (a.use_class) {
    try {
      spec.cu = use_coefficient(parse_use_class(*a.use_class));
    } catch (const InputError& e) {
      throw InputError(std::string("--use-class: ") + e.what());
    }
  }
  spec.grid_path = a.grid;
  spec.islands_path = a.islands;
  return spec;
}

std::vector<SpectrumColumn> evaluate(const SpectrumArgs& a, const Site& site) {
  if (a.tr && a.limit_state) throw InputError("give either --limit-state or --tr, not both");
  std::vector<LimitState> states(all_limit_states.begin(), all_limit_states.end());
  if (a.limit_state) {
    try {
      states = {parse_limit_state(*a.limit_state)};
    } catch (const InputError& e) {
      throw InputError(std::string("--limit-state: ") + e.what());
    }
  }
  return spectrum_columns(site, states, a.limit_state.has_value(), a.tr);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

void print_table(const Site& site, const std::vector<SpectrumColumn>& cols, const std::vector<ElasticSpectrum>& spectra,
                 const std::vector<double>& periods, std::optional<double> q) {
  const SiteSpec& sp = site.spec();
  std::ostream& o = std::cout;
  o << "NTC 2018 elastic spectra (§3.2.3.2)\n";
  o << "Site        : " << site.describe();
  if (const auto nodes = site.grid_nodes(); !nodes.empty()) {
    o << "  (grid cell nodes";
    for (int n : nodes) o << " " << n;
    o << ")";
  }
  if (!sp.comune.empty()) o << "\nNote        : " << comune_note();
  o << "\nSubsoil     : " << to_string(sp.conditions.soil) << ", topography " << to_string(sp.conditions.topography)
    << " (h/H = " << fmt("%.2f", sp.conditions.h_over_H) << ")\n";
  if (sp.given.empty())
    o << "VN = " << fmt("%.0f", sp.vn_years) << " years, CU = " << fmt("%.2f", sp.cu)
      << ", VR = " << fmt("%.1f", site.VR()) << " years\n";
  o << "Damping     : " << fmt("%.1f", spectra[0].damping_pct()) << " % (eta = " << fmt("%.4f", spectra[0].eta())
    << ")\n\n";
  auto row = [&](const std::string& name, const std::string& unit, auto get, const char* f) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%-10s %-7s", name.c_str(), unit.c_str());
    o << buf;
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const std::optional<double> v = get(i);
      std::snprintf(buf, sizeof buf, "%11s", v ? fmt(f, *v).c_str() : "-");
      o << buf;
    }
    o << "\n";
  };
  {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%-10s %-7s", "", "");
    o << buf;
    for (const auto& c : cols) std::snprintf(buf, sizeof buf, "%11s", c.label.c_str()), o << buf;
    o << "\n";
  }
  using OD = std::optional<double>;
  row("P_VR", "%", [&](std::size_t i) { return cols[i].PVR ? OD(*cols[i].PVR * 100) : OD(); }, "%.0f");
  row("TR", "years", [&](std::size_t i) { return cols[i].TR; }, "%.2f");
  row("ag", "g", [&](std::size_t i) { return OD(spectra[i].ag_g()); }, "%.4f");
  row("F0", "-", [&](std::size_t i) { return OD(spectra[i].F0()); }, "%.4f");
  row("Tc*", "s", [&](std::size_t i) { return OD(spectra[i].Tc_star()); }, "%.4f");
  row("SS", "-", [&](std::size_t i) { return OD(spectra[i].SS()); }, "%.4f");
  row("CC", "-", [&](std::size_t i) { return OD(spectra[i].CC()); }, "%.4f");
  row("ST", "-", [&](std::size_t i) { return OD(spectra[i].ST()); }, "%.4f");
  row("S", "-", [&](std::size_t i) { return OD(spectra[i].S()); }, "%.4f");
  row("TB", "s", [&](std::size_t i) { return OD(spectra[i].TB()); }, "%.4f");
  row("TC", "s", [&](std::size_t i) { return OD(spectra[i].TC()); }, "%.4f");
  row("TD", "s", [&](std::size_t i) { return OD(spectra[i].TD()); }, "%.4f");
  row("ag*S", "g", [&](std::size_t i) { return OD(spectra[i].PGA() / units::g); }, "%.4f");
  o << "\nHorizontal elastic spectrum Se (g) [3.2.2] and displacement spectrum SDe (mm) [3.2.10-11]";
  if (q) o << "; design spectrum Sd (g) with q = " << fmt("%.2f", *q);
  o << "\n";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%8s", "T (s)");
  o << buf;
  for (const auto& c : cols) {
    std::snprintf(buf, sizeof buf, "%11s", ("Se " + c.label).c_str()), o << buf;
    std::snprintf(buf, sizeof buf, "%11s", ("SDe " + c.label).c_str()), o << buf;
    if (q) std::snprintf(buf, sizeof buf, "%11s", ("Sd " + c.label).c_str()), o << buf;
  }
  o << "\n";
  for (double T : periods) {
    std::snprintf(buf, sizeof buf, "%8.3f", T);
    o << buf;
    for (const auto& s : spectra) {
      std::snprintf(buf, sizeof buf, "%11.4f", s.Se(T) / units::g), o << buf;
      std::snprintf(buf, sizeof buf, "%11.2f", s.SDe(T) * 1000.0), o << buf;
      if (q) std::snprintf(buf, sizeof buf, "%11.4f", s.Sd(T, *q) / units::g), o << buf;
    }
    o << "\n";
  }
}

void run(const SpectrumArgs& a) {
  // The number rules of the case files (support/number_rules.hpp) are the
  // options' (add_spectrum_command): TR, VN, damping and CU of 1e308 made
  // "TR = inf" and an infinite spectrum.
  const SiteSpec spec = make_spec(a);
  if (a.periods_given && a.periods.find_first_not_of(" ,") == std::string::npos)
    throw InputError("--periods '" + a.periods + "': expected a comma-separated list of periods >= 0 s, e.g. 0,0.5,1 "
                     "(leave the option out for the default periods)");
  const std::vector<double> periods = parse_periods(a.periods);
  const Site site(spec);
  const std::vector<SpectrumColumn> cols = evaluate(a, site);
  std::vector<ElasticSpectrum> spectra;
  for (const SpectrumColumn& c : cols) spectra.emplace_back(c.hazard, spec.conditions, a.damping);
  print_warnings(spectrum_warnings(cols));
  if (a.json) {
    nlohmann::json j = spectrum_json(site, cols, a.damping, periods, a.q);
    std::cout << stamp_version(j).dump(2) << "\n";
  } else {
    print_table(site, cols, spectra, periods, a.q);
  }
}

}  // namespace

void add_spectrum_command(CLI::App& app) {
  auto a = std::make_shared<SpectrumArgs>();
  auto* cmd = app.add_subcommand("spectrum", "NTC 2018 elastic spectra of a site (§3.2), per limit state");
  // Every number option with its range and reason: the rules of the case file's
  // site (support/number_rules.hpp), checked as the command line is parsed.
  with_rule(cmd->add_option("--lat", a->lat, "site latitude (decimal degrees, north)"), rules::latitude_deg);
  with_rule(cmd->add_option("--lon", a->lon, "site longitude (decimal degrees, east)"), rules::longitude_deg);
  with_rule(cmd->add_option("--ag", a->ag_g, "ag on rock, given directly (g)"), rules::ag_g);
  with_rule(cmd->add_option("--F0", a->F0, "F0, given directly (-)"), rules::F0);
  with_rule(cmd->add_option("--Tc-star", a->Tc_star, "TC*, given directly (s)"), rules::Tc_star_s);
  cmd->add_option("--comune", a->comune,
                  "site by comune (ISTAT list): the coordinates of the municipal seat are used and printed");
  cmd->add_option("--province", a->province, "province (sigla, e.g. AQ) of --comune, for a name shared by two");
  cmd->add_option("--island", a->island, "island of Allegato B Tab. 2 (e.g. Sardegna, Lipari)");
  cmd->add_option("--soil", a->soil, "subsoil class A..E (default A)");
  cmd->add_option("--topography", a->topography, "topographic class T1..T4 (default T1)");
  with_rule(cmd->add_option("--h-over-H", a->h_over_H, "relative height of the site on the relief, 0..1 (default 1)"),
            rules::relative_height);
  with_rule(cmd->add_option("--vn", a->vn, "nominal life VN (years, default 50)"), rules::nominal_life_years);
  with_rule(cmd->add_option("--cu", a->cu, "coefficient of use CU (default 1.0)"), rules::use_coefficient);
  cmd->add_option("--use-class", a->use_class, "use class I..IV (sets CU)");
  cmd->add_option("--limit-state", a->limit_state, "SLO|SLD|SLV|SLC (default: all four)");
  with_rule(cmd->add_option("--tr", a->tr, "return period (years) instead of a limit state"),
            rules::return_period_years);
  with_rule(cmd->add_option("--damping", a->damping, "viscous damping (%, default 5)"), rules::damping_or_zero_pct);
  with_rule(cmd->add_option("--q", a->q, "behaviour factor: also print the design spectrum Sd"), rules::behaviour_factor);
  cmd->add_option("--periods", a->periods, "comma-separated periods (s), e.g. 0,0.5,1")
      ->each([a](const std::string&) { a->periods_given = true; });
  cmd->add_option("--grid", a->grid, "hazard grid CSV (default: the shipped spectra/ntc2008_hazard_grid.csv)");
  cmd->add_option("--islands-table", a->islands, "islands CSV (default: the shipped table)");
  cmd->add_flag("--json", a->json, "print JSON (one object for one limit state)");
  cmd->callback([a] { run(*a); });
}

}  // namespace assess::cli

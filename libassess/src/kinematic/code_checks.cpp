// code_checks.cpp: checks of local mechanisms by NTC 2008 (Circ. 617/2009
// C8A.4) and NTC 2018 (Circ. 2019 §C8.7.1.2.1.5-.8).
//
// Notation: a0* spectral activation acceleration (m/s^2); du*, Ts (2008);
// d_SLV, T_SLV, d_SLC, T_SLC (2018); ag (g) on rock, S = SS ST; Se, SDe the
// elastic spectra (m/s^2, m) [3.2.2], [3.2.10]; q behaviour factor; psi = Z/H,
// gamma = 3N/(2N+1); T1 building period; a_Z floor acceleration [C7.2.7-8];
// S_eZ floor spectrum [C7.2.5-6]. The safety index of each check (the return
// period at which it reaches D/C = 1) is check_index.cpp's.
#include "assess/kinematic/code_checks.hpp"

#include "assess/kinematic/code_rules.hpp"
#include "assess/support/error.hpp"
#include "kinematic/checks_of_limit_state.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess {
namespace {


// The inputs of a demand at height: the building's first mode (C8.7.1.2.1.7 / C8A.4.10).
std::vector<std::pair<std::string, double>> height_inputs(const BuildingModel& b, double Z, double psi, double gam,
                                                          double Se_T1) {
  return {{"Z (m)", Z}, {"H (m)", b.H}, {"N (storeys)", double(b.storeys)}, {"T1 (s)", b.T1},
          {"psi(Z) (-)", psi}, {"gamma (-)", gam}, {"Se(T1) (m/s2)", Se_T1}};
}

CheckRow row(CodeEdition code, LimitState ls, const char* kind, const char* location, std::string clause,
             std::string formula, double demand, double capacity, const char* unit) {
  CheckRow r;
  r.code = to_string(code);
  r.limit_state = to_string(ls);
  r.kind = kind;
  r.location = location;
  r.clause = std::move(clause);
  r.formula = std::move(formula);
  r.demand = demand;
  r.capacity = capacity;
  r.unit = unit;
  r.dc = demand / capacity;
  decide(r);
  return r;
}

// Beyond TE the displacement spectrum is no longer Se T^2/4pi^2 but
// [3.2.11] of NTC 2018 §3.2.3.2.3: its inputs, so that the demand can be redone.
void add_long_period_inputs(CheckRow& r, const ElasticSpectrum& e, double T) {
  if (T <= e.TE()) return;
  r.inputs.insert(r.inputs.end(), {{"TE (s)", e.TE()}, {"TF (s)", e.TF()}, {"F0 (-)", e.F0()}, {"S (-)", e.S()},
                                   {"TC (s)", e.TC()}, {"TD (s)", e.TD()}});
}

void set_secant(CheckRow& r, double T, double d, double a, double xi) {
  r.secant_T = T;
  r.secant_d = d;
  r.secant_a = a;
  r.xi_pct = xi;
}

// NTC 2018 displacement demand (m) at the secant period T and the mechanism
// damping xi: SDe(T, xi) [3.2.10] at ground; at height S_eZ(T, xi) T^2/4pi^2
// [C8.7.1.12], not below the plateau's value Se(T1) (b T1)^2/4pi^2 beyond b T1.
double displacement_2018(const CheckInput& in, const HazardParams& h, double T, double xi) {
  if (!(in.Z > 0.0)) return ElasticSpectrum(h, in.site, xi).SDe(T);
  const double two_pi = 2.0 * units::pi;
  const FloorSpectrum fs(h, in.site, *in.building, in.Z, xi);
  const double b = code_rules::floor_spectrum_b, T1 = in.building->T1;
  double d = fs.SDe(T);  // [C8.7.1.12]
  if (T > b * T1) d = std::max(d, fs.Se(T1) * b * b * T1 * T1 / (two_pi * two_pi));
  return d;
}

}  // namespace

bool check_satisfied(double dc, bool no_verdict) { return !no_verdict && std::isfinite(dc) && dc <= 1.0; }

void decide(CheckRow& r) { r.satisfied = check_satisfied(r.dc, r.no_verdict); }

std::string to_string(CodeEdition c) { return c == CodeEdition::NTC2008 ? "NTC2008" : "NTC2018"; }

CodeEdition parse_code_edition(const std::string& s) {
  if (s == "NTC2008") return CodeEdition::NTC2008;
  if (s == "NTC2018") return CodeEdition::NTC2018;
  throw InputError("code edition '" + s + "': expected \"NTC2008\" or \"NTC2018\"");
}

void CheckInput::validate() const {
  if (!(Z >= 0.0)) throw InputError("height Z of the mechanism: expected >= 0 m");
  if (Z > 0.0) {
    if (!building) throw InputError("a mechanism at height Z > 0 m needs the building (H, storeys, T1)");
    building->validate();
  }
  if (!(q >= 1.0)) throw InputError("behaviour factor q: expected >= 1");
  for (CodeEdition c : codes) {
    std::vector<LimitState> need{LimitState::SLD, LimitState::SLV};
    if (c == CodeEdition::NTC2018) need.push_back(LimitState::SLC);
    for (LimitState ls : need)
      if (!hazard.count(ls))
        throw InputError(to_string(c) + " checks need the hazard of " + to_string(ls));
  }
}

double displacement_demand(const CheckInput& in, CodeEdition code, LimitState ls, double T) {
  const HazardParams& h = in.hazard.at(ls);
  if (code == CodeEdition::NTC2018)
    return displacement_2018(in, h, T, ls == LimitState::SLC ? in.damping_SLC_pct : in.damping_SLV_pct);
  const ElasticSpectrum s(h, in.site);  // 5 % [C8A.4.11-12]
  if (!(in.Z > 0.0)) return s.SDe(T);
  const BuildingModel& b = *in.building;
  return code_rules::demand_at_height_2008(s.SDe(b.T1), code_rules::psi_first_mode(in.Z, b.H),
                                           code_rules::gamma_first_mode(b.storeys), T, b.T1);
}

namespace {
// `only`: the rows of that limit state alone (null: every row).
std::vector<CheckRow> checks_of(const KinematicResult& r, const CheckInput& in, const LimitState* only);
}  // namespace

// Issue 37: a mechanism held by tie levels is checked as it is: its capacity
// curve has each level breaking where it fails (kinematic_analysis.hpp), and
// no check takes the wall without them instead (docs/theory/ties.md §2).
std::vector<CheckRow> run_code_checks(const KinematicResult& r, const CheckInput& in) {
  return checks_of(r, in, nullptr);
}

std::vector<CheckRow> detail::code_checks_of_limit_state(const KinematicResult& r, const CheckInput& in, LimitState ls) {
  return checks_of(r, in, &ls);
}

namespace {
std::vector<CheckRow> checks_of(const KinematicResult& r, const CheckInput& in, const LimitState* only) {
  in.validate();
  std::vector<CheckRow> rows;
  if (!r.activates) return rows;
  auto wants = [&](LimitState ls) { return !only || *only == ls; };
  const bool at_height = in.Z > 0.0;
  const bool nonlinear = r.curve_complete();

  for (CodeEdition code : in.codes) {
    const HazardParams& hSLD = in.hazard.at(LimitState::SLD);
    const HazardParams& hSLV = in.hazard.at(LimitState::SLV);
    if (code == CodeEdition::NTC2008) {
      const ElasticSpectrum sSLD(hSLD, in.site), sSLV(hSLV, in.site);
      if (wants(LimitState::SLD) && !at_height) {
        rows.push_back(row(code, LimitState::SLD, "strength", "ground", "C8A.4 SLD [R]", "ag S",
                           sSLD.PGA(), r.a0_star, "m/s2"));
        rows.back().inputs = {{"ag (g)", hSLD.ag_g}, {"S (-)", sSLD.S()}};
      } else if (wants(LimitState::SLD)) {
        const BuildingModel& b = *in.building;
        const double psi = code_rules::psi_first_mode(in.Z, b.H), gam = code_rules::gamma_first_mode(b.storeys);
        rows.push_back(row(code, LimitState::SLD, "strength", "height", "C8A.4 SLD at height [R]",
                           "Se(T1) psi gamma", sSLD.Se(b.T1) * psi * gam, r.a0_star, "m/s2"));
        rows.back().inputs = height_inputs(b, in.Z, psi, gam, sSLD.Se(b.T1));
      }
      if (!wants(LimitState::SLV)) continue;
      if (!at_height || code_rules::height_also_checks_ground_2008)
      {
        rows.push_back(row(code, LimitState::SLV, "strength", "ground", "C8A.4.9 [V-S]", "ag S / q",
                           sSLV.PGA() / in.q, r.a0_star, "m/s2"));
        rows.back().inputs = {{"ag (g)", hSLV.ag_g}, {"S (-)", sSLV.S()}, {"q (-)", in.q}};
      }
      if (at_height) {
        const BuildingModel& b = *in.building;
        const double psi = code_rules::psi_first_mode(in.Z, b.H), gam = code_rules::gamma_first_mode(b.storeys);
        rows.push_back(row(code, LimitState::SLV, "strength", "height", "C8A.4.10 [V-S]",
                           "Se(T1) psi gamma / q", sSLV.Se(b.T1) * psi * gam / in.q, r.a0_star, "m/s2"));
        rows.back().inputs = height_inputs(b, in.Z, psi, gam, sSLV.Se(b.T1));
        rows.back().inputs.push_back({"q (-)", in.q});
      }
      if (nonlinear) {
        if (!at_height || code_rules::height_also_checks_ground_2008)
        {
          CheckInput ground = in;
          ground.Z = 0.0;
          rows.push_back(row(code, LimitState::SLV, "displacement", "ground", "C8A.4.11 [R]", "SDe(Ts)",
                             displacement_demand(ground, code, LimitState::SLV, r.Ts), r.du_star, "m"));
          rows.back().inputs = {{"ag (g)", hSLV.ag_g}, {"Ts (s)", r.Ts}, {"xi (%)", 5.0}, {"eta (-)", sSLV.eta()},
                                {"Se(Ts) (m/s2)", sSLV.Se(r.Ts)}};
          add_long_period_inputs(rows.back(), sSLV, r.Ts);
          set_secant(rows.back(), r.Ts, r.ds_star, r.as_star, 5.0);
        }
        if (at_height) {
          const BuildingModel& b = *in.building;
          const double psi = code_rules::psi_first_mode(in.Z, b.H), gam = code_rules::gamma_first_mode(b.storeys);
          rows.push_back(row(code, LimitState::SLV, "displacement", "height", "C8A.4.12 [R]",
                             "SDe(T1) psi gamma (Ts/T1)^2 / sqrt((1 - Ts/T1)^2 + 0.02 Ts/T1)",
                             displacement_demand(in, code, LimitState::SLV, r.Ts), r.du_star, "m"));
          set_secant(rows.back(), r.Ts, r.ds_star, r.as_star, 5.0);
          rows.back().inputs = height_inputs(b, in.Z, psi, gam, sSLV.Se(b.T1));
          rows.back().inputs.push_back({"SDe(T1) (m)", sSLV.SDe(b.T1)});
          rows.back().inputs.push_back({"Ts (s)", r.Ts});
        }
      }
      continue;
    }

    // NTC 2018 / Circ. 2019.
    const HazardParams& hSLC = in.hazard.at(LimitState::SLC);
    const char* loc = at_height ? "height" : "ground";
    // Peak acceleration demand (m/s^2) for a hazard: ag S at ground, a_Z at height.
    auto peak = [&](const HazardParams& h) {
      if (!at_height) return ElasticSpectrum(h, in.site).PGA();
      return FloorSpectrum(h, in.site, *in.building, in.Z, 5.0).a_Z();
    };
    // Displacement demand (m) at period T and mechanism damping xi.
    auto disp = [&](const HazardParams& h, double T, double xi) { return displacement_2018(in, h, T, xi); };
    const std::string peak_name = at_height ? "a_Z [C7.2.7-8]" : "ag S";
    // The inputs of the peak demand: ag, S at ground; the first mode and a_Z at height.
    auto peak_inputs = [&](const HazardParams& h) {
      const ElasticSpectrum e(h, in.site);
      std::vector<std::pair<std::string, double>> v{{"ag (g)", h.ag_g}, {"S (-)", e.S()}};
      if (at_height) {
        const FloorSpectrum fs(h, in.site, *in.building, in.Z, 5.0);
        const auto hi = height_inputs(*in.building, in.Z, fs.psi(), fs.gamma(), e.Se(in.building->T1));
        v.insert(v.end(), hi.begin(), hi.end());
        v.push_back({"a_Z (m/s2)", fs.a_Z()});
      }
      return v;
    };

    if (wants(LimitState::SLD)) {
      CheckRow sld = row(code, LimitState::SLD, "strength", loc, "C8.7.1.2.1.5 [C8.7.1.8] [V-T]", peak_name,
                         peak(hSLD), r.a0_star, "m/s2");
      sld.inputs = peak_inputs(hSLD);
      rows.push_back(sld);
    }

    if (wants(LimitState::SLV)) {
      CheckRow slv = row(code, LimitState::SLV, "strength", loc, "C8.7.1.2.1.7 [V-T]", peak_name + " / q",
                         peak(hSLV) / in.q, r.a0_star, "m/s2");
      slv.inputs = peak_inputs(hSLV);
      slv.inputs.push_back({"q (-)", in.q});
      rows.push_back(slv);
    }

    if (nonlinear) {
      const std::string dname = at_height ? "S_eZ(T) T^2/4pi^2 [C8.7.1.12]" : "SDe(T) [3.2.10]";
      struct Ls { LimitState ls; const HazardParams* h; double d, T, xi; const char* clause; };
      for (const Ls& x : {Ls{LimitState::SLV, &hSLV, r.d_SLV, r.T_SLV, in.damping_SLV_pct, "C8.7.1.2.1.8 [C8.7.1.10] [V-T]"},
                          Ls{LimitState::SLC, &hSLC, r.d_SLC, r.T_SLC, in.damping_SLC_pct, "C8.7.1.2.1.8 [C8.7.1.11] [V-T]"}}) {
        if (!wants(x.ls)) continue;
        CheckRow c = row(code, x.ls, "displacement", loc, x.clause, dname + ", xi " + std::to_string(int(x.xi)) + " %",
                         disp(*x.h, x.T, x.xi), x.d, "m");
        set_secant(c, x.T, x.d, x.ls == LimitState::SLV ? r.a_SLV : r.a_SLC, x.xi);
        // T = T_SLV or T_SLC: the secant period 2 pi sqrt(d / a(d)) at the capacity point [C8.7.1.10-11].
        c.inputs = {{"ag (g)", x.h->ag_g}, {"T (s)", x.T}, {"xi (%)", x.xi},
                    {"eta (-)", ElasticSpectrum(*x.h, in.site, x.xi).eta()}};
        if (!at_height) {
          const ElasticSpectrum e(*x.h, in.site, x.xi);
          c.inputs.push_back({"Se(T) (m/s2)", e.Se(x.T)});
          add_long_period_inputs(c, e, x.T);
        }
        if (at_height) {
          const FloorSpectrum fs(*x.h, in.site, *in.building, in.Z, x.xi);
          const auto hi = height_inputs(*in.building, in.Z, fs.psi(), fs.gamma(),
                                        ElasticSpectrum(*x.h, in.site).Se(in.building->T1));
          c.inputs.insert(c.inputs.end(), hi.begin(), hi.end());
          c.inputs.push_back({"S_eZ(T) (m/s2)", fs.Se(x.T)});
          c.inputs.push_back({"a_Z (m/s2)", fs.a_Z()});
          const double b = code_rules::floor_spectrum_b, T1 = in.building->T1, two_pi = 2.0 * units::pi;
          c.floor_branch = x.T > b * T1 && fs.Se(T1) * b * b * T1 * T1 / (two_pi * two_pi) > fs.SDe(x.T)
                               ? "plateau_bound"
                               : fs.branch(x.T);
        }
        rows.push_back(c);
      }
    }
  }
  if (!in.sld)
    rows.erase(std::remove_if(rows.begin(), rows.end(), [](const CheckRow& x) { return x.limit_state == "SLD"; }),
               rows.end());
  return rows;
}
}  // namespace

}  // namespace assess

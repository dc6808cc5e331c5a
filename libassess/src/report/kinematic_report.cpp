// kinematic_report.cpp: text and JSON reports of a kinematic case (report
// layer: formats the results, never recomputes physics).
#include "assess/report/kinematic_report.hpp"

#include "assess/report/note_text.hpp"
#include "assess/support/units.hpp"
#include "report/number_text.hpp"
#include "report/text_format.hpp"

#include <cmath>
#include <cstdio>

namespace assess {

const char* verdict(bool satisfied) {
  return satisfied ? "verificato / satisfied" : "non verificato / not satisfied";
}

namespace {
constexpr double g = units::g;
using detail::number_text;

}  // namespace

nlohmann::json to_json(const CheckRow& r) {
  nlohmann::json j{{"code", r.code},         {"limit_state", r.limit_state}, {"kind", r.kind},
                   {"location", r.location}, {"demand", r.demand},           {"capacity", r.capacity},
                   {"unit", r.unit},         {"dc", r.dc},                   {"satisfied", satisfied_json(r.outcome())},
                   {"clause", r.clause},     {"formula", r.formula}};
  if (!r.candidate.empty()) j["candidate"] = r.candidate;
  j["outcome"] = to_string(r.outcome());
  if (!r.note.empty()) j["note"] = note_text(Lang::en, r.note);
  if (!r.inputs.empty()) {
    nlohmann::json in = nlohmann::json::object();
    for (const auto& [name, v] : r.inputs) in[name] = v;
    j["inputs"] = in;  // every input of the demand, name with its unit (issue 24)
  }
  if (!std::isfinite(r.dc)) j["dc"] = nullptr;
  if (!std::isfinite(r.demand)) j["demand"] = nullptr;
  if (r.analyses > 0) {  // dynamic and energy rows (issue 28): D/C = +inf (null) with a collapse or a failed analysis
    j["analyses"] = r.analyses;
    j["collapsed"] = r.collapsed;
    j["failed"] = r.failed;
    j["dc_survivors"] = std::isfinite(r.dc_survivors) ? nlohmann::json(r.dc_survivors) : nlohmann::json(nullptr);
    if (!std::isfinite(r.dc)) j["dc_meaning"] = r.collapsed > 0 ? "collapse" : "failed analyses";
  }
  if (r.index.defined || !r.index.note.empty()) j["index"] = to_json(r.index);
  return j;
}

nlohmann::json to_json(const CheckIndex& x) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json j{{"defined", x.defined}};
  if (x.defined) {
    j["zeta_E"] = num(x.zeta);
    j["ag_capacity_g"] = num(x.ag_capacity_g);
    j["ag_demand_g"] = num(x.ag_demand_g);
    j["TR_capacity_years"] = num(x.TR_capacity);
    j["TR_demand_years"] = num(x.TR_demand);
    j["TR_ratio"] = num(x.TR_ratio);
    j["extrapolated"] = x.extrapolated;
    j["bound"] = x.bound < 0 ? nlohmann::json("below") : x.bound > 0 ? nlohmann::json("above") : nlohmann::json(nullptr);
    j["non_monotonic"] = x.non_monotonic;
    if (x.non_monotonic) j["other_crossing_TR_years"] = num(x.other_crossing_TR);
    j["shape_held"] = x.shape_held;
  }
  if (!x.note.empty()) j["note"] = note_text(Lang::en, x.note);
  return j;
}

// Issue 33: the rows of a mechanism's data or derivation.
nlohmann::json quantities_json(const std::vector<MechanismQuantity>& q) {
  nlohmann::json a = nlohmann::json::array();
  for (const MechanismQuantity& x : q) {
    nlohmann::json j{{"label", x.label}, {"unit", x.unit}, {"source", x.source}};
    j["value"] = x.unit.empty() ? nlohmann::json(nullptr) : nlohmann::json(x.value);
    a.push_back(j);
  }
  return a;
}

std::string quantities_text(const std::vector<MechanismQuantity>& q, bool wide) {
  std::string out;
  for (const MechanismQuantity& x : q) {
    std::string line = "  " + x.label;
    if (!x.unit.empty()) line += " = " + format("%.6g", x.value) + (x.unit == "-" ? "" : " " + x.unit);
    if (!x.source.empty() && x.source != "input") line += " [" + x.source + "]";
    out += (wide ? line : wrap_text(line, 4)) + "\n";
  }
  return out;
}

nlohmann::json kinematic_json(const CaseFile& c, const KinematicCaseResult& out) {
  const CandidateResult& gc = out.candidates[out.governing];
  const KinematicResult& r = gc.result;
  nlohmann::json j;
  j["project"] = c.project;
  j["mechanism"] = c.mechanism.type;
  j["governing"] = gc.label;
  j["Z"] = gc.Z;
  j["alpha0"] = r.alpha0;
  j["FC"] = r.FC;
  j["knowledge_level"] = c.knowledge_level;
  j["M_star"] = r.M_star / units::tonne;
  j["e_star"] = r.e_star;
  j["a0_star"] = r.a0_star;
  j["sum_W_dx"] = r.sum_W_dx / units::kN;
  j["sum_W_dx2"] = r.sum_W_dx2 / units::kN;
  j["sum_W"] = r.sum_W / units::kN;
  j["dk0"] = r.dk0;
  j["d0_star"] = r.d0_star;
  j["du_star"] = r.du_star;
  j["ds_star"] = r.ds_star;
  j["as_star"] = r.as_star;
  j["Ts"] = r.Ts;
  j["d_SLV"] = r.d_SLV;
  j["a_SLV"] = r.a_SLV;
  j["T_SLV"] = r.T_SLV;
  j["d_SLC"] = r.d_SLC;
  j["a_SLC"] = r.a_SLC;
  j["T_SLC"] = r.T_SLC;
  j["curve_model"] = r.curve_model == CurveModel::Linearised ? "linearised" : "finite_displacement";
  // Issue 33: a bound on d0* from the mechanism (null without one).
  const MechanismCandidate& gm = c.mechanism.candidates.at(out.governing);
  j["d0_star_bound"] = std::isfinite(r.d0_star_bound) ? nlohmann::json(r.d0_star_bound) : nlohmann::json(nullptr);
  j["dk0_bound"] = std::isfinite(r.dk0_bound) ? nlohmann::json(r.dk0_bound) : nlohmann::json(nullptr);
  if (std::isfinite(gm.rotation_bound)) j["d0_star_bound_reason"] = gm.rotation_bound_reason;
  j["data"] = quantities_json(c.mechanism.data);
  j["quantities"] = quantities_json(gm.quantities);
  nlohmann::json loads = nlohmann::json::array();
  for (const LoadWork& w : r.loads)
    loads.push_back({{"name", w.load.name}, {"type", to_string(w.load.type)}, {"x", w.load.point.x()},
                     {"z", w.load.point.y()}, {"weight", w.load.weight / units::kN}, {"dx", w.dx}, {"dz", w.dz},
                     {"W_dx", w.W_dx / units::kN}, {"W_dx2", w.W_dx2 / units::kN}, {"work", w.work / units::kN}});
  j["loads"] = loads;
  nlohmann::json curve = nlohmann::json::array();
  for (const CapacityPoint& p : r.curve)
    curve.push_back({{"d_star", p.d_star}, {"a_star", p.a_star}, {"dk", p.dk}, {"alpha", p.alpha}});
  j["capacity_curve"] = curve;
  nlohmann::json cands = nlohmann::json::array();
  for (std::size_t i = 0; i < out.candidates.size(); ++i) {
    const CandidateResult& cr = out.candidates[i];
    nlohmann::json cj{{"label", cr.label}, {"parameter", cr.parameter}, {"Z", cr.Z}, {"alpha0", cr.result.alpha0},
                      {"a0_star", cr.result.a0_star}};
    nlohmann::json dc = nlohmann::json::object(), gov = nlohmann::json::array();
    for (const auto& [code, v] : cr.max_dc) dc[code] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
    for (const auto& [code, gi] : out.governing_by_code)
      if (gi == i) gov.push_back(code);
    cj["governing_dc"] = dc;
    cj["governing_for"] = gov;
    cj["quantities"] = quantities_json(c.mechanism.candidates.at(i).quantities);
    if (!cr.zeta_min.empty()) {
      nlohmann::json z = nlohmann::json::object();
      for (const auto& [code, v] : cr.zeta_min) z[code] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
      cj["zeta_E_min"] = z;  // the lowest index over its checks, per code (issue 41)
    }
    nlohmann::json rows = nlohmann::json::array();
    for (const CheckRow& row : cr.checks) rows.push_back(to_json(row));
    cj["checks"] = rows;
    cands.push_back(cj);
  }
  j["candidates"] = cands;
  j["governing_rule"] = out.checks.empty() ? "smallest alpha0 (no site: no checks)"
                                           : "largest D/C over the candidate's checks, per code (Circ. 2019 C8.7.1, "
                                             "C8A.4: the most unfavourable mechanism)";
  nlohmann::json gbc = nlohmann::json::object();
  for (const auto& [code, gi] : out.governing_by_code) gbc[code] = out.candidates[gi].label;
  j["governing_by_code"] = gbc;
  if (!out.checks.empty()) j["summary"] = to_json(out.verdict);
  j["warnings"] = out.warnings;
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckRow& row : out.checks) checks.push_back(to_json(row));
  j["checks"] = checks;
  return j;
}

std::string wrap_text(const std::string& text, std::size_t indent, std::size_t width) {
  auto columns = [](const std::string& w) {
    std::size_t n = 0;
    for (unsigned char ch : w) n += (ch & 0xC0) != 0x80;
    return n;
  };
  // Leading blanks are kept as they are (the first line's indentation).
  std::size_t pos = text.find_first_not_of(' ');
  if (pos == std::string::npos) return text;
  std::string out, line = text.substr(0, pos);
  std::size_t len = pos;
  bool first = true;
  while (pos <= text.size()) {
    std::size_t next = text.find(' ', pos);
    if (next == std::string::npos) next = text.size();
    const std::string word = text.substr(pos, next - pos);
    const std::size_t wl = columns(word);
    if (!first && len + 1 + wl > width) {
      out += line + "\n";
      line = std::string(indent, ' ') + word;
      len = indent + wl;
    } else {
      line += (first ? "" : " ") + word;
      len += (first ? 0 : 1) + wl;
    }
    first = false;
    pos = next + 1;
  }
  return out + line;
}

/// Items joined by "; " and packed into lines of at most `width` columns,
/// breaking between items (an item longer than a line is wrapped at blanks);
/// the first line starts with `first`, the others with `indent` blanks.
std::string wrap_items(const std::string& first, const std::vector<std::string>& items, std::size_t indent,
                       std::size_t width = 120) {
  auto columns = [](const std::string& w) {
    std::size_t n = 0;
    for (unsigned char ch : w) n += (ch & 0xC0) != 0x80;
    return n;
  };
  std::string out, line = first;
  bool empty = true;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string item = items[i] + (i + 1 < items.size() ? ";" : "");
    if (!empty && columns(line) + 1 + columns(item) > width) {
      out += wrap_text(line, indent, width) + "\n";
      line = std::string(indent, ' ') + item;
    } else {
      line += (empty ? "" : " ") + item;
    }
    empty = false;
  }
  return out + wrap_text(line, indent, width);
}

std::vector<std::string> split_items(const std::string& s) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (true) {
    const std::size_t next = s.find("; ", pos);
    out.push_back(s.substr(pos, next == std::string::npos ? std::string::npos : next - pos));
    if (next == std::string::npos) break;
    pos = next + 2;
  }
  return out;
}

// "inputs: ag (g) = 0.1937, S (-) = 1.411, q (-) = 2" (the demand's inputs, issue 24).
std::string inputs_text(const CheckRow& x) {
  std::string s;
  for (const auto& [name, v] : x.inputs) s += (s.empty() ? "inputs: " : ", ") + name + " = " + format("%.6g", v);
  return s;
}

std::string checks_text(const std::vector<CheckRow>& checks, TextWidth width) {
  std::string out;
  out += format("checks (D/C = demand / capacity; satisfied if D/C <= 1):\n");
  if (width == TextWidth::wide) {
    out += format("  %-8s %-4s %-12s %-7s %12s %12s %-5s %7s %10s %10s %7s  %-30s %s\n", "code", "LS", "kind", "where",
                  "demand", "capacity", "unit", "D/C", "PGA_C(g)", "PGA_D(g)", "zetaE", "verdict",
                  "demand formula / clause");
    for (const CheckRow& x : checks) {
      const std::string pga = x.index.defined ? number_text(x.index.ag_capacity_g, "%.5f", 10) + " " +
                                                    number_text(x.index.ag_demand_g, "%.5f", 10) + " " +
                                                    number_text(x.index.zeta, "%.3f", 7)
                                              : format("%10s %10s %7s", "-", "-", "-");
      out += format("  %-8s %-4s %-12s %-7s %s %s %-5s %s %s  %-30s %s; %s%s\n", x.code.c_str(),
                    x.limit_state.c_str(), x.kind.c_str(), x.location.c_str(), number_text(x.demand, "%.6f", 12),
                    number_text(x.capacity, "%.6f", 12), x.unit.c_str(), number_text(x.dc, "%.3f", 7), pga,
                    x.no_verdict ? "no verdict" : verdict(x.satisfied), x.formula.c_str(), x.clause.c_str(),
                    x.note.empty() ? "" : ("; " + note_text(Lang::en, x.note)).c_str());
      if (!x.inputs.empty()) out += "           " + inputs_text(x) + "\n";
    }
    return out;
  }
  // 120 columns: the numbers on one line (98 columns), the verdict, the
  // demand formula and the clause on the next, wrapped.
  out += format("  %-8s %-4s %-12s %-7s %10s %10s %-5s %7s %9s %9s %7s\n", "code", "LS", "kind", "where", "demand",
                "capacity", "unit", "D/C", "PGA_C(g)", "PGA_D(g)", "zetaE");
  out += format("  %-8s %s\n", "", "verdict; demand formula; clause");
  for (const CheckRow& x : checks) {
    const std::string pga = x.index.defined ? number_text(x.index.ag_capacity_g, "%.5f", 9) + " " +
                                                  number_text(x.index.ag_demand_g, "%.5f", 9) + " " +
                                                  number_text(x.index.zeta, "%.3f", 7)
                                            : format("%9s %9s %7s", "-", "-", "-");
    out += format("  %-8s %-4s %-12s %-7s %s %s %-5s %s %s\n", x.code.c_str(), x.limit_state.c_str(), x.kind.c_str(),
                  x.location.c_str(), number_text(x.demand, "%.6f", 10), number_text(x.capacity, "%.6f", 10),
                  x.unit.c_str(), number_text(x.dc, "%.3f", 7), pga);
    out += wrap_items(std::string(11, ' '),
                      split_items(std::string(x.no_verdict ? "no verdict" : verdict(x.satisfied)) + "; " + x.formula +
                                  "; " + x.clause + (x.note.empty() ? "" : "; " + note_text(Lang::en, x.note))),
                      11) +
           "\n";
    if (!x.inputs.empty()) out += wrap_text(std::string(11, ' ') + inputs_text(x), 11) + "\n";
  }
  return out;
}

std::string kinematic_text(const CaseFile& c, const KinematicCaseResult& res, TextWidth width) {
  const bool wide = width == TextWidth::wide;
  std::string out;
  const CandidateResult& gc = res.candidates[res.governing];
  const KinematicResult& r = gc.result;
  out += format("case: %s\n", c.file.c_str());
  if (!c.project.empty()) out += format("project: %s\n", c.project.c_str());
  {
    const std::string m = format("mechanism: %s, governing candidate: %s (Z = %.3f m)", c.mechanism.type.c_str(),
                                 gc.label.c_str(), gc.Z);
    out += (wide ? m : wrap_text(m, 11)) + "\n";
  }
  if (!c.mechanism.data.empty()) out += "\nmechanism data:\n" + quantities_text(c.mechanism.data, wide);
  if (!c.mechanism.candidates.at(res.governing).quantities.empty())
    out += "\nderivation (governing candidate):\n" + quantities_text(c.mechanism.candidates.at(res.governing).quantities, wide);
  if (res.candidates.size() > 1) {
    const bool checked = !res.governing_by_code.empty();
    const std::string head = format("\ncandidates (%s searched; governing = %s):", c.mechanism.parameter_name.c_str(),
                  checked ? "largest D/C over its checks, per code (Circ. 2019 C8.7.1; C8A.4: the most unfavourable "
                            "mechanism; NTC 2018: the lowest ag capacity)"
                          : "smallest alpha0 (no site: no checks)");
    out += (wide ? head : wrap_text(head, 2)) + "\n";
    // 120 columns: narrower number columns; a long label on a line of its own.
    const int lw = wide ? 44 : 40;
    out += format(wide ? "  %-*s %11s %11s" : "  %-*s %10s %10s", lw, "candidate", "alpha0 (-)", "a0* (m/s2)");
    for (const auto& [code, gi] : res.governing_by_code)
      out += format(wide ? " %11s" : " %8s", ("D/C " + code.substr(3)).c_str());
    if (checked) out += format(wide ? " %12s" : " %10s", "zetaE min");
    out += "\n";
    for (std::size_t i = 0; i < res.candidates.size(); ++i) {
      const CandidateResult& cr = res.candidates[i];
      std::string label = cr.label;
      if (!wide && label.size() > std::size_t(lw)) {
        out += "  " + label + "\n";
        label.clear();
      }
      out += format(wide ? "  %-*s %11.6f %11.6f" : "  %-*s %10.6f %10.5f", lw, label.c_str(), cr.result.alpha0,
                    cr.result.a0_star);
      std::string gov;
      for (const auto& [code, gi] : res.governing_by_code) {
        const auto it = cr.max_dc.find(code);
        out += " " + number_text(it == cr.max_dc.end() ? 0.0 : it->second, "%.3f", wide ? 11 : 8);
        if (gi == i) gov += (gov.empty() ? "" : ", ") + (wide ? code : code.substr(3));
      }
      if (checked) {
        // The lowest index of the code that governs the report (NTC 2018 when checked).
        const auto z = cr.zeta_min.find(res.governing_by_code.count("NTC2018") ? "NTC2018" : res.governing_by_code.begin()->first);
        out += " " + number_text(z == cr.zeta_min.end() ? std::nan("") : z->second, "%.3f", wide ? 12 : 10);
      }
      if (!checked && i == res.governing) gov = "smallest alpha0";
      out += gov.empty() ? "\n" : (wide ? "  <- governing (" : "  <- governing ") + gov + (wide ? ")\n" : "\n");
    }
  }
  out += format("\nvirtual displacements (largest block rotation = 1 rad; x outward, z up):\n");
  if (wide) {
    out += format("  %-28s %-11s %9s %9s %11s %10s %10s %12s %12s %12s\n", "load", "type", "x (m)", "z (m)", "W (kN)",
                  "dx (m)", "dz (m)", "W dx (kNm)", "W dx2 (kNm2)", "work (kNm)");
    for (const LoadWork& w : r.loads)
      out += format("  %-28s %-11s %9.4f %9.4f %11.4f %10.5f %10.5f %12.5f %12.5f %12.5f\n", w.load.name.c_str(),
                    to_string(w.load.type).c_str(), w.load.point.x(), w.load.point.y(),
                    (w.load.type == LoadType::Weight || w.load.type == LoadType::SelfWeight ? w.load.weight
                                                                                             : w.load.force.norm()) /
                        units::kN,
                    w.dx, w.dz, w.W_dx / units::kN, w.W_dx2 / units::kN, w.work / units::kN);
  } else {
    // 120 columns: a load name longer than its column goes on a line of its own.
    out += format("  %-22s %-11s %8s %8s %10s %8s %8s %11s %12s %11s\n", "load", "type", "x (m)", "z (m)", "W (kN)",
                  "dx (m)", "dz (m)", "W dx (kNm)", "W dx2(kNm2)", "work (kNm)");
    for (const LoadWork& w : r.loads) {
      std::string name = w.load.name;
      if (name.size() > 22) {
        out += "  " + name + "\n";
        name.clear();
      }
      out += format("  %-22s %-11s %8.3f %8.3f %10.3f %8.4f %8.4f %11.4f %12.4f %11.4f\n", name.c_str(),
                    to_string(w.load.type).c_str(), w.load.point.x(), w.load.point.y(),
                    (w.load.type == LoadType::Weight || w.load.type == LoadType::SelfWeight ? w.load.weight
                                                                                             : w.load.force.norm()) /
                        units::kN,
                    w.dx, w.dz, w.W_dx / units::kN, w.W_dx2 / units::kN, w.work / units::kN);
    }
  }
  out += format("\nlinear kinematic analysis:\n");
  out += format("  sum W (seismic weights P + Q)          %14.6f kN\n", r.sum_W / units::kN);
  out += format("  sum W dx                               %14.6f kN m\n", r.sum_W_dx / units::kN);
  out += format("  sum W dx^2                             %14.6f kN m^2\n", r.sum_W_dx2 / units::kN);
  out += format("  work of the other forces               %14.6f kN m\n", r.work_other / units::kN);
  out += format("  alpha0         [C8A.4.1 / C8.7.1.1]    %14.6f -\n", r.alpha0);
  out += format("  M*             [C8A.4.2]               %14.6f t\n", r.M_star / units::tonne);
  out += format("  e*             [C8A.4.3 / C8.7.1.5]    %14.6f -\n", r.e_star);
  out += format("  FC (%s)                               %14.2f -\n", c.knowledge_level.c_str(), r.FC);
  out += format("  a0* = alpha0 g/(e* FC) [C8A.4.4 / C8.7.1.3] %9.6f m/s2 (%.5f g)\n", r.a0_star, r.a0_star / g);
  if (!r.activates) return out;
  out += format("\nnon-linear kinematic analysis (%s curve):\n",
              r.curve_model == CurveModel::Linearised ? "linearised" : "finite-displacement");
  out += format("  control point (block %d) x %.4f m, z %.4f m, dx_k = %.6f m\n", r.control_block, r.control_point.x(),
              r.control_point.y(), r.dx_k);
  if (!r.curve_complete()) {
    out += format("  curve incomplete: %s\n", r.message.c_str());
    return out;
  }
  out += format("  dk0 (alpha = 0)                        %14.6f m\n", r.dk0);
  out += format("  d*/dk          [C8A.4.5 / C8.7.1.4]    %14.6f -\n", r.d_star_per_dk);
  out += format("  d0*                                    %14.6f m\n", r.d0_star);
  if (std::isfinite(r.d0_star_bound)) {
    const std::string b = format("  d0* bound                              %14.6f m (dk = %.6f m): %s; du*, d_SLV, d_SLC "
                                 "capped at 0.4, 0.4, 0.6 of it", r.d0_star_bound, r.dk0_bound,
                                 c.mechanism.candidates.at(res.governing).rotation_bound_reason.c_str());
    out += (wide ? b : wrap_text(b, 4)) + "\n";
  }
  out += format("  NTC 2008: du* = %.6f m, ds* = %.6f m, as* = %.6f m/s2, Ts = %.6f s\n", r.du_star, r.ds_star,
              r.as_star, r.Ts);
  out += format("  NTC 2018: d_SLV = %.6f m, a(d_SLV) = %.6f m/s2, T_SLV = %.6f s [C8.7.1.10]\n", r.d_SLV, r.a_SLV, r.T_SLV);
  out += format("            d_SLC = %.6f m, a(d_SLC) = %.6f m/s2, T_SLC = %.6f s [C8.7.1.11]\n", r.d_SLC, r.a_SLC, r.T_SLC);
  out += format("\ncapacity curve:\n  %10s %10s %12s %12s\n", "dk (m)", "alpha (-)", "d* (m)", "a* (m/s2)");
  for (const CapacityPoint& p : r.curve)
    out += format("  %10.5f %10.6f %12.6f %12.6f\n", p.dk, p.alpha, p.d_star, p.a_star);
  if (res.checks.empty()) {
    out += "\nno site in the case: no code checks\n";
    return out;
  }
  out += "\n" + checks_text(res.checks, width);
  out += "\n" + verdict_text(res.verdict, width);
  return out;
}

nlohmann::json satisfied_json(Outcome o) {
  return o == Outcome::no_verdict ? nlohmann::json(nullptr) : nlohmann::json(o == Outcome::satisfied);
}

void add_outcome(nlohmann::json& j, Outcome o) {
  j["satisfied"] = satisfied_json(o);
  j["outcome"] = to_string(o);
}

nlohmann::json to_json(const VerdictRow& r) {
  return {{"code", r.code},
          {"approach", r.approach},
          {"limit_state", r.limit_state},
          {"location", r.location},
          {"dc", std::isfinite(r.dc) ? nlohmann::json(r.dc) : nlohmann::json(nullptr)},
          {"satisfied", satisfied_json(r.outcome())},
          {"outcome", to_string(r.outcome())},
          {"clause", r.clause},
          {"candidate", r.candidate},
          {"note", note_text(Lang::en, r.note)},
          {"checks", r.checks},
          {"failing", r.failing}};
}

nlohmann::json to_json(const Verdict& v) {
  nlohmann::json rows = nlohmann::json::array(), overall = nlohmann::json::array();
  for (const VerdictRow& r : v.rows) rows.push_back(to_json(r));
  for (const CodeVerdict& c : v.overall)
    overall.push_back({{"code", c.code},
                       {"satisfied", satisfied_json(c.outcome())},
                       {"outcome", to_string(c.outcome())},
                       {"checks", c.checks},
                       {"failing", c.failing},
                       {"no_verdict", c.no_verdict},
                       {"max_dc", std::isfinite(c.max_dc) ? nlohmann::json(c.max_dc) : nlohmann::json(nullptr)}});
  nlohmann::json methods = nlohmann::json::array();
  for (const MethodVerdict& m : v.methods)
    methods.push_back({{"code", m.code},
                       {"method", m.method},
                       {"satisfied", satisfied_json(m.outcome())},
                       {"outcome", to_string(m.outcome())},
                       {"checks", m.checks},
                       {"failing", m.failing},
                       {"no_verdict", m.no_verdict},
                       {"max_dc", std::isfinite(m.max_dc) ? nlohmann::json(m.max_dc) : nlohmann::json(nullptr)},
                       {"for_comparison", m.code != v.conclusion_code}});
  nlohmann::json conclusion = nullptr;
  if (const MethodVerdict* c = v.conclusion())
    conclusion = {{"method", c->method}, {"code", c->code}, {"satisfied", satisfied_json(c->outcome())},
                  {"outcome", to_string(c->outcome())},
                  {"max_dc", std::isfinite(c->max_dc) ? nlohmann::json(c->max_dc) : nlohmann::json(nullptr)}};
  return {{"by_approach", rows}, {"overall", overall}, {"by_method", methods}, {"adopted_method", v.adopted},
          {"conclusion", conclusion}};
}

std::string verdict_word(const VerdictRow& r) {
  if (r.no_verdict) return "no verdict";
  if (r.code == "seed") return r.satisfied ? "<= 1, no overturning" : std::isinf(r.dc) ? "collapse (overturned)" : "> 1";
  return verdict(r.satisfied);
}

std::string verdict_text(const Verdict& v, TextWidth width) {
  if (v.rows.empty()) return "";
  const bool wide = width == TextWidth::wide;
  auto para = [&](const std::string& line, std::size_t ind) { return wide ? line : wrap_text(line, ind); };
  std::string out = para("summary by approach (the governing check of each code and approach: the largest D/C over "
                         "every candidate, limit state and location; seed Fig. 8):",
                         2) +
                    "\n";
  out += format("  %-8s %-15s %-4s %-7s %8s  %-31s %s\n", "code", "approach", "LS", "where", "D/C", "verdict",
                "candidate; clause; notes");
  for (const VerdictRow& r : v.rows) {
    std::string tail = r.candidate.empty() ? r.clause : r.candidate + "; " + r.clause;
    if (r.failing > 0 && r.checks > 1) tail += format("; %d of %d checks fail", r.failing, r.checks);
    if (!r.note.empty()) tail += "; " + note_text(Lang::en, r.note);
    const std::string dc = number_text(r.dc, "%.3f", 8);
    const std::string cols = format("  %-8s %-15s %-4s %-7s %s  %-31s", r.code.c_str(),
                                    (r.code == "seed" ? std::string("energy (mean)") : r.approach).c_str(),
                                    r.limit_state.c_str(), r.location.c_str(), dc.c_str(), verdict_word(r).c_str());
    out += (wide ? cols + " " + tail : cols + "\n" + wrap_items(std::string(11, ' '), split_items(tail), 11)) + "\n";
  }
  out += para("verdict per procedure (Circ. 2019 C8.7.1.2: linear C8.7.1.2.1.7, non-linear C8.7.1.2.1.8 and "
              "dynamic C8.7.1.2.1.9 are alternatives; each fails if any of its checks fails; the seed's energy D/C "
              "is not a code check):",
              2) +
         "\n";
  for (const MethodVerdict& m : v.methods) {
    out += format("  %-8s %-10s %s: %d of %d checks fail, largest D/C %s", m.code.c_str(), m.method.c_str(),
                  m.satisfied ? "VERIFICATO / SATISFIED" : "NON VERIFICATO / NOT SATISFIED", m.failing, m.checks,
                  number_text(m.max_dc, "%.3f"));
    if (m.no_verdict > 0) out += format(" (%d without a verdict)", m.no_verdict);
    if (m.code != v.conclusion_code) out += " (for comparison)";
    out += "\n";
  }
  if (const MethodVerdict* c = v.conclusion())
    out += para(format("conclusion (adopted procedure: %s, %s; case key \"method\"): %s, D/C = %s",
                       c->method.c_str(), c->code.c_str(),
                       c->satisfied ? "VERIFICATO / SATISFIED" : "NON VERIFICATO / NOT SATISFIED",
                       number_text(c->max_dc, "%.3f")),
                2) +
           "\n";
  else if (!v.methods.empty())
    out += "conclusion: the adopted procedure (" + v.adopted + ") has no check in this case: no verdict\n";
  return out;
}

}  // namespace assess

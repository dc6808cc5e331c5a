// rocking_report.cpp: the JSON and the history CSV of one rocking analysis
// (report/rocking_report.hpp), moved from apps/cmd_rocking.cpp for issue 40.
#include "assess/report/rocking_report.hpp"

#include "assess/support/units.hpp"

#include <cstdio>
#include <optional>

namespace assess {
namespace {

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json rocking_result_json(const RockingResult& r) {
  nlohmann::json j;
  j["theta_max"] = r.theta_max;
  j["t_theta_max"] = r.t_theta_max;
  j["theta_u"] = r.theta_u;
  j["theta_max_over_theta_u"] = r.theta_max / r.theta_u;
  j["theta_cr"] = optional_json(r.theta_cr);
  j["alpha"] = r.alpha;
  j["restitution"] = optional_json(r.restitution);
  j["overturned"] = r.overturned;
  j["t_overturn"] = optional_json(r.t_overturn);
  j["kinetic_energy_overturn"] = r.kinetic_energy_overturn / units::kN;  // kJ/m
  j["impacts"] = r.impacts;
  j["energy_demand"] = r.energy_demand / units::kN;  // kJ/m
  j["capacity"] = r.capacity / units::kN;            // kJ/m
  j["dc"] = r.dc;
  j["d_max"] = r.d_max;
  j["termination"] = to_string(r.termination);
  j["end"] = to_string(r.end);
  j["t_end"] = r.t_end;
  j["motion_duration"] = r.motion_duration;
  j["steps"] = r.steps;
  j["rhs_evaluations"] = r.rhs_evaluations;
  return j;
}

nlohmann::json rocking_json(const RockingResult& r, const Record& record, double scale, bool reverse) {
  nlohmann::json j = rocking_result_json(r);
  j["record"] = {{"name", record.name}, {"format", record.format}, {"npts", record.size()},
                 {"dt", record.dt}, {"pga_g", record.pga() / units::g_n}, {"scale", scale},
                 {"reverse", reverse}};
  return j;
}

std::string rocking_history_csv(const RockingHistory& h, const std::string& header) {
  std::string out = header + "\n";
  out.reserve(out.size() + h.t.size() * 48);
  char line[96];
  for (std::size_t i = 0; i < h.t.size(); ++i) {
    std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g\n", h.t[i], h.theta[i], h.omega[i]);
    out += line;
  }
  return out;
}

}  // namespace assess

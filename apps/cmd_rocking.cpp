// cmd_rocking.cpp: `assess rocking`, time-history analysis of a rocking wall
// (rigid Housner block or smooth block on a Winkler foundation) under a
// recorded accelerogram. Parses, calls the library, prints.
#include "commands.hpp"

#include <assess/support/error.hpp>
#include <assess/records/record_io.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

namespace assess::cli {
namespace {

struct RockingArgs {
  std::string model;
  double thickness = 0.0, height = 0.0, unit_weight_kN = 0.0;
  double k_kN = std::nan("");
  std::string restitution;
  bool one_sided = false;
  std::string record;
  double dt = std::nan("");
  std::string unit;
  double scale = 1.0;
  bool reverse = false;
  std::string overturn_at = "theta_u";
  std::string history;
  bool json = false;
  std::string stepper = "rk8pd";
  double rtol = RockingOptions{}.rel_tol;
  double atol = RockingOptions{}.abs_tol;
  double tail = 0.0;
};

Restitution parse_restitution(const std::string& text, bool one_sided) {
  if (text.empty()) return one_sided ? Restitution::one_sided_theory() : Restitution::housner();
  if (text == "housner") return Restitution::housner();
  if (text == "one-sided-theory") return Restitution::one_sided_theory();
  if (text == "none") return Restitution::none();
  char* end = nullptr;
  const double e = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    throw InputError("--restitution expects a number in [-1, 1], 'housner', 'one-sided-theory' or 'none', got '" +
                     text + "'");
  return Restitution::given(e);
}

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

void run(const RockingArgs& a) {
  if (a.model != "smooth" && a.model != "rigid") throw InputError("--model must be 'smooth' or 'rigid'");
  const RockingBody body = RockingBody::rectangle(a.thickness, a.height, a.unit_weight_kN * units::kN);
  Foundation foundation = Foundation::rigid();
  if (a.model == "smooth") {
    if (std::isnan(a.k_kN)) throw InputError("--k (Winkler modulus, kN/m^3) is required for the smooth model");
    if (!(a.k_kN > 0.0 && std::isfinite(a.k_kN))) throw InputError("--k must be a positive number (kN/m^3)");
    foundation = Foundation::winkler(a.k_kN * units::kN);
  } else if (!std::isnan(a.k_kN)) {
    throw InputError("--k applies only to --model smooth");
  }
  const Sidedness sided = a.one_sided ? Sidedness::one_sided : Sidedness::two_sided;
  const RockingModel model(body, foundation, sided, parse_restitution(a.restitution, a.one_sided));

  // A plain record: --dt (and --unit, default g) for one column; --unit alone
  // for two columns (time, acceleration), dt read from the time column (the
  // same readers as the case files' {"file", "dt", "unit"}).
  Record record;
  if (!std::isnan(a.dt)) {
    record = read_plain_record(a.record, a.dt, parse_acceleration_unit(a.unit.empty() ? "g" : a.unit));
  } else if (!a.unit.empty()) {
    try {
      record = read_plain_record(a.record, parse_acceleration_unit(a.unit));
    } catch (const InputError& e) {
      throw InputError(std::string("--unit applies only to a plain record file: without --dt, a plain file of two "
                                   "columns (time in s, acceleration): ") + e.what());
    }
  } else {
    record = read_record(a.record);
  }
  RockingOptions opt;
  opt.scale = a.scale;
  opt.reverse = a.reverse;
  opt.tail_s = a.tail;
  opt.rel_tol = a.rtol;
  opt.abs_tol = a.atol;
  if (a.overturn_at == "theta_u") opt.overturn = OverturnCriterion::theta_u;
  else if (a.overturn_at == "half_pi") opt.overturn = OverturnCriterion::half_pi;
  else throw InputError("--overturn-at must be 'theta_u' or 'half_pi'");
  const auto stepper = parse_stepper(a.stepper);
  if (!stepper) throw InputError("--stepper must be rk8pd, rkck or rkf45");
  opt.stepper = *stepper;
  opt.record_history = !a.history.empty();

  const RockingResult r = analyse(model, record, opt);

  if (!a.history.empty()) {
    std::ofstream out(a.history);
    if (!out) throw InputError("cannot write the history file '" + a.history + "'");
    out << "t_s,theta_rad,omega_rad_s\n";
    char line[96];
    for (std::size_t i = 0; i < r.history.t.size(); ++i) {
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g\n", r.history.t[i], r.history.theta[i], r.history.omega[i]);
      out << line;
    }
  }

  if (a.json) {
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
    j["steps"] = r.steps;
    j["rhs_evaluations"] = r.rhs_evaluations;
    j["record"] = {{"name", record.name}, {"format", record.format}, {"npts", record.size()},
                   {"dt", record.dt}, {"pga_g", record.pga() / units::g_n}, {"scale", a.scale},
                   {"reverse", a.reverse}};
    std::cout << stamp_version(j).dump(2) << "\n";
    return;
  }
  std::printf("rocking analysis: %s block, %s, record %s (%s, %zu points, dt = %g s, PGA = %.4f g) x %g%s\n",
              a.model.c_str(), a.one_sided ? "one-sided" : "two-sided", record.name.c_str(), record.format.c_str(),
              record.size(), record.dt, record.pga() / units::g_n, a.scale, a.reverse ? ", reversed" : "");
  std::printf("  alpha          = %.6f rad\n", r.alpha);
  if (r.theta_cr) std::printf("  theta_cr       = %.6g rad\n", *r.theta_cr);
  std::printf("  theta_u        = %.6f rad\n", r.theta_u);
  if (r.restitution) std::printf("  restitution    = %.6f\n", *r.restitution);
  else std::printf("  restitution    = none\n");
  std::printf("  theta_max      = %.6g rad at t = %.4f s (theta_max/theta_u = %.4f)\n", r.theta_max, r.t_theta_max,
              r.theta_max / r.theta_u);
  std::printf("  d_max          = %.6g m (centroid)\n", r.d_max);
  std::printf("  impacts        = %ld\n", r.impacts);
  if (r.overturned)
    std::printf("  OVERTURNED at t = %.4f s, kinetic energy %.6g kJ/m\n", *r.t_overturn,
                r.kinetic_energy_overturn / units::kN);
  std::printf("  energy D/C     = %.4f (demand %.6g kJ/m, capacity %.6g kJ/m)\n", r.dc, r.energy_demand / units::kN,
              r.capacity / units::kN);
  std::printf("  termination    = %s (%ld steps, %ld rhs evaluations)\n", to_string(r.termination), r.steps,
              r.rhs_evaluations);
}

}  // namespace

void add_rocking_command(CLI::App& app) {
  auto args = std::make_shared<RockingArgs>();
  auto* cmd = app.add_subcommand("rocking", "Non-linear rocking of a wall under an accelerogram (rigid or smooth block)");
  cmd->add_option("--model", args->model, "smooth (Winkler foundation) or rigid (Housner)")->required();
  cmd->add_option("--thickness", args->thickness, "full thickness 2b (m)")->required();
  cmd->add_option("--height", args->height, "full height 2h (m)")->required();
  cmd->add_option("--unit-weight", args->unit_weight_kN, "unit weight (kN/m^3)")->required();
  cmd->add_option("--k", args->k_kN, "Winkler modulus (kN/m^3), smooth model only");
  cmd->add_option("--restitution", args->restitution,
                  "VALUE in [-1, 1] | housner | one-sided-theory | none (default: housner, one-sided-theory if --one-sided)");
  cmd->add_flag("--one-sided", args->one_sided, "one-sided rocking (facade against transverse walls)");
  cmd->add_option("--record", args->record, "accelerogram file (PEER AT2, ESM/ITACA ASCII, .cor.acc; plain with --dt)")
      ->required();
  cmd->add_option("--dt", args->dt, "time step of a plain record file (s)");
  cmd->add_option("--unit", args->unit, "unit of a plain record file: g, m/s^2, cm/s^2 (default g)");
  cmd->add_option("--scale", args->scale, "factor on the record (default 1)");
  cmd->add_flag("--reverse", args->reverse, "flip the record's polarity");
  cmd->add_option("--overturn-at", args->overturn_at, "theta_u (default) or half_pi");
  cmd->add_option("--history", args->history, "write t, theta, theta' to this CSV file");
  cmd->add_flag("--json", args->json, "print the results as one JSON object");
  cmd->add_option("--stepper", args->stepper, "rk8pd (default), rkck or rkf45");
  cmd->add_option("--rtol", args->rtol, "relative tolerance per step (default 1e-7)");
  cmd->add_option("--atol", args->atol, "absolute tolerance per step, rad and rad/s (default 1e-9)");
  cmd->add_option("--tail", args->tail, "free motion after the record (s, default 0)");
  cmd->callback([args] { run(*args); });
}

}  // namespace assess::cli

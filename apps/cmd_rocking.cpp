// cmd_rocking.cpp: `assess rocking`, time-history analysis of a rocking wall
// (rigid Housner block or smooth block on a Winkler foundation) under a
// recorded accelerogram. Parses, calls the library, prints.
#include "commands.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/assessment/mechanism_dynamics.hpp>
#include <assess/support/error.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/output_file.hpp>
#include <assess/records/record_io.hpp>
#include <assess/dynamics/analysis_limits.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/dynamics/rocking_request.hpp>
#include <assess/report/note_text.hpp>
#include <assess/report/rocking_report.hpp>
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
  bool dt_given = false;  // --dt on the command line (a NaN given is an error, not "no --dt")
  std::string unit;
  double scale = 1.0;
  bool reverse = false;
  std::string overturn_at = "theta_u";
  std::string history;
  bool json = false;
  std::string stepper = "rk8pd";
  double rtol = RockingOptions{}.rel_tol;
  double atol = RockingOptions{}.abs_tol;
  double tail = RockingOptions{}.tail_s;  // the one default of every dynamic command
};

void run(const RockingArgs& a) {
  // The options checked, the model built and the record read by the library
  // (dynamics/rocking_request.hpp), as for the Python module's assess.rocking.
  RockingRequest q;
  q.model = a.model;
  q.thickness = a.thickness;
  q.height = a.height;
  q.unit_weight_kN = a.unit_weight_kN;
  if (!std::isnan(a.k_kN)) q.k_kN = a.k_kN;
  q.restitution = a.restitution;
  q.one_sided = a.one_sided;
  q.record = a.record;
  if (a.dt_given) q.dt = a.dt;
  q.unit = a.unit;
  q.scale = a.scale;
  q.reverse = a.reverse;
  q.overturn_at = a.overturn_at;
  q.stepper = a.stepper;
  q.rtol = a.rtol;
  q.atol = a.atol;
  q.tail = a.tail;
  q.history = !a.history.empty();
  const RockingSetup setup = prepare_rocking(q);
  const Record& record = setup.record;
  const RockingResult r = run_rocking(setup);

  // Whole or not at all; a full disk (/dev/full) is an error, never exit 0 (output_file.hpp).
  if (!a.history.empty())
    write_output_file(a.history, rocking_history_csv(r.history, "t_s,theta_rad,omega_rad_s"), "--history");

  if (a.json) {
    nlohmann::json j = rocking_json(r, record, a.scale, a.reverse);
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
  std::printf("  end            = %s at t = %.4f s (record %.4f s, free motion cap %g s)\n", to_string(r.end), r.t_end,
              r.motion_duration, a.tail);
}

// `assess dynamic CASE --record FILE`: the governing mechanism of a case file
// (any 1-DOF chain, at ground level or at height) under one record.
struct CaseDynamicArgs {
  std::string file, record, unit, history, model, restitution, stepper = "rk8pd";
  double dt = std::nan(""), scale = 1.0, k_kN = std::nan(""), tail = RockingOptions{}.tail_s;
  double rtol = RockingOptions{}.rel_tol, atol = RockingOptions{}.abs_tol;
  bool reverse = false, json = false, floor = false;
};

void run_case(const CaseDynamicArgs& a) {
  const CaseFile kase = read_case_file(a.file);
  const KinematicCaseResult kin = run_kinematic_case(kase);
  const CandidateResult& gov = kin.candidates[kin.governing];
  const Chain& chain = kase.mechanism.candidates[kin.governing].chain;
  DynamicSpec spec;
  spec.smooth = false;
  if (!kase.dynamic.is_null()) {
    nlohmann::json d = kase.dynamic;
    if (!d.contains("records") && !d.contains("select"))  // the record comes from --record
      d["records"] = nlohmann::json::array({nlohmann::json{{"file", "(--record)"}}});
    spec = parse_dynamic(d, kase.file, ".");
  }
  // Errors about a value the command line gave name its option, not the case's JSON path.
  if (!a.model.empty()) {
    if (a.model != "smooth" && a.model != "rigid") throw InputError("--model must be 'smooth' or 'rigid'");
    spec.smooth = a.model == "smooth";
    spec.model_from = "--model";
  }
  if (!std::isnan(a.k_kN)) spec.k = a.k_kN * units::kN, spec.k_from = "--k";
  if (spec.smooth && !(spec.k > 0.0))
    throw InputError("--k (Winkler modulus, kN/m^3) is required for the smooth model (or give /dynamic/k in the case)");
  if (!a.restitution.empty()) {
    spec.restitutions = {parse_restitution_option(a.restitution, spec.sidedness == Sidedness::one_sided)};
    spec.restitution_given = true;
    spec.restitution_from = "--restitution";
  } else if (spec.restitutions.empty()) {
    spec.restitutions = {spec.sidedness == Sidedness::one_sided ? Restitution::one_sided_theory() : Restitution::housner()};
  }
  if (a.floor) spec.floor_input = true;
  const MechanismDynamics md = build_mechanism_dynamics(kase, gov, chain, spec);
  if (!md.applies) throw InputError(a.file + ": the dynamic model does not apply: " + note_text(Lang::en, md.note));

  if (std::isnan(a.dt) && !a.unit.empty())
    throw InputError("--unit applies only to a plain record file, given with --dt");
  const Record record = std::isnan(a.dt) ? read_record(a.record)
                                         : read_plain_record(a.record, a.dt, parse_acceleration_unit(a.unit.empty() ? "g" : a.unit));
  RockingOptions opt = spec.options;
  opt.scale = a.scale;
  opt.reverse = a.reverse;
  opt.tail_s = a.tail;
  opt.rel_tol = a.rtol;
  opt.abs_tol = a.atol;
  const auto stepper = parse_stepper(a.stepper);
  if (!stepper) throw InputError("--stepper must be rk8pd, rkck or rkf45");
  opt.stepper = *stepper;
  opt.record_history = !a.history.empty();
  const Record input = md.input(record);
  const RockingResult r = md.analyse(0, input, opt);
  const KinematicResult& k = gov.result;
  const double d_control = md.control_displacement(k, r.theta_max_side * r.theta_max);
  const double d_star = d_control * k.d_star_per_dk;

  // Whole or not at all; a full disk (/dev/full) is an error, never exit 0 (output_file.hpp).
  if (!a.history.empty()) write_output_file(a.history, rocking_history_csv(r.history, "t_s,q_rad,qdot_rad_s"), "--history");
  if (a.json) {
    nlohmann::json j;
    j["case_file"] = a.file;
    j["mechanism"] = gov.label;
    j["model"] = note_text(Lang::en, md.describe());
    j["Z"] = md.Z;
    j["theta_max"] = r.theta_max;
    j["t_theta_max"] = r.t_theta_max;
    j["theta_u"] = r.theta_u;
    j["d_control"] = d_control;
    j["d_star"] = d_star;
    j["dk0"] = k.dk0;
    j["d_SLV"] = k.d_SLV;
    j["overturned"] = r.overturned;
    j["impacts"] = r.impacts;
    j["restitution"] = md.e.front();
    j["dc"] = r.dc;
    j["termination"] = to_string(r.termination);
    j["end"] = to_string(r.end);
    j["t_end"] = r.t_end;
    j["motion_duration"] = r.motion_duration;
    j["steps"] = r.steps;
    j["record"] = {{"name", record.name}, {"npts", record.size()}, {"dt", record.dt},
                   {"pga_g", record.pga() / units::g_n}, {"scale", a.scale}, {"reverse", a.reverse},
                   {"input_pga_g", input.pga() * a.scale / units::g_n}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("dynamic analysis of %s: %s\n", a.file.c_str(), gov.label.c_str());
  std::printf("  model          : %s\n", note_text(Lang::en, md.describe()).c_str());
  std::printf("  record         : %s (%zu points, dt = %g s, PGA = %.4f g) x %g%s; at the base PGA = %.4f g\n",
              record.name.c_str(), record.size(), record.dt, record.pga() / units::g_n, a.scale,
              a.reverse ? ", reversed" : "", input.pga() * a.scale / units::g_n);
  std::printf("  restitution    = %.6f\n", md.e.front());
  std::printf("  theta_max      = %.6g rad at t = %.4f s (q_u = %.6f rad, ratio %.4f)\n", r.theta_max, r.t_theta_max,
              r.theta_u, r.theta_max / r.theta_u);
  std::printf("  d_control      = %.6g m (dk0 = %.6g m), d* = %.6g m (d_SLV = %.6g m)\n", d_control, k.dk0, d_star,
              k.d_SLV);
  std::printf("  impacts        = %ld\n", r.impacts);
  std::printf("  overturned     = %s\n", r.overturned ? "yes" : "no");
  std::printf("  energy D/C     = %.4f\n", r.dc);
  std::printf("  termination    = %s (%ld steps)\n", to_string(r.termination), r.steps);
  std::printf("  end            = %s at t = %.4f s (motion %.4f s, free motion cap %g s)\n", to_string(r.end), r.t_end,
              r.motion_duration, a.tail);
}

}  // namespace

void add_case_dynamic_command(CLI::App& app) {
  auto a = std::make_shared<CaseDynamicArgs>();
  auto* cmd = app.add_subcommand("dynamic",
                                 "Non-linear dynamics of a case file's mechanism (any 1-DOF chain, at ground level or "
                                 "at height) under one record");
  cmd->add_option("case", a->file, "case file (JSON, see docs/user/case-file.md)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--record", a->record, "accelerogram file (PEER AT2, ESM/ITACA ASCII, .cor.acc; plain with --dt)")
      ->required();
  with_rule(cmd->add_option("--dt", a->dt, "time step of a plain record file (s)"), record_dt_rule);
  cmd->add_option("--unit", a->unit, "unit of a plain record file: g, m/s^2, cm/s^2 (default g)");
  with_rule(cmd->add_option("--scale", a->scale, "factor on the record (default 1)"), limits::option::scale);
  cmd->add_flag("--reverse", a->reverse, "flip the record's polarity");
  cmd->add_flag("--floor-record", a->floor, "the record is the floor motion at the mechanism's base (not filtered)");
  cmd->add_option("--model", a->model, "smooth or rigid (default: the case's /dynamic/model, else rigid)");
  with_rule(cmd->add_option("--k", a->k_kN, "Winkler modulus (kN/m^3), smooth model"), limits::option::winkler_k_kN_m3);
  cmd->add_option("--restitution", a->restitution,
                  "VALUE (chains: in [-1, 0]) | housner | one-sided-theory | none (one block)");
  cmd->add_option("--history", a->history, "write t, q, q' to this CSV file");
  cmd->add_flag("--json", a->json, "print the results as one JSON object");
  cmd->add_option("--stepper", a->stepper, "rk8pd (default), rkck or rkf45");
  with_rule(cmd->add_option("--rtol", a->rtol, "relative tolerance per step (default 1e-7)"), limits::option::rel_tol);
  with_rule(cmd->add_option("--atol", a->atol, "absolute tolerance per step, rad and rad/s (default 1e-9)"),
            limits::option::abs_tol);
  with_rule(cmd->add_option("--tail", a->tail, "cap on the free motion after the whole record (s, default 30): it ends earlier at rest or when the energy left cannot reach the peak"), limits::option::tail_s);
  cmd->callback([a] { run_case(*a); });
}

void add_rocking_command(CLI::App& app) {
  auto args = std::make_shared<RockingArgs>();
  auto* cmd = app.add_subcommand("rocking", "Non-linear rocking of a wall under an accelerogram (rigid or smooth block)");
  cmd->add_option("--model", args->model, "smooth (Winkler foundation) or rigid (Housner)")->required();
  with_rule(cmd->add_option("--thickness", args->thickness, "full thickness 2b (m)"), rules::dimension_m)->required();
  with_rule(cmd->add_option("--height", args->height, "full height 2h (m)"), rules::dimension_m)->required();
  with_rule(cmd->add_option("--unit-weight", args->unit_weight_kN, "unit weight (kN/m^3)"), rules::unit_weight_kN_m3)
      ->required();
  with_rule(cmd->add_option("--k", args->k_kN, "Winkler modulus (kN/m^3), smooth model only"),
            limits::option::winkler_k_kN_m3);
  cmd->add_option("--restitution", args->restitution,
                  "VALUE in [-1, 1] | housner | one-sided-theory | none (default: housner, one-sided-theory if --one-sided)");
  cmd->add_flag("--one-sided", args->one_sided, "one-sided rocking (facade against transverse walls)");
  cmd->add_option("--record", args->record, "accelerogram file (PEER AT2, ESM/ITACA ASCII, .cor.acc; plain with --dt)")
      ->required();
  with_rule(cmd->add_option("--dt", args->dt, "time step of a plain record file (s)"), record_dt_rule);
  cmd->add_option("--unit", args->unit, "unit of a plain record file: g, m/s^2, cm/s^2 (default g)");
  with_rule(cmd->add_option("--scale", args->scale, "factor on the record (default 1)"), limits::option::scale);
  cmd->add_flag("--reverse", args->reverse, "flip the record's polarity");
  cmd->add_option("--overturn-at", args->overturn_at, "theta_u (default) or half_pi");
  cmd->add_option("--history", args->history, "write t, theta, theta' to this CSV file");
  cmd->add_flag("--json", args->json, "print the results as one JSON object");
  cmd->add_option("--stepper", args->stepper, "rk8pd (default), rkck or rkf45");
  with_rule(cmd->add_option("--rtol", args->rtol, "relative tolerance per step (default 1e-7)"), limits::option::rel_tol);
  with_rule(cmd->add_option("--atol", args->atol, "absolute tolerance per step, rad and rad/s (default 1e-9)"),
            limits::option::abs_tol);
  with_rule(cmd->add_option("--tail", args->tail, "cap on the free motion after the whole record (s, default 30): it ends earlier at rest or when the energy left cannot reach the peak"), limits::option::tail_s);
  cmd->callback([args, cmd] {
    args->dt_given = cmd->count("--dt") > 0;
    run(*args);
  });
}

}  // namespace assess::cli

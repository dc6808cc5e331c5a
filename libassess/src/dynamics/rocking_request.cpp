// rocking_request.cpp: the options of one rocking analysis checked and turned
// into a model, a record and analysis options (dynamics/rocking_request.hpp);
// moved here from the command line (apps/cmd_rocking.cpp) for issue 40, so
// that the Python module shares them.
#include "assess/dynamics/rocking_request.hpp"

#include "assess/dynamics/analysis_limits.hpp"
#include "assess/records/record_io.hpp"
#include "assess/support/error.hpp"
#include "assess/support/number_rules.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace assess {
namespace {

// An option obeying its rule (analysis_limits.hpp, number_rules.hpp), else
// the command line's own message: "--scale: value 0 out of range: ...".
void check_rule(const char* option, double v, const NumberRule& rule) {
  const std::string bad = number_rule_violation(v, rule);
  if (!bad.empty()) throw InputError(std::string(option) + ": " + bad);
}

// A plain record: --dt (and --unit, default g) for one column; --unit alone
// for two columns (time, acceleration), dt read from the time column (the
// same readers as the case files' {"file", "dt", "unit"}); values in memory
// with dt (and unit, default g).
Record request_record(const RockingRequest& a) {
  if (a.values) {
    if (!a.dt) throw InputError("--dt: the time step (s) of the record's values is required");
    return make_plain_record(a.values->data, a.values->size, *a.dt,
                             parse_acceleration_unit(a.unit.empty() ? "g" : a.unit), a.record);
  }
  if (a.dt) return read_plain_record(a.record, *a.dt, parse_acceleration_unit(a.unit.empty() ? "g" : a.unit));
  if (a.unit.empty()) return read_record(a.record);
  // --unit without --dt: a plain file of two columns (time in s,
  // acceleration); the reader names the file, the line and what is wrong
  // (a decreasing time is the file's fault, not --unit's). A record file
  // with a header (AT2, ESM, .cor.acc) gives its own unit: --unit is wrong.
  try {
    return read_plain_record(a.record, parse_acceleration_unit(a.unit));
  } catch (const InputError& plain) {
    std::string format;
    try {
      format = read_record(a.record).format;
    } catch (const InputError&) {
      throw plain;
    }
    throw InputError("--unit applies only to a plain record file: " + a.record + " is a " + format +
                     " record, whose header gives the unit and the time step (leave --unit out)");
  }
}

}  // namespace

Restitution parse_restitution_option(const std::string& text, bool one_sided) {
  if (text.empty()) return one_sided ? Restitution::one_sided_theory() : Restitution::housner();
  if (text == "housner") return Restitution::housner();
  if (text == "one-sided-theory") return Restitution::one_sided_theory();
  if (text == "none") return Restitution::none();
  double e = 0.0;
  if (!decimal_number_violation(text, e).empty())
    throw InputError("--restitution expects a number in [-1, 1], 'housner', 'one-sided-theory' or 'none', got '" +
                     text + "'");
  return Restitution::given(e);
}

RockingModel rocking_model_of(const RockingRequest& a) {
  if (a.model != "smooth" && a.model != "rigid") throw InputError("--model must be 'smooth' or 'rigid'");
  check_rule("--thickness", a.thickness, rules::dimension_m);
  check_rule("--height", a.height, rules::dimension_m);
  check_rule("--unit-weight", a.unit_weight_kN, rules::unit_weight_kN_m3);
  if (a.k_kN && a.model == "smooth") check_rule("--k", *a.k_kN, limits::option::winkler_k_kN_m3);
  const RockingBody body = RockingBody::rectangle(a.thickness, a.height, a.unit_weight_kN * units::kN);
  Foundation foundation = Foundation::rigid();
  if (a.model == "smooth") {
    if (!a.k_kN) throw InputError("--k (Winkler modulus, kN/m^3) is required for the smooth model");
    if (!(*a.k_kN > 0.0 && std::isfinite(*a.k_kN))) throw InputError("--k must be a positive number (kN/m^3)");
    foundation = Foundation::winkler(*a.k_kN * units::kN);
  } else if (a.k_kN) {
    throw InputError("--k applies only to --model smooth");
  }
  const Sidedness sided = a.one_sided ? Sidedness::one_sided : Sidedness::two_sided;
  return RockingModel(body, foundation, sided, parse_restitution_option(a.restitution, a.one_sided));
}

RockingSetup prepare_rocking(const RockingRequest& a) {
  if (a.model != "smooth" && a.model != "rigid") throw InputError("--model must be 'smooth' or 'rigid'");
  check_rule("--rtol", a.rtol, limits::option::rel_tol);
  check_rule("--atol", a.atol, limits::option::abs_tol);
  check_rule("--tail", a.tail, limits::option::tail_s);
  check_rule("--scale", a.scale, limits::option::scale);
  if (a.dt) check_rule("--dt", *a.dt, record_dt_rule);
  RockingModel model = rocking_model_of(a);
  Record record = request_record(a);
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
  opt.record_history = a.history;
  return RockingSetup{std::move(model), std::move(record), opt};
}

RockingResult run_rocking(const RockingSetup& s) {
  RockingResult r = analyse(s.model, s.record, s.options);
  // A failed analysis is reported as a failure, never with its numbers as a result.
  if (!succeeded(r))
    throw InputError(std::string("the analysis failed (termination ") + to_string(r.termination) + " at t = " +
                     std::to_string(r.t_end) + " s): " + r.message + "; no result is reported");
  return r;
}

}  // namespace assess

// rocking_analysis.hpp: time-history analysis of a rocking wall under a
// ground motion (record or function), with exact event handling, and its
// results (peak rotation, impacts, overturning, energy demand/capacity).
#pragma once

#include "assess/dynamics/analysis_end.hpp"
#include "assess/records/ground_motion.hpp"
#include "assess/dynamics/hybrid_ode.hpp"
#include "assess/records/record.hpp"
#include "assess/dynamics/rocking_model.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// When the wall is declared overturned.
enum class OverturnCriterion {
  theta_u,  ///< |theta| reaches theta_u, where the net restoring moment vanishes (seed's ultimate rotation; default)
  half_pi   ///< |theta| reaches pi/2
};

/// Settings of a rocking analysis, with documented defaults.
struct RockingOptions {
  OdeStepper stepper = OdeStepper::rk8pd;  ///< GSL stepper (default rk8pd)
  /// Relative and absolute (rad, rad/s) local error tolerances per step.
  /// Defaults 1e-7 / 1e-9: with one rk8pd step per record sample they meet a
  /// 1e-4 relative accuracy of theta_max with the fewest steps (bench/bench_rocking.cpp).
  double rel_tol = 1e-7;
  double abs_tol = 1e-9;
  double event_time_tol = 1e-12;  ///< bracket width of located events (s; default 1e-12)
  OverturnCriterion overturn = OverturnCriterion::theta_u;  ///< default theta_u
  double scale = 1.0;     ///< factor on the record (record overload only; default 1)
  bool reverse = false;   ///< flip the record's polarity (record overload only; default false)
  /// Cap on the free motion after the end of the excitation (s; default 30):
  /// the free motion ends earlier when the body is at rest or its energy has
  /// decayed (analysis_end.hpp). The one default of every front end.
  double tail_s = 30.0;
  bool record_history = false;  ///< keep theta(t), theta'(t) (default false)
  /// Rest (Zeno) criterion: after an impact, if |theta'+| < rest_velocity and the
  /// excitation cannot lift the body, it comes to rest on its base (rad/s; default 1e-6).
  double rest_velocity = 1e-6;
  long max_steps = 50'000'000;  ///< limit on integrator steps (default 5e7)
  long max_events = 10'000'000; ///< limit on events (impacts, branch switches; default 1e7)
  /// @throws InputError naming the invalid field and its unit
  void validate() const;
};

enum class RockingTermination { completed, overturned, step_limit, event_limit, integrator_error };
const char* to_string(RockingTermination t);

/// theta(t), theta'(t) at every step end, and before and after every jump.
struct RockingHistory {
  std::vector<double> t;      ///< s
  std::vector<double> theta;  ///< rad
  std::vector<double> omega;  ///< rad/s
};

/// One tie level's outcome in a tied analysis (dynamics/tied_rocking.hpp).
struct TiedLevelResult {
  double max_force = 0.0;           ///< largest force (N/m for a body, N for a chain)
  double max_elongation = 0.0;      ///< largest elongation e (m)
  bool yielded = false;             ///< a ductile level yielded (snervata)
  double plastic_elongation = 0.0;  ///< e_p at the end (m)
  double plastic_energy = 0.0;      ///< T_y e_p (J/m for a body, J for a chain)
  /// Issue 29: the level broke (its force lost from then on): a level that is
  /// not ductile when its force reached its strength (rottura of its weakest
  /// component), a ductile one when its elongation reached its ultimate.
  bool broken = false;
  bool broken_by_elongation = false;  ///< a ductile rod at its ultimate elongation
  double t_broken = 0.0;              ///< s
};

/// Outcome of one analysis (SI units).
struct RockingResult {
  double theta_max = 0.0;     ///< peak |theta| (rad)
  double t_theta_max = 0.0;   ///< its time (s)
  int theta_max_side = +1;    ///< +1 outward, -1 inward
  double theta_u = 0.0;       ///< ultimate rotation on the side of the peak (rad)
  std::optional<double> theta_cr;  ///< end of full contact (rad); none for a rigid base
  double alpha = 0.0;         ///< slenderness (rad)
  std::optional<double> restitution;  ///< coefficient used; none if no impact law
  bool overturned = false;
  std::optional<double> t_overturn;     ///< s
  double kinetic_energy_overturn = 0.0; ///< 1/2 I0 theta'^2 at the last outward passage of theta_u before collapse (J/m)
  long impacts = 0;           ///< crossings of theta = 0 (impacts when a restitution applies)
  double energy_demand = 0.0; ///< seed §3.2: area under M(theta) up to theta_max, or capacity + kinetic energy (J/m)
  double capacity = 0.0;      ///< area under M(theta) up to theta_u on the side of the peak (J/m)
  double dc = 0.0;            ///< energy_demand / capacity
  double d_max = 0.0;         ///< peak horizontal displacement of the centroid (control point, m), Circ. 2019 C8.7.1.2.1.9
  RockingTermination termination = RockingTermination::completed;
  std::string message;
  double t_end = 0.0;         ///< time reached (s)
  double motion_duration = 0.0;  ///< duration of the excitation, integrated to its last sample (s)
  AnalysisEnd end = AnalysisEnd::free_motion_cap;  ///< why the analysis ended (analysis_end.hpp)
  long steps = 0, rejected_steps = 0, event_steps = 0, rhs_evaluations = 0;
  RockingHistory history;     ///< filled if RockingOptions::record_history
  /// A wall held by tie rods (dynamics/tied_rocking.hpp): each level's
  /// outcome, in the order of the levels; empty for an analysis without ties.
  std::vector<TiedLevelResult> ties;

  /// One-line summary.
  std::string brief_report() const;
};

/// Initial condition (rad, rad/s); (0, 0) means at rest on the base.
struct RockingInitialState {
  double theta = 0.0;
  double omega = 0.0;
};

/// Marks a completed or overturned result that cannot be true as a failure
/// (termination integrator_error, with a message): a non-finite peak, energy
/// or displacement, or a peak beyond the rotation that stops the analysis
/// (theta_u, or pi/2 with OverturnCriterion::half_pi). Called by analyse();
/// public for front ends that build results otherwise, and for tests.
void flag_untrustworthy(const RockingModel& model, const RockingOptions& options, RockingResult& result);

/// True if the result is one to report (completed or overturned); any other
/// termination (step_limit, event_limit, integrator_error) is a failed analysis.
inline bool succeeded(const RockingResult& r) {
  return r.termination == RockingTermination::completed || r.termination == RockingTermination::overturned;
}

/// Analysis under a record (scaled and polarity-flipped as in options).
RockingResult analyse(const RockingModel& model, const Record& record, const RockingOptions& options);
/// Analysis under a ground motion (options.scale/reverse are not applied) from an initial state.
/// @throws InputError for invalid options (analysis_limits.hpp) and for a
///   Winkler modulus the integration cannot resolve: k > 1e9 kN/m^3, or
///   theta_cr < 10 abs_tol (docs/theory/rocking.md, "Upper bound on k").
RockingResult analyse(const RockingModel& model, const GroundMotion& motion, const RockingOptions& options,
                      const RockingInitialState& initial = {});
/// Free rocking from an initial state for duration_s (s): options.tail_s is
/// not added (the duration is the free motion), the end rule applies.
RockingResult analyse_free(const RockingModel& model, const RockingInitialState& initial, double duration_s,
                           const RockingOptions& options);

}  // namespace assess

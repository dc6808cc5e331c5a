// rocking_request.hpp: one rocking analysis of a wall as the front ends ask
// for it (`assess rocking`, the Python module's assess.rocking): the options
// in their units (m, kN/m^3, the record's file or its values held in
// memory), checked against analysis_limits.hpp with the command line's
// messages (they name its options, "--k", "--scale"), and the model, record
// and analysis options they give. One place, so that both front ends refuse
// the same input with the same words and analyse the same wall.
#pragma once

#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/dynamics/rocking_model.hpp"
#include "assess/records/record.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The options of `assess rocking` (docs/user/rocking.md), with its defaults.
struct RockingRequest {
  std::string model;                ///< "smooth" (Winkler foundation) or "rigid" (Housner)
  double thickness = 0.0;           ///< full thickness 2b (m)
  double height = 0.0;              ///< full height 2h (m)
  double unit_weight_kN = 0.0;      ///< unit weight (kN/m^3)
  std::optional<double> k_kN;       ///< Winkler modulus (kN/m^3), smooth model only
  /// "" (housner, or one-sided-theory when one_sided), "housner",
  /// "one-sided-theory", "none" or a number in [-1, 1].
  std::string restitution;
  bool one_sided = false;           ///< one-sided rocking (a façade against its side walls)
  /// The record's file (PEER AT2, ESM/ITACA ASCII, .cor.acc; plain with dt
  /// or unit); with `values`, the name the record's messages give it.
  std::string record;
  /// The record's samples held in memory (`size` values at `data`, in
  /// `unit`, default g), at time step `dt` (required with them); copied by
  /// prepare_rocking, so they need to live only until it returns (the
  /// Python module's numpy array, without a copy of its own); none: read `record`.
  struct Values {
    const double* data = nullptr;
    std::size_t size = 0;
  };
  std::optional<Values> values;
  std::optional<double> dt;         ///< time step of a plain record or of `values` (s)
  std::string unit;                 ///< unit of a plain record or of `values`: g, m/s^2, cm/s^2 ("" = g)
  double scale = 1.0;               ///< factor on the record (-, in (0, 100])
  bool reverse = false;             ///< flip the record's polarity
  std::string overturn_at = "theta_u";  ///< "theta_u" or "half_pi"
  std::string stepper = "rk8pd";    ///< "rk8pd", "rkck" or "rkf45"
  double rtol = RockingOptions{}.rel_tol;  ///< relative tolerance per step (-)
  double atol = RockingOptions{}.abs_tol;  ///< absolute tolerance per step (rad, rad/s)
  double tail = RockingOptions{}.tail_s;   ///< cap on the free motion after the record (s)
  bool history = false;             ///< keep theta(t), theta'(t)
};

/// What a request gives: the wall's model, its record (unscaled, in m/s^2)
/// and the analysis options (scale, polarity, tolerances, history).
struct RockingSetup {
  RockingModel model;
  Record record;
  RockingOptions options;
};

/// The restitution of --restitution: "" gives housner (one_sided:
/// one-sided-theory). @throws InputError naming --restitution
Restitution parse_restitution_option(const std::string& text, bool one_sided);

/// The wall's model of the request (model, thickness, height, unit weight,
/// k, sidedness, restitution), checked; the record and the analysis options
/// are not looked at (the Python module's assess.RockingModel).
/// @throws InputError naming the option, what was expected and its unit
RockingModel rocking_model_of(const RockingRequest& request);

/// Checks the request, builds the model and reads (or takes) the record.
/// @throws InputError naming the option, what was expected and its unit, or
///   the record file and line (record_io.hpp)
RockingSetup prepare_rocking(const RockingRequest& request);

/// analyse(setup.model, setup.record, setup.options), refusing a failed
/// analysis: a result that is not a result is an error, never numbers
/// (InputError "the analysis failed (termination ... at t = ... s): ...").
RockingResult run_rocking(const RockingSetup& setup);

}  // namespace assess

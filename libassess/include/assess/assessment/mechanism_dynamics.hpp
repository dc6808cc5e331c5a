// mechanism_dynamics.hpp: the dynamic model of a case file's mechanism and
// the motion at its base (issue 13; docs/theory/chain-dynamics.md):
//  - a chain that rotates as one body about one ground hinge: the rocking
//    model (seed Eq. 1; the specialised path, identical to the chain model to
//    1e-10, tests/numeric/chain_dynamics.cpp);
//  - any other 1-DOF chain (vertical flexure, storeys above a hinge, wedges,
//    explicit chains): the chain model (ChainDynamics), one-sided;
//  - at height Z > 0 the ground records are filtered to the floor by the
//    building's first mode (a_Z = ug'' + gamma psi(Z) ur'', records/floor_motion),
//    unless the records are floor motions ("input": "floor").
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/dynamic_case.hpp"
#include "assess/dynamics/chain_analysis.hpp"
#include "assess/dynamics/rocking_from_chain.hpp"
#include "assess/records/floor_motion.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace assess {

struct MechanismDynamics {
  bool applies = false;                           ///< false: `note` says why the model cannot represent the chain
  std::string note;
  std::optional<ChainRockingBody> body;           ///< one rotating body: the rocking body
  std::vector<RockingModel> rocking;              ///< one rotating body: a model per restitution value
  std::shared_ptr<const ChainDynamics> chain;     ///< otherwise: the chain model
  std::vector<double> e;                          ///< coefficient per restitution value (velocity ratio)
  Sidedness sidedness = Sidedness::one_sided;     ///< chain: two-sided only if mirror-symmetric
  double length = 1.0;                            ///< out-of-plane length energies are divided by (m)
  double Z = 0.0;                                 ///< height of the mechanism's base (m)
  bool floor_input = false;                       ///< the records are floor motions as given
  std::optional<FloorFilter> filter;              ///< first-mode filter applied to ground records (Z > 0)
  double filter_damping_pct = 0.0;                ///< its damping (%)

  bool single_body() const { return body.has_value(); }
  /// The motion at the mechanism's base from a ground record (the record itself
  /// at ground level or for floor input).
  Record input(const Record& record) const { return filter ? floor_motion(record, *filter) : record; }
  /// Analysis `ie` (restitution index) under an input motion (options.scale/reverse applied).
  RockingResult analyse(std::size_t ie, const Record& input, const RockingOptions& options) const;
  /// Peak horizontal displacement (m, magnitude) of the kinematic control point for a peak
  /// coordinate q (rad; signed: q < 0 inward, two-sided).
  double control_displacement(const KinematicResult& kin, double q) const;
  /// Ultimate coordinate (rad) and energy capacity per unit length (J/m) of the outward side.
  double q_u() const;
  double capacity() const;
  /// Net restoring moment (single body, N m/m) or generalised force per unit length (N m/m) at q.
  double restoring(double q) const;
  /// One line: "rocking body ..." or "chain of N blocks ...", the input motion.
  std::string describe() const;
};

/// Builds the model of `chain` (candidate `cand` of `kase`) for the dynamic
/// section `d`. Errors name the case file and the JSON path (a two-sided or
/// "housner"/"one-sided-theory" request for a multi-block chain, a missing
/// building at height). A chain the dynamic model cannot represent (friction
/// loads, a locking chain, a Winkler bed under several ground hinges) gives
/// applies = false and the reason in `note`.
MechanismDynamics build_mechanism_dynamics(const CaseFile& kase, const CandidateResult& cand, const Chain& chain,
                                           const DynamicSpec& d);

}  // namespace assess

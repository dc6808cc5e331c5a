// mechanism_dynamics.hpp: the dynamic model of a case file's mechanism and
// the motion at its base (issue 13; docs/theory/chain-dynamics.md):
//  - a chain that rotates as one body about one ground hinge: the rocking
//    model (seed Eq. 1; the specialised path, identical to the chain model to
//    1e-10, tests/numeric/chain_dynamics.cpp);
//  - any other 1-DOF chain (vertical flexure, storeys above a hinge, wedges,
//    explicit chains): the chain model (ChainDynamics), one-sided;
//  - a mechanism held by tie rods (issue 23; the case's "ties", or a
//    design's): the same model with each level as a one-sided elastic-
//    perfectly-plastic restraint (dynamics/tied_rocking.hpp), one-sided only;
//  - at height Z > 0 the ground records are filtered to the floor by the
//    building's first mode (a_Z = ug'' + gamma psi(Z) ur'', records/floor_motion),
//    unless the records are floor motions ("input": "floor").
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/dynamic_case.hpp"
#include "assess/dynamics/chain_analysis.hpp"
#include "assess/dynamics/rocking_from_chain.hpp"
#include "assess/dynamics/tied_rocking.hpp"
#include "assess/records/floor_motion.hpp"
#include "assess/support/note.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace assess {

/// A tie level holding the mechanism in the dynamic analysis (issue 23).
struct DynamicTie {
  TieRestraint level;              ///< the whole level on the chain (N, N/m; kinematic result's TieWork::tie),
                                   ///< with its ductility and failure elongation (issue 29)
  double per_tie = 1.0;            ///< factor turning the analysis' forces and energies into one tie's (-)
  std::optional<Tie> tie;          ///< the tie of the same name (its components, for the report)
};

struct MechanismDynamics {
  bool applies = false;                           ///< false: `note` says why the model cannot represent the chain
  NoteText note;
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
  /// Tie levels holding the mechanism (empty: none); for one body, the same
  /// levels per unit depth about its hinge (body_ties).
  std::vector<DynamicTie> ties;
  std::vector<RockingTie> body_ties;
  /// The tied wall's restoring moment with the ties at their strength, its
  /// collapse rotation and energy capacity (dynamics/tied_rocking.hpp); tied only.
  std::optional<TiedEnvelope> tied_envelope;

  bool tied() const { return !ties.empty(); }
  /// The same model held by `levels` instead (none: the bare mechanism).
  /// applies = false, with the reason, when the tied analysis cannot represent
  /// it (two-sided rocking).
  MechanismDynamics with_ties(std::vector<DynamicTie> levels) const;
  /// True if a tie level of the analysis broke (issue 29): a level that is not
  /// ductile reached its strength, or a ductile rod its ultimate elongation.
  bool ruptured(const RockingResult& r) const;

  bool single_body() const { return body.has_value(); }
  /// The motion at the mechanism's base from a ground record (the record itself
  /// at ground level or for floor input).
  Record input(const Record& record) const { return filter ? floor_motion(record, *filter) : record; }
  /// Analysis `ie` (restitution index) under an input motion (options.scale/reverse applied).
  RockingResult analyse(std::size_t ie, const Record& input, const RockingOptions& options) const;
  /// Peak horizontal displacement (m, magnitude) of the kinematic control point for a peak
  /// coordinate q (rad; signed: q < 0 inward, two-sided).
  double control_displacement(const KinematicResult& kin, double q) const;
  /// Ultimate coordinate (rad) and energy capacity per unit length (J/m) of the
  /// outward side (held by ties: the collapse rotation and the capacity on the envelope).
  double q_u() const;
  double capacity() const;
  /// Net restoring moment (single body, N m/m) or generalised force per unit
  /// length (N m/m) at q (held by ties: on the envelope, q in [0, q_u]).
  double restoring(double q) const;
  /// One line, as data (note.hpp): "rocking body ..." or "chain of N blocks ...", the input motion.
  NoteText describe() const;
};

/// The tie levels of a kinematic candidate (`cand.result.ties`) as the model
/// `md` of its chain holds them: per-tie factors for one body (per metre of
/// wall) or a chain (whole level), with the tie of the same name in `ties`.
std::vector<DynamicTie> dynamic_ties(const MechanismDynamics& md, const CandidateResult& cand,
                                     const std::vector<Tie>& ties);

/// Builds the model of `chain` (candidate `cand` of `kase`) for the dynamic
/// section `d`. Errors name the case file and the JSON path (a two-sided or
/// "housner"/"one-sided-theory" request for a multi-block chain, a missing
/// building at height). A chain the dynamic model cannot represent (friction
/// loads, a locking chain, a Winkler bed under several ground hinges) gives
/// applies = false and the reason in `note`. The tie levels of the candidate
/// (`cand.result.ties`, the case's "ties") hold the model; their rods'
/// ultimate elongation comes from the case's ties of the same name.
MechanismDynamics build_mechanism_dynamics(const CaseFile& kase, const CandidateResult& cand, const Chain& chain,
                                           const DynamicSpec& d);

}  // namespace assess

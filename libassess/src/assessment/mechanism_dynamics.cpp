// mechanism_dynamics.cpp: the dynamic model of a case's mechanism (rocking
// body or chain) and its base motion (ground, filtered floor, given floor).
//
// Notation: Z height of the mechanism's base (m, the candidate's constraint
// height, CheckInput::Z); H, N, T1, xi_1 building height (m), storeys, first
// period (s) and damping (%); gamma = 3N/(2N+1), psi = Z/H [C7.2.10]
// (code_rules); e restitution (velocity ratio).
#include "assess/assessment/mechanism_dynamics.hpp"

#include "assess/kinematic/code_rules.hpp"
#include "assess/kinematic/tie_checks.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <cstdio>

namespace assess {

namespace {

// Where a value was given, for an error: "<file>: /dynamic/k" for a JSON path
// of the case, the option itself ("--k") when the command line replaced it.
std::string given_at(const std::string& file, const std::string& from) {
  return !from.empty() && from[0] == '/' ? file + ": " + from : from;
}
std::string restitution_at(const std::string& file, const DynamicSpec& d, std::size_t i) {
  return d.restitution_from.empty() || d.restitution_from[0] != '/' ? d.restitution_from
                                                                   : given_at(file, d.restitution_from) + "/" + std::to_string(i);
}


// Where the sidedness a restitution is checked against comes from (issue 31:
// a two-sided override in a building's wall was reported at restitution/0
// alone): "<file>: /dynamic/sidedness" when given, which the building reader
// maps to the wall or mechanism that wrote it.
std::string sidedness_note(const std::string& file, const DynamicSpec& d) {
  if (d.sidedness == Sidedness::two_sided) return " (sidedness two-sided, " + file + ": /dynamic/sidedness)";
  return " (sidedness one-sided, the default of /dynamic/sidedness)";
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The tie levels on the chain (whole levels, N and N/m).
std::vector<TieRestraint> chain_levels(const std::vector<DynamicTie>& ties) {
  std::vector<TieRestraint> levels;
  for (const DynamicTie& t : ties) levels.push_back(t.level);
  return levels;
}

// " held by n tie levels (...)", of one body or of a chain (the words agree in Italian).
Note held_by(bool body, std::size_t n) {
  const std::string id = std::string(body ? "dyn.body_held" : "dyn.chain_held") + (n == 1 ? "_one" : "");
  return n == 1 ? Note{id, {}} : Note{id, {count_arg(n)}};
}

}  // namespace

RockingResult MechanismDynamics::analyse(std::size_t ie, const Record& in, const RockingOptions& options) const {
  if (tied()) {
    if (body) return analyse_tied(rocking.at(ie), body_ties, in, options);
    return analyse_tied(*chain, chain_levels(ties), e.at(ie), in, options);
  }
  if (body) return assess::analyse(rocking.at(ie), in, options);
  return analyse_chain(*chain, in, options, e.at(ie), sidedness);
}

MechanismDynamics MechanismDynamics::with_ties(std::vector<DynamicTie> levels) const {
  MechanismDynamics m = *this;
  m.ties = std::move(levels);
  m.body_ties.clear();
  m.tied_envelope.reset();
  if (m.ties.empty()) return m;
  if (sidedness != Sidedness::one_sided) {
    m.applies = false;
    m.note = {{"dyn.na_tied_two_sided", {}}};
    return m;
  }
  if (body) {
    // One body per unit depth of wall, about its ground hinge.
    for (const DynamicTie& t : m.ties) {
      const TieRestraint& r = t.level;
      RockingTie tie;
      tie.point = r.point - body->hinge;
      tie.direction = r.direction;
      tie.stiffness = r.stiffness / body->length;
      tie.capacity = r.capacity / body->length;
      tie.pretension = std::min(r.pretension, r.capacity) / body->length;
      tie.ductile = r.ductile;
      tie.ultimate_elongation = r.ultimate_elongation;
      m.body_ties.push_back(tie);
    }
    m.tied_envelope = assess::tied_envelope(rocking.front(), m.body_ties);
  } else {
    m.tied_envelope = assess::tied_envelope(*chain, chain_levels(m.ties));
  }
  return m;
}

bool MechanismDynamics::ruptured(const RockingResult& r) const {
  for (const TiedLevelResult& x : r.ties)
    if (x.broken) return true;
  return false;
}

double MechanismDynamics::control_displacement(const KinematicResult& kin, double q) const {
  if (body) return std::fabs(body->horizontal_displacement(kin.control_point, std::fabs(q)));
  return std::fabs(chain->horizontal_displacement(kin.control_block, kin.control_point, q));
}

double MechanismDynamics::q_u() const {
  if (tied_envelope) return tied_envelope->theta_collapse;
  return body ? rocking.front().theta_u(+1) : chain->q_u();
}

double MechanismDynamics::capacity() const {
  if (tied_envelope) return tied_envelope->capacity / (body ? 1.0 : length);
  return body ? rocking.front().capacity() : chain->capacity() / length;
}

double MechanismDynamics::restoring(double q) const {
  if (tied_envelope) {  // linear on the envelope's evenly spaced samples
    const TiedEnvelope& E = *tied_envelope;
    const double n = double(E.theta.size() - 1), x = std::min(std::max(q / E.theta_collapse * n, 0.0), n);
    const std::size_t i = std::min(static_cast<std::size_t>(x), E.theta.size() - 2);
    return (E.restoring[i] + (x - double(i)) * (E.restoring[i + 1] - E.restoring[i])) / (body ? 1.0 : length);
  }
  if (body) return rocking.front().restoring_moment(q) - body->body.M_ext;
  return chain->net_restoring(q) / length;
}

NoteText MechanismDynamics::describe() const {
  NoteText s;
  const bool two = sidedness == Sidedness::two_sided;
  if (body) {
    s.push_back({"dyn.body", {}});
  } else {
    const NoteArg q_u_rad = number_arg(chain->q_u(), 5, "rad");
    const std::size_t n = chain->chain().blocks().size();
    if (n == 1)  // issue 33: a roof thrust, its moment exact at every rotation
      s.push_back({two ? "dyn.thrust_two" : "dyn.thrust_one", {q_u_rad}});
    else  // the reference block by its name in the case ("block 'lower'": the report names the catalogue's blocks)
      s.push_back({two ? "dyn.chain_two" : "dyn.chain_one",
                   {count_arg(n),
                    generated_arg("block '" + chain->chain().blocks()[std::size_t(chain->reference_block())].name + "'"),
                    q_u_rad}});
  }
  if (tied()) s.push_back(held_by(static_cast<bool>(body), ties.size()));
  if (Z > 0.0 || floor_input) {
    if (floor_input)
      s.push_back({"dyn.floor_given", {number_arg(Z, 2, "m")}});
    else
      s.push_back({"dyn.floor_filter", {number_arg(Z, 2, "m"), number_arg(filter->T1, 3, "s"),
                                        number_arg(filter_damping_pct, -3, "%"), number_arg(filter->gamma_psi, 4)}});
  }
  return s;
}

namespace {

MechanismDynamics build_bare(const CaseFile& kase, const CandidateResult& cand, const Chain& chain,
                             const DynamicSpec& d) {
  MechanismDynamics m;
  const std::string& file = kase.file;
  // Issue 33: the mechanisms the 1-DOF rocking equation does not describe
  // (docs/theory/mechanisms.md §1.5, §2.4).
  if (chain.plan()) {
    m.note = {{"dyn.na_plan", {}}};
    return m;
  }
  for (const Load& l : chain.loads())
    if (l.type == LoadType::Friction) {
      m.note = {{"dyn.na_friction", {}}};
      return m;
    }
  // Issue 33: a roof thrust's moment about the hinge varies with the rotation,
  // P_H (H_P cos q + e sin q); the rocking body holds a constant external
  // moment, the chain model the exact one: a roof_thrust mechanism uses it.
  const bool exact_forces = kase.mechanism.type == "roof_thrust";
  m.Z = cand.Z;
  m.floor_input = d.floor_input;
  m.sidedness = d.sidedness;
  if (m.Z > 0.0 && !d.floor_input) {
    if (!kase.building)
      throw InputError(file + ": /building: missing: the mechanism is at height (Z = " + fmt("%.2f", m.Z) +
                       " m) and its records are ground motions; the floor-motion filter needs the building "
                       "(\"height_m\", \"storeys\", optionally \"T1_s\"), or give floor motions with "
                       "/dynamic/input \"floor\"");
    const BuildingModel& b = *kase.building;
    FloorFilter f;
    f.T1 = d.filter_T1.value_or(b.T1);
    m.filter_damping_pct = d.filter_damping_pct.value_or(b.damping_pct);
    f.xi = m.filter_damping_pct / 100.0;
    // [C7.2.10]: gamma1 = 3N/(2N+1), psi1(Z) = Z/H.
    f.gamma_psi = code_rules::gamma_first_mode(b.storeys) * code_rules::psi_first_mode(std::min(m.Z, b.H), b.H);
    m.filter = f;
  }
  const Foundation found = d.smooth ? Foundation::winkler(d.k) : Foundation::rigid();

  // One rotating body: the rocking model (specialised path).
  std::optional<ChainRockingBody> body;
  try {
    body = rocking_body_from_chain(chain);
  } catch (const InputError&) {
    body.reset();  // not one body (or a carried mass the rocking body cannot hold): the chain model
  }
  std::vector<double> body_e;  // a one-body chain (roof thrust): the rocking laws' coefficients
  if (body && exact_forces) {
    for (std::size_t i = 0; i < d.restitutions.size(); ++i) {
      try {
        body_e.push_back(RockingModel(body->body, found, d.sidedness, d.restitutions[i]).restitution());
      } catch (const InputError& e) {
        throw InputError(restitution_at(file, d, i) + ": " + e.what());
      }
    }
    body.reset();
  }
  if (body) {
    for (std::size_t i = 0; i < d.restitutions.size(); ++i) {
      try {
        m.rocking.emplace_back(body->body, found, d.sidedness, d.restitutions[i]);
      } catch (const InputError& e) {
        throw InputError(restitution_at(file, d, i) + ": " + e.what() + sidedness_note(file, d));
      }
      m.e.push_back(m.rocking.back().restitution());
    }
    m.body = body;
    m.length = body->length;
    m.applies = true;
    return m;
  }

  // A multi-block chain: given coefficients; two-sided only if mirror-symmetric (checked below).
  const bool two = d.sidedness == Sidedness::two_sided;
  if (!body_e.empty()) {
    m.e = body_e;
  } else if (!d.restitution_given)
    throw InputError(file + ": /dynamic/restitution: missing: a chain of several blocks needs a given coefficient "
                     "(q'+ = e q'- at q = 0: in [-1, 0] one-sided, 0 stops the chain; in [0, 1] two-sided); the "
                     "laws \"housner\" and \"one-sided-theory\" are derived for one block");
  for (std::size_t i = 0; i < d.restitutions.size() && body_e.empty(); ++i) {
    const Restitution& r = d.restitutions[i];
    const std::string path = d.restitutions.size() > 1 ? restitution_at(file, d, i) : given_at(file, d.restitution_from);
    if (r.kind != Restitution::Kind::value)
      throw InputError(path + ": a chain of several blocks needs a given coefficient (q'+ = e q'-); \"" +
                       (r.kind == Restitution::Kind::housner ? "housner" : r.kind == Restitution::Kind::none ? "none"
                                                                                                   : "one-sided-theory") +
                       "\" is derived for one block");
    if (!two && !(r.e >= -1.0 && r.e <= 0.0))
      throw InputError(path + ": expected a coefficient in [-1, 0] (-, one-sided rebound q'+ = e q'-), got " +
                       fmt("%g", r.e) + sidedness_note(file, d));
    if (two && !(r.e >= 0.0 && r.e <= 1.0))
      throw InputError(path + ": expected a coefficient in [0, 1] (-, two-sided: the chain goes through q = 0 with "
                       "q'+ = e q'-), got " + fmt("%g", r.e) + sidedness_note(file, d));
    m.e.push_back(r.e);
  }
  if (d.options.overturn != OverturnCriterion::theta_u)
    throw InputError(file + ": /dynamic/overturn_at: a chain overturns at q_u, where its net restoring force "
                     "vanishes; \"half_pi\" applies to one rocking block");
  try {
    m.chain = std::make_shared<const ChainDynamics>(chain, found);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (d.smooth && (msg.find("Winkler") != std::string::npos || msg.find("smooth") != std::string::npos))
      throw InputError(given_at(file, msg.find("modulus") != std::string::npos ? d.k_from : d.model_from) + ": " + msg);
    m.note = {{"dyn.na_chain", {generated_arg(msg)}}};
    return m;
  }
  if (two && !m.chain->symmetric())
    throw InputError(file + ": /dynamic/sidedness: \"two-sided\" needs a chain whose blocks and loads are mirror "
                     "images of themselves (the inward mechanism is then the mirror of the outward one); this "
                     "chain is not symmetric: its inward motion would open other hinges, a different mechanism; "
                     "use \"one-sided\"");
  m.length = chain.blocks()[std::size_t(m.chain->reference_block())].length;
  m.applies = true;
  return m;
}

}  // namespace

std::vector<DynamicTie> dynamic_ties(const MechanismDynamics& md, const CandidateResult& cand,
                                     const std::vector<Tie>& ties) {
  std::vector<DynamicTie> out;
  for (const TieWork& w : cand.result.ties) {
    DynamicTie t;
    t.level = w.tie;
    const double per_count = w.tie.count > 0.0 ? 1.0 / w.tie.count : 0.0;
    t.per_tie = md.single_body() ? per_count * md.body->length : per_count;
    for (const Tie& given : ties)
      if (given.name == w.tie.name) t.tie = given;
    out.push_back(t);
  }
  return out;
}

MechanismDynamics build_mechanism_dynamics(const CaseFile& kase, const CandidateResult& cand, const Chain& chain,
                                           const DynamicSpec& d) {
  MechanismDynamics m = build_bare(kase, cand, chain, d);
  if (!m.applies || cand.result.ties.empty()) return m;
  if (d.options.overturn != OverturnCriterion::theta_u)
    throw InputError(kase.file + ": /dynamic/overturn_at: a wall held by tie rods (\"ties\") collapses where its net "
                     "restoring moment with the ties at their strength vanishes; \"half_pi\" is not available with ties");
  return m.with_ties(dynamic_ties(m, cand, kase.ties));
}

}  // namespace assess

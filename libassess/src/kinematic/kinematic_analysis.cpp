// kinematic_analysis.cpp: linear and non-linear kinematic analysis of a chain
// of rigid blocks (Circ. 617/2009 C8A.4.1-C8A.4.5; Circ. 2019 [C8.7.1.1],
// [C8.7.1.3]-[C8.7.1.5], §C8.7.1.2.1.6, [C8.7.1.10]-[C8.7.1.11]).
//
// Notation (code symbol -> name here):
//   P_i, Q_j (weights whose masses take part)  -> seismic weights W (N)
//   delta_x,i, delta_y,i (virtual displacements) -> dx, dz (m per rad)
//   F_h delta_h, L_fi                          -> work_other (N m per rad)
//   alpha0      activation multiplier          -> alpha0
//   M*          participating mass (kg)        -> M_star
//   e*          participating mass fraction    -> e_star
//   a0*         spectral activation accel.     -> a0_star (m/s^2)
//   FC          confidence factor              -> FC
//   d_k, d_k0   control-point displacement, its value at alpha = 0 -> dk, dk0 (m)
//   d*, d0*     equivalent SDOF displacement   -> d_star, d0_star (m)
//   du*, ds*, as*, Ts (2008); d_SLV, d_SLC, T_SLV, T_SLC (2018)
#include "assess/kinematic/kinematic_analysis.hpp"

#include "assess/kinematic/code_rules.hpp"
#include "assess/support/error.hpp"
#include "kinematic/ground_hinge.hpp"
#include "assess/support/units.hpp"
#include "support/root_find.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace assess {

// The samples of the equilibrium path (m, Chain coordinates) and the tie
// levels' breaks along it: what the march computed, shared by every result
// derived from it (rederive_kinematic).
struct PathSamples {
  std::vector<double> dk;            // marched samples (m)
  std::vector<Eigen::VectorXd> q;    // their configurations
  std::vector<double> broken_at;     // per tie level: the d_k at which it failed (m; infinity while it holds)
  double h = 0.0;                    // the marching step (m)
  // The control displacements (m) of the path's events, whose d* follow the
  // masses' distribution (d*/d_k): each break of KinematicResult::tie_breaks,
  // and per level where it reaches its strength (infinity: never).
  std::vector<double> break_dk, strength_dk;
};

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

bool is_seismic_weight(const Load& l) {
  return (l.type == LoadType::SelfWeight || l.type == LoadType::Weight) && l.seismic;
}

// Equilibrium path of the chain, parametrised by the control displacement d_k.
// Issue 37: tie level i acts up to broken_at[i] (the d_k at which it failed;
// infinity while it holds) and is lost beyond.
struct Path {
  const Chain& chain;
  const std::vector<TieRestraint>& ties;
  int block;
  Eigen::Vector2d point;
  const PathSamples& s;

  // Configuration at control displacement d (m), from the nearest sample below.
  bool configuration(double d, Eigen::VectorXd& out) const {
    std::size_t i = 0;
    while (i + 1 < s.dk.size() && s.dk[i + 1] <= d) ++i;
    return chain.solve_configuration(block, point, d, s.q[i], out);
  }
  // The levels acting at d (those broken at or before d left out; `without`:
  // also leave out level `without`).
  std::vector<TieRestraint> acting(double d, std::size_t without = std::size_t(-1)) const {
    std::vector<TieRestraint> out;
    for (std::size_t i = 0; i < ties.size(); ++i)
      if (i != without && d <= s.broken_at[i] * (1.0 + 1e-12)) out.push_back(ties[i]);
    return out;
  }
  double alpha(double d) const {
    Eigen::VectorXd qd;
    if (!configuration(d, qd)) return std::nan("");
    return load_multiplier(chain, qd, acting(d));
  }
  // The first d_k in (lo, hi] at which level t's elongation reaches `lim` (m),
  // by bisection on the path's configurations.
  double crossing(const TieRestraint& t, double lim, double lo, double hi) const {
    Eigen::VectorXd q;
    for (int it = 0; it < 60 && hi - lo > 1e-12 * chain.size(); ++it) {
      const double mid = 0.5 * (lo + hi);
      (configuration(mid, q) && tie_elongation(chain, t, q) >= lim ? hi : lo) = mid;
    }
    return hi;
  }
};

// Elongation at which a level fails (m): a ductile one at its ultimate
// elongation, one that is not ductile at its strength; infinity for a level
// without an elastic range (rigid-plastic, or at its strength from the start,
// as in the search of required forces), which never breaks.
double failure_elongation_of(const TieRestraint& t) {
  if (!(t.stiffness > 0.0) || !(t.capacity > t.pretension)) return std::numeric_limits<double>::infinity();
  return t.failure_elongation();
}

}  // namespace

// The marched path of a result and the options its code quantities were
// derived with (kinematic_analysis.hpp).
struct MarchedPath {
  KinematicOptions options;
  std::shared_ptr<const PathSamples> samples;
  /// (d_k (m), alpha (-)) at each point of the path where the code quantities
  /// took alpha: a derivation for other options takes them from here (the
  /// same d_k gives the same alpha) instead of solving the configuration again.
  std::vector<std::pair<double, double>> alphas;
};

std::string to_string(CurveTermination t) {
  switch (t) {
    case CurveTermination::Complete: return "complete";
    case CurveTermination::NotActivated: return "not activated";
    case CurveTermination::NoZeroCrossing: return "no zero crossing";
    case CurveTermination::NewtonFailure: return "Newton failure";
  }
  return "?";
}

void KinematicOptions::validate() const {
  if (!(FC >= 1.0) || !std::isfinite(FC))
    throw InputError("confidence factor FC = " + std::to_string(FC) + ": expected >= 1");
  if (curve_points < 3)
    throw InputError("curve_points = " + std::to_string(curve_points) + ": expected >= 3");
  if (!(du_cap > 0.0)) throw InputError("du* cap: expected > 0 m");
  if (!(d_SLV_cap > 0.0)) throw InputError("d_SLV cap: expected > 0 m");
  if (!(d_SLC_cap > 0.0)) throw InputError("d_SLC cap: expected > 0 m");
  if (!(dSLV_over_d0 > 0.0 && dSLV_over_d0 < 1.0)) throw InputError("d_SLV / d0*: expected in (0, 1)");
  if (!(dSLC_over_d0 > 0.0 && dSLC_over_d0 < 1.0)) throw InputError("d_SLC / d0*: expected in (0, 1)");
  if (!(rotation_cap > 0.0)) throw InputError("rotation cap: expected > 0 rad");
}

std::vector<LoadWork> load_works(const Chain& chain, const Eigen::VectorXd& q) {
  const Eigen::VectorXd v = chain.virtual_displacement(q);
  std::vector<LoadWork> out;
  for (const Load& l : chain.loads()) {
    LoadWork w;
    w.load = l;
    const Eigen::Vector2d d = chain.position_jacobian(l.block, l.point, q) * v;
    w.dx = d.x();
    w.dz = d.y();
    switch (l.type) {
      case LoadType::SelfWeight:
      case LoadType::Weight:
        if (l.seismic) {
          w.W_dx = l.weight * w.dx;
          // A block's weight is distributed over its area: integral dx^2 dW.
          const double dphi = l.type == LoadType::SelfWeight ? v(3 * l.block + 2) : 0.0;
          const double r2 = l.type == LoadType::SelfWeight ? chain.vertical_gyration_sq(l.block, q) : 0.0;
          w.W_dx2 = l.weight * (w.dx * w.dx + dphi * dphi * r2);
        }
        if (l.vertical) w.work = -l.weight * w.dz;  // self weights bear unless drawn in plan
        break;
      case LoadType::Force:
      case LoadType::Tie: w.work = l.force.dot(d); break;
      case LoadType::Friction:
        // Lost once the point has slipped by slip_limit (issue 33).
        if (!(std::fabs(chain.position(l.block, l.point, q).x() - l.point.x()) >= l.slip_limit))
          w.work = -l.force.x() * std::fabs(w.dx);
        break;
    }
    out.push_back(w);
  }
  return out;
}

// [C8A.4.1] / [C8.7.1.1]: alpha sum W dx + sum(other work) = 0.
double load_multiplier(const Chain& chain, const Eigen::VectorXd& q) {
  double sum_W_dx = 0.0, work = 0.0;
  for (const LoadWork& w : load_works(chain, q)) {
    sum_W_dx += w.W_dx;
    work += w.work;
  }
  return -work / sum_W_dx;
}

// Tie levels (issue 23): the work of each level in configuration q with
// virtual displacements v (docs/theory/ties.md §2).
TieWork tie_work(const Chain& chain, const TieRestraint& t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                 bool rigid_plastic) {
  TieWork w;
  w.tie = t;
  const Eigen::Vector2d dp = chain.position_jacobian(t.block, t.point, q) * v;
  w.d_along = -t.direction.dot(dp);
  w.force = rigid_plastic ? (w.d_along > 0.0 ? t.capacity : std::min(t.pretension, t.capacity))
                          : tie_force(t, tie_elongation(chain, t, q));
  w.work = w.force * t.direction.dot(dp);
  return w;
}

double load_multiplier(const Chain& chain, const Eigen::VectorXd& q, const std::vector<TieRestraint>& ties,
                       bool rigid_plastic) {
  if (ties.empty()) return load_multiplier(chain, q);
  double sum_W_dx = 0.0, work = 0.0;
  for (const LoadWork& w : load_works(chain, q)) {
    sum_W_dx += w.W_dx;
    work += w.work;
  }
  const Eigen::VectorXd v = chain.virtual_displacement(q);
  for (const TieRestraint& t : ties) work += tie_work(chain, t, q, v, rigid_plastic).work;
  return -work / sum_W_dx;
}

namespace {

// Linear kinematic analysis (C8A.4.1-C8A.4.3): the virtual-work table in the
// reference configuration q0 (virtual displacements v0), sum W, sum W dx,
// sum W dx^2, the work of the other forces with the tie levels at their
// design strength, alpha0, M*, e*. Returns sum W p (N m), the moment of the
// seismic weights about the origin.
Eigen::Vector2d linear_analysis(const Chain& chain, const KinematicOptions& opt, const std::vector<TieRestraint>& ties,
                                const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, KinematicResult& R) {
  R.loads = load_works(chain, q0);
  if (opt.lumped_masses)  // the alternative of the relazione's modelling choices (issue 36)
    for (LoadWork& w : R.loads)
      if (w.load.type == LoadType::SelfWeight && w.load.seismic) w.W_dx2 = w.load.weight * w.dx * w.dx;
  Eigen::Vector2d Wp(0.0, 0.0);
  for (const LoadWork& w : R.loads) {
    R.sum_W_dx += w.W_dx;
    R.sum_W_dx2 += w.W_dx2;
    R.work_other += w.work;
    if (is_seismic_weight(w.load)) {
      R.sum_W += w.load.weight;
      Wp += w.load.weight * w.load.point;
    }
  }
  for (const TieRestraint& t : ties) {
    R.ties.push_back(tie_work(chain, t, q0, v0, true));
    R.work_other += R.ties.back().work;
  }
  // Every weight, work and virtual displacement must be a finite number
  // before anything is divided by them (coordinates of 1e150 m made the
  // weights infinite and their works not-a-number).
  if (!std::isfinite(R.sum_W_dx) || !std::isfinite(R.sum_W_dx2) || !std::isfinite(R.work_other) ||
      !std::isfinite(R.sum_W) || !Wp.allFinite())
    throw InputError("the weights or virtual displacements of the mechanism are not finite numbers: check the "
                     "coordinates (m), unit weights (kN/m^3) and loads (kN) for absurd magnitudes");
  if (!(R.sum_W > 0.0))
    throw InputError("the mechanism has no seismic weight (weightless blocks and no weight load with \"seismic\": "
                     "true): alpha0 = -(work of the other loads) / (sum W dx) is undefined [C8A.4.1]");
  if (!(R.sum_W_dx > 0.0))
    // (virtual_displacement orients the mechanism so that sum W dx >= 0.)
    throw InputError("no seismic weight of the mechanism moves horizontally (sum W dx = 0): a horizontal action "
                     "does no work on it, so alpha0 [C8A.4.1] is undefined; check the constraints (a vertical "
                     "slider alone, a hinge at every block's centroid)");
  R.alpha0 = -R.work_other / R.sum_W_dx;                        // [C8A.4.1]
  R.M_star = R.sum_W_dx * R.sum_W_dx / (units::g * R.sum_W_dx2); // [C8A.4.2]
  R.e_star = units::g * R.M_star / R.sum_W;                      // [C8A.4.3] = [C8.7.1.5]
  R.activates = R.alpha0 > 0.0;
  return Wp;
}

// The smallest horizontal virtual displacement (m/rad) that counts as moving
// outward: 1e-6 of the largest of the loads'.
double outward_threshold(const KinematicResult& R) {
  double max_dx = 0.0;
  for (const LoadWork& w : R.loads) max_dx = std::max(max_dx, std::fabs(w.dx));
  return 1e-6 * max_dx;
}

// The control point (KinematicOptions::control_block) and d*/d_k
// [C8A.4.5] / [C8.7.1.4]; Wp from linear_analysis.
void choose_control_point(const Chain& chain, const KinematicOptions& opt, const Eigen::VectorXd& q0,
                          const Eigen::VectorXd& v0, const Eigen::Vector2d& Wp, KinematicResult& R) {
  auto dx_of = [&](int b, const Eigen::Vector2d& p) { return (chain.position_jacobian(b, p, q0) * v0).x(); };
  const double dx_min = outward_threshold(R);
  if (opt.control_block >= 0) {
    if (opt.control_block >= static_cast<int>(chain.blocks().size()))
      throw InputError("control point: block index " + std::to_string(opt.control_block) +
                       " does not exist");
    if (!chain.contains(opt.control_block, opt.control_point))
      throw InputError("control point: the point is not on block " +
                       std::to_string(opt.control_block));
    if (!(dx_of(opt.control_block, opt.control_point) > dx_min))
      throw InputError("control point: it must move outward (dx > 0) in the mechanism");
    R.control_block = opt.control_block;
    R.control_point = opt.control_point;
  } else {
    const Eigen::Vector2d g = Wp / R.sum_W;
    for (int b : chain.blocks_containing(g))
      if (dx_of(b, g) > dx_min) {
        R.control_block = b;
        R.control_point = g;
        break;
      }
    if (R.control_block < 0) {
      double best = 0.0;
      for (const LoadWork& w : R.loads)
        if (w.W_dx > best) {
          best = w.W_dx;
          R.control_block = w.load.block;
          R.control_point = w.load.point;
        }
    }
  }
  if (R.control_block < 0)  // (not reached: sum W dx > 0 above; position_jacobian of block -1 wrote outside its matrix)
    throw InputError("no seismic weight of the mechanism moves outward (sum W dx = " + std::to_string(R.sum_W_dx / units::kN) +
                     " kN m): no control point; check the constraints and the loads");
  R.dx_k = dx_of(R.control_block, R.control_point);
  R.d_star_per_dk = R.sum_W_dx2 / (R.dx_k * R.sum_W_dx);  // [C8A.4.5] / [C8.7.1.4]
}

// Issue 37: the levels that fail within the step ending at the sample just
// marched (d_k = dk, configuration qn), in the order they fail: each breaks
// where its elongation reaches its failure elongation (found by bisection)
// and the curve goes on without it. Returns true when the wall left holds no
// more (alpha <= 0 once a level broke): the collapse is at that break (R.dk0).
bool break_failing_levels(const Path& path, PathSamples& S, double dk, const Eigen::VectorXd& qn, KinematicResult& R) {
  const std::vector<TieRestraint>& ties = path.ties;
  for (;;) {
    double first = inf;
    std::size_t who = ties.size();
    for (std::size_t l = 0; l < ties.size(); ++l) {
      if (std::isfinite(S.broken_at[l])) continue;
      const double lim = failure_elongation_of(ties[l]);
      if (!std::isfinite(lim) || tie_elongation(path.chain, ties[l], qn) < lim) continue;
      const double at = path.crossing(ties[l], lim, dk - S.h, dk);
      if (at < first) first = at, who = l;
    }
    if (who == ties.size()) return false;
    KinematicResult::TieBreak b;
    b.level = ties[who].name;
    Eigen::VectorXd qb;
    if (path.configuration(first, qb)) {
      b.alpha_before = load_multiplier(path.chain, qb, path.acting(first));
      b.alpha_after = load_multiplier(path.chain, qb, path.acting(first, who));
    }
    b.caps = b.alpha_after < 0.5 * b.alpha_before;
    S.broken_at[who] = first;
    S.break_dk.push_back(first);
    R.tie_breaks.push_back(b);
    if (!(b.alpha_after > 0.0)) {
      R.dk0 = first;
      return true;
    }
  }
}

// Non-linear analysis (Circ. 2019 §C8.7.1.2.1.2): march d_k in steps of
// 1/1000 of the chain's size from the configuration of the sample before
// (predicted along its virtual displacements) until alpha changes sign, then
// the zero d_k0 by Brent; tie levels break along the way
// (break_failing_levels). Sets the termination, dk0 and the breaks.
void march(const Path& path, PathSamples& S, KinematicResult& R) {
  const Chain& chain = path.chain;
  const double dx_min = outward_threshold(R);
  const int max_steps = 3000;
  R.termination = CurveTermination::NoZeroCrossing;
  R.message = "alpha stays > 0 up to d_k = 3 times the size of the chain";
  for (int i = 1; i <= max_steps; ++i) {
    const Eigen::VectorXd& qp = S.q.back();
    const Eigen::VectorXd vp = chain.virtual_displacement(qp);
    const double dxk = (chain.position_jacobian(R.control_block, R.control_point, qp) * vp).x();
    const Eigen::VectorXd guess = std::fabs(dxk) > dx_min ? Eigen::VectorXd(qp + vp * (S.h / dxk)) : qp;
    Eigen::VectorXd qn;
    const double dk = i * S.h;
    if (!chain.solve_configuration(R.control_block, R.control_point, dk, guess, qn)) {
      R.termination = CurveTermination::NewtonFailure;
      R.message = "no finite-displacement configuration found at d_k = " + std::to_string(dk) + " m";
      return;
    }
    S.dk.push_back(dk);
    S.q.push_back(qn);
    if (break_failing_levels(path, S, dk, qn, R)) {
      R.termination = CurveTermination::Complete;
      R.message.clear();
      return;
    }
    const double a = load_multiplier(chain, qn, path.acting(dk));
    if (!(a > 0.0)) {
      const double lo = dk - S.h;
      R.dk0 = a == 0.0 ? dk
                       : detail::brent_root([&](double d) { return path.alpha(d); }, lo, dk,
                                            1e-13 * chain.size());
      if (!std::isfinite(R.dk0)) {
        R.termination = CurveTermination::NewtonFailure;
        R.message = "the zero of alpha could not be refined";
      } else {
        R.termination = CurveTermination::Complete;
        R.message.clear();
      }
      return;
    }
  }
}

// Tie levels: where each level reaches its strength (its elongation
// (T_Rd - P0)/k), by the first crossing on the marching grid (S.strength_dk).
void levels_at_strength(const Path& path, PathSamples& S, const KinematicResult& R) {
  for (std::size_t l = 0; l < path.ties.size(); ++l) {
    const TieRestraint& t = path.ties[l];
    if (!(t.stiffness > 0.0) || !(t.capacity > t.pretension)) continue;
    const double lim = t.yield_elongation();
    for (std::size_t i = 1; i < S.dk.size(); ++i) {
      if (S.dk[i] > std::min(R.dk0, S.broken_at[l]) + S.h) break;
      if (tie_elongation(path.chain, t, S.q[i]) < lim) continue;
      S.strength_dk[l] = std::min(path.crossing(t, lim, S.dk[i - 1], S.dk[i]), R.dk0);
      break;
    }
  }
}

// The d* (m) of the path's events from their control displacements with
// d*/d_k [C8A.4.5]/[C8.7.1.4]: each break and the first that caps the
// capacity (d_star_tie_cap), d0* and the first level at its strength (reported).
void d_star_of_events(const PathSamples& S, const std::vector<TieRestraint>& ties, KinematicResult& R) {
  R.d_star_tie_cap = inf;
  for (std::size_t i = 0; i < R.tie_breaks.size(); ++i) {
    KinematicResult::TieBreak& b = R.tie_breaks[i];
    b.d_star = S.break_dk[i] * R.d_star_per_dk;
    if (b.caps && !std::isfinite(R.d_star_tie_cap)) R.d_star_tie_cap = b.d_star;
  }
  R.d0_star = 0.0;
  R.d_star_tie_limit = inf;
  R.tie_limit_level.clear();
  if (!R.curve_complete()) return;
  R.d0_star = R.d_star_per_dk * R.dk0;
  for (std::size_t l = 0; l < ties.size(); ++l) {
    if (!std::isfinite(S.strength_dk[l])) continue;
    const double at = S.strength_dk[l] * R.d_star_per_dk;
    if (at < R.d_star_tie_limit) {
      R.d_star_tie_limit = at;
      R.tie_limit_level = ties[l].name;
    }
  }
}

// Issue 33: a rotation bound of a one-body mechanism about its ground hinge
// (KinematicOptions::rotation_cap): dk0_bound, d0_star_bound, and the options
// with du*, d_SLV and d_SLC capped at their fractions of d0_star_bound when
// it is below d0*.
KinematicOptions rotation_capped(const Chain& chain, const KinematicOptions& opt, KinematicResult& R) {
  KinematicOptions capped = opt;
  if (!std::isfinite(opt.rotation_cap)) return capped;
  const Constraint* hinge = &detail::single_ground_hinge(chain, "rotation cap");
  const Eigen::VectorXd v0 =
      chain.virtual_displacement(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.n_coordinates())));
  const double phi = v0(3 * hinge->block + 2);
  for (std::size_t b = 0; b < chain.blocks().size(); ++b)
    if (std::fabs(v0(Eigen::Index(3 * b + 2)) - phi) > 1e-9 * std::max(1.0, std::fabs(phi)))
      throw InputError("rotation cap: the mechanism does not turn as one rigid body");
  // Outward rotation theta of the whole chain about the hinge O (clockwise in
  // x-z with x outward): x' = O.x + r.x cos(theta) + r.z sin(theta).
  const Eigen::Vector2d r = R.control_point - hinge->point;
  const double th = opt.rotation_cap;
  R.dk0_bound = r.x() * (std::cos(th) - 1.0) + r.y() * std::sin(th);
  R.d0_star_bound = R.d_star_per_dk * R.dk0_bound;
  if (R.d0_star_bound < R.d0_star) {
    capped.du_cap = std::min(opt.du_cap, code_rules::du_over_d0_2008 * R.d0_star_bound);
    capped.d_SLV_cap = std::min(opt.d_SLV_cap, opt.dSLV_over_d0 * R.d0_star_bound);
    capped.d_SLC_cap = std::min(opt.d_SLC_cap, opt.dSLC_over_d0 * R.d0_star_bound);
  }
  return capped;
}

// The code quantities on the marched path `S` of R for the options `opt`
// (only FC, the curve's model and points, the caps, the fractions of d0* and
// the rotation bound enter): a0* [C8A.4.4]/[C8.7.1.3], the rotation bound, the
// reported capacity curve, du*, ds*, as*, Ts (C8A.4, §6 of
// docs/theory/kinematic.md) and d_SLV, T_SLV, d_SLC, T_SLC (Circ. 2019
// §C8.7.1.2.1.6, [C8.7.1.10], [C8.7.1.11]). `prior`: the path as an earlier
// derivation left it (its alphas, R.curve its curve), or null. Sets R.marched.
void derive_code_quantities(const Chain& chain, const KinematicOptions& opt, const std::vector<TieRestraint>& ties,
                            const std::shared_ptr<const PathSamples>& S, const MarchedPath* prior,
                            KinematicResult& R) {
  auto M = std::make_shared<MarchedPath>(MarchedPath{opt, S, {}});
  R.marched = M;
  const std::vector<CapacityPoint> prior_curve = std::move(R.curve);
  R.FC = opt.FC;
  R.curve_model = opt.curve_model;
  R.a0_star = R.alpha0 * units::g / (R.e_star * R.FC);  // [C8A.4.4] / [C8.7.1.3]
  R.dk0_bound = R.d0_star_bound = inf;
  R.curve.clear();
  R.du_star = R.ds_star = R.as_star = R.Ts = 0.0;
  R.d_SLV = R.a_SLV = R.T_SLV = R.d_SLC = R.a_SLC = R.T_SLC = 0.0;
  if (!R.curve_complete()) return;
  const Path path{chain, ties, R.control_block, R.control_point, *S};
  const KinematicOptions capped = rotation_capped(chain, opt, R);

  // alpha(d_k) on the path, the earlier derivation's where it took it.
  auto path_alpha = [&](double dk) {
    double alpha = 0.0;
    bool found = false;
    if (prior)
      for (const auto& [d, a] : prior->alphas)
        if (d == dk) {
          alpha = a, found = true;
          break;
        }
    if (!found) alpha = path.alpha(dk);
    M->alphas.emplace_back(dk, alpha);
    return alpha;
  };
  const double a_scale = units::g / (R.e_star * R.FC);
  // a*(d*) (m/s^2) from the chosen curve model.
  auto a_star_at = [&](double d_star) {
    const double dk = d_star / R.d_star_per_dk;
    const double alpha = opt.curve_model == CurveModel::Linearised ? R.alpha0 * (1.0 - dk / R.dk0)
                                                                    : path_alpha(dk);
    return alpha * a_scale;
  };
  for (int j = 0; j < opt.curve_points; ++j) {
    CapacityPoint p;
    p.d_star = R.d0_star * j / (opt.curve_points - 1);
    p.dk = p.d_star / R.d_star_per_dk;
    p.a_star = j == 0 && ties.empty() ? R.a0_star : j == opt.curve_points - 1 ? 0.0 : a_star_at(p.d_star);
    p.alpha = p.a_star / a_scale;
    if (prior && std::size_t(j) < prior_curve.size() && prior_curve[std::size_t(j)].dk == p.dk) {
      p.tie_elongation = prior_curve[std::size_t(j)].tie_elongation;  // the same point of the path
      p.tie_force = prior_curve[std::size_t(j)].tie_force;
    } else if (!ties.empty()) {
      Eigen::VectorXd qj;
      if (path.configuration(p.dk, qj))
        for (std::size_t l = 0; l < ties.size(); ++l) {
          const double e = tie_elongation(chain, ties[l], qj);
          p.tie_elongation.push_back(e);
          p.tie_force.push_back(p.dk <= path.s.broken_at[l] * (1.0 + 1e-12) ? tie_force(ties[l], e) : 0.0);
        }
    }
    R.curve.push_back(p);
  }

  // The displacement capacities, each capped by the first break that drops
  // the capacity by more than 50 % (d_star_tie_cap), and their periods.
  const double d_tie = R.d_star_tie_cap;
  // NTC 2008 (C8A.4, §6 of docs/theory/kinematic.md).
  R.du_star = std::min({code_rules::du_over_d0_2008 * R.d0_star, capped.du_cap, d_tie});
  R.ds_star = code_rules::ds_over_du_2008 * R.du_star;
  R.as_star = a_star_at(R.ds_star);
  R.Ts = 2.0 * units::pi * std::sqrt(R.ds_star / R.as_star);
  // NTC 2018 (Circ. 2019 §C8.7.1.2.1.6, [C8.7.1.10], [C8.7.1.11]).
  R.d_SLV = std::min({opt.dSLV_over_d0 * R.d0_star, capped.d_SLV_cap, d_tie});
  R.a_SLV = a_star_at(R.d_SLV);
  R.T_SLV = code_rules::T_SLV_factor_of_pi * units::pi * std::sqrt(R.d_SLV / R.a_SLV);
  R.d_SLC = std::min({opt.dSLC_over_d0 * R.d0_star, capped.d_SLC_cap, d_tie});
  R.a_SLC = a_star_at(R.d_SLC);
  R.T_SLC = code_rules::T_SLC_factor_of_pi * units::pi * std::sqrt(R.d_SLC / R.a_SLC);
}

// The options that shape the marched path: the control point. The lumping
// of the masses changes the linear analysis and d*/d_k alone
// (redistribute_masses); the others only enter derive_code_quantities.
bool same_path(const KinematicOptions& a, const KinematicOptions& b) {
  return a.control_block == b.control_block && a.control_point == b.control_point;
}

bool same_options(const KinematicOptions& a, const KinematicOptions& b) {
  return same_path(a, b) && a.lumped_masses == b.lumped_masses && a.FC == b.FC && a.curve_model == b.curve_model && a.curve_points == b.curve_points &&
         a.du_cap == b.du_cap && a.d_SLV_cap == b.d_SLV_cap && a.d_SLC_cap == b.d_SLC_cap &&
         a.dSLV_over_d0 == b.dSLV_over_d0 && a.dSLC_over_d0 == b.dSLC_over_d0 && a.rotation_cap == b.rotation_cap;
}

// The linear analysis, the control point and the marched path (with the
// levels' breaks and the first level at its strength): everything of the
// analysis that the options of derive_code_quantities do not change.
KinematicResult march_kinematic(const Chain& chain, const KinematicOptions& opt,
                                const std::vector<TieRestraint>& ties) {
  KinematicResult R;
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.n_coordinates()));
  const Eigen::VectorXd v0 = chain.virtual_displacement(q0);
  const Eigen::Vector2d Wp = linear_analysis(chain, opt, ties, q0, v0, R);
  choose_control_point(chain, opt, q0, v0, Wp, R);
  auto S = std::make_shared<PathSamples>();
  S->dk = {0.0};
  S->q = {q0};
  S->broken_at.assign(ties.size(), inf);
  S->strength_dk.assign(ties.size(), inf);
  S->h = chain.size() / 1000.0;
  R.marched = std::make_shared<const MarchedPath>(MarchedPath{opt, S, {}});
  if (!R.activates) {
    R.termination = CurveTermination::NotActivated;
    R.message = "alpha0 <= 0: the mechanism is not activated by any horizontal action";
    return R;
  }
  const Path path{chain, ties, R.control_block, R.control_point, *S};
  march(path, *S, R);
  if (R.curve_complete()) levels_at_strength(path, *S, R);
  d_star_of_events(*S, ties, R);
  return R;
}

// Another lumping of the masses (KinematicOptions::lumped_masses, the
// relazione's alternative): the linear analysis again (M*, e*, d*/d_k) and
// the d* of the path's events. The path and the control point do not depend
// on it: the march knows no mass, and the control point is chosen from W and
// W dx (choose_control_point), which the lumping leaves as they are.
void redistribute_masses(const Chain& chain, const KinematicOptions& opt, const std::vector<TieRestraint>& ties,
                         const PathSamples& S, KinematicResult& R) {
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.n_coordinates()));
  const Eigen::VectorXd v0 = chain.virtual_displacement(q0);
  R.loads.clear();
  R.ties.clear();
  R.sum_W = R.sum_W_dx = R.sum_W_dx2 = R.work_other = 0.0;
  linear_analysis(chain, opt, ties, q0, v0, R);
  R.d_star_per_dk = R.sum_W_dx2 / (R.dx_k * R.sum_W_dx);  // [C8A.4.5] / [C8.7.1.4]
  d_star_of_events(S, ties, R);
}

void check_tie_blocks(const Chain& chain, const std::vector<TieRestraint>& ties) {
  for (const TieRestraint& t : ties)
    if (t.block < 0 || t.block >= static_cast<int>(chain.blocks().size()))
      throw InputError("tie \"" + t.name + "\": it holds no block of the mechanism");
}

}  // namespace

KinematicResult analyse_kinematic(const Chain& chain, const KinematicOptions& opt) {
  return analyse_kinematic(chain, opt, {});
}

KinematicResult analyse_kinematic(const Chain& chain, const KinematicOptions& opt,
                                  const std::vector<TieRestraint>& ties,
                                  std::shared_ptr<const KinematicResult> without_ties) {
  opt.validate();
  check_tie_blocks(chain, ties);
  if (!ties.empty() && !without_ties)
    without_ties = std::make_shared<const KinematicResult>(analyse_kinematic(chain, opt, {}));
  KinematicResult R = march_kinematic(chain, opt, ties);
  if (!ties.empty()) R.without_ties = std::move(without_ties);
  const std::shared_ptr<const PathSamples> samples = R.marched->samples;  // (R.marched is replaced)
  derive_code_quantities(chain, opt, ties, samples, nullptr, R);
  return R;
}

KinematicResult rederive_kinematic(const Chain& chain, const KinematicOptions& opt,
                                   const std::vector<TieRestraint>& ties, const KinematicResult& marched) {
  opt.validate();
  check_tie_blocks(chain, ties);
  const MarchedPath* m = marched.marched.get();
  if (!m || !same_path(m->options, opt) || m->samples->broken_at.size() != ties.size() ||
      marched.ties.size() != ties.size() || ties.empty() != !marched.without_ties)
    return analyse_kinematic(chain, opt, ties);
  if (same_options(m->options, opt)) return marched;
  KinematicResult R = marched;
  if (opt.lumped_masses != m->options.lumped_masses) redistribute_masses(chain, opt, ties, *m->samples, R);
  if (marched.without_ties)
    R.without_ties = std::make_shared<const KinematicResult>(rederive_kinematic(chain, opt, {}, *marched.without_ties));
  derive_code_quantities(chain, opt, ties, m->samples, m, R);
  return R;
}

}  // namespace assess

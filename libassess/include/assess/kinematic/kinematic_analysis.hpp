// kinematic_analysis.hpp: linear and non-linear kinematic analysis of a chain
// of rigid blocks: alpha0, M*, e*, a0* and the capacity curve with d0*, du*,
// Ts (NTC 2008, Circ. 617/2009 C8A.4) and d_SLV, d_SLC, T_SLV, T_SLC
// (NTC 2018, Circ. 2019 §C8.7.1.2.1).
#pragma once

#include "assess/kinematic/chain.hpp"
#include "assess/kinematic/code_rules.hpp"
#include "assess/kinematic/tie.hpp"

#include <Eigen/Dense>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace assess {

/// How alpha varies with the control displacement d_k.
enum class CurveModel {
  /// alpha(d_k) from the equilibrium of the chain in its finite-displacement
  /// configuration (default; Circ. 2019 §C8.7.1.2.1.2).
  FiniteDisplacement,
  /// alpha = alpha0 (1 - d_k / d_k0), the straight line of C8A.4.5 through the
  /// same end points (d_k0 still from the finite displacements).
  Linearised,
};

/// Settings of the analysis.
struct KinematicOptions {
  /// Confidence factor FC (-), >= 1 (code_rules::confidence_factor).
  double FC = 1.35;
  CurveModel curve_model = CurveModel::FiniteDisplacement;
  /// Number of points of the reported capacity curve, >= 3.
  int curve_points = 41;
  /// Control point: a material point (m) of block `control_block`. With
  /// control_block = -1 (default) it is the centroid of the seismic weights
  /// when that lies on a block and moves outward, else the seismic weight point
  /// with the largest W dx.
  int control_block = -1;
  Eigen::Vector2d control_point{0.0, 0.0};
  /// Caps on the equivalent displacement d* (m) for local incompatibilities
  /// (beam unseating ...): du* (2008), d_SLV and d_SLC (2018). Infinity = none.
  double du_cap = std::numeric_limits<double>::infinity();
  double d_SLV_cap = std::numeric_limits<double>::infinity();
  double d_SLC_cap = std::numeric_limits<double>::infinity();
  /// d_SLV / d0* (-): the code's 0.40 (Circ. 2019 C8.7.1.2.1.6); another
  /// value only for the relazione's sensitivity study (assessment/sensitivity.hpp).
  double dSLV_over_d0 = code_rules::dSLV_over_d0_2018;
  /// d_SLC / d0* (-): the code's 0.60 (C8.7.1.2.1.6); another value only for
  /// the relazione's modelling choices (issue 36: the reading of the limit
  /// state that governs is the one varied).
  double dSLC_over_d0 = code_rules::dSLC_over_d0_2018;
  /// Issue 36 (the relazione's modelling choices): each block's weight
  /// lumped at its centroid in sum W dx^2 (M*, e*, d*/d_k), instead of
  /// distributed over its area (the default: integral dx^2 dW, C8A.4.2 for a
  /// block of continuous mass). Only the alternative shown to the reviewer.
  bool lumped_masses = false;
  /// Issue 33: a bound on the rotation (rad) of a mechanism that turns as one
  /// rigid body about its single ground hinge (the corner pier's own
  /// overturning, the pull-out of the side walls' interlocking): d0* is
  /// bounded by d* at that rotation, so du*, d_SLV and d_SLC are capped at
  /// 0.4, 0.4 and 0.6 of it (the same fractions as of d0*, code_rules).
  /// Infinity = none. Why the bound holds is the mechanism's
  /// (MechanismCandidate::rotation_bound_reason).
  double rotation_cap = std::numeric_limits<double>::infinity();
  /// Throws InputError naming the field.
  void validate() const;
};

/// The virtual-work contribution of one load (virtual displacements with the
/// normalisation of Chain::virtual_displacement: largest rotation 1 rad).
struct LoadWork {
  Load load;          ///< the load (self weights included)
  double dx = 0.0;    ///< horizontal virtual displacement of its point (m/rad)
  double dz = 0.0;    ///< vertical virtual displacement, up positive (m/rad)
  double W_dx = 0.0;  ///< W dx of a seismic weight (N m/rad), else 0
  /// W dx^2 of a seismic weight (N m^2/rad^2), else 0; for a self weight the
  /// integral of dx^2 dW over the block (distributed mass, see vertical_gyration_sq).
  double W_dx2 = 0.0;
  /// Virtual work of the load's non-seismic force (N m/rad): -W dz for a
  /// weight on the chain, F . delta for a force or tie, -F |dx| for friction.
  double work = 0.0;
};

/// One point of the capacity curve.
struct CapacityPoint {
  double dk = 0.0;       ///< horizontal displacement of the control point (m)
  double alpha = 0.0;    ///< load multiplier (-)
  double d_star = 0.0;   ///< equivalent SDOF displacement d* (m) [C8A.4.5]/[C8.7.1.4]
  double a_star = 0.0;   ///< spectral acceleration a* (m/s^2) [C8A.4.4]/[C8.7.1.3]
  /// Tie levels (issue 23), in the order given: force (N) and elongation (m)
  /// of each level at this point (elastic-perfectly-plastic law); empty without ties.
  std::vector<double> tie_force;
  std::vector<double> tie_elongation;
};

/// The virtual work of one tie level at alpha0 (issue 23): the level at its
/// design strength (rigid-plastic) when the mechanism elongates it
/// (docs/theory/ties.md §2).
struct TieWork {
  TieRestraint tie;
  double d_along = 0.0;  ///< virtual elongation rate -e . delta p (m/rad)
  double force = 0.0;    ///< force counted in alpha0 (N)
  double work = 0.0;     ///< its virtual work (N m/rad), negative when it restrains
};

enum class CurveTermination {
  Complete,        ///< the curve reaches alpha = 0 at d_k0
  NotActivated,    ///< alpha0 <= 0: the mechanism never activates (no curve)
  NoZeroCrossing,  ///< alpha stays > 0 up to the largest displacement explored
  NewtonFailure,   ///< the finite-displacement configuration could not be found
};
std::string to_string(CurveTermination t);

/// The equilibrium path marched by finite displacements (its samples and the
/// tie levels' breaks) and the options a result's code quantities were
/// derived with: private to kinematic_analysis.cpp, kept by each result so
/// that rederive_kinematic derives the code quantities for other options
/// without marching again.
struct MarchedPath;

/// Every intermediate quantity of the analysis. Two stages (issue 41, speed):
/// the marched path (the linear analysis, the control point, the curve's zero
/// d_k0 and d0*, the tie levels' breaks), which depends only on the chain,
/// its tie levels, the control point and the lumping of the masses; and the
/// code quantities derived from it for the options (a0* with FC, the reported
/// curve, du*, Ts, d_SLV, T_SLV, d_SLC, T_SLC with their caps and fractions of d0*).
struct KinematicResult {
  // Linear kinematic analysis.
  std::vector<LoadWork> loads;
  double sum_W = 0.0;       ///< sum of the seismic weights P + Q (N)
  double sum_W_dx = 0.0;    ///< sum W dx (N m/rad)
  double sum_W_dx2 = 0.0;   ///< sum W dx^2 (N m^2/rad^2)
  double work_other = 0.0;  ///< virtual work of the non-seismic forces (N m/rad), ties included
  std::vector<TieWork> ties;  ///< tie levels (issue 23); their work is in work_other
  double alpha0 = 0.0;      ///< activation multiplier (-) [C8A.4.1]/[C8.7.1.1]
  bool activates = false;   ///< alpha0 > 0
  double M_star = 0.0;      ///< participating mass M* (kg) [C8A.4.2]
  double e_star = 0.0;      ///< participating mass fraction e* (-) [C8A.4.3]/[C8.7.1.5]
  double FC = 0.0;          ///< confidence factor used (-)
  double a0_star = 0.0;     ///< spectral activation acceleration a0* (m/s^2) [C8A.4.4]/[C8.7.1.3]
  // Control point.
  int control_block = -1;
  Eigen::Vector2d control_point{0.0, 0.0};  ///< m
  double dx_k = 0.0;        ///< its horizontal virtual displacement (m/rad)
  double d_star_per_dk = 0.0;  ///< d*/d_k = sum W dx^2 / (dx_k sum W dx) (-)
  // Non-linear kinematic analysis.
  CurveModel curve_model = CurveModel::FiniteDisplacement;
  CurveTermination termination = CurveTermination::NotActivated;
  std::string message;        ///< why the curve is incomplete, if it is
  double dk0 = 0.0;           ///< control displacement at alpha = 0 (m)
  double d0_star = 0.0;       ///< d* at alpha = 0 (m)
  /// Issue 33: the control displacement and d* at KinematicOptions::rotation_cap
  /// (m); infinity without a cap. The displacement capacities use
  /// min(d0*, d0_star_bound) and a dynamic analysis collapses at min(dk0, dk0_bound).
  double dk0_bound = std::numeric_limits<double>::infinity();
  double d0_star_bound = std::numeric_limits<double>::infinity();
  std::vector<CapacityPoint> curve;  ///< from d* = 0 to d0*
  // NTC 2008 (Circ. 617/2009 C8A.4).
  double du_star = 0.0;   ///< ultimate displacement du* (m)
  double ds_star = 0.0;   ///< secant displacement ds* (m)
  double as_star = 0.0;   ///< a*(ds*) (m/s^2)
  double Ts = 0.0;        ///< secant period 2 pi sqrt(ds*/as*) (s)
  // NTC 2018 (Circ. 2019 §C8.7.1.2.1.6, .8).
  double d_SLV = 0.0, a_SLV = 0.0, T_SLV = 0.0;  ///< m, m/s^2, s [C8.7.1.10]
  double d_SLC = 0.0, a_SLC = 0.0, T_SLC = 0.0;  ///< m, m/s^2, s [C8.7.1.11]
  // Tie levels (issues 29, 37; docs/theory/ties.md §2): the capacity curve is
  // that of the wall as it is: each level elastic, a ductile one yielding at
  // its strength up to its ultimate elongation, and every level breaking where
  // it fails (a ductile one at eps_ud L, one that is not ductile at its
  // strength), the curve going on with the levels left. d0* is where that
  // curve vanishes. Circ. 2019 §C8.7.1.2.1.6: d_SLV (and du*, d_SLC) are at
  // most the displacement at which an element fails with a capacity drop
  // above 50 %: a break whose alpha falls below half its value.
  /// d* at which the first level reaches its strength (yields or breaks; m;
  /// infinity without ties) and that level.
  double d_star_tie_limit = std::numeric_limits<double>::infinity();
  std::string tie_limit_level;
  /// A level breaking along the curve.
  struct TieBreak {
    std::string level;
    double d_star = 0.0;        ///< m
    double alpha_before = 0.0;  ///< alpha with the level at its failure (-)
    double alpha_after = 0.0;   ///< alpha without it, same configuration (-)
    bool caps = false;          ///< alpha_after < 0.5 alpha_before: the capacity stops here
  };
  std::vector<TieBreak> tie_breaks;
  /// The cap of the first break that drops the capacity by more than 50 % (m;
  /// infinity: none).
  double d_star_tie_cap = std::numeric_limits<double>::infinity();
  /// The same chain without its tie levels (the wall once every level broke):
  /// its d0 bounds a dynamic analysis in which a level broke. Null without ties.
  std::shared_ptr<const KinematicResult> without_ties;
  /// The marched path and the options derived with (rederive_kinematic).
  std::shared_ptr<const MarchedPath> marched;

  bool curve_complete() const { return termination == CurveTermination::Complete; }
};

/// Load multiplier alpha in the configuration q (Chain coordinates), by
/// virtual work with the virtual displacements of that configuration:
/// alpha = -(work of the non-seismic forces) / (sum W dx).
double load_multiplier(const Chain& chain, const Eigen::VectorXd& q);

/// Same with tie levels (issue 23): `rigid_plastic` counts each level at its
/// design strength when the virtual motion elongates it (alpha0), otherwise
/// the elastic-perfectly-plastic force at the elongation of q (capacity curve).
double load_multiplier(const Chain& chain, const Eigen::VectorXd& q, const std::vector<TieRestraint>& ties,
                       bool rigid_plastic = false);

/// Virtual-work table of the loads in configuration q.
std::vector<LoadWork> load_works(const Chain& chain, const Eigen::VectorXd& q);

/// Runs the linear and non-linear analysis. Never throws for a mechanism that
/// does not activate (termination NotActivated); throws InputError for bad
/// options or a control point not on its block.
KinematicResult analyse_kinematic(const Chain& chain, const KinematicOptions& options = {});
/// Same with tie levels (issues 23, 37; docs/theory/ties.md §2): alpha0 (and
/// a0*) with each level at its design strength (rigid-plastic, the practice of
/// C8A.4), the capacity curve with the elastic-perfectly-plastic law in the
/// rod's elongation, each level broken from where it fails (its first point is
/// then alpha(0) of that law, not alpha0).
/// Throws InputError for a level on a missing block. With ties, `without_ties`
/// is the analysis of the same chain and options without them (computed here
/// when not given).
KinematicResult analyse_kinematic(const Chain& chain, const KinematicOptions& options,
                                  const std::vector<TieRestraint>& ties,
                                  std::shared_ptr<const KinematicResult> without_ties = nullptr);

/// The analysis of the same chain and tie levels as `marched` (an
/// analyse_kinematic or rederive_kinematic result: the caller guarantees the
/// chain and levels are those) with other options: the code quantities derived
/// again on its marched path, bit for bit what analyse_kinematic(chain,
/// options, ties) gives, without marching again (the sensitivity to FC and
/// d_SLV/d0*, the modelling choices, the safety indices of a trial's state).
/// lumped_masses redoes the linear analysis alone; another control point or
/// a result without its path falls back to analyse_kinematic.
KinematicResult rederive_kinematic(const Chain& chain, const KinematicOptions& options,
                                   const std::vector<TieRestraint>& ties, const KinematicResult& marched);

}  // namespace assess

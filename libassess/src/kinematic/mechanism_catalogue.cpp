// mechanism_catalogue.cpp: chains of the classic out-of-plane mechanisms
// (DPC-ReLUIS / regional repertories: ribaltamento semplice, flessione
// verticale, ribaltamento composto, timpano, ribaltamento del cantonale).
//
// Notation: t thickness, h heights, z above the foundation; the outer face is
// x = 0 and the wall lies at x < 0. beta wedge angle from the vertical. Corner:
// s (drawn as x) outward distance along the bisector, r = 1/sqrt(2). alpha0
// activation multiplier [C8A.4.1]/[C8.7.1.1]; Z constraint height (C8A.4.9).
#include "assess/kinematic/mechanism_catalogue.hpp"

#include "kinematic/catalogue_helpers.hpp"

#include "assess/support/error.hpp"
#include "kinematic/ground_hinge.hpp"
#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/support/units.hpp"
#include "assess/kinematic/roof_thrust.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace assess {

using namespace catalogue;

double activation_multiplier(const Chain& chain) {
  return load_multiplier(chain, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.n_coordinates())));
}

// Issue 38: docs/theory/mechanisms.md §5 [I].
double bearing_part_rotation(const Chain& chain, int part) {
  if (part < 0 || part >= static_cast<int>(chain.blocks().size()))
    throw InputError("bearing part: block " + std::to_string(part) + " is not in the mechanism");
  const Constraint* hinge = &detail::single_ground_hinge(chain, "bearing part");
  // x outward: the part's weights lie inward of the hinge (x < x_O) and above it.
  double Ws = 0.0, Wz = 0.0;
  for (const Load& l : chain.loads())
    if (l.block == part && (l.type == LoadType::SelfWeight || l.type == LoadType::Weight) && l.vertical) {
      Ws += l.weight * (hinge->point.x() - l.point.x());
      Wz += l.weight * (l.point.y() - hinge->point.y());
    }
  if (!(Ws > 0.0 && Wz > 0.0))
    throw InputError("bearing part \"" + chain.blocks()[static_cast<std::size_t>(part)].name +
                     "\": its weight is not inward of and above the hinge");
  return std::atan2(Ws, Wz);
}

std::size_t governing_candidate(const MechanismSet& set) {
  std::size_t best = 0;
  double a_best = 0.0;
  for (std::size_t i = 0; i < set.candidates.size(); ++i) {
    const double a = activation_multiplier(set.candidates[i].chain);
    if (i == 0 || a < a_best) {
      best = i;
      a_best = a;
    }
  }
  return best;
}

// ---------------------------------------------------------------- simple overturning
MechanismSet simple_overturning(const SimpleOverturningParams& p) {
  const int n = static_cast<int>(p.storeys.size());
  if (n == 0) throw InputError("simple_overturning: 'storeys' needs at least one storey");
  require_positive(p.unit_weight, "simple_overturning: unit_weight", "kN/m^3");
  require_positive(p.length, "simple_overturning: length", "m");
  require_non_negative(p.hinge_setback, "simple_overturning: hinge_setback", "m");
  std::vector<double> z(n + 1, 0.0);  // z[i] = base of storey i
  for (int i = 0; i < n; ++i) {
    const Storey& s = p.storeys[i];
    const std::string lab = "simple_overturning: storeys[" + std::to_string(i) + "].";
    require_positive(s.height, lab + "height", "m");
    require_positive(s.thickness, lab + "thickness", "m");
    require_non_negative(s.floor_weight, lab + "floor_weight", "kN");
    require_non_negative(s.tie, lab + "tie", "kN");
    if (!(s.floor_distance_from_inner_face >= 0.0 && s.floor_distance_from_inner_face <= s.thickness))
      throw InputError(lab + "floor_distance_from_inner_face must lie in [0, thickness] m");
    if (s.floor_held && !s.floor_bears && s.floor_weight > 0.0)
      throw InputError(lab + "a floor that neither bears (floor_bears false) nor pushes (floor_held true) acts on "
                       "nothing: drop it or give one of the two");
    z[i + 1] = z[i] + s.height;
  }
  RoofLoads roof;
  if (p.roof) {
    p.roof->validate("roof_thrust: roof: ");
    if (!(p.roof->seat_from_inner_face <= p.storeys.back().thickness))
      throw InputError("roof_thrust: roof: the seat's distance from the inner face must lie in [0, thickness of the "
                       "top storey] m");
    roof = roof_loads(*p.roof);
  }
  MechanismSet set;
  set.type = "simple_overturning";
  set.parameter_name = "hinge z (m)";
  set.searched = !p.hinge_level.has_value();
  int first = 0, last = n - 1;
  if (p.hinge_level) {
    if (*p.hinge_level < 0 || *p.hinge_level >= n)
      throw InputError("simple_overturning: hinge_level = " + std::to_string(*p.hinge_level) +
                       ": expected 0.." + std::to_string(n - 1) + " (0 = ground)");
    first = last = *p.hinge_level;
  }
  for (int j = first; j <= last; ++j) {
    if (!(p.hinge_setback < p.storeys[j].thickness))
      throw InputError("simple_overturning: hinge_setback must be < the thickness of storey " +
                       std::to_string(j));
    // One block: outer face x = 0 from z[j] to the top, inner face stepped.
    Block b;
    b.name = "facade above z = " + fmt("%.2f", z[j]) + " m";
    b.unit_weight = p.unit_weight;
    b.length = p.length;
    b.polygon.push_back(V(0.0, z[j]));
    b.polygon.push_back(V(0.0, z[n]));
    for (int i = n - 1; i >= j; --i) {
      b.polygon.push_back(V(-p.storeys[i].thickness, z[i + 1]));
      b.polygon.push_back(V(-p.storeys[i].thickness, z[i]));
    }
    // Drop repeated vertices where consecutive storeys have the same thickness.
    std::vector<V> poly;
    for (const V& v : b.polygon)
      if (poly.empty() || (v - poly.back()).norm() > 0.0) poly.push_back(v);
    b.polygon = poly;
    std::vector<Load> loads;
    for (int i = j; i < n; ++i) {
      const Storey& s = p.storeys[i];
      const V at(-s.thickness + s.floor_distance_from_inner_face, z[i + 1]);
      const std::string lvl = "level " + std::to_string(i + 1);
      if (s.floor_weight > 0.0) {
        loads.push_back(weight("floor " + lvl, 0, at, s.floor_weight, s.floor_bears));
        loads.back().seismic = !s.floor_held;  // issue 38: it moves with the wall unless held
      }
      if (s.thrust != 0.0) loads.push_back(force(LoadType::Force, "thrust " + lvl, 0, at, V(s.thrust, 0.0)));
      if (s.tie > 0.0)
        loads.push_back(force(LoadType::Tie, "tie " + lvl, 0, V(-0.5 * s.thickness, z[i + 1]), V(-s.tie, 0.0)));
    }
    if (p.roof) {  // issue 33: the roof on the top storey, at its seat
      const V seat(-p.storeys.back().thickness + p.roof->seat_from_inner_face, z[n]);
      if (roof.V > 0.0) {
        loads.push_back(weight("roof weight", 0, seat, roof.V * p.length));
        loads.back().seismic = !p.roof->held;  // issue 38
      }
      if (roof.H > 0.0) loads.push_back(force(LoadType::Force, "roof thrust", 0, seat, V(roof.H * p.length, 0.0)));
    }
    const V h(-p.hinge_setback, z[j]);
    set.candidates.push_back({"hinge at z = " + fmt("%.2f", z[j]) + " m (level " + std::to_string(j) + ")",
                              Chain({b}, {ground_hinge("hinge", 0, h)}, loads), z[j], z[j]});
  }
  return set;
}

// ---------------------------------------------------------------- roof thrust (issue 33)
MechanismSet roof_thrust_overturning(const SimpleOverturningParams& p) {
  if (!p.roof) throw InputError("roof_thrust: the roof (\"roof\") is required");
  MechanismSet set = simple_overturning(p);
  set.type = "roof_thrust";
  const RoofLoads r = roof_loads(*p.roof);
  const std::string src = roof_thrust_formula(p.roof->scheme) + "; docs/theory/mechanisms.md §3.1 [D]";
  for (MechanismCandidate& c : set.candidates) {
    // alpha0 = -(sum of the non-seismic work) / (sum W dx) [C8.7.1.1], with and
    // without the roof's terms (the same virtual displacements: one block).
    double sWdx = 0.0, work = 0.0, w_thrust = 0.0, w_roof = 0.0, Wdx_roof = 0.0;
    for (const LoadWork& w : load_works(c.chain, Eigen::VectorXd::Zero(Eigen::Index(c.chain.n_coordinates())))) {
      sWdx += w.W_dx;
      work += w.work;
      if (w.load.name == "roof thrust") w_thrust = w.work;
      if (w.load.name == "roof weight") w_roof = w.work, Wdx_roof = w.W_dx;
    }
    c.quantities = {
        {"roof: load q", p.roof->load / units::kN, "kN/m²", "input"},
        {"roof: span l (plan)", p.roof->span, "m", "input"},
        {"roof: pitch φ", p.roof->pitch_deg, "°", "input"},
        {"roof: vertical reaction V per metre", r.V / units::kN, "kN/m", src},
        {"roof: thrust H per metre", r.H / units::kN, "kN/m", src},
        {"roof: thrust over the façade", r.H * p.length / units::kN, "kN", src},
        {"α0 with the roof's weight and thrust", -work / sWdx, "-", "C8.7.1.1; docs/theory/mechanisms.md (3.3) [V-p]"},
        {"α0 without the roof thrust", -(work - w_thrust) / sWdx, "-", "C8.7.1.1"},
        {"α0 without the roof", -(work - w_thrust - w_roof) / (sWdx - Wdx_roof), "-", "C8.7.1.1"},
    };
  }
  return set;
}

// ---------------------------------------------------------------- vertical flexure
namespace {
Chain vertical_flexure_chain(const VerticalFlexureParams& p, double hh) {
  const double t = p.thickness, z0 = p.base_z, zt = p.base_z + p.height, zh = z0 + hh;
  Block lower, upper;
  lower.name = "lower";
  upper.name = "upper";
  lower.unit_weight = upper.unit_weight = p.unit_weight;
  lower.length = upper.length = p.length;
  lower.polygon = {V(0.0, z0), V(0.0, zh), V(-t, zh), V(-t, z0)};
  upper.polygon = {V(0.0, zh), V(0.0, zt), V(-t, zt), V(-t, zh)};
  Constraint top;
  top.type = ConstraintType::Slider;
  top.name = "top restraint";
  top.block = 1;
  top.point = V(0.0, zt);
  top.direction = V(0.0, 1.0);
  std::vector<Load> loads;
  if (p.top_load > 0.0) {
    loads.push_back(weight("top load", 1, V(-t + p.top_load_distance_from_inner_face, zt), p.top_load));
    // It bears on the upper block at the top restraint, which takes its
    // horizontal force: its point does not move horizontally (dx = 0), its
    // mass belongs to the building above (the exception of C8A.4.1 [R]);
    // counted in sum W it would only lower e* and raise a0* (issue 38,
    // docs/theory/mechanisms.md §0).
    loads.back().seismic = false;
  }
  return Chain({lower, upper},
               {ground_hinge("base hinge", 0, V(0.0, z0)), hinge("middle hinge", 0, 1, V(-t, zh)), top},
               loads);
}
}  // namespace

MechanismSet vertical_flexure(const VerticalFlexureParams& p) {
  require_positive(p.height, "vertical_flexure: height", "m");
  require_positive(p.thickness, "vertical_flexure: thickness", "m");
  require_positive(p.unit_weight, "vertical_flexure: unit_weight", "kN/m^3");
  require_positive(p.length, "vertical_flexure: length", "m");
  require_non_negative(p.top_load, "vertical_flexure: top_load", "kN");
  require_non_negative(p.base_z, "vertical_flexure: base_z", "m");
  if (!(p.top_load_distance_from_inner_face >= 0.0 && p.top_load_distance_from_inner_face <= p.thickness))
    throw InputError("vertical_flexure: top_load_distance_from_inner_face must lie in [0, thickness] m");
  MechanismSet set;
  set.type = "vertical_flexure";
  set.parameter_name = "hinge height above the base (m)";
  set.searched = !p.hinge_height.has_value();
  const double Z = p.base_z + 0.5 * p.height;  // centroid of the bottom and top restraints
  auto add = [&](double hh) {
    set.candidates.push_back({"middle hinge at " + fmt("%.3f", hh) + " m above the base",
                              vertical_flexure_chain(p, hh), Z, hh});
  };
  if (p.hinge_height) {
    if (!(*p.hinge_height > 0.0 && *p.hinge_height < p.height))
      throw InputError("vertical_flexure: hinge_height must lie in (0, height) m");
    add(*p.hinge_height);
    return set;
  }
  if (p.search_points < 3) throw InputError("vertical_flexure: search_points must be >= 3");
  const int m = p.search_points;
  for (int i = 1; i <= m; ++i) add(p.height * i / (m + 1));
  // Refine around the best grid point by golden section on alpha0.
  const std::size_t g = governing_candidate(set);
  const double step = p.height / (m + 1);
  const double best = golden_minimum(
      [&](double hh) { return activation_multiplier(vertical_flexure_chain(p, hh)); },
      std::max(set.candidates[g].parameter - step, 1e-3 * p.height),
      std::min(set.candidates[g].parameter + step, (1 - 1e-3) * p.height), 1e-6 * p.height);
  add(best);
  set.candidates.back().label += " (minimum of alpha0)";
  return set;
}

// ---------------------------------------------------------------- composite overturning
MechanismSet composite_overturning(const CompositeOverturningParams& p) {
  const std::string lab = "composite_overturning: ";
  require_positive(p.height, lab + "height", "m");
  require_positive(p.thickness, lab + "thickness", "m");
  require_positive(p.length, lab + "length", "m");
  require_positive(p.unit_weight, lab + "unit_weight", "kN/m^3");
  require_positive(p.side_thickness, lab + "side_thickness", "m");
  require_positive(p.side_length, lab + "side_length", "m");
  require_non_negative(p.top_weight, lab + "top_weight", "kN");
  require_non_negative(p.tie, lab + "tie", "kN");
  if (p.side_walls != 1 && p.side_walls != 2) throw InputError(lab + "side_walls must be 1 or 2");
  MechanismSet set;
  set.type = "composite_overturning";
  set.parameter_name = "wedge angle beta from the vertical (deg)";
  const std::vector<double> betas = wedge_angles(lab, p, set.searched);
  const double t = p.thickness, z0 = p.base_z, zt = p.base_z + p.height;
  for (double beta : betas) {
    // The wedge: triangle from the façade's inner face at the hinge level up
    // to the top, reaching inward by height * tan(beta) (bounded by the side wall).
    // When the side wall is too short the crack meets its end at zc and the
    // wedge is a trapezoid.
    const double tb = std::tan(beta * units::deg);
    const double reach = std::min(p.height * tb, p.side_length);
    const double zc = z0 + reach / tb;
    Block facade, wedge;
    facade.name = "facade";
    facade.unit_weight = wedge.unit_weight = p.unit_weight;
    facade.length = p.length;
    facade.polygon = {V(0.0, z0), V(0.0, zt), V(-t, zt), V(-t, z0)};
    wedge.name = "side-wall wedge";
    wedge.length = p.side_walls * p.side_thickness;
    wedge.polygon = {V(-t, z0), V(-t, zt), V(-t - reach, zt)};
    if (p.height * tb > p.side_length) wedge.polygon = {V(-t, z0), V(-t, zt), V(-t - reach, zt), V(-t - reach, zc)};
    // Two hinges at distinct points weld the wedge to the façade (rank 3).
    std::vector<Constraint> cons{ground_hinge("base hinge", 0, V(0.0, z0)),
                                 hinge("weld bottom", 0, 1, V(-t, z0)), hinge("weld top", 0, 1, V(-t, zt))};
    std::vector<Load> loads;
    if (p.top_weight > 0.0) {
      loads.push_back(weight("top load", 0, V(-0.5 * t, zt), p.top_weight));
      loads.back().seismic = !p.top_weight_held;  // issue 38
    }
    if (p.tie > 0.0) loads.push_back(force(LoadType::Tie, "tie", 0, V(-0.5 * t, zt), V(-p.tie, 0.0)));
    MechanismCandidate c{"wedge beta = " + fmt("%.1f", beta) + " deg", Chain({facade, wedge}, cons, loads), z0, beta};
    // Issue 38: the wedges hang on the façade by the interlocking; the body
    // bears on the hinge through the façade: bounded by its own overturning.
    c.rotation_bound = bearing_part_rotation(c.chain, 0);
    c.rotation_bound_reason = "the façade's own overturning about its hinge";
    c.quantities = {{"rotation bound: the façade's weight and its loads over the hinge", c.rotation_bound, "rad",
                     "docs/theory/mechanisms.md §5 [I]"}};
    set.candidates.push_back(std::move(c));
  }
  return set;
}

// ---------------------------------------------------------------- gable
MechanismSet gable_overturning(const GableParams& p) {
  const std::string lab = "gable_overturning: ";
  require_positive(p.width, lab + "width", "m");
  require_positive(p.height, lab + "height", "m");
  require_positive(p.thickness, lab + "thickness", "m");
  require_positive(p.unit_weight, lab + "unit_weight", "kN/m^3");
  require_non_negative(p.ridge_weight, lab + "ridge_weight", "kN");
  require_non_negative(p.tie, lab + "tie", "kN");
  require_non_negative(p.base_z, lab + "base_z", "m");
  if (p.slices < 2) throw InputError(lab + "slices must be >= 2");
  const double t = p.thickness, z0 = p.base_z, dz = p.height / p.slices;
  std::vector<Block> blocks;
  std::vector<Constraint> cons{ground_hinge("base hinge", 0, V(0.0, z0))};
  for (int i = 0; i < p.slices; ++i) {
    Block b;
    b.name = "slice " + std::to_string(i);
    b.unit_weight = p.unit_weight;
    // Mean width of the triangle over the slice: its weight is exact.
    b.length = p.width * (1.0 - (i + 0.5) / p.slices);
    const double za = z0 + i * dz, zb = za + dz;
    b.polygon = {V(0.0, za), V(0.0, zb), V(-t, zb), V(-t, za)};
    if (i > 0) {
      cons.push_back(hinge("joint " + std::to_string(i) + " outer", i - 1, i, V(0.0, za)));
      cons.push_back(hinge("joint " + std::to_string(i) + " inner", i - 1, i, V(-t, za)));
    }
    blocks.push_back(b);
  }
  const int top = p.slices - 1;
  const V apex(-0.5 * t, z0 + p.height);
  std::vector<Load> loads;
  if (p.ridge_weight > 0.0) {
    loads.push_back(weight("ridge beam", top, apex, p.ridge_weight));
    loads.back().seismic = !p.ridge_weight_held;  // issue 38
  }
  if (p.ridge_thrust != 0.0) loads.push_back(force(LoadType::Force, "ridge thrust", top, apex, V(p.ridge_thrust, 0.0)));
  if (p.tie > 0.0) loads.push_back(force(LoadType::Tie, "tie", top, apex, V(-p.tie, 0.0)));
  MechanismSet set;
  set.type = "gable_overturning";
  set.parameter_name = "-";
  set.candidates.push_back({"gable about its base", Chain(blocks, cons, loads), z0, 0.0});
  return set;
}

}  // namespace assess

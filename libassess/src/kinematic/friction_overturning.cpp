// friction_overturning.cpp: overturning of a façade held by the friction of
// its interlocking with the side walls, and the composite wedge of the same
// crack (issue 33; docs/theory/mechanisms.md §2).
//
// Notation: h façade height above the hinge z0, t thickness, L length, gamma
// unit weight, b side-wall thickness, f friction coefficient, kappa
// activation, q load on the side walls (N/m), alpha_b crack angle from the
// vertical, v = unit_length/2 the units' overlap, h_c the height over which
// the crack steps through the side wall (h, or side_length/tan(alpha_b) when
// the crack reaches the wall's end first). Outer face x = 0, façade at x < 0.
#include "assess/kinematic/friction_overturning.hpp"

#include "kinematic/catalogue_helpers.hpp"

#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>

namespace assess {

using namespace catalogue;

SideWallFriction side_wall_friction(const FrictionOverturningParams& p) {
  SideWallFriction s;
  const double h = p.height;
  s.tan_alpha = 0.5 * p.unit_length / p.course_height;
  s.reach = std::min(h * s.tan_alpha, p.side_length);
  s.crack_height = std::min(h, p.side_length / s.tan_alpha);
  const double hc = s.crack_height;
  // The bed joint at height y above the hinge carries, on its overlap of
  // width v per course, the column of side wall above it: gamma b v (h - y)
  // per course, i.e. gamma b tan(alpha_b) (h - y) per unit height of crack
  // (Argiento et al. 2018 eq. (5) [V-p], continuum [D]).
  const double k = p.friction * p.unit_weight * p.side_thickness * s.tan_alpha;
  s.F_g = k * (h * hc - 0.5 * hc * hc);
  s.z_g = (0.5 * h * hc * hc - hc * hc * hc / 3.0) / (h * hc - 0.5 * hc * hc);
  // The load q adds q v per course on every step (eq. (6) [V-p]).
  s.F_q = p.friction * p.side_load * s.tan_alpha * hc;
  s.z_q = 0.5 * hc;
  return s;
}

namespace {

struct Built {
  std::vector<Block> blocks;
  std::vector<Constraint> cons;
  std::vector<Load> loads;
};

// The façade with its own loads (top weight, tie, floors): the bare wall.
Built facade(const FrictionOverturningParams& p, bool floor_friction) {
  const double t = p.thickness, z0 = p.base_z, zt = z0 + p.height;
  Built b;
  Block f;
  f.name = "facade";
  f.unit_weight = p.unit_weight;
  f.length = p.length;
  f.polygon = {V(0.0, z0), V(0.0, zt), V(-t, zt), V(-t, z0)};
  b.blocks.push_back(f);
  b.cons.push_back(ground_hinge("base hinge", 0, V(0.0, z0)));
  if (p.top_weight > 0.0) {
    b.loads.push_back(weight("top load", 0, V(-0.5 * t, zt), p.top_weight));
    b.loads.back().seismic = !p.top_weight_held;  // issue 38: it pushes with the façade unless held
  }
  if (p.tie > 0.0) b.loads.push_back(force(LoadType::Tie, "tie", 0, V(-0.5 * t, zt), V(-p.tie, 0.0)));
  for (std::size_t i = 0; i < p.floors.size(); ++i) {
    const SupportedFloor& fl = p.floors[i];
    const V at(-t + fl.distance_from_inner_face, fl.z);
    const std::string n = "supported floor " + std::to_string(i + 1);
    if (fl.weight > 0.0) {
      Load w = weight(n, 0, at, fl.weight);
      w.seismic = !fl.held;  // held by the building: its mass does not push the façade
      b.loads.push_back(w);
    }
    if (floor_friction && fl.held && fl.friction * fl.weight > 0.0) {
      Load fr = force(LoadType::Friction, "seat friction " + std::to_string(i + 1), 0, at,
                      V(fl.friction * fl.weight, 0.0));
      fr.slip_limit = fl.seat_length;
      b.loads.push_back(fr);
    }
  }
  return b;
}

double alpha0_of(const Built& b) { return activation_multiplier(Chain(b.blocks, b.cons, b.loads)); }

}  // namespace

MechanismSet friction_overturning(const FrictionOverturningParams& p) {
  const std::string lab = "friction_overturning: ";
  require_positive(p.height, lab + "height", "m");
  require_positive(p.thickness, lab + "thickness", "m");
  require_positive(p.length, lab + "length", "m");
  require_positive(p.unit_weight, lab + "unit_weight", "kN/m^3");
  require_non_negative(p.base_z, lab + "base_z", "m");
  require_positive(p.side_thickness, lab + "side_thickness", "m");
  require_positive(p.side_length, lab + "side_length", "m");
  require_positive(p.unit_length, lab + "unit_length", "m");
  require_positive(p.course_height, lab + "course_height", "m");
  require_positive(p.friction, lab + "friction", "-");
  require_non_negative(p.side_load, lab + "side_load", "kN/m");
  require_non_negative(p.top_weight, lab + "top_weight", "kN");
  require_non_negative(p.tie, lab + "tie", "kN");
  if (p.side_walls != 1 && p.side_walls != 2) throw InputError(lab + "side_walls must be 1 or 2");
  if (!(p.activation >= 0.0 && p.activation <= 1.0)) throw InputError(lab + "activation must lie in [0, 1]");
  for (std::size_t i = 0; i < p.floors.size(); ++i) {
    const SupportedFloor& f = p.floors[i];
    const std::string fl = lab + "floors[" + std::to_string(i) + "].";
    require_non_negative(f.weight, fl + "weight", "kN");
    require_non_negative(f.friction, fl + "friction", "-");
    if (!(f.z > p.base_z && f.z <= p.base_z + p.height))
      throw InputError(fl + "z must lie on the façade, in (base_z, base_z + height] m");
    if (!(f.distance_from_inner_face >= 0.0 && f.distance_from_inner_face <= p.thickness))
      throw InputError(fl + "distance_from_inner_face must lie in [0, thickness] m");
    if (!(f.seat_length > 0.0)) throw InputError(fl + "seat_length must be > 0 m");
  }
  const double t = p.thickness, z0 = p.base_z, zt = z0 + p.height;
  const SideWallFriction sf = side_wall_friction(p);
  const double n = p.side_walls * p.activation, v = 0.5 * p.unit_length;

  MechanismSet set;
  set.type = "friction_overturning";
  set.parameter_name = "side walls' mechanism (1 friction, 2 wedge)";

  // Candidate 1: the façade slides out of the side walls.
  Built fr = facade(p, true);
  if (n * sf.F_g > 0.0) {
    Load l = force(LoadType::Friction, "side walls' friction (masonry)", 0, V(-t, z0 + sf.z_g), V(n * sf.F_g, 0.0));
    l.slip_limit = v;
    fr.loads.push_back(l);
  }
  if (n * sf.F_q > 0.0) {
    Load l = force(LoadType::Friction, "side walls' friction (load)", 0, V(-t, z0 + sf.z_q), V(n * sf.F_q, 0.0));
    l.slip_limit = v;
    fr.loads.push_back(l);
  }

  // Candidate 2: the side walls' wedges of the same crack turn with the façade.
  Built wd = facade(p, true);
  {
    const double tb = sf.tan_alpha, reach = sf.reach, zc = z0 + reach / tb;
    Block w;
    w.name = "side-wall wedge";
    w.unit_weight = p.unit_weight;
    w.length = p.side_walls * p.side_thickness;
    w.polygon = {V(-t, z0), V(-t, zt), V(-t - reach, zt)};
    if (p.height * tb > p.side_length) w.polygon = {V(-t, z0), V(-t, zt), V(-t - reach, zt), V(-t - reach, zc)};
    wd.blocks.push_back(w);
    wd.cons.push_back(hinge("weld bottom", 0, 1, V(-t, z0)));
    wd.cons.push_back(hinge("weld top", 0, 1, V(-t, zt)));
    if (p.side_load * reach > 0.0) {
      // Issue 38: the load rests on the wedges and turns with them: its mass
      // pushes (C8.7.1.1's Q weights) unless the case holds it.
      Load q = weight("side walls' load on the wedges", 1, V(-t - 0.5 * reach, zt), p.side_load * reach * p.side_walls);
      q.seismic = !p.side_load_held;
      wd.loads.push_back(q);
    }
  }

  const double a_bare = alpha0_of(facade(p, false));
  const double a_bare_seat = alpha0_of(facade(p, true));
  const double a_fr = alpha0_of(fr), a_wd = alpha0_of(wd);
  const std::string src = "docs/theory/mechanisms.md §2.2 [D]";
  std::vector<MechanismQuantity> q = {
      {"crack angle α_b from the texture, tan α_b = (unit length/2)/(course height)", std::atan(sf.tan_alpha) / units::deg,
       "°", "Szabó et al. 2023 eq. (3) [V-p]"},
      {"crack reach at the top of the side wall", sf.reach, "m", src},
      {"friction coefficient f", p.friction, "-", "input"},
      {"activation κ", p.activation, "-", "input; docs/theory/mechanisms.md §2.2"},
      {"side wall friction F_g (masonry), each", sf.F_g / units::kN, "kN",
       "f·γ·b·tan α_b·h²/2; Argiento et al. 2018 eq. (5) [V-p]"},
      {"its height above the hinge", sf.z_g, "m", src},
      {"side wall friction F_q (load q), each", sf.F_q / units::kN, "kN", "f·q·tan α_b·h; Argiento et al. 2018 eq. (6) [V-p]"},
      {"its height above the hinge", sf.z_q, "m", src},
      {"slip that disengages the steps (unit length/2)", v, "m", src},
      {"α0 of the bare façade (no interlocking, no seat friction)", a_bare, "-", "C8.7.1.1"},
  };
  if (std::fabs(a_bare_seat - a_bare) > 1e-12)
    q.push_back({"α0 of the façade with the floors' seat friction only", a_bare_seat, "-", src});
  q.push_back({"α0 with the side walls' friction", a_fr, "-", src});
  q.push_back({"α0 with the side walls' wedges (composite)", a_wd, "-", "C8.7.1.1"});
  set.candidates.push_back({"facade sliding out of the side walls (friction)", Chain(fr.blocks, fr.cons, fr.loads), z0,
                            1.0, q});
  MechanismCandidate wc{"facade with the side walls' wedges", Chain(wd.blocks, wd.cons, wd.loads), z0, 2.0, q};
  // Issue 38: the wedges hang on the façade: bounded by its own overturning (§5).
  wc.rotation_bound = bearing_part_rotation(wc.chain, 0);
  wc.rotation_bound_reason = "the façade's own overturning about its hinge";
  wc.quantities.push_back({"rotation bound: the façade's weight and its loads over the hinge", wc.rotation_bound, "rad",
                           "docs/theory/mechanisms.md §5 [I]"});
  set.candidates.push_back(std::move(wc));
  set.data = {{"façade height above the hinge", p.height, "m", "input"},
              {"façade thickness", p.thickness, "m", "input"},
              {"façade length", p.length, "m", "input"},
              {"side walls", double(p.side_walls), "-", "input"},
              {"side wall thickness b", p.side_thickness, "m", "input"},
              {"side wall length available", p.side_length, "m", "input"},
              {"unit length", p.unit_length, "m", "input"},
              {"course height", p.course_height, "m", "input"},
              {"load on each side wall q", p.side_load / units::kN, "kN/m", "input"},
              {"unit weight γ", p.unit_weight / units::kN, "kN/m³", "input"}};
  return set;
}

}  // namespace assess

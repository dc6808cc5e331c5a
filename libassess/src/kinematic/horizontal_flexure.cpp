// horizontal_flexure.cpp: the three-hinge horizontal arch of a wall strip
// between transverse walls (issue 33; docs/theory/mechanisms.md §1).
//
// Notation: L span, t thickness, h strip height, h_s / h_m net heights of the
// sections at the supports / at the middle hinge, f compressive strength,
// H thrust, e = kb H/(f h) distance of a hinge (the stress block's resultant)
// from its face (kb = 1/2 rectangular, 2/3 triangular block), z = t - e_s - e_m
// the arch's lever arm, u_m the middle hinge's distance from the first
// support, w = gamma t h, n carried weight per metre. The chain is drawn in
// plan: x outward (outer face x = 0, wall at x < 0), the chain's z = u.
#include "assess/kinematic/horizontal_flexure.hpp"

#include "kinematic/catalogue_helpers.hpp"

#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace assess {

using namespace catalogue;

namespace {

double block_factor(StressBlock b) { return b == StressBlock::Rectangular ? 0.5 : 2.0 / 3.0; }

// Net height of the strip on (u0, u1) (m): the strip's height less the
// tallest opening over that stretch.
double net_height(const HorizontalStrip& s, double u0, double u1) {
  double cut = 0.0;
  for (const StripOpening& o : s.openings)
    if (o.from < u1 - 1e-9 && o.to > u0 + 1e-9) cut = std::max(cut, o.height);
  return s.height - cut;
}

// The strip cut at the supports, the openings' edges and the middle hinge
// u_m: segments [u_i, u_i+1] of net height hn_i, the first right of u_m at
// im, the thrust of the sections at the supports and at the middle hinge.
struct StripGeometry {
  std::vector<double> u, hn;
  std::size_t im = 0;
  double h_support = 0.0, h_middle = 0.0;
  ArchThrust thrust;
};

StripGeometry strip_geometry(const HorizontalFlexureParams& p, const HorizontalStrip& s, double um) {
  const double L = p.span;
  StripGeometry g;
  std::set<double> cuts = {0.0, L, um};
  for (const StripOpening& o : s.openings) {
    if (o.from > 0.0 && o.from < L) cuts.insert(o.from);
    if (o.to > 0.0 && o.to < L) cuts.insert(o.to);
  }
  g.u.assign(cuts.begin(), cuts.end());
  g.u.erase(std::unique(g.u.begin(), g.u.end(), [](double a, double b) { return std::fabs(a - b) < 1e-9; }), g.u.end());
  const std::size_t nseg = g.u.size() - 1;
  g.hn.resize(nseg);
  for (std::size_t i = 0; i < nseg; ++i) {
    g.hn[i] = net_height(s, g.u[i], g.u[i + 1]);
    if (std::fabs(g.u[i] - um) < 1e-9) g.im = i;
  }
  g.h_support = std::min(g.hn.front(), g.hn.back());
  g.h_middle = std::min(g.hn[g.im - 1], g.hn[g.im]);
  g.thrust = arch_thrust(p, g.h_support, g.h_middle);
  return g;
}

struct StripChain {
  Chain chain;
  ArchThrust thrust;
  double h_support = 0.0, h_middle = 0.0, ring_force = 0.0;
};

StripChain strip_chain(const HorizontalFlexureParams& p, const HorizontalStrip& s, double um) {
  const double L = p.span, t = p.thickness;
  const StripGeometry g = strip_geometry(p, s, um);
  const std::vector<double>& u = g.u;
  const std::vector<double>& hn = g.hn;
  const std::size_t nseg = u.size() - 1, im = g.im;
  const double h_support = g.h_support, h_middle = g.h_middle;
  const ArchThrust thrust = g.thrust;
  const double es = thrust.e_support, em = thrust.e_middle, H = thrust.H;
  double ring_force = 0.0;
  std::vector<Block> blocks;
  std::vector<Constraint> cons;
  std::vector<Load> loads;
  for (std::size_t i = 0; i < nseg; ++i) {
    Block b;
    b.name = std::string(i < im ? "left" : "right") + " half" + (s.carried_weight > 0.0 ? " with the carried weight" : "") +
             ", u = " + fmt("%.2f", u[i]) + "-" + fmt("%.2f", u[i + 1]) + " m";
    b.unit_weight = p.unit_weight;
    // The carried weight n moves with the strip and is spread like it along
    // the wall: part of the block's mass (an equivalent height n/(gamma t)),
    // so that its integral of dx^2 dW is exact (C8A.4.2).
    b.length = hn[i] + s.carried_weight / (p.unit_weight * t);
    b.weight_in_plane = false;
    b.polygon = {V(0.0, u[i]), V(0.0, u[i + 1]), V(-t, u[i + 1]), V(-t, u[i])};
    blocks.push_back(b);
    if (i > 0 && i != im) {  // consecutive segments of one half: welded along their common edge
      cons.push_back(hinge("joint u = " + fmt("%.2f", u[i]) + " m, outer", int(i) - 1, int(i), V(0.0, u[i])));
      cons.push_back(hinge("joint u = " + fmt("%.2f", u[i]) + " m, inner", int(i) - 1, int(i), V(-t, u[i])));
    }
  }
  cons.insert(cons.begin(), ground_hinge("support hinge u = 0", 0, V(-es, 0.0)));
  cons.push_back(hinge("middle hinge", int(im) - 1, int(im), V(-t + em, um)));
  cons.push_back(slider("support u = L (the supports separate)", int(nseg) - 1, V(-es, L), V(0.0, 1.0)));
  loads.push_back(force(LoadType::Force, "arch thrust", int(nseg) - 1, V(-es, L), V(0.0, -H)));
  if (p.ring_beam_moment > 0.0) {
    // Simply supported ring beam with a plastic hinge at u_m: M_Rd (theta_A +
    // theta_B) = F dx_m with dx_m = theta_A u_m = theta_B (L - u_m). The
    // force acts where the beam's hinge is, on the beam's axis: the wall's
    // centre line at u_m (issue 38; docs/theory/mechanisms.md §1.2: at
    // finite rotation the closer constant force to the exact M_Rd (theta_A
    // + theta_B): within 0.5 % of it up to the worked example's theta_0, a
    // force at the middle hinge 1.9 %).
    ring_force = p.ring_beam_moment * L / (um * (L - um));
    loads.push_back(force(LoadType::Force, "ring beam", int(im) - 1, V(-0.5 * t, um), V(-ring_force, 0.0)));
  }
  return {Chain(blocks, cons, loads), thrust, h_support, h_middle, ring_force};
}

}  // namespace

double strip_alpha0(const HorizontalFlexureParams& p, const HorizontalStrip& s, double um) {
  // Virtual work of the chain of strip_chain (docs/theory/mechanisms.md §1.3,
  // (1.3)): the left half turns by theta about its support hinge, the right
  // half by theta u_m/(L - u_m) about the other, whose support slides apart
  // by s = z theta L/(L - u_m); a point at u moves outward by theta u (left)
  // or theta u_m (L - u)/(L - u_m) (right); the thrust -H does -H s, the ring
  // beam's force M_Rd L/(u_m (L - u_m)) at the middle hinge -M_Rd L/(L - u_m)
  // theta. Each segment's mass W_i = gamma t (u_i+1 - u_i) hn_i + n (u_i+1 -
  // u_i) at its middle.
  const double L = p.span;
  const StripGeometry g = strip_geometry(p, s, um);
  double left = 0.0, right = 0.0;
  for (std::size_t i = 0; i + 1 < g.u.size(); ++i) {
    const double du = g.u[i + 1] - g.u[i], uc = 0.5 * (g.u[i] + g.u[i + 1]);
    const double W = p.unit_weight * p.thickness * du * g.hn[i] + s.carried_weight * du;
    (i < g.im ? left : right) += i < g.im ? W * uc : W * (L - uc);
  }
  const double z = p.thickness - g.thrust.e_support - g.thrust.e_middle;
  const double work_out = left + um / (L - um) * right;
  return L / (L - um) * (g.thrust.H * z + p.ring_beam_moment) / work_out;
}

ArchThrust arch_thrust(const HorizontalFlexureParams& p, double h_s, double h_m) {
  ArchThrust a;
  const double kb = block_factor(p.stress_block), t = p.thickness, f = p.strength;
  // z = t - kb H/f (1/h_s + 1/h_m) = t - k H; H z is largest at H_c = t/(2k), z = t/2.
  const double k = kb / f * (1.0 / h_s + 1.0 / h_m);
  a.H_c = t / (2.0 * k);
  a.H_lim = p.rigid_supports ? std::numeric_limits<double>::infinity()
                             : p.tie + p.side_wall_friction * p.side_wall_load + p.restraint;
  a.crushing = a.H_c <= a.H_lim;
  a.H = std::min(a.H_c, a.H_lim);
  a.e_support = kb * a.H / (f * h_s);
  a.e_middle = kb * a.H / (f * h_m);
  return a;
}

MechanismSet horizontal_flexure(const HorizontalFlexureParams& p) {
  const std::string lab = "horizontal_flexure: ";
  require_positive(p.span, lab + "span", "m");
  require_positive(p.thickness, lab + "thickness", "m");
  require_positive(p.unit_weight, lab + "unit_weight", "kN/m^3");
  require_positive(p.strength, lab + "strength", "MPa");
  require_non_negative(p.tie, lab + "tie", "kN");
  require_non_negative(p.side_wall_friction, lab + "side_wall_friction", "-");
  require_non_negative(p.side_wall_load, lab + "side_wall_load", "kN");
  require_non_negative(p.restraint, lab + "restraint", "kN");
  require_non_negative(p.ring_beam_moment, lab + "ring_beam_moment", "kN m");
  if (!p.rigid_supports && !(p.tie + p.side_wall_friction * p.side_wall_load + p.restraint > 0.0))
    throw InputError(lab + "the supports take no thrust (no tie, no side walls' friction, no given restraint, not "
                     "rigid): no horizontal arch can form; the strip overturns instead (simple overturning)");
  if (p.strips.empty()) throw InputError(lab + "'strips' needs at least one strip");
  if (p.search_points < 3) throw InputError(lab + "search_points must be >= 3");
  MechanismSet set;
  set.type = "horizontal_flexure";
  set.parameter_name = "strip mid-height z (m)";
  for (std::size_t k = 0; k < p.strips.size(); ++k) {
    const HorizontalStrip& s = p.strips[k];
    const std::string sl = lab + "strips[" + std::to_string(k) + "].";
    require_non_negative(s.base_z, sl + "base_z", "m");
    require_positive(s.height, sl + "height", "m");
    require_non_negative(s.carried_weight, sl + "carried_weight", "kN/m");
    std::vector<double> edges;
    for (std::size_t j = 0; j < s.openings.size(); ++j) {
      const StripOpening& o = s.openings[j];
      const std::string ol = sl + "openings[" + std::to_string(j) + "].";
      if (!(o.from >= 0.0 && o.to > o.from && o.to <= p.span))
        throw InputError(ol + "expected 0 <= from < to <= span m (along the wall from the first support)");
      if (!(o.height > 0.0 && o.height < s.height))
        throw InputError(ol + "height must lie in (0, strip height) m: an opening through the whole strip "
                         "interrupts the horizontal arch (choose a strip above or below it)");
      for (double e : {o.from, o.to})
        if (e > 1e-6 * p.span && e < (1 - 1e-6) * p.span) edges.push_back(e);
    }
    // The middle hinge: mid-span for a uniform strip, else the minimum of
    // alpha0 over a grid and the openings' edges, refined by golden section.
    // alpha0 in closed form (strip_alpha0, equal to the chain's virtual work,
    // unit test): the search costs microseconds instead of a chain analysis
    // per point (issue 39: 57 s of CPU for one mechanism at its caps).
    auto alpha = [&](double um) { return strip_alpha0(p, s, um); };
    double um = 0.5 * p.span;
    if (s.middle_hinge) {
      if (!(*s.middle_hinge > 0.0 && *s.middle_hinge < p.span))
        throw InputError(sl + "middle_hinge must lie in (0, span) m");
      um = *s.middle_hinge;
    } else if (!s.openings.empty()) {
      std::vector<double> grid = edges;
      for (int i = 1; i <= p.search_points; ++i) grid.push_back(p.span * i / (p.search_points + 1));
      std::sort(grid.begin(), grid.end());
      double best = 1e300;
      std::size_t ib = 0;
      for (std::size_t i = 0; i < grid.size(); ++i) {
        const double a = alpha(grid[i]);
        if (a < best) best = a, ib = i;
      }
      um = grid[ib];
      const double lo = ib > 0 ? grid[ib - 1] : 1e-3 * p.span, hi = ib + 1 < grid.size() ? grid[ib + 1] : (1 - 1e-3) * p.span;
      const double g = golden_minimum(alpha, lo, hi, 1e-6 * p.span);
      if (alpha(g) < best) um = g;
    }
    const StripChain sc = strip_chain(p, s, um);
    const ArchThrust& a = sc.thrust;
    const double zm = s.base_z + 0.5 * s.height;
    const std::string src = "docs/theory/mechanisms.md §1.2 [D]";
    std::vector<MechanismQuantity> q = {
        {"strip: bottom z", s.base_z, "m", "input"},
        {"strip: height h", s.height, "m", "input"},
        {"middle hinge from the first support u_m", um, "m",
         s.middle_hinge ? "input" : s.openings.empty() ? src : "minimum of α0"},
        {"net height at the supports", sc.h_support, "m", src},
        {"net height at the middle hinge", sc.h_middle, "m", src},
        {"weight of the strip per metre w = γ t h", p.unit_weight * p.thickness * s.height / units::kN, "kN/m", src},
        {"carried weight per metre n", s.carried_weight / units::kN, "kN/m", "input"},
        {"crushing thrust H_c (lever arm t/2)", a.H_c / units::kN, "kN", "(1.2) " + src},
    };
    if (std::isfinite(a.H_lim)) q.push_back({"restraint of the supports H_lim", a.H_lim / units::kN, "kN", "(1.1) " + src});
    q.push_back({a.crushing ? "arch thrust H = H_c (crushing at the hinges governs)"
                            : "arch thrust H = H_lim (the restraint governs)",
                 a.H / units::kN, "kN", src});
    q.push_back({"support hinges from the outer face", a.e_support, "m", "C8.7.1.2.1 d) [V-T]; " + src});
    q.push_back({"middle hinge from the inner face", a.e_middle, "m", "C8.7.1.2.1 d) [V-T]; " + src});
    q.push_back({"lever arm of the arch z", p.thickness - a.e_support - a.e_middle, "m", src});
    if (sc.ring_force > 0.0)
      q.push_back({"ring beam: force at u_m on the beam's axis (the wall's centre line) M_Rd L/(u_m (L - u_m))",
                   sc.ring_force / units::kN, "kN", "docs/theory/mechanisms.md §1.2 [D]"});
    set.candidates.push_back({"strip z = " + fmt("%.2f", s.base_z) + "-" + fmt("%.2f", s.base_z + s.height) +
                                  " m, middle hinge at u = " + fmt("%.2f", um) + " m",
                              sc.chain, zm, zm, q});
  }
  set.data = {{"span between the transverse walls L", p.span, "m", "input"},
              {"thickness t", p.thickness, "m", "input"},
              {"unit weight γ", p.unit_weight / units::kN, "kN/m³", "input"},
              {"compressive strength at the hinges f (f_m/FC)", p.strength / 1e6, "MPa", "C8.7.1.2.1 d) [V-T]"},
              {p.stress_block == StressBlock::Rectangular ? "stress block: rectangular, H = f h a, at a/2"
                                                          : "stress block: triangular, H = f h a/2, at a/3",
               0.0, "", "docs/theory/mechanisms.md §1.2 [D]"}};
  if (p.rigid_supports) set.data.push_back({"supports: rigid abutments", 0.0, "", "input"});
  if (p.tie > 0.0) set.data.push_back({"tie across the span (design strength)", p.tie / units::kN, "kN", "input"});
  if (p.side_wall_friction * p.side_wall_load > 0.0) {
    set.data.push_back({"side walls: friction μ", p.side_wall_friction, "-", "input"});
    set.data.push_back({"side walls: normal force N at the strip, each end", p.side_wall_load / units::kN, "kN", "input"});
  }
  if (p.restraint > 0.0) set.data.push_back({"given restraint of the supports", p.restraint / units::kN, "kN", "input"});
  if (p.ring_beam_moment > 0.0)
    set.data.push_back({"ring beam: plastic moment in plan M_Rd", p.ring_beam_moment / units::kN, "kN m", "input"});
  return set;
}

}  // namespace assess

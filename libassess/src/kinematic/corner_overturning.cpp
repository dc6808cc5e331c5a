// corner_overturning.cpp: the corner wedge (ribaltamento del cantonale) about
// any horizontal axis through the outer corner edge (issue 33;
// docs/theory/kinematic.md §5, docs/theory/mechanisms.md §4).
//
// Plan: the corner's outer edge at the origin, the building at x > 0, y > 0;
// wall A along x (thickness t_A, 0 <= y <= t_A), wall B along y (thickness
// t_B, 0 <= x <= t_B); the pier x in [0, t_B], y in [0, t_A]. Wall A's arm:
// x in [t_B, t_B + r_A(z)], r_A = min((z - z0) tan beta_A, L_A), less its
// openings; wall B's likewise in y from t_A. Axis: horizontal through the
// outer corner edge at z0, at psi from wall A: direction (cos psi, -sin psi),
// inward normal n = (S, C) = (sin psi, cos psi); the action is along -n. A
// point at plan position p has s = n . p (inward distance from the axis):
// rotating by theta about the axis it moves in the vertical plane normal to
// the axis, (s, z) -> R(theta)(s, z), so the planar chain in (x = -s, z) is
// exact when each piece keeps its weight, its s-centroid, its distribution
// in z and (for the dynamics) its variance in s.
//
// A piece of wall A whose slice at height z is x in [a(z), b(z)] (a, b linear
// in z) is drawn as the interval of width w = b - a centred at
// c = S (a + b)/2 + C t_A/2 with out-of-plane length t_A: weight gamma t_A w
// and first moment gamma t_A w c per unit height, as the 3-D slice. The
// slice's variance in s is S^2 w^2/12 + C^2 t_A^2/12, the drawn one w^2/12:
// Block::extra_gyration_sq takes the difference C^2 (t_A^2 - w^2)/12,
// weight-averaged over the piece (2-point Gauss in z: exact, the integrand is
// cubic). Wall B likewise with S <-> C. The pier is drawn as s in [0, 2 s_p],
// s_p = (S t_B + C t_A)/2, with length t_A t_B/(2 s_p): its axis edge is the
// ground hinge.
#include "assess/kinematic/mechanism_catalogue.hpp"

#include "kinematic/catalogue_helpers.hpp"

#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess {

using namespace catalogue;

namespace {

// One wall of the corner, resolved.
struct Wall {
  double t = 0.0;       // own thickness (m)
  double other = 0.0;   // the other wall's thickness: where the arm starts (m)
  double length = 0.0;  // beyond the other wall's inner face (m)
  double tanb = 0.0;    // tan of the crack angle
  std::vector<CornerOpening> openings;
};

struct Interval {
  double a0, a1, b0, b1;  // ends at the band's bottom and top (m)
};

// The arm's slices on each band of heights where their structure is fixed.
struct Band {
  double za, zb;
  std::vector<Interval> pieces;
};

std::vector<Band> arm_bands(const Wall& w, double z0, double zt) {
  auto reach = [&](double z) { return std::min((z - z0) * w.tanb, w.length); };
  std::vector<double> zs = {z0, zt};
  if (z0 + w.length / w.tanb < zt) zs.push_back(z0 + w.length / w.tanb);
  for (const CornerOpening& o : w.openings) {
    for (double z : {o.bottom, o.top})
      if (z > z0 && z < zt) zs.push_back(z);
    for (double e : {o.from, o.to}) {
      const double r = e - w.other;
      if (r > 0.0 && r < w.length && z0 + r / w.tanb < zt) zs.push_back(z0 + r / w.tanb);
    }
  }
  std::sort(zs.begin(), zs.end());
  std::vector<Band> out;
  for (std::size_t k = 0; k + 1 < zs.size(); ++k) {
    const double za = zs[k], zb = zs[k + 1];
    if (zb - za < 1e-9) continue;
    const double zm = 0.5 * (za + zb), tol = 1e-9 * std::max(1.0, w.length);
    // The slice at mid-band: [other, other + r] less the openings over the band.
    std::vector<std::pair<double, double>> iv = {{w.other, w.other + reach(zm)}};
    for (const CornerOpening& o : w.openings) {
      if (!(o.bottom <= za + 1e-12 && o.top >= zb - 1e-12)) continue;
      std::vector<std::pair<double, double>> next;
      for (const auto& x : iv) {
        if (o.to <= x.first || o.from >= x.second) {
          next.push_back(x);
          continue;
        }
        if (o.from > x.first) next.push_back({x.first, o.from});
        if (o.to < x.second) next.push_back({o.to, x.second});
      }
      iv = next;
    }
    Band b{za, zb, {}};
    // Each end is the reach edge (linear in z) or a constant.
    auto at = [&](double v, double z) {
      return std::fabs(v - (w.other + reach(zm))) <= tol ? w.other + reach(z) : v;
    };
    for (const auto& x : iv)
      if (x.second - x.first > tol) b.pieces.push_back({at(x.first, za), at(x.first, zb), at(x.second, za), at(x.second, zb)});
    out.push_back(b);
  }
  return out;
}

struct Axis {
  double S, C;  // sin, cos of psi
};

// The chain of the corner about the axis at psi (deg).
MechanismCandidate corner_candidate(const CornerOverturningParams& p, const Wall& A, const Wall& B, double psi,
                                    const std::string& crack_label) {
  const double S = std::sin(psi * units::deg), C = std::cos(psi * units::deg);
  const double z0 = p.base_z, zt = p.base_z + p.height, g = p.unit_weight;
  std::vector<Block> blocks;
  std::vector<Constraint> cons;
  std::vector<Load> loads;
  // The pier.
  const double sp = 0.5 * (S * B.t + C * A.t);
  Block pier;
  pier.name = "corner pier";
  pier.unit_weight = g;
  pier.length = A.t * B.t / (2.0 * sp);
  pier.polygon = {V(0.0, z0), V(0.0, zt), V(-2.0 * sp, zt), V(-2.0 * sp, z0)};
  pier.extra_gyration_sq = (S * S * B.t * B.t + C * C * A.t * A.t) / 12.0 - sp * sp / 3.0;
  blocks.push_back(pier);
  cons.push_back(ground_hinge("corner hinge", 0, V(0.0, z0)));
  // The arms.
  const double gauss = 0.5 / std::sqrt(3.0);
  for (int wi = 0; wi < 2; ++wi) {
    const Wall& W = wi == 0 ? A : B;
    // s of the slice's centre: wall A's pieces run along x (S), B's along y (C).
    const double along = wi == 0 ? S : C, across = wi == 0 ? C : S;
    int k = 0;
    for (const Band& band : arm_bands(W, z0, zt))
      for (const Interval& iv : band.pieces) {
        const double w0 = iv.b0 - iv.a0, w1 = iv.b1 - iv.a1;
        const double c0 = along * 0.5 * (iv.a0 + iv.b0) + across * 0.5 * W.t;
        const double c1 = along * 0.5 * (iv.a1 + iv.b1) + across * 0.5 * W.t;
        std::vector<V> poly = {V(-(c0 - 0.5 * w0), band.za), V(-(c1 - 0.5 * w1), band.zb),
                               V(-(c1 + 0.5 * w1), band.zb), V(-(c0 + 0.5 * w0), band.za)};
        std::vector<V> clean;
        for (const V& v : poly)
          if (clean.empty() || (v - clean.back()).norm() > 1e-12) clean.push_back(v);
        if (clean.size() > 1 && (clean.front() - clean.back()).norm() <= 1e-12) clean.pop_back();
        if (clean.size() < 3) continue;
        Block b;
        b.name = std::string(wi == 0 ? "wall A" : "wall B") + " arm" + (k > 0 ? " " + std::to_string(k + 1) : "");
        b.unit_weight = g;
        b.length = W.t;
        b.polygon = clean;
        // Weight-averaged across^2 (t^2 - w^2)/12 over the piece (w linear in z).
        double num = 0.0, den = 0.0;
        for (double xi : {0.5 - gauss, 0.5 + gauss}) {
          const double w = w0 + (w1 - w0) * xi;
          num += w * across * across * (W.t * W.t - w * w) / 12.0;
          den += w;
        }
        b.extra_gyration_sq = num / den;
        const int bi = int(blocks.size());
        blocks.push_back(b);
        cons.push_back(weld("weld " + b.name + " bottom", 0, bi, V(-sp, z0)));
        cons.push_back(weld("weld " + b.name + " top", 0, bi, V(-sp, zt)));
        ++k;
      }
  }
  const V top(-sp, zt);
  if (p.top_weight > 0.0) {
    loads.push_back(weight("top load", 0, top, p.top_weight));
    loads.back().seismic = !p.top_weight_held;  // issue 38: it pushes with the wedge unless held
  }
  const double thrust = p.thrust * std::cos((psi - 45.0) * units::deg);
  if (std::fabs(thrust) > 1e-9 * std::fabs(p.thrust) && p.thrust != 0.0)
    loads.push_back(force(LoadType::Force, "hip rafter thrust (normal to the axis)", 0, top, V(thrust, 0.0)));
  if (p.tie * S > 1e-9 * p.tie)
    loads.push_back(force(LoadType::Tie, "tie along wall A (normal to the axis)", 0, top, V(-p.tie * S, 0.0)));
  if (p.tie * C > 1e-9 * p.tie)
    loads.push_back(force(LoadType::Tie, "tie along wall B (normal to the axis)", 0, top, V(-p.tie * C, 0.0)));
  MechanismCandidate c{"axis at " + fmt("%.1f", psi) + " deg from wall A" + crack_label, Chain(blocks, cons, loads), z0,
                       psi};
  // The pier's own overturning: its weight and the top load pass over the
  // axis, tan theta_b = s_p / z_c (docs/theory/mechanisms.md §5).
  c.rotation_bound = bearing_part_rotation(c.chain, 0);
  c.rotation_bound_reason = "the corner pier's own overturning about the axis";
  double W = 0.0;
  for (const Load& l : c.chain.loads())
    if (l.type == LoadType::SelfWeight) W += l.weight;
  const std::string src = "docs/theory/mechanisms.md §4 [D]";
  c.quantities = {{"axis: angle from wall A (0: action normal to wall A)", psi, "°", src},
                  {"weight of the wedge", W / units::kN, "kN", src},
                  {"corner pier: lever arm of its centroid about the axis", sp, "m", src},
                  {"rotation bound: the pier's weight over the axis", c.rotation_bound, "rad", src}};
  return c;
}

Wall resolve(const CornerOverturningParams& p, const CornerWall& w, double other_t, const std::string& lab,
             std::optional<double> common_tanb) {
  Wall r;
  r.t = w.thickness.value_or(p.thickness);
  require_positive(r.t, lab + "thickness", "m");
  r.other = other_t;
  r.length = w.length.value_or(p.wall_length);
  require_positive(r.length, lab + "length", "m");
  if (w.beta_deg) {
    if (!(*w.beta_deg > 0.0 && *w.beta_deg < 90.0)) throw InputError(lab + "beta_deg must lie in (0, 90) deg");
    r.tanb = std::tan(*w.beta_deg * units::deg);
  } else if (w.unit_length || w.course_height) {
    if (!w.unit_length || !w.course_height)
      throw InputError(lab + "the texture needs both unit_length and course_height (m)");
    require_positive(*w.unit_length, lab + "unit_length", "m");
    require_positive(*w.course_height, lab + "course_height", "m");
    r.tanb = 0.5 * *w.unit_length / *w.course_height;
  } else if (w.crack_reach) {
    require_positive(*w.crack_reach, lab + "crack_reach", "m");
    if (*w.crack_reach > r.length) throw InputError(lab + "crack_reach must not exceed the wall's length (m)");
    r.tanb = *w.crack_reach / p.height;
  } else if (common_tanb) {
    r.tanb = *common_tanb;
  } else {
    throw InputError(lab + "the crack needs beta_deg, the texture or crack_reach");
  }
  for (std::size_t i = 0; i < w.openings.size(); ++i) {
    const CornerOpening& o = w.openings[i];
    const std::string ol = lab + "openings[" + std::to_string(i) + "]: ";
    if (!(o.from >= other_t && o.to > o.from))
      throw InputError(ol + "expected the other wall's thickness <= from < to (m from the corner's outer face): an "
                       "opening through the corner pier leaves no corner mechanism");
    if (!(o.top > o.bottom)) throw InputError(ol + "expected bottom < top (m above the foundation)");
    // Within the wall (issue 39: an opening beyond it was clipped without a word).
    if (!(o.to <= other_t + r.length + 1e-9))
      throw InputError(ol + "ends " + fmt("%g", o.to) + " m from the corner's outer face, beyond the wall's end (" +
                       fmt("%g", other_t + r.length) + " m: the other wall's thickness and the length)");
    if (!(o.top <= p.base_z + p.height + 1e-9))
      throw InputError(ol + "its top " + fmt("%g", o.top) + " m is above the wall's top (" +
                       fmt("%g", p.base_z + p.height) + " m above the foundation)");
    r.openings.push_back(o);
  }
  return r;
}

}  // namespace

MechanismSet corner_overturning(const CornerOverturningParams& p) {
  const std::string lab = "corner_overturning: ";
  require_positive(p.height, lab + "height", "m");
  require_positive(p.unit_weight, lab + "unit_weight", "kN/m^3");
  require_non_negative(p.base_z, lab + "base_z", "m");
  require_non_negative(p.top_weight, lab + "top_weight", "kN");
  require_non_negative(p.tie, lab + "tie", "kN");
  MechanismSet set;
  set.type = "corner_overturning";
  set.parameter_name = "axis angle from wall A (deg)";
  // The common crack angle(s): needed unless both walls give their own.
  auto own = [](const CornerWall& w) { return w.beta_deg || w.unit_length || w.course_height || w.crack_reach; };
  std::vector<double> betas;
  bool beta_searched = false;
  if (!own(p.wall_a) || !own(p.wall_b)) betas = wedge_angles(lab, p, beta_searched);
  if (betas.empty()) betas.push_back(0.0);  // unused
  const double tA = p.wall_a.thickness.value_or(p.thickness), tB = p.wall_b.thickness.value_or(p.thickness);
  // Axes (issue 38; docs/theory/mechanisms.md §4.2): the wedge stands on
  // its pier's footprint and tips about one of its outer edges, the axes
  // along the walls' outer faces (0 and 90 deg): about an axis through the
  // outer vertex at psi, alpha0(psi) = (a sin psi + b cos psi)/D (every term
  // of the numerator is the work of a point or a force with s = x sin psi +
  // y cos psi, D does not depend on psi), never below min(alpha0(0),
  // alpha0(90)); no intermediate axis can govern. Given: that axis alone.
  std::vector<double> axes = {0.0, 90.0};
  if (p.axis_deg) {
    if (!(*p.axis_deg >= 0.0 && *p.axis_deg <= 90.0)) throw InputError(lab + "axis_deg must lie in [0, 90] deg");
    axes = {*p.axis_deg};
  }
  set.searched = !p.axis_deg || beta_searched;
  if (beta_searched)
    set.parameter_name = p.axis_deg ? "crack angle beta from the vertical (deg)"
                                    : "axis angle from wall A (deg); crack angle in the label";
  Wall A, B;
  for (double beta : betas) {
    std::optional<double> tb;
    if (!own(p.wall_a) || !own(p.wall_b)) tb = std::tan(beta * units::deg);
    A = resolve(p, p.wall_a, tB, lab + "wall_a: ", tb);
    B = resolve(p, p.wall_b, tA, lab + "wall_b: ", tb);
    const std::string cl = beta_searched ? ", crack beta = " + fmt("%.1f", beta) + " deg" : "";
    const std::size_t first = set.candidates.size();
    for (double psi : axes) set.candidates.push_back(corner_candidate(p, A, B, psi, cl));
    if (beta_searched && p.axis_deg) set.candidates.back().parameter = beta;  // the axis given: the crack varies
    if (!p.axis_deg) {
      // The classical 45 deg reduction, for comparison (never the lower).
      const double a45 = activation_multiplier(corner_candidate(p, A, B, 45.0, cl).chain);
      for (std::size_t i = first; i < set.candidates.size(); ++i)
        set.candidates[i].quantities.push_back({"α0 about the axis at 45° (the classical reduction, for comparison)", a45,
                                                "-", "docs/theory/mechanisms.md §4.2 [D]"});
    }
  }
  const double deg = 1.0 / units::deg;
  set.data = {{"wedge height above the hinge", p.height, "m", "input"},
              {"wall A: thickness", A.t, "m", "input"},
              {"wall B: thickness", B.t, "m", "input"},
              {"wall A: length beyond wall B's inner face", A.length, "m", "input"},
              {"wall B: length beyond wall A's inner face", B.length, "m", "input"},
              {"wall A: crack angle from the vertical", std::atan(A.tanb) * deg, "°", beta_searched ? "searched" : "input"},
              {"wall B: crack angle from the vertical", std::atan(B.tanb) * deg, "°", beta_searched ? "searched" : "input"},
              {"wall A: crack reach at the top", std::min(p.height * A.tanb, A.length), "m", "min(h tan β, length)"},
              {"wall B: crack reach at the top", std::min(p.height * B.tanb, B.length), "m", "min(h tan β, length)"},
              {"openings in wall A / wall B", double(A.openings.size() + B.openings.size()), "-", "input"},
              {"unit weight γ", p.unit_weight / units::kN, "kN/m³", "input"}};
  if (p.top_weight > 0.0) set.data.push_back({"load on the corner", p.top_weight / units::kN, "kN", "input"});
  if (p.thrust != 0.0) set.data.push_back({"hip rafter thrust along the bisector", p.thrust / units::kN, "kN", "input"});
  if (p.tie > 0.0) set.data.push_back({"tie along each wall", p.tie / units::kN, "kN", "input"});
  return set;
}

}  // namespace assess

// acceptability.cpp: the checks of acceptability of acceptability.hpp (issue
// 36, item 2; docs/theory/facade.md §10).
#include "assess/assessment/acceptability.hpp"

#include "assess/assessment/facade_assessment.hpp"
#include "assess/kinematic/chain.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

namespace assess {

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// Area (m^2, positive) and centroid of a simple polygon (the shoelace formula),
// computed here rather than taken from the chain: the check is independent.
struct Section {
  double area = 0.0;
  Eigen::Vector2d centroid{0.0, 0.0};
};
Section section(const std::vector<Eigen::Vector2d>& p) {
  double a2 = 0.0, cx = 0.0, cz = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& u = p[i];
    const Eigen::Vector2d& v = p[(i + 1) % p.size()];
    const double cross = u.x() * v.y() - v.x() * u.y();
    a2 += cross;
    cx += (u.x() + v.x()) * cross;
    cz += (u.y() + v.y()) * cross;
  }
  Section s;
  s.area = std::abs(a2) / 2.0;
  if (a2 != 0.0) s.centroid = Eigen::Vector2d(cx / (3.0 * a2), cz / (3.0 * a2));
  return s;
}

// The rigid bodies of the chain: blocks welded together, or joined by two
// hinges at distinct points, move as one.
std::vector<int> bodies_of(const Chain& chain, int* count) {
  const std::size_t n = chain.blocks().size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const std::function<int(int)> root = [&](int i) { return parent[std::size_t(i)] == i ? i : parent[std::size_t(i)] = root(parent[std::size_t(i)]); };
  const auto& cons = chain.constraints();
  for (std::size_t i = 0; i < cons.size(); ++i) {
    if (cons[i].type == ConstraintType::Weld) parent[std::size_t(root(cons[i].block))] = root(cons[i].other);
    if (cons[i].type != ConstraintType::Hinge) continue;
    for (std::size_t j = i + 1; j < cons.size(); ++j) {
      if (cons[j].type != ConstraintType::Hinge) continue;
      const bool same_pair = (cons[i].block == cons[j].block && cons[i].other == cons[j].other) ||
                             (cons[i].block == cons[j].other && cons[i].other == cons[j].block);
      if (same_pair && (cons[i].point - cons[j].point).norm() > 1e-9)
        parent[std::size_t(root(cons[i].block))] = root(cons[i].other);
    }
  }
  std::vector<int> body(n, -1), index(n, -1);
  int k = 0;
  for (std::size_t b = 0; b < n; ++b) {
    const int r = root(int(b));
    if (index[std::size_t(r)] < 0) index[std::size_t(r)] = k++;
    body[b] = index[std::size_t(r)];
  }
  *count = k;
  return body;
}

bool same_point(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double scale) {
  return (a - b).norm() <= 1e-9 * std::max(1.0, scale);
}

}  // namespace

double closed_form_alpha0(const Chain& chain, std::string* why) {
  auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return nan;
  };
  for (const Block& b : chain.blocks())
    if (!b.weight_in_plane) return fail("plan");
  int nb = 0;
  const std::vector<int> body = bodies_of(chain, &nb);
  if (nb > 2) return fail("bodies");
  const double size = chain.size();
  // Each body's instantaneous centre and rotation rate (clockwise: outward for x outward, z up).
  const std::size_t n = std::size_t(nb);
  std::vector<Eigen::Vector2d> centre(n, Eigen::Vector2d::Zero());
  std::vector<double> omega(n, 0.0);
  std::vector<int> grounded(n, 0), sliders(n, 0);
  std::vector<Eigen::Vector2d> ground_point(n, Eigen::Vector2d::Zero()), slider_point(n, Eigen::Vector2d::Zero()),
      slider_dir(n, Eigen::Vector2d::Zero());
  int links = 0;
  Eigen::Vector2d link_point(0.0, 0.0);
  for (const Constraint& c : chain.constraints()) {
    const std::size_t b = std::size_t(body[std::size_t(c.block)]);
    switch (c.type) {
      case ConstraintType::GroundHinge:
        if (grounded[b] && !same_point(ground_point[b], c.point, size)) return fail("topology");
        grounded[b] = 1;
        ground_point[b] = c.point;
        break;
      case ConstraintType::Slider:
        if (sliders[b]++) return fail("topology");
        slider_point[b] = c.point;
        slider_dir[b] = c.direction;
        break;
      case ConstraintType::Hinge:
        if (body[std::size_t(c.other)] == int(b)) break;  // internal to one body
        if (links && !same_point(link_point, c.point, size)) return fail("topology");
        links = 1;
        link_point = c.point;
        break;
      case ConstraintType::Weld: break;
    }
  }
  if (nb == 1) {
    if (!grounded[0] || sliders[0]) return fail("topology");
    centre[0] = ground_point[0];
    omega[0] = 1.0;
  } else {
    const std::size_t A = grounded[0] ? 0 : 1, B = 1 - A;
    if (!grounded[A] || grounded[B] || sliders[A] || sliders[B] != 1 || !links) return fail("topology");
    centre[A] = ground_point[A];
    omega[A] = 1.0;
    // Body B: its centre on the line through A's centre and the hinge, and on
    // the normal to the slider's direction through the slider's point.
    const Eigen::Vector2d d1 = link_point - centre[A];
    const Eigen::Vector2d n2(-slider_dir[B].y(), slider_dir[B].x());
    const double det = d1.x() * (-n2.y()) - d1.y() * (-n2.x());
    if (std::abs(det) <= 1e-12 * d1.norm() * n2.norm()) return fail("topology");
    const Eigen::Vector2d rhs = slider_point[B] - centre[A];
    const double t = (rhs.x() * (-n2.y()) - rhs.y() * (-n2.x())) / det;
    centre[B] = centre[A] + t * d1;
    const Eigen::Vector2d rb = link_point - centre[B];
    if (rb.norm() <= 1e-9 * size) return fail("topology");
    omega[B] = omega[A] * (link_point - centre[A]).dot(rb) / rb.squaredNorm();
  }
  // The virtual work of every load with these displacements.
  auto works = [&](double sign, double* sum_W_dx) {
    double work = 0.0;
    *sum_W_dx = 0.0;
    for (const Load& l : chain.loads()) {
      const std::size_t b = std::size_t(body[std::size_t(l.block)]);
      double W = l.weight;
      Eigen::Vector2d p = l.point;
      if (l.type == LoadType::SelfWeight) {  // recomputed from the block's own polygon
        const Block& bl = chain.blocks()[std::size_t(l.block)];
        const Section s = section(bl.polygon);
        W = bl.unit_weight * s.area * bl.length;
        p = s.centroid;
      }
      const Eigen::Vector2d r = p - centre[b];
      const double dx = sign * omega[b] * r.y(), dz = -sign * omega[b] * r.x();
      switch (l.type) {
        case LoadType::SelfWeight:
        case LoadType::Weight:
          if (l.seismic) *sum_W_dx += W * dx;
          if (l.vertical) work += -W * dz;
          break;
        case LoadType::Force:
        case LoadType::Tie: work += l.force.x() * dx + l.force.y() * dz; break;
        case LoadType::Friction: work += -l.force.x() * std::abs(dx); break;
      }
    }
    return work;
  };
  double sum = 0.0;
  double work = works(1.0, &sum);
  if (sum < 0.0) work = works(-1.0, &sum);
  if (!(sum > 0.0)) return fail("topology");
  if (why) why->clear();
  return -work / sum;
}

double thickness_at_hinge(const Chain& chain) {
  for (const Block& b : chain.blocks())
    if (!b.weight_in_plane) return nan;
  for (const Constraint& c : chain.constraints()) {
    if (c.type != ConstraintType::GroundHinge) continue;
    const std::vector<Eigen::Vector2d>& p = chain.blocks()[std::size_t(c.block)].polygon;
    double zmin = 1e300, zmax = -1e300;
    for (const Eigen::Vector2d& v : p) zmin = std::min(zmin, v.y()), zmax = std::max(zmax, v.y());
    const double z = c.point.y() + 1e-3 * (zmax - zmin);
    double xmin = 1e300, xmax = -1e300;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Eigen::Vector2d& u = p[i];
      const Eigen::Vector2d& v = p[(i + 1) % p.size()];
      if ((u.y() - z) * (v.y() - z) > 0.0 || u.y() == v.y()) continue;
      const double x = u.x() + (z - u.y()) * (v.x() - u.x()) / (v.y() - u.y());
      xmin = std::min(xmin, x), xmax = std::max(xmax, x);
    }
    return xmax > xmin ? xmax - xmin : nan;
  }
  return nan;
}

std::vector<AcceptabilityCheck> acceptability_checks(const FacadeAssessment& a) {
  std::vector<AcceptabilityCheck> out;
  const MethodVerdict* m = a.verdict.conclusion();
  if (!m) return out;
  std::size_t ci = a.kinematic.governing;
  if (m->governing >= 0)
    for (std::size_t i = 0; i < a.kinematic.candidates.size(); ++i)
      if (a.kinematic.candidates[i].label == a.verdict.rows[std::size_t(m->governing)].candidate) ci = i;
  const CandidateResult& cr = a.kinematic.candidates[ci];
  const KinematicResult& k = cr.result;
  const Chain& chain = a.kase.mechanism.candidates[ci].chain;

  AcceptabilityCheck alpha;
  alpha.key = "alpha0_closed_form";
  alpha.candidate = cr.label;
  alpha.value = k.alpha0;
  alpha.tolerance = 1e-6;
  if (!k.ties.empty()) {
    alpha.applicable = false;
    alpha.why_not = "ties";
  } else {
    alpha.reference = closed_form_alpha0(chain, &alpha.why_not);
    alpha.applicable = !std::isnan(alpha.reference);
    alpha.passed = alpha.applicable &&
                   std::abs(alpha.reference - k.alpha0) <= alpha.tolerance * std::max(std::abs(k.alpha0), std::abs(alpha.reference));
  }
  out.push_back(alpha);

  AcceptabilityCheck disp;
  disp.key = "displacement_vs_thickness";
  disp.candidate = cr.label;
  if (!k.curve_complete()) {
    disp.applicable = false;
    disp.why_not = "curve";
  } else {
    disp.value = std::min(k.d0_star, k.d0_star_bound);
    disp.reference = thickness_at_hinge(chain);
    disp.applicable = !std::isnan(disp.reference);
    if (!disp.applicable) disp.why_not = "plan";
    disp.passed = disp.applicable && disp.value <= disp.reference * (1.0 + 1e-9);
  }
  out.push_back(disp);

  AcceptabilityCheck methods;
  methods.key = "methods_agree";
  methods.candidate = cr.label;
  for (const MethodVerdict& x : a.verdict.methods)
    if (x.code == m->code) {
      methods.methods.push_back({x.method, x.max_dc});
      methods.method_outcomes.push_back(int(x.outcome()));
    }
  methods.applicable = methods.methods.size() > 1;
  if (!methods.applicable) methods.why_not = "methods";
  methods.passed = methods.applicable && std::all_of(methods.method_outcomes.begin(), methods.method_outcomes.end(),
                                                     [&](int o) { return o == methods.method_outcomes.front(); });
  out.push_back(methods);
  return out;
}

}  // namespace assess

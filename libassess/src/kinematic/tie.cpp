// tie.cpp: the tie rod and its restraint law (docs/theory/ties.md §2).
#include "assess/kinematic/tie.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace assess {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError(what);
}

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

const char* to_string(TieEnds e) {
  switch (e) {
    case TieEnds::Threaded: return "threaded";
    case TieEnds::Upset: return "upset";
    case TieEnds::Welded: return "welded";
  }
  return "threaded";
}

double TieLayout::centre_spacing() const {
  return count > 1 ? (wall_length - 2.0 * edge_distance) / double(count - 1) : wall_length;
}

double TieLayout::position(int j) const { return count > 1 ? edge_distance + j * centre_spacing() : edge_distance; }

namespace {
// The area pi/4 (d_eq - 2 delta)^2 of a round section of area A after a loss
// of thickness delta on its faces (d_eq = sqrt(4 A / pi)).
double corroded(double A, double delta) {
  if (!(delta > 0.0)) return A;
  const double d = std::sqrt(4.0 * A / units::pi);
  const double r = std::max(0.0, d - 2.0 * delta);
  return units::pi * r * r / 4.0;
}
}  // namespace

double TieRod::corroded_area() const { return corroded(area, corrosion); }
double TieRod::corroded_thread_area() const { return corroded(thread_area, corrosion); }

// Every field within its bounds (tie_catalogue::bounds): the case-file reader
// refuses the same values first, naming the JSON path; this guards the
// library's other callers.
void Tie::validate() const {
  namespace B = tie_catalogue::bounds;
  const std::string t = "tie \"" + name + "\": ";
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  require(point.allFinite(), t + "point: expected finite (x, z) in m");
  require(direction.allFinite() && direction.norm() > 0.0, t + "direction: expected a non-zero vector");
  require(in(rod.area, B::rod_area_min, B::rod_area_max),
          t + "rod area = " + num(rod.area) + " m^2: expected " + num(B::rod_area_min) + " to " + num(B::rod_area_max) + " m^2");
  require(in(rod.fyk, B::fyk_min, B::fyk_max), t + "rod fyk: expected 100 to 1000 MPa");
  require(in(rod.ftk, rod.fyk, 2.0 * B::fyk_max), t + "rod ftk: expected >= fyk and <= 2000 MPa");
  require(in(rod.eps_uk, 0.001, 0.6), t + "rod uniform elongation: expected 0.001 to 0.6");
  require(in(rod.corrosion, 0.0, B::corrosion_max),
          t + "corrosion allowance = " + num(rod.corrosion * 1e3) + " mm: expected 0 to " + num(B::corrosion_max * 1e3) +
              " mm");
  require(2.0 * rod.corrosion < std::sqrt(4.0 * rod.thread_area / units::pi),
          t + "corrosion allowance = " + num(rod.corrosion * 1e3) + " mm: expected less than the radius of the thread's "
              "stress section");
  require(in(rod.gamma_M0, 1.0, 10.0), t + "rod gamma_M0 = " + num(rod.gamma_M0) + ": expected 1 to 10");
  require(in(rod.E, 1e9, 1e12), t + "rod E: expected 1 to 1000 GPa");
  require(in(rod.thread_area, B::rod_area_min, B::rod_area_max),
          t + "thread stress area = " + num(rod.thread_area) + " m^2: expected " + num(B::rod_area_min) + " to " +
              num(B::rod_area_max) + " m^2");
  require(in(rod.nut_width, 0.005, 0.5), t + "nut width across flats = " + num(rod.nut_width) + " m: expected 0.005 to 0.5 m");
  require(in(free_length, B::free_length_min, B::free_length_max),
          t + "free length = " + num(free_length) + " m: expected " + num(B::free_length_min) + " to " +
              num(B::free_length_max) + " m");
  if (anchor.type == AnchorType::Plate)
    require(in(anchor.a, B::plate_side_min, B::plate_side_max) && in(anchor.b, B::plate_side_min, B::plate_side_max),
            t + "anchor plate size: expected " + num(B::plate_side_min) + " to " + num(B::plate_side_max) + " m");
  else
    require(in(anchor.a, B::bar_length_min, B::bar_length_max) && in(anchor.b, B::bar_diameter_min, B::bar_diameter_max),
            t + "bar anchor: expected a length of " + num(B::bar_length_min) + " to " + num(B::bar_length_max) +
                " m and a diameter of " + num(B::bar_diameter_min) + " to " + num(B::bar_diameter_max) + " m");
  require(anchor.type == AnchorType::Bar || in(anchor.t, B::plate_t_min, B::plate_t_max),
          t + "anchor plate thickness = " + num(anchor.t) + " m: expected " + num(B::plate_t_min) + " to " +
              num(B::plate_t_max) + " m");
  // The nut must bear on the plate with a cantilever around it (issue 29): a
  // plate no wider than the nut is refused (its bending capacity has no meaning).
  require(anchor.type == AnchorType::Bar || std::min(anchor.a, anchor.b) > rod.nut_width,
          t + "anchor plate " + num(anchor.a * 1e3) + " x " + num(anchor.b * 1e3) + " mm: expected wider than its nut (" +
              num(rod.nut_width * 1e3) + " mm across flats)");
  require(anchor.type == AnchorType::Plate || anchor.b < anchor.a,
          t + "bar anchor: expected its length larger than its diameter");
  require(in(anchor.fyk, B::fyk_min, B::fyk_max), t + "anchor fyk: expected 100 to 1000 MPa");
  require(in(masonry.fm, B::fm_min, B::fm_max),
          t + "masonry fm = " + num(masonry.fm) + " Pa: expected " + num(B::fm_min / 1e6) + " to " + num(B::fm_max / 1e6) + " MPa");
  require(in(masonry.tau, B::tau_min, B::tau_max),
          t + "masonry tau = " + num(masonry.tau) + " Pa: expected " + num(B::tau_min / 1e6) + " to " + num(B::tau_max / 1e6) +
              " MPa");
  require(in(masonry.thickness, B::thickness_min, B::thickness_max),
          t + "masonry thickness = " + num(masonry.thickness) + " m: expected " + num(B::thickness_min) + " to " +
              num(B::thickness_max) + " m");
  require(in(masonry.FC, 1.0, 10.0), t + "masonry FC = " + num(masonry.FC) + ": expected 1 to 10");
  require(in(masonry.gamma_M, 1.0, 10.0), t + "masonry gamma_M = " + num(masonry.gamma_M) + ": expected 1 to 10");
  require(in(layout.wall_length, B::wall_length_min, B::wall_length_max),
          t + "wall length = " + num(layout.wall_length) + " m: expected " + num(B::wall_length_min) + " to " +
              num(B::wall_length_max) + " m");
  require(layout.count >= 1 && layout.count <= B::count_max,
          t + "count = " + std::to_string(layout.count) + ": expected 1 to " + std::to_string(B::count_max) + " ties");
  require(std::isfinite(layout.edge_distance) && layout.edge_distance > 0.0 &&
              (layout.count == 1 ? layout.edge_distance < layout.wall_length
                                 : 2.0 * layout.edge_distance <= layout.wall_length),
          t + "edge distance = " + num(layout.edge_distance) + " m: expected > 0 and the ties within the wall");
  require(layout.count == 1 || in(layout.centre_spacing(), B::spacing_min, B::spacing_max),
          t + "spacing = " + num(layout.centre_spacing()) + " m: expected " + num(B::spacing_min) + " to " +
              num(B::spacing_max) + " m");
  require(in(spacing, B::spacing_min * 1e-3, B::wall_length_max), t + "tributary length = " + num(spacing) + " m: expected > 0");
  require(in(pretension, 0.0, B::pretension_max),
          t + "pretension = " + num(pretension) + " N: expected 0 to " + num(B::pretension_max / 1e3) + " kN");
  require(in(delta_T, 0.0, B::delta_T_max), t + "temperature variation = " + num(delta_T) + " K: expected 0 to " +
                                                 num(B::delta_T_max) + " K");
  require(masonry.fv0 == 0.0 || in(masonry.fv0, B::tau_min, B::tau_max),
          t + "masonry fv0 = " + num(masonry.fv0) + " Pa: expected " + num(B::tau_min / 1e6) + " to " +
              num(B::tau_max / 1e6) + " MPa");
  require(in(masonry.mu, 0.0, 1.5), t + "masonry friction coefficient mu = " + num(masonry.mu) + ": expected 0 to 1.5");
  require(in(masonry.unit_weight, B::unit_weight_min, B::unit_weight_max),
          t + "masonry unit weight = " + num(masonry.unit_weight / 1e3) + " kN/m3: expected " +
              num(B::unit_weight_min / 1e3) + " to " + num(B::unit_weight_max / 1e3) + " kN/m3");
  require(in(layout.crown_load, 0.0, B::crown_load_max),
          t + "load on the crown = " + num(layout.crown_load / 1e3) + " kN/m: expected 0 to " +
              num(B::crown_load_max / 1e3) + " kN/m");
  require(std::isfinite(layout.base) && !(layout.crown <= layout.base) && !std::isnan(layout.crown),
          t + "wall crown at z = " + num(layout.crown) + " m: expected above the wall's base (z = " + num(layout.base) +
              " m)");
  require(layout.openings.size() <= static_cast<std::size_t>(B::openings_max),
          t + std::to_string(layout.openings.size()) + " openings: expected at most " + std::to_string(B::openings_max));
  // Issue 37: every anchor lies within the wall: below its crown, above its
  // base, within its ends, off its openings, apart from its neighbours.
  const double w = anchor.width(), hh = anchor.height();
  const double top = point.y() + hh / 2.0, bottom = point.y() - hh / 2.0;
  require(!(top > layout.crown + 1e-9),
          t + "the anchor reaches z = " + num(top) + " m (its centre at " + num(point.y()) + " m, " + num(hh * 1e3) +
              " mm high), above the wall's crown at z = " + num(layout.crown) +
              " m: expected the whole anchor within the wall");
  require(!(bottom < layout.base - 1e-9), t + "the anchor reaches below the wall's base (z = " + num(layout.base) + " m)");
  require(!(w / 2.0 > layout.edge_distance + 1e-9),
          t + "the first and last anchors (" + num(w * 1e3) + " mm wide) reach beyond the wall's ends (edge distance " +
              num(layout.edge_distance) + " m): expected the anchors within the wall");
  require(layout.count == 1 || w < layout.centre_spacing() - 1e-9,
          t + "adjacent anchors (" + num(w * 1e3) + " mm wide) overlap at a spacing of " + num(layout.centre_spacing()) +
              " m");
  for (std::size_t k = 0; k < layout.openings.size(); ++k) {
    const WallOpening& o = layout.openings[k];
    require(std::isfinite(o.x0) && std::isfinite(o.x1) && std::isfinite(o.z0) && std::isfinite(o.z1) && o.x1 > o.x0 &&
                o.z1 > o.z0,
            t + "opening " + std::to_string(k + 1) + ": expected x0 < x1 and z0 < z1 (m)");
    for (int j = 0; j < layout.count; ++j) {
      const double x = layout.position(j);
      require(!(x + w / 2.0 > o.x0 && x - w / 2.0 < o.x1 && top > o.z0 && bottom < o.z1),
              t + "the anchor of tie " + std::to_string(j + 1) + " (at " + num(x) + " m along the wall) lies over opening " +
                  std::to_string(k + 1) + ": expected the anchors on masonry");
    }
  }
}

double TieRestraint::yield_elongation() const {
  return stiffness > 0.0 ? std::max(capacity - pretension, 0.0) / stiffness : 0.0;
}

double TieRestraint::failure_elongation() const {
  return ductile ? std::max(ultimate_elongation, yield_elongation()) : yield_elongation();
}

double tie_force(const TieRestraint& r, double e) {
  if (!(r.stiffness > 0.0)) return e > 0.0 ? r.capacity : std::min(r.pretension, r.capacity);
  return std::min(std::max(r.pretension + r.stiffness * e, 0.0), r.capacity);
}

double tie_elongation(const Chain& chain, const TieRestraint& r, const Eigen::VectorXd& q) {
  return -r.direction.dot(chain.position(r.block, r.point, q) - r.point);
}

int tie_block(const Chain& chain, int block, const Eigen::Vector2d& point) {
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.n_coordinates()));
  const Eigen::VectorXd v = chain.virtual_displacement(q0);
  if (block >= 0) {
    if (block >= static_cast<int>(chain.blocks().size()))
      throw InputError("tie: block index " + std::to_string(block) + " does not exist");
    if (!chain.contains(block, point)) throw InputError("tie: the anchor point is not on block " + std::to_string(block));
    return block;
  }
  int best = -1;
  double best_move = 1e-9 * chain.size();
  for (int b : chain.blocks_containing(point)) {
    const double move = (chain.position_jacobian(b, point, q0) * v).norm();
    if (move > best_move) {
      best_move = move;
      best = b;
    }
  }
  return best;
}

}  // namespace assess

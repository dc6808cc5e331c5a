// tie.cpp: the tie rod and its restraint law (docs/theory/ties.md §2).
#include "assess/kinematic/tie.hpp"

#include "assess/support/error.hpp"

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

void Tie::validate() const {
  const std::string t = "tie \"" + name + "\": ";
  require(point.allFinite(), t + "point: expected finite (x, z) in m");
  require(direction.allFinite() && direction.norm() > 0.0, t + "direction: expected a non-zero vector");
  require(rod.area > 0.0 && std::isfinite(rod.area), t + "rod area = " + num(rod.area) + ": expected > 0 m^2");
  require(rod.fyk > 0.0 && std::isfinite(rod.fyk), t + "rod fyk: expected > 0 Pa");
  require(rod.gamma_M0 >= 1.0 && std::isfinite(rod.gamma_M0), t + "rod gamma_M0 = " + num(rod.gamma_M0) + ": expected >= 1");
  require(rod.E > 0.0 && std::isfinite(rod.E), t + "rod E: expected > 0 Pa");
  require(free_length > 0.0 && std::isfinite(free_length), t + "free length = " + num(free_length) + ": expected > 0 m");
  require(anchor.a > 0.0 && anchor.b > 0.0 && std::isfinite(anchor.a) && std::isfinite(anchor.b),
          t + "anchor size: expected > 0 m");
  require(anchor.type == AnchorType::Bar || (anchor.t > 0.0 && std::isfinite(anchor.t)),
          t + "anchor plate thickness = " + num(anchor.t) + ": expected > 0 m");
  require(anchor.fyk > 0.0 && std::isfinite(anchor.fyk), t + "anchor fyk: expected > 0 Pa");
  require(masonry.fm > 0.0 && std::isfinite(masonry.fm), t + "masonry fm = " + num(masonry.fm) + ": expected > 0 Pa");
  require(masonry.tau > 0.0 && std::isfinite(masonry.tau), t + "masonry tau = " + num(masonry.tau) + ": expected > 0 Pa");
  require(masonry.thickness > 0.0 && std::isfinite(masonry.thickness),
          t + "masonry thickness = " + num(masonry.thickness) + ": expected > 0 m");
  require(masonry.FC >= 1.0 && std::isfinite(masonry.FC), t + "masonry FC = " + num(masonry.FC) + ": expected >= 1");
  require(masonry.gamma_M >= 1.0 && std::isfinite(masonry.gamma_M),
          t + "masonry gamma_M = " + num(masonry.gamma_M) + ": expected >= 1");
  require(spacing > 0.0 && std::isfinite(spacing), t + "spacing = " + num(spacing) + ": expected > 0 m");
  require(pretension >= 0.0 && std::isfinite(pretension), t + "pretension = " + num(pretension) + ": expected >= 0 N");
}

double TieRestraint::yield_elongation() const {
  return stiffness > 0.0 ? std::max(capacity - pretension, 0.0) / stiffness : 0.0;
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

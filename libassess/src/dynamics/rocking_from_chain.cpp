// rocking_from_chain.cpp: rocking body of a one-block kinematic chain.
//
// Notation (rocking.md §0, seed Eq. 1): toe O = the ground hinge, W weight
// per unit depth, (x_G, z_G) centroid relative to the toe (x_G measured
// inward), I0 moment of inertia about O, b half base width, M_ext constant
// external moment about O (positive outward). Chain coordinates: x outward,
// z up.
#include "assess/dynamics/rocking_from_chain.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>

namespace assess {

double ChainRockingBody::horizontal_displacement(const Eigen::Vector2d& p0, double theta) const {
  // Outward rotation theta about the hinge (clockwise in x-z with x outward):
  // r' = R(-theta) r, x' = x cos + z sin.
  const Eigen::Vector2d r = p0 - hinge;
  return r.x() * (std::cos(theta) - 1.0) + r.y() * std::sin(theta);
}

namespace {

// True if the chain's virtual displacement is a rigid rotation of every block
// about `h` (e.g. slices of a gable welded together): then it rocks as one body.
bool moves_as_one_body(const Chain& chain, const Eigen::Vector2d& h) {
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(Eigen::Index(chain.n_coordinates()));
  const Eigen::VectorXd v = chain.virtual_displacement(q0);
  const double phi = v(2);
  const double tol = 1e-9 * std::max(1.0, chain.size());
  for (std::size_t b = 0; b < chain.blocks().size(); ++b) {
    const Eigen::Index j = Eigen::Index(3 * b);
    const Eigen::Vector2d r = chain.centroid(int(b)) - h;
    // Counter-clockwise rotation phi about h: dp = phi (-(z - z_h), x - x_h).
    if (std::fabs(v(j + 2) - phi) > 1e-9 || std::fabs(v(j) + phi * r.y()) > tol ||
        std::fabs(v(j + 1) - phi * r.x()) > tol)
      return false;
  }
  return true;
}

}  // namespace

ChainRockingBody rocking_body_from_chain(const Chain& chain) {
  const Constraint* hinge = nullptr;
  int ground_hinges = 0;
  for (const Constraint& c : chain.constraints())
    if (c.type == ConstraintType::GroundHinge) hinge = &c, ++ground_hinges;
  if (ground_hinges != 1 || !moves_as_one_body(chain, hinge->point))
    throw InputError("dynamic analysis: the mechanism (" + std::to_string(chain.blocks().size()) +
                     " blocks) does not rotate as one body about a single ground hinge; the rocking model "
                     "applies to one rotating block (simple overturning, gable, one-block façade); multi-block chains "
                     "use the chain model (dynamics/chain_dynamics.hpp)");
  const Block& blk = chain.blocks()[std::size_t(hinge->block)];  // the base block, on the hinge

  ChainRockingBody out;
  out.hinge = hinge->point;
  out.length = blk.length;
  const double g = units::g;
  double W = 0.0, I0 = 0.0, M_ext = 0.0;
  Eigen::Vector2d first_moment(0.0, 0.0);
  for (const Load& l : chain.loads()) {
    const Eigen::Vector2d r = l.point - out.hinge;
    switch (l.type) {
      case LoadType::SelfWeight: {
        const double m = l.weight / g;
        W += l.weight;
        first_moment += l.weight * l.point;
        I0 += m * (chain.polar_gyration_sq(l.block) + r.squaredNorm());  // parallel axes
        break;
      }
      case LoadType::Weight:
        if (l.vertical != l.seismic)
          throw InputError("dynamic analysis: load '" + l.name +
                           "': a carried weight must both bear on the wall and take part in the seismic action "
                           "for the rocking model (one mass, one weight)");
        if (!l.seismic) break;
        W += l.weight;
        first_moment += l.weight * l.point;
        I0 += l.weight / g * r.squaredNorm();  // point mass
        break;
      case LoadType::Force:
      case LoadType::Tie:
        // Virtual work of F for an outward rotation d(theta) about the hinge:
        // dp = (z - z_h, -(x - x_h)) d(theta).
        M_ext += l.force.x() * r.y() - l.force.y() * r.x();
        break;
      case LoadType::Friction:
        throw InputError("dynamic analysis: load '" + l.name +
                         "': interlocking friction is not part of the rocking model; remove it from the "
                         "mechanism for the dynamic analysis");
    }
  }
  if (!(W > 0.0)) throw InputError("dynamic analysis: the block has no weight");
  out.total_weight = W;
  out.centroid = first_moment / W;
  // Base half-width: extent of the polygon's vertices at the hinge level.
  double xmin = 1e300, xmax = -1e300;
  const double tol = 1e-6 * chain.size();
  for (const auto& v : blk.polygon)
    if (std::fabs(v.y() - out.hinge.y()) <= tol) xmin = std::min(xmin, v.x()), xmax = std::max(xmax, v.x());
  if (!(xmax > xmin))
    throw InputError("dynamic analysis: the block has no base edge at the hinge level z = " +
                     std::to_string(out.hinge.y()) + " m");
  const double L = blk.length;
  const double x_G = out.hinge.x() - out.centroid.x();  // inward distance toe -> centroid
  const double z_G = out.centroid.y() - out.hinge.y();
  out.body = RockingBody::from_centroid(W / L, x_G, z_G, I0 / L, 0.5 * (xmax - xmin), M_ext / L);
  return out;
}

}  // namespace assess

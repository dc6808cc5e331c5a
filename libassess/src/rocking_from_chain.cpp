// rocking_from_chain.cpp: rocking body of a one-block kinematic chain.
//
// Notation (rocking.md §0, seed Eq. 1): toe O = the ground hinge, W weight
// per unit depth, (x_G, z_G) centroid relative to the toe (x_G measured
// inward), I0 moment of inertia about O, b half base width, M_ext constant
// external moment about O (positive outward). Chain coordinates: x outward,
// z up.
#include "assess/rocking_from_chain.hpp"

#include "assess/error.hpp"
#include "assess/units.hpp"

#include <cmath>

namespace assess {

double ChainRockingBody::horizontal_displacement(const Eigen::Vector2d& p0, double theta) const {
  // Outward rotation theta about the hinge (clockwise in x-z with x outward):
  // r' = R(-theta) r, x' = x cos + z sin.
  const Eigen::Vector2d r = p0 - hinge;
  return r.x() * (std::cos(theta) - 1.0) + r.y() * std::sin(theta);
}

ChainRockingBody rocking_body_from_chain(const Chain& chain) {
  if (chain.blocks().size() != 1)
    throw InputError("dynamic analysis: the mechanism has " + std::to_string(chain.blocks().size()) +
                     " blocks; the rocking model applies to one rotating block (simple overturning, gable, "
                     "one-block façade); the dynamic analysis does not apply yet to multi-block chains");
  const Block& blk = chain.blocks()[0];
  const Constraint* hinge = nullptr;
  for (const Constraint& c : chain.constraints()) {
    if (c.type != ConstraintType::GroundHinge)
      throw InputError("dynamic analysis: constraint '" + c.name +
                       "' is not a ground hinge; the rocking model needs a block free to rotate about its toe");
    hinge = &c;
  }
  if (!hinge) throw InputError("dynamic analysis: the block has no ground hinge to rock about");

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

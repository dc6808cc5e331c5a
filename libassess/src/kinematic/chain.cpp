// chain.cpp: kinematic chain of rigid blocks (Circ. 617/2009 C8A.4;
// Circ. 2019 §C8.7.1.2.1).
//
// Notation:
//   q = (x_0, z_0, phi_0, x_1, ...)   generalised coordinates: displacement of
//                                     each block's reference point c_i (its
//                                     undeformed centroid, m) and rotation (rad)
//   p(q) = c_i + u_i + R(phi_i)(p0 - c_i)   position of the material point p0
//   g(q) = 0                          constraint equations, J = dg/dq
//   delta q in ker J                  virtual displacement (one DOF)
//   P_i, Q_j                          self weights and carried weights (N)
#include "assess/kinematic/chain.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace assess {
namespace {

std::string block_label(const std::vector<Block>& blocks, int i) {
  std::ostringstream os;
  os << "block " << i;
  if (!blocks[i].name.empty()) os << " '" << blocks[i].name << "'";
  return os.str();
}

std::string item_label(const char* what, const std::string& name, std::size_t i) {
  std::ostringstream os;
  os << what << ' ' << i;
  if (!name.empty()) os << " '" << name << "'";
  return os.str();
}

std::string point_str(const Eigen::Vector2d& p) {
  std::ostringstream os;
  os << "(x " << p.x() << " m, z " << p.y() << " m)";
  return os.str();
}

// Shoelace area (signed, m^2) and centroid of a simple polygon.
void polygon_area_centroid(const std::vector<Eigen::Vector2d>& v, double& area,
                           Eigen::Vector2d& centroid) {
  double a2 = 0.0;
  Eigen::Vector2d c(0.0, 0.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d& p = v[i];
    const Eigen::Vector2d& r = v[(i + 1) % v.size()];
    const double cross = p.x() * r.y() - r.x() * p.y();
    a2 += cross;
    c += (p + r) * cross;
  }
  area = 0.5 * a2;
  centroid = a2 != 0.0 ? Eigen::Vector2d(c / (3.0 * a2)) : Eigen::Vector2d(v.front());
}

// Centroidal second moments / A of a polygon: (xx, xz, zz) (m^2).
Eigen::Vector3d polygon_moments(const std::vector<Eigen::Vector2d>& v, const Eigen::Vector2d& c) {
  double a2 = 0.0, ixx = 0.0, ixz = 0.0, izz = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d p = v[i] - c, r = v[(i + 1) % v.size()] - c;
    const double cross = p.x() * r.y() - r.x() * p.y();
    a2 += cross;
    ixx += cross * (p.x() * p.x() + p.x() * r.x() + r.x() * r.x());
    izz += cross * (p.y() * p.y() + p.y() * r.y() + r.y() * r.y());
    ixz += cross * (2 * p.x() * p.y() + p.x() * r.y() + r.x() * p.y() + 2 * r.x() * r.y());
  }
  // integral x^2 dA = sum cross (..)/12, integral x z dA = sum cross (..)/24, A = a2/2.
  return Eigen::Vector3d(ixx / 6.0, ixz / 12.0, izz / 6.0) / a2;
}

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

Eigen::Matrix2d rotation(double phi) {
  Eigen::Matrix2d R;
  R << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return R;
}

Eigen::Matrix2d rotation_derivative(double phi) {
  Eigen::Matrix2d R;
  R << -std::sin(phi), -std::cos(phi), std::cos(phi), -std::sin(phi);
  return R;
}

// Null-space dimension of J (m x n): n - rank, rank from the singular values
// above a relative threshold.
constexpr double rank_tolerance = 1e-10;

}  // namespace

std::string to_string(LoadType t) {
  switch (t) {
    case LoadType::SelfWeight: return "self weight";
    case LoadType::Weight: return "weight";
    case LoadType::Force: return "force";
    case LoadType::Tie: return "tie";
    case LoadType::Friction: return "friction";
  }
  return "?";
}

Chain::Chain(std::vector<Block> blocks, std::vector<Constraint> constraints, std::vector<Load> loads)
    : blocks_(std::move(blocks)), constraints_(std::move(constraints)) {
  if (blocks_.empty()) throw InputError("the chain has no blocks");
  const int nb = static_cast<int>(blocks_.size());
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (int i = 0; i < nb; ++i) {
    const Block& b = blocks_[i];
    if (b.polygon.size() < 3)
      throw InputError(block_label(blocks_, i) + ": the polygon needs at least 3 vertices");
    for (const auto& v : b.polygon) {
      if (!v.allFinite()) throw InputError(block_label(blocks_, i) + ": a vertex is not finite");
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    if (!(b.unit_weight >= 0.0) || !std::isfinite(b.unit_weight))
      throw InputError(block_label(blocks_, i) + ": unit weight must be >= 0 kN/m^3");
    if (!(b.length > 0.0) || !std::isfinite(b.length))
      throw InputError(block_label(blocks_, i) + ": out-of-plane length must be > 0 m");
    double a;
    Eigen::Vector2d c;
    polygon_area_centroid(b.polygon, a, c);
    areas_.push_back(std::fabs(a));
    centroids_.push_back(c);
    moments_.push_back(polygon_moments(b.polygon, c));
  }
  size_ = (hi - lo).norm();
  for (int i = 0; i < nb; ++i) {
    // A degenerate (self-crossing or sliver) polygon: area tiny against its extent.
    Eigen::Vector2d blo = blocks_[i].polygon[0], bhi = blo;
    for (const auto& v : blocks_[i].polygon) {
      blo = blo.cwiseMin(v);
      bhi = bhi.cwiseMax(v);
    }
    if (areas_[i] < 1e-12 * (bhi - blo).squaredNorm())
      throw InputError(block_label(blocks_, i) + ": the polygon has zero area");
  }

  // Constraints: valid blocks, points on their blocks.
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    const std::string lab = item_label("constraint", c.name, k);
    if (c.block < 0 || c.block >= nb)
      throw InputError(lab + ": block index " + std::to_string(c.block) + " does not exist");
    if (!c.point.allFinite()) throw InputError(lab + ": the point is not finite");
    if (!contains(c.block, c.point))
      throw InputError(lab + ": the point " + point_str(c.point) + " is not on " +
                       block_label(blocks_, c.block));
    switch (c.type) {
      case ConstraintType::GroundHinge: n_equations_ += 2; break;
      case ConstraintType::Hinge:
        if (c.other < 0 || c.other >= nb)
          throw InputError(lab + ": block index " + std::to_string(c.other) + " does not exist");
        if (c.other == c.block) throw InputError(lab + ": a hinge joins two different blocks");
        if (!contains(c.other, c.point))
          throw InputError(lab + ": the point " + point_str(c.point) + " is not on " +
                           block_label(blocks_, c.other));
        n_equations_ += 2;
        break;
      case ConstraintType::Slider:
        if (!(c.direction.norm() > 0.0) || !c.direction.allFinite())
          throw InputError(lab + ": the sliding direction must be a non-zero vector");
        n_equations_ += 1;
        break;
    }
  }

  // Self weights first, then the given loads.
  for (int i = 0; i < nb; ++i) {
    const double W = blocks_[i].unit_weight * areas_[i] * blocks_[i].length;
    if (W <= 0.0) continue;
    Load p;
    p.type = LoadType::SelfWeight;
    p.name = "P " + (blocks_[i].name.empty() ? std::to_string(i) : blocks_[i].name);
    p.block = i;
    p.point = centroids_[i];
    p.weight = W;
    loads_.push_back(p);
  }
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const Load& l = loads[k];
    const std::string lab = item_label("load", l.name, k);
    if (l.type == LoadType::SelfWeight)
      throw InputError(lab + ": self weights are computed from the blocks");
    if (l.block < 0 || l.block >= nb)
      throw InputError(lab + ": block index " + std::to_string(l.block) + " does not exist");
    if (!l.point.allFinite() || !l.force.allFinite() || !std::isfinite(l.weight))
      throw InputError(lab + ": a value is not finite");
    if (!contains(l.block, l.point))
      throw InputError(lab + ": the point " + point_str(l.point) + " is not on " +
                       block_label(blocks_, l.block));
    if (l.type == LoadType::Weight && !(l.weight >= 0.0))
      throw InputError(lab + ": the weight must be >= 0 kN");
    if (l.type == LoadType::Tie && !(l.force.x() <= 0.0 && l.force.y() == 0.0))
      throw InputError(lab + ": a tie force is horizontal and points inward (-x)");
    if (l.type == LoadType::Friction && !(l.force.x() >= 0.0 && l.force.y() == 0.0))
      throw InputError(lab + ": a friction force is a magnitude >= 0 kN");
    loads_.push_back(l);
  }

  // Exactly one degree of freedom.
  const Eigen::Index n = static_cast<Eigen::Index>(n_coordinates());
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n);
  Eigen::Index rank = 0;
  if (n_equations_ > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian(q0));
    const auto& s = svd.singularValues();
    for (Eigen::Index i = 0; i < s.size(); ++i)
      if (s(i) > rank_tolerance * s(0)) ++rank;
  }
  const Eigen::Index dof = n - rank;
  if (dof == 0)
    throw InputError("the chain is not a mechanism: its constraints leave 0 degrees of freedom "
                     "(the blocks cannot move)");
  if (dof >= 2) {
    std::string free;
    for (int i = 0; i < nb; ++i) {
      bool touched = false;
      for (const auto& c : constraints_) touched = touched || c.block == i || c.other == i;
      if (!touched) free += (free.empty() ? "" : ", ") + block_label(blocks_, i);
    }
    throw InputError("the chain has " + std::to_string(dof) +
                     " degrees of freedom, a mechanism needs exactly 1" +
                     (free.empty() ? std::string(": add a hinge or a restraint")
                                   : ": no constraint acts on " + free));
  }
  // The mechanism must move the seismic masses horizontally.
  double sum_Wdx = 0.0, sum_W = 0.0;
  {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian(q0), Eigen::ComputeFullV);
    const Eigen::VectorXd v = svd.matrixV().col(n - 1);
    for (const Load& l : loads_) {
      if (!(l.type == LoadType::SelfWeight || l.type == LoadType::Weight) || !l.seismic) continue;
      sum_Wdx += l.weight * (position_jacobian(l.block, l.point, q0) * v).x();
      sum_W += l.weight;
    }
  }
  if (!(sum_W > 0.0))
    throw InputError("the chain carries no seismic weight (unit weights and carried weights are 0)");
  if (std::fabs(sum_Wdx) <= 1e-9 * sum_W * size_)
    throw InputError("the mechanism moves no seismic mass horizontally (sum W dx = 0)");
}

Eigen::Vector2d Chain::position(int block, const Eigen::Vector2d& p0,
                                const Eigen::VectorXd& q) const {
  const Eigen::Vector2d& c = centroids_[block];
  const Eigen::Index j = 3 * block;
  return c + Eigen::Vector2d(q(j), q(j + 1)) + rotation(q(j + 2)) * (p0 - c);
}

Eigen::MatrixXd Chain::position_jacobian(int block, const Eigen::Vector2d& p0,
                                         const Eigen::VectorXd& q) const {
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(2, static_cast<Eigen::Index>(n_coordinates()));
  const Eigen::Index j = 3 * block;
  G.block<2, 2>(0, j).setIdentity();
  const Eigen::Vector2d dp = rotation_derivative(q(j + 2)) * (p0 - centroids_[block]);
  G(0, j + 2) = dp.x();
  G(1, j + 2) = dp.y();
  return G;
}

double Chain::vertical_gyration_sq(int block, const Eigen::VectorXd& q) const {
  // z' - z_c' = sin(phi) (x - x_c) + cos(phi) (z - z_c) after a rotation phi.
  const double phi = q(3 * block + 2), s = std::sin(phi), c = std::cos(phi);
  const Eigen::Vector3d& m = moments_[block];
  return s * s * m(0) + 2.0 * s * c * m(1) + c * c * m(2);
}

Eigen::VectorXd Chain::residual(const Eigen::VectorXd& q) const {
  Eigen::VectorXd r(static_cast<Eigen::Index>(n_equations_));
  Eigen::Index k = 0;
  for (const Constraint& c : constraints_) {
    switch (c.type) {
      case ConstraintType::GroundHinge:
        r.segment<2>(k) = position(c.block, c.point, q) - c.point;
        k += 2;
        break;
      case ConstraintType::Hinge:
        r.segment<2>(k) = position(c.block, c.point, q) - position(c.other, c.point, q);
        k += 2;
        break;
      case ConstraintType::Slider: {
        const Eigen::Vector2d nrm = Eigen::Vector2d(-c.direction.y(), c.direction.x()).normalized();
        r(k++) = nrm.dot(position(c.block, c.point, q) - c.point);
        break;
      }
    }
  }
  return r;
}

Eigen::MatrixXd Chain::jacobian(const Eigen::VectorXd& q) const {
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n_equations_),
                    static_cast<Eigen::Index>(n_coordinates()));
  Eigen::Index k = 0;
  for (const Constraint& c : constraints_) {
    switch (c.type) {
      case ConstraintType::GroundHinge:
        J.middleRows(k, 2) = position_jacobian(c.block, c.point, q);
        k += 2;
        break;
      case ConstraintType::Hinge:
        J.middleRows(k, 2) =
            position_jacobian(c.block, c.point, q) - position_jacobian(c.other, c.point, q);
        k += 2;
        break;
      case ConstraintType::Slider: {
        const Eigen::Vector2d nrm = Eigen::Vector2d(-c.direction.y(), c.direction.x()).normalized();
        J.row(k++) = nrm.transpose() * position_jacobian(c.block, c.point, q);
        break;
      }
    }
  }
  return J;
}

Eigen::VectorXd Chain::virtual_displacement(const Eigen::VectorXd& q) const {
  const Eigen::Index n = static_cast<Eigen::Index>(n_coordinates());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian(q), Eigen::ComputeFullV);
  Eigen::VectorXd v = svd.matrixV().col(n - 1);
  double max_rot = 0.0;
  for (std::size_t i = 0; i < blocks_.size(); ++i) max_rot = std::max(max_rot, std::fabs(v(3 * i + 2)));
  v /= max_rot > 1e-12 ? max_rot : v.cwiseAbs().maxCoeff();
  double sum_Wdx = 0.0;
  for (const Load& l : loads_)
    if ((l.type == LoadType::SelfWeight || l.type == LoadType::Weight) && l.seismic)
      sum_Wdx += l.weight * (position_jacobian(l.block, l.point, q) * v).x();
  if (sum_Wdx < 0.0) v = -v;
  return v;
}

bool Chain::contains(int block, const Eigen::Vector2d& p) const {
  const auto& v = blocks_[block].polygon;
  Eigen::Vector2d lo = v[0], hi = v[0];
  for (const auto& x : v) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double tol = 1e-9 * std::max((hi - lo).norm(), 1.0);
  bool inside = false;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if (segment_distance(p, v[j], v[i]) <= tol) return true;
    if ((v[i].y() > p.y()) != (v[j].y() > p.y())) {
      const double x = v[j].x() + (p.y() - v[j].y()) * (v[i].x() - v[j].x()) / (v[i].y() - v[j].y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

std::vector<int> Chain::blocks_containing(const Eigen::Vector2d& p) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < blocks_.size(); ++i)
    if (contains(static_cast<int>(i), p)) out.push_back(static_cast<int>(i));
  return out;
}

bool Chain::solve_configuration(int block, const Eigen::Vector2d& p0, double dk,
                                const Eigen::VectorXd& guess, Eigen::VectorXd& q) const {
  // Newton on [g(q); x_k(q) - x_k(0) - dk] = 0, least-squares steps so that
  // redundant (dependent) constraints do no harm.
  const Eigen::Index m = static_cast<Eigen::Index>(n_equations_);
  const Eigen::Index n = static_cast<Eigen::Index>(n_coordinates());
  const double x0 = p0.x();
  const double tol = 1e-13 * std::max(size_, 1.0);
  q = guess;
  Eigen::VectorXd r(m + 1);
  Eigen::MatrixXd A(m + 1, n);
  for (int it = 0; it < 60; ++it) {
    r.head(m) = residual(q);
    r(m) = position(block, p0, q).x() - x0 - dk;
    if (r.cwiseAbs().maxCoeff() <= tol) return true;
    A.topRows(m) = jacobian(q);
    A.row(m) = position_jacobian(block, p0, q).row(0);
    const Eigen::VectorXd dq = A.completeOrthogonalDecomposition().solve(-r);
    if (!dq.allFinite()) return false;
    q += dq;
  }
  r.head(m) = residual(q);
  r(m) = position(block, p0, q).x() - x0 - dk;
  return r.cwiseAbs().maxCoeff() <= 1e3 * tol;
}

}  // namespace assess

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

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

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

// Up to this many coordinates (32 blocks) the constructor's SVD is Jacobi's
// (as before issue 10); beyond, the divide-and-conquer BDCSVD (same singular
// values to rounding, O(n^3) with a far smaller constant).
constexpr Eigen::Index jacobi_svd_max_coordinates = 96;

using SparseMatrix = Eigen::SparseMatrix<double>;

// Least squares min |A x - b| for a sparse A (rows >= cols) of full column
// rank, through the augmented system [[I, A], [A^T, 0]] [r; x] = [b; 0]
// (Bjorck 1996, Numerical Methods for Least Squares Problems, §2.5.3): its
// matrix is regular exactly when A has full column rank, it keeps the
// conditioning of A (the normal equations would square it) and redundant
// (dependent, consistent) rows do no harm. Sparse LU with COLAMD ordering:
// O(n) for a chain. Returns false if the factorisation fails.
bool sparse_least_squares(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const Eigen::Index m = A.rows(), n = A.cols();
  if (n <= jacobi_svd_max_coordinates) {
    // Small chains: a dense Householder QR (O(m n^2), no allocation of a
    // sparse factorisation's workspace), the least-squares solution for a
    // full column rank.
    const Eigen::MatrixXd D(A);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(D);
    x = qr.solve(b);
    return x.allFinite();
  }
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(std::size_t(m + 2 * A.nonZeros()));
  for (Eigen::Index i = 0; i < m; ++i) t.emplace_back(i, i, 1.0);
  for (Eigen::Index k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) {
      t.emplace_back(it.row(), m + it.col(), it.value());
      t.emplace_back(m + it.col(), it.row(), it.value());
    }
  SparseMatrix K(m + n, m + n);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(K);
  if (lu.info() != Eigen::Success) return false;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + n);
  rhs.head(m) = b;
  const Eigen::VectorXd y = lu.solve(rhs);
  if (lu.info() != Eigen::Success || !y.allFinite()) return false;
  x = y.tail(n);
  return true;
}

// The constraint Jacobian as a sparse matrix (issue 10, defect 13): each row
// of a hinge touches the 6 coordinates of its two blocks, of a ground hinge
// or slider the 3 of its block, so a chain of n blocks has O(n) non-zeros and
// a sparse QR factorises it in about O(n) for a chain-like structure (COLAMD
// ordering), where the dense SVD and complete orthogonal decomposition cost
// O(n^3). `extra` rows (column index, value) are appended below it.
struct Entry {
  Eigen::Index row, col;
  double value;
};

void position_entries(const Chain& chain, int block, const Eigen::Vector2d& p0, const Eigen::VectorXd& q,
                      Eigen::Index row, double sign, std::vector<Eigen::Triplet<double>>& t,
                      const Eigen::Vector2d* project = nullptr) {
  // d position / d (x, z, phi) of the block = [I, R'(phi) (p0 - c)].
  const Eigen::Index j = 3 * block;
  const Eigen::Vector2d dp = rotation_derivative(q(j + 2)) * (p0 - chain.centroid(block));
  if (project) {  // one row: n . d position
    t.emplace_back(row, j, sign * project->x());
    t.emplace_back(row, j + 1, sign * project->y());
    t.emplace_back(row, j + 2, sign * project->dot(dp));
    return;
  }
  t.emplace_back(row, j, sign);
  t.emplace_back(row + 1, j + 1, sign);
  t.emplace_back(row, j + 2, sign * dp.x());
  t.emplace_back(row + 1, j + 2, sign * dp.y());
}

SparseMatrix sparse_jacobian(const Chain& chain, const Eigen::VectorXd& q, Eigen::Index equations,
                             const std::vector<Entry>& extra) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(std::size_t(8 * equations) + extra.size());
  Eigen::Index k = 0;
  for (const Constraint& c : chain.constraints()) {
    switch (c.type) {
      case ConstraintType::GroundHinge:
        position_entries(chain, c.block, c.point, q, k, 1.0, t);
        k += 2;
        break;
      case ConstraintType::Hinge:
      case ConstraintType::Weld:
        position_entries(chain, c.block, c.point, q, k, 1.0, t);
        position_entries(chain, c.other, c.point, q, k, -1.0, t);
        k += 2;
        break;
      case ConstraintType::Slider: {
        const Eigen::Vector2d nrm = Eigen::Vector2d(-c.direction.y(), c.direction.x()).normalized();
        position_entries(chain, c.block, c.point, q, k, 1.0, t, &nrm);
        k += 1;
        break;
      }
    }
  }
  for (const Entry& e : extra) t.emplace_back(k + e.row, e.col, e.value);
  Eigen::Index rows = k;
  for (const Entry& e : extra) rows = std::max(rows, k + e.row + 1);
  SparseMatrix A(rows, static_cast<Eigen::Index>(chain.n_coordinates()));
  A.setFromTriplets(t.begin(), t.end());  // sums duplicates (a hinge's two blocks never share a column)
  A.makeCompressed();
  return A;
}

// True when segments [a, b] and [c, d] share a point (orientation tests;
// collinear overlaps included).
bool segments_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d, double tol) {
  auto orient = [tol](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const double v = (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    return v > tol ? 1 : v < -tol ? -1 : 0;
  };
  auto on = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
           r.y() <= std::max(p.y(), q.y());
  };
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // a proper crossing
  if (o1 == 0 && on(a, b, c)) return true;
  if (o2 == 0 && on(a, b, d)) return true;
  if (o3 == 0 && on(c, d, a)) return true;
  if (o4 == 0 && on(c, d, b)) return true;
  return false;
}

std::string num_m(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

std::string polygon_defect(const std::vector<Eigen::Vector2d>& polygon, bool repeated_vertices_ok) {
  std::vector<Eigen::Vector2d> v = polygon;
  std::size_t n = v.size();
  if (n < 3) return "the polygon needs at least 3 vertices";
  Eigen::Vector2d lo = v[0], hi = v[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (!v[i].allFinite()) return "vertex " + std::to_string(i) + " is not a finite point";
    if (v[i].cwiseAbs().maxCoeff() > chain_max_coordinate_m)
      return "vertex " + std::to_string(i) + " " + point_str(v[i]) + " lies farther than " +
             num_m(chain_max_coordinate_m) + " m from the origin: coordinates are in m";
    lo = lo.cwiseMin(v[i]);
    hi = hi.cwiseMax(v[i]);
  }
  const double extent = (hi - lo).norm();
  if (extent < chain_min_extent_m)
    return "the polygon is " + num_m(extent) + " m across, less than " + num_m(chain_min_extent_m) +
           " m: a block is at least 1 mm across (coordinates are in m)";
  for (std::size_t i = 0; i < n; ++i)
    if ((v[i] - v[(i + 1) % n]).norm() <= 1e-12 * extent && !repeated_vertices_ok)
      return "vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " are the same point " +
             point_str(v[i]) + ": each vertex once, in order around the block";
  if (repeated_vertices_ok) {
    // The polygon without its repeated vertices, for the tests below.
    std::vector<Eigen::Vector2d> u;
    for (std::size_t i = 0; i < n; ++i)
      if ((v[i] - v[(i + 1) % n]).norm() > 1e-12 * extent) u.push_back(v[i]);
    v = std::move(u);
    n = v.size();
    if (n < 3) return "its vertices lie on one line (zero area): a block's polygon encloses an area";
  }
  // Collinear: every vertex within a rounding distance of the line through the two farthest apart.
  std::size_t ia = 0, ib = 1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if ((v[i] - v[j]).squaredNorm() > (v[ia] - v[ib]).squaredNorm()) ia = i, ib = j;
  const Eigen::Vector2d u = (v[ib] - v[ia]).normalized();
  double off = 0.0;
  for (const Eigen::Vector2d& p : v) off = std::max(off, std::fabs(u.x() * (p - v[ia]).y() - u.y() * (p - v[ia]).x()));
  if (off <= 1e-9 * extent)
    return "its " + std::to_string(n) + " vertices lie on one line (zero area): a block's polygon encloses an area";
  // Simple polygon: no two non-adjacent edges meet.
  const double tol = 1e-12 * extent * extent;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // adjacent edges share a vertex
      if (segments_cross(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n], tol))
        return "its edges cross: edge " + std::to_string(i) + "-" + std::to_string((i + 1) % n) + " meets edge " +
               std::to_string(j) + "-" + std::to_string((j + 1) % n) +
               " (a self-crossing polygon): list the vertices in order around the block";
    }
  double a;
  Eigen::Vector2d c;
  polygon_area_centroid(v, a, c);
  if (std::fabs(a) < 1e-12 * (hi - lo).squaredNorm())
    return "the polygon has zero area (a sliver of its " + num_m(extent) + " m extent)";
  return "";
}

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
    if (const std::string d = polygon_defect(b.polygon, true); !d.empty())
      throw InputError(block_label(blocks_, i) + ": " + d);
    for (const auto& v : b.polygon) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    if (!(b.unit_weight >= 0.0) || !std::isfinite(b.unit_weight))
      throw InputError(block_label(blocks_, i) + ": unit weight must be >= 0 kN/m^3");
    if (!(b.length > 0.0) || !std::isfinite(b.length))
      throw InputError(block_label(blocks_, i) + ": out-of-plane length must be > 0 m");
    if (!std::isfinite(b.extra_gyration_sq))
      throw InputError(block_label(blocks_, i) + ": the extra radius of gyration squared is not finite");
    double a;
    Eigen::Vector2d c;
    polygon_area_centroid(b.polygon, a, c);
    areas_.push_back(std::fabs(a));
    centroids_.push_back(c);
    moments_.push_back(polygon_moments(b.polygon, c));
  }
  for (int i = 1; i < nb; ++i)
    if (blocks_[i].weight_in_plane != blocks_[0].weight_in_plane)
      throw InputError(block_label(blocks_, i) + ": a chain is drawn either in section or in plan, not both");
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
    if (!(moments_[i](0) + moments_[i](2) + blocks_[i].extra_gyration_sq > 0.0))
      throw InputError(block_label(blocks_, i) + ": the extra radius of gyration squared leaves no rotational inertia");
  }

  // Constraints: valid blocks, points on their blocks.
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    const std::string lab = item_label("constraint", c.name, k);
    if (c.block < 0 || c.block >= nb)
      throw InputError(lab + ": block index " + std::to_string(c.block) + " does not exist");
    if (!c.point.allFinite()) throw InputError(lab + ": the point is not finite");
    if (c.type != ConstraintType::Weld && !contains(c.block, c.point))
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
      case ConstraintType::Weld:
        if (c.other < 0 || c.other >= nb)
          throw InputError(lab + ": block index " + std::to_string(c.other) + " does not exist");
        if (c.other == c.block) throw InputError(lab + ": a weld joins two different blocks");
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
    p.vertical = blocks_[i].weight_in_plane;  // in plan the weight acts normal to the drawing
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
    if (!(l.slip_limit > 0.0)) throw InputError(lab + ": the slip limit must be > 0 m");
    loads_.push_back(l);
  }

  // Exactly one degree of freedom: the rank of J from its singular values,
  // and the null vector (the mechanism) from the same decomposition.
  const Eigen::Index n = static_cast<Eigen::Index>(n_coordinates());
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n);
  Eigen::Index rank = 0;
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(n);
  if (n_equations_ > 0) {
    const Eigen::MatrixXd J0 = jacobian(q0);
    Eigen::VectorXd s;
    Eigen::MatrixXd V;
    if (n <= jacobi_svd_max_coordinates) {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(J0, Eigen::ComputeFullV);
      s = svd.singularValues();
      V = svd.matrixV();
    } else {
      // Singular values only (no U, V: the bulk of an SVD's cost); the null
      // vector below from the sparse system.
      Eigen::BDCSVD<Eigen::MatrixXd> svd(J0);
      s = svd.singularValues();
    }
    for (Eigen::Index i = 0; i < s.size(); ++i)
      if (s(i) > rank_tolerance * s(0)) ++rank;
    if (V.size() > 0) {
      v0 = V.col(n - 1);
    } else if (n - rank == 1) {
      // [J; e_p^T] v = [0; 1] for the first rotation coordinate p the mechanism moves.
      const SparseMatrix J = sparse_jacobian(*this, q0, static_cast<Eigen::Index>(n_equations_), {});
      const Eigen::Index m = J.rows();
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
      rhs(m) = 1.0;
      for (Eigen::Index p = 2; p < n + 2 && v0.isZero(); ++p) {
        const Eigen::Index c = p < n ? p : p - n;  // rotations first, then every coordinate
        if (p < n && p % 3 != 2) continue;
        Eigen::VectorXd v;
        if (!sparse_least_squares(sparse_jacobian(*this, q0, m, {{0, c, 1.0}}), rhs, v)) continue;
        const double vmax = v.cwiseAbs().maxCoeff();
        if (vmax > 0.0 && (J * v).cwiseAbs().maxCoeff() <= 1e-9 * std::max(s(0), 1.0) * vmax) v0 = v / v.norm();
      }
      if (v0.isZero()) {  // not found sparsely: the full SVD
        Eigen::BDCSVD<Eigen::MatrixXd> svd(J0, Eigen::ComputeFullV);
        v0 = svd.matrixV().col(n - 1);
      }
    }
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
  // The coordinate that moves most in the mechanism: fixing it to 1 turns the
  // null space of J into the solution of a full-rank sparse system.
  v0.cwiseAbs().maxCoeff(&pivot_);
  // The mechanism must move the seismic masses horizontally.
  double sum_Wdx = 0.0, sum_W = 0.0;
  for (const Load& l : loads_) {
    if (!(l.type == LoadType::SelfWeight || l.type == LoadType::Weight) || !l.seismic) continue;
    sum_Wdx += l.weight * point_velocity(l.block, l.point, q0, v0).x();
    sum_W += l.weight;
  }
  if (!(sum_W > 0.0))
    throw InputError("the chain carries no seismic weight (unit weights and carried weights are 0)");
  if (std::fabs(sum_Wdx) <= 1e-9 * sum_W * size_)
    throw InputError("the mechanism moves no seismic mass horizontally (sum W dx = 0)");
}

bool Chain::plan() const { return !blocks_.empty() && !blocks_.front().weight_in_plane; }

Eigen::Vector2d Chain::position(int block, const Eigen::Vector2d& p0,
                                const Eigen::VectorXd& q) const {
  const Eigen::Vector2d& c = centroids_[block];
  const Eigen::Index j = 3 * block;
  return c + Eigen::Vector2d(q(j), q(j + 1)) + rotation(q(j + 2)) * (p0 - c);
}

Eigen::MatrixXd Chain::position_jacobian(int block, const Eigen::Vector2d& p0,
                                         const Eigen::VectorXd& q) const {
  // A block index out of range wrote outside G (issue 31: "free(): invalid
  // pointer" when no control point was found for coordinates of 1e150 m).
  if (block < 0 || block >= static_cast<int>(blocks_.size()))
    throw InputError("block index " + std::to_string(block) + " does not exist (0.." +
                     std::to_string(blocks_.size() - 1) + ")");
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
      case ConstraintType::Weld:
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
      case ConstraintType::Weld:
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

Eigen::Vector2d Chain::point_velocity(int block, const Eigen::Vector2d& p0, const Eigen::VectorXd& q,
                                      const Eigen::VectorXd& v) const {
  // d position = (dx, dz) + R'(phi) (p0 - c) dphi: position_jacobian(...) * v without the 2 x n matrix.
  if (block < 0 || block >= static_cast<int>(blocks_.size()))
    throw InputError("block index " + std::to_string(block) + " does not exist (0.." +
                     std::to_string(blocks_.size() - 1) + ")");
  const Eigen::Index j = 3 * block;
  return Eigen::Vector2d(v(j), v(j + 1)) + rotation_derivative(q(j + 2)) * (p0 - centroids_[block]) * v(j + 2);
}

Eigen::VectorXd Chain::virtual_displacement(const Eigen::VectorXd& q) const {
  const Eigen::Index n = static_cast<Eigen::Index>(n_coordinates());
  const Eigen::Index m = static_cast<Eigen::Index>(n_equations_);
  // [J; e_p^T] v = [0; 1]: J v = 0 with the pivot coordinate p fixed. Full
  // column rank while v_p != 0 (redundant constraints make it tall and
  // consistent): sparse least squares, O(n) for a chain.
  Eigen::VectorXd v;
  {
    const SparseMatrix A = sparse_jacobian(*this, q, m, {{0, pivot_, 1.0}});
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
    rhs(m) = 1.0;
    if (!sparse_least_squares(A, rhs, v)) v.resize(0);
  }
  // Checked: J v = 0 to rounding (relative to |J| |v|); else (v_p = 0 in this
  // configuration, a degenerate factorisation) the dense SVD of before.
  bool ok = v.size() == n && v.allFinite();
  if (ok) {
    const SparseMatrix J = sparse_jacobian(*this, q, m, {});
    double jmax = 0.0;
    for (Eigen::Index k = 0; k < J.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(J, k); it; ++it) jmax = std::max(jmax, std::fabs(it.value()));
    const double vmax = v.cwiseAbs().maxCoeff();
    ok = vmax > 0.0 && (J * v).cwiseAbs().maxCoeff() <= 1e-9 * std::max(jmax, 1.0) * vmax;
  }
  if (!ok) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian(q), Eigen::ComputeFullV);
    v = svd.matrixV().col(n - 1);
  }
  double max_rot = 0.0;
  for (std::size_t i = 0; i < blocks_.size(); ++i) max_rot = std::max(max_rot, std::fabs(v(3 * i + 2)));
  v /= max_rot > 1e-12 * v.cwiseAbs().maxCoeff() ? max_rot : v.cwiseAbs().maxCoeff();
  double sum_Wdx = 0.0;
  for (const Load& l : loads_)
    if ((l.type == LoadType::SelfWeight || l.type == LoadType::Weight) && l.seismic)
      sum_Wdx += l.weight * point_velocity(l.block, l.point, q, v).x();
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
  // redundant (dependent) constraints do no harm: sparse QR of the (m + 1) x n
  // Jacobian by its augmented system (O(n) for a chain; issue 10, defect 13).
  const Eigen::Index m = static_cast<Eigen::Index>(n_equations_);
  const double x0 = p0.x();
  const double tol = 1e-13 * std::max(size_, 1.0);
  q = guess;
  Eigen::VectorXd r(m + 1);
  for (int it = 0; it < 60; ++it) {
    r.head(m) = residual(q);
    r(m) = position(block, p0, q).x() - x0 - dk;
    if (r.cwiseAbs().maxCoeff() <= tol) return true;
    // Last row: d x_k / d q = (1, 0, d(R (p0 - c)).x / dphi) on the block's coordinates.
    const Eigen::Index j = 3 * block;
    const double dxdphi = (rotation_derivative(q(j + 2)) * (p0 - centroids_[block])).x();
    const SparseMatrix A = sparse_jacobian(*this, q, m, {{0, j, 1.0}, {0, j + 2, dxdphi}});
    Eigen::VectorXd dq;
    if (!sparse_least_squares(A, -r, dq)) return false;
    q += dq;
  }
  r.head(m) = residual(q);
  r(m) = position(block, p0, q).x() - x0 - dk;
  return r.cwiseAbs().maxCoeff() <= 1e3 * tol;
}

}  // namespace assess

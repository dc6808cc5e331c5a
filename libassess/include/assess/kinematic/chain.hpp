// chain.hpp: a kinematic chain of rigid blocks in the vertical plane of a
// wall (Circ. 617/2009 C8A.4; Circ. 2019 §C8.7.1.2.1).
//
// Plane x-z: x horizontal, positive OUTWARD (the direction of the seismic
// action that activates the mechanism), z vertical, positive up. Each block is
// a rigid polygon; its configuration is (x, z, phi): the displacement of its
// reference point (the centroid of the undeformed polygon) and its rotation
// (rad, counter-clockwise in the x-z plane). Constraints are equations on these
// coordinates; a valid chain has exactly one degree of freedom. Virtual
// displacements are the null space of the constraint Jacobian; finite
// displacements are found by Newton's method.
#pragma once

#include <Eigen/Dense>

#include <limits>
#include <string>
#include <vector>

namespace assess {

/// A rigid block: a simple polygon of the wall's section, with the unit weight
/// and the out-of-plane length that turn its area into a weight.
struct Block {
  std::string name;                       ///< used in messages and reports
  std::vector<Eigen::Vector2d> polygon;   ///< vertices (x, z) (m), either orientation
  double unit_weight = 0.0;               ///< gamma (N/m^3), >= 0
  double length = 1.0;                    ///< out-of-plane length (m), > 0
  /// false: the chain is drawn in PLAN (horizontal flexure, issue 33): the
  /// block's weight acts normal to the drawing and does no virtual work, its
  /// mass still takes part in the seismic action (its self weight is a
  /// seismic, non-bearing load: Load::vertical = false).
  bool weight_in_plane = true;
  /// Added to the polygon's polar radius of gyration squared (m^2, may be
  /// negative, the total must stay > 0): the spread of the mass normal to the
  /// drawing that a planar reduction of a 3-D body does not draw (the corner
  /// wedge projected on the plane normal to its rotation axis, issue 33;
  /// docs/theory/kinematic.md §5). Only the rotational inertia uses it.
  double extra_gyration_sq = 0.0;
};

enum class ConstraintType {
  GroundHinge,  ///< the block rotates about a fixed point (2 equations)
  Hinge,        ///< two blocks share a point (2 equations)
  Slider,       ///< a point of the block moves along a fixed line (1 equation)
  /// Two blocks share a material point that need not lie on either polygon
  /// (2 equations, as Hinge): two welds at distinct points join two pieces of
  /// one rigid body drawn apart (the planar reduction of a 3-D wedge, issue 33).
  Weld,
};

/// A constraint. Points are in the undeformed configuration (m).
struct Constraint {
  ConstraintType type = ConstraintType::GroundHinge;
  std::string name;
  int block = -1;                       ///< index of the (first) block
  int other = -1;                       ///< Hinge, Weld: index of the second block
  Eigen::Vector2d point{0.0, 0.0};      ///< hinge point / sliding point (m)
  /// Slider: direction of the line the point moves along (any length); e.g.
  /// (0, 1) for a floor that stops the horizontal motion of the wall.
  Eigen::Vector2d direction{0.0, 1.0};
};

enum class LoadType {
  SelfWeight,  ///< P: weight of a block at its centroid (added by Chain)
  Weight,      ///< Q: a carried weight (floor, roof) at a point
  Force,       ///< a constant external force (thrust of an arch, vault or roof)
  Tie,         ///< a tie rod: constant horizontal force pointing inward (-x)
  Friction,    ///< a constant horizontal force opposing the motion (C8.7.1.2)
};

/// A load applied at a material point of a block (undeformed coordinates).
struct Load {
  LoadType type = LoadType::Weight;
  std::string name;
  int block = -1;                   ///< index of the block that carries it
  Eigen::Vector2d point{0.0, 0.0};  ///< application point (m)
  /// SelfWeight / Weight: weight (N, acting downward), >= 0.
  double weight = 0.0;
  /// Weight: its vertical force acts on the chain (false for a mass that
  /// only pushes horizontally, the "m" weights of C8A.4.1).
  bool vertical = true;
  /// SelfWeight / Weight: its mass takes part in the seismic action (alpha W
  /// horizontal, outward).
  bool seismic = true;
  /// Force: the force vector (N); Tie: (-T, 0); Friction: (F, 0), F >= 0.
  Eigen::Vector2d force{0.0, 0.0};
  /// The drawing's label of a force, tie or friction (report/mechanism_drawing;
  /// issue 29: ties labelled per tie and per level); "": "T = <force> kN".
  std::string label;
  /// Friction (issue 33): the horizontal slip of the point (m) beyond which
  /// the friction is lost (the interlocked units or a floor's seat
  /// disengage); infinity = never. alpha0 is unaffected (no slip at rest).
  double slip_limit = std::numeric_limits<double>::infinity();
};

/// What makes a block's polygon unusable, or "" for a usable one (issue 31):
/// fewer than 3 vertices, a vertex not finite or farther than
/// chain_max_coordinate_m from the origin, two consecutive vertices at the
/// same point, a polygon smaller than chain_min_extent_m across, every vertex
/// on one line, edges that cross each other (not a simple polygon), or an
/// area that is a sliver of its extent. The Chain constructor and the case
/// file reader (with the JSON path) give the same diagnosis.
/// `repeated_vertices_ok`: a vertex repeated at once (a catalogue mechanism
/// whose wedge vanishes) is skipped rather than refused; a case file's
/// explicit block refuses it.
std::string polygon_defect(const std::vector<Eigen::Vector2d>& polygon, bool repeated_vertices_ok = false);

/// Coordinates of a chain lie within 1000 km of its origin: products of
/// coordinates (areas, moments) stay far from overflow (1e150 m made every
/// weight infinite). The case file's physical bound is tighter (1 km,
/// support/number_rules.hpp).
inline constexpr double chain_max_coordinate_m = 1e6;
/// A block is at least 1 mm across.
inline constexpr double chain_min_extent_m = 1e-3;

/// The chain. Immutable once built; the constructor validates it.
class Chain {
 public:
  /// Validates and builds the chain; the blocks' self weights are added as the
  /// first loads. Throws InputError naming the element: a degenerate polygon,
  /// a bad unit weight or length, a constraint or load on a missing block, a
  /// hinge or load point not on its block, a chain with 0 or 2+ degrees of
  /// freedom, a mechanism that moves no seismic mass horizontally.
  Chain(std::vector<Block> blocks, std::vector<Constraint> constraints, std::vector<Load> loads);

  const std::vector<Block>& blocks() const { return blocks_; }
  const std::vector<Constraint>& constraints() const { return constraints_; }
  /// Every load: self weights first (one per block with weight > 0), then the given loads.
  const std::vector<Load>& loads() const { return loads_; }
  std::size_t n_coordinates() const { return 3 * blocks_.size(); }

  /// Centroid of the undeformed block (m).
  const Eigen::Vector2d& centroid(int block) const { return centroids_[block]; }
  /// Area of the block's polygon (m^2).
  double area(int block) const { return areas_[block]; }
  /// Mean square of (z - z_c) over the block's area in configuration q (m^2):
  /// the integral of (z - z_c)^2 dA / A of the rotated polygon. With it the
  /// distributed self weight gives integral(dx^2 dW) = W (dx_c^2 + dphi^2 r2),
  /// the sum P dx^2 of C8A.4.2 for a block of continuous mass.
  double vertical_gyration_sq(int block, const Eigen::VectorXd& q) const;

  /// Polar radius of gyration squared about the block's centroid (m^2):
  /// integral of ((x - x_c)^2 + (z - z_c)^2) dA / A of the undeformed polygon,
  /// plus Block::extra_gyration_sq. The block's moment of inertia about its
  /// centroid is then m * this.
  double polar_gyration_sq(int block) const {
    return moments_[block](0) + moments_[block](2) + blocks_[block].extra_gyration_sq;
  }
  /// True if every block is drawn in plan (Block::weight_in_plane false).
  bool plan() const;

  /// Position (m) of the material point p0 (undeformed, m) of `block` in the
  /// configuration q (size n_coordinates(); zero = undeformed).
  Eigen::Vector2d position(int block, const Eigen::Vector2d& p0, const Eigen::VectorXd& q) const;
  /// d position / d q (2 x n_coordinates()).
  Eigen::MatrixXd position_jacobian(int block, const Eigen::Vector2d& p0,
                                    const Eigen::VectorXd& q) const;
  /// Constraint residuals (m) and their Jacobian.
  Eigen::VectorXd residual(const Eigen::VectorXd& q) const;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& q) const;

  /// The virtual displacement field at configuration q: a basis vector of the
  /// (one-dimensional) null space of the constraint Jacobian, scaled so that
  /// the largest block rotation is 1 rad and signed so that the seismic
  /// weights move outward on balance (sum W dx > 0).
  Eigen::VectorXd virtual_displacement(const Eigen::VectorXd& q) const;

  /// Index of a block containing p (m) (inside or on its boundary), -1 if none.
  /// All blocks containing it are returned by blocks_containing().
  std::vector<int> blocks_containing(const Eigen::Vector2d& p) const;
  /// True if p lies inside or on the boundary of `block` (tolerance 1e-9 of its size).
  bool contains(int block, const Eigen::Vector2d& p) const;

  /// Finite-displacement configuration in which the material point `p0` of
  /// `block` has moved horizontally by `dk` (m), found by Newton's method from
  /// `guess`. Returns false when Newton does not converge (q holds the last
  /// iterate).
  bool solve_configuration(int block, const Eigen::Vector2d& p0, double dk,
                           const Eigen::VectorXd& guess, Eigen::VectorXd& q) const;

  /// Characteristic size of the chain (m): the diagonal of its bounding box.
  double size() const { return size_; }

 private:
  /// position_jacobian(block, p0, q) * v, without building the 2 x n matrix.
  Eigen::Vector2d point_velocity(int block, const Eigen::Vector2d& p0, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& v) const;

  std::vector<Block> blocks_;
  std::vector<Constraint> constraints_;
  std::vector<Load> loads_;
  std::vector<Eigen::Vector2d> centroids_;
  std::vector<double> areas_;
  std::vector<Eigen::Vector3d> moments_;  // centroidal integral of (x^2, x z, z^2) dA / A (m^2)
  std::size_t n_equations_ = 0;
  double size_ = 1.0;
  /// The coordinate that moves most in the undeformed mechanism: fixed to 1
  /// in virtual_displacement's sparse system.
  Eigen::Index pivot_ = 0;
};

/// "self weight", "weight", "force", "tie", "friction".
std::string to_string(LoadType t);

}  // namespace assess

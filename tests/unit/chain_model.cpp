// The chain model: degrees of freedom, virtual displacements against finite
// differences of the finite-displacement configuration, and every bad-input
// error naming its element.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/chain.hpp>
#include <assess/support/error.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>

#include <string>

using assess::test::abs_tol;

namespace {
// Central differences with step eps = 1e-6 m: truncation O(eps^2 * curvature)
// ~1e-12 plus Newton residuals 1e-13 / eps ~ 1e-7.
constexpr double tol_fd = 1e-6;  // m per m of control displacement

assess::Block rect(const std::string& name, double x0, double z0, double x1, double z1) {
  assess::Block b;
  b.name = name;
  b.polygon = {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}};
  b.unit_weight = 18000.0;
  return b;
}
assess::Constraint ground(int b, double x, double z) {
  assess::Constraint c;
  c.type = assess::ConstraintType::GroundHinge;
  c.name = "ground";
  c.block = b;
  c.point = {x, z};
  return c;
}
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const assess::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("virtual displacements equal finite differences of the finite-displacement configuration") {
  assess::VerticalFlexureParams p;
  p.height = 4.0;
  p.thickness = 0.4;
  p.unit_weight = 18000.0;
  p.top_load = 50000.0;
  p.top_load_distance_from_inner_face = 0.1;
  p.hinge_height = 1.7;
  const auto set = assess::vertical_flexure(p);
  const assess::Chain& chain = set.candidates[0].chain;
  const Eigen::Vector2d ctrl(-0.2, 1.0);  // on the lower block
  for (double dk : {0.0, 0.05}) {
    Eigen::VectorXd q, qp, qm;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
    REQUIRE(chain.solve_configuration(0, ctrl, dk, zero, q));
    const double eps = 1e-6;
    REQUIRE(chain.solve_configuration(0, ctrl, dk + eps, q, qp));
    REQUIRE(chain.solve_configuration(0, ctrl, dk - eps, q, qm));
    const Eigen::VectorXd fd = (qp - qm) / (2 * eps);
    Eigen::VectorXd v = chain.virtual_displacement(q);
    v /= (chain.position_jacobian(0, ctrl, q) * v).x();  // per unit control displacement
    for (Eigen::Index i = 0; i < v.size(); ++i) CHECK_CLOSE(v(i), fd(i), abs_tol(tol_fd));
    // Every load point: the same check on positions.
    for (const auto& l : chain.loads()) {
      const Eigen::Vector2d d_fd =
          (chain.position(l.block, l.point, qp) - chain.position(l.block, l.point, qm)) / (2 * eps);
      const Eigen::Vector2d d_v = chain.position_jacobian(l.block, l.point, q) * v;
      CHECK_CLOSE(d_v.x(), d_fd.x(), abs_tol(tol_fd));
      CHECK_CLOSE(d_v.y(), d_fd.y(), abs_tol(tol_fd));
    }
  }
}

TEST_CASE("a chain that is not a 1-DOF mechanism is rejected") {
  const auto b0 = rect("a", -0.5, 0, 0, 3), b1 = rect("b", -0.5, 3, 0, 6);
  CHECK(error_of([&] { assess::Chain({b0}, {}, {}); }).find("3 degrees of freedom") != std::string::npos);
  // Two ground hinges lock the block.
  CHECK(error_of([&] { assess::Chain({b0}, {ground(0, 0, 0), ground(0, -0.5, 0)}, {}); })
            .find("0 degrees of freedom") != std::string::npos);
  // A second block with no constraint: 4 DOF, the message names it.
  const std::string e = error_of([&] { assess::Chain({b0, b1}, {ground(0, 0, 0)}, {}); });
  CHECK(e.find("4 degrees of freedom") != std::string::npos);
  CHECK(e.find("block 1 'b'") != std::string::npos);
}

TEST_CASE("a hinge not on its block, a load outside the block, bad geometry: named errors") {
  const auto b0 = rect("wall", -0.5, 0, 0, 3);
  CHECK(error_of([&] { assess::Chain({b0}, {ground(0, 1.0, 0)}, {}); }).find("constraint 0 'ground'") !=
        std::string::npos);
  assess::Load l;
  l.type = assess::LoadType::Weight;
  l.name = "floor";
  l.block = 0;
  l.point = {-0.2, 3.5};
  l.weight = 1000.0;
  const std::string e = error_of([&] { assess::Chain({b0}, {ground(0, 0, 0)}, {l}); });
  CHECK(e.find("load 0 'floor'") != std::string::npos);
  CHECK(e.find("not on block 0 'wall'") != std::string::npos);
  auto bad = b0;
  bad.polygon = {{0, 0}, {1, 0}, {2, 0}};
  CHECK(error_of([&] { assess::Chain({bad}, {ground(0, 0, 0)}, {}); }).find("zero area") != std::string::npos);
  bad = b0;
  bad.unit_weight = -1.0;
  CHECK(error_of([&] { assess::Chain({bad}, {ground(0, 0, 0)}, {}); }).find("unit weight") != std::string::npos);
  assess::SimpleOverturningParams p;
  assess::Storey s;
  s.height = 3.0;
  s.thickness = -0.3;
  p.storeys = {s};
  p.unit_weight = 18000.0;
  CHECK(error_of([&] { assess::simple_overturning(p); }).find("storeys[0].thickness") != std::string::npos);
}

TEST_CASE("a large tie raises alpha0; a large outward thrust gives alpha0 <= 0: a result, not an error") {
  assess::SimpleOverturningParams p;
  assess::Storey s;
  s.height = 3.0;
  s.thickness = 0.4;
  s.tie = 1e6;
  p.storeys = {s};
  p.unit_weight = 18000.0;
  p.hinge_level = 0;
  const auto set = assess::simple_overturning(p);
  // An inward tie raises alpha0; an outward thrust larger than the
  // restoring moment makes it negative.
  p.storeys[0].tie = 0.0;
  p.storeys[0].thrust = 1e6;
  const auto set2 = assess::simple_overturning(p);
  const auto r = assess::analyse_kinematic(set2.candidates[0].chain);
  CHECK_FALSE(r.activates);
  CHECK(r.alpha0 < 0.0);
  CHECK(r.termination == assess::CurveTermination::NotActivated);
  CHECK(assess::activation_multiplier(set.candidates[0].chain) > 1.0);
}

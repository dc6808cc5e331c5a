// Dynamics of 1-DOF chains (issue 13, docs/theory/chain-dynamics.md):
//  - single-block identity with the rocking model (theta_max, D/C to 1e-10),
//  - interpolated M, V', B against the exact evaluation (1e-10 of each scale),
//  - energy of a two-block chain (vertical flexure) in free motion with |e| = 1,
//  - vertical flexure's first excursion under a one-sine pulse against an
//    independent Lagrangian written here (closed-form loop closure, complex-step
//    derivatives, fixed-step RK4),
//  - the rocking frame of Makris & Vassiliou (2013): two columns capped by a
//    beam rock like one column with p^2 (1 + 2 gamma)/(1 + 3 gamma).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/dynamics/chain_analysis.hpp>
#include <assess/dynamics/rocking_from_chain.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <complex>
#include <functional>
#include <string>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// Identity with the rocking model: same ODE, different rounding and an
// interpolated (1e-14) right-hand side: theta_max (rad) and D/C (-).
constexpr double kIdentityTol = 1e-10;
// Interpolation vs exact, relative to the function's largest magnitude on [0, q_u].
constexpr double kInterpTol = 1e-10;
// Energy (J) relative to the initial potential energy, integration at rel_tol 1e-12.
constexpr double kEnergyTol = 1e-8;
// Flexure's first excursion (rad, relative): RK4 at dt = 2e-5 s and a
// finite-difference M' (step 1e-5 rad, error ~1e-10) in the independent model.
constexpr double kFlexureTol = 1e-6;
// Rocking frame: closed-form M, V', B to rounding (relative) and theta_max (relative).
constexpr double kFrameFormTol = 1e-11;
constexpr double kFrameTol = 1e-9;

using V2 = Eigen::Vector2d;

Block rect(const std::string& name, double x0, double x1, double z0, double z1, double gamma) {
  Block b;
  b.name = name;
  b.polygon = {V2(x0, z0), V2(x1, z0), V2(x1, z1), V2(x0, z1)};
  b.unit_weight = gamma;
  b.length = 1.0;
  return b;
}

Constraint ground(int block, V2 p) {
  Constraint c;
  c.type = ConstraintType::GroundHinge;
  c.block = block;
  c.point = p;
  return c;
}
Constraint hinge(int a, int b, V2 p) {
  Constraint c;
  c.type = ConstraintType::Hinge;
  c.block = a;
  c.other = b;
  c.point = p;
  return c;
}

// A façade block t x H rocking outward about its outer toe (0, 0).
Chain facade_block(double t, double H, double gamma) {
  return Chain({rect("wall", -t, 0.0, 0.0, H, gamma)}, {ground(0, V2(0.0, 0.0))}, {});
}

// Vertical flexure as in the catalogue: lower block on a ground hinge at the
// outer toe, middle hinge on the inner face, top slider (vertical line) at the
// outer face, a non-seismic bearing load Q at distance d from the inner face.
struct Flexure {
  double t = 0.4, H = 4.0, zh = 2.4, gamma = 18e3, Q = 30e3, d = 0.2;
};
Chain flexure_chain(const Flexure& f) {
  Constraint top;
  top.type = ConstraintType::Slider;
  top.block = 1;
  top.point = V2(0.0, f.H);
  top.direction = V2(0.0, 1.0);
  Load q;
  q.type = LoadType::Weight;
  q.name = "Q";
  q.block = 1;
  q.point = V2(-f.t + f.d, f.H);
  q.weight = f.Q;
  q.seismic = false;
  return Chain({rect("lower", -f.t, 0.0, 0.0, f.zh, f.gamma), rect("upper", -f.t, 0.0, f.zh, f.H, f.gamma)},
               {ground(0, V2(0.0, 0.0)), hinge(0, 1, V2(-f.t, f.zh)), top}, {q});
}

RockingOptions tight() {
  RockingOptions o;
  o.rel_tol = 1e-12;
  o.abs_tol = 1e-14;
  return o;
}

GroundMotion one_sine(double A, double Tp, double duration) {
  const double w = 2.0 * units::pi / Tp;
  return GroundMotion::from_function([=](double t) { return t <= Tp ? -A * std::sin(w * t) : 0.0; }, duration, {Tp},
                                     0.01);
}

}  // namespace

TEST_CASE("single block: the chain path reproduces the rocking model (theta_max, D/C to 1e-10)") {
  const Chain chain = facade_block(0.45, 3.5, 18e3);
  const ChainRockingBody cb = rocking_body_from_chain(chain);
  const Record rec = read_record(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/RSN292_ITALY_A-STU270.AT2");
  struct Case {
    const char* name;
    Foundation f;
    double e;
    double scale;
  };
  for (const Case& c : {Case{"rigid, e = -0.5", Foundation::rigid(), -0.5, 2.0},
                        Case{"rigid, e = 0", Foundation::rigid(), 0.0, 2.5},
                        Case{"smooth, e = -0.7", Foundation::winkler(5e8), -0.7, 2.0}}) {
    CAPTURE(c.name);
    const RockingModel rm(cb.body, c.f, Sidedness::one_sided, Restitution::given(c.e));
    const ChainDynamics cd(chain, c.f);
    CHECK_CLOSE(cd.q_u(), rm.theta_u(+1), abs_tol(1e-13));
    CHECK_CLOSE(cd.capacity() / cb.length, rm.capacity(), rel_tol(1e-12));
    RockingOptions o;
    o.scale = c.scale;
    const RockingResult a = analyse(rm, rec, o);
    const RockingResult b = analyse_chain(cd, rec, o, c.e);
    CAPTURE(a.brief_report());
    CAPTURE(b.brief_report());
    MESSAGE(std::string(c.name) << ": record theta_max diff " << std::fabs(a.theta_max - b.theta_max) << " rad, D/C diff "
                   << std::fabs(a.dc - b.dc) << " (impacts " << a.impacts << ")");
    CHECK(a.impacts > 0);
    CHECK(a.impacts == b.impacts);
    CHECK(a.overturned == b.overturned);
    CHECK_CLOSE(b.theta_max, a.theta_max, abs_tol(kIdentityTol));
    CHECK_CLOSE(b.dc, a.dc, abs_tol(kIdentityTol));
    // Under a one-sine pulse, inward half first (first excursion and free rocking after it).
    const GroundMotion p = one_sine(-1.5 * units::g * cb.body.x_G() / cb.body.z_G(), 0.6, 4.0);
    const RockingResult pa = analyse(rm, p, o), pb = analyse_chain(cd, p, o, c.e);
    MESSAGE(std::string(c.name) << ": pulse theta_max diff " << std::fabs(pa.theta_max - pb.theta_max) << " rad, D/C diff "
                   << std::fabs(pa.dc - pb.dc));
    CHECK(pa.theta_max > 0.0);
    CHECK_CLOSE(pb.theta_max, pa.theta_max, abs_tol(kIdentityTol));
    CHECK_CLOSE(pb.dc, pa.dc, abs_tol(kIdentityTol));
  }
}

TEST_CASE("single block, two-sided: the chain path (mirror image for q < 0) reproduces the rocking model") {
  const Chain chain = facade_block(0.45, 3.5, 18e3);
  const ChainRockingBody cb = rocking_body_from_chain(chain);
  const Record rec = read_record(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/RSN292_ITALY_A-STU270.AT2");
  for (const Foundation f : {Foundation::rigid(), Foundation::winkler(5e8)}) {
    const RockingModel rm(cb.body, f, Sidedness::two_sided, Restitution::housner());
    const ChainDynamics cd(chain, f);
    REQUIRE(cd.symmetric());
    RockingOptions o;
    o.scale = 1.5;
    const RockingResult a = analyse(rm, rec, o);
    const RockingResult b = analyse_chain(cd, rec, o, rm.restitution(), Sidedness::two_sided);
    MESSAGE("two-sided " << std::string(f.is_rigid() ? "rigid" : "smooth") << ": theta_max diff "
                         << std::fabs(a.theta_max - b.theta_max) << " rad, D/C diff " << std::fabs(a.dc - b.dc)
                         << " (impacts " << a.impacts << ", side " << a.theta_max_side << ")");
    CHECK(a.impacts > 2);
    CHECK(a.impacts == b.impacts);
    CHECK(a.theta_max_side == b.theta_max_side);
    CHECK_CLOSE(b.theta_max, a.theta_max, abs_tol(kIdentityTol));
    CHECK_CLOSE(b.dc, a.dc, abs_tol(kIdentityTol));
  }
  // A chain that is not mirror-symmetric refuses two-sided motion.
  Load w;
  w.type = LoadType::Weight;
  w.block = 0;
  w.point = V2(-0.4, 3.5);
  w.weight = 1e4;
  const Chain asym({rect("wall", -0.45, 0.0, 0.0, 3.5, 18e3)}, {ground(0, V2(0.0, 0.0))}, {w});
  const ChainDynamics ca(asym, Foundation::rigid());
  CHECK(!ca.symmetric());
  CHECK_THROWS_WITH(analyse_chain(ca, rec, RockingOptions{}, 0.5, Sidedness::two_sided),
                    doctest::Contains("mirror images"));
}

TEST_CASE("interpolated M, M', V', B match the exact evaluation of the chain") {
  for (const Foundation f : {Foundation::rigid(), Foundation::winkler(2e8)}) {
    const ChainDynamics cd(flexure_chain(Flexure{}), f);
    REQUIRE(cd.q_u() > 0.01);
    double sM = 0, sdM = 0, sV = 0, sB = 0;
    std::vector<ChainState> ex;
    for (int i = 0; i < 97; ++i) {  // off the nodes, all over [0, q_u]
      const double q = cd.q_u() * (i + 0.37) / 97.0;
      ex.push_back(cd.exact(q));
      sM = std::max(sM, std::fabs(ex.back().M));
      sdM = std::max(sdM, std::fabs(ex.back().dM));
      sV = std::max(sV, std::fabs(ex.back().dV));
      sB = std::max(sB, std::fabs(ex.back().B));
    }
    double eM = 0, edM = 0, eV = 0, eB = 0;
    for (const ChainState& s : ex) {
      eM = std::max(eM, std::fabs(cd.mass(s.q) - s.M) / sM);
      edM = std::max(edM, std::fabs(cd.dmass(s.q) - s.dM) / sdM);
      eV = std::max(eV, std::fabs(cd.dpotential(s.q) - s.dV) / sV);
      eB = std::max(eB, std::fabs(cd.coupling(s.q) - s.B) / sB);
    }
    MESSAGE("max relative interpolation error: M " << eM << ", M' " << edM << ", V' " << eV << ", B " << eB);
    CHECK(eM <= kInterpTol);
    CHECK(edM <= kInterpTol);
    CHECK(eV <= kInterpTol);
    CHECK(eB <= kInterpTol);
    // The Jacobian derivatives against central differences of the exact configuration.
    const double q = 0.4 * cd.q_u(), dq = 1e-5;
    const ChainState a = cd.exact(q - dq), b = cd.exact(q + dq), c = cd.exact(q);
    CHECK_CLOSE((b.V - a.V) / (2 * dq), c.dV, rel_tol(1e-8));
    CHECK_CLOSE((b.M - a.M) / (2 * dq), c.dM, rel_tol(1e-7));
    CHECK_CLOSE((b.dV - a.dV) / (2 * dq), c.d2V, rel_tol(1e-7));
  }
}

TEST_CASE("two-block chain with restitution 1: free motion conserves energy to 1e-8") {
  const ChainDynamics cd(flexure_chain(Flexure{}), Foundation::rigid());
  RockingOptions o = tight();
  o.record_history = true;
  const double q0 = 0.5 * cd.q_u();
  const RockingResult r = analyse_chain(cd, GroundMotion::none(3.0), o, -1.0, {q0, 0.0});
  REQUIRE(r.termination == RockingTermination::completed);
  CHECK(r.impacts >= 4);
  const double E0 = cd.exact(q0).V;
  double worst = 0.0;
  for (std::size_t i = 0; i < r.history.t.size(); i += 7) {
    const ChainState s = cd.exact(r.history.theta[i]);
    const double E = 0.5 * s.M * r.history.omega[i] * r.history.omega[i] + s.V;
    worst = std::max(worst, std::fabs(E - E0) / E0);
  }
  MESSAGE("impacts " << r.impacts << ", max |E - E0|/E0 = " << worst);
  CHECK(worst <= kEnergyTol);
  CHECK_CLOSE(r.theta_max, q0, rel_tol(1e-9));  // every rebound returns to q0
}

TEST_CASE("two-block chain on the Winkler bed with restitution 1: energy with the bed's elastic work") {
  // The bed's moment depends on q only, so 1/2 M q'^2 + work(q) is conserved
  // (work = V(q) + the bed's work, both branches; ChainDynamics::work).
  const ChainDynamics cd(flexure_chain(Flexure{}), Foundation::winkler(2e8));
  REQUIRE(cd.q_cr() > 0.0);
  RockingOptions o = tight();
  o.record_history = true;
  const double q0 = 0.4 * cd.q_u();
  REQUIRE(q0 > 10 * cd.q_cr());  // the motion crosses both branches
  const RockingResult r = analyse_chain(cd, GroundMotion::none(3.0), o, -1.0, {q0, 0.0});
  REQUIRE(r.termination == RockingTermination::completed);
  CHECK(r.impacts >= 4);
  const double E0 = cd.work(q0);
  double worst = 0.0;
  for (std::size_t i = 0; i < r.history.t.size(); ++i) {
    const double q = r.history.theta[i], w = r.history.omega[i];
    worst = std::max(worst, std::fabs(0.5 * cd.mass(q) * w * w + cd.work(q) - E0) / E0);
  }
  MESSAGE("Winkler: impacts " << r.impacts << ", max |E - E0|/E0 = " << worst);
  CHECK(worst <= kEnergyTol);
}

namespace {

// Independent model of the flexure chain: closed-form loop closure.
using C = std::complex<double>;
struct FlexureModel {
  Flexure f;
  double m1, m2, I1, I2, mQ, W1, W2;
  explicit FlexureModel(const Flexure& fl) : f(fl) {
    const double g = units::g, h2 = f.H - f.zh;
    W1 = f.gamma * f.t * f.zh;
    W2 = f.gamma * f.t * h2;
    m1 = W1 / g, m2 = W2 / g, mQ = f.Q / g;
    I1 = m1 * (f.t * f.t + f.zh * f.zh) / 12.0;
    I2 = m2 * (f.t * f.t + h2 * h2) / 12.0;
  }
  // Rotation clockwise by th of p about the origin.
  static void rotcw(C th, C x, C z, C& X, C& Z) {
    X = x * std::cos(th) + z * std::sin(th);
    Z = -x * std::sin(th) + z * std::cos(th);
  }
  // Positions at th (complex for complex-step derivatives): G1, G2, top load.
  void positions(C th, C* out) const {
    const double h2 = f.H - f.zh;
    C Bx, Bz, Gx, Gz;
    rotcw(th, -f.t, f.zh, Bx, Bz);
    rotcw(th, -0.5 * f.t, 0.5 * f.zh, Gx, Gz);
    // Upper block: counter-clockwise rotation psi about B with t cos psi - h2 sin psi = -Bx.
    const double rho = std::hypot(f.t, h2), beta = std::atan2(h2, f.t);
    const C psi = std::acos(-Bx / rho) - beta;
    auto up = [&](double x, double z, C& X, C& Z) {  // material point of the upper block
      const double dx = x + f.t, dz = z - f.zh;
      X = Bx + dx * std::cos(psi) - dz * std::sin(psi);
      Z = Bz + dx * std::sin(psi) + dz * std::cos(psi);
    };
    C G2x, G2z, Qx, Qz;
    up(-0.5 * f.t, f.zh + 0.5 * h2, G2x, G2z);
    up(-f.t + f.d, f.H, Qx, Qz);
    out[0] = Gx, out[1] = Gz, out[2] = G2x, out[3] = G2z, out[4] = Qx, out[5] = Qz, out[6] = psi;
  }
  // First derivatives by complex step (exact to rounding).
  void derivs(double th, double* d) const {
    const double hs = 1e-30;
    C p[7];
    positions(C(th, hs), p);
    for (int i = 0; i < 7; ++i) d[i] = p[i].imag() / hs;
  }
  double mass(double th) const {
    double d[7];
    derivs(th, d);
    return m1 * (d[0] * d[0] + d[1] * d[1]) + m2 * (d[2] * d[2] + d[3] * d[3]) + mQ * d[5] * d[5] + I1 +
           I2 * d[6] * d[6];
  }
  double accel(double th, double w, double ug) const {
    double d[7];
    derivs(th, d);
    const double M = mass(th), e = 1e-5, dM = (mass(th + e) - mass(th - e)) / (2 * e);
    const double dV = W1 * d[1] + W2 * d[3] + f.Q * d[5];
    const double B = m1 * d[0] + m2 * d[2];  // Q is not seismic
    return (-0.5 * dM * w * w - dV - ug * B) / M;
  }
};

}  // namespace

TEST_CASE("vertical flexure: first excursion under a one-sine pulse vs an independent Lagrangian") {
  const Flexure f;
  const FlexureModel ind(f);
  const ChainDynamics cd(flexure_chain(f), Foundation::rigid());
  // Lift-off acceleration of the independent model: V'(0) / B(0).
  double d[7];
  ind.derivs(0.0, d);
  const double a_lift = (ind.W1 * d[1] + ind.W2 * d[3] + f.Q * d[5]) / (ind.m1 * d[0] + ind.m2 * d[2]);
  const ChainState s0 = cd.exact(0.0);
  CHECK_CLOSE(s0.dV / s0.B, a_lift, rel_tol(1e-12));
  const double A = 1.6 * a_lift, Tp = 0.5, w = 2 * units::pi / Tp;
  auto ug = [&](double t) { return t <= Tp ? -A * std::sin(w * t) : 0.0; };
  // RK4 from the lift-off time to the first maximum.
  const double t_lift = std::asin(a_lift / A) / w;
  double t = t_lift, q = 0.0, v = 0.0, qmax = 0.0;
  const double dt = 2e-5;
  while (true) {
    auto F = [&](double tt, double qq, double vv, double& dq, double& dv) { dq = vv, dv = ind.accel(qq, vv, ug(tt)); };
    double k1q, k1v, k2q, k2v, k3q, k3v, k4q, k4v;
    F(t, q, v, k1q, k1v);
    F(t + dt / 2, q + dt / 2 * k1q, v + dt / 2 * k1v, k2q, k2v);
    F(t + dt / 2, q + dt / 2 * k2q, v + dt / 2 * k2v, k3q, k3v);
    F(t + dt, q + dt * k3q, v + dt * k3v, k4q, k4v);
    const double qn = q + dt / 6 * (k1q + 2 * k2q + 2 * k3q + k4q), vn = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (vn < 0.0 && v > 0.0) {  // maximum inside the step: cubic Hermite in time
      const double a0 = k1v, a1 = ind.accel(qn, vn, ug(t + dt));
      double lo = 0.0, hi = 1.0;
      auto vel = [&](double s) {
        return (2 * s * s * s - 3 * s * s + 1) * v + (s * s * s - 2 * s * s + s) * dt * a0 +
               (-2 * s * s * s + 3 * s * s) * vn + (s * s * s - s * s) * dt * a1;
      };
      for (int i = 0; i < 60; ++i) (vel(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
      const double s = 0.5 * (lo + hi);
      const double s2 = s * s, s3 = s2 * s;  // cubic Hermite of q from (q, v)
      qmax = (2 * s3 - 3 * s2 + 1) * q + (s3 - 2 * s2 + s) * dt * v + (-2 * s3 + 3 * s2) * qn + (s3 - s2) * dt * vn;
      break;
    }
    q = qn, v = vn, t += dt;
    REQUIRE(t < 5.0);
  }
  REQUIRE(qmax < cd.q_u());
  RockingOptions o = tight();
  const RockingResult r = analyse_chain(cd, GroundMotion::from_function(ug, 4.0, {Tp}, 0.01), o, 0.0);
  MESSAGE("flexure first excursion: independent " << qmax << " rad, engine " << r.theta_max << " rad (q_u "
                                                    << cd.q_u() << " rad), relative difference "
                                                    << std::fabs(r.theta_max - qmax) / qmax);
  CHECK(r.impacts == 1);  // e = 0: the chain stops at its first return
  CHECK_CLOSE(r.theta_max, qmax, rel_tol(kFlexureTol));
}

TEST_CASE("rocking frame of Makris & Vassiliou (2013): p_hat^2 = p^2 (1 + 2 gamma)/(1 + 3 gamma)") {
  // Two columns 2b x 2h at x = 0 and x = S, a beam of depth hb on top, hinged at
  // the columns' top inner corners; the columns rock about their outer toes.
  const double b = 0.25, h = 2.0, S = 4.0, hb = 0.5, gamma = 20e3;
  const Chain frame({rect("column 1", 0.0, 2 * b, 0.0, 2 * h, gamma), rect("column 2", S, S + 2 * b, 0.0, 2 * h, gamma),
                     rect("beam", 0.0, S + 2 * b, 2 * h, 2 * h + hb, gamma)},
                    {ground(0, V2(2 * b, 0.0)), ground(1, V2(S + 2 * b, 0.0)), hinge(0, 2, V2(0.0, 2 * h)),
                     hinge(1, 2, V2(S, 2 * h))},
                    {});
  const ChainDynamics cd(frame, Foundation::rigid());
  const double g = units::g, mc = gamma * 2 * b * 2 * h / g, mb = gamma * (S + 2 * b) * hb / g;
  const double R = std::hypot(b, h), alpha = std::atan(b / h), gam = mb / (2 * mc);
  for (double q : {0.0, 0.3 * alpha, 0.8 * alpha}) {
    CAPTURE(q);
    const ChainState s = cd.exact(q);
    CHECK_CLOSE(s.M, (8.0 / 3.0) * mc * R * R + 4 * mb * R * R, rel_tol(kFrameFormTol));
    CHECK_CLOSE(s.dV, 2 * (mc + mb) * g * R * std::sin(alpha - q), rel_tol(kFrameFormTol));
    CHECK_CLOSE(s.B, 2 * (mc + mb) * R * std::cos(alpha - q), rel_tol(kFrameFormTol));
    CHECK_CLOSE(s.dV / s.M, (1 + 2 * gam) / (1 + 3 * gam) * 3 * g / (4 * R) * std::sin(alpha - q),
                rel_tol(kFrameFormTol));
  }
  CHECK_CLOSE(cd.q_u(), alpha, abs_tol(1e-13));
  // One-sine pulse: the frame against one column with the modified frequency parameter
  // (a rocking body with the same R, alpha and I0 = M, i.e. p_hat).
  const double W = 2 * (mc + mb) * g;
  const RockingBody eq = RockingBody::from_centroid(W, R * std::sin(alpha), R * std::cos(alpha),
                                                    (8.0 / 3.0) * mc * R * R + 4 * mb * R * R, b);
  CHECK_CLOSE(eq.p() * eq.p(), (1 + 2 * gam) / (1 + 3 * gam) * 3 * g / (4 * R), rel_tol(kFrameFormTol));
  const RockingModel rm(eq, Foundation::rigid(), Sidedness::one_sided, Restitution::given(0.0));
  const GroundMotion p = one_sine(2.0 * g * std::tan(alpha), 0.8, 3.0);
  const RockingResult a = analyse(rm, p, tight()), c = analyse_chain(cd, p, tight(), 0.0);
  MESSAGE("frame theta_max: chain " << c.theta_max << " rad, equivalent column " << a.theta_max << " rad");
  CHECK(a.theta_max > 0.1 * alpha);
  CHECK_CLOSE(c.theta_max, a.theta_max, rel_tol(kFrameTol));
  // Two-sided (the frame is mirror-symmetric) under a record, e = 0.9 on both.
  REQUIRE(cd.symmetric());
  const RockingModel rm2(eq, Foundation::rigid(), Sidedness::two_sided, Restitution::given(0.9));
  const Record rec = read_record(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/RSN292_ITALY_A-STU270.AT2");
  RockingOptions o;
  o.scale = 1.0;
  const RockingResult a2 = analyse(rm2, rec, o), c2 = analyse_chain(cd, rec, o, 0.9, Sidedness::two_sided);
  MESSAGE("frame two-sided: chain " << c2.brief_report() << "; column " << a2.brief_report());
  CHECK(a2.impacts > 2);
  CHECK(c2.impacts == a2.impacts);
  CHECK_CLOSE(c2.theta_max, a2.theta_max, rel_tol(kFrameTol));
}

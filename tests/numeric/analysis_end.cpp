// The end of a dynamic analysis (issue 21; dynamics/analysis_end.hpp,
// docs/theory/rocking.md §8): every record is integrated to its last sample;
// the analysis ends earlier only where that is exact, and the free motion
// after the record ends at rest, when the energy left cannot reach the peak,
// or at the cap.
//
// Exactness is checked against the same analysis with the free motion made
// part of the excitation: the record padded with `cap` seconds of zeros and no
// free motion (tail_s = 0). Then the energy rule cannot fire (it applies
// after the motion only) and the integration goes on through the whole free
// motion; up to the early end both integrations take the same steps (the
// padded samples are the zero pieces the free motion integrates), so theta_max,
// the energy D/C, d_max and overturning must be equal to the bit.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/dynamics/chain_analysis.hpp>
#include <assess/dynamics/chain_dynamics.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/kinematic/chain.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <string>

using namespace assess;

namespace {

const std::string kRoot = std::string(ASSESS_TEST_DATA_DIR);
constexpr double kCap = 30.0;  // s, the default cap of the free motion

// One-sine pulse record, outward first: ug'' = A sin(2 pi t / Tp) on [0, Tp], dt = 1 ms (m/s^2).
Record pulse(double A, double Tp) {
  Record r;
  r.name = "one-sine";
  r.dt = 1e-3;
  const int n = int(std::lround(Tp / r.dt));
  for (int i = 0; i <= n; ++i) r.acc.push_back(A * std::sin(2.0 * units::pi * i * r.dt / Tp));
  return r;
}

Record padded(Record r, double seconds) {
  const auto extra = static_cast<std::size_t>(std::lround(seconds / r.dt));
  r.acc.insert(r.acc.end(), extra, 0.0);
  return r;
}

void same_as_padded(const RockingModel& m, const Record& rec, double scale, bool reverse) {
  RockingOptions o;
  o.scale = scale;
  o.reverse = reverse;
  const RockingResult a = analyse(m, rec, o);
  RockingOptions op = o;
  op.tail_s = 0.0;
  const RockingResult b = analyse(m, padded(rec, kCap), op);
  CAPTURE(to_string(a.end));
  CAPTURE(a.t_end);
  REQUIRE(succeeded(a));
  REQUIRE(succeeded(b));
  CHECK(a.motion_duration == doctest::Approx(rec.duration()).epsilon(1e-15));
  // The whole record is integrated unless the body overturned or rests for good.
  if (a.end != AnalysisEnd::overturned && a.end != AnalysisEnd::rest_input_below) CHECK(a.t_end >= rec.duration());
  CHECK(a.theta_max == b.theta_max);
  CHECK(a.dc == b.dc);
  CHECK(a.d_max == b.d_max);
  CHECK(a.overturned == b.overturned);
}

}  // namespace

TEST_CASE("the early end is exact: rocking block, pulses and a real record, every model and side") {
  const Record elcentro = read_record(kRoot + "/spectra/records/elCentro.AT2");
  const RockingBody body = RockingBody::rectangle(0.4, 4.0, 18e3);
  for (bool smooth : {false, true})
    for (Sidedness sd : {Sidedness::one_sided, Sidedness::two_sided}) {
      const Restitution e = sd == Sidedness::one_sided ? Restitution::given(-0.65) : Restitution::housner();
      const RockingModel m(body, smooth ? Foundation::winkler(1e9) : Foundation::rigid(), sd, e);
      for (bool rev : {false, true}) {
        CAPTURE(smooth);
        CAPTURE(int(sd));
        CAPTURE(rev);
        same_as_padded(m, pulse(0.35 * units::g_n, 0.2), 1.0, rev);
        same_as_padded(m, elcentro, 1.5, rev);
      }
    }
}

TEST_CASE("free motion after the record ends by the stated rule") {
  // A rigid one-sided block thrown by a pulse comes to rest (e = 0: the first
  // impact stops it) or its energy decays at the impacts; never at the cap.
  const RockingBody body = RockingBody::rectangle(0.4, 4.0, 18e3);
  const RockingModel stop(body, Foundation::rigid(), Sidedness::one_sided, Restitution::given(0.0));
  const RockingResult a = analyse(stop, pulse(0.35 * units::g_n, 0.2), RockingOptions{});
  CHECK(a.end == AnalysisEnd::rest_after_motion);
  CHECK(a.impacts == 1);
  const RockingModel bounce(body, Foundation::rigid(), Sidedness::one_sided, Restitution::given(-0.65));
  const RockingResult b = analyse(bounce, pulse(0.35 * units::g_n, 0.2), RockingOptions{});
  CHECK(b.end == AnalysisEnd::energy_decayed);
  CHECK(b.t_end < b.motion_duration + kCap);
  // No dissipation (no impact law): the energy never decays; the cap ends it.
  const RockingModel smooth(body, Foundation::winkler(1e9), Sidedness::two_sided, Restitution::none());
  const RockingResult c = analyse(smooth, pulse(0.35 * units::g_n, 0.2), RockingOptions{});
  CHECK(c.end == AnalysisEnd::free_motion_cap);
  CHECK(c.t_end == doctest::Approx(c.motion_duration + kCap).epsilon(1e-12));
  // Overturning.
  const RockingResult d = analyse(bounce, pulse(3.0 * units::g_n, 0.5), RockingOptions{});
  CHECK(d.overturned);
  CHECK(d.end == AnalysisEnd::overturned);
}

TEST_CASE("at rest during the record: the end is exact when no later sample can lift the body") {
  // Rigid block: lift-off needs |ug''| > g tan(alpha) = g b/h = 0.1 g. A
  // strong pulse, then 20 s of a 0.05 g sine (half the threshold): the
  // block comes to rest (e = 0) and the rest of the record cannot lift it.
  const RockingBody body = RockingBody::rectangle(0.4, 4.0, 18e3);
  const RockingModel m(body, Foundation::rigid(), Sidedness::one_sided, Restitution::given(0.0));
  Record weak = pulse(0.35 * units::g_n, 0.2);
  for (int i = 1; i <= 20000; ++i) weak.acc.push_back(0.05 * units::g_n * std::sin(2.0 * units::pi * i * 1e-3 / 0.3));
  const RockingResult a = analyse(m, weak, RockingOptions{});
  CHECK(a.end == AnalysisEnd::rest_input_below);
  CHECK(a.t_end < 1.0);
  // What follows the end cannot move the resting body: the same record with
  // zeros from two samples after the end gives the same result to the bit.
  Record zero = weak;
  for (std::size_t i = static_cast<std::size_t>(a.t_end / weak.dt) + 2; i < zero.acc.size(); ++i) zero.acc[i] = 0.0;
  const RockingResult b = analyse(m, zero, RockingOptions{});
  CHECK(a.theta_max == b.theta_max);
  CHECK(a.dc == b.dc);
  CHECK(a.impacts == b.impacts);
  // A threshold crossed in the last samples keeps the analysis going to them:
  // +-0.2 g at the very end lifts the block again (whichever its side).
  Record late = weak;
  late.acc.push_back(0.2 * units::g_n);
  late.acc.push_back(-0.2 * units::g_n);
  const RockingResult c = analyse(m, late, RockingOptions{});
  CHECK(c.end != AnalysisEnd::rest_input_below);
  CHECK(c.t_end >= late.duration());
  CHECK(c.impacts > a.impacts);
}

TEST_CASE("the early end is exact: a two-block chain (vertical flexure), one-sided") {
  using V2 = Eigen::Vector2d;
  auto rect = [](const std::string& name, double x0, double x1, double z0, double z1) {
    Block b;
    b.name = name;
    b.polygon = {V2(x0, z0), V2(x1, z0), V2(x1, z1), V2(x0, z1)};
    b.unit_weight = 18e3;
    b.length = 1.0;
    return b;
  };
  Constraint g0;
  g0.type = ConstraintType::GroundHinge, g0.block = 0, g0.point = V2(0.0, 0.0);
  Constraint h;
  h.type = ConstraintType::Hinge, h.block = 0, h.other = 1, h.point = V2(-0.4, 2.4);
  Constraint top;
  top.type = ConstraintType::Slider, top.block = 1, top.point = V2(0.0, 4.0), top.direction = V2(0.0, 1.0);
  const Chain chain({rect("lower", -0.4, 0.0, 0.0, 2.4), rect("upper", -0.4, 0.0, 2.4, 4.0)}, {g0, h, top}, {});
  const ChainDynamics cd(chain, Foundation::rigid());
  const Record elcentro = read_record(kRoot + "/spectra/records/elCentro.AT2");
  for (double e : {0.0, -0.5})
    for (const Record& rec : {pulse(0.6 * units::g_n, 0.25), elcentro}) {
      RockingOptions o;
      o.scale = 2.0;
      const RockingResult a = analyse_chain(cd, rec, o, e);
      RockingOptions op = o;
      op.tail_s = 0.0;
      const RockingResult b = analyse_chain(cd, padded(rec, kCap), op, e);
      CAPTURE(e);
      CAPTURE(to_string(a.end));
      REQUIRE(succeeded(a));
      CHECK(a.theta_max == b.theta_max);
      CHECK(a.dc == b.dc);
      CHECK(a.overturned == b.overturned);
      if (!a.overturned && a.end != AnalysisEnd::rest_input_below) CHECK(a.t_end >= rec.duration());
    }
}

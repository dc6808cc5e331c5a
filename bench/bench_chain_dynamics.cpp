// bench_chain_dynamics.cpp: a two-block chain (vertical flexure, 0.3 m x 6 m, middle
// hinge at 4.77 m, top load 5 kN, rigid, e = -0.5) against a single block
// (façade 0.45 m x 3.5 m on its outer toe, rigid, e = -0.5, the rocking model)
// under the same 39.3 s record (Sturno E-W, RSN292_ITALY_A-STU270.AT2, scaled
// x 1.6 for the chain, x 1.35 for the block: both rock for the whole record without
// overturning, q_max/q_u 0.26 and 0.39). Prints ms per analysis (best of N),
// steps, rhs evaluations, impacts and the ratio chain/single (target <= 3).
// Also: the single block by the chain path (identity) and the set-up time of
// the chain model (grid). Usage: bench_chain_dynamics [repeats] [chain scale] [block scale]
#include <assess/dynamics/chain_analysis.hpp>
#include <assess/dynamics/rocking_from_chain.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>

using namespace assess;
using V2 = Eigen::Vector2d;

namespace {
Block rect(const char* name, double x0, double x1, double z0, double z1) {
  Block b;
  b.name = name;
  b.polygon = {V2(x0, z0), V2(x1, z0), V2(x1, z1), V2(x0, z1)};
  b.unit_weight = 18e3;
  return b;
}
double best_ms(int n, const std::function<void()>& f) {
  double best = 1e300;
  for (int i = 0; i < n; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 20;
  const Record rec = read_record(data_dir() + "/spectra/records/RSN292_ITALY_A-STU270.AT2");
  // Two-block chain: vertical flexure.
  const double t = 0.3, H = 6.0, zh = 4.767;
  Constraint g0, mid, top;
  g0.type = ConstraintType::GroundHinge, g0.block = 0, g0.point = V2(0, 0);
  mid.type = ConstraintType::Hinge, mid.block = 0, mid.other = 1, mid.point = V2(-t, zh);
  top.type = ConstraintType::Slider, top.block = 1, top.point = V2(0, H), top.direction = V2(0, 1);
  Load q;
  q.type = LoadType::Weight, q.block = 1, q.point = V2(-0.15, H), q.weight = 5e3, q.seismic = false;
  const Chain flex({rect("lower", -t, 0, 0, zh), rect("upper", -t, 0, zh, H)}, {g0, mid, top}, {q});
  ChainDynamics* cd = nullptr;
  const double setup = best_ms(5, [&] { delete cd; cd = new ChainDynamics(flex, Foundation::rigid()); });
  // Single block.
  Constraint gb;
  gb.type = ConstraintType::GroundHinge, gb.block = 0, gb.point = V2(0, 0);
  const Chain blk({rect("wall", -0.45, 0, 0, 3.5)}, {gb}, {});
  const RockingModel rm(rocking_body_from_chain(blk).body, Foundation::rigid(), Sidedness::one_sided,
                        Restitution::given(-0.5));
  const ChainDynamics cb(blk, Foundation::rigid());

  RockingOptions oc, ob;
  oc.scale = argc > 2 ? std::atof(argv[2]) : 1.6;
  ob.scale = argc > 3 ? std::atof(argv[3]) : 1.35;
  RockingResult rc, rb, rbc;
  const double t_chain = best_ms(repeats, [&] { rc = analyse_chain(*cd, rec, oc, -0.5); });
  const double t_block = best_ms(repeats, [&] { rb = analyse(rm, rec, ob); });
  const double t_block_chain = best_ms(repeats, [&] { rbc = analyse_chain(cb, rec, ob, -0.5); });
  std::printf("bench_chain_dynamics: record %s (%zu points, dt = %g s, %.1f s) x %g (chain), x %g (block), rigid, "
              "one-sided, e = -0.5\n",
              rec.name.c_str(), rec.size(), rec.dt, rec.duration(), oc.scale, ob.scale);
  std::printf("two-block chain (vertical flexure): %.3f ms (best of %d), %ld steps, %ld rhs, %ld impacts, "
              "q_max/q_u = %.4f%s\n",
              t_chain, repeats, rc.steps, rc.rhs_evaluations, rc.impacts, rc.theta_max / rc.theta_u,
              rc.overturned ? " (overturned)" : "");
  std::printf("single block (rocking model):       %.3f ms, %ld steps, %ld rhs, %ld impacts, theta_max/theta_u = %.4f\n",
              t_block, rb.steps, rb.rhs_evaluations, rb.impacts, rb.theta_max / rb.theta_u);
  std::printf("single block (chain path):          %.3f ms, theta_max difference %.3g rad\n", t_block_chain,
              std::fabs(rbc.theta_max - rb.theta_max));
  std::printf("ratio two-block chain / single block = %.2f (target <= 3); per rhs %.1f ns vs %.1f ns\n",
              t_chain / t_block, 1e6 * t_chain / double(rc.rhs_evaluations), 1e6 * t_block / double(rb.rhs_evaluations));
  std::printf("chain model set-up (grid of %zu intervals of %.6f rad): %.3f ms\n", cd->grid_intervals(),
              cd->grid_step(), setup);
  delete cd;
  return 0;
}

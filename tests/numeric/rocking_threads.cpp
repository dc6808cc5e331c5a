// Analyses run concurrently (as campaigns do on all cores) give the same
// results as the same analyses run one after the other.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/record_io.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <thread>
#include <vector>

using namespace assess;

TEST_CASE("concurrent analyses reproduce the serial results bit for bit") {
  const Record rec = read_record(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/RSN292_ITALY_A-STU270.AT2");
  const RockingModel model(RockingBody::rectangle(0.25, 3.0, 12.06 * units::kN), Foundation::winkler(1e9),
                           Sidedness::two_sided, Restitution::housner());
  const int n = 8;
  std::vector<RockingOptions> opts(n);
  for (int i = 0; i < n; ++i) opts[i].scale = 0.1 + 0.1 * i;
  std::vector<RockingResult> serial(n), parallel(n);
  for (int i = 0; i < n; ++i) serial[i] = analyse(model, rec, opts[i]);
  std::vector<std::thread> pool;
  for (int i = 0; i < n; ++i) pool.emplace_back([&, i] { parallel[i] = analyse(model, rec, opts[i]); });
  for (auto& t : pool) t.join();
  for (int i = 0; i < n; ++i) {
    CAPTURE(i);
    CHECK(parallel[i].theta_max == serial[i].theta_max);
    CHECK(parallel[i].impacts == serial[i].impacts);
    CHECK(parallel[i].overturned == serial[i].overturned);
    CHECK(parallel[i].rhs_evaluations == serial[i].rhs_evaluations);
  }
}

// Plain records in a campaign file (issue 11): {"file", "dt", "unit"} for one
// column and {"file", "unit"} for two columns give the same accelerogram as
// the AT2 file they were copied from (tests/data/elcentro_plain_*.txt hold El
// Centro 1940 NS of spectra/records/elCentro.AT2, in g and in cm/s^2).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/campaign/campaign.hpp>
#include <assess/support/error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using assess::test::abs_tol;
using nlohmann::json;

namespace {
const std::string kData = ASSESS_TEST_DATA_DIR;
// The one-column file copies the AT2 decimals (g): identical after the same
// conversion. The two-column file holds g x 980.665 to 10 significant digits:
// 1e-10 relative of a PGA of about 3.4 m/s^2.
constexpr double tol_same = 1e-15;  // m/s^2
constexpr double tol_cm = 1e-8;     // m/s^2

json spec(json record) {
  return json{{"walls", json::array({{{"b", 0.2}, {"h", 2.0}}})},
              {"unit_weight_kN_m3", 18.0},
              {"k_kN_m3", 1e6},
              {"records", json::array({"spectra/records/elCentro.AT2", std::move(record)})},
              {"scale_factors", json::array({1.0})}};
}
}  // namespace

TEST_CASE("campaign: plain one- and two-column records read like the AT2 file") {
  for (const json& rec : {json{{"file", "tests/data/elcentro_plain_1col.txt"}, {"dt", 0.02}, {"unit", "g"}},
                          json{{"file", "tests/data/elcentro_plain_2col_cms2.txt"}, {"unit", "cm/s^2"}}}) {
    INFO(rec.dump());
    const assess::Campaign c(assess::parse_campaign(spec(rec), kData));
    const assess::Record a = c.applied_record(0, 0, 1.0), b = c.applied_record(1, 0, 1.0);
    REQUIRE(a.acc.size() == b.acc.size());
    CHECK(a.dt == doctest::Approx(b.dt).epsilon(1e-12));
    const double tol = rec.contains("dt") ? tol_same : tol_cm;
    double worst = 0.0;
    for (std::size_t i = 0; i < a.acc.size(); ++i) worst = std::max(worst, std::fabs(b.acc[i] - a.acc[i]));
    CHECK_CLOSE(worst, 0.0, abs_tol(tol));
  }
}

TEST_CASE("campaign: plain record errors name the JSON pointer") {
  auto error_of = [](const json& rec) {
    try {
      assess::parse_campaign(spec(rec), kData);
    } catch (const assess::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error_of({{"file", "tests/data/elcentro_plain_1col.txt"}, {"dt", 0.02}}).find("/records/1: a plain record with \"dt\" needs \"unit\"") !=
        std::string::npos);
  CHECK(error_of({{"file", "tests/data/elcentro_plain_1col.txt"}, {"unit", "furlongs"}}).find("/records/1/unit") !=
        std::string::npos);
  CHECK(error_of({{"file", "tests/data/elcentro_plain_1col.txt"}, {"dt", -1.0}, {"unit", "g"}}).find("/records/1/dt") !=
        std::string::npos);
}

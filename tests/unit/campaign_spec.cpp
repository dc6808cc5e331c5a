// Campaign spec: JSON parsing with JSON-path errors, the flat index and the
// counter-based random multipliers.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/campaign/campaign.hpp"
#include "assess/support/error.hpp"

#include <cmath>
#include <string>

using assess::test::abs_tol;
using nlohmann::json;

namespace {

const std::string kData = std::string(ASSESS_TEST_DATA_DIR);

// Statistics of 40000 realisations: the standard error of the mean is
// cov/sqrt(n) = 1.5e-4 and of the standard deviation cov/sqrt(2n) = 1.1e-4;
// 5 standard errors (-).
constexpr double kMeanAbsTol = 7.5e-4;
constexpr double kStdAbsTol = 5.5e-4;
// Sample correlation of the time and amplitude multipliers: standard error 1/sqrt(n) = 0.005; 5 of them (-).
constexpr double kCorrAbsTol = 0.025;

json tiny() {
  return json::parse(R"({
    "walls": [{"b": 0.125, "h": 1.5}, {"name": "w2", "b": 0.25, "h": 3.0, "k_kN_m3": 2e6}],
    "unit_weight_kN_m3": 12.06, "k_kN_m3": 1e6,
    "records": ["spectra/records/RSN292_ITALY_A-STU270.AT2",
                {"name": "Bevagna", "file": "spectra/records/RSN4346_UBMARCHE.P_A-BEV270.AT2"}],
    "scale_factors": {"from": 0.2, "to": 2.0, "step": 0.2},
    "realisations": 3, "restitution": ["housner", 0.9], "seed": 5})");
}

std::string error_of(const json& j) {
  try {
    assess::parse_campaign(j, kData);
  } catch (const assess::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("campaign spec: values, defaults and half-dimension walls") {
  const assess::CampaignSpec s = assess::parse_campaign(tiny(), kData);
  REQUIRE(s.walls.size() == 2);
  CHECK(s.walls[0].name == "b0.125_h1.5");
  CHECK(s.walls[0].b_m == 0.125);
  CHECK(s.walls[1].k_N_m3 == 2e9);
  CHECK(s.walls[0].k_N_m3 == 1e9);
  CHECK(s.walls[0].unit_weight_N_m3 == 12060.0);
  CHECK(s.records[0].name == "RSN292_ITALY_A-STU270.AT2");
  CHECK(s.records[1].name == "Bevagna");
  REQUIRE(s.scale_factors.size() == 10);
  // Generated from from/to/step, they are the decimal values (0.6, not 0.6000000000000001).
  const double decimal[] = {0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0};
  for (int i = 0; i < 10; ++i) CHECK(s.scale_factors[i] == decimal[i]);
  CHECK(s.models.size() == 2);
  CHECK(s.restitutions[1].label == "0.9");
  CHECK(s.time_cov == 0.03);
  CHECK(s.amplitude_cov == 0.03);
  CHECK(s.size() == 2u * 2 * 10 * 3 * 2 * 2);
}

TEST_CASE("campaign spec: records by catalogue id") {
  json j = tiny();
  j["records"][1] = {{"id", "RSN289_1"}};
  const assess::CampaignSpec s = assess::parse_campaign(j, kData);
  CHECK(s.records[1].name == "RSN289_1");
  CHECK(s.records[1].path.find("spectra/records/RSN289_1.AT2") != std::string::npos);
  j["records"][1] = {{"id", "RSN999_NOWHERE"}};
  CHECK(error_of(j).find("/records/1/id: 'RSN999_NOWHERE' is not in the record catalogue") == 0);
}

TEST_CASE("campaign spec: errors name the JSON path") {
  json j = tiny();
  j["records"][1]["file"] = "spectra/records/no_such_record.AT2";
  CHECK(error_of(j).find("/records/1/file: record file 'spectra/records/no_such_record.AT2' not found") == 0);
  j = tiny();
  j["walls"][1]["h"] = 0.1;
  CHECK(error_of(j).find("/walls/1/h") == 0);
  j = tiny();
  j["scale_factors"] = json::array({0.5, -1});
  CHECK(error_of(j).find("/scale_factors/1") == 0);
  j = tiny();
  j["restitution"] = json::array({"housner", 1.5});
  CHECK(error_of(j).find("/restitution/1") == 0);
  j = tiny();
  j["models"] = json::array({"elastic"});
  CHECK(error_of(j).find("/models/0") == 0);
  j = tiny();
  j["time_cov"] = 0.5;
  CHECK(error_of(j).find("/time_cov") == 0);
  j = tiny();
  j["integrator"] = {{"rel_tol", -1}};
  CHECK(error_of(j).find("/integrator/rel_tol") == 0);
  j = tiny();
  j["walls"][0]["name"] = 12;
  CHECK(error_of(j).find("/walls/0/name: expected a string") == 0);
  j = tiny();
  j["realisation"] = 3;  // typo
  CHECK(error_of(j).find("/realisation: unknown key") == 0);
  j = tiny();
  j.erase("k_kN_m3");
  CHECK(error_of(j).find("/walls/0: the smooth model needs k_kN_m3") == 0);
}

TEST_CASE("campaign index: compose inverts decompose, model is the fastest index") {
  const assess::CampaignSpec s = assess::parse_campaign(tiny(), kData);
  for (std::uint64_t id = 0; id < s.size(); ++id) CHECK(assess::compose(s, assess::decompose(s, id)) == id);
  const auto a = assess::decompose(s, 0), b = assess::decompose(s, 1), c = assess::decompose(s, s.size() - 1);
  CHECK(a.model == 0);
  CHECK(b.model == 1);
  CHECK(b.wall == 0);
  CHECK(c.wall == 1);
  CHECK(c.record == 1);
  CHECK(c.scale == 9);
  CHECK(c.realisation == 2);
  CHECK(c.restitution == 1);
  CHECK(c.model == 1);
  // A group (same applied record) is restitutions x models consecutive ids.
  CHECK(s.group_size() == 4);
  CHECK(assess::decompose(s, 4).realisation == 1);
}

TEST_CASE("multipliers: realisation 0 is the record itself; the rest are N(1, cov), reproducible") {
  const auto p0 = assess::perturbation(42, 3, 0, 0.03, 0.03);
  CHECK(p0.time == 1.0);
  CHECK(p0.amplitude == 1.0);
  const auto p1 = assess::perturbation(42, 3, 7, 0.03, 0.03), p2 = assess::perturbation(42, 3, 7, 0.03, 0.03);
  CHECK(p1.time == p2.time);
  CHECK(p1.amplitude == p2.amplitude);
  CHECK(assess::perturbation(43, 3, 7, 0.03, 0.03).time != p1.time);
  CHECK(assess::perturbation(42, 2, 7, 0.03, 0.03).time != p1.time);

  const int n = 40000;
  double st = 0, st2 = 0, sa = 0, sa2 = 0, sta = 0;
  for (int k = 1; k <= n; ++k) {
    const auto p = assess::perturbation(42, 1, std::size_t(k), 0.03, 0.03);
    st += p.time, st2 += p.time * p.time, sa += p.amplitude, sa2 += p.amplitude * p.amplitude;
    sta += (p.time - 1) * (p.amplitude - 1);
  }
  const double mt = st / n, ma = sa / n;
  const double sdt = std::sqrt(st2 / n - mt * mt), sda = std::sqrt(sa2 / n - ma * ma);
  CHECK_CLOSE(mt, 1.0, abs_tol(kMeanAbsTol));
  CHECK_CLOSE(ma, 1.0, abs_tol(kMeanAbsTol));
  CHECK_CLOSE(sdt, 0.03, abs_tol(kStdAbsTol));
  CHECK_CLOSE(sda, 0.03, abs_tol(kStdAbsTol));
  CHECK_CLOSE(sta / n / (sdt * sda), 0.0, abs_tol(kCorrAbsTol));
}

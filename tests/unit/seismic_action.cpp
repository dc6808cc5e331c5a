// Reference and return periods (NTC 2018 §2.4, §3.2.1) against ntc.md §1.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/support/error.hpp>
#include <assess/hazard/seismic_action.hpp>

using namespace assess;
using assess::test::abs_tol;

// TR values of ntc.md §1 are printed to 0.01 year.
constexpr double tol_tr_years = 0.006;

TEST_CASE("TR for VN = 50 years and each CU matches the table of NTC 2018 [3.2.0]") {
  struct Row {
    double cu, slo, sld, slv, slc;
  };
  // ntc.md §1 table (computed from [3.2.0]); CU 0.7 has VR = 35 (floor).
  const Row rows[] = {{0.7, 21.08, 35.20, 332.19, 682.35},
                      {1.0, 30.11, 50.29, 474.56, 974.79},
                      {1.5, 45.16, 75.43, 711.84, 1462.18},
                      {2.0, 60.21, 100.58, 949.12, 1949.57}};
  for (const Row& r : rows) {
    CAPTURE(r.cu);
    CHECK_CLOSE(return_period(50, r.cu, LimitState::SLO), r.slo, abs_tol(tol_tr_years));
    CHECK_CLOSE(return_period(50, r.cu, LimitState::SLD), r.sld, abs_tol(tol_tr_years));
    CHECK_CLOSE(return_period(50, r.cu, LimitState::SLV), r.slv, abs_tol(tol_tr_years));
    CHECK_CLOSE(return_period(50, r.cu, LimitState::SLC), r.slc, abs_tol(tol_tr_years));
  }
}

TEST_CASE("VR has a floor of 35 years and CU follows Tab. 2.4.II") {
  CHECK(reference_period(10, 1.0) == 35.0);
  CHECK(reference_period(50, 2.0) == 100.0);
  CHECK(use_coefficient(1) == 0.7);
  CHECK(use_coefficient(2) == 1.0);
  CHECK(use_coefficient(3) == 1.5);
  CHECK(use_coefficient(4) == 2.0);
  CHECK(parse_use_class("iii") == 3);
  CHECK(parse_use_class("4") == 4);
  CHECK_THROWS_AS(parse_use_class("V"), InputError);
  CHECK_THROWS_AS(reference_period(0, 1), InputError);
  CHECK_THROWS_AS(reference_period(50, -1), InputError);
}

TEST_CASE("P_VR of Tab. 3.2.I and limit-state names") {
  CHECK(exceedance_probability(LimitState::SLO) == 0.81);
  CHECK(exceedance_probability(LimitState::SLD) == 0.63);
  CHECK(exceedance_probability(LimitState::SLV) == 0.10);
  CHECK(exceedance_probability(LimitState::SLC) == 0.05);
  CHECK(parse_limit_state("slv") == LimitState::SLV);
  CHECK(to_string(LimitState::SLC) == "SLC");
  CHECK_THROWS_WITH_AS(parse_limit_state("ULS"), doctest::Contains("SLO, SLD, SLV, SLC"), InputError);
}

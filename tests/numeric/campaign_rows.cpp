// A small campaign's rows agree with single rocking analyses built
// independently (record read, scaled and time-stretched by hand) and with
// the code ratios of the seed's Eq. 8 computed from the record's own spectrum.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/campaign/campaign.hpp"
#include "assess/campaign/campaign_runner.hpp"
#include "assess/kinematic/free_wall_capacity.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/dynamics/rocking_analysis.hpp"

#include <string>

using assess::test::rel_tol;

namespace {

const std::string kDir = std::string(ASSESS_TEST_DATA_DIR);
// Campaign rows vs the same computation done by hand: the same arithmetic up
// to the rounding of the multiplied record (scale * amplitude in one factor
// vs two), so agreement to a few ulps is expected; the CSV keeps 10
// significant digits (-).
constexpr double kRowRelTol = 1e-9;
// Chaotic rocking amplifies the rounding differences of the record; peak
// rotations and D/C are compared to 1e-6 relative (-).
constexpr double kDynamicsRelTol = 1e-6;

}  // namespace

TEST_CASE("campaign rows equal single analyse() runs with the same applied record") {
  const assess::Campaign c(assess::read_campaign(kDir + "/tests/data/campaign/tiny.json"));
  const assess::CampaignSpec& s = c.spec();
  for (std::uint64_t id : {0ull, 1ull, 7ull, 22ull, 35ull, 47ull}) {
    CAPTURE(id);
    const assess::AnalysisIndex ix = assess::decompose(s, id);
    const assess::AnalysisRow row = assess::parse_campaign_csv_row(assess::campaign_csv_row(c.evaluate(id)));
    REQUIRE(row.ok);

    // Independent construction of the analysis.
    assess::Record rec = assess::read_record(s.records[ix.record].path);
    const assess::Perturbation p = assess::perturbation(s.seed, ix.record, ix.realisation, s.time_cov, s.amplitude_cov);
    CHECK(row.time_mult == doctest::Approx(p.time).epsilon(kRowRelTol));
    for (double& a : rec.acc) a *= s.scale_factors[ix.scale] * p.amplitude;
    rec.dt *= p.time;
    const auto& w = s.walls[ix.wall];
    const assess::RockingBody body = assess::RockingBody::rectangle(2 * w.b_m, 2 * w.h_m, w.unit_weight_N_m3);
    const bool smooth = s.models[ix.model] == assess::CampaignModel::smooth;
    const assess::RockingModel model(body, smooth ? assess::Foundation::winkler(w.k_N_m3) : assess::Foundation::rigid(),
                                     assess::Sidedness::two_sided, assess::Restitution::housner());
    const assess::RockingResult r = assess::analyse(model, rec, assess::RockingOptions{});
    const assess::FreeWallCapacity cap = assess::free_wall_capacity(w.b_m, w.h_m);
    const double sd = assess::spectral_ordinates(rec, cap.Ts).SD;

    CHECK(row.model == (smooth ? "smooth" : "rigid"));
    CHECK_CLOSE(row.pga_m_s2, rec.pga(), rel_tol(kRowRelTol));
    CHECK_CLOSE(row.Ts_s, cap.Ts, rel_tol(kRowRelTol));
    CHECK_CLOSE(row.SDe_Ts_m, sd, rel_tol(kRowRelTol));
    CHECK_CLOSE(row.dc_strength, rec.pga() / (2 * cap.a0_star), rel_tol(kRowRelTol));
    CHECK_CLOSE(row.dc_displacement, sd / cap.du_star, rel_tol(kRowRelTol));
    CHECK(row.overturned == r.overturned);
    CHECK(row.impacts == r.impacts);
    CHECK_CLOSE(row.theta_max_rad, r.theta_max, rel_tol(kDynamicsRelTol));
    CHECK_CLOSE(row.theta_u_rad, r.theta_u, rel_tol(kRowRelTol));
    CHECK_CLOSE(row.dc_energy, r.dc, rel_tol(kDynamicsRelTol));
  }
}

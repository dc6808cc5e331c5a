// fragility_job.hpp: the analyses of a fragility study as a campaign job, so
// that the campaign runner runs them (threads, ordered streaming CSV, resume,
// MPI parts). Id = (group * polarities + polarity) * restitutions +
// restitution, a group being one record of one stripe, groups numbered
// stripe by stripe.
#pragma once

#include "assess/campaign/campaign_runner.hpp"
#include "assess/risk/fragility_study.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace assess {

/// One analysis of a fragility study (one line of results.csv).
struct FragilityRow {
  std::uint64_t id = 0;
  std::size_t stripe = 0;
  double TR_years = 0, im_m_s2 = 0;  ///< the stripe's return period and PGA
  std::string record;
  double scale = 1;
  bool reversed = false;
  std::size_t restitution = 0;  ///< index in the case's restitution list
  double theta_max_rad = 0, theta_u_rad = 0, theta_ratio = 0;
  double d_star_m = 0;     ///< peak d* of the control point [C8.7.1.4] (m)
  double dc_energy = 0;    ///< energy demand/capacity (seed §3.2) (-)
  double dc_displacement = 0;  ///< d* / d_SLV [C8.7.1.2.1.9] (-)
  bool overturned = false;
  std::string termination;
  bool ok = true;
  std::string reason;
};

std::string fragility_csv_header();
std::string fragility_csv_row(const FragilityRow& r);
/// @throws InputError if the line is malformed
FragilityRow parse_fragility_csv_row(const std::string& line);
/// Reads every row of a results file. @throws InputError naming the file.
std::vector<FragilityRow> read_fragility_csv(const std::string& path);

/// The study as a job for run_campaign_job().
class FragilityJob final : public CampaignJob {
 public:
  explicit FragilityJob(const FragilityStudy& study) : s_(study) {}
  std::uint64_t size() const override { return s_.size(); }
  std::uint64_t group_size() const override { return s_.group_size(); }
  std::string inputs_file() const override { return "fragility.json"; }
  /// The normalised inputs: case file, method, stripes with records and scales.
  std::string inputs_text() const override;
  std::string csv_header() const override { return fragility_csv_header(); }
  std::vector<std::string> evaluate_csv(std::uint64_t first, std::uint64_t end, std::uint64_t& failed) const override;
  std::uint64_t row_id(const std::string& line) const override { return parse_fragility_csv_row(line).id; }

  /// The analyses [first, end) of one group.
  std::vector<FragilityRow> evaluate(std::uint64_t first, std::uint64_t end) const;

 private:
  const FragilityStudy& s_;
};

}  // namespace assess

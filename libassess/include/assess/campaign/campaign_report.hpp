// campaign_report.hpp: the summary (summary.json) and the plots of a
// campaign, equivalent to the seed paper's Fig. 4a, 4b, 5a and 5b.
#pragma once

#include "assess/campaign/campaign.hpp"
#include "assess/report/plot.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace assess {

/// Statistics of a set of rows: per (wall, record, model, restitution) the
/// counts of analyses, failures and overturning, and the mean and sample
/// standard deviation of the energy D/C, theta_max/theta_u and the two code
/// ratios; per (model, scale) the fraction of analyses in which the wall
/// moved; and the comparison of the code ratios with the dynamic D/C.
nlohmann::json summarise_campaign(const std::vector<AnalysisRow>& rows);

/// Plots of the campaign (name of the SVG file, plot):
///  - fig4a_<wall>.svg (wall name with characters other than letters, digits,
///    '.', '-', '_' replaced by '_'): dynamic D/C against PGA, smooth vs rigid (means over
///    the realisations per record and scale, with +/- one standard deviation);
///  - fig4b_capacity.svg: moment-rotation curves of the walls, smooth and rigid;
///  - fig5a_strength.svg, fig5b_displacement.svg: code D/C against dynamic D/C
///    (means over the realisations), with the line of equality.
std::vector<std::pair<std::string, Plot>> campaign_plots(const Campaign& campaign,
                                                         const std::vector<AnalysisRow>& rows);

/// Files written by write_campaign_report.
struct CampaignReportFiles {
  std::string summary;             ///< out_dir/summary.json
  std::vector<std::string> plots;  ///< SVG files (empty if plots were not asked for)
  std::string index;               ///< out_dir/index.html: the summary tables and the plots
};

/// The campaign's index page: self-contained HTML with the summary tables
/// (by model, by model and scale, code against dynamic verdicts) and the
/// plots inline (file name, SVG). Formatting only: reads the summary.
std::string campaign_index_html(const nlohmann::json& summary,
                                const std::vector<std::pair<std::string, std::string>>& svgs);

/// Reads out_dir/results.csv and writes summary.json, index.html and, if
/// `plots`, the SVG plots (render_svg). @throws InputError if a file cannot be
/// read or written.
CampaignReportFiles write_campaign_report(const Campaign& campaign, const std::string& out_dir, bool plots = true);

}  // namespace assess

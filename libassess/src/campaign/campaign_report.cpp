// campaign_report.cpp: summary statistics and plots of a campaign (seed paper
// Lipo & de Felice 2017, §3.2, Fig. 4 and 5).
//
// Notation:
//   dc_energy        dynamic (energy) demand/capacity of the rocking analysis (seed Fig. 3)
//   dc_strength      PGA/(2 a0*), dc_displacement SDe(Ts)/du*  (seed Eq. 8)
//   mean, std        arithmetic mean and sample standard deviation (n - 1) over the
//                    analyses with status ok
//   moved            theta_max > 0: the block left its rest position
#include "assess/campaign/campaign_report.hpp"

#include "report/text_format.hpp"

#include "assess/report/html_report.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/messages.hpp"

#include <cctype>
#include <cstdio>
#include <limits>

#include "assess/campaign/campaign_runner.hpp"
#include "assess/support/error.hpp"
#include "assess/support/output_file.hpp"
#include "assess/support/units.hpp"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <tuple>

namespace assess {

namespace {

using nlohmann::json;

struct Stat {
  double n = 0, sum = 0, sum2 = 0;
  void add(double v) { n += 1, sum += v, sum2 += v * v; }
  double mean() const { return n > 0 ? sum / n : NAN; }
  double std() const { return n > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))) : 0.0; }
  json to_json() const {
    if (n == 0) return {{"mean", nullptr}, {"std", nullptr}};
    return {{"mean", mean()}, {"std", std()}};
  }
};

struct Group {
  long analyses = 0, failed = 0, overturned = 0, moved = 0;
  Stat dc, ratio, strength, displacement;
  void add(const AnalysisRow& r) {
    ++analyses;
    if (!r.ok) {
      ++failed;
      return;
    }
    overturned += r.overturned ? 1 : 0;
    moved += r.theta_max_rad > 0.0 ? 1 : 0;
    dc.add(r.dc_energy);
    ratio.add(r.theta_ratio);
    strength.add(r.dc_strength);
    displacement.add(r.dc_displacement);
  }
};

// A wall name made safe as part of a file name.
std::string file_stem(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  return s;
}

const char* kSmoothColour = "#1f77b4";
const char* kRigidColour = "#d62728";

}  // namespace

json summarise_campaign(const std::vector<AnalysisRow>& rows) {
  // std::map keeps the groups in a stable (sorted) order.
  std::map<std::tuple<std::string, std::string, std::string, std::string>, Group> groups;
  std::map<std::pair<std::string, double>, Group> by_scale;
  std::map<std::string, Group> by_model;
  long failed = 0;
  // Code ratios against the dynamic D/C (seed Fig. 5), per model and code
  // ratio c: among the analyses where not both c and the dynamic D/C exceed 1
  // (the seed neglects those), how often c is below the dynamic D/C
  // (unconservative); how often the verdicts (ratio > 1: not verified)
  // agree; and the Pearson correlation of c with the dynamic D/C.
  struct Cmp {
    long considered = 0, below = 0, agree = 0, n = 0;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    void add(double code, double dyn) {
      ++n, sx += code, sy += dyn, sxx += code * code, syy += dyn * dyn, sxy += code * dyn;
      agree += (code > 1.0) == (dyn > 1.0) ? 1 : 0;
      if (code > 1.0 && dyn > 1.0) return;
      ++considered;
      below += code < dyn ? 1 : 0;
    }
    json to_json() const {
      const double cov = sxy - sx * sy / double(n), vx = sxx - sx * sx / double(n), vy = syy - sy * sy / double(n);
      return {{"considered", considered},
              {"fraction_code_below_dynamic", considered ? double(below) / double(considered) : 0.0},
              {"fraction_same_verdict", n ? double(agree) / double(n) : 0.0},
              {"correlation", vx > 0 && vy > 0 ? json(cov / std::sqrt(vx * vy)) : json(nullptr)}};
    }
  };
  std::map<std::string, std::pair<Cmp, Cmp>> cmp;  // model -> (strength, displacement)
  // Strength against displacement ratio, where not both exceed 1.
  std::map<std::string, std::pair<long, long>> s_vs_d;  // model -> (considered, strength < displacement)
  for (const auto& r : rows) {
    groups[{r.wall, r.record, r.model, r.restitution}].add(r);
    by_scale[{r.model, r.scale}].add(r);
    by_model[r.model].add(r);
    if (!r.ok) {
      ++failed;
      continue;
    }
    cmp[r.model].first.add(r.dc_strength, r.dc_energy);
    cmp[r.model].second.add(r.dc_displacement, r.dc_energy);
    if (!(r.dc_strength > 1.0 && r.dc_displacement > 1.0)) {
      ++s_vs_d[r.model].first;
      s_vs_d[r.model].second += r.dc_strength < r.dc_displacement ? 1 : 0;
    }
  }
  json j;
  j["analyses"] = rows.size();
  j["failed"] = failed;
  j["groups"] = json::array();
  for (const auto& [k, g] : groups) {
    j["groups"].push_back({{"wall", std::get<0>(k)},
                           {"record", std::get<1>(k)},
                           {"model", std::get<2>(k)},
                           {"restitution", std::get<3>(k)},
                           {"analyses", g.analyses},
                           {"failed", g.failed},
                           {"overturned", g.overturned},
                           {"dc_energy", g.dc.to_json()},
                           {"theta_max_over_theta_u", g.ratio.to_json()},
                           {"dc_strength", g.strength.to_json()},
                           {"dc_displacement", g.displacement.to_json()}});
  }
  j["by_model_and_scale"] = json::array();
  for (const auto& [k, g] : by_scale) {
    const double ok = double(g.analyses - g.failed);
    j["by_model_and_scale"].push_back({{"model", k.first},
                                       {"scale", k.second},
                                       {"analyses", g.analyses},
                                       {"moved_fraction", ok > 0 ? g.moved / ok : 0.0},
                                       {"overturned_fraction", ok > 0 ? g.overturned / ok : 0.0},
                                       {"dc_energy", g.dc.to_json()}});
  }
  j["code_vs_dynamic"] = json::object();
  for (const auto& [m, c] : cmp)
    j["code_vs_dynamic"][m] = {
        {"strength", c.first.to_json()},
        {"displacement", c.second.to_json()},
        {"strength_below_displacement",
         {{"considered", s_vs_d[m].first},
          {"fraction", s_vs_d[m].first ? double(s_vs_d[m].second) / double(s_vs_d[m].first) : 0.0}}}};
  for (const auto& [m, g] : by_model)
    j["by_model"][m] = {{"analyses", g.analyses}, {"failed", g.failed}, {"overturned", g.overturned},
                        {"moved", g.moved}, {"dc_energy", g.dc.to_json()}};
  return j;
}

std::vector<std::pair<std::string, Plot>> campaign_plots(const Campaign& campaign, const std::vector<AnalysisRow>& rows) {
  const CampaignSpec& spec = campaign.spec();
  std::vector<std::pair<std::string, Plot>> plots;

  // Means over the realisations per (wall, record, scale, model).
  struct Cell {
    Stat pga, dc, strength, displacement;
  };
  std::map<std::tuple<std::string, std::string, double, std::string>, Cell> cells;
  for (const auto& r : rows) {
    if (!r.ok) continue;
    Cell& c = cells[{r.wall, r.record, r.scale, r.model}];
    c.pga.add(r.pga_m_s2 / units::g);
    c.dc.add(r.dc_energy);
    c.strength.add(r.dc_strength);
    c.displacement.add(r.dc_displacement);
  }
  auto colour = [](const std::string& model) { return model == "smooth" ? kSmoothColour : kRigidColour; };

  // Fig. 4a, one plot per wall.
  for (const auto& wall : spec.walls) {
    Plot p;
    p.title = "Dynamic D/C against PGA, wall " + wall.name + " (means over realisations, +/- 1 std)";
    p.x_label = "PGA (g)";
    p.y_label = "energy demand/capacity (-)";
    for (CampaignModel m : spec.models) {
      const std::string model = to_string(m);
      PlotSeries s;
      s.name = model;
      s.style = PlotSeries::Style::Points;
      s.color = colour(model);
      for (const auto& [k, c] : cells)
        if (std::get<0>(k) == wall.name && std::get<3>(k) == model) {
          s.x.push_back(c.pga.mean());
          s.y.push_back(c.dc.mean());
          s.y_err.push_back(c.dc.std());
        }
      if (!s.x.empty()) p.series.push_back(std::move(s));
    }
    if (!p.series.empty()) plots.emplace_back("fig4a_" + file_stem(wall.name) + ".svg", std::move(p));
  }

  // Fig. 4b: capacity (moment-rotation) curves.
  {
    Plot p;
    p.title = "Capacity curves of the walls (moment-rotation about the toe)";
    p.x_label = "theta (rad)";
    p.y_label = "restoring moment M (kN m/m)";
    const Sidedness side = spec.one_sided ? Sidedness::one_sided : Sidedness::two_sided;
    const char* palette[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02", "#a6761d", "#666666"};
    std::size_t w = 0;
    for (const auto& wall : spec.walls) {
      const char* wall_colour = palette[w++ % (sizeof palette / sizeof *palette)];
      const RockingBody body = RockingBody::rectangle(2 * wall.b_m, 2 * wall.h_m, wall.unit_weight_N_m3);
      for (CampaignModel m : {CampaignModel::smooth, CampaignModel::rigid}) {
        if (m == CampaignModel::smooth && !(wall.k_N_m3 > 0.0)) continue;
        const RockingModel model(body, m == CampaignModel::smooth ? Foundation::winkler(wall.k_N_m3) : Foundation::rigid(),
                                 side, Restitution::housner());
        PlotSeries s;
        s.name = wall.name + " " + to_string(m);
        s.style = m == CampaignModel::smooth ? PlotSeries::Style::Line : PlotSeries::Style::Dashed;
        s.color = wall_colour;
        const int n = 200;
        const double tu = model.theta_u(+1);
        // Smooth: from 0 (M = 0); rigid: from 0+ (M jumps to W b at uplift).
        for (int i = 0; i <= n; ++i) {
          const double th = tu * double(i) / n;
          s.x.push_back(th);
          s.y.push_back((i == 0 && m == CampaignModel::rigid ? 0.0 : model.restoring_moment(th)) / units::kN);
        }
        if (m == CampaignModel::rigid) {  // the vertical branch at theta = 0
          s.x.insert(s.x.begin() + 1, 0.0);
          s.y.insert(s.y.begin() + 1, model.restoring_moment(1e-12 * tu) / units::kN);
        }
        p.series.push_back(std::move(s));
      }
    }
    plots.emplace_back("fig4b_capacity.svg", std::move(p));
  }

  // Fig. 5a/5b: code ratios against the dynamic D/C.
  for (int which = 0; which < 2; ++which) {
    Plot p;
    p.title = which == 0 ? "Strength-based code D/C, PGA/(2 a0*), against dynamic D/C"
                         : "Displacement-based code D/C, SDe(Ts)/du*, against dynamic D/C";
    p.x_label = "dynamic energy D/C (-)";
    p.y_label = which == 0 ? "PGA/(2 a0*) (-)" : "SDe(Ts)/du* (-)";
    double top = 1.0;  // extent of the line of equality: the largest value plotted
    for (CampaignModel m : spec.models) {
      const std::string model = to_string(m);
      PlotSeries s;
      s.name = model;
      s.style = PlotSeries::Style::Points;
      s.color = colour(model);
      for (const auto& [k, c] : cells)
        if (std::get<3>(k) == model) {
          s.x.push_back(c.dc.mean());
          s.y.push_back(which == 0 ? c.strength.mean() : c.displacement.mean());
          top = std::max({top, s.x.back(), s.y.back()});
        }
      if (!s.x.empty()) p.series.push_back(std::move(s));
    }
    PlotSeries eq;
    eq.name = "code = dynamic";
    eq.style = PlotSeries::Style::Dashed;
    eq.x = {0.0, top};
    eq.y = {0.0, top};
    eq.color = "#555555";
    p.series.push_back(std::move(eq));
    plots.emplace_back(which == 0 ? "fig5a_strength.svg" : "fig5b_displacement.svg", std::move(p));
  }
  return plots;
}

namespace {

std::string fmt(const char* f, double v) {
  if (!std::isfinite(v)) return "—";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

double number_at(const json& j, const char* a, const char* b = nullptr) {
  const json* v = j.contains(a) ? &j.at(a) : nullptr;
  if (v && b) v = v->contains(b) ? &v->at(b) : nullptr;
  return v && v->is_number() ? v->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::string campaign_index_html(const json& s, const std::vector<std::pair<std::string, std::string>>& svgs) {
  const Lang L = Lang::en;  // campaigns are research output: English (messages.cpp "camp.*")
  HtmlReport h(msg(L, "camp.title") + " — " + s.value("campaign", std::string()));
  h.set_lang(to_string(L));
  h.add_paragraph(msgf(L, "camp.intro", s.value("analyses", 0ull), s.value("analyses_in_campaign", 0ull),
                       s.value("failed", 0ull)));
  // A cell: "num" right-aligns a figure.
  const auto C = [](std::string text, const std::string& cls = "") {
    Cell c(std::move(text));
    c.numeric = cls == "num";
    return c;
  };
  if (s.contains("by_model")) {
    std::vector<std::vector<Cell>> rows;
    for (const auto& [model, m] : s.at("by_model").items())
      rows.push_back({C(model), C(fmt("%.0f", number_at(m, "analyses")), "num"), C(fmt("%.0f", number_at(m, "failed")), "num"),
                      C(fmt("%.0f", number_at(m, "moved")), "num"), C(fmt("%.0f", number_at(m, "overturned")), "num"),
                      C(fmt("%.3f", number_at(m, "dc_energy", "mean")), "num"),
                      C(fmt("%.3f", number_at(m, "dc_energy", "std")), "num")});
    h.add_heading(msg(L, "camp.by_model"), 2, false);
    h.add_cell_table({msg(L, "camp.model"), C(msg(L, "dyn.analyses"), "num"), C(msg(L, "camp.failed"), "num"),
                      C(msg(L, "camp.moved"), "num"), C(msg(L, "dyn.overturned"), "num"), C("mean D/C", "num"),
                      C("std D/C", "num")},
                     rows, "");
  }
  if (s.contains("by_model_and_scale")) {
    std::vector<std::vector<Cell>> rows;
    for (const json& m : s.at("by_model_and_scale"))
      rows.push_back({C(m.value("model", std::string())), C(fmt("%.3f", number_at(m, "scale")), "num"),
                      C(fmt("%.0f", number_at(m, "analyses")), "num"),
                      C(fmt("%.3f", number_at(m, "moved_fraction")), "num"),
                      C(fmt("%.3f", number_at(m, "overturned_fraction")), "num"),
                      C(fmt("%.3f", number_at(m, "dc_energy", "mean")), "num"),
                      C(fmt("%.3f", number_at(m, "dc_energy", "std")), "num")});
    h.add_heading(msg(L, "camp.by_scale"), 2, false);
    h.add_cell_table({msg(L, "camp.model"), C(msg(L, "dyn.scale"), "num"), C(msg(L, "dyn.analyses"), "num"),
                      C(msg(L, "camp.moved_fraction"), "num"), C(msg(L, "camp.overturned_fraction"), "num"),
                      C("mean D/C", "num"), C("std D/C", "num")},
                     rows, "");
  }
  if (s.contains("code_vs_dynamic")) {
    std::vector<std::vector<Cell>> rows;
    for (const auto& [model, m] : s.at("code_vs_dynamic").items())
      for (const auto& [kind, k] : m.items())
        rows.push_back({C(model), C(kind), C(fmt("%.0f", number_at(k, "considered")), "num"),
                        C(fmt("%.3f", number_at(k, "correlation")), "num"),
                        C(fmt("%.3f", number_at(k, "fraction_same_verdict")), "num"),
                        C(fmt("%.3f", number_at(k, "fraction_code_below_dynamic")), "num")});
    h.add_heading(msg(L, "camp.code_vs_dynamic"), 2, false);
    h.add_cell_table({msg(L, "camp.model"), msg(L, "camp.code_check"), C(msg(L, "camp.considered"), "num"),
                      C(msg(L, "camp.correlation"), "num"), C(msg(L, "camp.same_verdict"), "num"),
                      C(msg(L, "camp.code_below"), "num")},
                     rows, "");
  }
  if (!svgs.empty()) h.add_heading(msg(L, "camp.figures"));
  for (std::size_t i = 0; i < svgs.size(); ++i) {
    std::string id = "fig-" + svgs[i].first.substr(0, svgs[i].first.rfind('.'));
    for (char& c : id)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    h.add_svg(svgs[i].second, svgs[i].first, id);
  }
  h.add_paragraph(msg(L, "camp.files"));
  return h.str();
}

CampaignReportFiles write_campaign_report(const Campaign& campaign, const std::string& out_dir, bool plots) {
  const std::vector<AnalysisRow> rows = read_campaign_csv(out_dir + "/results.csv");
  CampaignReportFiles files;
  json summary = summarise_campaign(rows);
  summary["campaign"] = campaign.spec().name;
  summary["analyses_in_campaign"] = campaign.size();
  files.summary = out_dir + "/summary.json";
  write_output_file(files.summary, summary.dump(2) + "\n", "the campaign summary", out_dir);
  std::vector<std::pair<std::string, std::string>> svgs;  // file name, SVG
  if (plots)
    for (const auto& [name, plot] : campaign_plots(campaign, rows)) {
      const std::string path = out_dir + "/" + name;
      std::string svg = render_svg(plot);
      write_output_file(path, svg, "a campaign plot", out_dir);
      files.plots.push_back(path);
      svgs.emplace_back(name, std::move(svg));
    }
  files.index = out_dir + "/index.html";
  write_output_file(files.index, campaign_index_html(summary, svgs), "the campaign page", out_dir);
  return files;
}

}  // namespace assess

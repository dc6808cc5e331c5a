// bench_plot: time and size of render_svg() for the kinds of figure of the
// relazione (issues 28 and 32: the figures used to cost one gnuplot process
// each). Each figure is rendered N times; the best and mean times per figure
// are printed with the SVG's size. Usage: bench_plot [N=200]
#include <assess/report/plot.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

using namespace assess;
using St = PlotSeries::Style;

namespace {

/// A smooth spectrum-like curve over T in [0, 4] s (n points), peak at Tp.
PlotSeries spectrum(const std::string& name, int n, double peak, double Tp, St style, const std::string& colour) {
  PlotSeries s;
  s.name = name, s.style = style, s.color = colour;
  for (int i = 0; i < n; ++i) {
    const double T = 4.0 * i / (n - 1);
    s.x.push_back(T);
    s.y.push_back(peak * (T < Tp ? 0.4 + 0.6 * T / Tp : Tp / T) * (1.0 + 0.15 * std::sin(37.0 * T + peak)));
  }
  return s;
}

std::vector<std::pair<std::string, Plot>> figures() {
  std::vector<std::pair<std::string, Plot>> out;
  {  // site spectra: 4 limit states, 7 records, their mean (100 periods)
    Plot p;
    p.title = "Spettri di risposta elastici (5 %)", p.x_label = "T (s)", p.y_label = "Se, PSA (g)";
    const char* ls[] = {"Se SLO", "Se SLD", "Se SLV", "Se SLC"};
    for (int k = 0; k < 4; ++k) p.series.push_back(spectrum(ls[k], 100, 0.2 + 0.2 * k, 0.45, St::Line, ""));
    for (int r = 0; r < 7; ++r) p.series.push_back(spectrum(r ? "" : "accelerogrammi (scalati)", 100, 0.5 + 0.2 * r, 0.2 + 0.05 * r, St::Dashed, "#999999"));
    p.series.push_back(spectrum("media degli accelerogrammi", 100, 0.8, 0.3, St::Line, "#000000"));
    p.series.back().highlight = true;
    out.emplace_back("spectra (12 lines x 100 points)", p);
  }
  {  // ADRS: capacity line, 4 demand spectra, secants, check points, legend below
    Plot p;
    p.title = "Curva di capacità e spettri di domanda (ADRS)", p.x_label = "spostamento spettrale d*, Sd (m)";
    p.y_label = "accelerazione spettrale a*, Sa (m/s²)";
    PlotSeries cap{"curva di capacità a*–d*", {0.0, 0.433}, {0.432, 0.0}, St::Line, {}, true, "#000000"};
    p.series.push_back(cap);
    for (int k = 0; k < 4; ++k) {
      PlotSeries s;
      s.name = "domanda " + std::to_string(k), s.style = k % 2 ? St::Dashed : St::Line;
      for (int i = 1; i <= 200; ++i) {
        const double T = 0.02 * i;
        s.x.push_back(0.1 * T * T), s.y.push_back(2.0 / (0.3 + T) + 0.05 * k);
      }
      p.series.push_back(s);
      p.series.push_back({"", {0.0, 0.3}, {0.0, 1.0 + 0.1 * k}, St::Dashed, {}, false, "#888888"});
      PlotSeries d{"domanda " + std::to_string(k), {0.17 + 0.02 * k}, {0.36}, St::Points, {}, false, ""};
      d.point_size = 1.3;
      p.series.push_back(d);
      PlotSeries q{"capacità " + std::to_string(k), {0.17 + 0.03 * k}, {0.26}, St::Points, {}, false, ""};
      q.point_type = 5, q.point_size = 1.1;
      p.series.push_back(q);
    }
    p.x_min = 0, p.x_max = 0.45, p.y_min = 0, p.y_max = 1.33, p.key = "below", p.height = 572;
    out.emplace_back("ADRS (17 series, legend below)", p);
  }
  {  // one panel of the theta/theta_u histories: 3 runs of 600 samples, 300 x 190
    Plot p;
    p.x_label = "t (s)", p.y_label = "θ/θu", p.width = 300, p.height = 190, p.font_size = 8, p.key = "off";
    for (int r = 0; r < 3; ++r) {
      PlotSeries s;
      for (int i = 0; i < 600; ++i) {
        const double t = 30.0 * i / 600;
        s.x.push_back(t), s.y.push_back(0.8 * std::sin(3.0 * t + r) * std::exp(-0.05 * t) * std::sin(0.3 * t));
      }
      p.series.push_back(s);
    }
    p.series.push_back({"", {0.0, 30.0}, {1.0, 1.0}, St::Dashed, {}, false, "#b3001b"});
    p.x_min = 0, p.x_max = 30, p.y_min = -1.1, p.y_max = 1.1;
    out.emplace_back("history panel (3 x 600 points)", p);
  }
  {  // D/C bars with rotated category labels, legend outside
    Plot p;
    p.title = "D/C per approccio", p.y_label = "D/C (-)", p.rotate_x_tic_labels = true, p.width = 720, p.height = 480;
    p.key = "outside right top";
    for (int g = 0; g < 3; ++g) {
      PlotSeries b;
      b.name = "gruppo " + std::to_string(g), b.style = St::Bars;
      for (int i = 0; i < 3; ++i) {
        const double x = 3.6 * g + i;
        b.x.push_back(x), b.y.push_back(0.5 + 0.4 * i + 0.3 * g);
        p.x_tic_labels.push_back({x, "din. SLV e=-0." + std::to_string(4 + i)});
      }
      p.series.push_back(b);
    }
    p.series.push_back({"D/C = 1", {-0.6, 10.0}, {1.0, 1.0}, St::Dashed, {}, true, "#b3001b"});
    p.x_min = -0.6, p.x_max = 10.0, p.y_min = 0, p.y_max = 2.5;
    out.emplace_back("D/C bars (9 categories)", p);
  }
  {  // hazard curve, log-log
    Plot p;
    p.title = "Hazard curve", p.x_label = "PGA (g)", p.y_label = "lambda (1/year)", p.log_x = p.log_y = true;
    PlotSeries line{"log-log", {}, {}, St::Line, {}, false, ""}, pts{"grid", {}, {}, St::Points, {}, false, ""};
    for (int i = 0; i <= 60; ++i) {
      const double x = 0.05 * std::pow(16.0, i / 60.0);
      line.x.push_back(x), line.y.push_back(1e-3 * std::pow(x / 0.3, -2.5));
      if (i % 7 == 0) pts.x.push_back(x), pts.y.push_back(line.y.back());
    }
    p.series = {line, pts};
    out.emplace_back("hazard (log-log)", p);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200;
  std::size_t bytes_total = 0;
  double mean_total = 0.0;
  for (const auto& [name, plot] : figures()) {
    double best = 1e300, sum = 0.0;
    std::size_t bytes = 0;
    for (int i = 0; i < n; ++i) {
      const auto t0 = clock::now();
      const std::string svg = render_svg(plot);
      const double us = std::chrono::duration<double, std::micro>(clock::now() - t0).count();
      best = std::min(best, us), sum += us, bytes = svg.size();
    }
    std::printf("%-36s best %8.1f us  mean %8.1f us  %6zu bytes\n", name.c_str(), best, sum / n, bytes);
    bytes_total += bytes, mean_total += sum / n;
  }
  std::printf("mean per figure over these kinds: %.1f us, %.0f bytes (%d renders each)\n", mean_total / 5.0,
              double(bytes_total) / 5.0, n);
  return 0;
}

// The native SVG plots (report/plot.hpp, plot_layout.hpp): nice tick values
// for known ranges (closed forms), data mapped to the right SVG coordinate on
// linear and log axes, clipping to the plot area, thinning of dense lines,
// gaps at non-finite values, escaping of hostile text, legend placement,
// determinism and validate() errors.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/report/plot.hpp"
#include "assess/report/plot_layout.hpp"
#include "assess/support/error.hpp"

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <utility>
#include <vector>

namespace {

using assess::AxisTick;
using assess::Plot;
using assess::PlotAxis;
using assess::PlotSeries;
using St = PlotSeries::Style;
using assess::test::abs_tol;

// SVG coordinates are written with two decimals: a written coordinate is
// within 0.005 unit of the exact one; 0.01 unit (px at 100 %) leaves room
// for one more rounding (a relative path step between rounded points).
const auto kPx = abs_tol(0.01);

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> labelled_values(const PlotAxis& a) {
  std::vector<double> v;
  for (const AxisTick& t : a.ticks)
    if (!t.label.empty()) v.push_back(t.value);
  return v;
}

std::vector<std::string> labels(const PlotAxis& a) {
  std::vector<std::string> v;
  for (const AxisTick& t : a.ticks)
    if (!t.label.empty()) v.push_back(t.label);
  return v;
}

std::size_t minor_count(const PlotAxis& a) {
  std::size_t n = 0;
  for (const AxisTick& t : a.ticks) n += t.label.empty() ? 1 : 0;
  return n;
}

/// The "d" of the first <path> with this attribute text (e.g. stroke="#123456").
std::string path_d(const std::string& svg, const std::string& attr) {
  const std::regex re("<path[^>]*" + attr + "[^>]* d=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(svg, m, re) ? m[1].str() : std::string();
}

using Pt = std::pair<double, double>;

/// Polylines of a path made of "M x y" and relative "l dx dy ..." commands.
std::vector<std::vector<Pt>> polylines(const std::string& d) {
  std::vector<std::vector<Pt>> out;
  const std::regex num(R"re(-?[0-9]+(\.[0-9]+)?)re");
  std::size_t i = 0;
  char cmd = 0;
  double x = 0, y = 0;
  std::vector<double> vals;
  const auto flush = [&]() {
    if (cmd == 'M' && vals.size() >= 2) {
      x = vals[0], y = vals[1];
      out.push_back({{x, y}});
    } else if (cmd == 'l') {
      for (std::size_t k = 0; k + 1 < vals.size(); k += 2) {
        x += vals[k], y += vals[k + 1];
        out.back().push_back({x, y});
      }
    }
    vals.clear();
  };
  while (i < d.size()) {
    const char c = d[i];
    if (c == 'M' || c == 'l') {
      flush();
      cmd = c;
      ++i;
    } else if (c == ' ') {
      ++i;
    } else {
      std::smatch m;
      const std::string rest = d.substr(i);
      REQUIRE(std::regex_search(rest, m, num, std::regex_constants::match_continuous));
      vals.push_back(std::stod(m[0].str()));
      i += m[0].length();
    }
  }
  flush();
  return out;
}

/// Centres of the plus markers (point type 1) of a path: "M x-r y h2r M x y-r v2r".
std::vector<Pt> plus_centres(const std::string& d) {
  std::vector<Pt> out;
  const std::regex re(R"re(M(-?[0-9.]+) (-?[0-9.]+)h[0-9.]+M(-?[0-9.]+) (-?[0-9.]+)v)re");
  for (auto it = std::sregex_iterator(d.begin(), d.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[3].str()), std::stod((*it)[2].str())});
  return out;
}

Plot sample_plot() {
  Plot p;
  p.title = "Spectra";
  p.x_label = "T (s)";
  p.y_label = "Se (m/s²)";
  p.log_x = true;
  p.series.push_back({"target", {0.1, 0.5, 1.0, 2.0}, {5.0, 7.0, 3.0, 1.5}, St::Line, {}, true, "#000000"});
  p.series.push_back({"band", {0.1, 2.0}, {4.5, 1.35}, St::Dashed, {}, false, ""});
  p.series.push_back({"rec_1", {0.1, 0.5, 1.0}, {4.0, 8.0, 2.5}, St::Points, {0.2, 0.3, 0.1}, false, ""});
  p.series.push_back({"bars", {0.3, 0.6}, {2.0, 3.0}, St::Bars, {}, false, "#3366cc"});
  return p;
}

}  // namespace

TEST_CASE("linear ticks: the smallest 1-2-5 step at least g font sizes apart, exact values and labels") {
  // Closed form: step = min{m 10^k, m in {1, 2, 5}} with step >= range g fs / length
  // (g = 3 on a y axis, 4.5 on an x axis when the labels are narrower than that).
  // x, [0, 4] over 550 px, fs 11: 4 x 49.5 / 550 = 0.36 -> step 0.5.
  const PlotAxis x = assess::make_plot_axis(0.0, 4.0, true, false, 0.0, 550.0, 11, false);
  CHECK(labelled_values(x) == std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0});
  CHECK(labels(x) == std::vector<std::string>{"0", "0.5", "1.0", "1.5", "2.0", "2.5", "3.0", "3.5", "4.0"});
  // y, [-1.1, 1.1] over 140 px, fs 8: 2.2 x 24 / 140 = 0.377 -> 0.5; negative labels with U+2212.
  const PlotAxis y = assess::make_plot_axis(-1.1, 1.1, true, false, 150.0, 10.0, 8, true);
  CHECK(labelled_values(y) == std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0});
  CHECK(labels(y) == std::vector<std::string>{"−1.0", "−0.5", "0", "0.5", "1.0"});
  CHECK(y.lo == -1.1);
  CHECK(y.hi == 1.1);
  // y, [0, 0.3] over 300 px, fs 10: 0.3 x 30 / 300 = 0.03 -> 0.05; values exactly the decimals.
  const PlotAxis z = assess::make_plot_axis(0.0, 0.3, true, false, 300.0, 0.0, 10, true);
  CHECK(labelled_values(z) == std::vector<double>{0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3});
  CHECK(labels(z) == std::vector<std::string>{"0", "0.05", "0.10", "0.15", "0.20", "0.25", "0.30"});
}

TEST_CASE("autoscaled linear axes widen to the ticks around the data") {
  // Data [0.03, 2.1] on a 330 px y axis, fs 11: 2.07 x 33 / 330 = 0.207 -> step 0.5, range [0, 2.5].
  const PlotAxis y = assess::make_plot_axis(0.03, 2.1, false, false, 330.0, 0.0, 11, true);
  CHECK(y.lo == 0.0);
  CHECK(y.hi == 2.5);
  CHECK(labelled_values(y) == std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0, 2.5});
  // Data [-0.3, 5.7]: step 1 -> [-1, 6].
  const PlotAxis w = assess::make_plot_axis(-0.3, 5.7, false, false, 330.0, 0.0, 11, true);
  CHECK(w.lo == -1.0);
  CHECK(w.hi == 6.0);
  // A constant (degenerate extent) is widened by 10 % either side: [0.9, 1.1].
  const PlotAxis c = assess::make_plot_axis(1.0, 1.0, false, false, 330.0, 0.0, 11, true);
  CHECK_CLOSE(c.lo, 0.9, abs_tol(1e-12));
  CHECK_CLOSE(c.hi, 1.1, abs_tol(1e-12));
  // Large values: scientific labels from the exact integers.
  const PlotAxis big = assess::make_plot_axis(0.0, 5e7, true, false, 0.0, 550.0, 11, false);
  const auto bl = labels(big);
  REQUIRE(bl.size() >= 3);
  CHECK(bl[0] == "0");
  CHECK(bl[1] == "5×10⁶");
  CHECK(bl[2] == "10⁷");
}

TEST_CASE("log ticks: decades (10^k labels below 1e-4), 1-2-5 within two decades, minor ticks 2..9") {
  // Data [1.1e-5, 0.15] widen to whole decades [1e-5, 1]; 5 decades over 330 px: every decade labelled.
  const PlotAxis y = assess::make_plot_axis(1.1e-5, 0.15, false, true, 330.0, 0.0, 11, true);
  CHECK(y.lo == 1e-5);
  CHECK(y.hi == 1.0);
  CHECK(labelled_values(y) == std::vector<double>{1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0});
  CHECK(labels(y) == std::vector<std::string>{"10⁻⁵", "10⁻⁴", "10⁻³", "10⁻²", "10⁻¹", "10⁰"});
  CHECK(minor_count(y) == 5 * 8);  // 2..9 in each of the 5 decades (66 px each)
  // Two decades over 550 px: 1, 2 and 5 of each decade labelled, 3, 4, 6..9 minor.
  const PlotAxis x = assess::make_plot_axis(0.01, 1.0, true, true, 0.0, 550.0, 11, false);
  CHECK(labels(x) == std::vector<std::string>{"0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1"});
  CHECK(minor_count(x) == 2 * 6);
  // 40 decades on 200 px: labels every n-th decade, still apart.
  const PlotAxis wide = assess::make_plot_axis(1e-20, 1e20, true, true, 200.0, 0.0, 11, true);
  const auto v = labelled_values(wide);
  REQUIRE(v.size() >= 2);
  for (std::size_t i = 1; i < v.size(); ++i) CHECK(std::fabs(wide.to_px(v[i]) - wide.to_px(v[i - 1])) >= 33.0);
}

TEST_CASE("labelled ticks never crowd: a sweep of ranges and lengths") {
  // On x, centres at least 4.5 font sizes apart; on y, 3 font sizes.
  for (int i = 0; i < 200; ++i) {
    const double lo = std::pow(10.0, (i % 13) - 6) * ((i % 3) - 1), span = std::pow(10.0, (i % 11) - 4) * (1 + i % 7);
    const double length = 80.0 + 37.0 * (i % 17), fs = 6 + i % 15;
    for (bool vertical : {false, true}) {
      const PlotAxis a = assess::make_plot_axis(lo, lo + span, i % 2 == 0, false, 0.0, length, fs, vertical);
      const auto v = labelled_values(a);
      CHECK(!v.empty());
      for (std::size_t k = 1; k < v.size(); ++k) {
        INFO("range " << a.lo << ".." << a.hi << " length " << length << " fs " << fs);
        CHECK(std::fabs(a.to_px(v[k]) - a.to_px(v[k - 1])) >= (vertical ? 3.0 : 4.5) * fs - 1e-9);
      }
    }
  }
}

TEST_CASE("a data point is drawn at the pixel of the closed-form mapping, linear and log axes") {
  for (bool log : {false, true}) {
    Plot p;
    p.title = log ? "log" : "linear";
    p.log_x = p.log_y = log;
    p.x_min = log ? 0.01 : -2.0, p.x_max = log ? 100.0 : 8.0;
    p.y_min = log ? 1e-3 : 0.0, p.y_max = log ? 10.0 : 1.0;
    const double px = log ? 0.3 : 3.7, py = log ? 0.02 : 0.42;
    PlotSeries s{"", {px}, {py}, St::Points, {}, false, "#123456"};
    s.point_type = 1;
    p.series.push_back(s);
    const assess::PlotLayout L = assess::plot_layout(p);
    const auto f = [&](double v, double lo, double hi) { return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo); };
    const double ex = L.left + f(px, p.x_min, p.x_max) * (L.right - L.left);
    const double ey = L.bottom - f(py, p.y_min, p.y_max) * (L.bottom - L.top);
    CHECK_CLOSE(L.x.to_px(px), ex, abs_tol(1e-9));
    CHECK_CLOSE(L.y.to_px(py), ey, abs_tol(1e-9));
    const std::string svg = assess::render_svg(p);
    const auto c = plus_centres(path_d(svg, "stroke=\"#123456\""));
    REQUIRE(c.size() == 1);
    CHECK_CLOSE(c[0].first, ex, kPx);
    CHECK_CLOSE(c[0].second, ey, kPx);
    // The frame is the plot area of the layout.
    const std::regex frame(R"re(<rect x="([0-9.]+)" y="([0-9.]+)" width="([0-9.]+)" height="([0-9.]+)" fill="none" stroke="#000"/>)re");
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, frame));
    CHECK_CLOSE(std::stod(m[1].str()), L.left, kPx);
    CHECK_CLOSE(std::stod(m[2].str()), L.top, kPx);
    CHECK_CLOSE(std::stod(m[1].str()) + std::stod(m[3].str()), L.right, kPx);
    CHECK_CLOSE(std::stod(m[2].str()) + std::stod(m[4].str()), L.bottom, kPx);
  }
}

TEST_CASE("lines are clipped to the plot area, bars cut at the frame, markers outside dropped") {
  Plot p;
  p.title = "clip";
  p.x_min = 0.0, p.x_max = 10.0, p.y_min = 0.0, p.y_max = 5.0;
  p.series.push_back({"y = 2x", {-5.0, 0.0, 10.0, 20.0}, {-10.0, 0.0, 20.0, 40.0}, St::Line, {}, false, "#aa0000"});
  p.series.push_back({"bar", {8.0}, {100.0}, St::Bars, {}, false, "#00aa00"});
  PlotSeries pts{"pts", {1.0, 50.0, 2.0}, {1.0, 1.0, -7.0}, St::Points, {}, false, "#0000aa"};
  pts.point_type = 1;
  p.series.push_back(pts);
  p.key = "off";
  const assess::PlotLayout L = assess::plot_layout(p);
  const std::string svg = assess::render_svg(p);
  const auto lines = polylines(path_d(svg, "stroke=\"#aa0000\""));
  REQUIRE(lines.size() == 1);
  for (const Pt& q : lines[0]) {
    CHECK(q.first >= L.left - 0.01);
    CHECK(q.first <= L.right + 0.01);
    CHECK(q.second >= L.top - 0.01);
    CHECK(q.second <= L.bottom + 0.01);
  }
  // It enters at the origin and leaves through the top at x = 2.5 (y = 5).
  CHECK_CLOSE(lines[0].front().first, L.x.to_px(0.0), kPx);
  CHECK_CLOSE(lines[0].front().second, L.y.to_px(0.0), kPx);
  CHECK_CLOSE(lines[0].back().first, L.x.to_px(2.5), kPx);
  CHECK_CLOSE(lines[0].back().second, L.top, kPx);
  // The bar reaches the top of the frame, not beyond.
  const std::regex bar(R"re(<rect x="[0-9.]+" y="([0-9.]+)" width="[0-9.]+" height="([0-9.]+)"/>)re");
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, bar));
  CHECK_CLOSE(std::stod(m[1].str()), L.top, kPx);
  CHECK_CLOSE(std::stod(m[1].str()) + std::stod(m[2].str()), L.bottom, kPx);
  // One marker of three is inside.
  CHECK(plus_centres(path_d(svg, "stroke=\"#0000aa\"")).size() == 1);
}

TEST_CASE("dense lines are thinned, within 0.2 unit of every data point") {
  Plot p;
  p.title = "dense";
  p.key = "off";
  PlotSeries s{"", {}, {}, St::Line, {}, false, "#123456"};
  const int n = 20000;
  for (int i = 0; i < n; ++i) s.x.push_back(40.0 * i / n), s.y.push_back(std::sin(40.0 * i / n));
  p.series.push_back(s);
  const assess::PlotLayout L = assess::plot_layout(p);
  const std::string svg = assess::render_svg(p);
  const auto lines = polylines(path_d(svg, "stroke=\"#123456\""));
  REQUIRE(lines.size() == 1);
  const auto& pl = lines[0];
  CHECK(pl.size() < 600);  // 20 000 points: a few hundred remain
  CHECK(svg.size() < 12000);
  // Every 10th data point lies within 0.2 (+ rounding) of the drawn polyline.
  for (int i = 0; i < n; i += 10) {
    const double x = L.x.to_px(s.x[i]), y = L.y.to_px(s.y[i]);
    double best = 1e9;
    for (std::size_t k = 1; k < pl.size(); ++k) {
      const double dx = pl[k].first - pl[k - 1].first, dy = pl[k].second - pl[k - 1].second;
      const double l2 = dx * dx + dy * dy;
      double t = l2 > 0 ? ((x - pl[k - 1].first) * dx + (y - pl[k - 1].second) * dy) / l2 : 0.0;
      t = std::max(0.0, std::min(1.0, t));
      best = std::min(best, std::hypot(x - pl[k - 1].first - t * dx, y - pl[k - 1].second - t * dy));
    }
    CHECK(best <= 0.2 + 0.02);
  }
}

TEST_CASE("non-finite values are gaps; a series without a finite point still renders") {
  Plot p;
  p.title = "gaps";
  p.series.push_back({"a", {0, 1, 2, 3, 4, 5}, {1, 2, kNaN, 3, kInf, 2}, St::Line, {}, false, "#123456"});
  p.series.push_back({"b", {0, kNaN, 2}, {1, 1, 1}, St::Points, {kNaN, 0.1, 0.1}, false, "#654321"});
  const std::string svg = assess::render_svg(p);
  const auto lines = polylines(path_d(svg, "stroke=\"#123456\""));
  REQUIRE(lines.size() == 1);  // [0,1], then [3] alone and [5] alone draw nothing
  CHECK(lines[0].size() == 2);
  for (const char* bad : {"nan", "inf", "NaN", "Inf"}) CHECK(svg.find(bad) == std::string::npos);
  Plot q;
  q.title = "empty";
  q.series.push_back({"nothing", {kNaN, 1.0}, {0.0, kInf}, St::Line, {}, false, ""});
  const std::string e = assess::render_svg(q);
  CHECK(e.find("</svg>") != std::string::npos);
  CHECK(e.find("nan") == std::string::npos);
}

TEST_CASE("hostile text is printed literally and the SVG stays well-formed") {
  Plot p = sample_plot();
  p.title = "a <script>alert('x')</script> & \"q\"";
  p.x_label = "ctl\x01\x1b[31m end";
  p.y_label = "bad utf8 \xff\xfe and θ α ²";
  p.series[2].name = "rec_1 @x `echo hi` url(#a)";
  p.x_tic_labels = {{0.3, "<b>"}, {0.6, "\xc3\x28"}};
  const std::string svg = assess::render_svg(p);
  CHECK(svg.find("<script") == std::string::npos);
  CHECK(svg.find("<b>") == std::string::npos);
  CHECK(svg.find("a &lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;q&quot;") != std::string::npos);
  CHECK(svg.find("<title>a &lt;script&gt;") != std::string::npos);
  CHECK(svg.find("rec_1 @x `echo hi` url(#a)") != std::string::npos);
  CHECK(svg.find("θ α ²") != std::string::npos);
  CHECK(svg.find("\xef\xbf\xbd") != std::string::npos);  // U+FFFD for the invalid bytes
  // No control characters but line breaks, and valid UTF-8 throughout.
  for (char c : svg) CHECK((static_cast<unsigned char>(c) >= 0x20 || c == '\n'));
  for (std::size_t i = 0; i < svg.size();) {
    const unsigned char c = static_cast<unsigned char>(svg[i]);
    const std::size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    REQUIRE(len > 0);
    for (std::size_t k = 1; k < len; ++k) REQUIRE((static_cast<unsigned char>(svg[i + k]) >> 6) == 2);
    i += len;
  }
}

TEST_CASE("the legend: below the plot when asked, moved off the data when inside, none when off") {
  Plot p;
  p.title = "key";
  p.x_min = 0, p.x_max = 1, p.y_min = 0, p.y_max = 1;
  // A line along the top edge: the top corners are taken.
  p.series.push_back({"top line", {0.0, 1.0}, {0.95, 0.95}, St::Line, {}, false, "#123456"});
  const assess::PlotLayout inside = assess::plot_layout(p);
  CHECK(inside.height == p.height);  // a bottom corner is free
  const std::regex text_y(R"re(<text x="[0-9.]+" y="([0-9.]+)">top line</text>)re");
  std::smatch m;
  std::string svg = assess::render_svg(p);
  REQUIRE(std::regex_search(svg, m, text_y));
  CHECK(std::stod(m[1].str()) > 0.5 * (inside.top + inside.bottom));  // in the lower half
  // Lines across all four corners: the legend goes below and the figure grows.
  p.series.push_back({"bottom line", {0.0, 1.0}, {0.05, 0.05}, St::Line, {}, false, "#654321"});
  const assess::PlotLayout moved = assess::plot_layout(p);
  CHECK(moved.height > p.height);
  CHECK_CLOSE(moved.bottom - moved.top, inside.bottom - inside.top, kPx);
  svg = assess::render_svg(p);
  REQUIRE(std::regex_search(svg, m, text_y));
  CHECK(std::stod(m[1].str()) > moved.bottom);
  // "below": under the plot area.
  p.key = "below";
  const assess::PlotLayout below = assess::plot_layout(p);
  CHECK(below.height == p.height);
  svg = assess::render_svg(p);
  REQUIRE(std::regex_search(svg, m, text_y));
  CHECK(std::stod(m[1].str()) > below.bottom);
  // "outside right top": right of the plot area.
  p.key = "outside right top";
  const assess::PlotLayout right = assess::plot_layout(p);
  svg = assess::render_svg(p);
  const std::regex text_x(R"re(<text x="([0-9.]+)" y="[0-9.]+">top line</text>)re");
  REQUIRE(std::regex_search(svg, m, text_x));
  CHECK(std::stod(m[1].str()) > right.right);
  p.key = "off";
  CHECK(assess::render_svg(p).find(">top line<") == std::string::npos);
}

TEST_CASE("rotated category labels are all printed when they fit; the SVG has no ids and is deterministic") {
  Plot p;
  p.title = "D/C";
  p.y_label = "D/C (-)";
  p.rotate_x_tic_labels = true;
  p.width = 720;
  p.key = "outside right top";
  PlotSeries bars{"NTC 2018", {}, {}, St::Bars, {}, false, "#1f5fbf"};
  for (int i = 0; i < 8; ++i) {
    bars.x.push_back(i), bars.y.push_back(0.3 + 0.2 * i);
    p.x_tic_labels.push_back({double(i), i == 4 ? "din. SLV (quota) moti di piano (filtro del primo modo)" : "lin. SLV " + std::to_string(i)});
  }
  p.series.push_back(bars);
  const std::string svg = assess::render_svg(p);
  for (int i = 0; i < 8; ++i)
    if (i != 4) CHECK(svg.find(">lin. SLV " + std::to_string(i) + "<") != std::string::npos);
  CHECK(svg.find("moti di") != std::string::npos);
  CHECK(svg.find("rotate(-30") != std::string::npos);
  CHECK(svg.find(" id=") == std::string::npos);
  CHECK(svg == assess::render_svg(p));
  CHECK(svg.find("viewBox=\"0 0 720 ") != std::string::npos);
}

TEST_CASE("invalid plots throw InputError") {
  using assess::InputError;
  auto bad = [](auto change) {
    Plot p = sample_plot();
    change(p);
    CHECK_THROWS_AS(assess::render_svg(p), InputError);
    CHECK_THROWS_AS(p.validate(), InputError);
  };
  bad([](Plot& p) { p.series[0].y.pop_back(); });
  bad([](Plot& p) { p.series[1].color = "red; x"; });
  bad([](Plot& p) { p.series.clear(); });
  bad([](Plot& p) { p.width = 50; });
  bad([](Plot& p) { p.font_size = 30; });
  bad([](Plot& p) { p.key = "top rigth"; });
  bad([](Plot& p) { p.key = "off top"; });
  bad([](Plot& p) { p.x_min = 0.0, p.x_max = 2.0; });  // log x from 0
  bad([](Plot& p) { p.y_max = kNaN; });
  bad([](Plot& p) { p.series[2].point_type = 16; });
  bad([](Plot& p) { p.series[2].point_size = 0.0; });
  bad([](Plot& p) { p.series[2].y_err.pop_back(); });
  bad([](Plot& p) { p.series[1].style = St::Band; });  // no y_low
  bad([](Plot& p) { p.bar_width = kInf; });
  bad([](Plot& p) { p.series[0].x = {-1.0, -2.0, -3.0, -4.0}; });  // no positive x on the log axis
  std::string msg;
  try {
    Plot p = sample_plot();
    p.key = "top rigth";
    p.validate();
  } catch (const InputError& e) {
    msg = e.what();
  }
  CHECK(msg.find("'rigth' is not a position word") != std::string::npos);
}

TEST_CASE("hostile sizes: long text is wrapped, cut and capped; the plot area keeps 30 % of the figure") {
  Plot p;
  p.title = std::string(500, 'W');
  p.y_label = std::string(300, 'y');
  p.width = 200, p.height = 150;
  p.series.push_back({std::string(400, 'n'), {0.0, 1.0}, {0.0, 1.0}, St::Line, {}, false, ""});
  const assess::PlotLayout L = assess::plot_layout(p);
  CHECK(L.right - L.left >= 0.3 * L.width - 1e-9);
  CHECK(L.bottom - L.top >= 0.3 * L.height - 1e-9);
  const std::string svg = assess::render_svg(p);
  std::size_t title_lines = 0;
  for (auto pos = svg.find("font-size=\"12.1\">W"); pos != std::string::npos; pos = svg.find("font-size=\"12.1\">W", pos + 1)) ++title_lines;
  CHECK(title_lines == 3);
  CHECK(svg.find("W…</text>") != std::string::npos);
  CHECK(svg.find("y…</text>") != std::string::npos);
}

TEST_CASE("random plots (extreme values, all styles, keys and markers) render well-formed, without nan") {
  // A deterministic sweep in the spirit of a fuzzer: it must never throw for
  // a valid plot, never print nan/inf, and always close the document.
  unsigned long long state = 12345;
  const auto next = [&]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / 9007199254740992.0;  // [0, 1)
  };
  const auto pick = [&](int n) { return int(next() * n); };
  const double special[] = {0.0, -0.0, 1e300, -1e300, 1e-300, 4.9e-324, kNaN, kInf, -kInf, 1e15, -1e-15};
  const auto value = [&]() {
    const int k = pick(8);
    if (k == 0) return special[pick(11)];
    return (2.0 * next() - 1.0) * (k < 4 ? 1.0 : std::pow(10.0, pick(25) - 12));
  };
  const char* keys[] = {"top right", "below", "outside right top", "off", "top left", "bottom center", "above", "outside left"};
  for (int it = 0; it < 300; ++it) {
    Plot p;
    p.title = "random " + std::to_string(it);
    p.x_label = "x", p.y_label = "y";
    p.log_x = pick(4) == 0, p.log_y = pick(4) == 0;
    p.width = 100 + pick(900), p.height = 100 + pick(700), p.font_size = 6 + pick(15);
    p.key = keys[pick(8)];
    if (pick(3) == 0) p.x_min = p.log_x ? 1e-3 : -std::fabs(value()), p.x_max = std::fabs(value()) + 1.0;
    if (pick(3) == 0) p.y_min = p.log_y ? 1e-3 : -std::fabs(value()), p.y_max = std::fabs(value()) + 1.0;
    if (!std::isfinite(p.x_min) || !std::isfinite(p.x_max)) p.x_min = p.x_max = 0.0;
    if (!std::isfinite(p.y_min) || !std::isfinite(p.y_max)) p.y_min = p.y_max = 0.0;
    if (pick(4) == 0) {
      for (int i = 0, n = 1 + pick(20); i < n; ++i) p.x_tic_labels.push_back({double(i), "category " + std::to_string(i)});
      p.rotate_x_tic_labels = pick(2) == 0;
    }
    for (int s = 0, ns = 1 + pick(5); s < ns; ++s) {
      PlotSeries q;
      q.style = St(pick(6));
      q.name = pick(2) ? "series " + std::to_string(s) : "";
      const bool smooth = pick(2) == 0;
      for (int i = 0, n = 1 + pick(pick(8) == 0 ? 2000 : 40); i < n; ++i) {
        q.x.push_back(smooth ? 0.1 * i : value());
        q.y.push_back(smooth ? 3.0 * std::sin(0.1 * i) : value());
        if (q.style == St::Band) q.y_low.push_back(smooth ? q.y.back() - 1.0 : value());
      }
      if (pick(4) == 0) q.y_err.assign(q.y.size(), 0.3);
      // one point positive on both axes, so log axes validate
      q.x.push_back(1.0), q.y.push_back(1.0);
      if (!q.y_low.empty()) q.y_low.push_back(0.5);
      if (!q.y_err.empty()) q.y_err.push_back(0.1);
      q.point_type = pick(16), q.point_size = 0.1 + 5.0 * next(), q.highlight = pick(2) == 0;
      p.series.push_back(q);
    }
    INFO("iteration " << it);
    std::string svg;
    REQUIRE_NOTHROW(svg = assess::render_svg(p));
    CHECK(svg.size() >= 7);
    CHECK(svg.compare(svg.size() - 7, 7, "</svg>\n") == 0);
    CHECK(svg.find("nan") == std::string::npos);
    CHECK(svg.find("inf") == std::string::npos);
  }
}

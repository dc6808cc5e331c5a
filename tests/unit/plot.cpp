// SVG rendering through gnuplot: structure of the output, escaping of user
// text, and the failure message when gnuplot is missing.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/support/error.hpp"
#include "assess/report/plot.hpp"

#include <cstdlib>
#include <string>

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

assess::Plot sample_plot() {
  using St = assess::PlotSeries::Style;
  assess::Plot p;
  p.title = "Spectra <site> & 'records'";
  p.x_label = "T (s)";
  p.y_label = "Se (m/s²)";
  p.log_x = true;
  p.series.push_back({"target", {0.1, 0.5, 1.0, 2.0}, {5.0, 7.0, 3.0, 1.5}, St::Line, {}, true, "#000000"});
  p.series.push_back({"band", {0.1, 2.0}, {4.5, 1.35}, St::Dashed, {}, false, ""});
  p.series.push_back({"rec_1 @x `echo hi`", {0.1, 0.5, 1.0}, {4.0, 8.0, 2.5}, St::Points, {0.2, 0.3, 0.1}, false, ""});
  p.series.push_back({"bars", {0.3, 0.6}, {2.0, 3.0}, St::Bars, {}, false, "#3366cc"});
  return p;
}

}  // namespace

TEST_CASE("render_svg returns an SVG with the title and one group per series") {
  if (!assess::gnuplot_available()) {
    MESSAGE("gnuplot not installed (Debian: gnuplot-nox): test skipped");
    return;
  }
  const std::string svg = assess::render_svg(sample_plot());
  CHECK(svg.find("<svg") != std::string::npos);
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(count(svg, "id=\"gnuplot_plot_") == 4);
  CHECK(svg.find("<title>Spectra &lt;site&gt; &amp; &#39;records&#39;</title>") != std::string::npos);
  // Legend text printed literally: no macro or command substitution.
  CHECK(svg.find("rec_1 @x `echo hi`") != std::string::npos);
  CHECK(svg.find("Se (m/s²)") != std::string::npos);
}

TEST_CASE("category tics and bars render") {
  if (!assess::gnuplot_available()) {
    MESSAGE("gnuplot not installed (Debian: gnuplot-nox): test skipped");
    return;
  }
  assess::Plot p;
  p.title = "D/C";
  p.y_label = "D/C (-)";
  p.x_tic_labels = {{0, "kinematic"}, {1, "rocking"}};
  p.series.push_back({"D/C", {0, 1}, {0.8, 1.2}, assess::PlotSeries::Style::Bars, {}, false, ""});
  const std::string svg = assess::render_svg(p);
  CHECK(svg.find(">kinematic<") != std::string::npos);
  CHECK(svg.find(">rocking<") != std::string::npos);
}

TEST_CASE("user text cannot break out of the gnuplot string") {
  assess::Plot p = sample_plot();
  p.title = "a'\nsystem('touch /tmp/x')";
  const std::string gp = assess::gnuplot_script(p);
  CHECK(gp.find("set title 'a'' system(''touch /tmp/x'')' noenhanced") != std::string::npos);
}

TEST_CASE("invalid plots throw InputError") {
  assess::Plot p = sample_plot();
  p.series[0].y.pop_back();
  CHECK_THROWS_AS(assess::gnuplot_script(p), assess::InputError);
  p = sample_plot();
  p.series[1].color = "red; system('x')";
  CHECK_THROWS_AS(assess::gnuplot_script(p), assess::InputError);
  p = sample_plot();
  p.series.clear();
  CHECK_THROWS_AS(assess::gnuplot_script(p), assess::InputError);
}

TEST_CASE("a missing gnuplot is reported with the package to install") {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", "/nonexistent", 1);
  std::string msg;
  try {
    assess::render_svg(sample_plot());
  } catch (const assess::InputError& e) {
    msg = e.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  CHECK(msg.find("gnuplot-nox") != std::string::npos);
}

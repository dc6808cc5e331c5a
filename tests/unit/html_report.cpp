// HtmlReport: well-formed HTML5 with one <figure> per plot, escaped text,
// page-unique SVG ids; and, when chromium is installed, a page of real plots
// (render_svg) loads in headless Chromium with every figure present and no
// console message (tests/browser/check_html.sh).
#include <doctest/doctest.h>

#include "check_close.hpp"
#include "tag_balance.hpp"

#include "assess/support/error.hpp"
#include "assess/report/html_report.hpp"
#include "assess/report/plot.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace {

const char* kSvg =
    "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
    "xmlns:xlink=\"http://www.w3.org/1999/xlink\" viewBox=\"0 0 10 10\"><defs><path id='gpPt0' d='M0,0'/>"
    "</defs><g id=\"gnuplot_plot_1\"><use xlink:href='#gpPt0'/></g></svg>\n";

// HTML's void elements (no end tag), for tag_balance.
const std::set<std::string> html_void_tags = {"meta", "br", "hr", "img", "link", "input"};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

bool have(const char* program) {
  return std::system((std::string("command -v ") + program + " >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace

TEST_CASE("the report is well-formed HTML5 with one figure per plot and escaped text") {
  assess::HtmlReport r("Façade <assessment> & check");
  r.add_heading("Input");
  r.add_paragraph("ag = 0.25 g; \"quoted\" <b>not bold</b>");
  r.add_table({"Record", "f (-)"}, {{"RSN285 <BAG>", "1.34"}, {"STU", "0.97"}}, "Scale factors");
  r.add_heading("Spectra");
  r.add_svg(kSvg, "Spectra", "fig-spectra");
  r.add_svg(kSvg, "Capacity", "fig-capacity");
  const std::string html = r.str();
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(tag_balance(html, html_void_tags) == "");
  CHECK(r.figure_count() == 2);
  CHECK(count(html, "<figure id=") == 2);
  CHECK(count(html, "<svg") == 2);
  CHECK(html.find("<?xml") == std::string::npos);
  CHECK(html.find("&lt;b&gt;not bold&lt;/b&gt;") != std::string::npos);
  CHECK(html.find("RSN285 &lt;BAG&gt;") != std::string::npos);
  // SVG ids made unique per figure, references follow.
  CHECK(html.find("id='fig-spectra-gpPt0'") != std::string::npos);
  CHECK(html.find("xlink:href='#fig-capacity-gpPt0'") != std::string::npos);
  CHECK(html.find("id=\"fig-capacity-gnuplot_plot_1\"") != std::string::npos);
  // Self-contained: no external resources or scripts.
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("<link") == std::string::npos);
  CHECK(html.find("src=") == std::string::npos);
  // Print styles: A4 and a page break before every section but the first.
  CHECK(html.find("size: A4") != std::string::npos);
  CHECK(count(html, "class=\"page-break\"") == 1);
}

TEST_CASE("invalid figures and tables throw InputError") {
  assess::HtmlReport r("t");
  r.add_svg(kSvg, "", "a");
  CHECK_THROWS_AS(r.add_svg(kSvg, "", "a"), assess::InputError);
  CHECK_THROWS_AS(r.add_svg(kSvg, "", "1bad id"), assess::InputError);
  CHECK_THROWS_AS(r.add_svg("<div>no svg</div>", "", "b"), assess::InputError);
  CHECK_THROWS_AS(r.add_table({"a", "b"}, {{"1"}}), assess::InputError);
  CHECK_THROWS_AS(r.add_heading("x", 1), assess::InputError);
}

TEST_CASE("a report of plots loads in headless Chromium with every figure and no console message") {
  if (!have("chromium")) {
    MESSAGE("chromium not installed: browser test skipped");
    return;
  }
  using St = assess::PlotSeries::Style;
  assess::HtmlReport r("Browser test");
  r.add_heading("Plots");
  for (int k = 0; k < 3; ++k) {
    assess::Plot p;
    p.title = "Plot " + std::to_string(k);
    p.x_label = "T (s)";
    p.y_label = "Se (m/s²)";
    p.log_x = k == 1;
    p.series.push_back({"a", {0.1, 0.5, 1.0}, {1.0, 3.0, 2.0}, St::Line, {}, true, ""});
    p.series.push_back({"b", {0.1, 0.5, 1.0}, {1.5, 2.0, 2.5}, St::Points, {}, false, ""});
    r.add_svg(assess::render_svg(p), p.title, "fig" + std::to_string(k));
  }
  const auto dir = std::filesystem::temp_directory_path() / "assess_html_report_test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "report.html";
  std::ofstream(file) << r.str();
  const std::string script = std::string(ASSESS_TEST_DATA_DIR) + "/tests/browser/check_html.sh";
  const int status = std::system(("sh '" + script + "' '" + file.string() + "' 3").c_str());
  CHECK(status == 0);
  std::filesystem::remove_all(dir);
}

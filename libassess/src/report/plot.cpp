// plot.cpp: gnuplot-driven SVG rendering (report layer; no physics).
//
// The script is written to a private temporary file (mkstemp) and run as
// `gnuplot FILE`; stdout is the SVG, stderr goes to a second temporary file
// and is quoted in the error message if gnuplot fails. Both paths are
// shell-quoted. Data travel inline in datablocks ($dN << EOD ... EOD).
#include "assess/report/plot.hpp"

#include "report/xml_escape.hpp"

#include "assess/support/error.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace assess {

namespace {

/// A gnuplot single-quoted string with literal content: ' doubled, control
/// characters (line breaks) replaced by blanks.
std::string gp_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) out += ' ';
    else out += c;
  }
  return out + "'";
}

/// POSIX shell single-quoting of a path.
std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}


std::string num(double x) {
  if (!std::isfinite(x)) return "NaN";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

/// A temporary file that is removed when it goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& stem) {
    std::string tmpl = (std::filesystem::temp_directory_path() / (stem + "XXXXXX")).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) throw InputError("plot: cannot create a temporary file in " + tmpl);
    ::close(fd);
    path_ = tmpl;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

constexpr const char* kMissing =
    "gnuplot was not found on PATH: install it (Debian/Ubuntu: apt-get install gnuplot-nox) to draw plots";

/// Runs gnuplot on a script file; returns {exit status, stdout}. Status 127
/// means the shell did not find the program.
std::pair<int, std::string> run_gnuplot(const std::string& script_path, const std::string& err_path) {
  const std::string cmd = "gnuplot " + sh_quote(script_path) + " 2>" + sh_quote(err_path);
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) throw InputError(kMissing);
  std::string out;
  char buf[65536];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int status = ::pclose(p);
  const int code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : 1;
  return {code, out};
}

}  // namespace

void Plot::validate() const {
  if (width < 100 || width > 4000 || height < 100 || height > 4000)
    throw InputError("plot '" + title + "': width and height must be in [100, 4000] px");
  if (font_size < 6 || font_size > 20) throw InputError("plot '" + title + "': font_size must be in [6, 20] pt");
  static const std::regex key_re("[a-z ]+");
  if (!std::regex_match(key, key_re)) throw InputError("plot '" + title + "': key must be gnuplot position words");
  if (series.empty()) throw InputError("plot '" + title + "': no series");
  if (!(bar_width > 0.0)) throw InputError("plot '" + title + "': bar_width must be > 0");
  static const std::regex colour("#[0-9a-fA-F]{6}");
  for (const auto& s : series) {
    const std::string what = "plot '" + title + "', series '" + s.name + "': ";
    if (s.x.empty() || s.x.size() != s.y.size())
      throw InputError(what + "x and y must be non-empty and of equal length");
    if (s.style == PlotSeries::Style::Band && s.y_low.size() != s.y.size())
      throw InputError(what + "a band needs y_low as long as y");
    if (!s.y_err.empty() && s.y_err.size() != s.y.size())
      throw InputError(what + "y_err must be empty or as long as y");
    if (!s.color.empty() && !std::regex_match(s.color, colour))
      throw InputError(what + "color must be \"#rrggbb\"");
    bool any_positive = false;
    for (std::size_t i = 0; i < s.x.size(); ++i)
      any_positive = any_positive || ((!log_x || s.x[i] > 0) && (!log_y || s.y[i] > 0));
    if ((log_x || log_y) && !any_positive)
      throw InputError(what + "no point with positive coordinates on a log axis");
  }
}

std::string gnuplot_script(const Plot& plot) {
  plot.validate();
  std::ostringstream gp;
  gp << "set encoding utf8\n"
     << "set terminal svg size " << plot.width << "," << plot.height
     << " dynamic enhanced font 'sans," << plot.font_size << "' background '#ffffff'\n"
     << "unset output\n"
     << "set title " << gp_quote(plot.title) << " noenhanced\n"
     << "set xlabel " << gp_quote(plot.x_label) << " noenhanced\n"
     << "set ylabel " << gp_quote(plot.y_label) << " noenhanced\n"
     << "set grid\n" << (plot.key == "off" ? std::string("unset key") : "set key " + plot.key + " noenhanced") << "\n"
     << "set style fill solid 0.6 border -1\nset boxwidth " << num(plot.bar_width) << " absolute\n";
  if (plot.log_x) gp << "set logscale x\n";
  if (plot.log_y) gp << "set logscale y\n";
  if (plot.x_min < plot.x_max) gp << "set xrange [" << num(plot.x_min) << ":" << num(plot.x_max) << "]\n";
  if (plot.y_min < plot.y_max) gp << "set yrange [" << num(plot.y_min) << ":" << num(plot.y_max) << "]\n";
  if (!plot.x_tic_labels.empty()) {
    gp << "set xtics noenhanced " << (plot.rotate_x_tic_labels ? "rotate by 30 right " : "") << "(";
    for (std::size_t i = 0; i < plot.x_tic_labels.size(); ++i)
      gp << (i ? ", " : "") << gp_quote(plot.x_tic_labels[i].second) << " " << num(plot.x_tic_labels[i].first);
    gp << ")\n";
  }
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    gp << "$d" << k << " << EOD\n";
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      gp << num(s.x[i]) << " " << num(s.y[i]);
      if (!s.y_err.empty()) gp << " " << num(s.y_err[i]);
      if (s.style == PlotSeries::Style::Band) gp << " " << num(s.y_low[i]);
      gp << "\n";
    }
    gp << "EOD\n";
  }
  gp << "plot ";
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    const bool err = !s.y_err.empty();
    const std::string lw = s.highlight ? " lw 3" : " lw 1.5";
    const bool band = s.style == PlotSeries::Style::Band;
    gp << (k ? ", \\\n     " : "") << "$d" << k
       << (band ? (err ? " using 1:4:2" : " using 1:3:2") : (err ? " using 1:2:3" : " using 1:2")) << " with ";
    const std::string pts = " pt " + std::to_string(s.point_type) + " ps " + num(s.point_size);
    using St = PlotSeries::Style;
    switch (s.style) {
      case St::Line: gp << (err ? "yerrorlines" : "lines") << lw; break;
      case St::Dashed: gp << (err ? "yerrorlines" : "lines") << " dt 2" << lw; break;
      case St::Points: gp << (err ? "yerrorbars" : "points") << pts; break;
      case St::LinePoints: gp << (err ? "yerrorlines" : "linespoints") << pts << lw; break;
      case St::Bars: gp << (err ? "boxerrorbars" : "boxes"); break;
      case St::Band: gp << "filledcurves fs transparent solid 0.25 noborder"; break;
    }
    if (!s.color.empty()) gp << " lc rgb " << gp_quote(s.color);
    if (s.name.empty()) gp << " notitle";
    else gp << " title " << gp_quote(s.name) << " noenhanced";
  }
  gp << "\n";
  return gp.str();
}

std::string render_svg(const Plot& plot) {
  const std::string script = gnuplot_script(plot);
  TempFile script_file("assess_plot_"), err_file("assess_plot_err_");
  {
    std::ofstream out(script_file.path(), std::ios::binary);
    out << script;
    if (!out) throw InputError("plot: cannot write the gnuplot script to " + script_file.path());
  }
  auto [code, svg] = run_gnuplot(script_file.path(), err_file.path());
  if (code == 127) throw InputError(kMissing);
  const std::string err = read_file(err_file.path());
  if (code != 0 || svg.find("</svg>") == std::string::npos)
    throw InputError("gnuplot failed on plot '" + plot.title + "' (exit " + std::to_string(code) + "): " + err);
  // Give the document the plot's title instead of "Gnuplot" (accessibility).
  const std::string generic = "<title>Gnuplot</title>";
  if (const auto pos = svg.find(generic); pos != std::string::npos)
    svg.replace(pos, generic.size(), "<title>" + detail::xml_escape(plot.title) + "</title>");
  return svg;
}

bool gnuplot_available() {
  TempFile script_file("assess_plot_probe_"), err_file("assess_plot_probe_err_");
  { std::ofstream(script_file.path()) << "exit\n"; }
  return run_gnuplot(script_file.path(), err_file.path()).first == 0;
}

}  // namespace assess

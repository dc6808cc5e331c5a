// plot.hpp: render 2-D plots to SVG with gnuplot (report layer; no physics).
//
// A Plot is plain data (title, axis labels, series); render_svg() writes a
// gnuplot script with the data inline, runs the `gnuplot` program found on
// PATH (Debian package gnuplot-nox, version >= 5.0) and returns the SVG text
// it writes to standard output. User text (titles, labels, series names) is
// passed in single-quoted gnuplot strings with enhanced-text processing off,
// so it is printed literally and can neither run commands (backquotes and
// @macros are not expanded inside single quotes) nor end the command (line
// breaks and control characters are replaced by blanks).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace assess {

/// One data series of a plot.
struct PlotSeries {
  enum class Style {
    Line,        ///< solid line
    Dashed,      ///< dashed line (limits, bands, reference curves)
    Points,      ///< markers only
    LinePoints,  ///< line with markers
    Bars,        ///< filled boxes centred at x (width: Plot::bar_width)
    Band,        ///< translucent area between y_low and y (a tolerance band)
  };
  std::string name;            ///< legend entry; empty: not in the legend
  std::vector<double> x, y;    ///< same length; non-finite y values are gaps
  Style style = Style::Line;
  std::vector<double> y_err;   ///< optional +/- error of y (same length), drawn as error bars
  bool highlight = false;      ///< drawn thicker (e.g. the mean of a set or the target)
  std::string color;           ///< optional "#rrggbb"; empty: gnuplot's cycle
  std::vector<double> y_low;   ///< Band: lower edge (same length as y)
  int point_type = 7;          ///< Points/LinePoints: gnuplot pt (7 circle, 5 square, 2 cross)
  double point_size = 0.6;     ///< Points/LinePoints: gnuplot ps
};

/// A 2-D plot. Axis labels should state the unit, e.g. "T (s)".
struct Plot {
  std::string title;
  std::string x_label, y_label;
  bool log_x = false, log_y = false;
  int width = 640, height = 400;   ///< SVG size (px), each in [100, 4000]
  double bar_width = 0.8;          ///< width of Bars in x units
  /// Optional fixed ranges; equal bounds (the default) mean autoscale.
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  /// Optional category labels at given x (e.g. a bar chart of approaches).
  std::vector<std::pair<double, std::string>> x_tic_labels;
  bool rotate_x_tic_labels = false;  ///< long category names: rotated by 30 degrees
  std::string key = "top right";     ///< legend position (gnuplot "set key" words) or "off"
  int font_size = 11;                ///< pt, 6..20 (small multiples use a smaller font)
  std::vector<PlotSeries> series;

  /// Throws InputError when the description is inconsistent (sizes, log
  /// axes with empty series, bad colour or size).
  void validate() const;
};

/// The gnuplot script that render_svg() runs (exposed for inspection/tests).
std::string gnuplot_script(const Plot& plot);

/// Renders the plot to an SVG document (UTF-8 text). Throws InputError if
/// gnuplot is not installed (naming the package gnuplot-nox) or fails (with
/// its message).
std::string render_svg(const Plot& plot);

/// True if a working `gnuplot` is on PATH.
bool gnuplot_available();

}  // namespace assess

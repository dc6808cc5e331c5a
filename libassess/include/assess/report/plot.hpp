// plot.hpp: render 2-D plots to SVG (report layer; no physics).
//
// A Plot is plain data (title, axis labels, series); render_svg() writes the
// SVG document itself, in this process (no external program): a frame with
// nice ticks (plot_layout.hpp), a light grid, the series clipped to the plot
// area, a legend, and the text escaped for XML (user text is printed
// literally). The output depends on the Plot only (byte-identical runs) and
// stays small: coordinates to 0.01 user unit, lines thinned where a point
// lies within 0.2 unit of the line through its neighbours.
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
  std::vector<double> x, y;    ///< same length; a non-finite x or y is a gap
  Style style = Style::Line;
  std::vector<double> y_err;   ///< optional +/- error of y (same length), drawn as error bars
  bool highlight = false;      ///< drawn thicker (e.g. the mean of a set or the target)
  std::string color;           ///< optional "#rrggbb"; empty: the next colour of a fixed cycle
  std::vector<double> y_low;   ///< Band: lower edge (same length as y)
  /// Points/LinePoints marker, numbered as gnuplot's: 0 dot, 1 plus, 2 cross,
  /// 3 star, 4/5 square, 6/7 circle, 8/9 triangle, 10/11 inverted triangle,
  /// 12/13 diamond, 14/15 pentagon (odd: filled, even: open).
  int point_type = 7;
  double point_size = 0.6;     ///< marker half-size in units of 0.375 font sizes, (0, 10]
};

/// A series with its legend entry, style and (optionally) its points.
inline PlotSeries plot_series(std::string name, PlotSeries::Style style, std::vector<double> x = {},
                              std::vector<double> y = {}) {
  PlotSeries s;
  s.name = std::move(name);
  s.style = style;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

/// A 2-D plot. Axis labels should state the unit, e.g. "T (s)".
struct Plot {
  std::string title;
  std::string x_label, y_label;
  bool log_x = false, log_y = false;
  int width = 640, height = 400;   ///< SVG size (px), each in [100, 4000]
  double bar_width = 0.8;          ///< width of Bars in x units
  /// Optional fixed ranges (finite; > 0 on a log axis); min >= max (the
  /// default: equal bounds) means autoscale to nice ticks around the data.
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  /// Optional category labels at given x (e.g. a bar chart of approaches):
  /// they replace the numeric x ticks.
  std::vector<std::pair<double, std::string>> x_tic_labels;
  /// Category labels rotated by 30 degrees (also done when they would
  /// overlap side by side; crowded rotated labels are thinned).
  bool rotate_x_tic_labels = false;
  /// Legend position, words among top, bottom, left, right, center, inside,
  /// outside, below, above, or "off". Inside (the default "top right"): a
  /// box in that corner of the plot area; when it would cover a line, marker,
  /// bar or band, the first free corner (top right, top left, bottom right,
  /// bottom left), else below the plot (the figure grows). "below"/"above":
  /// columns under the x label / over the plot; "outside" (right unless
  /// "left"; "top", "center", "bottom" align it): beside the plot area.
  std::string key = "top right";
  /// Tick labels with the decimal comma (the Italian relazione, issue 28).
  bool decimal_comma = false;
  int font_size = 11;                ///< SVG units (px at 100 %), 6..20 (small multiples use a smaller font)
  std::vector<PlotSeries> series;

  /// Throws InputError when the description is inconsistent (sizes, log
  /// axes without a positive point, bad colour, marker, range or key words).
  void validate() const;
};

/// Renders the plot to an SVG document (UTF-8 text, no ids, viewBox only so
/// that it scales to the width of its container). Non-finite values (and
/// values <= 0 on a log axis) are gaps. Throws InputError if the plot does
/// not validate.
std::string render_svg(const Plot& plot);

}  // namespace assess

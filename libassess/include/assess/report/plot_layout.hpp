// plot_layout.hpp: where render_svg() draws a Plot (report layer; no
// physics): the plot area in SVG user units and, per axis, the range shown,
// its ticks and the mapping of a data value to an SVG coordinate. Exposed so
// tests (and callers that annotate a figure) can check the geometry.
#pragma once

#include "assess/report/plot.hpp"

#include <string>
#include <vector>

namespace assess {

/// A tick of an axis: labelled (major) or, with an empty label, minor.
struct AxisTick {
  double value = 0;   ///< data units
  std::string label;  ///< as printed ("0.5", "−1.0", "10⁻⁵"); empty: minor tick
};

/// One axis: range, ticks and mapping.
struct PlotAxis {
  double lo = 0, hi = 1;        ///< range shown, data units (lo < hi; both > 0 on a log axis)
  bool log = false;             ///< logarithmic
  double px_lo = 0, px_hi = 1;  ///< SVG coordinates of lo and hi (y axis: px_lo > px_hi)
  std::vector<AxisTick> ticks;  ///< ascending; labelled ticks never overlap
  /// SVG coordinate of v: px_lo + (v - lo) / (hi - lo) (px_hi - px_lo), with
  /// log10 of each on a log axis; NaN when v is not finite (or not > 0 on a log axis).
  double to_px(double v) const;
};

/// The axis of a range. Fixed: [lo, hi] as given. Otherwise [lo, hi] is the
/// data's extent, widened to the ticks around it (linear: multiples of the
/// step; log: whole decades); a degenerate extent is widened first.
/// Linear ticks: steps of 1, 2 or 5 x 10^k, the smallest whose labels (set in
/// `font_size`) keep clear of each other (x: 4.5 font sizes apart at least
/// and a font size between labels; y: 3 font sizes), printed with the
/// step's decimals. Log: decades (every n-th decade when crowded), minor
/// ticks at 2..9 where a decade is wide enough, and 2 and 5 labelled when
/// fewer than two decades are shown; a range within one decade falls back to
/// linear steps. `vertical`: a y axis (labels stacked, not side by side).
PlotAxis make_plot_axis(double lo, double hi, bool fixed, bool log, double px_lo, double px_hi, double font_size,
                        bool vertical);

/// Where render_svg() draws `plot`.
struct PlotLayout {
  /// The SVG's viewBox: Plot::width and height, grown by an inside legend
  /// moved below, or where the text would leave the plot area less than 30 %
  /// of the figure's width or height.
  double width = 0, height = 0;
  double left = 0, top = 0, right = 0, bottom = 0;  ///< the plot area (inside the frame), SVG coordinates
  PlotAxis x, y;  ///< x.px_lo = left, x.px_hi = right, y.px_lo = bottom, y.px_hi = top
};

/// The layout of a plot (validates it first: InputError like Plot::validate()).
PlotLayout plot_layout(const Plot& plot);

}  // namespace assess

// plot_frame.hpp (private): the full layout of a plot as render_svg() draws
// it: the public PlotLayout (plot area and axes) plus the text lines, the
// category tick labels and the legend's box and entries.
#pragma once

#include "assess/report/plot_layout.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace assess::detail {

enum class KeyPlace { None, Inside, Below, Above, OutsideRight, OutsideLeft };

/// Plot::key parsed: place and alignment ('l', 'c', 'r'; 't', 'c', 'b').
struct KeySpec {
  KeyPlace place = KeyPlace::Inside;
  char h = 'r', v = 't';
};

/// Parses Plot::key; throws InputError naming the allowed words.
KeySpec parse_key(const std::string& key, const std::string& plot_title);

struct KeyEntry {
  std::size_t series = 0;          ///< index in Plot::series
  std::vector<std::string> lines;  ///< the name, wrapped
  double width = 0, height = 0;    ///< sample + text
};

/// The legend: entries in columns (column-major), its box's top-left corner and size.
struct KeyBox {
  KeySpec spec;
  std::vector<KeyEntry> entries;
  std::vector<std::vector<std::size_t>> columns;  ///< entry indices per column
  std::vector<double> column_width;
  double x = 0, y = 0, w = 0, h = 0;
};

/// Sizes shared by the layout and the drawing, in units of the font size.
struct KeyMetrics {
  static constexpr double sample = 2.2, gap = 0.5, line = 1.25, inner = 0.45, column_gap = 1.2;
};

struct FrameLayout {
  PlotLayout pub;
  double fs = 11, title_fs = 12.1, pad = 6.6;
  std::vector<std::string> title_lines, x_label_lines, y_label_lines;
  bool categories = false;     ///< x ticks are Plot::x_tic_labels
  bool rotate = false;         ///< category labels at 30 degrees
  std::size_t category_stride = 1;  ///< every n-th category label printed (crowded rotated labels)
  bool wrap_categories = true;      ///< rotated category labels wrapped (unless that crowds them)
  double x_label_y = 0;        ///< baseline of the first x-label line
  KeyBox key;
};

/// A rotated category label in lines (long names wrapped at 14 font sizes
/// when `wrap`).
std::vector<std::string> category_lines(const std::string& label, double fs, bool wrap);

/// Puts an inside legend in a corner of the plot area ('l', 'c', 'r'; 't', 'c', 'b').
void place_inside_key(FrameLayout& f, char h, char v);

/// The layout; `key_below` moves an inside legend below the plot and grows
/// the height by it (the plot area keeps its size). Validates the plot.
FrameLayout frame_layout(const Plot& plot, bool key_below = false);

}  // namespace assess::detail

// plot_layout.cpp: the layout of a plot (plot_frame.hpp, plot_layout.hpp):
// margins from the text they hold (title, axis labels, tick labels), the
// axes over the plot area, and the legend's columns and place.
//
// Vertical sizes come first (title, x label, legend below or above, the x
// tick labels' band), then the y axis over the plot area's height, whose
// widest label sets the left margin, then the x axis over the remaining
// width; the margins grow where an x tick label would overflow the canvas.
#include "report/plot_frame.hpp"

#include "report/svg_text.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess::detail {

namespace {

constexpr double kSin30 = 0.5, kCos30 = 0.8660254037844386;

std::vector<std::string> split_words(const std::string& s) {
  std::vector<std::string> out;
  std::string w;
  for (char c : s) {
    if (c == ' ') {
      if (!w.empty()) out.push_back(w), w.clear();
    } else {
      w += c;
    }
  }
  if (!w.empty()) out.push_back(w);
  return out;
}

bool has_text(const std::string& s) {
  for (char c : s)
    if (static_cast<unsigned char>(c) > 0x20) return true;
  return false;
}

/// Range of the data along one axis.
struct Extent {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v, bool log) {
    if (!std::isfinite(v) || (log && !(v > 0.0))) return;
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

bool fixed_range(double lo, double hi) { return lo < hi; }

/// The extents of the data in x and y; a fixed range of one axis limits the
/// points that set the other's extent to those inside it.
std::pair<Extent, Extent> data_extents(const Plot& p) {
  Extent ex, ey;
  const bool fx = fixed_range(p.x_min, p.x_max), fy = fixed_range(p.y_min, p.y_max);
  using St = PlotSeries::Style;
  for (const PlotSeries& s : p.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double x = s.x[i], y = s.y[i];
      if (!std::isfinite(x) || !std::isfinite(y) || (p.log_x && !(x > 0.0)) || (p.log_y && !(y > 0.0))) continue;
      const bool in_x = !fx || (x >= p.x_min && x <= p.x_max), in_y = !fy || (y >= p.y_min && y <= p.y_max);
      if (in_y) {
        if (s.style == St::Bars) {
          ex.add(x - 0.5 * p.bar_width, p.log_x);
          ex.add(x + 0.5 * p.bar_width, p.log_x);
        } else {
          ex.add(x, p.log_x);
        }
      }
      if (in_x) {
        ey.add(y, p.log_y);
        if (!s.y_err.empty() && std::isfinite(s.y_err[i])) {
          ey.add(y - std::fabs(s.y_err[i]), p.log_y);
          ey.add(y + std::fabs(s.y_err[i]), p.log_y);
        }
        if (s.style == St::Band) ey.add(s.y_low[i], p.log_y);
        if (s.style == St::Bars && !p.log_y) ey.add(0.0, false);
      }
    }
  }
  return {ex, ey};
}

/// Lays the legend's entries out in columns (column-major, as many columns
/// as fit in max_w when `multi`), and sizes its box.
void arrange_key(KeyBox& k, const Plot& p, double max_w, bool multi, double fs) {
  using M = KeyMetrics;
  const double fixed = (M::sample + M::gap + 2 * M::inner) * fs;
  const double text_max = std::max(4.0 * fs, max_w - fixed);
  for (KeyEntry& e : k.entries) {
    e.lines = wrap_text(p.series[e.series].name, text_max, fs, 3);
    double tw = 0.0;
    for (const auto& l : e.lines) tw = std::max(tw, text_width(l, fs));
    e.width = (M::sample + M::gap) * fs + tw;
    e.height = double(std::max<std::size_t>(1, e.lines.size())) * M::line * fs;
  }
  const std::size_t n = k.entries.size();
  for (std::size_t want = multi ? n : 1; want >= 1; --want) {
    const std::size_t rows = (n + want - 1) / want, cols = (n + rows - 1) / rows;
    k.columns.assign(cols, {});
    k.column_width.assign(cols, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      k.columns[i / rows].push_back(i);
      k.column_width[i / rows] = std::max(k.column_width[i / rows], k.entries[i].width);
    }
    double w = 2 * M::inner * fs + M::column_gap * fs * double(cols - 1);
    for (double cw : k.column_width) w += cw;
    double h = 0.0;
    for (const auto& c : k.columns) {
      double ch = 0.0;
      for (std::size_t i : c) ch += k.entries[i].height;
      h = std::max(h, ch);
    }
    k.w = w, k.h = h + 2 * M::inner * fs;
    if (w <= max_w || want == 1) break;
  }
}

/// True if the rotated category labels, every `stride`-th printed, keep
/// clear of each other: a label's further lines run down-right, into the
/// next label when that one reaches back over it.
bool rotated_labels_fit(const PlotAxis& x, std::size_t stride, double fs, bool wrap) {
  std::vector<std::pair<double, std::pair<double, std::size_t>>> shown;  // position, (width, lines)
  for (std::size_t i = 0; i < x.ticks.size(); i += stride) {
    const std::vector<std::string> lines = category_lines(x.ticks[i].label, fs, wrap);
    double w = 0.0;
    for (const auto& l : lines) w = std::max(w, text_width(l, fs));
    shown.push_back({x.to_px(x.ticks[i].value), {w, std::max<std::size_t>(1, lines.size())}});
  }
  for (std::size_t i = 0; i < shown.size(); ++i)
    for (std::size_t j = i + 1; j < shown.size(); ++j) {
      const double gap = std::fabs(shown[j].first - shown[i].first);
      if (gap * kCos30 - shown[j].second.first > 0.2 * fs) break;  // j does not reach back to i (nor do later ones, mostly)
      if (gap * kSin30 < double(shown[i].second.second - 1) * 1.15 * fs + 1.05 * fs) return false;
    }
  return true;
}

/// Extent of a rotated (30 degrees) category label below its anchor and to its left.
std::pair<double, double> rotated_extent(const std::string& label, double fs, bool wrap) {
  const std::vector<std::string> lines = category_lines(label, fs, wrap);
  double w = 0.0;
  for (const auto& l : lines) w = std::max(w, text_width(l, fs));
  const double depth = double(std::max<std::size_t>(1, lines.size())) * 1.15 * fs;
  return {w * kSin30 + depth * kCos30, w * kCos30 + depth * kSin30};
}

}  // namespace

std::vector<std::string> category_lines(const std::string& label, double fs, bool wrap) {
  return wrap_text(label, wrap ? 14.0 * fs : std::numeric_limits<double>::infinity(), fs, 3);
}

KeySpec parse_key(const std::string& key, const std::string& title) {
  static const char* allowed[] = {"off", "top", "bottom", "left", "right", "center", "inside", "outside", "below", "above"};
  const std::vector<std::string> words = split_words(key);
  const std::string what = "plot '" + title + "': key '" + key + "'";
  if (words.empty()) throw InputError(what + ": empty (give position words or \"off\")");
  for (const auto& w : words)
    if (std::find(std::begin(allowed), std::end(allowed), w) == std::end(allowed))
      throw InputError(what + ": '" + w +
                       "' is not a position word (off, top, bottom, left, right, center, inside, outside, below, above)");
  const auto has = [&](const char* w) { return std::find(words.begin(), words.end(), w) != words.end(); };
  KeySpec k;
  if (has("off")) {
    if (words.size() != 1) throw InputError(what + ": \"off\" stands alone");
    k.place = KeyPlace::None;
    return k;
  }
  k.v = has("top") ? 't' : has("bottom") ? 'b' : has("center") ? 'c' : 't';
  k.h = has("left") ? 'l' : has("right") ? 'r' : has("center") ? 'c' : 'r';
  if (has("below")) k.place = KeyPlace::Below;
  else if (has("above")) k.place = KeyPlace::Above;
  else if (has("outside")) {
    if (has("left")) k.place = KeyPlace::OutsideLeft;
    else if (has("right")) k.place = KeyPlace::OutsideRight;
    else if (has("bottom")) k.place = KeyPlace::Below;
    else if (has("top")) k.place = KeyPlace::Above;
    else k.place = KeyPlace::OutsideRight;
  }
  return k;
}

void place_inside_key(FrameLayout& f, char h, char v) {
  const PlotLayout& L = f.pub;
  const double m = 0.5 * f.fs;
  f.key.x = h == 'l' ? L.left + m : h == 'r' ? L.right - m - f.key.w : 0.5 * (L.left + L.right - f.key.w);
  f.key.y = v == 't' ? L.top + m : v == 'b' ? L.bottom - m - f.key.h : 0.5 * (L.top + L.bottom - f.key.h);
}

namespace {

FrameLayout layout(const Plot& plot, bool key_below, bool wrap) {
  FrameLayout f;
  f.wrap_categories = wrap;
  const double fs = plot.font_size, W = plot.width, H = plot.height;
  f.fs = fs, f.title_fs = 1.1 * fs, f.pad = 0.6 * fs;
  const double pad = f.pad;
  // Text wraps to the figure; beyond a few lines it is cut with "…" (the
  // caption and tables carry long text, not the figure).
  f.title_lines = wrap_text(plot.title, W - 2 * pad, f.title_fs, 3);
  f.x_label_lines = wrap_text(plot.x_label, W - 2 * pad, fs, 2);

  KeyBox& key = f.key;
  key.spec = parse_key(plot.key, plot.title);
  for (std::size_t i = 0; i < plot.series.size(); ++i)
    if (has_text(plot.series[i].name)) key.entries.push_back({i, {}, 0, 0});
  if (key.entries.empty()) key.spec.place = KeyPlace::None;
  const bool grow = key_below && key.spec.place == KeyPlace::Inside;
  if (grow) key.spec.place = KeyPlace::Below;

  const double title_h = f.title_lines.empty() ? 0.0 : double(f.title_lines.size()) * 1.25 * f.title_fs + 0.3 * fs;
  double top = pad + title_h + 0.6 * fs;
  double bottom_base = pad + (f.x_label_lines.empty() ? 0.0 : double(f.x_label_lines.size()) * 1.25 * fs + 0.2 * fs);
  double left_base = pad, right_base = pad;
  switch (key.spec.place) {
    case KeyPlace::Below:
      arrange_key(key, plot, W - 2 * pad, true, fs);
      bottom_base += key.h + 0.5 * fs;
      break;
    case KeyPlace::Above:
      arrange_key(key, plot, W - 2 * pad, true, fs);
      key.y = pad + title_h;
      top += key.h + 0.4 * fs;
      break;
    case KeyPlace::OutsideRight:
      arrange_key(key, plot, 0.4 * W, false, fs);
      right_base += key.w + 0.8 * fs;
      break;
    case KeyPlace::OutsideLeft:
      arrange_key(key, plot, 0.4 * W, false, fs);
      left_base += key.w + 0.8 * fs;
      break;
    case KeyPlace::Inside:
      arrange_key(key, plot, 0.5 * W, false, fs);
      break;
    case KeyPlace::None:
      break;
  }

  const auto [ex, ey] = data_extents(plot);
  f.categories = !plot.x_tic_labels.empty();
  f.rotate = f.categories && plot.rotate_x_tic_labels;
  const bool fx = fixed_range(plot.x_min, plot.x_max), fy = fixed_range(plot.y_min, plot.y_max);
  double x_lo = fx ? plot.x_min : ex.lo, x_hi = fx ? plot.x_max : ex.hi;
  bool x_fixed = fx;
  if (f.categories && !fx) {  // categories: their extent and the data's, half a slot either side
    Extent e = ex;
    for (const auto& c : plot.x_tic_labels) e.add(c.first, plot.log_x);
    if (!e.empty() && !plot.log_x) x_lo = e.lo - 0.6, x_hi = e.hi + 0.6, x_fixed = true;
  }

  double plot_bottom_margin = 0.0, Heff = H, Wd = W;  // Heff, Wd: grown when text leaves too little room
  for (int pass = 0; pass < 2; ++pass) {
    double band = 1.75 * fs;  // x tick labels: gap, ascent and descent
    if (f.rotate) {
      double need = 0.0;
      for (const auto& c : plot.x_tic_labels)
        if (!x_fixed || (c.first >= x_lo && c.first <= x_hi)) need = std::max(need, rotated_extent(c.second, fs, wrap).first);
      band = need + 0.6 * fs;
    }
    const double bottom = bottom_base + band;
    Heff = H;
    // The plot area keeps at least 30 % of the height (the figure grows);
    // a legend moved below grows the figure by its own block.
    if (grow) Heff += key.h + 0.5 * fs;
    const double min_h = std::max(3.0 * fs, 0.3 * H);
    if (Heff - top - bottom < min_h) Heff = top + bottom + min_h;
    f.pub.y = make_plot_axis(fy ? plot.y_min : ey.lo, fy ? plot.y_max : ey.hi, fy, plot.log_y, Heff - bottom, top, fs, true);
    double y_label_w = 0.0;
    for (const auto& t : f.pub.y.ticks) y_label_w = std::max(y_label_w, text_width(t.label, fs));
    f.y_label_lines = wrap_text(plot.y_label, Heff - bottom - top, fs, 2);
    double left = left_base + (f.y_label_lines.empty() ? 0.0 : double(f.y_label_lines.size()) * 1.25 * fs + 0.2 * fs) +
                  y_label_w + 0.5 * fs;
    double right_m = right_base;
    Wd = W;
    for (int it = 0; it < 6; ++it) {
      // The plot area keeps at least 30 % of the width (the figure grows).
      Wd = std::max(W, left + right_m + std::max(3.0 * fs, 0.3 * W));
      f.pub.x = make_plot_axis(x_lo, x_hi, x_fixed, plot.log_x, left, Wd - right_m, fs, false);
      if (f.categories) {
        f.pub.x.ticks.clear();
        for (const auto& c : plot.x_tic_labels) {
          const double px = f.pub.x.to_px(c.first);
          if (std::isfinite(px) && px >= left - 0.01 && px <= Wd - right_m + 0.01) f.pub.x.ticks.push_back({c.first, c.second});
        }
      }
      double over_l = 0.0, over_r = 0.0;
      for (const auto& t : f.pub.x.ticks) {
        if (t.label.empty()) continue;
        const double px = f.pub.x.to_px(t.value), w = text_width(t.label, fs);
        if (f.rotate) {
          over_l = std::max(over_l, pad - (px - rotated_extent(t.label, fs, wrap).second));
        } else {
          over_l = std::max(over_l, pad - (px - 0.5 * w));
          over_r = std::max(over_r, px + 0.5 * w - (Wd - pad));
        }
      }
      if (over_l <= 0.01 && over_r <= 0.01) break;
      left += std::max(0.0, over_l), right_m += std::max(0.0, over_r);
    }
    plot_bottom_margin = bottom;
    f.pub.left = left, f.pub.right = Wd - right_m, f.pub.top = top, f.pub.bottom = Heff - bottom;
    if (f.categories && !f.rotate) {  // side by side they would overlap: rotate them
      bool overlap = false;
      const auto& t = f.pub.x.ticks;
      for (std::size_t i = 1; i < t.size(); ++i)
        overlap = overlap || std::fabs(f.pub.x.to_px(t[i].value) - f.pub.x.to_px(t[i - 1].value)) <
                                 0.5 * (text_width(t[i].label, fs) + text_width(t[i - 1].label, fs)) + 0.5 * fs;
      if (overlap) {
        f.rotate = true;
        continue;
      }
    }
    break;
  }
  if (f.rotate) {  // rotated labels that would touch: print every n-th
    const auto& t = f.pub.x.ticks;
    while (f.category_stride < t.size() && !rotated_labels_fit(f.pub.x, f.category_stride, fs, wrap)) ++f.category_stride;
  }
  f.pub.width = Wd, f.pub.height = Heff;
  // x label under the tick labels' band; legends at their places.
  f.x_label_y = f.pub.bottom + (plot_bottom_margin - bottom_base) + 0.95 * fs;
  switch (key.spec.place) {
    case KeyPlace::Below:
      key.x = std::clamp(0.5 * (f.pub.left + f.pub.right - key.w), pad, std::max(pad, Wd - pad - key.w));
      key.y = Heff - pad - key.h;
      break;
    case KeyPlace::Above:
      key.x = std::clamp(0.5 * (f.pub.left + f.pub.right - key.w), pad, std::max(pad, Wd - pad - key.w));
      break;
    case KeyPlace::OutsideRight:
    case KeyPlace::OutsideLeft:
      key.x = key.spec.place == KeyPlace::OutsideRight ? Wd - pad - key.w : pad;
      key.y = key.spec.v == 'b' ? f.pub.bottom - key.h : key.spec.v == 'c' ? 0.5 * (f.pub.top + f.pub.bottom - key.h) : f.pub.top;
      break;
    case KeyPlace::Inside:
      place_inside_key(f, key.spec.h, key.spec.v);
      break;
    case KeyPlace::None:
      break;
  }
  return f;
}

}  // namespace

FrameLayout frame_layout(const Plot& plot, bool key_below) {
  plot.validate();
  FrameLayout f = layout(plot, key_below, true);
  if (f.rotate && f.category_stride > 1) {  // wrapped names crowd each other: single lines
    FrameLayout g = layout(plot, key_below, false);
    if (g.category_stride <= f.category_stride) return g;
  }
  return f;
}

}  // namespace assess::detail

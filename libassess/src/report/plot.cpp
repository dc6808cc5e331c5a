// plot.cpp: SVG rendering of a Plot, written directly (no external program).
//
// The data are mapped to SVG coordinates through the layout's axes
// (plot_layout.cpp), clipped to the plot area (lines and error bars by
// Liang-Barsky, bands by Sutherland-Hodgman, bars as rectangles, markers
// whose centre lies outside dropped), thinned (Ramer-Douglas-Peucker, 0.2
// unit: invisible) and written with two decimals, polylines as relative path
// commands between rounded points (exact, no drift). An inside legend goes to
// the first corner where it hides no data, else below the plot.
#include "assess/report/plot.hpp"
#include "assess/report/plot_layout.hpp"

#include "report/plot_frame.hpp"
#include "report/svg_text.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace assess {

namespace {

using detail::append_coord;
using detail::coord;
using detail::FrameLayout;
using detail::KeyPlace;
using detail::svg_escape;
using St = PlotSeries::Style;

bool is_colour(const std::string& c) {
  if (c.size() != 7 || c[0] != '#') return false;
  for (std::size_t i = 1; i < 7; ++i)
    if (!std::isxdigit(static_cast<unsigned char>(c[i]))) return false;
  return true;
}

// ------------------------------------------------------------------ geometry

struct P {
  double x, y;
};

struct Box {
  double x0, y0, x1, y1;  // x0 <= x1, y0 <= y1
  Box inflated(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
  bool contains(const P& p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
  bool overlaps(const Box& b) const { return b.x0 <= x1 && b.x1 >= x0 && b.y0 <= y1 && b.y1 >= y0; }
};

/// Liang-Barsky: clips segment a-b to the box; false when nothing is left.
/// `a_moved`/`b_moved`: that end was cut.
bool clip_segment(P& a, P& b, const Box& r, bool& a_moved, bool& b_moved) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t0 = 0.0, t1 = 1.0;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - r.x0, r.x1 - a.x, a.y - r.y0, r.y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
    } else {
      const double t = q[i] / p[i];
      if (p[i] < 0.0) {
        if (t > t1) return false;
        t0 = std::max(t0, t);
      } else {
        if (t < t0) return false;
        t1 = std::min(t1, t);
      }
    }
  }
  a_moved = t0 > 0.0, b_moved = t1 < 1.0;
  const P a0 = a;
  if (a_moved) a = {a0.x + t0 * dx, a0.y + t0 * dy};
  if (b_moved) b = {a0.x + t1 * dx, a0.y + t1 * dy};
  return true;
}

bool segment_hits(P a, P b, const Box& r) {
  bool ma = false, mb = false;
  return clip_segment(a, b, r, ma, mb);
}

/// Sutherland-Hodgman: a polygon clipped to the box.
std::vector<P> clip_polygon(std::vector<P> poly, const Box& r) {
  for (int edge = 0; edge < 4 && !poly.empty(); ++edge) {
    const auto inside = [&](const P& p) {
      switch (edge) {
        case 0: return p.x >= r.x0;
        case 1: return p.x <= r.x1;
        case 2: return p.y >= r.y0;
        default: return p.y <= r.y1;
      }
    };
    const auto cut = [&](const P& a, const P& b) {
      double t = 0.0;
      switch (edge) {
        case 0: t = (r.x0 - a.x) / (b.x - a.x); break;
        case 1: t = (r.x1 - a.x) / (b.x - a.x); break;
        case 2: t = (r.y0 - a.y) / (b.y - a.y); break;
        default: t = (r.y1 - a.y) / (b.y - a.y); break;
      }
      return P{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    };
    std::vector<P> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const P& cur = poly[i];
      const P& prev = poly[(i + poly.size() - 1) % poly.size()];
      const bool ci = inside(cur), pi = inside(prev);
      if (ci) {
        if (!pi) out.push_back(cut(prev, cur));
        out.push_back(cur);
      } else if (pi) {
        out.push_back(cut(prev, cur));
      }
    }
    poly = std::move(out);
  }
  return poly;
}

double segment_distance(const P& p, const P& a, const P& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// Ramer-Douglas-Peucker over chunks of at most 1024 points (their ends
/// kept), so the cost stays linear in the number of points.
std::vector<P> simplify(const std::vector<P>& pts, double eps) {
  const std::size_t n = pts.size();
  if (n <= 2) return pts;
  std::vector<char> keep(n, 0);
  constexpr std::size_t chunk = 1024;
  std::vector<std::pair<std::size_t, std::size_t>> stack;
  for (std::size_t s = 0; s + 1 < n; s += chunk) stack.push_back({s, std::min(n - 1, s + chunk)});
  keep[0] = keep[n - 1] = 1;
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    keep[a] = keep[b] = 1;
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = segment_distance(pts[i], pts[a], pts[b]);
      if (d > worst) worst = d, at = i;
    }
    if (worst > eps) {
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
  std::vector<P> out;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) out.push_back(pts[i]);
  return out;
}

/// Splits a run of points into the pieces inside the box.
void clip_run(const std::vector<P>& run, const Box& r, std::vector<std::vector<P>>& out) {
  std::vector<P> cur;
  const auto flush = [&]() {
    if (cur.size() >= 2) out.push_back(cur);
    cur.clear();
  };
  for (std::size_t i = 1; i < run.size(); ++i) {
    P a = run[i - 1], b = run[i];
    bool ma = false, mb = false;
    if (!clip_segment(a, b, r, ma, mb)) {
      flush();
      continue;
    }
    if (cur.empty() || ma) {
      flush();
      cur.push_back(a);
    }
    cur.push_back(b);
    if (mb) flush();
  }
  flush();
}

/// One series in SVG coordinates, clipped.
struct SeriesGeom {
  std::vector<std::vector<P>> lines, bands;
  std::vector<Box> bars;
  std::vector<std::pair<P, P>> errs;
  std::vector<P> caps;  // error-bar ends inside the plot area
  std::vector<P> markers;
  std::string colour;
  double lw = 1.5, marker_r = 2.5;
};

/// The default colour cycle (series without a colour, in order): print-safe
/// hues, no yellow.
const char* const kCycle[] = {"#1f5fbf", "#d9730d", "#2b7a2b", "#b3001b", "#8a3ea8", "#17879b", "#8c564b", "#555555"};

double base_width(double fs) { return std::max(1.0, 1.5 * fs / 11.0); }

std::vector<SeriesGeom> geometry(const Plot& plot, const FrameLayout& f) {
  const PlotLayout& L = f.pub;
  const Box area{L.left, L.top, L.right, L.bottom};
  std::vector<SeriesGeom> out;
  std::size_t cycle = 0;
  for (const PlotSeries& s : plot.series) {
    SeriesGeom g;
    g.colour = s.color.empty() ? kCycle[cycle++ % 8] : s.color;
    for (char& c : g.colour) c = char(std::tolower(static_cast<unsigned char>(c)));
    g.lw = base_width(f.fs) * (s.highlight ? 2.0 : 1.0);
    g.marker_r = std::max(1.5, 0.375 * f.fs * s.point_size);
    const std::size_t n = s.x.size();
    std::vector<P> pts(n);
    std::vector<char> ok(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      pts[i] = {L.x.to_px(s.x[i]), L.y.to_px(s.y[i])};
      ok[i] = std::isfinite(pts[i].x) && std::isfinite(pts[i].y);
    }
    const bool lines = s.style == St::Line || s.style == St::Dashed || s.style == St::LinePoints;
    if (lines) {
      std::vector<P> run;
      const auto end_run = [&]() {
        std::vector<std::vector<P>> pieces;
        clip_run(run, area, pieces);
        for (auto& piece : pieces) g.lines.push_back(simplify(piece, 0.2));
        run.clear();
      };
      for (std::size_t i = 0; i < n; ++i) {
        if (ok[i]) run.push_back(pts[i]);
        else end_run();
      }
      end_run();
    }
    if (s.style == St::Band) {
      std::vector<P> upper, lower;
      const auto end_band = [&]() {
        if (upper.size() >= 2) {
          std::vector<P> poly = simplify(upper, 0.2);
          const std::vector<P> low = simplify(lower, 0.2);
          poly.insert(poly.end(), low.rbegin(), low.rend());
          poly = clip_polygon(poly, area);
          if (poly.size() >= 3) g.bands.push_back(poly);
        }
        upper.clear(), lower.clear();
      };
      for (std::size_t i = 0; i < n; ++i) {
        const double yl = L.y.to_px(s.y_low[i]);
        if (ok[i] && std::isfinite(yl)) upper.push_back(pts[i]), lower.push_back({pts[i].x, yl});
        else end_band();
      }
      end_band();
    }
    if (s.style == St::Bars) {
      const double base = L.y.log ? L.y.px_lo : L.y.to_px(std::clamp(0.0, L.y.lo, L.y.hi));
      for (std::size_t i = 0; i < n; ++i) {
        if (!ok[i]) continue;
        const double xa = L.x.to_px(s.x[i] - 0.5 * plot.bar_width), xb = L.x.to_px(s.x[i] + 0.5 * plot.bar_width);
        if (!std::isfinite(xa) || !std::isfinite(xb)) continue;
        Box b{std::min(xa, xb), std::min(base, pts[i].y), std::max(xa, xb), std::max(base, pts[i].y)};
        b = {std::max(b.x0, area.x0), std::max(b.y0, area.y0), std::min(b.x1, area.x1), std::min(b.y1, area.y1)};
        if (b.x1 - b.x0 > 0.005 && b.y1 - b.y0 > 0.005) g.bars.push_back(b);
      }
    }
    if (!s.y_err.empty()) {
      for (std::size_t i = 0; i < n; ++i) {
        if (!ok[i] || !std::isfinite(s.y_err[i])) continue;
        const double e = std::fabs(s.y_err[i]);
        double y0 = L.y.to_px(s.y[i] - e), y1 = L.y.to_px(s.y[i] + e);
        if (!std::isfinite(y0)) y0 = L.y.px_lo + 1e4;  // below a log axis: off the bottom
        if (!std::isfinite(y1)) continue;
        P a{pts[i].x, y0}, b{pts[i].x, y1};
        bool ma = false, mb = false;
        if (!clip_segment(a, b, area, ma, mb)) continue;
        g.errs.push_back({a, b});
        if (!ma) g.caps.push_back(a);
        if (!mb) g.caps.push_back(b);
      }
    }
    if (s.style == St::Points || s.style == St::LinePoints) {
      std::set<std::pair<long long, long long>> seen;
      const Box in = area.inflated(0.01);
      for (std::size_t i = 0; i < n; ++i) {
        if (!ok[i] || !in.contains(pts[i])) continue;
        if (seen.insert({std::llround(pts[i].x * 100), std::llround(pts[i].y * 100)}).second) g.markers.push_back(pts[i]);
      }
    }
    out.push_back(std::move(g));
  }
  return out;
}

/// True if a legend box at `box` would hide any of the data.
bool hides_data(const Box& box, const std::vector<SeriesGeom>& geo) {
  for (const SeriesGeom& g : geo) {
    const Box wide = box.inflated(0.5 * g.lw + 1.0);
    for (const auto& line : g.lines)
      for (std::size_t i = 1; i < line.size(); ++i)
        if (segment_hits(line[i - 1], line[i], wide)) return true;
    for (const auto& poly : g.bands) {
      for (std::size_t i = 0; i < poly.size(); ++i)
        if (segment_hits(poly[i], poly[(i + 1) % poly.size()], wide)) return true;
      // the box inside the band: its centre inside the polygon (even-odd)
      const P c{0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
      bool in = false;
      for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > c.y) != (poly[j].y > c.y) &&
            c.x < (poly[j].x - poly[i].x) * (c.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
          in = !in;
      if (in) return true;
    }
    for (const Box& b : g.bars)
      if (b.overlaps(wide)) return true;
    for (const auto& e : g.errs)
      if (segment_hits(e.first, e.second, wide)) return true;
    const Box around = box.inflated(g.marker_r + 1.0);
    for (const P& m : g.markers)
      if (around.contains(m)) return true;
  }
  return false;
}

// ------------------------------------------------------------------ SVG text

struct Svg {
  std::string s;
  Svg& operator<<(const std::string& t) { return s += t, *this; }
  Svg& operator<<(const char* t) { return s += t, *this; }
  Svg& n(double v) { return append_coord(s, v), *this; }
};

/// A path "d" of polylines: absolute move, then relative lines between the
/// rounded points (so the rounding never drifts).
std::string path_data(const std::vector<std::vector<P>>& lines, bool close) {
  std::string d;
  for (const auto& line : lines) {
    long long px = 0, py = 0;
    bool first = true;
    for (const P& p : line) {
      const long long x = std::llround(std::fmax(-1e12, std::fmin(1e12, p.x)) * 100.0);
      const long long y = std::llround(std::fmax(-1e12, std::fmin(1e12, p.y)) * 100.0);
      if (first) {
        d += 'M';
        detail::append_hundredths(d, x);
        d += ' ';
        detail::append_hundredths(d, y);
        d += 'l';
        first = false;
      } else {
        if (x == px && y == py) continue;
        const long long dx = x - px, dy = y - py;
        if (d.back() != 'l' && dx >= 0) d += ' ';
        detail::append_hundredths(d, dx);
        if (dy >= 0) d += ' ';
        detail::append_hundredths(d, dy);
      }
      px = x, py = y;
    }
    if (d.back() == 'l') d.pop_back();
    if (close) d += 'z';
  }
  return d;
}

std::string dash(double lw) { return coord(std::max(5.0, 3.5 * lw)) + " " + coord(std::max(3.5, 2.3 * lw)); }

/// A colour mixed with white (bar fill).
std::string lighter(const std::string& c, double white) {
  static const char* hex = "0123456789abcdef";
  std::string out = "#";
  for (int i = 0; i < 3; ++i) {
    const int v = std::stoi(c.substr(1 + 2 * i, 2), nullptr, 16);
    const int m = int(std::lround(v + (255 - v) * white));
    out += hex[m / 16], out += hex[m % 16];
  }
  return out;
}

bool filled_marker(int pt) { return pt == 0 || (pt >= 5 && pt % 2 == 1); }
bool stroked_marker(int pt) { return pt >= 1 && pt <= 3; }

/// Path data of one marker at p, half-size r.
void marker_path(std::string& d, int pt, const P& p, double r) {
  const auto mv = [&](double x, double y) {
    d += 'M';
    append_coord(d, x);
    d += ' ';
    append_coord(d, y);
  };
  const auto rel = [&](char c, std::initializer_list<double> v) {
    d += c;
    bool first = true;
    for (double x : v) {
      if (!first && x >= 0) d += ' ';
      append_coord(d, x);
      first = false;
    }
  };
  const double k = 1.33 * r;
  switch (pt) {
    case 1:  // plus
      mv(p.x - r, p.y), rel('h', {2 * r}), mv(p.x, p.y - r), rel('v', {2 * r});
      break;
    case 2:  // cross
      mv(p.x - r, p.y - r), rel('l', {2 * r, 2 * r}), mv(p.x + r, p.y - r), rel('l', {-2 * r, 2 * r});
      break;
    case 3:  // star
      mv(p.x - r, p.y), rel('h', {2 * r}), mv(p.x, p.y - r), rel('v', {2 * r});
      mv(p.x - r, p.y - r), rel('l', {2 * r, 2 * r}), mv(p.x + r, p.y - r), rel('l', {-2 * r, 2 * r});
      break;
    case 4: case 5:  // square
      mv(p.x - r, p.y - r), rel('h', {2 * r}), rel('v', {2 * r}), rel('h', {-2 * r}), d += 'z';
      break;
    case 8: case 9:  // triangle
      mv(p.x, p.y - k), rel('l', {k, 2 * r}), rel('h', {-2 * k}), d += 'z';
      break;
    case 10: case 11:  // inverted triangle
      mv(p.x, p.y + k), rel('l', {k, -2 * r}), rel('h', {-2 * k}), d += 'z';
      break;
    case 12: case 13:  // diamond
      mv(p.x, p.y - k), rel('l', {k, k}), rel('l', {-k, k}), rel('l', {-k, -k}), d += 'z';
      break;
    case 14: case 15:  // pentagon
      mv(p.x, p.y - k), rel('l', {1.265 * r, 0.919 * r}), rel('l', {-0.483 * r, 1.478 * r}), rel('h', {-1.564 * r}),
          rel('l', {-0.483 * r, -1.478 * r}), d += 'z';
      break;
    default: {  // 0 dot, 6/7 circle
      const double rr = pt == 0 ? std::max(1.0, 0.35 * r) : r;
      mv(p.x - rr, p.y), rel('a', {rr, rr, 0, 1, 0, 2 * rr, 0}), rel('a', {rr, rr, 0, 1, 0, -2 * rr, 0}), d += 'z';
    }
  }
}

void write_markers(Svg& svg, int pt, const std::vector<P>& pts, double r, const std::string& colour, double lw) {
  if (pts.empty()) return;
  std::string d;
  for (const P& p : pts) marker_path(d, pt, p, r);
  if (filled_marker(pt))
    svg << "<path fill=\"" << colour << "\" stroke=\"#fff\" stroke-width=\"0.5\" d=\"" << d << "\"/>\n";
  else
    svg << "<path fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << coord(stroked_marker(pt) ? std::max(1.2, lw) : 1.0)
        << "\" d=\"" << d << "\"/>\n";
}

void write_line_attrs(Svg& svg, const PlotSeries& s, const SeriesGeom& g) {
  svg << "fill=\"none\" stroke=\"" << g.colour << "\" stroke-width=\"" << coord(g.lw) << "\"";
  if (s.style == St::Dashed) svg << " stroke-dasharray=\"" << dash(g.lw) << "\"";
  svg << " stroke-linejoin=\"round\"";
}

void write_series(Svg& svg, const PlotSeries& s, const SeriesGeom& g, double fs) {
  for (const auto& poly : g.bands)
    svg << "<path fill=\"" << g.colour << "\" fill-opacity=\"0.25\" d=\"" << path_data({poly}, true) << "\"/>\n";
  if (!g.bars.empty()) {
    svg << "<g fill=\"" << lighter(g.colour, 0.4) << "\" stroke=\"" << g.colour << "\" stroke-width=\"0.8\">\n";
    for (const Box& b : g.bars)
      svg << "<rect x=\"" << coord(b.x0) << "\" y=\"" << coord(b.y0) << "\" width=\"" << coord(b.x1 - b.x0)
          << "\" height=\"" << coord(b.y1 - b.y0) << "\"/>\n";
    svg << "</g>\n";
  }
  if (!g.lines.empty()) {
    svg << "<path ";
    write_line_attrs(svg, s, g);
    svg << " d=\"" << path_data(g.lines, false) << "\"/>\n";
  }
  if (!g.errs.empty()) {
    std::vector<std::vector<P>> segs;
    const double c = std::max(2.5, 0.3 * fs);
    for (const auto& e : g.errs) segs.push_back({e.first, e.second});
    for (const P& p : g.caps) segs.push_back({{p.x - c, p.y}, {p.x + c, p.y}});
    svg << "<path fill=\"none\" stroke=\"" << g.colour << "\" stroke-width=\"" << coord(base_width(fs) * 0.8)
        << "\" d=\"" << path_data(segs, false) << "\"/>\n";
  }
  if (s.style == St::Points || s.style == St::LinePoints) write_markers(svg, s.point_type, g.markers, g.marker_r, g.colour, g.lw);
}

void write_key(Svg& svg, const Plot& plot, const FrameLayout& f, const std::vector<SeriesGeom>& geo) {
  using M = detail::KeyMetrics;
  const auto& k = f.key;
  if (k.spec.place == KeyPlace::None || k.entries.empty()) return;
  const double fs = f.fs;
  svg << "<g>\n";
  if (k.spec.place == KeyPlace::Inside)
    svg << "<rect x=\"" << coord(k.x) << "\" y=\"" << coord(k.y) << "\" width=\"" << coord(k.w) << "\" height=\""
        << coord(k.h) << "\" fill=\"#fff\" fill-opacity=\"0.9\" stroke=\"#bbb\" stroke-width=\"0.6\"/>\n";
  double cx = k.x + M::inner * fs;
  for (std::size_t c = 0; c < k.columns.size(); ++c) {
    double y = k.y + M::inner * fs;
    for (std::size_t ei : k.columns[c]) {
      const detail::KeyEntry& e = k.entries[ei];
      const PlotSeries& s = plot.series[e.series];
      const SeriesGeom& g = geo[e.series];
      const double yc = y + 0.5 * M::line * fs, x0 = cx, x1 = cx + M::sample * fs, xm = 0.5 * (x0 + x1);
      switch (s.style) {
        case St::Band:
          svg << "<rect x=\"" << coord(x0) << "\" y=\"" << coord(yc - 0.4 * fs) << "\" width=\"" << coord(x1 - x0)
              << "\" height=\"" << coord(0.8 * fs) << "\" fill=\"" << g.colour << "\" fill-opacity=\"0.25\"/>\n";
          break;
        case St::Bars:
          svg << "<rect x=\"" << coord(x0 + 0.3 * fs) << "\" y=\"" << coord(yc - 0.4 * fs) << "\" width=\""
              << coord(x1 - x0 - 0.6 * fs) << "\" height=\"" << coord(0.8 * fs) << "\" fill=\"" << lighter(g.colour, 0.4)
              << "\" stroke=\"" << g.colour << "\" stroke-width=\"0.8\"/>\n";
          break;
        case St::Points:
          break;
        default:
          svg << "<path ";
          write_line_attrs(svg, s, g);
          svg << " d=\"" << path_data({{{x0, yc}, {x1, yc}}}, false) << "\"/>\n";
      }
      if (!s.y_err.empty())
        svg << "<path stroke=\"" << g.colour << "\" stroke-width=\"" << coord(base_width(fs) * 0.8) << "\" d=\""
            << path_data({{{xm, yc - 0.45 * fs}, {xm, yc + 0.45 * fs}}}, false) << "\"/>\n";
      if (s.style == St::Points || s.style == St::LinePoints)
        write_markers(svg, s.point_type, {{xm, yc}}, std::min(g.marker_r, 0.55 * fs), g.colour, g.lw);
      const double tx = x1 + M::gap * fs;
      for (std::size_t li = 0; li < e.lines.size(); ++li)
        svg << "<text x=\"" << coord(tx) << "\" y=\"" << coord(yc + 0.36 * fs + double(li) * M::line * fs) << "\">"
            << svg_escape(e.lines[li]) << "</text>\n";
      y += e.height;
    }
    cx += k.column_width[c] + M::column_gap * fs;
  }
  svg << "</g>\n";
}

/// The final layout and geometry: an inside legend moved to a free corner,
/// or below the plot.
std::pair<FrameLayout, std::vector<SeriesGeom>> settle(const Plot& plot) {
  FrameLayout f = detail::frame_layout(plot);
  std::vector<SeriesGeom> geo = geometry(plot, f);
  if (f.key.spec.place != KeyPlace::Inside) return {f, geo};
  const PlotLayout& L = f.pub;
  const bool fits = f.key.w <= (L.right - L.left) - f.fs && f.key.h <= (L.bottom - L.top) - f.fs;
  if (fits) {
    std::vector<std::pair<char, char>> corners = {{f.key.spec.h, f.key.spec.v}, {'r', 't'}, {'l', 't'}, {'r', 'b'}, {'l', 'b'}};
    for (const auto& [h, v] : corners) {
      detail::place_inside_key(f, h, v);
      const Box box{f.key.x, f.key.y, f.key.x + f.key.w, f.key.y + f.key.h};
      if (!hides_data(box, geo)) return {f, geo};
    }
  }
  f = detail::frame_layout(plot, true);
  geo = geometry(plot, f);
  return {f, geo};
}

}  // namespace

void Plot::validate() const {
  const std::string what = "plot '" + title + "': ";
  if (width < 100 || width > 4000 || height < 100 || height > 4000)
    throw InputError(what + "width and height must be in [100, 4000] px");
  if (font_size < 6 || font_size > 20) throw InputError(what + "font_size must be in [6, 20]");
  detail::parse_key(key, title);
  if (series.empty()) throw InputError(what + "no series");
  if (!(bar_width > 0.0) || !std::isfinite(bar_width)) throw InputError(what + "bar_width must be finite and > 0");
  for (const double v : {x_min, x_max, y_min, y_max})
    if (!std::isfinite(v)) throw InputError(what + "the axis ranges must be finite");
  if (log_x && x_min < x_max && !(x_min > 0.0)) throw InputError(what + "a log x axis needs x_min > 0");
  if (log_y && y_min < y_max && !(y_min > 0.0)) throw InputError(what + "a log y axis needs y_min > 0");
  for (const auto& c : x_tic_labels)
    if (!std::isfinite(c.first)) throw InputError(what + "category label '" + c.second + "' at a non-finite x");
  for (const auto& s : series) {
    const std::string ws = what + "series '" + s.name + "': ";
    if (s.x.empty() || s.x.size() != s.y.size()) throw InputError(ws + "x and y must be non-empty and of equal length");
    if (s.style == PlotSeries::Style::Band && s.y_low.size() != s.y.size())
      throw InputError(ws + "a band needs y_low as long as y");
    if (!s.y_err.empty() && s.y_err.size() != s.y.size()) throw InputError(ws + "y_err must be empty or as long as y");
    if (!s.color.empty() && !is_colour(s.color)) throw InputError(ws + "color must be \"#rrggbb\"");
    if (s.point_type < 0 || s.point_type > 15) throw InputError(ws + "point_type must be in [0, 15]");
    if (!(s.point_size > 0.0 && s.point_size <= 10.0)) throw InputError(ws + "point_size must be in (0, 10]");
    bool any_positive = false;
    for (std::size_t i = 0; i < s.x.size(); ++i)
      any_positive = any_positive || ((!log_x || s.x[i] > 0) && (!log_y || s.y[i] > 0));
    if ((log_x || log_y) && !any_positive) throw InputError(ws + "no point with positive coordinates on a log axis");
  }
}

PlotLayout plot_layout(const Plot& plot) { return settle(plot).first.pub; }

std::string render_svg(const Plot& plot) {
  // A tick's number in the plot's convention: the decimal comma of an Italian relazione (issue 28).
  const auto number_label = [&](std::string label) {
    if (plot.decimal_comma)
      for (char& c : label)
        if (c == '.') c = ',';
    return label;
  };
  const auto [f, geo] = settle(plot);
  const PlotLayout& L = f.pub;
  const double fs = f.fs, W = L.width, H = L.height;
  Svg svg;
  svg.s.reserve(16384);
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ";
  svg.n(W) << " ";
  svg.n(H) << "\" font-family=\"sans-serif\" font-size=\"" << coord(fs) << "\">\n";
  svg << "<title>" << svg_escape(plot.title) << "</title>\n";
  svg << "<rect width=\"" << coord(W) << "\" height=\"" << coord(H) << "\" fill=\"#fff\"/>\n";

  // Grid: major ticks (and a darker line at 0 inside a linear range), minor ticks of log axes lighter.
  {
    std::vector<std::vector<P>> major, minor, zero;
    const auto add = [&](const PlotAxis& a, bool vertical_lines, bool skip) {
      if (skip) return;
      for (const AxisTick& t : a.ticks) {
        const double p = a.to_px(t.value);
        if (!std::isfinite(p)) continue;
        std::vector<P> seg = vertical_lines ? std::vector<P>{{p, L.top}, {p, L.bottom}} : std::vector<P>{{L.left, p}, {L.right, p}};
        const bool at_zero = !a.log && t.value == 0.0 && a.lo < 0.0 && a.hi > 0.0;
        (at_zero ? zero : t.label.empty() ? minor : major).push_back(seg);
      }
    };
    add(L.x, true, f.categories);
    add(L.y, false, false);
    if (!minor.empty()) svg << "<path stroke=\"#ececec\" stroke-width=\"0.5\" d=\"" << path_data(minor, false) << "\"/>\n";
    if (!major.empty()) svg << "<path stroke=\"#d4d4d4\" stroke-width=\"0.6\" d=\"" << path_data(major, false) << "\"/>\n";
    if (!zero.empty()) svg << "<path stroke=\"#8c8c8c\" stroke-width=\"0.8\" d=\"" << path_data(zero, false) << "\"/>\n";
  }

  for (std::size_t i = 0; i < plot.series.size(); ++i) write_series(svg, plot.series[i], geo[i], fs);

  // Frame and tick marks (inward, on all four sides).
  svg << "<rect x=\"" << coord(L.left) << "\" y=\"" << coord(L.top) << "\" width=\"" << coord(L.right - L.left)
      << "\" height=\"" << coord(L.bottom - L.top) << "\" fill=\"none\" stroke=\"#000\"/>\n";
  {
    std::vector<std::vector<P>> ticks;
    for (const AxisTick& t : L.x.ticks) {
      const double p = L.x.to_px(t.value), len = (t.label.empty() ? 0.22 : 0.4) * fs;
      if (!std::isfinite(p)) continue;
      ticks.push_back({{p, L.bottom}, {p, L.bottom - len}});
      ticks.push_back({{p, L.top}, {p, L.top + len}});
    }
    for (const AxisTick& t : L.y.ticks) {
      const double p = L.y.to_px(t.value), len = (t.label.empty() ? 0.22 : 0.4) * fs;
      if (!std::isfinite(p)) continue;
      ticks.push_back({{L.left, p}, {L.left + len, p}});
      ticks.push_back({{L.right, p}, {L.right - len, p}});
    }
    if (!ticks.empty()) svg << "<path stroke=\"#000\" d=\"" << path_data(ticks, false) << "\"/>\n";
  }

  // Tick labels.
  if (f.rotate) {
    svg << "<g text-anchor=\"end\">\n";
    std::size_t i = 0;
    for (const AxisTick& t : L.x.ticks) {
      if (t.label.empty() || (i++ % f.category_stride) != 0) continue;
      // Lines of a long name stacked under the first in the rotated frame.
      const std::vector<std::string> lines = detail::category_lines(t.label, fs, f.wrap_categories);
      const double x = L.x.to_px(t.value) + 0.3 * fs, y = L.bottom + 0.45 * fs + 0.75 * fs;
      svg << "<text transform=\"rotate(-30 " << coord(x) << " " << coord(y) << ")\" x=\"" << coord(x) << "\" y=\""
          << coord(y) << "\">";
      for (std::size_t li = 0; li < lines.size(); ++li) {
        if (lines.size() == 1) svg << svg_escape(lines[li]);
        else
          svg << (li ? "<tspan x=\"" + coord(x) + "\" dy=\"" + coord(1.15 * fs) + "\">" : std::string("<tspan>"))
              << svg_escape(lines[li]) << "</tspan>";
      }
      svg << "</text>\n";
    }
    svg << "</g>\n";
  } else {
    svg << "<g text-anchor=\"middle\">\n";
    for (const AxisTick& t : L.x.ticks)
      if (!t.label.empty())
        svg << "<text x=\"" << coord(L.x.to_px(t.value)) << "\" y=\"" << coord(L.bottom + 0.45 * fs + 0.8 * fs) << "\">"
            << svg_escape(number_label(t.label)) << "</text>\n";
    svg << "</g>\n";
  }
  svg << "<g text-anchor=\"end\">\n";
  for (const AxisTick& t : L.y.ticks)
    if (!t.label.empty())
      svg << "<text x=\"" << coord(L.left - 0.5 * fs) << "\" y=\"" << coord(L.y.to_px(t.value) + 0.36 * fs) << "\">"
          << svg_escape(number_label(t.label)) << "</text>\n";
  svg << "</g>\n";

  // Axis labels and title.
  svg << "<g text-anchor=\"middle\">\n";
  for (std::size_t i = 0; i < f.x_label_lines.size(); ++i)
    svg << "<text x=\"" << coord(0.5 * (L.left + L.right)) << "\" y=\"" << coord(f.x_label_y + 1.25 * fs * double(i))
        << "\">" << svg_escape(f.x_label_lines[i]) << "</text>\n";
  const double ylx0 = (f.key.spec.place == KeyPlace::OutsideLeft ? f.key.x + f.key.w + 0.8 * fs : f.pad) + 0.95 * fs;
  for (std::size_t i = 0; i < f.y_label_lines.size(); ++i) {
    const double x = ylx0 + 1.25 * fs * double(i), y = 0.5 * (L.top + L.bottom);
    svg << "<text transform=\"rotate(-90 " << coord(x) << " " << coord(y) << ")\" x=\"" << coord(x) << "\" y=\""
        << coord(y) << "\">" << svg_escape(f.y_label_lines[i]) << "</text>\n";
  }
  for (std::size_t i = 0; i < f.title_lines.size(); ++i)
    svg << "<text x=\"" << coord(0.5 * W) << "\" y=\"" << coord(f.pad + 0.95 * f.title_fs + 1.25 * f.title_fs * double(i))
        << "\" font-size=\"" << coord(f.title_fs) << "\">" << svg_escape(f.title_lines[i]) << "</text>\n";
  svg << "</g>\n";

  write_key(svg, plot, f, geo);
  svg << "</svg>\n";
  return std::move(svg.s);
}

}  // namespace assess

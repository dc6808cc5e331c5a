// mechanism_drawing.cpp: SVG drawing of a chain of blocks, written directly
// (no gnuplot: polygons, arrows, dimension lines and labels at exact
// positions). The labels are placed last by a small deterministic placer
// (Placer below) so that no two labels overlap; the viewBox is the extent of
// everything drawn.
#include "assess/report/mechanism_drawing.hpp"

#include "report/xml_escape.hpp"

#include "assess/support/units.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace assess {

namespace {

using detail::xml_escape;
using V2 = Eigen::Vector2d;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The drawing's numbers in its language: the decimal comma in Italian (issue
// 28), set by mechanism_svg for the drawing it makes (one per thread at a time).
thread_local bool decimal_comma = false;

// A value printed in a label (the drawing's language); coordinates use f1.
std::string number(const char* layout, double v) {
  char b[32];
  std::snprintf(b, sizeof b, layout, v);
  if (decimal_comma)
    for (char* p = b; *p; ++p)
      if (*p == '.') *p = ',';
  return b;
}

std::string f1(double v) {  // an SVG coordinate: always the decimal point
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

std::string d2(double v) { return number("%.2f", v); }  // a dimension value: m, 2 decimals, no unit (the legend says "m")

std::string kn(double newton) { return number("%.2f kN", newton / units::kN); }

std::string m2(double v) { return number("%.2f m", v); }

// Strings of the drawing only (kept here, both languages).
std::string tr(Lang lang, const char* it, const char* en) { return lang == Lang::it ? it : en; }

// ------------------------------------------------------------------ text boxes

enum class Anchor { Start, Middle, End };

const char* anchor_name(Anchor a) { return a == Anchor::Start ? "start" : a == Anchor::Middle ? "middle" : "end"; }

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

bool overlap(const Box& a, const Box& b, double pad) {
  return a.x0 < b.x1 + pad && b.x0 < a.x1 + pad && a.y0 < b.y1 + pad && b.y0 < a.y1 + pad;
}

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return n;
}

// The estimate of a label's box (px) used by the placer and by the test
// (tests/unit/mechanism_drawing.cpp): 0.6 em per character (UTF-8 code point;
// DejaVu Sans, Chromium's sans-serif here, measures 0.50-0.57 em per
// character on the drawing's strings), from 0.95 em above the baseline to
// 0.25 em below, placed by text-anchor.
Box text_box(double x, double y, double fs, Anchor a, const std::string& t) {
  const double w = 0.6 * fs * double(code_points(t));
  const double x0 = a == Anchor::Start ? x : a == Anchor::Middle ? x - 0.5 * w : x - w;
  return {x0, y - 0.95 * fs, x0 + w, y + 0.25 * fs};
}

// Liang-Barsky: does the segment meet the box?
bool segment_hits(double x1, double y1, double x2, double y2, const Box& b) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = x2 - x1, dy = y2 - y1;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x1 - b.x0, b.x1 - x1, y1 - b.y0, b.y1 - y1};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0.0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
  }
  return true;
}

// --------------------------------------------------------------- label placer

// A label: its text, size and style, the point it belongs to (anchor), and its
// preferred positions in order.
struct Cand {
  double x, y;
  Anchor a;
};

struct Placed {
  std::string text;
  double x, y, fs;
  Anchor a;
  std::string attrs;
  Box box;
};

// Deterministic greedy placer. Each label takes the first of its candidate
// positions (its preferred ones, then rings further and further out around
// its anchor) whose box is free of every label already placed (2 px apart)
// and of the drawing (lines, arrows, symbols, blocks); failing that, the first
// one free of the labels and the lines; failing that, the first one free of
// the labels. A label placed more than 12 px from its anchor gets a leader
// line to it, which crosses no label placed before it.
class Placer {
 public:
  void segment(double x1, double y1, double x2, double y2) { segs_.push_back({x1, y1, x2, y2}); }
  void mark(const Box& b) { marks_.push_back(b); }
  void polygon(std::vector<std::array<double, 2>> p) {
    Box b{kInf, kInf, -kInf, -kInf};
    for (const auto& v : p) b = {std::min(b.x0, v[0]), std::min(b.y0, v[1]), std::max(b.x1, v[0]), std::max(b.y1, v[1])};
    polys_.push_back(std::move(p));
    poly_boxes_.push_back(b);
  }

  void place(const std::string& text, double fs, const std::string& attrs, double ax, double ay,
             std::vector<Cand> prefs) {
    const std::size_t n_prefs = prefs.size();
    // Rings around the anchor: 16 directions, 12 px apart, the box centred on the ring.
    const double w = 0.6 * fs * double(code_points(text));
    for (int ring = 1; ring <= 40; ++ring) {
      const double d = 6.0 + 12.0 * ring;
      for (int k = 0; k < 16; ++k) {
        const double ang = k * 3.14159265358979323846 / 8.0;
        const double cx = ax + std::cos(ang) * (d + 0.5 * w), cy = ay - std::sin(ang) * (d + 0.6 * fs);
        prefs.push_back({cx, cy + 0.35 * fs, Anchor::Middle});
      }
    }
    // Passes: free of everything (labels, lines, block outlines) among the
    // preferred positions, then the first 4 rings; then free of labels and
    // lines among those; then the far rings likewise; last, anything free of
    // labels.
    const std::size_t near_end = std::min(prefs.size(), n_prefs + 4 * 16);
    const std::size_t ranges[3][2] = {{0, n_prefs}, {n_prefs, near_end}, {near_end, prefs.size()}};
    std::size_t chosen = prefs.size();
    static const int order[6][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {2, 1}};  // (range, tier)
    for (int pass = 0; pass < 7 && chosen == prefs.size(); ++pass) {
      const int tier = pass == 6 ? 2 : order[pass][1];
      const std::size_t lo = pass == 6 ? 0 : ranges[order[pass][0]][0];
      const std::size_t hi = pass == 6 ? prefs.size() : ranges[order[pass][0]][1];
      for (std::size_t i = lo; i < hi; ++i) {
        const Box b = text_box(prefs[i].x, prefs[i].y, fs, prefs[i].a, text);
        if (hits_labels(b)) continue;
        if (tier < 2 && hits_lines(b)) continue;
        if (tier < 1 && hits_shapes(b)) continue;
        if (tier < 2 && leader_hits_labels(ax, ay, b)) continue;
        chosen = i;
        break;
      }
    }
    if (chosen == prefs.size()) {  // never with 40 rings; below everything, to be safe
      double y = 0.0;
      for (const Placed& p : labels_) y = std::max(y, p.box.y1);
      prefs.push_back({ax, y + 1.3 * fs, Anchor::Middle});
    }
    const Cand c = prefs[chosen];
    const Box b = text_box(c.x, c.y, fs, c.a, text);
    labels_.push_back({text, c.x, c.y, fs, c.a, attrs, b});
    double px = 0.0, py = 0.0;
    if (leader_to(ax, ay, b, px, py)) leaders_.push_back({ax, ay, px, py});
  }

  const std::vector<Placed>& labels() const { return labels_; }
  const std::vector<std::array<double, 4>>& leaders() const { return leaders_; }

 private:
  // The leader from the anchor to the nearest point of the box, if the box is
  // more than 12 px away.
  static bool leader_to(double ax, double ay, const Box& b, double& px, double& py) {
    px = std::clamp(ax, b.x0, b.x1), py = std::clamp(ay, b.y0, b.y1);
    return std::hypot(px - ax, py - ay) > 12.0;
  }
  bool leader_hits_labels(double ax, double ay, const Box& b) const {
    double px = 0.0, py = 0.0;
    if (!leader_to(ax, ay, b, px, py)) return false;
    for (const Placed& p : labels_)
      if (segment_hits(ax, ay, px, py, {p.box.x0 - 1, p.box.y0 - 1, p.box.x1 + 1, p.box.y1 + 1})) return true;
    return false;
  }
  bool hits_labels(const Box& b) const {
    for (const Placed& p : labels_)
      if (overlap(b, p.box, 2.0)) return true;
    return false;
  }
  bool hits_lines(const Box& b) const {
    const Box g{b.x0 - 1.0, b.y0 - 1.0, b.x1 + 1.0, b.y1 + 1.0};
    for (const auto& s : segs_)
      if (segment_hits(s[0], s[1], s[2], s[3], g)) return true;
    for (const Box& m : marks_)
      if (overlap(b, m, 1.0)) return true;
    for (const auto& l : leaders_)
      if (segment_hits(l[0], l[1], l[2], l[3], g)) return true;
    return false;
  }
  bool hits_shapes(const Box& b) const {
    for (std::size_t i = 0; i < polys_.size(); ++i) {
      if (!overlap(b, poly_boxes_[i], 1.0)) continue;
      const auto& P = polys_[i];  // text on a block is legible; text across its outline is not
      for (std::size_t k = 0; k < P.size(); ++k) {
        const auto& p = P[k];
        const auto& q = P[(k + 1) % P.size()];
        if (segment_hits(p[0], p[1], q[0], q[1], b)) return true;
      }
    }
    return false;
  }

  std::vector<std::array<double, 4>> segs_;
  std::vector<Box> marks_;
  std::vector<std::vector<std::array<double, 2>>> polys_;
  std::vector<Box> poly_boxes_;
  std::vector<Placed> labels_;
  std::vector<std::array<double, 4>> leaders_;
};

// ------------------------------------------------------------ block geometry

// x intervals of the polygon on the horizontal line z (z not a vertex level).
std::vector<std::pair<double, double>> cut_h(const std::vector<V2>& P, double z) {
  std::vector<double> xs;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const V2& a = P[i];
    const V2& b = P[(i + 1) % P.size()];
    if ((a.y() > z) != (b.y() > z)) xs.push_back(a.x() + (z - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
  }
  std::sort(xs.begin(), xs.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2) out.push_back({xs[i], xs[i + 1]});
  return out;
}

// z intervals of the polygon on the vertical line x (x not a vertex abscissa).
std::vector<std::pair<double, double>> cut_v(const std::vector<V2>& P, double x) {
  std::vector<double> zs;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const V2& a = P[i];
    const V2& b = P[(i + 1) % P.size()];
    if ((a.x() > x) != (b.x() > x)) zs.push_back(a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x()));
  }
  std::sort(zs.begin(), zs.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < zs.size(); i += 2) out.push_back({zs[i], zs[i + 1]});
  return out;
}

struct Geometry {
  const std::vector<Block>& blocks;
  double eps;  // m, a small fraction of the chain's size

  // Highest point of the blocks on the vertical through x (-inf if none).
  double top_at(double x) const {
    double t = -kInf;
    for (const Block& b : blocks)
      for (double xx : {x - eps, x + eps})
        for (const auto& iv : cut_v(b.polygon, xx)) t = std::max(t, iv.second);
    return t;
  }
  double bottom_at(double x) const {
    double t = kInf;
    for (const Block& b : blocks)
      for (double xx : {x - eps, x + eps})
        for (const auto& iv : cut_v(b.polygon, xx)) t = std::min(t, iv.first);
    return t;
  }
  // Rightmost / leftmost point of the blocks on the horizontal z (+-inf if none).
  double right_at(double z) const {
    double r = -kInf;
    for (const Block& b : blocks)
      for (double zz : {z - eps, z + eps})
        for (const auto& iv : cut_h(b.polygon, zz)) r = std::max(r, iv.second);
    return r;
  }
  double left_at(double z) const {
    double r = kInf;
    for (const Block& b : blocks)
      for (double zz : {z - eps, z + eps})
        for (const auto& iv : cut_h(b.polygon, zz)) r = std::min(r, iv.first);
    return r;
  }
  // True if (x, z) lies strictly inside a block (farther than eps from its boundary).
  bool inside(double x, double z) const {
    for (const Block& b : blocks) {
      for (const auto& iv : cut_h(b.polygon, z))
        if (x > iv.first + eps && x < iv.second - eps) {
          for (const auto& jv : cut_v(b.polygon, x))
            if (z > jv.first + eps && z < jv.second - eps) return true;
        }
    }
    return false;
  }
  // The vertical from (x, z0) to (x, z1) passes through no block's interior.
  bool vertical_free(double x, double z0, double z1) const {
    for (int k = 1; k < 64; ++k)
      if (inside(x, z0 + (z1 - z0) * k / 64.0)) return false;
    return true;
  }
};


// ---------------------------------------------------------------- canvas
// The styles of dimension and extension lines.
const char* const dim_style = "class=\"dim-line\" stroke=\"#333\" stroke-width=\"0.7\"";
const char* const ext_style = "class=\"ext-line\" stroke=\"#666\" stroke-width=\"0.5\"";

// A label to place once everything is drawn, with its preferred positions.
struct LabelReq {
  std::string text;
  double fs;
  std::string attrs;
  double ax, ay;
  std::vector<Cand> prefs;
};

// What the section and the plan drawings share: the graphics drawn so far,
// the label placer (every line and mark an obstacle), the extent of
// everything drawn (px), the labels to place once all is drawn (dimension
// values first, so that they stay by their lines), and the SVG document.
struct Canvas {
  std::string o;  // graphics
  Placer placer;
  Box ext{kInf, kInf, -kInf, -kInf};
  std::vector<LabelReq> dim_labels, labels;

  void grow(double x, double y) {
    ext = {std::min(ext.x0, x), std::min(ext.y0, y), std::max(ext.x1, x), std::max(ext.y1, y)};
  }
  void line(double x1, double y1, double x2, double y2, const std::string& style, bool obstacle = true) {
    o += "<line x1=\"" + f1(x1) + "\" y1=\"" + f1(y1) + "\" x2=\"" + f1(x2) + "\" y2=\"" + f1(y2) + "\" " + style +
         "/>\n";
    grow(x1, y1), grow(x2, y2);
    if (obstacle) placer.segment(x1, y1, x2, y2);
  }
  void circle(double x, double y, double rad, const std::string& style) {
    o += "<circle cx=\"" + f1(x) + "\" cy=\"" + f1(y) + "\" r=\"" + f1(rad) + "\" " + style + "/>\n";
    grow(x - rad, y - rad), grow(x + rad, y + rad);
    placer.mark({x - rad, y - rad, x + rad, y + rad});
  }
  // The head of an arrow drawn with a marker (7 stroke widths long and wide)
  // ending at (x2, y2): an obstacle for the labels.
  void head(double x1, double y1, double x2, double y2, double stroke_width) {
    const double n = std::hypot(x2 - x1, y2 - y1), h = 3.5 * stroke_width;
    if (!(n > 0.0)) return;
    const double cx = x2 - (x2 - x1) / n * h, cy = y2 - (y2 - y1) / n * h;
    placer.mark({cx - h, cy - h, cx + h, cy + h});
    grow(cx - h, cy - h), grow(cx + h, cy + h);
  }
  // Architectural ticks (45 degree strokes) at the ends of dimension lines.
  void tick(double x, double y) {
    line(x - 3.5, y + 3.5, x + 3.5, y - 3.5, "class=\"dim-line\" stroke=\"#333\" stroke-width=\"1\"");
  }
  // Places the labels asked for; returns the baseline of a legend under everything.
  double place_labels() {
    for (const LabelReq& q : dim_labels) placer.place(q.text, q.fs, q.attrs, q.ax, q.ay, q.prefs);
    for (const LabelReq& q : labels) placer.place(q.text, q.fs, q.attrs, q.ax, q.ay, q.prefs);
    double ly = ext.y1;
    for (const Placed& p : placer.labels()) ly = std::max(ly, p.box.y1);
    return ly + 16;
  }
  // The legend's lines from (x, y) down (their anchor is their position: no leader).
  void place_legend(const std::vector<std::string>& legend, double x, double y) {
    for (const std::string& lt : legend) {
      placer.place(lt, 10, "fill=\"#444\" font-style=\"italic\"", x, y, {{x, y, Anchor::Start}});
      y += 14;
    }
  }
  // An arrow head for marker-end (7 stroke widths long and wide).
  static std::string marker(const char* id, const char* fill, const char* orient = "auto") {
    return std::string("<marker id=\"") + id + "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" " +
           "markerHeight=\"7\" orient=\"" + orient + "\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"" + fill +
           "\"/></marker>";
  }
  // The SVG document: the leaders, the placed labels, a viewBox around
  // everything, at least 640 px wide (centred: the report scales the figure
  // to the column's width, 170 mm, so a narrow drawing would grow, text and all).
  std::string document(const std::string& title, const std::string& defs) {
    for (const auto& l : placer.leaders()) line(l[0], l[1], l[2], l[3], "stroke=\"#777\" stroke-width=\"0.6\"", false);
    std::string t;
    for (const Placed& p : placer.labels()) {
      grow(p.box.x0, p.box.y0), grow(p.box.x1, p.box.y1);
      t += "<text x=\"" + f1(p.x) + "\" y=\"" + f1(p.y) + "\" font-size=\"" + f1(p.fs) + "\" text-anchor=\"" +
           anchor_name(p.a) + "\"" + (p.attrs.empty() ? "" : " " + p.attrs) + ">" + xml_escape(p.text) + "</text>\n";
    }
    const double m = 8.0;
    double vx = std::floor(ext.x0 - m), vw = std::ceil(ext.x1 + m) - vx;
    if (vw < 640.0) vx -= std::floor(0.5 * (640.0 - vw)), vw = 640.0;
    const double vy = std::floor(ext.y0 - m), vh = std::ceil(ext.y1 + m) - vy;
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + f1(vx) + " " + f1(vy) + " " + f1(vw) + " " +
           f1(vh) + "\" width=\"" + f1(vw) + "\" height=\"" + f1(vh) +
           "\" font-family=\"sans-serif\" font-size=\"11\">\n<title>" + xml_escape(title) + "</title>\n" + defs + o + t +
           "</svg>\n";
  }
};

long mm(double v) { return std::lround(v * 1000.0); }

// ------------------------------------------------------------------ plan
// Issue 33: a chain drawn in plan (horizontal flexure): the strip along the
// page (u to the right), outward up; the transverse walls at the ends, the
// vertical hinges, the arch's thrust line and its thrust at both supports,
// the ring beam's force, the control point, the seismic action outward.
// Dimensions: the stretches between the hinges and openings (kind "level"),
// the span (kind "total"), the thickness (kind "thickness").
// The plan of a horizontal strip (plan_svg, issue 33): the state its drawing
// steps share, each step one member, in the order plan_svg calls them.
class Plan {
 public:
  Plan(const Chain& chain, const KinematicResult& r, Lang lang, const std::array<double, 4>& box);
  std::string draw();

 private:
  // To scale: along the wall u to the right, outward (x > 0) up.
  double X(double u) const { return 120.0 + s * (u - umin); }
  double Y(double x) const { return 200.0 - sx * x; }
  void draw_blocks();
  void transverse_walls();
  void hinges();
  void loads();
  void control_point();
  void span_dimensions();
  void thickness_dimension();
  void seismic_action();
  std::string legend_and_document();

  const Chain& chain;
  const KinematicResult& r;
  const Lang lang;
  const std::vector<Block>& blocks;
  // The blocks' extent across (x, m) and along (u, m) the wall, the thickness t and span L (m).
  const double xmin, xmax, umin, umax, t, L;
  // The span in at most 520 px, the thickness at least 24 px (exaggerated if thin, said in the legend).
  const double s, sx;
  // The transverse walls at the supports: width and depth drawn (px).
  const double wall_w, wall_d = 70.0;
  Canvas cv;
  std::set<char> symbols;  // of the loads drawn, explained in the legend
};

// The extent of the blocks' polygons: min and max of their first coordinate,
// min and max of their second (m): x and z in elevation, x and u in plan.
std::array<double, 4> block_extent(const std::vector<Block>& blocks) {
  std::array<double, 4> b{kInf, -kInf, kInf, -kInf};
  for (const Block& k : blocks)
    for (const auto& p : k.polygon) {
      b[0] = std::min(b[0], p.x()), b[1] = std::max(b[1], p.x());
      b[2] = std::min(b[2], p.y()), b[3] = std::max(b[3], p.y());
    }
  return b;
}

Plan::Plan(const Chain& chain_, const KinematicResult& r_, Lang lang_, const std::array<double, 4>& box)
    : chain(chain_), r(r_), lang(lang_), blocks(chain_.blocks()), xmin(box[0]), xmax(box[1]), umin(box[2]),
      umax(box[3]), t(std::max(xmax - xmin, 1e-6)), L(std::max(umax - umin, 1e-6)),
      s(std::min(520.0 / L, 160.0 / t)), sx(std::max(s, 24.0 / t)), wall_w(std::max(14.0, s * t)) {}

std::string Plan::draw() {
  draw_blocks();
  transverse_walls();
  hinges();
  loads();
  control_point();
  span_dimensions();
  thickness_dimension();
  seismic_action();
  return legend_and_document();
}

// The strip's blocks.
void Plan::draw_blocks() {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    std::string pts;
    std::vector<std::array<double, 2>> px;
    for (const auto& p : blocks[i].polygon) {
      pts += f1(X(p.y())) + "," + f1(Y(p.x())) + " ";
      px.push_back({X(p.y()), Y(p.x())});
      cv.grow(X(p.y()), Y(p.x()));
    }
    cv.o += "<polygon points=\"" + pts + "\" fill=\"" + (i % 2 ? "#d9cbb5" : "#e6dcc8") +
         "\" stroke=\"#5a4a32\" stroke-width=\"1.2\"/>\n";
    cv.placer.polygon(std::move(px));
  }
}

// The transverse walls at the supports (context, hatched, inward of the strip).
void Plan::transverse_walls() {
  for (int side = 0; side < 2; ++side) {
    const double xa = side == 0 ? X(umin) - wall_w : X(umax), xb = xa + wall_w;
    const double ya = Y(xmax), yb = Y(xmin) + wall_d;
    cv.o += "<rect x=\"" + f1(xa) + "\" y=\"" + f1(ya) + "\" width=\"" + f1(xb - xa) + "\" height=\"" + f1(yb - ya) +
         "\" fill=\"#cfcfcf\" stroke=\"#555\" stroke-width=\"1\"/>\n";
    cv.grow(xa, ya), cv.grow(xb, yb);
    cv.placer.polygon({{xa, ya}, {xb, ya}, {xb, yb}, {xa, yb}});
    for (double hy = ya + 8; hy < yb; hy += 10)
      cv.line(xa, hy, xb, hy - 6, "stroke=\"#888\" stroke-width=\"0.5\"", false);
    cv.labels.push_back({tr(lang, "muro trasversale", "transverse wall"), 10, "fill=\"#444\"", 0.5 * (xa + xb), yb,
                      {{0.5 * (xa + xb), yb + 14, Anchor::Middle}, {side == 0 ? xa - 4 : xb + 4, yb - 4,
                                                                      side == 0 ? Anchor::End : Anchor::Start}}});
  }
}

// Hinges and the thrust line through them.
void Plan::hinges() {
  std::vector<std::array<double, 2>> hinge_px;
  for (const Constraint& c : chain.constraints()) {
    if (c.type == ConstraintType::Hinge) {
      bool middle = true;  // a joint of two segments of one half lies on a face, the middle hinge inside
      for (const Constraint& d : chain.constraints())
        if (&d != &c && d.type == ConstraintType::Hinge && std::fabs(d.point.y() - c.point.y()) < 1e-9) middle = false;
      if (!middle) continue;
    }
    const double Xp = X(c.point.y()), Yp = Y(c.point.x());
    hinge_px.push_back({Xp, Yp});
    cv.circle(Xp, Yp, 4.5, "fill=\"#fff\" stroke=\"#b3001b\" stroke-width=\"1.8\"");
    cv.labels.push_back({msg(lang, "draw.hinge") + " u = " + m2(c.point.y()), 10, "fill=\"#b3001b\"", Xp, Yp,
                      {{Xp, Yp - 9, Anchor::Middle}, {Xp, Yp + 16, Anchor::Middle}, {Xp + 8, Yp - 8, Anchor::Start},
                       {Xp - 8, Yp - 8, Anchor::End}}});
  }
  std::sort(hinge_px.begin(), hinge_px.end());
  for (std::size_t k = 0; k + 1 < hinge_px.size(); ++k)
    cv.line(hinge_px[k][0], hinge_px[k][1], hinge_px[k + 1][0], hinge_px[k + 1][1],
         "stroke=\"#b3001b\" stroke-width=\"1\" stroke-dasharray=\"5 3\"", false);
}

// Loads: the arch's thrust (at both supports), the ring beam's force.
void Plan::loads() {
  for (const Load& l : chain.loads()) {
    if (l.type != LoadType::Force && l.type != LoadType::Tie) continue;
    const double n = l.force.norm();
    if (!(n > 0.0)) continue;
    symbols.insert('S');
    if (std::fabs(l.force.x()) < 1e-12) {  // the thrust, along the wall
      for (int side = 0; side < 2; ++side) {
        const double Xp = X(side == 0 ? umin : umax), Yp = Y(l.point.x());
        const double x1 = side == 0 ? Xp - 46 : Xp + 46;
        cv.line(x1, Yp - 16, Xp + (side == 0 ? 10 : -10), Yp - 16,
             "stroke=\"#8a3ea8\" stroke-width=\"2.2\" marker-end=\"url(#arrowk)\"");
        cv.head(x1, Yp - 16, Xp + (side == 0 ? 10 : -10), Yp - 16, 2.2);
        cv.labels.push_back({"H = " + kn(n), 11, "fill=\"#8a3ea8\"", x1, Yp - 16,
                          {{x1, Yp - 22, side == 0 ? Anchor::Start : Anchor::End},
                           {side == 0 ? x1 - 4 : x1 + 4, Yp - 12, side == 0 ? Anchor::End : Anchor::Start}}});
      }
    } else {  // a force across the wall (ring beam), inward
      const double Xp = X(l.point.y()), Yp = Y(l.point.x());
      cv.line(Xp, Yp - 40, Xp, Yp - 4, "stroke=\"#8a3ea8\" stroke-width=\"2.2\" marker-end=\"url(#arrowk)\"");
      cv.head(Xp, Yp - 40, Xp, Yp - 4, 2.2);
      cv.labels.push_back({"S = " + kn(n), 11, "fill=\"#8a3ea8\"", Xp, Yp - 40,
                        {{Xp + 5, Yp - 36, Anchor::Start}, {Xp - 5, Yp - 36, Anchor::End}}});
    }
  }
}

// The control point.
void Plan::control_point() {
  if (r.control_block >= 0) {
    const double Xp = X(r.control_point.y()), Yp = Y(r.control_point.x());
    cv.circle(Xp, Yp, 6, "fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"");
    cv.line(Xp - 8, Yp, Xp + 8, Yp, "stroke=\"#000\"");
    cv.line(Xp, Yp - 8, Xp, Yp + 8, "stroke=\"#000\"");
    cv.labels.push_back({msg(lang, "draw.control"), 10, "", Xp, Yp,
                      {{Xp + 10, Yp + 16, Anchor::Start}, {Xp - 10, Yp + 16, Anchor::End}}});
  }
}

// Dimensions below the strip (inside the building, beyond the walls' ends).
void Plan::span_dimensions() {
  std::set<long> us = {mm(umin), mm(umax)};
  for (const Block& b : blocks)
    for (const auto& p : b.polygon) us.insert(mm(p.y()));
  for (const Constraint& c : chain.constraints())
    if (c.type == ConstraintType::Hinge) us.insert(mm(c.point.y()));
  std::vector<double> uv;
  for (long v : us) uv.push_back(v / 1000.0);
  const double yd1 = Y(xmin) + wall_d + 34.0, yd2 = yd1 + 22.0;
  for (std::size_t row = 0; row < 2; ++row) {
    const double yd = row == 0 ? yd1 : yd2;
    const std::vector<double> pts = row == 0 ? uv : std::vector<double>{umin, umax};
    if (row == 0 && pts.size() <= 2) continue;
    cv.line(X(pts.front()) - 5, yd, X(pts.back()) + 5, yd, dim_style);
    for (double u : pts) {
      cv.tick(X(u), yd);
      cv.line(X(u), Y(xmin) + 3, X(u), yd + 5, ext_style);
    }
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      const double xm = 0.5 * (X(pts[k]) + X(pts[k + 1]));
      cv.dim_labels.push_back({d2(pts[k + 1] - pts[k]), 10,
                            std::string("class=\"dim\" data-kind=\"") + (row == 0 ? "level" : "total") + "\" fill=\"#222\"",
                            xm, yd, {{xm, yd - 3, Anchor::Middle}, {xm, yd + 12, Anchor::Middle}}});
    }
  }
}

// The thickness, beyond the last support's wall.
void Plan::thickness_dimension() {
  const double xd = X(umax) + wall_w + 40.0;
  cv.line(xd, Y(xmax) - 5, xd, Y(xmin) + 5, dim_style);
  cv.tick(xd, Y(xmax)), cv.tick(xd, Y(xmin));
  cv.line(X(umax) + wall_w + 3, Y(xmax), xd + 5, Y(xmax), ext_style);
  cv.line(X(umax) + wall_w + 3, Y(xmin), xd + 5, Y(xmin), ext_style);
  const double ym = 0.5 * (Y(xmax) + Y(xmin));
  cv.dim_labels.push_back({d2(t), 10, "class=\"dim\" data-kind=\"thickness\" fill=\"#222\"", xd, ym,
                        {{xd + 5, ym + 3.5, Anchor::Start}, {xd - 5, ym + 3.5, Anchor::End}}});
}

// Outer face, inside, the seismic action outward.
void Plan::seismic_action() {
  const double xa = 0.5 * (X(umin) + X(umax)), ya = Y(xmax) - 70.0;
  cv.line(xa, ya + 48, xa, ya, "stroke=\"#b3001b\" stroke-width=\"2.5\" marker-end=\"url(#arrowr)\"");
  cv.head(xa, ya + 48, xa, ya, 2.5);
  cv.labels.push_back({msg(lang, "draw.seismic"), 11, "fill=\"#b3001b\"", xa, ya,
                    {{xa + 8, ya + 10, Anchor::Start}, {xa - 8, ya + 10, Anchor::End}}});
  cv.labels.push_back({tr(lang, "esterno", "outside"), 10, "fill=\"#444\" font-style=\"italic\"", X(umin), Y(xmax),
                    {{X(umin) + 4, Y(xmax) - 6, Anchor::Start}}});
  cv.labels.push_back({tr(lang, "interno", "inside"), 10, "fill=\"#444\" font-style=\"italic\"", X(umin), Y(xmin),
                    {{X(umin) + 4, Y(xmin) + 14, Anchor::Start}}});
}

// The labels placed, the legend, the SVG document.
std::string Plan::legend_and_document() {
  const double ly = cv.place_labels();
  std::vector<std::string> legend = {tr(lang, "pianta della fascia, quote in m", "plan of the strip, dimensions in m")};
  if (sx > s * 1.0001)
    legend.push_back(tr(lang, "spessore esagerato per leggibilità", "thickness exaggerated for legibility"));
  legend.push_back(tr(lang, "H = spinta dell'arco; tratteggio rosso: linea delle pressioni tra le cerniere",
                      "H = the arch's thrust; red dashes: the thrust line between the hinges"));
  if (symbols.count('S') && chain.loads().size() > 0)
    for (const Load& l : chain.loads())
      if (l.type == LoadType::Force && std::fabs(l.force.x()) > 0.0) {
        legend.push_back(tr(lang, "S = forza equivalente del cordolo", "S = the ring beam's equivalent force"));
        break;
      }
  cv.place_legend(legend, X(umin) - wall_w - 60.0, ly);
  return cv.document(msg(lang, "mech.heading"), "<defs>" + Canvas::marker("arrowr", "#b3001b") +
                                                   Canvas::marker("arrowk", "#222") + "</defs>\n");
}

std::string plan_svg(const Chain& chain, const KinematicResult& r, Lang lang) {
  return Plan(chain, r, lang, block_extent(chain.blocks())).draw();
}

// The bounding box of the blocks and of the foundation level z = 0: xmin, xmax, zmin, zmax (m).
std::array<double, 4> bounding_box(const std::vector<Block>& blocks) {
  std::array<double, 4> b = block_extent(blocks);
  b[2] = std::min(b[2], 0.0);
  return b;
}

// A horizontal dimension: the wall's thickness over a band, a block's width, a load's offset.
struct HDim {
  double x1, x2;      // m
  double zt1, zt2;    // upper reference levels of the two ends (m)
  double zb1, zb2;    // lower reference levels of the two ends (m)
  std::string kind;   // thickness, width, offset
  int load = -1;      // offset: index of the load
};

// A column of vertical dimensions on the outer side of the wall.
struct Column {
  std::vector<double> z;  // levels, bottom to top
  std::string kind;
};

// A row of horizontal dimensions (px) taken, for the next not to clash with it.
struct Row {
  double y, X1, X2;
};

// The elevation of a chain in its plane (mechanism_svg): the state its drawing
// steps share, each step one member, in the order mechanism_svg calls them.
class Elevation {
 public:
  Elevation(const Chain& chain, const KinematicResult& r, Lang lang)
      : Elevation(chain, r, lang, bounding_box(chain.blocks())) {}
  std::string draw();

 private:
  Elevation(const Chain& chain, const KinematicResult& r, Lang lang, const std::array<double, 4>& box);
  // The wall to scale in at most 240 x 440 px.
  double X(double x) const { return 300.0 + s * (x - xmin); }
  double Y(double z) const { return 80.0 + s * (zmax - z); }
  void draw_blocks();
  void collect_levels();
  void place_columns();
  void vertical_dimensions();
  void horizontal_dimensions();
  void level_lines();
  void loads();
  void constraints();
  void control_point();
  void seismic_action();
  std::string legend_and_document();

  const Chain& chain;
  const KinematicResult& r;
  const Lang lang;
  const std::vector<Block>& blocks;
  // Bounding box of the blocks and of the foundation level z = 0 (m), its sizes, the scale (px/m).
  const double xmin, xmax, zmin, zmax, wx, wz, s;
  const Geometry geo;
  // A projected 3-D body (issue 33: the corner's pieces welded, drawn as
  // equivalent strips in the plane normal to the axis): one resultant weight,
  // the pieces translucent, no per-piece widths.
  bool welded = false;
  bool many = false;  // a sliced body (gable): joints and slice weights not labelled
  Canvas cv;
  std::set<long> level_mm, floor_mm, hinge_mm;  // levels (mm): all, floors, ground hinges
  std::vector<double> levels;                   // m
  std::vector<HDim> hdims;
  // Extent of the drawing's lines on each side of the wall (px); ties are drawn
  // on the outer face, the dimension columns beyond them.
  double gx1 = 0.0, col0 = 0.0;
  static constexpr double arrow = 34.0, tie_len = 36.0, col_step = 46.0;
  std::set<long> tie_mm;
  std::vector<Column> cols;
  std::vector<Row> rows;
  std::map<int, double> offset_notes;  // load index -> offset (m) not dimensioned
  std::set<char> symbols;              // of the loads drawn, explained in the legend
};

Elevation::Elevation(const Chain& chain_, const KinematicResult& r_, Lang lang_, const std::array<double, 4>& box)
    : chain(chain_), r(r_), lang(lang_), blocks(chain_.blocks()), xmin(box[0]), xmax(box[1]), zmin(box[2]),
      zmax(box[3]), wx(std::max(xmax - xmin, 1e-6)), wz(std::max(zmax - zmin, 1e-6)),
      s(std::min(240.0 / wx, 440.0 / wz)), geo{blocks, 1e-7 * std::max(wx, wz)} {
  for (const Constraint& c : chain.constraints()) welded = welded || c.type == ConstraintType::Weld;
  many = blocks.size() > 6 || welded;
}

std::string Elevation::draw() {
  draw_blocks();
  collect_levels();
  place_columns();
  vertical_dimensions();
  horizontal_dimensions();
  level_lines();
  loads();
  constraints();
  control_point();
  seismic_action();
  return legend_and_document();
}

// The blocks, as filled polygons (the label placer avoids them).
void Elevation::draw_blocks() {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Block& b = blocks[i];
    std::string pts;
    std::vector<std::array<double, 2>> px;
    for (const auto& p : b.polygon) {
      pts += f1(X(p.x())) + "," + f1(Y(p.y())) + " ";
      px.push_back({X(p.x()), Y(p.y())});
      cv.grow(X(p.x()), Y(p.y()));
    }
    cv.o += "<polygon points=\"" + pts + "\" fill=\"" + (i % 2 ? "#d9cbb5" : "#e6dcc8") + "\"" +
         (welded ? " fill-opacity=\"0.55\"" : "") + " stroke=\"#5a4a32\" stroke-width=\"" + (many ? "0.6" : "1.2") +
         "\"/>\n";
    cv.placer.polygon(std::move(px));
  }
}

// The levels of the drawing and its horizontal dimensions.
void Elevation::collect_levels() {
  // The levels of the drawing: the foundation, the base and top of the wall,
  // the ground hinges, the hinges between blocks, the carried loads, the steps
  // of the wall's thickness.
  level_mm = {0, mm(zmax)};
  for (const Constraint& c : chain.constraints()) {
    if (c.type == ConstraintType::GroundHinge) hinge_mm.insert(mm(c.point.y())), level_mm.insert(mm(c.point.y()));
    if (c.type == ConstraintType::Hinge && !many) level_mm.insert(mm(c.point.y()));
  }
  for (const Load& l : chain.loads()) {
    if (l.type == LoadType::SelfWeight) continue;
    level_mm.insert(mm(l.point.y()));
    if (l.type == LoadType::Weight) floor_mm.insert(mm(l.point.y()));
  }
  level_mm.insert(mm(zmin));
  double base = zmax;  // the lowest point of the blocks
  for (const Block& b : blocks)
    for (const auto& p : b.polygon) base = std::min(base, p.y());
  level_mm.insert(mm(base));
  // Steps of the thickness, and the bands of constant section (for the thickness dimensions).
  std::set<std::pair<long, long>> hdim_keys;
  for (const Block& b : blocks) {
    if (welded) break;  // the pieces of a projection: equivalent widths, not dimensions of the wall
    // The block's vertex levels as they are (rounding them to mm would put a
    // cut of a thin slice outside it: the 0.117 m slices of a 2.8 m gable).
    std::vector<double> zv;
    for (const auto& p : b.polygon) zv.push_back(p.y());
    std::sort(zv.begin(), zv.end());
    zv.erase(std::unique(zv.begin(), zv.end(), [](double a, double c) { return std::abs(a - c) < 1e-9; }), zv.end());
    bool rectangular = true;
    std::vector<std::pair<std::pair<double, double>, std::pair<double, double>>> bands;  // (x1, x2), (bottom, top)
    for (std::size_t k = 0; k + 1 < zv.size(); ++k) {
      const double lo = zv[k], hi = zv[k + 1], d = 1e-3 * (hi - lo);
      const auto a = cut_h(b.polygon, lo + d), c = cut_h(b.polygon, hi - d);
      if (a.size() != 1 || c.size() != 1 || std::abs(a[0].first - c[0].first) > 1e-6 ||
          std::abs(a[0].second - c[0].second) > 1e-6) {
        rectangular = false;
        continue;
      }
      bands.push_back({a[0], {lo, hi}});
    }
    if (rectangular && !many)  // a step of the thickness is a level
      for (std::size_t k = 1; k < bands.size(); ++k)
        if (std::abs(bands[k - 1].first.first - bands[k].first.first) > 1e-6 ||
            std::abs(bands[k - 1].first.second - bands[k].first.second) > 1e-6)
          level_mm.insert(mm(bands[k].second.first));
    if (rectangular) {
      for (const auto& band : bands) {
        const std::pair<long, long> key{mm(band.first.first), mm(band.first.second)};
        if (!hdim_keys.insert(key).second) continue;
        hdims.push_back({band.first.first, band.first.second, band.second.second, band.second.second,
                         band.second.first, band.second.first, "thickness"});
      }
    } else {
      double bx0 = kInf, bx1 = -kInf, t0 = -kInf, t1 = -kInf, u0 = kInf, u1 = kInf;
      for (const auto& p : b.polygon) bx0 = std::min(bx0, p.x()), bx1 = std::max(bx1, p.x());
      for (const auto& p : b.polygon) {
        if (std::abs(p.x() - bx0) < 1e-9) t0 = std::max(t0, p.y()), u0 = std::min(u0, p.y());
        if (std::abs(p.x() - bx1) < 1e-9) t1 = std::max(t1, p.y()), u1 = std::min(u1, p.y());
      }
      const std::pair<long, long> key{mm(bx0), mm(bx1)};
      if (hdim_keys.insert(key).second) hdims.push_back({bx0, bx1, t0, t1, u0, u1, "width"});
    }
  }
  // Offsets of the carried weights from the inner face of the wall under them.
  for (std::size_t i = 0; i < chain.loads().size(); ++i) {
    const Load& l = chain.loads()[i];
    if (l.type != LoadType::Weight || l.block < 0) continue;
    const double z = l.point.y(), x = l.point.x();
    double face = kInf, outer = kInf;
    for (const auto& iv : cut_h(blocks[l.block].polygon, z - 1e-4 * wz))
      if (x >= iv.first - 1e-9 && x <= iv.second + 1e-9) face = iv.first, outer = iv.second;
    if (!std::isfinite(face) || x - face < 5e-4 || outer - x < 5e-4) continue;
    hdims.push_back({face, x, z, z, z, z, "offset", int(i)});
  }

  for (long v : level_mm) levels.push_back(v / 1000.0);
}

// The left end of the level lines and the first dimension column, beyond the ties.
void Elevation::place_columns() {
  gx1 = X(xmin) - 175.0;
  for (const Load& l : chain.loads())
    if (l.type == LoadType::Tie) tie_mm.insert(mm(l.point.y()));
  col0 = X(xmax) + 34.0 + (tie_mm.empty() ? 0.0 : 86.0);
}

// Columns of vertical dimensions on the outer side.
void Elevation::vertical_dimensions() {
  // Columns on the outer side: the chain of levels, the hinge level (when the
  // chain does not show it as one dimension), the overall height.
  if (levels.size() > 2) cols.push_back({levels, "level"});
  for (long h : hinge_mm) {
    const double zh = h / 1000.0;
    if (zh <= 1e-3) continue;
    bool shown = false;  // one segment of the chain from 0 to zh
    if (cols.empty()) shown = true;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k)
      if (mm(levels[k]) == 0 && mm(levels[k + 1]) == h) shown = true;
    if (!shown) cols.push_back({{0.0, zh}, "hinge"});
  }
  cols.push_back({{std::min(0.0, zmin), zmax}, "total"});
  std::map<long, double> ext_to;  // level (mm) -> x (px) its extension line reaches
  for (std::size_t c = 0; c < cols.size(); ++c) {
    const double cx = col0 + col_step * double(c);
    const Column& col = cols[c];
    cv.line(cx, Y(col.z.back()) - 5, cx, Y(col.z.front()) + 5, dim_style);
    for (double z : col.z) {
      cv.tick(cx, Y(z));
      double& e = ext_to[mm(z)];
      e = std::max(e, cx + 5);
    }
    for (std::size_t k = 0; k + 1 < col.z.size(); ++k) {
      const double y1 = Y(col.z[k + 1]), y2 = Y(col.z[k]), ym = 0.5 * (y1 + y2), fs = 10;
      std::vector<Cand> p = {{cx + 5, ym + 0.35 * fs, Anchor::Start}, {cx - 5, ym + 0.35 * fs, Anchor::End}};
      for (double dy : {-10.0, 10.0, -20.0, 20.0})
        if (ym + dy > y1 + 4 && ym + dy < y2 - 4) p.push_back({cx + 5, ym + dy + 0.35 * fs, Anchor::Start});
      cv.dim_labels.push_back({d2(col.z[k + 1] - col.z[k]), fs,
                            "class=\"dim\" data-kind=\"" + col.kind + "\" fill=\"#222\"", cx, ym, p});
    }
  }
  std::set<long> slider_mm;
  for (const Constraint& c : chain.constraints())
    if (c.type == ConstraintType::Slider) slider_mm.insert(mm(c.point.y()));
  for (const auto& e : ext_to) {
    const double z = e.first / 1000.0;
    double xr = geo.right_at(z);
    const double x0 = (std::isfinite(xr) ? X(xr) : X(xmax)) +
                      (tie_mm.count(e.first) ? tie_len + 6 : slider_mm.count(e.first) ? 16 : 4);
    cv.line(x0, Y(z), e.second, Y(z), ext_style);
  }
}

// Rows of horizontal dimensions above or below the wall.
void Elevation::horizontal_dimensions() {
  // In rows above the wall (or below it when an extension line upward would
  // cross a block), the narrower ones nearer; an offset that cannot be
  // dimensioned outside the wall is written by its load ("d = ...").
  std::stable_sort(hdims.begin(), hdims.end(), [](const HDim& a, const HDim& b) {
    const int ra = a.kind == "offset" ? 0 : 1, rb = b.kind == "offset" ? 0 : 1;
    if (ra != rb) return ra < rb;
    return (a.x2 - a.x1) < (b.x2 - b.x1);
  });
  for (const HDim& d : hdims) {
    // Above the wall or below it, where the extension lines cross no block;
    // of the two, the side with the shorter extension lines.
    const double t1 = geo.top_at(d.x1), t2 = geo.top_at(d.x2), b1 = geo.bottom_at(d.x1), b2 = geo.bottom_at(d.x2);
    const bool up_ok = geo.vertical_free(d.x1, d.zt1, std::max(d.zt1, t1)) &&
                       geo.vertical_free(d.x2, d.zt2, std::max(d.zt2, t2));
    const bool down_ok = geo.vertical_free(d.x1, d.zb1, std::min(d.zb1, b1)) &&
                         geo.vertical_free(d.x2, d.zb2, std::min(d.zb2, b2));
    if (!up_ok && !down_ok) {
      if (d.kind == "offset") offset_notes[d.load] = d.x2 - d.x1;
      continue;
    }
    // The silhouette over the dimension's span, on each side.
    double sil_t = std::max(d.zt1, d.zt2), sil_b = std::min(d.zb1, d.zb2);
    for (int k = 0; k <= 32; ++k) {
      const double x = d.x1 + (d.x2 - d.x1) * k / 32.0;
      sil_t = std::max(sil_t, geo.top_at(x));
      sil_b = std::min(sil_b, geo.bottom_at(x));
    }
    const double cost_up = 2 * sil_t - d.zt1 - d.zt2, cost_down = d.zb1 + d.zb2 - 2 * sil_b;
    const bool up = up_ok && (!down_ok || cost_up <= cost_down + 1e-9);
    const double sil = up ? sil_t : sil_b;
    const double X1 = X(d.x1), X2 = X(d.x2);
    double y = 0.0;
    for (int k = 0;; ++k) {
      y = up ? Y(sil) - 18.0 - 16.0 * k : Y(sil) + (sil <= 1e-3 ? 30.0 : 18.0) + 16.0 * k;
      bool clash = false;
      for (const Row& rw : rows)
        if (std::abs(rw.y - y) < 8.0 && X1 < rw.X2 + 34.0 && rw.X1 < X2 + 34.0) clash = true;
      if (!clash) break;
    }
    rows.push_back({y, X1, X2});
    const double e1 = up ? std::max(d.zt1, t1) : std::min(d.zb1, b1), e2 = up ? std::max(d.zt2, t2) : std::min(d.zb2, b2);
    const double sgn = up ? -1.0 : 1.0;
    cv.line(X1, Y(e1) + sgn * 3, X1, y + sgn * 5, ext_style);
    cv.line(X2, Y(e2) + sgn * 3, X2, y + sgn * 5, ext_style);
    cv.line(X1 - 5, y, X2 + 5, y, dim_style);
    cv.tick(X1, y), cv.tick(X2, y);
    const double fs = 10, xm = 0.5 * (X1 + X2);
    std::vector<Cand> p = {{xm, y - 3, Anchor::Middle}, {xm, y + 3 + 0.95 * fs, Anchor::Middle},
                           {X1 - 7, y + 0.35 * fs, Anchor::End}, {X2 + 7, y + 0.35 * fs, Anchor::Start},
                           {X1 - 3, y - 3, Anchor::End}, {X2 + 3, y - 3, Anchor::Start}};
    cv.dim_labels.push_back(
        {d2(d.x2 - d.x1), fs, "class=\"dim\" data-kind=\"" + d.kind + "\" fill=\"#222\"", xm, y, p});
  }
}

// The floors and hinge levels, the ground.
void Elevation::level_lines() {
  double right_edge = col0 + col_step * double(cols.size() - 1) + 16.0;
  for (long zmm_ : floor_mm) {
    const double z = zmm_ / 1000.0;
    if (std::abs(z) < 1e-9) continue;
    const double xl = geo.left_at(z);
    const double x2 = std::isfinite(xl) ? X(xl) - 4 : X(xmin) - 4;
    cv.line(gx1, Y(z), x2, Y(z), "stroke=\"#888\" stroke-dasharray=\"6 4\"");
    const std::string t = tr(lang, "piano", "floor") + std::string(" z = ") + m2(z);
    cv.labels.push_back({t, 11, "fill=\"#555\"", gx1, Y(z),
                      {{gx1 + 2, Y(z) - 5, Anchor::Start}, {gx1 + 2, Y(z) + 14, Anchor::Start},
                       {gx1 + 62, Y(z) - 5, Anchor::Start}, {gx1 + 62, Y(z) + 14, Anchor::Start}}});
  }
  for (long zmm_ : hinge_mm) {
    const double z = zmm_ / 1000.0;
    if (std::abs(z) < 1e-9) continue;
    const double xl = geo.left_at(z);
    const double x2 = std::isfinite(xl) ? X(xl) - 4 : X(xmin) - 4;
    cv.line(gx1, Y(z), x2, Y(z), "stroke=\"#b3001b\" stroke-dasharray=\"10 3 2 3\"");
    cv.labels.push_back({msg(lang, "draw.hinge_level") + " z = " + m2(z), 11, "fill=\"#b3001b\"", gx1, Y(z),
                      {{gx1 + 2, Y(z) - 5, Anchor::Start}, {gx1 + 2, Y(z) + 14, Anchor::Start},
                       {gx1 + 62, Y(z) - 5, Anchor::Start}, {gx1 + 62, Y(z) + 14, Anchor::Start}}});
  }
  const double Y0 = Y(0.0);
  cv.line(gx1, Y0, right_edge, Y0, "stroke=\"#444\" stroke-width=\"2\"");
  for (double hx = X(xmin) - 24; hx < X(xmax) + 20; hx += 14)
    cv.line(hx, Y0 + 8, hx + 8, Y0, "stroke=\"#444\"");
  cv.labels.push_back({msg(lang, "draw.ground") + " z = 0", 11, "fill=\"#444\"", gx1, Y0,
                    {{gx1, Y0 + 22, Anchor::Start}, {gx1, Y0 - 5, Anchor::Start}, {gx1 + 60, Y0 + 22, Anchor::Start}}});
}

// The loads: self weights, carried weights, forces, ties, friction.
void Elevation::loads() {
  double self_total = 0.0, self_x = 0.0, self_z = 0.0;
  for (std::size_t li = 0; li < chain.loads().size(); ++li) {
    const Load& l = chain.loads()[li];
    const double Xp = X(l.point.x()), Yp = Y(l.point.y());
    switch (l.type) {
      case LoadType::SelfWeight:
        self_total += l.weight, self_x += l.weight * l.point.x(), self_z += l.weight * l.point.y();
        if (!many) {
          cv.line(Xp, Yp - 24, Xp, Yp, "stroke=\"#222\" stroke-width=\"1.2\" marker-end=\"url(#arrowk)\"");
          cv.head(Xp, Yp - 24, Xp, Yp, 1.2);
          const double xl = geo.left_at(l.point.y()), xr = geo.right_at(l.point.y());
          symbols.insert('P');
          cv.labels.push_back({"P = " + kn(l.weight), 10, "", Xp, Yp - 12,
                            {{Xp - 5, Yp - 12 + 3.5, Anchor::End}, {Xp + 5, Yp - 12 + 3.5, Anchor::Start},
                             {Xp - 5, Yp - 24, Anchor::End}, {Xp + 5, Yp - 24, Anchor::Start},
                             {X(xl) - 8, Yp - 12 + 3.5, Anchor::End}, {X(xr) + 8, Yp - 12 + 3.5, Anchor::Start}}});
        }
        break;
      case LoadType::Weight: {
        cv.line(Xp, Yp - arrow, Xp, Yp, "stroke=\"#0b4f9c\" stroke-width=\"2\" marker-end=\"url(#arrowb)\"");
        cv.head(Xp, Yp - arrow, Xp, Yp, 2.0);
        const double ay = Yp - arrow;
        symbols.insert('Q');
        cv.labels.push_back({"Q = " + kn(l.weight) + (l.vertical ? "" : " (m)"), 11,
                          "fill=\"#0b4f9c\"", Xp, ay,
                          {{Xp - 5, ay + 4, Anchor::End}, {Xp + 5, ay + 4, Anchor::Start}, {Xp, ay - 4, Anchor::Middle},
                           {Xp - 5, ay - 6, Anchor::End}, {Xp + 5, ay - 6, Anchor::Start}}});
        break;
      }
      case LoadType::Force:
      case LoadType::Tie:
      case LoadType::Friction: {
        const double n = l.force.norm();
        if (!(n > 0.0)) break;
        const double ux = l.force.x() / n, uz = l.force.y() / n;
        // Arrow ending at the point of application (force pushing on it); a
        // tie (horizontal, inward) as the push of its anchor plate on the
        // outer face of the wall, on the same line of action.
        const bool tie_out = l.type == LoadType::Tie && std::abs(uz) < 1e-9 && ux < 0.0;
        const double len = tie_out ? tie_len : arrow * 1.4;
        const double xe = tie_out ? X(geo.right_at(l.point.y())) + 1.0 : Xp;
        const double x1 = xe - ux * len, y1 = Yp + uz * len;
        const double x2 = xe, y2 = Yp;
        const char* colour = l.type == LoadType::Tie ? "#2b7a2b" : "#8a3ea8";
        cv.line(x1, y1, x2, y2,
             std::string("stroke=\"") + colour + "\" stroke-width=\"2.2\" marker-end=\"url(#arrowk)\"" +
                 (l.type == LoadType::Tie ? " stroke-dasharray=\"8 3\"" : ""));
        cv.head(x1, y1, x2, y2, 2.2);
        // Anchor: the free end of the arrow (its tail).
        const double ax = x1, ay = y1;
        const double xm = 0.5 * (x1 + x2), ym = std::min(y1, y2);
        const Anchor side = x1 <= x2 ? Anchor::End : Anchor::Start;  // beyond the tail
        const double sx = x1 <= x2 ? ax - 5 : ax + 5;
        const char sym = l.type == LoadType::Tie ? 'T' : l.type == LoadType::Force ? 'S' : 'F';
        symbols.insert(sym);
        std::vector<Cand> p = {{xm, ym - 5, Anchor::Middle}, {sx, ay + 4, side},
                               {xm, std::max(y1, y2) + 14, Anchor::Middle}, {sx, ay - 6, side}, {sx, ay + 15, side}};
        if (tie_out) p.insert(p.begin(), {{x2 + 3, ym - 5, Anchor::Start}, {x2 + 3, ym + 14, Anchor::Start}});
        cv.labels.push_back({l.label.empty() ? std::string(1, sym) + " = " + kn(n) : l.label, 11,
                          std::string("fill=\"") + colour + "\"", ax, ay, p});
        break;
      }
    }
  }
  for (const auto& on : offset_notes) {
    const Load& l = chain.loads()[on.first];
    const double Xp = X(l.point.x()), Yp = Y(l.point.y());
    cv.labels.push_back({"d = " + d2(on.second) + " m", 10, "class=\"dim\" data-kind=\"offset-note\" fill=\"#0b4f9c\"",
                      Xp, Yp,
                      {{Xp - 5, Yp + 13, Anchor::End}, {Xp - 5, Yp - 6, Anchor::End}, {Xp + 5, Yp + 13, Anchor::Start}}});
  }
  if (many && self_total > 0.0) {
    const double Xp = X(self_x / self_total), Yp = Y(self_z / self_total);
    cv.line(Xp, Yp - 30, Xp, Yp, "stroke=\"#222\" stroke-width=\"1.4\" marker-end=\"url(#arrowk)\"");
    cv.head(Xp, Yp - 30, Xp, Yp, 1.4);
    cv.labels.push_back({msg(lang, "draw.self_weights") + " (" + std::to_string(blocks.size()) +
                          ") ΣP = " + kn(self_total),
                      10, "", Xp, Yp - 15,
                      {{Xp - 5, Yp - 15 + 3.5, Anchor::End}, {Xp + 5, Yp - 15 + 3.5, Anchor::Start},
                       {X(geo.left_at(self_z / self_total)) - 8, Yp - 15 + 3.5, Anchor::End}}});
  }
}

// The hinges and sliders.
void Elevation::constraints() {
  std::set<std::pair<long, long>> drawn;
  for (const Constraint& c : chain.constraints()) {
    const double Xp = X(c.point.x()), Yp = Y(c.point.y());
    if ((c.type == ConstraintType::Hinge && many) || c.type == ConstraintType::Weld) continue;  // joints of a sliced body are not drawn
    if (!drawn.insert({std::lround(Xp), std::lround(Yp)}).second) continue;
    if (c.type == ConstraintType::Slider) {
      cv.circle(Xp + 6, Yp, 4, "fill=\"#fff\" stroke=\"#222\"");
      cv.line(Xp + 11, Yp - 12, Xp + 11, Yp + 12, "stroke=\"#222\" stroke-width=\"2\"");
      cv.labels.push_back({msg(lang, "draw.slider"), 10, "", Xp + 11, Yp,
                        {{Xp + 15, Yp - 8, Anchor::Start}, {Xp + 15, Yp + 16, Anchor::Start},
                         {Xp + 15, Yp + 3.5, Anchor::Start}}});
    } else if (c.type == ConstraintType::GroundHinge) {
      cv.circle(Xp, Yp, 5, "fill=\"#fff\" stroke=\"#b3001b\" stroke-width=\"2\"");
      cv.labels.push_back({msg(lang, "draw.hinge") + " z = " + m2(c.point.y()), 10, "fill=\"#b3001b\"", Xp, Yp,
                        {{Xp + 8, Yp + 14, Anchor::Start}, {Xp - 8, Yp + 14, Anchor::End},
                         {Xp + 8, Yp - 7, Anchor::Start}, {Xp - 8, Yp - 7, Anchor::End},
                         {Xp, Yp + 17, Anchor::Middle}}});
    } else {
      cv.circle(Xp, Yp, 4, "fill=\"#fff\" stroke=\"#b3001b\" stroke-width=\"1.5\"");
      cv.labels.push_back({msg(lang, "draw.hinge"), 10, "fill=\"#b3001b\"", Xp, Yp,
                        {{Xp + 7, Yp + 3.5, Anchor::Start}, {Xp - 7, Yp + 3.5, Anchor::End},
                         {Xp + 6, Yp + 14, Anchor::Start}, {Xp - 6, Yp + 14, Anchor::End},
                         {Xp + 6, Yp - 6, Anchor::Start}, {Xp - 6, Yp - 6, Anchor::End}}});
    }
  }
}

// The control point of the capacity curve.
void Elevation::control_point() {
  if (r.control_block >= 0) {
    const double Xp = X(r.control_point.x()), Yp = Y(r.control_point.y());
    cv.circle(Xp, Yp, 6, "fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"");
    cv.line(Xp - 8, Yp, Xp + 8, Yp, "stroke=\"#000\"");
    cv.line(Xp, Yp - 8, Xp, Yp + 8, "stroke=\"#000\"");
    cv.labels.push_back({msg(lang, "draw.control") + " (z = " + m2(r.control_point.y()) + ")", 10, "", Xp, Yp,
                      {{Xp + 10, Yp - 8, Anchor::Start}, {Xp - 10, Yp - 8, Anchor::End},
                       {Xp + 10, Yp + 16, Anchor::Start}, {Xp - 10, Yp + 16, Anchor::End},
                       {X(geo.left_at(r.control_point.y())) - 8, Yp + 3.5, Anchor::End},
                       {X(geo.left_at(r.control_point.y())) - 8, Yp + 16, Anchor::End},
                       {X(geo.left_at(r.control_point.y())) - 8, Yp - 9, Anchor::End},
                       {X(geo.left_at(r.control_point.y())) - 8, Yp + 28, Anchor::End},
                       {X(geo.left_at(r.control_point.y())) - 8, Yp - 21, Anchor::End},
                       {X(geo.left_at(r.control_point.y())) - 8, Yp + 40, Anchor::End}}});
  }
}

// The direction of the seismic action.
void Elevation::seismic_action() {
  {
    double top = Y(zmax);
    for (const Row& rw : rows) top = std::min(top, rw.y);
    const std::string st = msg(lang, "draw.seismic");
    const double sy = top - 40.0, sx1 = X(xmax) + 14.0, sx2 = sx1 + std::max(90.0, 0.6 * 11 * code_points(st) + 8);
    cv.line(sx1, sy, sx2, sy, "stroke=\"#b3001b\" stroke-width=\"2.5\" marker-end=\"url(#arrowr)\"");
    cv.head(sx1, sy, sx2, sy, 2.5);
    cv.labels.push_back({st, 11, "fill=\"#b3001b\"", sx1, sy,
                      {{sx1, sy - 8, Anchor::Start}, {sx1 - 6, sy + 4, Anchor::End}, {sx1, sy + 18, Anchor::Start}}});
    cv.labels.push_back({"x", 11, "fill=\"#b3001b\"", sx2, sy, {{sx2 + 6, sy + 4, Anchor::Start}}});
  }
}

// The labels placed, the legend under everything, the SVG document.
std::string Elevation::legend_and_document() {
  // The legend under everything.
  const double ly = cv.place_labels();
  std::vector<std::string> legend = {tr(lang, "quote in m", "dimensions in m")};
  {
    std::string sy;
    const std::pair<char, std::string> names[] = {{'P', tr(lang, "peso proprio", "self weight")},
                                                  {'Q', msg(lang, "load.weight")},
                                                  {'S', msg(lang, "load.force")},
                                                  {'T', msg(lang, "load.tie")},
                                                  {'F', msg(lang, "load.friction")}};
    for (const auto& nm : names)
      if (symbols.count(nm.first)) sy += (sy.empty() ? "" : ", ") + std::string(1, nm.first) + " = " + nm.second;
    if (!sy.empty()) legend.push_back(sy);
  }
  if (!offset_notes.empty())
    legend.push_back(tr(lang, "d = distanza del carico dal filo interno del muro",
                        "d = distance of the load from the inner face of the wall"));
  cv.place_legend(legend, gx1, ly);

  return cv.document(msg(lang, "mech.heading"),
                     "<defs>" + Canvas::marker("arrow", "context-stroke", "auto-start-reverse") +
                         Canvas::marker("arrowb", "#0b4f9c") + Canvas::marker("arrowr", "#b3001b") +
                         Canvas::marker("arrowk", "#222") + "</defs>\n");
}

}  // namespace

std::string mechanism_svg(const Chain& chain, const KinematicResult& r, Lang lang) {
  decimal_comma = lang == Lang::it;
  if (chain.plan()) return plan_svg(chain, r, lang);  // issue 33: horizontal flexure, in plan
  return Elevation(chain, r, lang).draw();
}

}  // namespace assess

// The drawing of the mechanism (report/mechanism_drawing.hpp) that a checking
// engineer signs off: for every candidate chain of every shipped case in
// mechanisms/ (built as the report builds it: read_case_file +
// run_kinematic_case) and for a dense synthetic façade (4 storeys with floor
// loads, thrusts and ties on every storey), in Italian and English, the SVG's
// text elements are parsed (x, y, font-size, text-anchor, text) and
//  - no two label boxes overlap, every label box lies inside the viewBox;
//  - no dimension or extension line crosses a block (0.5 px inside its outline);
//  - the dimension values equal the geometry: the overall height is the top of
//    the wall (to 0.005 m), the chain of level dimensions adds up to it and
//    contains each storey height and the hinge level, every distinct thickness
//    of a band of constant section is dimensioned, and every carried weight's
//    distance from the inner face is dimensioned (or written by the load).
//
// Box estimate (the placer's, mechanism_drawing.cpp text_box): a label of n
// characters (UTF-8 code points) in font size f at (x, y) is 0.6 f n wide,
// from y - 0.95 f to y + 0.25 f, left-aligned at x (start), centred (middle)
// or right-aligned (end). Measured in Chromium (DejaVu Sans) the drawing's
// strings are 0.50-0.57 f per character, 0.90 f above and 0.27 f below the
// baseline at most.
//
// ASSESS_DRAWING_DUMP=DIR writes every drawing checked to DIR (to look at them).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <assess/assessment/building_case.hpp>
#include <assess/assessment/case_file.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/report/mechanism_drawing.hpp>
#include <assess/report/messages.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <array>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string kData = ASSESS_TEST_DATA_DIR;

// Dimension values are printed with 2 decimals: half a centimetre.
constexpr double tol_dim = 0.005 + 1e-9;  // m: half the last printed digit (2 decimals), and round-off

struct Text {
  double x = 0, y = 0, fs = 11;
  std::string anchor = "start", cls, kind, text;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // estimated box (px)
};

// The value of attribute `name` in a tag's text (the first ` name="..."`);
// plain search: a regex built per call was 90 % of this test's time.
std::string attr(const std::string& tag, const std::string& name) {
  const std::string key = name + "=\"";
  for (std::size_t at = tag.find(key); at != std::string::npos; at = tag.find(key, at + 1)) {
    if (at == 0 || !std::isspace(static_cast<unsigned char>(tag[at - 1]))) continue;
    const std::size_t from = at + key.size(), to = tag.find('"', from);
    return to == std::string::npos ? "" : tag.substr(from, to - from);
  }
  return "";
}

std::string unescape(std::string s) {
  const std::pair<const char*, const char*> ents[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& e : ents)
    for (std::size_t p = s.find(e.first); p != std::string::npos; p = s.find(e.first, p + 1))
      s.replace(p, std::string(e.first).size(), e.second);
  return s;
}

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return n;
}

struct Svg {
  double vx = 0, vy = 0, vw = 0, vh = 0;
  std::vector<Text> texts;
  std::vector<std::vector<std::array<double, 2>>> polygons;  // the blocks (px)
  std::vector<std::array<double, 4>> dim_lines;              // dimension and extension lines (px)
};

Svg parse(const std::string& svg) {
  Svg out;
  const std::string root = svg.substr(0, svg.find('>'));
  const std::string vb = attr(root, "viewBox");
  REQUIRE_MESSAGE(!vb.empty(), "no viewBox");
  REQUIRE(std::sscanf(vb.c_str(), "%lf %lf %lf %lf", &out.vx, &out.vy, &out.vw, &out.vh) == 4);
  const std::string root_fs = attr(root, "font-size");
  static const std::regex poly_re("<polygon points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), poly_re); it != std::sregex_iterator(); ++it) {
    std::vector<std::array<double, 2>> P;
    std::string pts = (*it)[1];
    std::replace(pts.begin(), pts.end(), ',', ' ');
    std::istringstream in(pts);
    double x = 0, y = 0;
    while (in >> x >> y) P.push_back({x, y});
    out.polygons.push_back(P);
  }
  static const std::regex line_re("<line ([^>]*)/>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line_re); it != std::sregex_iterator(); ++it) {
    const std::string tag = " " + (*it)[1].str();
    const std::string cls = attr(tag, "class");
    if (cls != "dim-line" && cls != "ext-line") continue;
    out.dim_lines.push_back({std::stod(attr(tag, "x1")), std::stod(attr(tag, "y1")), std::stod(attr(tag, "x2")),
                             std::stod(attr(tag, "y2"))});
  }
  static const std::regex text_re("<text([^>]*)>([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text_re); it != std::sregex_iterator(); ++it) {
    Text t;
    const std::string tag = (*it)[1];
    t.x = std::stod(attr(tag, "x"));
    t.y = std::stod(attr(tag, "y"));
    const std::string fs = attr(tag, "font-size");
    t.fs = std::stod(fs.empty() ? (root_fs.empty() ? "16" : root_fs) : fs);
    const std::string a = attr(tag, "text-anchor");
    if (!a.empty()) t.anchor = a;
    t.cls = attr(tag, "class");
    t.kind = attr(tag, "data-kind");
    t.text = unescape((*it)[2]);
    const double w = 0.6 * t.fs * double(code_points(t.text));
    t.x0 = t.anchor == "start" ? t.x : t.anchor == "middle" ? t.x - 0.5 * w : t.x - w;
    t.x1 = t.x0 + w;
    t.y0 = t.y - 0.95 * t.fs;
    t.y1 = t.y + 0.25 * t.fs;
    out.texts.push_back(t);
  }
  return out;
}

// Dimension values of one kind, in document order (the level chain bottom to top).
std::vector<double> dims(const Svg& s, const std::string& kind) {
  std::vector<double> v;
  for (const Text& t : s.texts)
    if (t.cls == "dim" && t.kind == kind) {
      std::string num = t.text;
      if (kind == "offset-note") {  // "d = 0.25 m" -> "0.25"
        if (num.rfind("d = ", 0) == 0) num.erase(0, 4);
        if (num.size() > 2 && num.compare(num.size() - 2, 2, " m") == 0) num.erase(num.size() - 2);
      }
      for (char& ch : num)  // the Italian drawing writes the decimal comma (issue 28)
        if (ch == ',') ch = '.';
      v.push_back(std::stod(num));
    }
  return v;
}

bool contains(const std::vector<double>& v, double x) {
  for (double a : v)
    if (std::abs(a - x) <= tol_dim) return true;
  return false;
}

// True if (x, y) lies inside the polygon farther than 0.5 px from its outline.
bool deep_inside(const std::vector<std::array<double, 2>>& P, double x, double y) {
  bool in = false;
  double d = 1e300;
  for (std::size_t i = 0, j = P.size() - 1; i < P.size(); j = i++) {
    const double ax = P[j][0], ay = P[j][1], bx = P[i][0], by = P[i][1];
    if ((by > y) != (ay > y) && x < (ax - bx) * (y - by) / (ay - by) + bx) in = !in;
    const double ex = bx - ax, ey = by - ay, L = ex * ex + ey * ey;
    const double t = L > 0 ? std::clamp(((x - ax) * ex + (y - ay) * ey) / L, 0.0, 1.0) : 0.0;
    d = std::min(d, std::hypot(ax + t * ex - x, ay + t * ey - y));
  }
  return in && d > 0.5;
}

// x intervals of a polygon on the horizontal line z (z not a vertex level).
std::vector<std::pair<double, double>> cut(const std::vector<Eigen::Vector2d>& P, double z) {
  std::vector<double> xs;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const auto& a = P[i];
    const auto& b = P[(i + 1) % P.size()];
    if ((a.y() > z) != (b.y() > z)) xs.push_back(a.x() + (z - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
  }
  std::sort(xs.begin(), xs.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2) out.push_back({xs[i], xs[i + 1]});
  return out;
}

// Checks one drawing against its chain; `storeys` (heights, m) when known.
void check_drawing(const std::string& what, const std::string& svg, const assess::Chain& chain,
                   const std::vector<double>& storeys = {}) {
  INFO(what);
  if (const char* dir = std::getenv("ASSESS_DRAWING_DUMP")) {  // for a look: one SVG per drawing
    std::string name = what;
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    std::ofstream(std::string(dir) + "/" + name + ".svg") << svg;
  }
  const Svg s = parse(svg);
  REQUIRE(!s.texts.empty());

  // No two label boxes overlap.
  for (std::size_t i = 0; i < s.texts.size(); ++i)
    for (std::size_t j = i + 1; j < s.texts.size(); ++j) {
      const Text& a = s.texts[i];
      const Text& b = s.texts[j];
      const bool overlap = a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
      if (overlap) FAIL_CHECK("labels overlap: '" << a.text << "' and '" << b.text << "'");
    }
  // Every label inside the viewBox.
  for (const Text& t : s.texts) {
    const bool inside = t.x0 >= s.vx && t.x1 <= s.vx + s.vw && t.y0 >= s.vy && t.y1 <= s.vy + s.vh;
    if (!inside) FAIL_CHECK("label outside the viewBox: '" << t.text << "'");
  }

  // Dimension and extension lines never cross a block.
  REQUIRE(!s.dim_lines.empty());
  for (const auto& l : s.dim_lines) {
    bool crosses = false;
    for (const auto& P : s.polygons)
      for (int k = 1; k < 50 && !crosses; ++k)
        crosses = deep_inside(P, l[0] + (l[2] - l[0]) * k / 50.0, l[1] + (l[3] - l[1]) * k / 50.0);
    if (crosses) FAIL_CHECK("dimension line crosses a block: " << l[0] << "," << l[1] << " - " << l[2] << "," << l[3]);
  }

  // Geometry of the chain.
  double zmax = -1e300, zbase = 1e300;
  for (const assess::Block& b : chain.blocks())
    for (const auto& p : b.polygon) zmax = std::max(zmax, p.y()), zbase = std::min(zbase, p.y());
  const double zmin = std::min(0.0, zbase);

  // Overall height: one dimension, the top of the wall above the foundation.
  const std::vector<double> total = dims(s, "total");
  REQUIRE(total.size() == 1);
  CHECK(std::abs(total[0] - (zmax - zmin)) <= tol_dim);

  // The chain of levels adds up to the overall height (each value rounded to cm).
  const std::vector<double> level = dims(s, "level");
  if (!level.empty()) {
    double sum = 0.0;
    for (double v : level) {
      CHECK(v > 0.0);
      sum += v;
    }
    CHECK(std::abs(sum - (zmax - zmin)) <= tol_dim * double(level.size()));
  }
  for (double h : storeys) {
    INFO("storey height " << h);
    CHECK(contains(level, h));
  }
  // The hinge level: the foundation-to-hinge distance is a dimension (a
  // segment of the level chain counted from the foundation, or its own).
  std::vector<double> reach = {0.0};  // levels reached by the chain from z = 0
  for (double v : level) reach.push_back(reach.back() + v);
  const std::vector<double> hinge = dims(s, "hinge");
  for (const assess::Constraint& c : chain.constraints()) {
    if (c.type != assess::ConstraintType::GroundHinge || c.point.y() < 1e-3) continue;
    const double zh = c.point.y();
    INFO("hinge level " << zh);
    CHECK((contains(hinge, zh) || contains(reach, zh) || (level.empty() && std::abs(zh - zmax) < tol_dim)));
  }

  // A projected 3-D body (issue 33, the corner's welded pieces): equivalent
  // widths, no wall dimension to check beyond the heights.
  bool welded = false;
  for (const assess::Constraint& c : chain.constraints()) welded = welded || c.type == assess::ConstraintType::Weld;
  if (welded) {
    CHECK(dims(s, "thickness").empty());
    return;
  }
  // Thicknesses: every band of constant section of every block (distinct values).
  const std::vector<double> thick = dims(s, "thickness");
  std::vector<double> width = dims(s, "width");
  std::set<long> expected;
  for (const assess::Block& b : chain.blocks()) {
    std::set<double> zs;
    for (const auto& p : b.polygon) zs.insert(p.y());
    std::vector<double> zv(zs.begin(), zs.end());
    bool rect = true;
    std::set<long> bt;
    for (std::size_t k = 0; k + 1 < zv.size(); ++k) {
      const double d = 1e-3 * (zv[k + 1] - zv[k]);
      const auto lo = cut(b.polygon, zv[k] + d), hi = cut(b.polygon, zv[k + 1] - d);
      if (lo.size() != 1 || hi.size() != 1 || std::abs(lo[0].first - hi[0].first) > 1e-6 ||
          std::abs(lo[0].second - hi[0].second) > 1e-6) {
        rect = false;
        continue;
      }
      bt.insert(std::lround((lo[0].second - lo[0].first) * 1000.0));
    }
    if (rect) expected.insert(bt.begin(), bt.end());
    else {
      double x0 = 1e300, x1 = -1e300;
      for (const auto& p : b.polygon) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
      INFO("width of block " << b.name);
      CHECK(contains(width, x1 - x0));
    }
  }
  for (long t : expected) {
    INFO("thickness " << t << " mm");
    CHECK(contains(thick, t / 1000.0));
  }
  for (double t : thick) {
    INFO("drawn thickness " << t);
    bool found = false;
    for (long e : expected) found = found || std::abs(e / 1000.0 - t) <= tol_dim;
    CHECK(found);
  }

  // Carried weights: the distance from the inner face under them.
  std::vector<double> off = dims(s, "offset");
  const std::vector<double> notes = dims(s, "offset-note");
  off.insert(off.end(), notes.begin(), notes.end());
  for (const assess::Load& l : chain.loads()) {
    if (l.type != assess::LoadType::Weight) continue;
    const double z = l.point.y() - 1e-6, x = l.point.x();
    for (const auto& iv : cut(chain.blocks()[l.block].polygon, z)) {
      if (x < iv.first + 5e-4 || x > iv.second - 5e-4) continue;
      INFO("load " << l.name << " at " << x - iv.first << " m from the inner face");
      CHECK(contains(off, x - iv.first));
    }
  }
}

}  // namespace

TEST_CASE("the drawing of every shipped mechanism has dimensions equal to the geometry and no overlapping label") {
  int drawn = 0;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(kData + "/mechanisms"))
    if (e.path().extension() == ".json" && e.path().filename().string().rfind("campaign", 0) != 0)
      files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 9);
  // A building case (issue 22) is drawn mechanism by mechanism, as its relazione does.
  std::vector<std::pair<std::string, assess::CaseFile>> cases;
  for (const std::string& f : files) {
    std::ifstream in(f);
    const nlohmann::json doc = nlohmann::json::parse(in);
    if (!assess::is_building_document(doc)) {
      cases.emplace_back(f, assess::read_case_file(f));
      continue;
    }
    const assess::BuildingCase b = assess::parse_building(doc, f);
    for (const assess::BuildingMechanism& m : b.mechanisms) cases.emplace_back(f + " " + m.id, m.kase);
  }
  for (const auto& [f, kase] : cases) {
    const assess::KinematicCaseResult res = assess::run_kinematic_case(kase);
    REQUIRE(res.candidates.size() == kase.mechanism.candidates.size());
    for (std::size_t i = 0; i < kase.mechanism.candidates.size(); ++i)
      for (assess::Lang lang : {assess::Lang::it, assess::Lang::en}) {
        const assess::Chain& chain = kase.mechanism.candidates[i].chain;
        const std::string what = std::filesystem::path(f).filename().string() + " candidate " +
                                 std::to_string(i) + " (" + assess::to_string(lang) + ")";
        check_drawing(what, assess::mechanism_svg(chain, res.candidates[i].result, lang), chain);
        ++drawn;
      }
  }
  MESSAGE(drawn << " drawings checked");
  CHECK(drawn >= 40);
}

TEST_CASE("a dense four-storey facade: floors, thrusts and ties on every storey, every hinge level") {
  assess::SimpleOverturningParams p;
  const double kN = 1000.0;
  // height, thickness, floor weight, its distance from the inner face, thrust, tie
  const double st[4][6] = {{4.2, 0.70, 60, 0.25, 8, 12}, {3.6, 0.60, 50, 0.20, 6, 10},
                           {3.4, 0.50, 40, 0.20, 5, 8}, {3.0, 0.40, 20, 0.15, 4, 6}};
  for (const auto& r : st) {
    assess::Storey s;
    s.height = r[0], s.thickness = r[1], s.floor_weight = r[2] * kN, s.floor_distance_from_inner_face = r[3];
    s.thrust = r[4] * kN, s.tie = r[5] * kN;
    p.storeys.push_back(s);
  }
  p.unit_weight = 18.0 * kN;
  p.length = 5.0;
  const assess::MechanismSet set = assess::simple_overturning(p);
  REQUIRE(set.candidates.size() == 4);
  for (std::size_t j = 0; j < set.candidates.size(); ++j) {
    const assess::Chain& chain = set.candidates[j].chain;
    const assess::KinematicResult r = assess::analyse_kinematic(chain);
    std::vector<double> heights;
    for (std::size_t i = j; i < 4; ++i) heights.push_back(st[i][0]);
    for (assess::Lang lang : {assess::Lang::it, assess::Lang::en})
      check_drawing("four storeys, hinge at level " + std::to_string(j) + " (" + assess::to_string(lang) + ")",
                    assess::mechanism_svg(chain, r, lang), chain, heights);
  }
  // Without a control point (a default result) the drawing is still checked.
  check_drawing("four storeys, no analysis", assess::mechanism_svg(set.candidates[0].chain, {}, assess::Lang::it),
                set.candidates[0].chain, {4.2, 3.6, 3.4, 3.0});
}

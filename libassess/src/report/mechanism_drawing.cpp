// mechanism_drawing.cpp: SVG drawing of a chain of blocks, written directly
// (no gnuplot: polygons, arrows and labels at exact positions).
#include "assess/report/mechanism_drawing.hpp"

#include "report/xml_escape.hpp"

#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace assess {

namespace {

using detail::xml_escape;

std::string f1(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

std::string kn(double newton) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f kN", newton / units::kN);
  return b;
}

std::string m2(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f m", v);
  return b;
}

// World (x, z) in metres to SVG pixels.
struct View {
  double xmin, zmax, s, ox, oy;
  double X(double x) const { return ox + s * (x - xmin); }
  double Y(double z) const { return oy + s * (zmax - z); }
};

}  // namespace

std::string mechanism_svg(const Chain& chain, const KinematicResult& r, Lang lang) {
  // Bounding box of the blocks and of the foundation level z = 0.
  double xmin = 1e300, xmax = -1e300, zmin = 0.0, zmax = -1e300;
  for (const Block& b : chain.blocks())
    for (const auto& p : b.polygon) {
      xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
      zmin = std::min(zmin, p.y()), zmax = std::max(zmax, p.y());
    }
  const double wx = std::max(xmax - xmin, 1e-6), wz = std::max(zmax - zmin, 1e-6);
  // Drawing area: 300 x 440 px for the wall, room on both sides for labels.
  const double W = 640, H = 520, left = 230, top = 40, area_w = 180, area_h = H - 90;
  const double s = std::min(area_w / wx, area_h / wz);
  const View v{xmin, zmax, s, left + (area_w - s * wx) / 2.0, top};

  std::string o;
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + f1(W) + " " + f1(H) + "\" width=\"" + f1(W) +
       "\" height=\"" + f1(H) + "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  o += "<title>" + xml_escape(msg(lang, "mech.heading")) + "</title>\n";
  o += "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
       "orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"context-stroke\"/></marker>"
       "<marker id=\"arrowb\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
       "orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#0b4f9c\"/></marker>"
       "<marker id=\"arrowr\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
       "orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#b3001b\"/></marker>"
       "<marker id=\"arrowk\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
       "orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#222\"/></marker></defs>\n";
  auto line = [&](double x1, double y1, double x2, double y2, const std::string& style) {
    o += "<line x1=\"" + f1(x1) + "\" y1=\"" + f1(y1) + "\" x2=\"" + f1(x2) + "\" y2=\"" + f1(y2) + "\" " + style +
         "/>\n";
  };
  auto text = [&](double x, double y, const std::string& t, const std::string& attrs = "") {
    o += "<text x=\"" + f1(x) + "\" y=\"" + f1(y) + "\" " + attrs + ">" + xml_escape(t) + "</text>\n";
  };

  // Levels: the foundation, the floors (levels of carried weights) and the hinges.
  const double gx1 = 10, gx2 = W - 10;
  line(gx1, v.Y(0.0), gx2, v.Y(0.0), "stroke=\"#444\" stroke-width=\"2\"");
  for (int i = 0; i < 12; ++i)
    line(v.X(xmin) - 40 + 16 * i, v.Y(0.0) + 8, v.X(xmin) - 32 + 16 * i, v.Y(0.0), "stroke=\"#444\"");
  text(gx1, v.Y(0.0) + 22, msg(lang, "draw.ground") + " z = 0", "fill=\"#444\"");
  std::set<long> floor_levels;
  for (const Load& l : chain.loads())
    if (l.type == LoadType::Weight) floor_levels.insert(std::lround(l.point.y() * 1000.0));
  for (long zmm : floor_levels) {
    const double z = zmm / 1000.0;
    if (std::abs(z) < 1e-9) continue;
    line(gx1, v.Y(z), gx2, v.Y(z), "stroke=\"#888\" stroke-dasharray=\"6 4\"");
    text(gx2, v.Y(z) - 4, msg(lang, "draw.storey") + " z = " + m2(z), "text-anchor=\"end\" fill=\"#555\"");
  }
  std::set<long> hinge_levels;
  for (const Constraint& c : chain.constraints())
    if (c.type == ConstraintType::GroundHinge) hinge_levels.insert(std::lround(c.point.y() * 1000.0));
  for (long zmm : hinge_levels) {
    const double z = zmm / 1000.0;
    if (std::abs(z) < 1e-9) continue;
    line(gx1, v.Y(z), gx2, v.Y(z), "stroke=\"#b3001b\" stroke-dasharray=\"10 3 2 3\"");
    text(gx1, v.Y(z) - 4, msg(lang, "draw.hinge_level") + " z = " + m2(z), "fill=\"#b3001b\"");
  }

  // Blocks.
  const bool many = chain.blocks().size() > 6;
  for (std::size_t i = 0; i < chain.blocks().size(); ++i) {
    const Block& b = chain.blocks()[i];
    std::string pts;
    for (const auto& p : b.polygon) pts += f1(v.X(p.x())) + "," + f1(v.Y(p.y())) + " ";
    o += "<polygon points=\"" + pts + "\" fill=\"" + (i % 2 ? "#d9cbb5" : "#e6dcc8") +
         "\" stroke=\"#5a4a32\" stroke-width=\"" + (many ? "0.6" : "1.2") + "\"/>\n";
  }

  // Loads.
  double self_total = 0.0;
  const double arrow = 34.0;
  for (const Load& l : chain.loads()) {
    const double X = v.X(l.point.x()), Y = v.Y(l.point.y());
    switch (l.type) {
      case LoadType::SelfWeight:
        self_total += l.weight;
        line(X, Y - (many ? 14 : 24), X, Y, "stroke=\"#222\" stroke-width=\"1.2\" marker-end=\"url(#arrowk)\"");
        if (!many) text(X - 6, Y - 12, "P = " + kn(l.weight), "font-size=\"10\" text-anchor=\"end\"");
        break;
      case LoadType::Weight:
        line(X, Y - arrow, X, Y, "stroke=\"#0b4f9c\" stroke-width=\"2\" marker-end=\"url(#arrowb)\"");
        text(X + 5, Y - arrow + 4,
             msg(lang, "load.weight") + " " + kn(l.weight) + (l.vertical ? "" : " (m)"), "fill=\"#0b4f9c\"");
        break;
      case LoadType::Force:
      case LoadType::Tie:
      case LoadType::Friction: {
        const double n = l.force.norm();
        if (!(n > 0.0)) break;
        const double ux = l.force.x() / n, uz = l.force.y() / n;
        // Arrow ending at the point of application (force pushing on it), or
        // starting from it for a tie (pulling inward).
        const bool pull = l.type == LoadType::Tie;
        const double x1 = pull ? X : X - ux * arrow * 1.4, y1 = pull ? Y : Y + uz * arrow * 1.4;
        const double x2 = pull ? X + ux * arrow * 1.4 : X, y2 = pull ? Y - uz * arrow * 1.4 : Y;
        const char* colour = l.type == LoadType::Tie ? "#2b7a2b" : "#8a3ea8";
        line(x1, y1, x2, y2,
             std::string("stroke=\"") + colour + "\" stroke-width=\"2.2\" marker-end=\"url(#arrowk)\"" +
                 (l.type == LoadType::Tie ? " stroke-dasharray=\"8 3\"" : ""));
        const std::string kind = l.type == LoadType::Tie ? "load.tie" : l.type == LoadType::Force ? "load.force" : "load.friction";
        text(std::min(x1, x2) - 4, std::min(y1, y2) - 6, msg(lang, kind) + " " + kn(n),
             std::string("text-anchor=\"end\" fill=\"") + colour + "\"");
        break;
      }
    }
  }
  double zc = 0.0;
  for (std::size_t i = 0; i < chain.blocks().size(); ++i) zc += chain.centroid(int(i)).y() / chain.blocks().size();
  if (many && self_total > 0.0)
    text(v.X(xmax) + 12, v.Y(zc) + 16,
         msg(lang, "draw.self_weights") + " (" + std::to_string(chain.blocks().size()) + ") ΣP = " + kn(self_total),
         "font-size=\"10\"");

  // Constraints: hinges (circles) and sliders (rollers).
  std::set<std::pair<long, long>> drawn;
  for (const Constraint& c : chain.constraints()) {
    const double X = v.X(c.point.x()), Y = v.Y(c.point.y());
    if (!drawn.insert({std::lround(X), std::lround(Y)}).second) continue;
    if (c.type == ConstraintType::Slider) {
      o += "<circle cx=\"" + f1(X + 6) + "\" cy=\"" + f1(Y) + "\" r=\"4\" fill=\"#fff\" stroke=\"#222\"/>\n";
      line(X + 11, Y - 12, X + 11, Y + 12, "stroke=\"#222\" stroke-width=\"2\"");
      text(X + 16, Y + 4, msg(lang, "draw.slider"), "font-size=\"10\"");
    } else if (c.type == ConstraintType::GroundHinge) {
      o += "<circle cx=\"" + f1(X) + "\" cy=\"" + f1(Y) + "\" r=\"5\" fill=\"#fff\" stroke=\"#b3001b\" "
           "stroke-width=\"2\"/>\n";
      text(X + 8, Y + 14, msg(lang, "draw.hinge") + " z = " + m2(c.point.y()), "fill=\"#b3001b\" font-size=\"10\"");
    } else if (!many) {  // a hinge between two blocks (joints of a sliced body are not drawn)
      o += "<circle cx=\"" + f1(X) + "\" cy=\"" + f1(Y) + "\" r=\"4\" fill=\"#fff\" stroke=\"#b3001b\" "
           "stroke-width=\"1.5\"/>\n";
      text(X + 7, Y + 4, msg(lang, "draw.hinge"), "fill=\"#b3001b\" font-size=\"10\"");
    }
  }

  // Control point.
  if (r.control_block >= 0) {
    const double X = v.X(r.control_point.x()), Y = v.Y(r.control_point.y());
    o += "<circle cx=\"" + f1(X) + "\" cy=\"" + f1(Y) + "\" r=\"6\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"/>\n";
    line(X - 8, Y, X + 8, Y, "stroke=\"#000\"");
    line(X, Y - 8, X, Y + 8, "stroke=\"#000\"");
    text(X + 10, Y - 8, msg(lang, "draw.control") + " (z = " + m2(r.control_point.y()) + ")", "font-size=\"10\"");
  }

  // Seismic action: outward (+x).
  const double sy = 18;
  line(W - 150, sy, W - 60, sy, "stroke=\"#b3001b\" stroke-width=\"2.5\" marker-end=\"url(#arrowr)\"");
  text(W - 155, sy + 4, msg(lang, "draw.seismic"), "text-anchor=\"end\" fill=\"#b3001b\"");
  text(W - 50, sy + 4, "x", "fill=\"#b3001b\"");
  o += "</svg>\n";
  return o;
}

}  // namespace assess

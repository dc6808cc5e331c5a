// case_file.cpp: the façade case JSON, version 1 (m, kN, kN/m^3 at the file
// edge; SI inside), and the kinematic assessment of the case.
#include "assess/assessment/case_file.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/dynamics/analysis_limits.hpp"
#include "assess/kinematic/code_rules.hpp"
#include "assess/kinematic/friction_overturning.hpp"
#include "assess/kinematic/horizontal_flexure.hpp"
#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/kinematic/tie_checks.hpp"
#include "assessment/plausibility.hpp"
#include "assess/support/error.hpp"
#include "assess/support/json_input.hpp"
#include "assess/assessment/site_block.hpp"
#include "assess/support/number_rules.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace assess {
namespace {

constexpr double kN = units::kN;

int block_ref(const JsonNode& n, const std::map<std::string, int>& names, int nb) {
  if (n.value().is_number_integer()) {
    const int i = n.value().get<int>();
    if (i < 0 || i >= nb) n.fail("block index " + std::to_string(i) + " does not exist (0.." + std::to_string(nb - 1) + ")");
    return i;
  }
  const std::string s = n.as_string();
  const auto it = names.find(s);
  if (it == names.end()) n.fail("no block named \"" + s + "\"");
  return it->second;
}

// A number strictly inside (lo, hi), e.g. a hinge between two restraints.
double open_interval(const JsonNode& n, const char* unit, double lo, double hi) {
  const double v = n.as_number(unit);
  if (!(v > lo && v < hi)) {
    std::ostringstream os;
    os << "value " << v << " out of range: expected in (" << lo << ", " << hi << ") " << unit;
    n.fail(os.str());
  }
  return v;
}

MechanismSet parse_blocks(const JsonNode& m) {
  m.allow_only({"type", "blocks", "constraints", "loads", "Z_m"});
  std::vector<Block> blocks;
  std::map<std::string, int> names;
  for (const JsonNode& b : m.array("blocks", 1)) {
    b.allow_only({"name", "polygon", "unit_weight", "length"});
    Block blk;
    blk.name = b.find("name") ? b.string("name") : "block " + std::to_string(blocks.size());
    for (const JsonNode& v : b.array("polygon", 3)) blk.polygon.push_back(v.as_point(rules::coordinate_m));
    // Degenerate polygons named as such, with the JSON path (kinematic/chain.hpp).
    if (const std::string d = polygon_defect(blk.polygon); !d.empty()) b.at("polygon").fail(d);
    blk.unit_weight = b.number("unit_weight", rules::block_unit_weight_kN_m3) * kN;
    blk.length = b.number("length", rules::dimension_m);
    names[blk.name] = static_cast<int>(blocks.size());
    blocks.push_back(blk);
  }
  const int nb = static_cast<int>(blocks.size());
  // Geometry checks that need a path: points on blocks.
  auto contains = [&](int i, const Eigen::Vector2d& p) {
    // Inside or on the boundary (as Chain::contains), checked here so that
    // the error names the JSON path.
    const auto& v = blocks[i].polygon;
    bool inside = false;
    for (std::size_t a = 0, c = v.size() - 1; a < v.size(); c = a++) {
      const Eigen::Vector2d e = v[a] - v[c];
      const double l2 = e.squaredNorm();
      const double t = l2 > 0 ? std::clamp((p - v[c]).dot(e) / l2, 0.0, 1.0) : 0.0;
      if ((v[c] + t * e - p).norm() <= 1e-9 * std::max(1.0, std::sqrt(l2))) return true;
      if ((v[a].y() > p.y()) != (v[c].y() > p.y()) &&
          p.x() < v[c].x() + (p.y() - v[c].y()) * (v[a].x() - v[c].x()) / (v[a].y() - v[c].y()))
        inside = !inside;
    }
    return inside;
  };
  std::vector<Constraint> cons;
  for (const JsonNode& c : m.array("constraints", 1)) {
    c.allow_only({"type", "name", "block", "blocks", "point", "direction"});
    Constraint k;
    const std::string type = c.choice("type", {"ground_hinge", "hinge", "slider"});
    k.name = c.find("name") ? c.string("name") : type + " " + std::to_string(cons.size());
    k.point = c.point("point");
    if (type == "hinge") {
      k.type = ConstraintType::Hinge;
      const auto bs = c.array("blocks", 2);
      k.block = block_ref(bs[0], names, nb);
      k.other = block_ref(bs[1], names, nb);
    } else {
      k.type = type == "slider" ? ConstraintType::Slider : ConstraintType::GroundHinge;
      k.block = block_ref(c.at("block"), names, nb);
      if (type == "slider") k.direction = c.find("direction") ? c.point("direction") : Eigen::Vector2d(0, 1);
    }
    for (int b : {k.block, k.other})
      if (b >= 0 && !contains(b, k.point))
        c.at("point").fail("the point is not on block \"" + blocks[b].name + "\"");
    cons.push_back(k);
  }
  std::vector<Load> loads;
  if (m.find("loads"))
    for (const JsonNode& l : m.array("loads")) {
      l.allow_only({"type", "name", "block", "point", "weight", "bears", "seismic", "force"});
      Load ld;
      const std::string type = l.choice("type", {"weight", "force", "tie", "friction"});
      ld.name = l.find("name") ? l.string("name") : type + " " + std::to_string(loads.size());
      ld.point = l.point("point");
      if (l.find("block")) {
        ld.block = block_ref(l.at("block"), names, nb);
        if (!contains(ld.block, ld.point)) l.at("point").fail("the point is not on block \"" + blocks[ld.block].name + "\"");
      } else {
        std::vector<int> in;
        for (int i = 0; i < nb; ++i)
          if (contains(i, ld.point)) in.push_back(i);
        if (in.empty()) l.at("point").fail("the load lies outside every block");
        if (in.size() > 1)
          l.fail("the point lies on blocks \"" + blocks[in[0]].name + "\" and \"" + blocks[in[1]].name +
                 "\": name the block with \"block\"");
        ld.block = in[0];
      }
      if (type == "weight") {
        ld.type = LoadType::Weight;
        ld.weight = l.number("weight", rules::weight_kN) * kN;
        ld.vertical = l.boolean_or("bears", true);
        ld.seismic = l.boolean_or("seismic", true);
      } else if (type == "force") {
        ld.type = LoadType::Force;
        ld.force = l.at("force").as_point(rules::force_kN) * kN;
      } else {
        ld.type = type == "tie" ? LoadType::Tie : LoadType::Friction;
        const double F = l.number("force", rules::weight_kN) * kN;
        ld.force = Eigen::Vector2d(type == "tie" ? -F : F, 0.0);
      }
      loads.push_back(ld);
    }
  MechanismSet set;
  set.type = "blocks";
  set.parameter_name = "-";
  // Z: the mean height of the constraints to the building (ground hinges, sliders).
  double zs = 0.0;
  int nz = 0;
  for (const Constraint& c : cons)
    if (c.type != ConstraintType::Hinge) {
      zs += c.point.y();
      ++nz;
    }
  const double Zc = m.find("Z_m") ? m.number("Z_m", rules::offset_m) : (nz ? zs / nz : 0.0);
  set.candidates.push_back({"explicit blocks", Chain(blocks, cons, loads), Zc, 0.0});
  return set;
}

// The crack angle of a wedge (composite and corner overturning): given
// (beta_deg), from the masonry texture (unit_length, course_height), or
// searched between beta_min_deg and beta_max_deg.
template <class Params>
void parse_crack_angle(const JsonNode& m, Params& p) {
  if (m.find("beta_deg")) p.beta_deg = open_interval(m.at("beta_deg"), "deg", 0.0, 90.0);
  if (m.find("unit_length")) p.unit_length = m.number("unit_length", rules::dimension_m);
  if (m.find("course_height")) p.course_height = m.number("course_height", rules::dimension_m);
  p.beta_min_deg = m.number_or("beta_min_deg", p.beta_min_deg, "deg", 0.0, 90.0);
  p.beta_max_deg = m.number_or("beta_max_deg", p.beta_max_deg, "deg", 0.0, 90.0);
  p.search_points = m.integer_or("search_points", p.search_points, 2, 100);
}

// ---- Issue 33: horizontal flexure, friction overturning, roof thrust, the
// corner about any axis (m, kN, kN/m, kN m, MPa at the file's edge) --------

RoofSpec parse_roof(const JsonNode& r, double top_thickness) {
  r.allow_only({"scheme", "load", "span", "pitch_deg", "seat_from_inner_face", "held"});
  RoofSpec roof;
  const std::string scheme = r.choice("scheme", {"a_frame", "strut", "ridge_beam", "truss"});
  roof.scheme = scheme == "a_frame"  ? RoofScheme::AFrame
                : scheme == "strut"  ? RoofScheme::Strut
                : scheme == "truss"  ? RoofScheme::Truss
                                     : RoofScheme::RidgeBeam;
  roof.load = r.number("load", "kN/m^2", 0.0) * kN;
  roof.span = r.positive("span", "m");
  roof.pitch_deg = open_interval(r.at("pitch_deg"), "deg", 0.0, 90.0);
  roof.seat_from_inner_face = r.number_or("seat_from_inner_face", 0.5 * top_thickness, "m", 0.0, top_thickness);
  roof.held = r.boolean_or("held", false);  // issue 38: the roof's mass moves with the wall unless held
  return roof;
}

// Rules of the issue-33 mechanisms' quantities that number_rules.hpp has no name for.
// The caps of a horizontal flexure (docs/reliability.md, "Bounds and limits").
constexpr std::size_t flexure_strips_max = 20, flexure_openings_max = 6;
constexpr NumberRule moment_kNm{"kN m", 0.0, 1e6, false, false, "0 to 1 GN m"};
constexpr NumberRule line_load_kN_m{"kN/m", 0.0, 1e6, false, false, "0 to 1 GN per metre of wall"};

MechanismSet parse_horizontal_flexure(const JsonNode& m, double FC) {
  m.allow_only({"type", "span", "thickness", "unit_weight", "fm_MPa", "stress_block", "supports", "ring_beam_moment",
                "strips", "search_points"});
  HorizontalFlexureParams p;
  // The number rules of case files (support/number_rules.hpp; issue 39: fm_MPa 1e-9 was taken).
  p.span = m.number("span", rules::dimension_m);
  p.thickness = m.number("thickness", rules::dimension_m);
  p.unit_weight = m.number("unit_weight", rules::unit_weight_kN_m3) * kN;
  // The strength at the hinges: the mean strength divided by FC (C8.5.4, C8.7.1.2.1 d)).
  p.strength = m.number("fm_MPa", rules::stress_MPa) * 1e6 / FC;
  if (m.find("stress_block"))
    p.stress_block = m.choice("stress_block", {"rectangular", "triangular"}) == "triangular" ? StressBlock::Triangular
                                                                                            : StressBlock::Rectangular;
  const JsonNode sup = m.at("supports");
  sup.allow_only({"rigid", "tie", "side_wall_friction", "side_wall_load", "restraint"});
  p.rigid_supports = sup.boolean_or("rigid", false);
  p.tie = sup.number_or("tie", 0.0, rules::weight_kN) * kN;
  p.side_wall_friction = sup.number_or("side_wall_friction", 0.0, "-", 0.0, 2.0);
  p.side_wall_load = sup.number_or("side_wall_load", 0.0, rules::weight_kN) * kN;
  if ((p.side_wall_friction > 0.0) != (p.side_wall_load > 0.0))
    sup.fail("the side walls' restraint needs both \"side_wall_friction\" (-) and \"side_wall_load\" (kN)");
  p.restraint = sup.number_or("restraint", 0.0, rules::weight_kN) * kN;
  if (p.rigid_supports && (p.tie > 0.0 || p.side_wall_load > 0.0 || p.restraint > 0.0))
    sup.fail("give \"rigid\": true or the restraint's parts (tie, side walls, restraint), not both");
  if (!p.rigid_supports && !(p.tie > 0.0 || p.side_wall_load > 0.0 || p.restraint > 0.0))
    sup.fail("expected \"rigid\": true or at least one of \"tie\" (kN), \"side_wall_friction\" with "
             "\"side_wall_load\" (kN), \"restraint\" (kN): without a restraint no horizontal arch forms");
  p.ring_beam_moment = m.number_or("ring_beam_moment", 0.0, moment_kNm) * kN;
  // Bounds that keep a run short whatever the input (docs/reliability.md, "Round five"): each strip is a
  // candidate whose chain has 2 blocks per opening, and a kinematic analysis grows with their square. At
  // the caps (20 strips of 6 openings, 200 search points) a mechanism takes 0.2-0.3 s of CPU; at 50 strips
  // of 20 openings it took 57 s (issue 39; 4 s with the closed-form search).
  if (m.at("strips").value().is_array() && m.at("strips").value().size() > flexure_strips_max)
    m.at("strips").fail("at most " + std::to_string(flexure_strips_max) + " strips (one candidate each: one per half "
                        "metre of a 10 m wall)");
  for (const JsonNode& st : m.array("strips", 1)) {
    st.allow_only({"base_z", "height", "carried_weight", "openings", "middle_hinge"});
    if (st.find("openings") && st.at("openings").value().is_array() &&
        st.at("openings").value().size() > flexure_openings_max)
      st.at("openings").fail("at most " + std::to_string(flexure_openings_max) + " openings per strip (the windows "
                             "of a span between two transverse walls; each adds two blocks to the strip's chain)");
    HorizontalStrip s;
    s.base_z = st.number_or("base_z", 0.0, rules::offset_m);
    s.height = st.number("height", rules::dimension_m);
    s.carried_weight = st.number_or("carried_weight", 0.0, line_load_kN_m) * kN;
    if (st.find("middle_hinge")) s.middle_hinge = open_interval(st.at("middle_hinge"), "m", 0.0, p.span);
    if (st.find("openings"))
      for (const JsonNode& o : st.array("openings")) {
        o.allow_only({"from", "to", "height"});
        StripOpening op;
        op.from = o.number("from", "m", 0.0, p.span);
        op.to = o.number("to", "m", 0.0, p.span);
        if (!(op.to > op.from)) o.at("to").fail("expected to > from (m along the wall from the first support)");
        op.height = open_interval(o.at("height"), "m", 0.0, s.height);
        s.openings.push_back(op);
      }
    p.strips.push_back(s);
  }
  p.search_points = m.integer_or("search_points", p.search_points, 3, 200);
  return horizontal_flexure(p);
}

MechanismSet parse_friction_overturning(const JsonNode& m) {
  m.allow_only({"type", "height", "thickness", "length", "unit_weight", "base_z", "side_walls", "side_thickness",
                "side_length", "unit_length", "course_height", "friction", "activation", "side_load", "side_load_held",
                "top_weight", "top_weight_held", "tie", "floors"});
  FrictionOverturningParams p;
  p.height = m.positive("height", "m");
  p.thickness = m.positive("thickness", "m");
  p.length = m.positive("length", "m");
  p.unit_weight = m.positive("unit_weight", "kN/m^3") * kN;
  p.base_z = m.number_or("base_z", 0.0, "m", 0.0);
  p.side_walls = m.integer_or("side_walls", 2, 1, 2);
  p.side_thickness = m.positive("side_thickness", "m");
  p.side_length = m.positive("side_length", "m");
  p.unit_length = m.positive("unit_length", "m");
  p.course_height = m.positive("course_height", "m");
  p.friction = m.number("friction", "-", 1e-6, 2.0);
  p.activation = m.number_or("activation", 1.0, "-", 0.0, 1.0);
  p.side_load = m.number_or("side_load", 0.0, "kN/m", 0.0) * kN;
  p.side_load_held = m.boolean_or("side_load_held", false);  // issue 38: every load moves unless held
  p.top_weight = m.number_or("top_weight", 0.0, "kN", 0.0) * kN;
  p.top_weight_held = m.boolean_or("top_weight_held", false);
  p.tie = m.number_or("tie", 0.0, "kN", 0.0) * kN;
  if (m.find("floors"))
    for (const JsonNode& f : m.array("floors")) {
      f.allow_only({"weight", "z", "distance_from_inner_face", "friction", "held", "seat_length"});
      SupportedFloor fl;
      fl.weight = f.number("weight", "kN", 0.0) * kN;
      fl.z = open_interval(f.at("z"), "m", p.base_z, p.base_z + p.height + 1e-9);
      fl.distance_from_inner_face = f.number_or("distance_from_inner_face", 0.5 * p.thickness, "m", 0.0, p.thickness);
      fl.friction = f.number_or("friction", 0.0, "-", 0.0, 2.0);
      fl.held = f.boolean_or("held", false);  // issue 38: moves with the façade unless held
      if (f.find("seat_length")) fl.seat_length = f.positive("seat_length", "m");
      p.floors.push_back(fl);
    }
  return friction_overturning(p);
}

CornerWall parse_corner_wall(const JsonNode& w) {
  w.allow_only({"thickness", "length", "beta_deg", "unit_length", "course_height", "crack_reach", "openings"});
  CornerWall c;
  if (w.find("thickness")) c.thickness = w.positive("thickness", "m");
  if (w.find("length")) c.length = w.positive("length", "m");
  const int ways = w.has("beta_deg") + (w.has("unit_length") || w.has("course_height")) + w.has("crack_reach");
  if (ways > 1) w.fail("give the crack by one of \"beta_deg\", the texture (\"unit_length\", \"course_height\") or \"crack_reach\"");
  if (w.find("beta_deg")) c.beta_deg = open_interval(w.at("beta_deg"), "deg", 0.0, 90.0);
  if (w.find("unit_length")) c.unit_length = w.positive("unit_length", "m");
  if (w.find("course_height")) c.course_height = w.positive("course_height", "m");
  if (w.find("crack_reach")) c.crack_reach = w.positive("crack_reach", "m");
  if (w.find("openings") && w.at("openings").value().is_array() && w.at("openings").value().size() > 20)
    w.at("openings").fail("at most 20 openings per wall");
  if (w.find("openings"))
    for (const JsonNode& o : w.array("openings")) {
      o.allow_only({"from", "to", "bottom", "top"});
      CornerOpening op;
      op.from = o.number("from", "m", 0.0);
      op.to = o.number("to", "m", 0.0);
      op.bottom = o.number("bottom", "m", 0.0);
      op.top = o.number("top", "m", 0.0);
      if (!(op.to > op.from)) o.at("to").fail("expected to > from (m along the wall from the corner's outer face)");
      if (!(op.top > op.bottom)) o.at("top").fail("expected top > bottom (m above the foundation)");
      c.openings.push_back(op);
    }
  return c;
}

MechanismSet parse_corner(const JsonNode& m) {
  // Issue 38: the axis is no longer scanned (an intermediate axis never
  // governs, docs/theory/mechanisms.md §4.2): the former scan's keys named.
  for (const char* k : {"axis_min_deg", "axis_max_deg", "axis_points"})
    if (m.has(k))
      m.at(k).fail("the axis is not scanned: the two axes along the walls' outer faces (0 and 90 deg) are the "
                   "candidates, an intermediate axis never governs (docs/theory/mechanisms.md §4.2); remove \"" +
                   std::string(k) + "\", or give \"axis_deg\" (deg) for one axis");
  m.allow_only({"type", "height", "thickness", "unit_weight", "wall_length", "base_z", "top_weight", "top_weight_held",
                "thrust", "tie", "beta_deg", "unit_length", "course_height", "beta_min_deg", "beta_max_deg",
                "search_points", "wall_a", "wall_b", "axis_deg"});
  CornerOverturningParams p;
  p.height = m.positive("height", "m");
  if (m.find("thickness")) p.thickness = m.positive("thickness", "m");
  p.unit_weight = m.positive("unit_weight", "kN/m^3") * kN;
  if (m.find("wall_length")) p.wall_length = m.positive("wall_length", "m");
  p.base_z = m.number_or("base_z", 0.0, "m", 0.0);
  p.top_weight = m.number_or("top_weight", 0.0, "kN", 0.0) * kN;
  p.top_weight_held = m.boolean_or("top_weight_held", false);  // issue 38
  p.thrust = m.number_or("thrust", 0.0, "kN") * kN;
  p.tie = m.number_or("tie", 0.0, "kN", 0.0) * kN;
  parse_crack_angle(m, p);
  if (m.find("wall_a")) p.wall_a = parse_corner_wall(m.at("wall_a"));
  if (m.find("wall_b")) p.wall_b = parse_corner_wall(m.at("wall_b"));
  for (const char* k : {"thickness", "length"})
    for (const auto& [w, name] : {std::pair<const CornerWall*, const char*>{&p.wall_a, "wall_a"}, {&p.wall_b, "wall_b"}}) {
      const bool given = std::string(k) == "thickness" ? w->thickness.has_value() : w->length.has_value();
      const bool common = std::string(k) == "thickness" ? m.has("thickness") : m.has("wall_length");
      if (!given && !common)
        m.fail(std::string("missing \"") + (std::string(k) == "thickness" ? "thickness" : "wall_length") +
               "\" (m): give it for both walls or \"" + k + "\" in \"" + name + "\"");
    }
  // An opening must lie beyond the corner pier, i.e. beyond the other wall's thickness.
  for (const auto& [w, other, name] : {std::tuple<const CornerWall*, const CornerWall*, const char*>{&p.wall_a, &p.wall_b, "wall_a"},
                                       {&p.wall_b, &p.wall_a, "wall_b"}}) {
    const double t_other = other->thickness.value_or(p.thickness);
    const double end = t_other + w->length.value_or(p.wall_length), top = p.base_z + p.height;
    for (std::size_t i = 0; i < w->openings.size(); ++i) {
      const JsonNode o = m.at(name).at("openings").at(i);
      if (w->openings[i].from < t_other)
        o.at("from").fail("the opening starts " + number_for_message(w->openings[i].from) + " m from the corner's outer "
                          "face, inside the corner pier (the other wall's thickness, " + number_for_message(t_other) +
                          " m): no corner mechanism with an opening through the pier");
      // Within the wall (issue 39: an opening beyond it was clipped without a word).
      if (w->openings[i].to > end + 1e-9)
        o.at("to").fail("the opening ends " + number_for_message(w->openings[i].to) + " m from the corner's outer face, "
                        "beyond the wall's end (" + number_for_message(end) + " m: the other wall's thickness and the "
                        "wall's length)");
      if (w->openings[i].top > top + 1e-9)
        o.at("top").fail("the opening's top " + number_for_message(w->openings[i].top) + " m is above the wall's top (" +
                         number_for_message(top) + " m above the foundation: base_z + height)");
    }
  }
  if (m.find("axis_deg")) p.axis_deg = m.number("axis_deg", "deg", 0.0, 90.0);
  // A searched crack angle (at most 100) times the two axes: at most 200 candidates.
  return corner_overturning(p);
}

MechanismSet parse_mechanism(const JsonNode& m, double FC) {
  const std::string type =
      m.choice("type", {"blocks", "simple_overturning", "vertical_flexure", "composite_overturning", "gable_overturning",
                        "corner_overturning", "horizontal_flexure", "friction_overturning", "roof_thrust"});
  if (type == "blocks") return parse_blocks(m);
  if (type == "simple_overturning" || type == "roof_thrust") {
    if (type == "roof_thrust")
      m.allow_only({"type", "storeys", "unit_weight", "length", "hinge_level", "hinge_setback", "roof"});
    else
      m.allow_only({"type", "storeys", "unit_weight", "length", "hinge_level", "hinge_setback"});
    SimpleOverturningParams p;
    for (const JsonNode& s : m.array("storeys", 1)) {
      s.allow_only({"height", "thickness", "floor_weight", "floor_distance_from_inner_face", "floor_bears", "floor_held",
                    "thrust", "tie"});
      Storey st;
      st.height = s.number("height", rules::dimension_m);
      st.thickness = s.number("thickness", rules::dimension_m);
      st.floor_weight = s.number_or("floor_weight", 0.0, rules::weight_kN) * kN;
      st.floor_distance_from_inner_face = s.number_or("floor_distance_from_inner_face", 0.0, "m", 0.0, st.thickness);
      st.floor_bears = s.boolean_or("floor_bears", true);
      st.floor_held = s.boolean_or("floor_held", false);  // issue 38: the floor's mass moves with the wall unless held
      if (st.floor_held && !st.floor_bears && st.floor_weight > 0.0)
        s.at("floor_held").fail("a floor that neither bears (\"floor_bears\": false) nor pushes (\"floor_held\": true) "
                                "acts on nothing: drop it or give one of the two");
      st.thrust = s.number_or("thrust", 0.0, rules::force_kN) * kN;
      st.tie = s.number_or("tie", 0.0, rules::weight_kN) * kN;
      p.storeys.push_back(st);
    }
    p.unit_weight = m.number("unit_weight", rules::unit_weight_kN_m3) * kN;
    p.length = m.number("length", rules::dimension_m);
    if (m.find("hinge_level")) p.hinge_level = m.integer("hinge_level", 0, static_cast<int>(p.storeys.size()) - 1);
    p.hinge_setback = m.number_or("hinge_setback", 0.0, rules::offset_m);
    if (type == "roof_thrust") {
      p.roof = parse_roof(m.at("roof"), p.storeys.back().thickness);
      return roof_thrust_overturning(p);
    }
    return simple_overturning(p);
  }
  if (type == "vertical_flexure") {
    m.allow_only({"type", "height", "thickness", "unit_weight", "length", "base_z", "top_load",
                  "top_load_distance_from_inner_face", "hinge_height"});
    VerticalFlexureParams p;
    p.height = m.number("height", rules::dimension_m);
    p.thickness = m.number("thickness", rules::dimension_m);
    p.unit_weight = m.number("unit_weight", rules::unit_weight_kN_m3) * kN;
    p.length = m.number("length", rules::dimension_m);
    p.base_z = m.number_or("base_z", 0.0, rules::offset_m);
    p.top_load = m.number_or("top_load", 0.0, rules::weight_kN) * kN;
    p.top_load_distance_from_inner_face = m.number_or("top_load_distance_from_inner_face", 0.0, "m", 0.0, p.thickness);
    if (m.find("hinge_height")) p.hinge_height = open_interval(m.at("hinge_height"), "m", 0.0, p.height);
    return vertical_flexure(p);
  }
  if (type == "composite_overturning") {
    m.allow_only({"type", "height", "thickness", "length", "unit_weight", "side_thickness", "side_walls",
                  "side_length", "base_z", "top_weight", "top_weight_held", "tie", "beta_deg", "unit_length", "course_height",
                  "beta_min_deg", "beta_max_deg", "search_points"});
    CompositeOverturningParams p;
    p.height = m.number("height", rules::dimension_m);
    p.thickness = m.number("thickness", rules::dimension_m);
    p.length = m.number("length", rules::dimension_m);
    p.unit_weight = m.number("unit_weight", rules::unit_weight_kN_m3) * kN;
    p.side_thickness = m.number("side_thickness", rules::dimension_m);
    p.side_walls = m.integer_or("side_walls", 2, 1, 2);
    p.side_length = m.number("side_length", rules::dimension_m);
    p.base_z = m.number_or("base_z", 0.0, rules::offset_m);
    p.top_weight = m.number_or("top_weight", 0.0, rules::weight_kN) * kN;
    p.top_weight_held = m.boolean_or("top_weight_held", false);  // issue 38: moves with the façade unless held
    p.tie = m.number_or("tie", 0.0, rules::weight_kN) * kN;
    parse_crack_angle(m, p);
    return composite_overturning(p);
  }
  if (type == "corner_overturning") return parse_corner(m);
  if (type == "horizontal_flexure") return parse_horizontal_flexure(m, FC);
  if (type == "friction_overturning") return parse_friction_overturning(m);
  m.allow_only({"type", "width", "height", "thickness", "unit_weight", "base_z", "ridge_weight", "ridge_weight_held",
                "ridge_thrust", "tie", "slices"});
  GableParams p;
  p.width = m.number("width", rules::dimension_m);
  p.height = m.number("height", rules::dimension_m);
  p.thickness = m.number("thickness", rules::dimension_m);
  p.unit_weight = m.number("unit_weight", rules::unit_weight_kN_m3) * kN;
  p.base_z = m.number_or("base_z", 0.0, rules::offset_m);
  p.ridge_weight = m.number_or("ridge_weight", 0.0, rules::weight_kN) * kN;
  p.ridge_weight_held = m.boolean_or("ridge_weight_held", false);  // issue 38: moves with the gable unless held
  p.ridge_thrust = m.number_or("ridge_thrust", 0.0, rules::force_kN) * kN;
  p.tie = m.number_or("tie", 0.0, rules::weight_kN) * kN;
  p.slices = m.integer_or("slices", p.slices, 2, 200);
  return gable_overturning(p);
}

SiteSpec parse_site(const JsonNode& s) {
  s.allow_only({"lat", "lon", "comune", "province", "island", "hazard", "soil", "topography", "h_over_H", "VN_years",
                "use_class", "CU"});
  SiteSpec spec;
  const int ways = (s.has("lat") || s.has("lon")) + s.has("comune") + s.has("island") + s.has("hazard");
  if (ways != 1) s.fail("give exactly one of {\"lat\", \"lon\"}, \"comune\", \"island\" or \"hazard\"");
  if (s.has("province") && !s.has("comune")) s.fail("\"province\" goes with \"comune\"");
  if (s.has("comune")) {
    // The municipal seat's coordinates (hazard/comuni.hpp); the report prints them.
    try {
      const Comune& c = ComuneTable::shipped()->find(s.string("comune"), s.has("province") ? s.string("province") : "");
      spec.lat = c.lat;
      spec.lon = c.lon;
      spec.comune = c.describe();
    } catch (const InputError& e) {
      s.at("comune").fail(e.what());
    }
  }
  if (s.has("lat") || s.has("lon")) {
    spec.lat = s.number("lat", rules::latitude_deg);
    spec.lon = s.number("lon", rules::longitude_deg);
  }
  if (s.has("island")) spec.island = s.string("island");
  if (s.has("hazard")) {
    const JsonNode h = s.at("hazard");
    h.allow_only({"SLO", "SLD", "SLV", "SLC"});
    for (const char* ls : {"SLO", "SLD", "SLV", "SLC"})
      if (const auto e = h.find(ls)) {
        e->allow_only({"ag_g", "F0", "Tc_star", "TR"});
        HazardParams p;
        p.ag_g = e->number("ag_g", rules::ag_g);
        p.F0 = e->number("F0", rules::F0);
        p.Tc_star = e->number("Tc_star", rules::Tc_star_s);
        p.TR = e->number_or("TR", 0.0, rules::return_period_years);
        p.tr_requested = p.TR;
        spec.given[parse_limit_state(ls)] = p;
      }
  }
  if (s.has("soil")) spec.conditions.soil = parse_soil_class(s.choice("soil", {"A", "B", "C", "D", "E"}));
  if (s.has("topography")) spec.conditions.topography = parse_topography(s.choice("topography", {"T1", "T2", "T3", "T4"}));
  spec.conditions.h_over_H = s.number_or("h_over_H", 1.0, rules::relative_height);
  spec.vn_years = s.number_or("VN_years", 50.0, rules::nominal_life_years);
  if (s.has("use_class") && s.has("CU")) s.fail("give \"use_class\" or \"CU\", not both");
  if (s.has("use_class")) spec.cu = use_coefficient(parse_use_class(s.choice("use_class", {"I", "II", "III", "IV"})));
  if (s.has("CU")) spec.cu = s.number("CU", rules::use_coefficient);
  // Hazard availability now (a point outside the grid, an unknown island),
  // with the JSON path in the message.
  try {
    const Site check(spec);
  } catch (const InputError& e) {
    s.fail(e.what());
  }
  // The subsoil category moves every demand (S = SS ST, TC = CC TC*): no
  // default is assumed (issue 41: a missing soil ran as A, a silent default).
  if (!s.has("soil"))
    s.fail_missing("soil", "the subsoil category of NTC 2018 Tab. 3.2.II, \"A\", \"B\", \"C\", \"D\" or \"E\" "
                           "(it sets S = SS ST and TC = CC TC* of every demand; no default is assumed)");
  return spec;
}

// Unit weights at most limits::unit_weight_max_N_m3 (1e4 kN/m^3): 1e300
// made every weight, energy and period inf ("period T = inf s").
void check_unit_weights(const JsonNode& mech) {
  const double hi = limits::unit_weight_max_N_m3 / kN;
  if (!mech.is_object()) return;
  if (const auto u = mech.find("unit_weight"); u && u->value().is_number()) u->as_number("kN/m^3", 0.0, hi);
  if (const auto bs = mech.find("blocks"); bs && bs->value().is_array())
    for (std::size_t i = 0; i < bs->value().size(); ++i)
      if (const auto u = bs->at(i).find("unit_weight"); u && u->value().is_number()) u->as_number("kN/m^3", 0.0, hi);
}

// Plausibility of the mechanism's dimensions (already validated as numbers):
// thickness, height, unit weight and slenderness (plausibility.hpp).
std::vector<std::string> input_warnings(const nlohmann::json& mech, const std::string& file) {
  namespace pl = plausibility;
  std::vector<std::string> w;
  const std::string base = file + ": /mechanism";
  auto num = [](const nlohmann::json& o, const char* k) -> std::optional<double> {
    if (o.is_object() && o.contains(k) && o.at(k).is_number()) return o.at(k).get<double>();
    return std::nullopt;
  };
  auto thickness = [&](const std::string& where, double t) {
    pl::range(w, where, t, "m", pl::thickness_min_m, pl::thickness_max_m,
              "a masonry wall is 0.05-3 m thick; was it typed in cm?");
  };
  auto height = [&](const std::string& where, double h) {
    if (h > pl::height_max_m)
      w.push_back(where + " = " + pl::number(h) + " m is over " + pl::number(pl::height_max_m) +
                  " m: a tower, not a façade; was it typed in cm? (the run goes on with " + pl::number(h) + " m)");
  };
  auto slender = [&](const std::string& where, double h, double t) {
    if (t > 0.0 && h / t > pl::slenderness_max)
      w.push_back(where + ": the wall is thinner than 1/" + pl::number(pl::slenderness_max) + " of its height (h = " +
                  pl::number(h) + " m, t = " + pl::number(t) + " m, h/t = " + pl::number(h / t) +
                  "): far more slender than load-bearing masonry; check the thickness (m) and the height (m)");
  };
  auto unit_weight = [&](const std::string& where, double g) {
    pl::range(w, where, g, "kN/m^3", pl::unit_weight_min_kN_m3, pl::unit_weight_max_kN_m3,
              "masonry weighs about 12-22 kN/m^3; 1800 would be kg/m^3 (divide by 102)");
  };
  if (const auto g = num(mech, "unit_weight")) unit_weight(base + "/unit_weight", *g);
  if (const auto t = num(mech, "thickness")) thickness(base + "/thickness", *t);
  if (const auto t = num(mech, "side_thickness")) thickness(base + "/side_thickness", *t);
  if (const auto h = num(mech, "height")) height(base + "/height", *h);
  if (const auto h = num(mech, "height"))
    if (const auto t = num(mech, "thickness")) slender(base, *h, *t);
  if (mech.is_object() && mech.contains("storeys") && mech.at("storeys").is_array()) {
    const nlohmann::json& st = mech.at("storeys");
    for (std::size_t i = 0; i < st.size(); ++i) {
      const std::string p = base + "/storeys/" + std::to_string(i);
      const auto t = num(st[i], "thickness"), h = num(st[i], "height");
      if (t) thickness(p + "/thickness", *t);
      if (h) height(p + "/height", *h);
      if (t && h) slender(p, *h, *t);
    }
  }
  if (mech.is_object() && mech.contains("blocks") && mech.at("blocks").is_array()) {
    const nlohmann::json& bl = mech.at("blocks");
    for (std::size_t i = 0; i < bl.size(); ++i)
      if (const auto g = num(bl[i], "unit_weight"); g && *g > 0.0)
        unit_weight(base + "/blocks/" + std::to_string(i) + "/unit_weight", *g);
  }
  return w;
}


// ---- Issues 23, 29: tie rods ("ties", "design") -----------------------------
// File units: mm (rod, thread, anchor), mm^2, MPa, kN, m (point, lengths,
// layout); SI inside. Bounds: tie_catalogue::bounds. docs/user/case-file.md §Ties.

namespace TB = tie_catalogue::bounds;

// A number as printed in the messages (6 significant digits, no trailing zeros).
std::string tnum(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

const tie_catalogue::SteelGrade& grade_of(const JsonNode& n, const std::string& key, std::string& grade) {
  grade = n.find(key) ? n.choice(key, {"S235", "S275", "S355", "B450C"}) : "S275";
  return *tie_catalogue::find_grade(grade);
}

// The layout of a level along its wall: its length and either the count of
// ties or their largest spacing (count = ceil(length / spacing)); the edge
// distance (default: half the tributary length).
TieLayout parse_layout(const JsonNode& t) {
  TieLayout L;
  L.wall_length = t.number("wall_length_m", "m", TB::wall_length_min, TB::wall_length_max);
  if (t.has("count") == t.has("spacing_m"))
    t.fail("give exactly one of \"count\" (ties on the wall, an integer) or \"spacing_m\" (their largest spacing, m)");
  if (t.has("count")) {
    L.count = t.integer("count", 1, TB::count_max);
  } else {
    const double s = t.number("spacing_m", "m", TB::spacing_min, TB::spacing_max);
    const double n = std::ceil(L.wall_length / s - 1e-9);
    if (n > TB::count_max)
      t.at("spacing_m").fail("gives " + std::to_string(static_cast<long long>(n)) + " ties on the " +
                             tnum(L.wall_length) + " m wall: expected at most " + std::to_string(TB::count_max));
    L.count = std::max(1, static_cast<int>(n));
  }
  const double tributary = L.wall_length / L.count;
  L.edge_distance = t.number_or("edge_distance_m", tributary / 2.0, "m", 0.0, L.wall_length / 2.0);
  if (!(L.edge_distance > 0.0)) t.at("edge_distance_m").fail("expected > 0 m");
  if (L.count > 1 && !(L.centre_spacing() >= TB::spacing_min))
    t.fail("the layout puts the ties " + tnum(L.centre_spacing()) + " m apart: expected at least " +
           tnum(TB::spacing_min) + " m (wall_length_m, count, edge_distance_m)");
  return L;
}

// The fields a tie level shares with a level to design (no rod, no anchor).
// Issue 37: the wall around the anchors (its crown, the load on it, its
// openings), the masonry's sliding parameters, the temperature variation and
// the corrosion allowance; the crown and the unit weight default to the block
// the tie holds (resolve_ties below).
void parse_tie_common(const JsonNode& t, Tie& tie, double FC, std::size_t index) {
  tie.name = t.find("name") ? t.string("name") : "tie " + std::to_string(index + 1);
  tie.point = t.point("point");
  if (t.find("block")) tie.block = t.integer("block", 0, 1000000);
  if (t.find("direction")) {
    tie.direction = t.at("direction").as_point("-");
    if (!(tie.direction.norm() > 1e-9) || !tie.direction.allFinite())
      t.at("direction").fail("expected a non-zero direction [dx, dz] (-), e.g. [-1, 0] inward");
    tie.direction.normalize();
  }
  tie.free_length = t.number("free_length_m", "m", TB::free_length_min, TB::free_length_max);
  const JsonNode m = t.at("masonry");
  m.allow_only({"fm_MPa", "tau_MPa", "thickness_m", "FC", "gamma_M", "fv0_MPa", "mu", "unit_weight_kN_m3"});
  tie.masonry.fm = m.number("fm_MPa", "MPa", TB::fm_min / 1e6, TB::fm_max / 1e6) * 1e6;
  tie.masonry.tau = m.number("tau_MPa", "MPa", TB::tau_min / 1e6, TB::tau_max / 1e6) * 1e6;
  tie.masonry.thickness = m.number("thickness_m", "m", TB::thickness_min, TB::thickness_max);
  tie.masonry.FC = m.number_or("FC", FC, "-", 1.0, 10.0);
  tie.masonry.gamma_M = m.number_or("gamma_M", tie_catalogue::masonry_gamma_M, "-", 1.0, 10.0);
  tie.masonry.fv0 = m.number_or("fv0_MPa", tie.masonry.tau / 1e6, "MPa", TB::tau_min / 1e6, TB::tau_max / 1e6) * 1e6;
  tie.masonry.mu = m.number_or("mu", tie_catalogue::sliding_mu, "-", 0.0, 1.5);
  tie.masonry.unit_weight = m.number_or("unit_weight_kN_m3", 0.0, "kN/m^3", TB::unit_weight_min / 1e3,
                                        TB::unit_weight_max / 1e3) * 1e3;  // 0: the block's (resolve_ties)
  tie.layout = parse_layout(t);
  tie.spacing = tie.layout.wall_length / tie.layout.count;
  tie.pretension = t.number_or("pretension_kN", 0.0, "kN", 0.0, TB::pretension_max / kN) * kN;
  tie.delta_T = t.number_or("delta_T_K", tie_catalogue::delta_T, "K", 0.0, TB::delta_T_max);
  tie.rod.corrosion = t.number_or("corrosion_mm", tie_catalogue::corrosion_loss * 1e3, "mm", 0.0,
                                  TB::corrosion_max * 1e3) * 1e-3;
  tie.layout.crown = t.number_or("crown_z_m", std::numeric_limits<double>::infinity(), "m", -1e4, 1e4);
  tie.layout.crown_load = t.number_or("crown_load_kN_m", 0.0, "kN/m", 0.0, TB::crown_load_max / kN) * kN;
  if (t.find("openings")) {
    const std::vector<JsonNode> ops = t.array("openings");
    if (ops.size() > static_cast<std::size_t>(TB::openings_max))
      t.at("openings").fail(std::to_string(ops.size()) + " openings: expected at most " + std::to_string(TB::openings_max));
    for (const JsonNode& o : ops) {
      o.allow_only({"x0_m", "x1_m", "z0_m", "z1_m"});
      WallOpening w;
      w.x0 = o.number("x0_m", "m", -1e4, 1e4);
      w.x1 = o.number("x1_m", "m", -1e4, 1e4);
      w.z0 = o.number("z0_m", "m", -1e4, 1e4);
      w.z1 = o.number("z1_m", "m", -1e4, 1e4);
      if (!(w.x1 > w.x0) || !(w.z1 > w.z0))
        o.fail("expected x0_m < x1_m (along the wall from its first end) and z0_m < z1_m (m)");
      tie.layout.openings.push_back(w);
    }
  }
}

// The end of a rod: its ISO metric thread (the table of tie_catalogue.hpp).
void parse_rod_ends(const JsonNode& r, TieRod& rod) {
  const std::string ends = r.find("ends") ? r.choice("ends", {"threaded", "upset", "welded"}) : "threaded";
  rod.ends = ends == "upset" ? TieEnds::Upset : ends == "welded" ? TieEnds::Welded : TieEnds::Threaded;
  double d = 0.0;
  if (r.has("thread_mm")) {
    d = r.number("thread_mm", "mm", 1.0, 1000.0) * 1e-3;
  } else if (rod.ends == TieEnds::Threaded && rod.diameter > 0.0) {
    d = rod.diameter;  // threaded on the rod itself
  } else {
    r.fail(std::string("missing required key \"thread_mm\": the nominal diameter (mm) of the ISO metric thread of ") +
           (rod.ends == TieEnds::Threaded ? "the rod's ends (a rod given by its area)" : "its " + ends + " ends"));
  }
  const tie_catalogue::Thread* th = tie_catalogue::find_thread(d);
  if (!th) {
    std::string list;
    for (const tie_catalogue::Thread& x : tie_catalogue::threads)
      list += (list.empty() ? "" : ", ") + std::to_string(static_cast<int>(std::lround(x.d * 1e3)));
    (r.has("thread_mm") ? r.at("thread_mm") : r.at("diameter_mm"))
        .fail("no ISO metric coarse thread M" + tnum(d * 1e3) + " in the table (mm: " + list +
              "); give \"thread_mm\" with \"ends\": \"upset\" or \"welded\" for an end larger than the rod");
  }
  if (rod.ends == TieEnds::Threaded && rod.diameter > 0.0 && std::fabs(th->d - rod.diameter) > 1e-4)
    r.at("thread_mm").fail("a rod threaded at its ends has the thread of its own diameter (" +
                           tnum(rod.diameter * 1e3) + " mm); an end of another size is \"upset\" or \"welded\"");
  if (rod.ends != TieEnds::Threaded && rod.diameter > 0.0 && th->d < rod.diameter - 1e-4)
    r.at("thread_mm").fail("expected an " + ends + " end at least as large as the rod (" + tnum(rod.diameter * 1e3) +
                           " mm)");
  rod.thread_diameter = th->d;
  rod.thread_area = th->As;
  rod.nut_width = th->s;
}

Tie parse_tie(const JsonNode& t, double FC, std::size_t index) {
  t.allow_only({"name", "existing", "point", "block", "direction", "rod", "free_length_m", "anchor", "masonry",
                "wall_length_m", "count", "spacing_m", "edge_distance_m", "pretension_kN", "delta_T_K", "corrosion_mm",
                "crown_z_m", "crown_load_kN_m", "openings"});
  Tie tie;
  tie.existing = t.boolean_or("existing", false);
  parse_tie_common(t, tie, FC, index);
  const JsonNode r = t.at("rod");
  r.allow_only({"diameter_mm", "area_mm2", "grade", "fyk_MPa", "ftk_MPa", "gamma_M0", "ends", "thread_mm"});
  if (r.has("diameter_mm") == r.has("area_mm2")) r.fail("give exactly one of \"diameter_mm\" (mm) or \"area_mm2\" (mm^2)");
  if (r.has("diameter_mm")) {
    tie.rod.diameter = r.number("diameter_mm", "mm", TB::rod_diameter_min * 1e3, TB::rod_diameter_max * 1e3) * 1e-3;
    tie.rod.area = units::pi * tie.rod.diameter * tie.rod.diameter / 4.0;
  } else {
    tie.rod.area = r.number("area_mm2", "mm^2", TB::rod_area_min * 1e6, TB::rod_area_max * 1e6) * 1e-6;
  }
  const tie_catalogue::SteelGrade& g = grade_of(r, "grade", tie.rod.grade);
  tie.rod.fyk = g.fyk;
  tie.rod.ftk = g.ftk;
  tie.rod.eps_uk = g.eps_uk;
  if (r.find("fyk_MPa")) tie.rod.fyk = r.number("fyk_MPa", "MPa", TB::fyk_min / 1e6, TB::fyk_max / 1e6) * 1e6;
  if (r.find("ftk_MPa")) tie.rod.ftk = r.number("ftk_MPa", "MPa", tie.rod.fyk / 1e6, 2.0 * TB::fyk_max / 1e6) * 1e6;
  if (!(tie.rod.ftk >= tie.rod.fyk))
    r.fail("ftk = " + tnum(tie.rod.ftk / 1e6) + " MPa below fyk = " + tnum(tie.rod.fyk / 1e6) +
           " MPa: give \"ftk_MPa\" with \"fyk_MPa\"");
  tie.rod.gamma_M0 = r.number_or("gamma_M0", tie_catalogue::gamma_M0, "-", 1.0, 10.0);
  tie.rod.E = tie_catalogue::steel_E;
  parse_rod_ends(r, tie.rod);
  const JsonNode a = t.at("anchor");
  const std::string type = a.choice("type", {"plate", "bar"});
  if (type == "plate") {
    a.allow_only({"type", "a_mm", "b_mm", "t_mm", "grade"});
    tie.anchor.type = AnchorType::Plate;
    tie.anchor.a = a.number("a_mm", "mm", TB::plate_side_min * 1e3, TB::plate_side_max * 1e3) * 1e-3;
    tie.anchor.b = a.find("b_mm") ? a.number("b_mm", "mm", TB::plate_side_min * 1e3, TB::plate_side_max * 1e3) * 1e-3
                                  : tie.anchor.a;
    tie.anchor.t = a.number("t_mm", "mm", TB::plate_t_min * 1e3, TB::plate_t_max * 1e3) * 1e-3;
    if (!(std::min(tie.anchor.a, tie.anchor.b) > tie.rod.nut_width))
      a.fail("a plate of " + tnum(tie.anchor.a * 1e3) + " x " + tnum(tie.anchor.b * 1e3) +
             " mm is no wider than its nut (" + tnum(tie.rod.nut_width * 1e3) +
             " mm across flats, ISO 4032): expected a plate wider than the nut");
  } else {
    a.allow_only({"type", "length_mm", "diameter_mm", "grade"});
    tie.anchor.type = AnchorType::Bar;
    tie.anchor.a = a.number("length_mm", "mm", TB::bar_length_min * 1e3, TB::bar_length_max * 1e3) * 1e-3;
    tie.anchor.b = a.number("diameter_mm", "mm", TB::bar_diameter_min * 1e3, TB::bar_diameter_max * 1e3) * 1e-3;
  }
  tie.anchor.fyk = grade_of(a, "grade", tie.anchor.grade).fyk;
  return tie;  // its default pretension and its wall by resolve_ties
}

TieDesignSpec parse_tie_design(const JsonNode& d, double FC) {
  d.allow_only({"ties"});
  const JsonNode t = d.at("ties");
  t.allow_only({"levels", "grades", "plate_grades", "anchors", "ends", "min_rod_diameter_mm"});
  TieDesignSpec spec;
  std::size_t i = 0;
  // Issue 37: no level to design is allowed (the design then changes only the
  // existing ties that fail: the least change, tie_intervention.hpp).
  for (const JsonNode& l : t.array("levels", 0)) {
    l.allow_only({"name", "point", "block", "direction", "free_length_m", "masonry", "wall_length_m", "count",
                  "spacing_m", "edge_distance_m", "pretension_kN", "delta_T_K", "corrosion_mm", "crown_z_m",
                  "crown_load_kN_m", "openings"});
    Tie tie;
    parse_tie_common(l, tie, FC, i++);
    if (!l.find("name")) tie.name = "new tie " + std::to_string(i);
    spec.levels.push_back(tie);
    spec.pretension_given.push_back(l.has("pretension_kN"));
  }
  if (t.find("plate_grades")) {
    spec.plate_grades.clear();
    for (const JsonNode& g : t.array("plate_grades", 1)) {
      const std::string s = g.as_string();
      if (!tie_catalogue::find_grade(s) || s == "B450C") g.fail("\"" + s + "\": expected \"S235\", \"S275\" or \"S355\"");
      spec.plate_grades.push_back(s);
    }
  }
  if (t.find("anchors")) {
    spec.anchors.clear();
    for (const JsonNode& g : t.array("anchors", 1)) {
      const std::string s = g.as_string();
      if (s != "plate" && s != "bar") g.fail("\"" + s + "\": expected \"plate\" or \"bar\" (paletto)");
      spec.anchors.push_back(s == "plate" ? AnchorType::Plate : AnchorType::Bar);
    }
  }
  if (t.find("grades")) {
    spec.grades.clear();
    for (const JsonNode& g : t.array("grades", 1)) {
      const std::string s = g.as_string();
      if (!tie_catalogue::find_grade(s)) g.fail("\"" + s + "\": expected \"S235\", \"S275\", \"S355\" or \"B450C\"");
      spec.grades.push_back(s);
    }
  }
  if (t.find("ends")) {
    const std::string e = t.choice("ends", {"threaded", "upset", "welded"});
    spec.ends = e == "upset" ? TieEnds::Upset : e == "welded" ? TieEnds::Welded : TieEnds::Threaded;
  }
  spec.min_rod_diameter = t.number_or("min_rod_diameter_mm", tie_catalogue::min_rod_diameter * 1e3, "mm",
                                      tie_catalogue::rod_diameters.front() * 1e3,
                                      tie_catalogue::rod_diameters.back() * 1e3) *
                          1e-3;
  return spec;
}

// Every level must hold a moving block of at least one candidate, and the
// wall it is laid along must be at least as long as the candidates that hold
// it. Issue 37: the wall's defaults from the block it holds (the first
// candidate's): its crown (the block's top) and the masonry's unit weight;
// then every given tie is validated with its wall (an anchor within it).
// `given`: the ties have a rod and an anchor (not a design's levels).
void resolve_ties(const JsonNode& arr, std::vector<Tie>& ties, const std::vector<std::size_t>& index,
                  const MechanismSet& set, bool given) {
  for (std::size_t i = 0; i < ties.size(); ++i) {
    const JsonNode node = arr.at(index[i]);
    bool holds = false;
    for (const MechanismCandidate& m : set.candidates) {
      int b = -1;
      try {
        b = tie_block(m.chain, ties[i].block, ties[i].point);
      } catch (const InputError& e) {
        node.fail(e.what());
      }
      if (b < 0) continue;
      const Block& blk = m.chain.blocks()[static_cast<std::size_t>(b)];
      if (!holds) {
        if (!node.has("crown_z_m")) {
          double top = -std::numeric_limits<double>::infinity();
          for (const Eigen::Vector2d& v : blk.polygon) top = std::max(top, v.y());
          ties[i].layout.crown = top;
        }
        if (!(ties[i].masonry.unit_weight > 0.0))
          ties[i].masonry.unit_weight = std::clamp(blk.unit_weight, TB::unit_weight_min, TB::unit_weight_max);
      }
      holds = true;
      const double length = blk.length;
      if (length > ties[i].layout.wall_length * (1.0 + 1e-9))
        node.at("wall_length_m")
            .fail("the wall is " + tnum(ties[i].layout.wall_length) + " m long, shorter than the mechanism (" +
                  tnum(length) + " m out of plane): expected the length of the wall the ties are laid along");
    }
    if (!holds)
      node.at("point").fail("the anchor point (" + tnum(ties[i].point.x()) + ", " +
                            tnum(ties[i].point.y()) +
                            ") m is on no moving block of the mechanism (the wall's outer face is x = 0, "
                            "the wall at x < 0, z up from the foundation)");
    if (!given) continue;
    // Issue 37: a new tie's pretension takes up the temperature range unless
    // given: E A alpha_T dT, when below the tie's strength (else none, and
    // its "pretension" check fails, saying so); an existing tie's is what it
    // is (0 unless given).
    if (!ties[i].existing && !node.has("pretension_kN")) {
      Tie slack = ties[i];
      slack.pretension = 0.0;
      try {
        const double P = thermal_pretension(slack);
        if (P < tie_resistance(slack).design) ties[i].pretension = P;
      } catch (const InputError&) {
        // refused below, with the node
      }
    }
    try {
      (void)tie_resistance(ties[i]);  // validate() with the wall, and the pretension below the strength
    } catch (const InputError& e) {
      (node.has("pretension_kN") && std::string(e.what()).find("pretension") != std::string::npos
           ? node.at("pretension_kN")
           : node)
          .fail(e.what());
    }
  }
}
// ---- end issue 23 -------------------------------------------------------------

// "report" (issue 28, item 7): the relazione's frontespizio and descriptive
// sections, text as written; masonry parameters in MPa.
ReportInfo parse_report_info(const JsonNode& r) {
  r.allow_only({"client", "work", "location", "engineer", "registration", "revision", "place", "description",
                "investigations", "masonry", "mechanism_criteria", "heritage"});
  ReportInfo x;
  auto text = [&](const char* key, std::string& out) {
    if (r.find(key)) out = r.string(key);
  };
  text("client", x.client);
  text("work", x.work);
  text("location", x.location);
  text("engineer", x.engineer);
  text("registration", x.registration);
  text("revision", x.revision);
  text("place", x.place);
  text("description", x.description);
  text("investigations", x.investigations);
  text("mechanism_criteria", x.mechanism_criteria);
  x.heritage = r.boolean_or("heritage", false);
  if (const auto m = r.find("masonry")) {
    m->allow_only({"type", "fm_MPa", "tau0_MPa", "E_MPa", "G_MPa"});
    if (m->find("type")) x.masonry = m->string("type");
    // Tab. C8.5.I spans fm 1-8 MPa, tau0 0.02-0.2 MPa, E 700-3000 MPa, G 230-1000 MPa: wide bounds, a unit slip fails.
    if (m->find("fm_MPa")) x.fm = m->number("fm_MPa", "MPa", 0.1, 100.0);
    if (m->find("tau0_MPa")) x.tau0 = m->number("tau0_MPa", "MPa", 0.001, 10.0);
    if (m->find("E_MPa")) x.E = m->number("E_MPa", "MPa", 10.0, 1e5);
    if (m->find("G_MPa")) x.G = m->number("G_MPa", "MPa", 1.0, 5e4);
  }
  return x;
}

}  // namespace

CaseFile parse_case(const nlohmann::json& doc, const std::string& file) {
  const JsonNode root(doc, file);
  root.allow_only({"schema_version", "project", "site", "mechanism", "knowledge_level", "FC", "codes",
                   "building", "analysis", "dynamic", "method", "check_SLD",
                   "ties", "design", "report"});
  CaseFile c;
  c.file = file;
  if (root.find("schema_version")) root.integer("schema_version", 1, 1);
  c.project = root.find("project") ? root.string("project") : "";
  if (const auto s = root.find("site")) c.site = parse_site(*s);
  // Confidence factor: FC given, else from the knowledge level (default LC1).
  if (root.find("FC")) {
    c.options.FC = root.number("FC", "-", 1.0, 10.0);
    c.knowledge_level = "given";
    if (root.has("knowledge_level")) root.fail("give \"knowledge_level\" or \"FC\", not both");
  } else {
    c.knowledge_level = root.find("knowledge_level") ? root.choice("knowledge_level", {"LC1", "LC2", "LC3"}) : "LC1";
    const code_rules::KnowledgeLevel lc = c.knowledge_level == "LC1"   ? code_rules::KnowledgeLevel::LC1
                                          : c.knowledge_level == "LC2" ? code_rules::KnowledgeLevel::LC2
                                                                       : code_rules::KnowledgeLevel::LC3;
    c.options.FC = code_rules::confidence_factor(lc);
  }
  const JsonNode mech = root.at("mechanism");
  check_unit_weights(mech);
  try {
    c.mechanism = parse_mechanism(mech, c.options.FC);
  } catch (const InputError& e) {
    // Errors of the model (degrees of freedom ...) get the file and path too.
    if (std::string(e.what()).rfind(file + ":", 0) == 0) throw;
    mech.fail(e.what());
  }

  if (const auto codes = root.find("codes")) {
    c.checks.codes.clear();
    for (const JsonNode& e : root.array("codes", 1)) {
      const std::string s = e.as_string();
      if (s != "NTC2008" && s != "NTC2018") e.fail("\"" + s + "\": expected \"NTC2008\" or \"NTC2018\"");
      c.checks.codes.push_back(parse_code_edition(s));
    }
  }
  // The adopted procedure (Circ. 2019 C8.7.1.2) and the SLD checks (issue 24).
  if (root.find("method")) {
    c.method = root.choice("method", {"linear", "nonlinear", "dynamic"});
    if (c.method == "dynamic" && !root.find("dynamic"))
      root.at("method").fail("the dynamic procedure (C8.7.1.2.1.9) needs a \"dynamic\" section with its records");
  }
  c.checks.sld = root.find("check_SLD") ? root.boolean_or("check_SLD", false) : false;
  if (const auto r = root.find("report")) c.report = parse_report_info(*r);
  if (const auto b = root.find("building")) {
    b->allow_only({"height_m", "storeys", "T1_s", "damping_pct", "Z_m"});
    BuildingModel bm;
    bm.H = b->number("height_m", rules::dimension_m);
    bm.storeys = b->integer("storeys", 1, 1000);
    bm.T1 = b->find("T1_s") ? b->number("T1_s", rules::period_s) : code_rules::T1_simplified(bm.H);
    bm.damping_pct = b->number_or("damping_pct", code_rules::building_damping_default_pct, rules::damping_pct);
    c.building = bm;
    // Z > H is allowed with a warning (psi = Z/H > 1, run_kinematic_case).
    if (b->find("Z_m")) c.Z = b->number("Z_m", rules::offset_m);
  }
  if (const auto a = root.find("analysis")) {
    a->allow_only({"curve_model", "curve_points", "control", "du_cap_m", "d_SLV_cap_m", "d_SLC_cap_m", "q",
                   "damping_SLV_pct", "damping_SLC_pct"});
    if (a->find("curve_model"))
      c.options.curve_model = a->choice("curve_model", {"finite_displacement", "linearised"}) == "linearised"
                                  ? CurveModel::Linearised
                                  : CurveModel::FiniteDisplacement;
    c.options.curve_points = a->integer_or("curve_points", c.options.curve_points, 3, 10000);
    if (const auto ctl = a->find("control")) {
      ctl->allow_only({"block", "point"});
      c.options.control_block = ctl->integer("block", 0, 1000000);
      c.options.control_point = ctl->point("point");
    }
    c.options.du_cap = a->number_or("du_cap_m", c.options.du_cap, rules::displacement_cap_m);
    c.options.d_SLV_cap = a->number_or("d_SLV_cap_m", c.options.d_SLV_cap, rules::displacement_cap_m);
    c.options.d_SLC_cap = a->number_or("d_SLC_cap_m", c.options.d_SLC_cap, rules::displacement_cap_m);
    c.checks.q = a->number_or("q", code_rules::q_local_mechanism, rules::behaviour_factor);
    c.checks.damping_SLV_pct = a->number_or("damping_SLV_pct", code_rules::mechanism_damping_SLV_pct, rules::damping_or_zero_pct);
    c.checks.damping_SLC_pct = a->number_or("damping_SLC_pct", code_rules::mechanism_damping_SLC_pct, rules::damping_or_zero_pct);
  }
  // Issues 23, 29: tie levels (after FC, their masonry's default): those marked
  // "existing" act in every analysis of the case (stato di fatto); the others,
  // and a design's, are the intervention.
  std::size_t levels = 0;
  if (root.find("ties")) {
    const std::vector<JsonNode> arr = root.array("ties");
    if (arr.size() > static_cast<std::size_t>(TB::levels_max))
      root.at("ties").fail(std::to_string(arr.size()) + " tie levels: expected at most " +
                           std::to_string(TB::levels_max) + " (each level is a row of ties along the wall: \"count\")");
    std::vector<std::size_t> idx_old, idx_new;
    for (std::size_t i = 0; i < arr.size(); ++i) {
      Tie t = parse_tie(arr[i], c.options.FC, i);
      (t.existing ? idx_old : idx_new).push_back(i);
      (t.existing ? c.ties : c.new_ties).push_back(std::move(t));
    }
    for (const auto* v : {&c.ties, &c.new_ties})
      for (const Tie& t : *v)
        for (const auto* w : {&c.ties, &c.new_ties})
          for (const Tie& u : *w)
            if (&t != &u && t.name == u.name)
              root.at("ties").fail("two tie levels named \"" + t.name + "\": expected distinct names");
    resolve_ties(root.at("ties"), c.ties, idx_old, c.mechanism, true);
    resolve_ties(root.at("ties"), c.new_ties, idx_new, c.mechanism, true);
    levels += arr.size();
  }
  if (const auto d = root.find("design")) {
    c.tie_design = parse_tie_design(*d, c.options.FC);
    std::vector<std::size_t> idx(c.tie_design->levels.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    resolve_ties(d->at("ties").at("levels"), c.tie_design->levels, idx, c.mechanism, false);
    levels += idx.size();
    for (const Tie& t : c.tie_design->levels)
      for (const auto* v : {&c.ties, &c.new_ties})
        for (const Tie& u : *v)
          if (t.name == u.name)
            d->at("ties").at("levels").fail("a level to design named \"" + t.name +
                                            "\" like a given tie level: expected distinct names");
  }
  if (levels > static_cast<std::size_t>(TB::levels_max))
    root.fail(std::to_string(levels) + " tie levels in \"ties\" and \"design\": expected at most " +
              std::to_string(TB::levels_max));
  if (c.tie_design && c.tie_design->levels.empty() && c.ties.empty())
    root.at("design").at("ties").at("levels").fail("empty, and the case has no existing tie to change: expected at "
                                      "least one level to design (or existing ties, whose failures the design then "
                                      "changes by the least change)");
  c.warnings = input_warnings(doc.at("mechanism"), file);
  // Hook for the façade issue (dynamic rocking): kept raw, parsed there.
  if (root.has("dynamic")) c.dynamic = doc.at("dynamic");
  c.defaults = case_defaults(doc, c);
  // Issue 36, item 5: the knowledge level has one source, the case key; the
  // investigations' text is compared with it (C8.5.4: LC and FC go together).
  for (std::size_t at = c.report.investigations.find("LC"); at != std::string::npos;
       at = c.report.investigations.find("LC", at + 2)) {
    const std::string& t = c.report.investigations;
    const bool word_start = at == 0 || !std::isalnum(static_cast<unsigned char>(t[at - 1]));
    std::size_t d = at + 2;
    while (d < t.size() && t[d] == ' ') ++d;
    if (!word_start || d >= t.size() || t[d] < '1' || t[d] > '3') continue;
    if (d + 1 < t.size() && std::isalnum(static_cast<unsigned char>(t[d + 1]))) continue;
    const std::string lc = std::string("LC") + t[d];
    if (std::find(c.knowledge_levels_stated.begin(), c.knowledge_levels_stated.end(), lc) ==
        c.knowledge_levels_stated.end())
      c.knowledge_levels_stated.push_back(lc);
  }
  char fc[32];
  std::snprintf(fc, sizeof fc, "%.2f", c.options.FC);
  for (const std::string& lc : knowledge_level_conflict(c))
    c.warnings.push_back("the investigations' text (/report/investigations) names " + lc + " but the case adopts " +
                         (c.knowledge_level == "given" ? std::string("FC = ") + fc : c.knowledge_level + " (FC = " + fc + ")") +
                         ": the knowledge level is the case key \"knowledge_level\" (or \"FC\"); correct the text or the key");
  c.source = doc;
  return c;
}

std::vector<std::string> knowledge_level_conflict(const CaseFile& c) {
  std::vector<std::string> out;
  for (const std::string& lc : c.knowledge_levels_stated) {
    const code_rules::KnowledgeLevel k = lc == "LC1"   ? code_rules::KnowledgeLevel::LC1
                                         : lc == "LC2" ? code_rules::KnowledgeLevel::LC2
                                                       : code_rules::KnowledgeLevel::LC3;
    const bool differs = c.knowledge_level == "given" ? code_rules::confidence_factor(k) != c.options.FC : lc != c.knowledge_level;
    if (differs) out.push_back(lc);
  }
  return out;
}

CaseFile read_case_file(const std::string& path) { return parse_case(read_json_file(path), path); }

namespace {

// "0.05 H^0.75 = 0.234 s"-like values of the defaults.
std::string value_text(double v, const char* unit) {
  char b[64];
  std::snprintf(b, sizeof b, "%.4g%s%s", v, *unit ? " " : "", unit);
  return b;
}

}  // namespace

std::vector<CaseDefault> case_defaults(const nlohmann::json& doc, const CaseFile& c) {
  std::vector<CaseDefault> out;
  auto absent = [&](const nlohmann::json& o, std::initializer_list<const char*> keys) {
    if (!o.is_object()) return true;
    for (const char* k : keys)
      if (o.contains(k)) return false;
    return true;
  };
  if (c.site && doc.contains("site")) {
    const nlohmann::json& s = doc.at("site");
    if (absent(s, {"hazard"})) {
      if (absent(s, {"topography"})) out.push_back({"/site/topography", "T1", "default.topography"});
      if (absent(s, {"VN_years"})) out.push_back({"/site/VN_years", value_text(c.site->vn_years, ""), "default.vn"});
      if (absent(s, {"use_class", "CU"})) out.push_back({"/site/use_class", "II (CU = 1.0)", "default.cu"});
    }
  }
  if (absent(doc, {"knowledge_level", "FC"}))
    out.push_back({"/knowledge_level", "LC1 (FC = " + value_text(c.options.FC, "") + ")", "default.knowledge"});
  if (c.site) {
    if (absent(doc, {"method"})) out.push_back({"/method", c.method, "default.method"});
    if (absent(doc, {"check_SLD"})) out.push_back({"/check_SLD", "false", "default.check_sld"});
    const nlohmann::json a = doc.contains("analysis") ? doc.at("analysis") : nlohmann::json::object();
    if (absent(a, {"q"})) out.push_back({"/analysis/q", value_text(c.checks.q, ""), "default.q"});
    if (absent(a, {"damping_SLV_pct"}))
      out.push_back({"/analysis/damping_SLV_pct", value_text(c.checks.damping_SLV_pct, "%"), "default.damping_slv"});
    if (absent(a, {"damping_SLC_pct"}))
      out.push_back({"/analysis/damping_SLC_pct", value_text(c.checks.damping_SLC_pct, "%"), "default.damping_slc"});
  }
  if (c.building) {
    const nlohmann::json& b = doc.at("building");
    if (absent(b, {"T1_s"})) out.push_back({"/building/T1_s", value_text(c.building->T1, "s"), "default.T1"});
    if (absent(b, {"damping_pct"}))
      out.push_back({"/building/damping_pct", value_text(c.building->damping_pct, "%"), "default.building_damping"});
  }
  return out;
}

namespace {

std::string fmt(const char* f, double v) {
  char b[48];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// alpha0 <= 0: the static loads alone overturn the candidate [C8A.4.1]/[C8.7.1.1]
// (alpha0 = -(work of the non-seismic forces) / sum W dx).
[[noreturn]] void statically_unstable(const CaseFile& c, const CandidateResult& cr) {
  const KinematicResult& r = cr.result;
  std::string driving, restoring;
  double w_drive = 0.0, w_rest = 0.0;
  for (const LoadWork& w : r.loads) {
    const double mag = (w.load.type == LoadType::Weight || w.load.type == LoadType::SelfWeight ? w.load.weight
                                                                                               : w.load.force.norm()) /
                       units::kN;
    const std::string item = "\"" + w.load.name + "\" (" + to_string(w.load.type) + ", " + fmt("%.4g", mag) +
                             " kN at z = " + fmt("%.2f", w.load.point.y()) + " m, virtual work " +
                             fmt("%+.4g", w.work / units::kN) + " kN m)";
    if (w.work > 0.0) {
      driving += (driving.empty() ? "" : ", ") + item;
      w_drive += w.work;
    } else if (w.work < 0.0) {
      w_rest += -w.work;
    }
  }
  std::string msg = c.file + ": /mechanism: the wall is statically unstable: it overturns under its static loads "
                    "alone, without any earthquake (alpha0 = " + fmt("%.4g", r.alpha0) + " <= 0 [C8A.4.1, C8.7.1.1]";
  if (c.mechanism.candidates.size() > 1) msg += ", candidate \"" + cr.label + "\"";
  msg += ")";
  if (!driving.empty())
    msg += "; the loads that push it outward: " + driving + ", total " + fmt("%.4g", w_drive / units::kN) +
           " kN m against " + fmt("%.4g", w_rest / units::kN) + " kN m of the restoring weights";
  else if (!(r.sum_W_dx > 0.0))
    msg += "; no seismic weight moves outward (sum W dx = " + fmt("%.4g", r.sum_W_dx / units::kN) +
           " kN m): check the constraints";
  msg += ". Check the sign and size of thrusts (outward positive, kN) and of ties";
  throw InputError(msg);
}

}  // namespace

std::vector<TieRestraint> case_tie_restraints(const CaseFile& c, const Chain& chain) {
  std::vector<TieRestraint> out;
  for (const Tie& t : c.ties) {
    const int b = tie_block(chain, t.block, t.point);
    if (b >= 0) out.push_back(tie_restraint(t, b, chain.blocks()[static_cast<std::size_t>(b)].length));
  }
  return out;
}

KinematicCaseResult run_kinematic_case(const CaseFile& c, bool indices) {
  return run_kinematic_case(c, indices, nullptr);
}

KinematicCaseResult run_kinematic_case(const CaseFile& c, bool indices, const KinematicCaseResult* marched) {
  KinematicCaseResult out;
  out.warnings = c.warnings;
  if (marched && marched->candidates.size() != c.mechanism.candidates.size()) marched = nullptr;
  for (std::size_t i = 0; i < c.mechanism.candidates.size(); ++i) {
    const MechanismCandidate& m = c.mechanism.candidates[i];
    KinematicOptions opt = c.options;
    opt.rotation_cap = m.rotation_bound;  // issue 33: the mechanism's own bound on its rotation
    const std::vector<TieRestraint> ties = case_tie_restraints(c, m.chain);
    out.candidates.push_back({m.label, m.parameter, c.Z.value_or(m.Z),
                              marched ? rederive_kinematic(m.chain, opt, ties, marched->candidates[i].result)
                                      : analyse_kinematic(m.chain, opt, ties),
                              {}, {}, {}});
  }
  for (const CandidateResult& cr : out.candidates)
    if (!cr.result.activates) statically_unstable(c, cr);
  // alpha0 > 1 of the governing candidate(s) (searched candidates far from
  // the governing one have large alpha0 by construction).
  auto warn_alpha0 = [&](std::size_t i) {
    const CandidateResult& cr = out.candidates[i];
    if (!(cr.result.alpha0 > plausibility::alpha0_max)) return;
    out.warnings.push_back(c.file + ": /mechanism: alpha0 = " + fmt("%.4g", cr.result.alpha0) + " (-) > 1" +
                           (out.candidates.size() > 1 ? " for the governing \"" + cr.label + "\"" : "") +
                           ": a horizontal force larger than the weight is needed to start the mechanism; "
                           "out-of-plane mechanisms are usually in 0.02-0.5 (a restrained wall under a heavy load "
                           "can exceed 1): check the thickness (m, not cm), ties and thrusts");
  };
  // Without a site: no checks; the governing candidate is the smallest alpha0.
  out.governing = governing_candidate(c.mechanism);
  if (!c.site) {
    warn_alpha0(out.governing);
    return out;
  }

  const Site site(*c.site);
  CheckInput in = c.checks;
  for (LimitState ls : {LimitState::SLD, LimitState::SLV, LimitState::SLC}) {
    if (!c.site->given.empty() && !c.site->given.count(ls)) continue;
    out.actions[ls] = site.action(ls);
    in.hazard[ls] = out.actions[ls].hazard;
  }
  for (CodeEdition code : in.codes)
    for (LimitState ls : {LimitState::SLD, LimitState::SLV, LimitState::SLC})
      if ((ls != LimitState::SLC || code == CodeEdition::NTC2018) && !in.hazard.count(ls))
        throw InputError(c.file + ": /site/hazard: the " + to_string(code) + " checks need the hazard of " +
                         to_string(ls) + " (ag_g, F0, Tc_star)");
  in.site = c.site->conditions;
  in.building = c.building;
  out.check_input = in;
  // The site's hazard along the return-period axis (none when given per limit state).
  HazardAxis axis;
  if (site.has_hazard_curve()) axis = [&site](double tr) { return site.hazard_extrapolated(tr); };
  bool warned_Z = false;
  for (CandidateResult& cr : out.candidates) {
    in.Z = cr.Z;
    if (cr.Z > 0.0 && !c.building)
      throw InputError(c.file + ": /building: missing: the candidate \"" + cr.label + "\" is at height Z = " +
                       fmt("%.3f", cr.Z) + " m and its checks need the building (\"height_m\" in m, \"storeys\", "
                       "optional \"T1_s\" in s) [C8A.4.10, C7.2.3]");
    if (c.building && cr.Z > c.building->H && !warned_Z) {
      warned_Z = true;
      const double psi = code_rules::psi_first_mode(cr.Z, c.building->H);
      out.warnings.push_back(c.file + ": " + (c.Z ? "/building/Z_m" : "/mechanism") + ": the mechanism's height Z = " +
                             fmt("%.3f", cr.Z) + " m is above the building height /building/height_m = " +
                             fmt("%.3f", c.building->H) + " m, so psi(Z) = Z/H = " + fmt("%.3f", psi) +
                             " > 1; the reading taken: the first-mode shape psi = Z/H extended linearly above H "
                             "(a gable or belfry above the eaves when H is taken at the eaves) [C8A.4.10, C7.2.10]");
    }
    try {
      cr.checks = run_code_checks(cr.result, in);
    } catch (const InputError& e) {
      throw InputError(c.file + ": /building: " + e.what());
    }
    for (CheckRow& row : cr.checks) {
      row.candidate = cr.label;
      double& m = cr.max_dc[row.code];
      m = std::max(m, std::isfinite(row.dc) ? row.dc : std::numeric_limits<double>::infinity());
      // The check's own index: the return period at which it reaches D/C = 1 (issue 41).
      if (indices) row.index = check_index(cr.result, in, row, axis);
      if (row.index.defined) {
        const auto it = cr.zeta_min.find(row.code);
        if (it == cr.zeta_min.end() || row.index.zeta < it->second) cr.zeta_min[row.code] = row.index.zeta;
      }
    }
  }
  // The governing candidate of each code: the largest D/C over its checks
  // (Circ. 2019 C8.7.1: the most unfavourable mechanism; ties: the first).
  for (CodeEdition code : in.codes) {
    const std::string k = to_string(code);
    std::size_t best = 0;
    // Ties to rounding (1e-12 relative; a symmetric corner's two end axes) go to the first.
    for (std::size_t i = 1; i < out.candidates.size(); ++i)
      if (out.candidates[i].max_dc[k] > out.candidates[best].max_dc[k] * (1.0 + 1e-12)) best = i;
    out.governing_by_code[k] = best;
    for (const CheckRow& row : out.candidates[best].checks)
      if (row.code == k) out.checks.push_back(row);
  }
  if (!in.codes.empty())
    out.governing = out.governing_by_code.count("NTC2018") ? out.governing_by_code["NTC2018"]
                                                           : out.governing_by_code[to_string(in.codes.front())];
  warn_alpha0(out.governing);
  std::vector<CheckRow> all;
  for (const CandidateResult& cr : out.candidates) all.insert(all.end(), cr.checks.begin(), cr.checks.end());
  out.verdict = build_verdict(all, c.method);
  return out;
}

SiteSpec parse_site_block(const nlohmann::json& site, const std::string& file) { return parse_site(JsonNode(site, file)); }

}  // namespace assess

// hazard.cpp: site hazard from the NTC 2008 Allegato B grid (NTC 2018 §3.2).
//
// Notation: ag (g) peak ground acceleration on rock, F0 maximum spectral
// amplification, Tc* (s) start of the constant-velocity branch; TR return
// period (years); p_i a parameter at grid vertex i, d_i the great-circle
// distance site-vertex (km).
//
// Rules (docs/theory/spectra.md):
//  - spatial interpolation (Allegato A): p = sum(p_i/d_i) / sum(1/d_i) over
//    the 4 vertices of the grid cell that contains the site; the node value
//    when the site is on a node;
//  - interpolation in TR (Allegato A eq. 2): log p = log p1 + log(p2/p1) *
//    log(TR/TR1) / log(TR2/TR1), between the bracketing tabulated TRs, applied
//    after the spatial interpolation;
//  - TR clamped to [30, 2475] years (Circ. 2019 Tab. C3.2.I and its note 1).
#include "assess/hazard/hazard.hpp"

#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/hazard/seismic_action.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/stat.h>

namespace assess {

namespace {

constexpr double earth_radius_km = 6371.0;  // mean Earth radius (IUGG), haversine
constexpr double deg_to_rad = 3.14159265358979323846 / 180.0;
constexpr int nodes_per_row = 222;         // lattice: id+1 east, id+222 south
constexpr double exact_hit_km = 1e-6;      // 1 mm: the site is on the node
constexpr double bin_deg = 0.1;            // spatial index bin (degrees)

double haversine_km(double lat1, double lon1, double lat2, double lon2) {
  const double p1 = lat1 * deg_to_rad, p2 = lat2 * deg_to_rad;
  const double dp = p2 - p1, dl = (lon2 - lon1) * deg_to_rad;
  const double s = std::sin(dp / 2) * std::sin(dp / 2) +
                   std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2.0 * earth_radius_km * std::asin(std::min(1.0, std::sqrt(s)));
}

bool file_exists(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

// Splits one CSV line honouring double quotes (the islands table quotes its
// list of names).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.push_back(cur), cur.clear();
    else if (c != '\r') cur += c;
  }
  out.push_back(cur);
  return out;
}

double parse_number(const std::string& s, const std::string& file, std::size_t line,
                    const std::string& column) {
  double v = 0.0;
  const char* b = s.data();
  while (b < s.data() + s.size() && *b == ' ') ++b;
  const auto r = std::from_chars(b, s.data() + s.size(), v);
  if (r.ec != std::errc() || !std::isfinite(v))
    throw InputError(file + ":" + std::to_string(line) + ": column '" + column + "': expected a number, got '" +
                     s + "'");
  return v;
}

// The whole file through the bounded reader (a regular file within its
// limit: /dev/zero as the grid is an error, not a read until memory runs out).
std::istringstream open_or_throw(const std::string& path, const InputKind& kind) {
  return std::istringstream(read_input_file(path, kind));
}

// Reads the 27 columns ag/F0/Tc x 9 TR starting at `first` into a node.
void read_params(const std::vector<std::string>& f, std::size_t first, HazardNode& n,
                 const std::vector<std::string>& header, const std::string& file, std::size_t line) {
  for (std::size_t k = 0; k < 9; ++k) {
    const std::size_t c = first + 3 * k;
    n.ag_g[k] = parse_number(f[c], file, line, header[c]);
    n.F0[k] = parse_number(f[c + 1], file, line, header[c + 1]);
    n.Tc_star[k] = parse_number(f[c + 2], file, line, header[c + 2]);
    if (!(n.ag_g[k] > 0.0 && n.F0[k] > 0.0 && n.Tc_star[k] > 0.0))
      throw InputError(file + ":" + std::to_string(line) + ": ag, F0 and Tc* must be > 0");
  }
}

void check_header(const std::vector<std::string>& h, std::size_t first, const std::string& file) {
  for (std::size_t k = 0; k < 9; ++k) {
    const std::string tr = std::to_string(static_cast<int>(grid_return_periods[k]));
    const std::string expect[3] = {"ag_" + tr, "F0_" + tr, "Tc_" + tr};
    for (int j = 0; j < 3; ++j)
      if (h.size() <= first + 3 * k + j || h[first + 3 * k + j] != expect[j])
        throw InputError(file + ":1: header: expected column '" + expect[j] + "' at position " +
                         std::to_string(first + 3 * k + j + 1));
  }
}

struct Bracket {
  std::size_t k1, k2;
  double w;  // log(TR/TR1)/log(TR2/TR1), 0 when k1 == k2
};

Bracket bracket_tr(double tr) {
  const auto& T = grid_return_periods;
  for (std::size_t k = 0; k < T.size(); ++k)
    if (tr == T[k]) return {k, k, 0.0};
  std::size_t k = 0;
  while (k + 2 < T.size() && tr > T[k + 1]) ++k;
  return {k, k + 1, std::log(tr / T[k]) / std::log(T[k + 1] / T[k])};
}

// Allegato A eq. 2: linear in log-log.
double log_interp(double p1, double p2, double w) {
  return w == 0.0 ? p1 : std::exp(std::log(p1) + w * std::log(p2 / p1));
}

double clamp_tr(double tr_years, HazardParams& out) {
  if (!(tr_years > 0.0) || !std::isfinite(tr_years))
    throw InputError("return period TR = " + std::to_string(tr_years) + " years: expected a number > 0 years");
  out.tr_requested = tr_years;
  const double tr = std::clamp(tr_years, tr_min_years, tr_max_years);
  out.tr_clamped = tr != tr_years;
  out.TR = tr;
  return tr;
}

}  // namespace

HazardParams interpolate_in_tr(const HazardNode& n, double tr_years) {
  HazardParams out;
  const Bracket b = bracket_tr(clamp_tr(tr_years, out));
  out.ag_g = log_interp(n.ag_g[b.k1], n.ag_g[b.k2], b.w);
  out.F0 = log_interp(n.F0[b.k1], n.F0[b.k2], b.w);
  out.Tc_star = log_interp(n.Tc_star[b.k1], n.Tc_star[b.k2], b.w);
  return out;
}

// ---------------------------------------------------------------- the grid

void HazardGrid::build_index() {
  int lo = std::numeric_limits<int>::max(), hi = std::numeric_limits<int>::min();
  double lat_lo = 1e9, lat_hi = -1e9, lon_lo = 1e9, lon_hi = -1e9;
  for (const auto& n : nodes_) {
    lo = std::min(lo, n.id), hi = std::max(hi, n.id);
    lat_lo = std::min(lat_lo, n.lat), lat_hi = std::max(lat_hi, n.lat);
    lon_lo = std::min(lon_lo, n.lon), lon_hi = std::max(lon_hi, n.lon);
  }
  id_min_ = lo;
  index_.assign(std::size_t(hi - lo + 1), -1);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    int& slot = index_[std::size_t(nodes_[i].id - lo)];
    if (slot != -1) throw InputError("hazard grid: duplicate node id " + std::to_string(nodes_[i].id));
    slot = int(i);
  }
  lat0_ = lat_lo, lon0_ = lon_lo;
  nlat_ = int((lat_hi - lat_lo) / bin_deg) + 1;
  nlon_ = int((lon_hi - lon_lo) / bin_deg) + 1;
  auto bin_of = [&](const HazardNode& n) {
    return std::size_t(int((n.lat - lat0_) / bin_deg)) * std::size_t(nlon_) +
           std::size_t(int((n.lon - lon0_) / bin_deg));
  };
  bin_start_.assign(std::size_t(nlat_) * std::size_t(nlon_) + 1, 0);
  for (const auto& n : nodes_) ++bin_start_[bin_of(n) + 1];
  for (std::size_t b = 1; b < bin_start_.size(); ++b) bin_start_[b] += bin_start_[b - 1];
  bin_nodes_.assign(nodes_.size(), 0);
  std::vector<int> fill(bin_start_.begin(), bin_start_.end() - 1);
  for (std::size_t i = 0; i < nodes_.size(); ++i) bin_nodes_[std::size_t(fill[bin_of(nodes_[i])]++)] = int(i);
}

HazardGrid HazardGrid::load(const std::string& csv_path) {
  std::istringstream in = open_or_throw(csv_path, input_kinds::hazard_grid);
  HazardGrid g;
  std::string line;
  if (!std::getline(in, line)) throw InputError("hazard grid file '" + csv_path + "' is empty");
  const auto header = split_csv(line);
  if (header.size() != 30 || header[0] != "id" || header[1] != "lon" || header[2] != "lat")
    throw InputError(csv_path + ":1: expected the header 'id,lon,lat,ag_30,F0_30,Tc_30,...' (30 columns)");
  check_header(header, 3, csv_path);
  g.nodes_.reserve(10751);
  std::size_t ln = 1;
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line == "\r") continue;
    const auto f = split_csv(line);
    if (f.size() != 30)
      throw InputError(csv_path + ":" + std::to_string(ln) + ": expected 30 columns, found " +
                       std::to_string(f.size()));
    HazardNode n;
    n.id = int(parse_number(f[0], csv_path, ln, "id"));
    n.lon = parse_number(f[1], csv_path, ln, "lon");
    n.lat = parse_number(f[2], csv_path, ln, "lat");
    read_params(f, 3, n, header, csv_path, ln);
    g.nodes_.push_back(n);
  }
  if (g.nodes_.empty()) throw InputError("hazard grid file '" + csv_path + "' has no data rows");
  g.build_index();
  return g;
}

HazardGrid HazardGrid::load_default() {
  return load(data_dir() + "/spectra/ntc2008_hazard_grid.csv");
}

const HazardNode* HazardGrid::node(int id) const {
  const long k = long(id) - id_min_;
  if (k < 0 || k >= long(index_.size()) || index_[std::size_t(k)] < 0) return nullptr;
  return &nodes_[std::size_t(index_[std::size_t(k)])];
}

namespace {

// Local planar coordinates (km) about a reference latitude: enough to decide
// on which side of a cell edge a point lies (cells are ~5.5 km).
struct Pt {
  double x, y;
};
Pt planar(double lat, double lon, double lat0) {
  return {lon * deg_to_rad * std::cos(lat0 * deg_to_rad) * earth_radius_km, lat * deg_to_rad * earth_radius_km};
}
double cross(Pt a, Pt b, Pt p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// True when p is inside the convex quadrilateral q (any orientation), edges included.
bool inside_quad(const Pt q[4], Pt p) {
  constexpr double eps_km2 = 1e-9;  // points on an edge belong to the cell
  bool pos = false, neg = false;
  for (int i = 0; i < 4; ++i) {
    const double c = cross(q[i], q[(i + 1) % 4], p);
    if (c > eps_km2) pos = true;
    if (c < -eps_km2) neg = true;
  }
  return !(pos && neg);
}

}  // namespace

std::vector<int> HazardGrid::cell_nodes(double lat, double lon) const {
  if (!(lat >= -90.0 && lat <= 90.0) || !std::isfinite(lat))
    throw InputError("latitude " + std::to_string(lat) + ": expected decimal degrees between -90 and 90");
  if (!(lon >= -180.0 && lon <= 180.0) || !std::isfinite(lon))
    throw InputError("longitude " + std::to_string(lon) + ": expected decimal degrees between -180 and 180");
  // The three nearest nodes, searched in the 3x3 bins around the site (a bin
  // of 0.1 deg is wider than the 5.5 km node spacing).
  const double coslat = std::cos(lat * deg_to_rad);
  std::array<std::pair<double, int>, 3> best{{{1e300, -1}, {1e300, -1}, {1e300, -1}}};
  const int bi = int(std::floor((lat - lat0_) / bin_deg)), bj = int(std::floor((lon - lon0_) / bin_deg));
  for (int i = bi - 1; i <= bi + 1; ++i) {
    if (i < 0 || i >= nlat_) continue;
    for (int j = bj - 1; j <= bj + 1; ++j) {
      if (j < 0 || j >= nlon_) continue;
      const std::size_t b = std::size_t(i) * std::size_t(nlon_) + std::size_t(j);
      for (int k = bin_start_[b]; k < bin_start_[b + 1]; ++k) {
        const HazardNode& n = nodes_[std::size_t(bin_nodes_[std::size_t(k)])];
        const double dy = n.lat - lat, dx = (n.lon - lon) * coslat;
        const double d2 = dx * dx + dy * dy;
        if (d2 < best[2].first) {
          best[2] = {d2, n.id};
          std::sort(best.begin(), best.end());
        }
      }
    }
  }
  const Pt p = planar(lat, lon, lat);
  for (const auto& [d2, id] : best) {
    if (id < 0) continue;
    // The 4 cells that have `id` as a vertex, named by their NW corner.
    for (int nw : {id, id - 1, id - nodes_per_row, id - nodes_per_row - 1}) {
      const int ids[4] = {nw, nw + 1, nw + nodes_per_row + 1, nw + nodes_per_row};  // ring order
      const HazardNode* v[4];
      bool complete = true;
      for (int k = 0; k < 4; ++k) complete = complete && (v[k] = node(ids[k])) != nullptr;
      if (!complete) continue;
      // Cells of the lattice must be ~5.5 km wide: reject wrap-around at row ends.
      if (haversine_km(v[0]->lat, v[0]->lon, v[1]->lat, v[1]->lon) > 10.0) continue;
      Pt q[4];
      for (int k = 0; k < 4; ++k) q[k] = planar(v[k]->lat, v[k]->lon, lat);
      if (inside_quad(q, p)) return {ids[0], ids[1], ids[3], ids[2]};  // NW, NE, SW, SE
    }
  }
  std::ostringstream msg;
  msg.precision(6);
  msg << "site (lat " << lat << ", lon " << lon << ") is outside the NTC hazard grid";
  if (best[0].second >= 0)
    msg << " (nearest node " << best[0].second << " at "
        << haversine_km(lat, lon, node(best[0].second)->lat, node(best[0].second)->lon) << " km)";
  msg << "; for the small islands of Allegato B Tab. 2 give the island name instead";
  throw InputError(msg.str());
}

HazardParams HazardGrid::at(double lat, double lon, double tr_years) const {
  HazardParams out;
  const Bracket b = bracket_tr(clamp_tr(tr_years, out));
  const std::vector<int> ids = cell_nodes(lat, lon);
  // Spatial IDW at the bracketing TRs, then log-log in TR (Allegato A order).
  double sw = 0.0, ag[2] = {0, 0}, f0[2] = {0, 0}, tc[2] = {0, 0};
  for (int id : ids) {
    const HazardNode& n = *node(id);
    const double d = haversine_km(lat, lon, n.lat, n.lon);
    if (d < exact_hit_km) {  // on the node: its own values
      sw = 1.0;
      ag[0] = n.ag_g[b.k1], ag[1] = n.ag_g[b.k2];
      f0[0] = n.F0[b.k1], f0[1] = n.F0[b.k2];
      tc[0] = n.Tc_star[b.k1], tc[1] = n.Tc_star[b.k2];
      break;
    }
    const double w = 1.0 / d;
    sw += w;
    ag[0] += w * n.ag_g[b.k1], ag[1] += w * n.ag_g[b.k2];
    f0[0] += w * n.F0[b.k1], f0[1] += w * n.F0[b.k2];
    tc[0] += w * n.Tc_star[b.k1], tc[1] += w * n.Tc_star[b.k2];
  }
  out.ag_g = log_interp(ag[0] / sw, ag[1] / sw, b.w);
  out.F0 = log_interp(f0[0] / sw, f0[1] / sw, b.w);
  out.Tc_star = log_interp(tc[0] / sw, tc[1] / sw, b.w);
  return out;
}

// ---------------------------------------------------------------- islands

namespace {
std::string fold(const std::string& s) {
  std::string out;
  for (unsigned char c : s)
    if (!std::isspace(c) && c != '.' && c != '\'') out += char(std::tolower(c));
  return out;
}
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}
}  // namespace

IslandTable IslandTable::load(const std::string& csv_path) {
  std::istringstream in = open_or_throw(csv_path, input_kinds::islands_table);
  IslandTable t;
  std::string line;
  if (!std::getline(in, line)) throw InputError("islands table '" + csv_path + "' is empty");
  const auto header = split_csv(line);
  if (header.size() != 29 || header[0] != "group" || header[1] != "islands")
    throw InputError(csv_path + ":1: expected the header 'group,islands,ag_30,F0_30,Tc_30,...' (29 columns)");
  check_header(header, 2, csv_path);
  std::size_t ln = 1;
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line == "\r") continue;
    const auto f = split_csv(line);
    if (f.size() != 29)
      throw InputError(csv_path + ":" + std::to_string(ln) + ": expected 29 columns, found " +
                       std::to_string(f.size()));
    HazardNode n;
    read_params(f, 2, n, header, csv_path, ln);
    t.islands_.emplace_back(trim(f[0]), n);  // the group name (G1..G5) itself
    std::stringstream names(f[1]);
    std::string name;
    while (std::getline(names, name, ';'))
      if (!trim(name).empty()) t.islands_.emplace_back(trim(name), n);
  }
  return t;
}

IslandTable IslandTable::load_default() {
  return load(data_dir() + "/spectra/ntc2008_islands_table2.csv");
}

HazardParams IslandTable::at(const std::string& name, double tr_years) const {
  const std::string key = fold(name);
  for (const auto& [n, node] : islands_) {
    std::string k = fold(n);
    if (k == key || (k.rfind("isole", 0) == 0 && k.substr(5) == key)) return interpolate_in_tr(node, tr_years);
  }
  std::string list;
  for (const auto& s : names()) list += (list.empty() ? "" : ", ") + s;
  throw InputError("island '" + name + "' is not in Allegato B Tab. 2; known: " + list);
}

std::vector<std::string> IslandTable::names() const {
  std::vector<std::string> out;
  for (const auto& p : islands_) out.push_back(p.first);
  return out;
}

// ---------------------------------------------------------------- data dir

std::string data_dir() {
  if (const char* env = std::getenv("ASSESS_DATA_DIR"); env && *env) return env;
  const std::string installed = ASSESS_INSTALL_DATA_DIR;
  if (file_exists(installed + "/spectra/ntc2008_hazard_grid.csv")) return installed;
  return ASSESS_SOURCE_DATA_DIR;
}

}  // namespace assess

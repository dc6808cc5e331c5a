// hazard.hpp: site hazard parameters ag, F0, TC* from the NTC 2008
// Allegato B reference grid and islands table (used by NTC 2018 §3.2).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace assess {

/// Hazard parameters of a site for one return period, rigid flat ground (soil A).
struct HazardParams {
  double TR = 0.0;       ///< return period used (years), after clamping
  double ag_g = 0.0;     ///< peak ground acceleration on rock (g)
  double F0 = 0.0;       ///< maximum spectral amplification (-)
  double Tc_star = 0.0;  ///< period of the start of the constant-velocity branch (s)
  bool tr_clamped = false;  ///< TR was outside [30, 2475] years and was clamped
  double tr_requested = 0.0;  ///< TR asked for (years), before clamping
};

/// The return periods of the grid (years), Allegato B.
inline constexpr std::array<double, 9> grid_return_periods{30, 50, 72, 101, 140, 201, 475, 975, 2475};

/// One node (or island group) of the hazard data: ag (g), F0, TC* (s) at the
/// 9 tabulated return periods.
struct HazardNode {
  int id = 0;
  double lon = 0.0, lat = 0.0;  ///< decimal degrees
  std::array<double, 9> ag_g{}, F0{}, Tc_star{};
};

/// Log-log interpolation in TR of one node's parameters (Allegato A eq. 2),
/// TR clamped to [30, 2475] years.
HazardParams interpolate_in_tr(const HazardNode& node, double tr_years);

/// The reference grid of NTC 2008 Allegato B Tab. 1 (10751 nodes).
class HazardGrid {
 public:
  /// Loads the grid CSV (ag in g; see spectra/README.md). Throws InputError
  /// naming the file (and line) when it cannot be read or is malformed.
  static HazardGrid load(const std::string& csv_path);
  /// Loads the grid shipped with libassess (data_dir()/spectra/...).
  static HazardGrid load_default();

  /// Hazard at (lat, lon) (decimal degrees) and return period TR (years):
  /// inverse-distance weights (1/d, great-circle d) over the 4 vertices of the
  /// grid cell that contains the site, the node value on an exact node hit,
  /// then log-log interpolation in TR (Allegato A). TR is clamped to
  /// [30, 2475] years (HazardParams::tr_clamped tells). Throws InputError for
  /// a point outside the grid.
  HazardParams at(double lat, double lon, double tr_years) const;

  /// The (up to) 4 node ids used for (lat, lon): the enclosing cell's vertices.
  std::vector<int> cell_nodes(double lat, double lon) const;

  const HazardNode* node(int id) const;
  std::size_t size() const { return nodes_.size(); }

 private:
  std::vector<HazardNode> nodes_;  // in file order
  std::vector<int> index_;         // id - id_min -> position in nodes_, -1 if absent
  int id_min_ = 0;
  // Spatial index: nodes binned on a regular lat/lon raster (CSR layout).
  double lat0_ = 0.0, lon0_ = 0.0;
  int nlat_ = 0, nlon_ = 0;
  std::vector<int> bin_start_, bin_nodes_;
  void build_index();
};

/// The islands of Allegato B Tab. 2 (not covered by the grid).
class IslandTable {
 public:
  static IslandTable load(const std::string& csv_path);
  static IslandTable load_default();
  /// Hazard of the island called `name` (case-insensitive, e.g. "Sardegna",
  /// "Lipari"); throws InputError listing the known names otherwise.
  HazardParams at(const std::string& name, double tr_years) const;
  std::vector<std::string> names() const;

 private:
  std::vector<std::pair<std::string, HazardNode>> islands_;  // island name -> its group's values
};

/// Root directory of the data shipped with libassess (containing spectra/ and
/// mechanisms/): $ASSESS_DATA_DIR if set, else the install prefix's
/// share/assess, else the source tree the library was built from.
std::string data_dir();

}  // namespace assess

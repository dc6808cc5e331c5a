// dynamic_case.hpp: the "dynamic" section of a façade case file (schema
// version 1, docs/user/case-file.md): rocking model, restitution values,
// sidedness, polarity, overturning criterion, and the records (listed or
// selected from the shipped catalogue to match the site spectrum).
#pragma once

#include "assess/assessment/case_default.hpp"
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/dynamics/rocking_model.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/record_selection.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// A record listed in the case file.
struct ListedRecord {
  std::string file;       ///< resolved path
  std::string json_path;  ///< "/dynamic/records/2" (for messages)
  double scale = 1.0;     ///< linear scale factor (-)
  /// Plain text record (one column, or time and acceleration): the unit of
  /// its values, and its time step (s) for one column; without dt the file
  /// must have two columns (time, acceleration) and dt is read from it.
  std::optional<AccelerationUnit> unit;
  std::optional<double> dt;
};

/// "Select N records compatible with the site spectrum" (REXEL's rule).
/// Defaults and rules: docs/theory/record-selection.md §2.
struct RecordSelectionSpec {
  int count = 7;                      ///< N
  std::optional<double> T_min, T_max;  ///< period range (s); default: around the mechanism's periods
  double max_scale = 3.0;             ///< largest scale factor of a record (-), record-selection.md §2.4
  double max_mean_scale = 2.0;        ///< largest mean scale factor of the set (-)
  double max_pga_ratio = 2.5;         ///< guard: scaled PGA <= max_pga_ratio * ag S (-)
  int max_per_event = 3, max_per_station = 1;
  std::optional<double> Mw_min, Mw_max;      ///< default window 5.5-7.5 (warned)
  std::optional<double> R_min_km, R_max_km;  ///< default window 0-50 km (warned)
  std::vector<std::string> site_classes;     ///< default: the site's soil class, relaxed with a warning
  bool relax_site_class = true;
  std::vector<std::string> countries;        ///< default: any
  bool include_near_fault = false;           ///< "near_fault": "include" (default "exclude")
  double near_fault_km = 10.0;               ///< distance threshold of the near-fault flag (km)
  double max_misfit = 0.5;                   ///< individual misfit flagged above it (-)
  std::string catalogue;              ///< catalogue.json (default: data_dir()/spectra/records/catalogue.json)
};

/// The catalogue filters of a selection of `count` records (docs/theory/
/// record-selection.md §2.1): the Mw and distance windows, the site classes
/// (default: `soil_class`, the site's, relaxed with a warning), the countries,
/// and at least 3 count candidates. One place for `assess run` and fragility.
CatalogueFilters catalogue_filters(const RecordSelectionSpec& rs, const std::string& soil_class, int count);

enum class Polarity { normal, reversed, both };

/// The dynamic section, validated.
struct DynamicSpec {
  bool smooth = true;                  ///< smooth (Winkler) or rigid (Housner) block
  double k = 0.0;                      ///< Winkler modulus (N/m^3), smooth only
  Sidedness sidedness = Sidedness::one_sided;
  std::vector<Restitution> restitutions;  ///< one analysis set per value
  bool restitution_given = false;      ///< "restitution" present (a multi-block chain needs values)
  /// Where k, the model and the restitution were given, named in errors: the
  /// case file's JSON paths, or the command-line options that replaced them
  /// (`assess dynamic --k`; issue 39: "/dynamic/k" was named for a case
  /// without one).
  std::string k_from = "/dynamic/k", model_from = "/dynamic/model", restitution_from = "/dynamic/restitution";
  Polarity polarity = Polarity::normal;
  RockingOptions options;              ///< overturning criterion, integrator, tail
  std::vector<ListedRecord> records;   ///< listed records (empty if selected)
  std::optional<RecordSelectionSpec> selection;
  /// "input": "ground" (default: records are ground motions, filtered to the
  /// floor at the mechanism's height Z > 0 by the building's first mode) or
  /// "floor" (records are floor motions at the mechanism's base, e.g. from a
  /// model of the building; used as given).
  bool floor_input = false;
  /// "floor_filter": {"T1_s", "damping_pct"}: period (s) and damping (%) of the
  /// first-mode filter; default the building's T1 and damping.
  std::optional<double> filter_T1, filter_damping_pct;
  // Every record is integrated to its last sample, then the free motion up
  // to options.tail_s (issue 21, dynamics/analysis_end.hpp): no trimming.
  /// The values of the section the case did not give (case_default.hpp).
  std::vector<CaseDefault> defaults;
};

/// Reads a listed record: a plain text file when `unit` is given (with `dt`
/// for one column), else the format detected from the content (read_record).
Record read_listed_record(const ListedRecord& r);

/// Parses `doc` (the value of the "dynamic" key). Errors name `file` and the
/// JSON path (e.g. /dynamic/records/2/scale), the expected type or range and
/// unit; unknown keys are errors with a suggestion. Record paths are resolved
/// against `case_dir`, then against data_dir().
DynamicSpec parse_dynamic(const nlohmann::json& doc, const std::string& file, const std::string& case_dir);

/// "e = -0.48", "Housner", "one-sided theory", "none".
std::string describe(const Restitution& r);
std::string to_string(Polarity p);

}  // namespace assess

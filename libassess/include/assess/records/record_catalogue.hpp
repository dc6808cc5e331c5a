// record_catalogue.hpp: the machine-readable list of the accelerograms
// shipped in spectra/records/ (catalogue.json), its generation from the
// record files plus a metadata table (metadata.csv), and its reading.
#pragma once

#include "assess/records/record.hpp"
#include "assess/records/record_io.hpp"
#include "assess/support/number_rules.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace assess {

/// One record component of the catalogue. Unknown numbers are NaN (null in JSON).
struct CatalogueEntry {
  std::string id;         ///< file name without folder and extension (unique)
  std::string file;       ///< path relative to the catalogue's directory
  std::string format;     ///< Record::format as read ("PEER AT2", "GEM cor.acc", "plain", ...)
  std::string event, date, station, component, source, note;
  std::string mechanism;           ///< fault mechanism (Normal, Reverse, strike slip, ...)
  std::string station_code;
  std::string positive_direction;  ///< direction of positive acceleration ("N", "W", "azimuth 228 deg", "not stated ...")
  std::string distance_kind;       ///< "Rjb", "Repi" or "Rrup" ("" if unknown)
  /// NTC 2018 Tab. 3.2.II class (issue 38, site_class_of): the one its Vs30
  /// implies (A..D), else the one the source states (site_class_stated of
  /// metadata.csv), else "".
  std::string site_class;
  std::string site_class_basis;    ///< "Vs30" (Tab. 3.2.II bands), "stated" (by the source) or ""
  std::string vs30_class;          ///< the class Vs30 implies ("" without Vs30); differs only from a stated E
  std::string content_hash;        ///< FNV-1a 64 of the file's bytes (16 hex digits), computed at build
  /// Pulse classification given by a source: "pulse-like", "non-pulse" or "" (not classified).
  std::string pulse;
  std::string country, terms;
  double Mw = std::numeric_limits<double>::quiet_NaN();                ///< moment magnitude (-)
  double distance_km = std::numeric_limits<double>::quiet_NaN();       ///< source-to-site distance (km)
  double vs30_m_s = std::numeric_limits<double>::quiet_NaN();          ///< Vs30 (m/s)
  double lowest_usable_hz = std::numeric_limits<double>::quiet_NaN();  ///< lowest usable frequency / high-pass corner (Hz)
  double pulse_period_s = std::numeric_limits<double>::quiet_NaN();    ///< Tp of a pulse-like record (s)
  double significant_duration_s = 0.0;  ///< D5-95 of the Arias intensity (s), Trifunac & Brady (1975)
  long npts = 0;          ///< number of samples
  double dt_s = 0.0;      ///< time step (s)
  double pga_g = 0.0;     ///< peak ground acceleration (g, g_n = 9.80665 m/s^2), computed from the file
  double plain_dt_s = 0.0;       ///< plain text files only: time step given in the table (s)
  std::string plain_unit;        ///< plain text files only: unit of the values ("g", "m/s2", "cm/s2")
  bool usable_for_design = true;  ///< false: see `note` for the reason
};

struct RecordCatalogue {
  std::string directory;  ///< folder holding the record files
  std::string path;       ///< the catalogue.json read ("" if built in memory)
  std::uint64_t text_hash = 0;  ///< content_hash of catalogue.json's bytes (0 if built in memory)
  std::string description;
  std::vector<CatalogueEntry> entries;

  /// Entry by id or file name (path relative to the directory); nullptr if absent.
  const CatalogueEntry* find(const std::string& id_or_file) const;
  /// Entries with usable_for_design = true.
  std::vector<CatalogueEntry> design_candidates() const;
  /// Reads the record of an entry (by id or file name); plain text files with
  /// the entry's time step and unit. Through the bounded reader; a file whose
  /// bytes differ from the entry's content_hash is refused ("changed since the
  /// catalogue was built"), in every command (issue 39).
  /// @throws InputError if absent, unreadable or changed
  Record load(const std::string& id_or_file) const;
  /// Same for an entry.
  Record load(const CatalogueEntry& entry) const;
  /// Reads the records of `entries` on all cores, in order. A file that
  /// cannot be read leaves an empty Record and its message in errors[i]
  /// ("" for the others); nothing is thrown for unreadable files.
  std::vector<Record> load_all(const std::vector<CatalogueEntry>& entries, std::vector<std::string>& errors) const;
};

/// Site class of NTC 2018 Tab. 3.2.II (= EC8 Tab. 3.1) implied by Vs30 (m/s):
/// A > 800 ("superiori a 800 m/s"), B 360-800, C 180-360, D < 180; 800
/// itself is B, and a value on the 360 or 180 bound takes the stiffer class
/// (B, C). Class E needs the stratigraphy
/// and is only taken where a source states it. "" for a non-finite Vs30.
std::string site_class_from_vs30(double vs30_m_s);

/// A record's site class and its basis ("Vs30", "stated" or "").
struct SiteClass {
  std::string site_class, basis;
};
/// Issue 38 (docs/theory/record-selection.md §3): the Tab. 3.2.II band of
/// the station's Vs30 where there is one (basis "Vs30"), the class the
/// source states only where there is none (basis "stated"); a stated E is
/// kept where Vs30 gives C or D (E is C or D velocities over a substrate
/// within 30 m: Vs30 cannot show it, and does not contradict it).
SiteClass site_class_of(double vs30_m_s, const std::string& stated);

/// Distance below which a record is near-fault (km, docs/theory/record-selection.md §2.4).
inline constexpr double near_fault_distance_km = 10.0;

/// Why a record is near-fault or pulse-like, "" if its metadata do not say so
/// (docs/theory/record-selection.md §2.4): pulse-like by its source's
/// classification; or its catalogued distance below `threshold_km` (km) of
/// any kind (Rjb <= Repi, so an epicentral distance below the threshold puts
/// the rupture's surface projection within it too).
std::string near_fault_reason(const CatalogueEntry& e, double threshold_km = near_fault_distance_km);

/// Weak motion threshold of the catalogue (g): a component whose PGA is
/// below it is not usable for design (docs/theory/record-selection.md §3).
inline constexpr double weak_motion_pga_g = 0.01;

/// The physical ranges of a catalogue's numbers, in their units: one place
/// for metadata.csv and catalogue.json alike (issue 39: Mw 1e308, a distance
/// of -5 km, Vs30 -1 m/s or dt 0 in a catalogue were taken as they were).
namespace catalogue_rules {
inline constexpr NumberRule Mw{"-", 2.0, 10.0, false, false, "the moment magnitude of a recorded earthquake"};
inline constexpr NumberRule distance_km{"km", 0.0, 20000.0, false, false,
                                        "a source-to-site distance on the Earth: at most half its circumference"};
inline constexpr NumberRule vs30_m_s{"m/s", 50.0, 5000.0, false, false,
                                     "Vs30 of a recording site: soft soils about 100, hard rock about 3000 m/s"};
inline constexpr NumberRule lowest_usable_hz{"Hz", 0.0, 100.0, false, false,
                                             "a high-pass corner of processed strong-motion data"};
inline constexpr NumberRule pulse_period_s{"s", 0.01, 100.0, false, false, "the period of a velocity pulse"};
/// The time step a table gives a plain text file (record_io.hpp's range is wider: any record).
inline constexpr NumberRule plain_dt_s{"s", 1e-5, 1.0, false, false, "strong-motion records are sampled at 0.001-0.04 s"};
inline constexpr NumberRule dt_s{"s", record_dt_min_s, record_dt_max_s, false, false, "the time step of any record"};
inline constexpr NumberRule pga_g{"g", 0.0, 100.0, false, false, "the peak acceleration of a ground-motion record"};
inline constexpr NumberRule significant_duration_s{"s", 0.0, 1e10, false, false,
                                                   "D5-95 of a record: at most 1e9 samples of 10 s"};
/// Samples of a record file (the readers' limit, record_io.cpp).
inline constexpr double npts_max = 1e9;
}  // namespace catalogue_rules

/// Builds the catalogue from a metadata table (CSV, one row per record file,
/// columns listed in spectra/records/README.md) and the record files next to
/// it: reads every file, computes npts, dt, PGA and D5-95, derives the site
/// class, and decides usable_for_design (excluded in the table, weak motion,
/// or Mw / distance / site class missing). The table is held to the rules of
/// case files (issue 39): every cell without control characters, numbers
/// decimal and within catalogue_rules, a UTF-8 byte order mark accepted, a
/// column named twice refused, a file name that gives no record id refused.
/// @throws InputError naming the table, row and column for a bad row or an unreadable file
RecordCatalogue build_catalogue(const std::string& metadata_csv);

/// The same from the table's text (`table` names it in errors and gives the
/// folder of the files); `read_record_file(path)` returns a record file's
/// bytes (build_catalogue: the bounded reader). For the fuzzers of fuzz/.
RecordCatalogue catalogue_from_metadata(const std::string& text, const std::string& table,
                                        const std::function<std::string(const std::string&)>& read_record_file);

/// The catalogue as seen from the folder `directory`: every entry's file
/// rewritten relative to it (`assess records build --output` in another
/// folder writes a catalogue whose paths resolve from where it is; issue 39).
/// @throws InputError when a file has no relative path from there
void relocate_catalogue(RecordCatalogue& cat, const std::string& directory);

/// catalogue.json text (2-space indent, stable order) of `cat`.
std::string catalogue_json(const RecordCatalogue& cat);

/// Reads a catalogue.json (the bounded reader); the record files are looked
/// up in its folder.
/// @throws InputError for a missing file or a malformed catalogue
RecordCatalogue read_catalogue(const std::string& path);

/// Parses catalogue.json text read from `path` (named in errors, its folder
/// the records' folder). Every entry is checked as metadata.csv is: the JSON
/// path of a bad value (/records/12/Mw), a unique non-empty id, a file name,
/// numbers within catalogue_rules, no control characters, an entry usable
/// for design only with its Mw, distance and site class.
/// @throws InputError for a malformed catalogue
RecordCatalogue parse_catalogue_text(const std::string& text, const std::string& path);

}  // namespace assess

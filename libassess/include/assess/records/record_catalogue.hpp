// record_catalogue.hpp: the machine-readable list of the accelerograms
// shipped in spectra/records/ (catalogue.json), its generation from the
// record files plus a metadata table (metadata.csv), and its reading.
#pragma once

#include "assess/records/record.hpp"

#include <cstdint>
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
  /// the entry's time step and unit.
  /// @throws InputError if absent or unreadable
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

/// Builds the catalogue from a metadata table (CSV, one row per record file,
/// columns listed in spectra/records/README.md) and the record files next to
/// it: reads every file, computes npts, dt, PGA and D5-95, derives the site
/// class, and decides usable_for_design (excluded in the table, weak motion,
/// or Mw / distance / site class missing).
/// @throws InputError naming the table, row and column for a bad row or an unreadable file
RecordCatalogue build_catalogue(const std::string& metadata_csv);

/// catalogue.json text (2-space indent, stable order) of `cat`.
std::string catalogue_json(const RecordCatalogue& cat);

/// Reads a catalogue.json; the record files are looked up in its folder.
/// @throws InputError for a missing file or a malformed catalogue
RecordCatalogue read_catalogue(const std::string& path);

}  // namespace assess

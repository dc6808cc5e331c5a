// record_catalogue.hpp: the machine-readable list of the accelerograms
// shipped in spectra/records/ (catalogue.json), for record selection.
#pragma once

#include "assess/records/record.hpp"

#include <string>
#include <vector>

namespace assess {

/// One record file of the catalogue.
struct CatalogueEntry {
  std::string id;         ///< file name without extension
  std::string file;       ///< file name in the catalogue's directory
  std::string format;     ///< "PEER AT2", "ESM ASCII", "ITACA ASCII", "GEM cor.acc"
  std::string event, date, station, component, source, note;
  long npts = 0;          ///< number of samples
  double dt_s = 0.0;      ///< time step (s)
  double pga_g = 0.0;     ///< peak ground acceleration (g, g_n = 9.80665 m/s^2)
  bool usable_for_design = true;  ///< false: format samples and unprocessed records (see note)
};

struct RecordCatalogue {
  std::string directory;  ///< folder holding the record files
  std::vector<CatalogueEntry> entries;

  /// Entry by id or file name; nullptr if absent.
  const CatalogueEntry* find(const std::string& id_or_file) const;
  /// Entries with usable_for_design = true.
  std::vector<CatalogueEntry> design_candidates() const;
  /// Reads the record of an entry (by id or file name).
  /// @throws InputError if absent or unreadable
  Record load(const std::string& id_or_file) const;
};

/// Reads a catalogue.json; the record files are looked up in its folder.
/// @throws InputError for a missing file or a malformed catalogue
RecordCatalogue read_catalogue(const std::string& path);

}  // namespace assess

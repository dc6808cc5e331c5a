// record_spectra.hpp: the pseudo-acceleration spectra of every record of the
// library, computed once by `assess records build` on a fixed period grid
// and stored beside the catalogue (spectra.bin), so that a selection reads
// and interpolates them instead of integrating every candidate again
// (docs/theory/record-selection.md §2.6).
#pragma once

#include "assess/records/record_catalogue.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace assess {

/// The fixed period grid (s): 0 (the PGA), then log-spaced from
/// spectra_grid_T_min_s to spectra_grid_T_max_s with
/// spectra_grid_per_decade points per decade (both ends included).
inline constexpr double spectra_grid_T_min_s = 0.01;
inline constexpr double spectra_grid_T_max_s = 10.0;
inline constexpr int spectra_grid_per_decade = 200;
/// The dampings stored (fractions): the 5 % of NTC 2018 §3.2.3.6, the only
/// one the selection and the compatibility check use.
inline const std::vector<double>& library_spectra_dampings();
std::vector<double> spectra_grid_periods();

/// Name of the spectra file beside catalogue.json.
inline constexpr const char* library_spectra_file = "spectra.bin";

/// PSA (m/s^2) of records on a period grid, one row per (record, damping).
struct LibrarySpectra {
  std::vector<double> periods;     ///< s: 0, then increasing
  std::vector<double> dampings;    ///< fractions of critical
  std::vector<std::string> ids;    ///< catalogue ids of the rows' records
  std::vector<double> psa;         ///< m/s^2, [record][damping][period]
  /// content_hash of the catalogue.json these spectra were computed for.
  std::uint64_t catalogue_hash = 0;

  /// Row of a record (position in ids) at a damping (position in dampings).
  const double* row(std::size_t record, std::size_t damping) const {
    return psa.data() + (record * dampings.size() + damping) * periods.size();
  }
  /// Position of a record id in ids; -1 if absent.
  long find(const std::string& id) const;
  /// Position of a damping in dampings (compared exactly); -1 if absent.
  long find_damping(double damping_ratio) const;
  /// PSA of `row` at T (s) in [0, periods.back()]: linear in T between 0
  /// and the first positive grid period, log-log linear between grid
  /// periods (docs/theory/record-selection.md §2.6).
  /// @throws InputError for T outside the grid
  double interpolate(const double* row, double T) const;
};

/// The spectra of the catalogue's records usable for design, at the grid
/// periods and `dampings`, by exact integration (response_spectrum.hpp,
/// default sub-stepping), on all cores. catalogue_hash is cat.text_hash.
LibrarySpectra compute_library_spectra(const RecordCatalogue& cat,
                                       const std::vector<double>& dampings = library_spectra_dampings());

/// Writes the binary file (layout in docs/theory/record-selection.md §2.6):
/// a header, the grid, the ids, the PSA as little-endian doubles, and the
/// content hash of everything before it. @throws InputError if it cannot be written
void write_library_spectra(const LibrarySpectra& s, const std::string& path);

/// Reads a spectra file (the bounded reader) and checks it: its own content
/// hash (a damaged file), that it was computed for this catalogue (the
/// catalogue's text hash; a catalogue rebuilt or edited since makes it
/// stale), its counts against its size in 64-bit arithmetic before any
/// allocation, and then what it holds (issue 39): a period grid from 0 s,
/// finite and strictly increasing; dampings in (0, 1); the catalogue's usable
/// records in its order; at T = 0 each record's PGA; every ordinate positive
/// and at most PGA/(xi sqrt(1 - xi^2)), the bound of any oscillator's response.
/// @throws InputError naming the file and why it cannot be used
LibrarySpectra read_library_spectra(const std::string& path, const RecordCatalogue& cat);
/// The same checks of a spectra file's bytes (`path` names it in errors),
/// for the fuzzers of fuzz/.
LibrarySpectra parse_library_spectra(const std::string& bytes, const std::string& path, const RecordCatalogue& cat);

inline const std::vector<double>& library_spectra_dampings() {
  static const std::vector<double> d{0.05};
  return d;
}

}  // namespace assess

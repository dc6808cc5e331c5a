// record_library.hpp: the record library of one catalogue.json as a process
// shares it: the catalogue read once, its precomputed spectra (spectra.bin,
// checked against the catalogue), and every record file parsed at most once,
// shared by every selection, mechanism and thread of the process
// (docs/theory/record-selection.md §2.6).
#pragma once

#include "assess/records/floor_motion.hpp"
#include "assess/records/record.hpp"
#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_spectra.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace assess {

namespace detail {
template <typename T>
class OnceValue;
}

class RecordLibrary {
 public:
  /// The library of the catalogue.json at `catalogue_path`, shared by the
  /// process: read and checked once, again only if the file's content
  /// changed. Thread-safe. Its spectra.bin (same folder) is used when it was
  /// built for this catalogue; otherwise spectra() is null and
  /// spectra_problem() says why (missing, damaged, stale): the selection then
  /// integrates its candidates' spectra and warns.
  /// @throws InputError for a missing or malformed catalogue
  static std::shared_ptr<const RecordLibrary> open(const std::string& catalogue_path);

  /// A library of a catalogue held in memory (no process sharing).
  explicit RecordLibrary(RecordCatalogue cat);

  const RecordCatalogue& catalogue() const { return cat_; }
  const LibrarySpectra* spectra() const { return spectra_ ? &*spectra_ : nullptr; }
  const std::string& spectra_problem() const { return spectra_problem_; }

  /// The record of an entry (SI units, name = the entry's id), parsed once
  /// per library and shared; thread-safe. A file whose bytes differ from the
  /// catalogue's content_hash is refused (changed since `assess records build`),
  /// and every caller gets the same error.
  /// @throws InputError naming the file
  std::shared_ptr<const Record> record(const CatalogueEntry& e) const;

  /// PSA (m/s^2) of an entry's record at `periods` (s) and `damping_ratio`
  /// (fraction), integrated exactly (response_spectrum.hpp) once per library
  /// for the same periods and damping, and shared: the report curves of the
  /// records that several mechanisms or candidates use. With `floor`, the
  /// PSA of the record's floor motion (floor_motion.hpp) under that filter.
  /// Thread-safe.
  std::shared_ptr<const std::vector<double>> psa(const CatalogueEntry& e, const std::vector<double>& periods,
                                                 double damping_ratio, const FloorFilter* floor = nullptr) const;

 private:
  RecordCatalogue cat_;
  std::optional<LibrarySpectra> spectra_;
  std::string spectra_problem_;
  mutable std::mutex mutex_;
  // Each record and each report spectrum is computed once, by the first
  // thread that asks; its value or its error is shared (support/once_value.hpp).
  mutable std::map<std::string, std::shared_ptr<detail::OnceValue<Record>>> records_;
  mutable std::map<std::string, std::shared_ptr<detail::OnceValue<std::vector<double>>>> spectra_memo_;
};

}  // namespace assess

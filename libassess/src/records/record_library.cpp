// record_library.cpp: the process's record library (record_library.hpp).
#include "assess/records/record_library.hpp"

#include "assess/records/record_io.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/content_hash.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "support/once_value.hpp"

#include <filesystem>

namespace assess {

RecordLibrary::RecordLibrary(RecordCatalogue cat) : cat_(std::move(cat)) {
  const std::string path = cat_.directory + "/" + library_spectra_file;
  if (cat_.text_hash == 0) {
    spectra_problem_ = "the catalogue was not read from a file";
    return;
  }
  try {
    spectra_ = read_library_spectra(path, cat_);
  } catch (const InputError& e) {
    spectra_problem_ = e.what();
  }
}

std::shared_ptr<const RecordLibrary> RecordLibrary::open(const std::string& catalogue_path) {
  // Per path: the library, and the size and modification time of the file
  // its text had; an unchanged stat is trusted (no re-read), a changed one
  // re-reads the text and compares its content hash.
  struct Cached {
    std::shared_ptr<const RecordLibrary> lib;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type mtime{};
  };
  static std::mutex mutex;
  static std::map<std::string, Cached> libraries;
  // The bounded reader's checks first (issue 39: a directory gave an internal
  // error, /dev/zero ran out of memory): a regular file within its limit.
  check_input_file(catalogue_path, input_kinds::record_catalogue);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(catalogue_path, ec);
  const std::filesystem::file_time_type mtime = ec ? std::filesystem::file_time_type{}
                                                   : std::filesystem::last_write_time(catalogue_path, ec);
  std::lock_guard<std::mutex> lock(mutex);
  auto it = libraries.find(catalogue_path);
  if (!ec && it != libraries.end() && it->second.size == size && it->second.mtime == mtime) return it->second.lib;
  const std::string text = read_input_file(catalogue_path, input_kinds::record_catalogue);
  const std::uint64_t h = content_hash(text);
  if (it != libraries.end() && it->second.lib->cat_.text_hash == h) {
    it->second.size = size, it->second.mtime = mtime;
    return it->second.lib;
  }
  auto lib = std::make_shared<const RecordLibrary>(parse_catalogue_text(text, catalogue_path));
  libraries[catalogue_path] = Cached{lib, ec ? 0 : size, mtime};
  return lib;
}

std::shared_ptr<const Record> RecordLibrary::record(const CatalogueEntry& e) const {
  std::shared_ptr<detail::OnceValue<Record>> slot;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& s = records_[e.id];
    if (!s) s = std::make_shared<detail::OnceValue<Record>>();
    slot = s;
  }
  // One thread reads and parses; the others wait for it and share its record,
  // or its error (a file missing, unreadable or changed since the build:
  // RecordCatalogue::load names it), never an exception through call_once.
  return slot->get([&] { return std::make_shared<const Record>(cat_.load(e)); });
}

std::shared_ptr<const std::vector<double>> RecordLibrary::psa(const CatalogueEntry& e, const std::vector<double>& periods,
                                                             double damping_ratio, const FloorFilter* floor) const {
  std::string key = e.id + "|";  // the id, then the exact bytes of the periods and damping
  key.append(reinterpret_cast<const char*>(periods.data()), periods.size() * sizeof(double));
  key.append(reinterpret_cast<const char*>(&damping_ratio), sizeof damping_ratio);
  if (floor)
    for (double v : {floor->T1, floor->xi, floor->gamma_psi}) key.append(reinterpret_cast<const char*>(&v), sizeof v);
  std::shared_ptr<detail::OnceValue<std::vector<double>>> slot;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& s = spectra_memo_[key];
    if (!s) s = std::make_shared<detail::OnceValue<std::vector<double>>>();
    slot = s;
  }
  return slot->get([&] {
    ResponseOptions ro;
    ro.damping_ratio = damping_ratio;
    const std::shared_ptr<const Record> r = record(e);
    return std::make_shared<const std::vector<double>>(
        response_spectrum(floor ? floor_motion(*r, *floor) : *r, periods, ro).psa());
  });
}

}  // namespace assess

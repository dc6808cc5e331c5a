// record_library.cpp: the process's record library (record_library.hpp).
#include "assess/records/record_library.hpp"

#include "assess/records/record_io.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/content_hash.hpp"
#include "assess/support/error.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace assess {

namespace {

std::string read_bytes(const std::string& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(std::string("cannot open ") + what + " '" + path + "'");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

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
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(catalogue_path, ec);
  const std::filesystem::file_time_type mtime = ec ? std::filesystem::file_time_type{}
                                                   : std::filesystem::last_write_time(catalogue_path, ec);
  std::lock_guard<std::mutex> lock(mutex);
  auto it = libraries.find(catalogue_path);
  if (!ec && it != libraries.end() && it->second.size == size && it->second.mtime == mtime) return it->second.lib;
  const std::uint64_t h = content_hash(read_bytes(catalogue_path, "record catalogue"));
  if (it != libraries.end() && it->second.lib->cat_.text_hash == h) {
    it->second.size = size, it->second.mtime = mtime;
    return it->second.lib;
  }
  auto lib = std::make_shared<const RecordLibrary>(read_catalogue(catalogue_path));
  libraries[catalogue_path] = Cached{lib, ec ? 0 : size, mtime};
  return lib;
}

std::shared_ptr<const Record> RecordLibrary::record(const CatalogueEntry& e) const {
  std::shared_ptr<Slot> slot;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::shared_ptr<Slot>& s = records_[e.id];
    if (!s) s = std::make_shared<Slot>();
    slot = s;
  }
  // One thread parses; the others wait for it. If it throws, the next caller tries again.
  std::call_once(slot->once, [&] {
    const std::string path = cat_.directory + "/" + e.file;
    const std::string bytes = read_bytes(path, "record file");
    if (!e.content_hash.empty() && hash_hex(content_hash(bytes)) != e.content_hash)
      throw InputError(path + ": the file changed since the catalogue was built (content hash " +
                       hash_hex(content_hash(bytes)) + ", catalogue " + e.content_hash +
                       "): run `assess records build`");
    Record r = e.plain_unit.empty()
                   ? parse_record_text(bytes, path)
                   : parse_plain_record_text(bytes, path, e.plain_dt_s, parse_acceleration_unit(e.plain_unit));
    r.name = e.id;
    slot->record = std::make_shared<const Record>(std::move(r));
  });
  return slot->record;
}

std::shared_ptr<const std::vector<double>> RecordLibrary::psa(const CatalogueEntry& e, const std::vector<double>& periods,
                                                             double damping_ratio, const FloorFilter* floor) const {
  std::string key = e.id + "|";  // the id, then the exact bytes of the periods and damping
  key.append(reinterpret_cast<const char*>(periods.data()), periods.size() * sizeof(double));
  key.append(reinterpret_cast<const char*>(&damping_ratio), sizeof damping_ratio);
  if (floor)
    for (double v : {floor->T1, floor->xi, floor->gamma_psi}) key.append(reinterpret_cast<const char*>(&v), sizeof v);
  std::shared_ptr<SpectrumSlot> slot;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::shared_ptr<SpectrumSlot>& s = spectra_memo_[key];
    if (!s) s = std::make_shared<SpectrumSlot>();
    slot = s;
  }
  std::call_once(slot->once, [&] {
    ResponseOptions ro;
    ro.damping_ratio = damping_ratio;
    const std::shared_ptr<const Record> r = record(e);
    slot->psa = std::make_shared<const std::vector<double>>(
        response_spectrum(floor ? floor_motion(*r, *floor) : *r, periods, ro).psa());
  });
  return slot->psa;
}

}  // namespace assess

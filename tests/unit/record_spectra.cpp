// The record library's precomputed spectra (issues 30, 32): the build is
// reproducible byte for byte, the file reads back as written, a damaged,
// stale or missing file is refused with its reason (and the library then
// reports it and integrates instead), the stored ordinates are the integrated
// ones at the grid periods, the content hashes, and the process's library
// (one parse per record, shared; re-read when the catalogue changes). On the
// small library tests/data/records_mini (3 usable records, short files).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_library.hpp>
#include <assess/records/record_spectra.hpp>
#include <assess/records/response_spectrum.hpp>
#include <assess/support/content_hash.hpp>
#include <assess/support/error.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "test_files.hpp"

using namespace assess;
namespace fs = std::filesystem;

namespace {

const std::string kMini = std::string(ASSESS_TEST_DATA_DIR) + "/tests/data/records_mini/metadata.csv";

void spit(const std::string& p, const std::string& bytes) {
  std::ofstream o(p, std::ios::binary | std::ios::trunc);
  o << bytes;
}

// A catalogue as `assess records build` makes it: the JSON text's hash ties the spectra to it.
RecordCatalogue built() {
  RecordCatalogue cat = build_catalogue(kMini);
  cat.text_hash = content_hash(catalogue_json(cat));
  return cat;
}

std::string message_of(const std::string& path, const RecordCatalogue& cat) {
  try {
    read_library_spectra(path, cat);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("FNV-1a 64: the published test vectors") {
  // Fowler-Noll-Vo reference values for FNV-1a 64.
  CHECK(content_hash(std::string()) == 0xcbf29ce484222325ull);
  CHECK(content_hash(std::string("a")) == 0xaf63dc4c8601ec8cull);
  CHECK(content_hash(std::string("foobar")) == 0x85944171f73967e8ull);
  CHECK(hash_hex(0xaf63dc4c8601ec8cull) == "af63dc4c8601ec8c");
}

TEST_CASE("the build is reproducible: catalogue.json and spectra.bin byte for byte") {
  const RecordCatalogue a = built(), b = built();
  CHECK(catalogue_json(a) == catalogue_json(b));
  const std::string dir = (fs::temp_directory_path() / "assess_records_mini_build").string();
  fs::create_directories(dir);
  write_library_spectra(compute_library_spectra(a), dir + "/a.bin");
  write_library_spectra(compute_library_spectra(b), dir + "/b.bin");
  const std::string sa = slurp(dir + "/a.bin");
  CHECK(sa.size() > 3 * 602 * 8);
  CHECK(sa == slurp(dir + "/b.bin"));
  // Every file's content hash is in the catalogue.
  for (const CatalogueEntry& e : a.entries) CHECK(e.content_hash == hash_hex(file_content_hash(a.directory + "/" + e.file, input_kinds::record_file)));
}

TEST_CASE("the spectra read back as written; the stored ordinates are the integrated ones at the grid periods") {
  const RecordCatalogue cat = built();
  const LibrarySpectra s = compute_library_spectra(cat);
  // The grid: 0, then 0.01-10 s at 200 per decade (601 periods).
  REQUIRE(s.periods.size() == 602);
  CHECK(s.periods[0] == 0.0);
  CHECK(s.periods[1] == spectra_grid_T_min_s);
  CHECK(s.periods.back() == spectra_grid_T_max_s);
  CHECK(s.dampings == std::vector<double>{0.05});
  CHECK(s.ids == std::vector<std::string>{"elCentro", "ARL360", "RSN289_1"});  // the usable ones, in order
  const std::string path = (fs::temp_directory_path() / "assess_records_mini_rw.bin").string();
  write_library_spectra(s, path);
  const LibrarySpectra r = read_library_spectra(path, cat);
  CHECK(r.periods == s.periods);
  CHECK(r.ids == s.ids);
  CHECK(r.psa == s.psa);
  CHECK(r.catalogue_hash == cat.text_hash);
  // Stored = integrated (same code, same periods: exactly equal).
  for (std::size_t i = 0; i < r.ids.size(); ++i) {
    const ResponseSpectrum rs = response_spectrum(cat.load(r.ids[i]), r.periods);
    for (std::size_t j = 0; j < r.periods.size(); j += 37) CHECK(r.row(i, 0)[j] == rs.ordinates[j].PSA);
    CHECK(r.row(i, 0)[0] == cat.load(r.ids[i]).pga());  // T = 0: the PGA
  }
  // At a grid period the interpolation returns the stored value; outside the grid it refuses.
  CHECK(r.interpolate(r.row(0, 0), r.periods[100]) == r.row(0, 0)[100]);
  CHECK_THROWS_AS(r.interpolate(r.row(0, 0), 10.5), InputError);
}

TEST_CASE("a damaged, stale, truncated or missing spectra file is refused with its reason") {
  const RecordCatalogue cat = built();
  const std::string path = (fs::temp_directory_path() / "assess_records_mini_bad.bin").string();
  write_library_spectra(compute_library_spectra(cat), path);
  const std::string good = slurp(path);
  std::string bytes = good;
  bytes[bytes.size() / 2] ^= 0x01;  // one bit of one ordinate
  spit(path, bytes);
  CHECK(message_of(path, cat).find("content hash mismatch (damaged file)") != std::string::npos);
  spit(path, good.substr(0, good.size() - 100));
  CHECK(message_of(path, cat).find("damaged") != std::string::npos);
  spit(path, good);
  CHECK(message_of(path, cat).empty());
  RecordCatalogue other = cat;
  other.text_hash ^= 1;  // a catalogue.json edited or rebuilt since
  CHECK(message_of(path, other).find("stale, rebuild them with `assess records build`") != std::string::npos);
  CHECK(message_of(path + ".nope", cat).find("not found") != std::string::npos);
  spit(path, "not a spectra file at all, long enough to have a header and a hash");
  CHECK(message_of(path, cat).find("not a spectra file of this version") != std::string::npos);
}

TEST_CASE("the process's library: catalogue read once, records parsed once and shared, stale spectra reported") {
  const std::string dir = (fs::temp_directory_path() / "assess_records_mini_lib").string();
  fs::remove_all(dir);
  fs::create_directories(dir);
  // A copy of the small library beside its catalogue, as `assess records build` leaves it.
  RecordCatalogue cat = build_catalogue(kMini);
  for (CatalogueEntry& e : cat.entries) {
    fs::copy_file(cat.directory + "/" + e.file, dir + "/" + fs::path(e.file).filename().string());
    e.file = fs::path(e.file).filename().string();
  }
  cat.directory = dir;
  const std::string text = catalogue_json(cat);
  spit(dir + "/catalogue.json", text);
  cat.text_hash = content_hash(text);
  write_library_spectra(compute_library_spectra(cat), dir + "/" + library_spectra_file);

  const auto lib = RecordLibrary::open(dir + "/catalogue.json");
  CHECK(lib == RecordLibrary::open(dir + "/catalogue.json"));  // the same, shared
  REQUIRE(lib->spectra());
  CHECK(lib->spectra_problem().empty());
  const CatalogueEntry& e = *lib->catalogue().find("ARL360");
  std::shared_ptr<const Record> r1, r2;
  std::thread t([&] { r1 = lib->record(e); });
  r2 = lib->record(e);
  t.join();
  CHECK(r1 == r2);  // parsed once, the same object for both threads
  CHECK(r1->size() == 2000);
  // Report spectra, integrated once per (record, periods, damping).
  const std::vector<double> T{0.1, 0.5, 1.0};
  CHECK(lib->psa(e, T, 0.05) == lib->psa(e, T, 0.05));
  CHECK(*lib->psa(e, T, 0.05) == response_spectrum(*r1, T).psa());

  // A record file changed since the build is refused by its content hash.
  spit(dir + "/elCentro.AT2", slurp(dir + "/elCentro.AT2") + " ");
  CHECK_THROWS_WITH_AS(lib->record(*lib->catalogue().find("elCentro")),
                       doctest::Contains("the file changed since the catalogue was built"), InputError);
  // The catalogue edited: read again, and its old spectra are stale (reported, not used).
  spit(dir + "/catalogue.json", text + " ");
  const auto lib2 = RecordLibrary::open(dir + "/catalogue.json");
  CHECK(lib2 != lib);
  CHECK(lib2->spectra() == nullptr);
  CHECK(lib2->spectra_problem().find("stale") != std::string::npos);
  fs::remove(dir + "/" + library_spectra_file);
  spit(dir + "/catalogue.json", text + "  ");
  CHECK(RecordLibrary::open(dir + "/catalogue.json")->spectra_problem().find("not found") != std::string::npos);
}

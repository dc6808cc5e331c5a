// libFuzzer harness (issue 39): the reader of the library's precomputed
// spectra (parse_library_spectra: spectra.bin) on arbitrary bytes. The input
// is the file's body after its header; the harness adds the header (magic,
// byte order marker, the hash of a small catalogue of two usable records) and
// the trailing content hash, so that every input passes the hash and reaches
// the checks after it: the counts against the size (64-bit, before any
// allocation), the period grid, the dampings, the records of the catalogue,
// PSA(0) = PGA, every ordinate within (0, PGA/(xi sqrt(1 - xi^2))]. Any
// exception but InputError, any crash, leak, undefined behaviour or
// allocation beyond -rss_limit_mb is a finding. Oracles: accepted spectra
// interpolate to finite positive values over their grid.
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_spectra.hpp>
#include <assess/support/content_hash.hpp>
#include <assess/support/error.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

assess::RecordCatalogue catalogue() {
  assess::RecordCatalogue cat;
  cat.text_hash = 0x0123456789abcdefull;
  for (const char* id : {"a", "b"}) {
    assess::CatalogueEntry e;
    e.id = id;
    e.file = std::string(id) + ".AT2";
    e.pga_g = 0.25;
    e.usable_for_design = true;
    cat.entries.push_back(e);
  }
  return cat;
}

template <typename T>
void put(std::string& s, const T& v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  s.append(b, sizeof(T));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const assess::RecordCatalogue cat = catalogue();
  std::string bytes("ASSESS-SPECTRA-1", 16);
  put(bytes, 1.0);
  put(bytes, cat.text_hash);
  bytes.append(reinterpret_cast<const char*>(data), size);
  put(bytes, assess::content_hash(bytes));
  assess::LibrarySpectra s;
  try {
    s = assess::parse_library_spectra(bytes, "fuzz/spectra.bin", cat);
  } catch (const assess::InputError&) {
    return 0;  // a named input error: the expected outcome for bad bytes
  }
  for (std::size_t i = 0; i < s.ids.size(); ++i)
    for (std::size_t d = 0; d < s.dampings.size(); ++d)
      for (double T : {0.0, 0.5 * s.periods[1], s.periods.back()}) {
        const double v = s.interpolate(s.row(i, d), T);
        if (!(std::isfinite(v) && v > 0.0)) std::abort();
      }
  return 0;
}

// libFuzzer harness (issue 39): the metadata table reader of `assess records
// build` (catalogue_from_metadata: metadata.csv as text) on arbitrary bytes.
// The record files it names are not read from disk: every name reads as one
// short, valid PEER AT2 record (or plain text for a row with plain_unit), so
// the fuzzer exercises the table's rules (columns, quoting, numbers, units,
// text, ids, site classes, the usable-for-design decision). Any exception but
// InputError, any crash, leak or undefined behaviour is a finding. Oracles: an
// accepted catalogue obeys the catalogue's rules and reads back from its JSON.
#include <assess/records/record_catalogue.hpp>
#include <assess/support/error.hpp>
#include <assess/support/number_rules.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

const char* const kAt2 =
    "PEER NGA STRONG MOTION DATABASE RECORD\n"
    "Fuzz 1980, 1/1/1980, Station, 0\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n"
    "NPTS=    8, DT=   .0100 SEC\n"
    "  .0100000  .0500000 -.1000000  .2000000\n"
    " -.1500000  .0800000 -.0200000  .0000000\n";

std::string read_stub(const std::string& path) {
  if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".txt") == 0) return "0.01\n0.05\n-0.1\n0.2\n-0.15\n";
  return kAt2;
}

void require(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  assess::RecordCatalogue cat;
  try {
    cat = assess::catalogue_from_metadata(text, "fuzz/metadata.csv", read_stub);
  } catch (const assess::InputError&) {
    return 0;  // a named input error: the expected outcome for bad bytes
  }
  for (const assess::CatalogueEntry& e : cat.entries) {
    require(!e.id.empty());
    for (const std::string* t : {&e.id, &e.file, &e.event, &e.station, &e.note, &e.source, &e.terms})
      require(assess::control_character_violation(*t).empty());
    for (double v : {e.Mw, e.distance_km, e.vs30_m_s, e.lowest_usable_hz, e.pulse_period_s})
      require(std::isnan(v) || std::isfinite(v));
    if (e.usable_for_design) require(std::isfinite(e.Mw) && std::isfinite(e.distance_km) && !e.site_class.empty());
  }
  // What `records build` writes is what the library reads.
  const assess::RecordCatalogue again = assess::parse_catalogue_text(assess::catalogue_json(cat), "fuzz/catalogue.json");
  require(again.entries.size() == cat.entries.size());
  return 0;
}

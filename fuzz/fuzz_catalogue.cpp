// libFuzzer harness (issue 39): the record catalogue reader
// (parse_catalogue_text: catalogue.json as the record library opens it) on
// arbitrary bytes, then what its users do with a catalogue: the filters of a
// selection, the near-fault reason, and catalogue_json. Any exception but
// InputError, any crash, leak or undefined behaviour is a finding. Oracles:
// an accepted entry obeys the catalogue's rules (numbers finite or unknown,
// ids unique and non-empty, no control character in any text), and the JSON
// written from an accepted catalogue reads back with the same entries.
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_selection.hpp>
#include <assess/support/error.hpp>
#include <assess/support/number_rules.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

void check_entry(const assess::CatalogueEntry& e) {
  require(!e.id.empty() && !e.file.empty());
  for (const std::string* t : {&e.id, &e.file, &e.event, &e.station, &e.note, &e.site_class, &e.pulse})
    require(assess::control_character_violation(*t).empty());
  for (double v : {e.Mw, e.distance_km, e.vs30_m_s, e.lowest_usable_hz, e.pulse_period_s})
    require(std::isnan(v) || std::isfinite(v));
  require(std::isfinite(e.dt_s) && e.dt_s > 0.0 && e.npts >= 1 && std::isfinite(e.pga_g) && e.pga_g >= 0.0);
  if (e.usable_for_design) require(std::isfinite(e.Mw) && std::isfinite(e.distance_km) && !e.site_class.empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  assess::RecordCatalogue cat;
  try {
    cat = assess::parse_catalogue_text(text, "fuzz/catalogue.json");
  } catch (const assess::InputError&) {
    return 0;  // a named input error: the expected outcome for bad bytes
  }
  std::set<std::string> ids;
  for (const assess::CatalogueEntry& e : cat.entries) {
    check_entry(e);
    require(ids.insert(e.id).second);
    (void)assess::near_fault_reason(e);
  }
  try {
    assess::CatalogueFilters f;
    f.site_classes = {"B"};
    (void)assess::filter_catalogue(cat.entries, f);
  } catch (const assess::InputError&) {
  }
  // Written back and read again: the same entries.
  const assess::RecordCatalogue again = assess::parse_catalogue_text(assess::catalogue_json(cat), "fuzz/catalogue.json");
  require(again.entries.size() == cat.entries.size());
  for (std::size_t i = 0; i < cat.entries.size(); ++i) require(again.entries[i].id == cat.entries[i].id);
  return 0;
}

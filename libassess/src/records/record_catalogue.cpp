// record_catalogue.cpp: reader of spectra/records/catalogue.json.
//
// Notation: one JSON object per record file with id, file, format, event, date,
// station, component, npts, dt_s (s), pga_g (g, g_n = 9.80665 m/s^2), source,
// usable_for_design and note (spectra/records/README.md §5).
#include "assess/records/record_catalogue.hpp"

#include "assess/support/error.hpp"
#include "assess/records/record_io.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace assess {

const CatalogueEntry* RecordCatalogue::find(const std::string& id_or_file) const {
  for (const auto& e : entries)
    if (e.id == id_or_file || e.file == id_or_file) return &e;
  return nullptr;
}

std::vector<CatalogueEntry> RecordCatalogue::design_candidates() const {
  std::vector<CatalogueEntry> out;
  for (const auto& e : entries)
    if (e.usable_for_design) out.push_back(e);
  return out;
}

Record RecordCatalogue::load(const std::string& id_or_file) const {
  const CatalogueEntry* e = find(id_or_file);
  if (!e) throw InputError("record '" + id_or_file + "' is not in the catalogue of " + directory);
  return read_record(directory + "/" + e->file);
}

RecordCatalogue read_catalogue(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot open record catalogue '" + path + "'");
  RecordCatalogue cat;
  const auto slash = path.find_last_of('/');
  cat.directory = slash == std::string::npos ? "." : path.substr(0, slash);
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const auto& r : j.at("records")) {
      CatalogueEntry e;
      e.id = r.at("id").get<std::string>();
      e.file = r.at("file").get<std::string>();
      e.format = r.at("format").get<std::string>();
      e.event = r.value("event", "");
      e.date = r.value("date", "");
      e.station = r.value("station", "");
      e.component = r.value("component", "");
      e.source = r.value("source", "");
      e.note = r.value("note", "");
      e.npts = r.at("npts").get<long>();
      e.dt_s = r.at("dt_s").get<double>();
      e.pga_g = r.at("pga_g").get<double>();
      e.usable_for_design = r.value("usable_for_design", true);
      cat.entries.push_back(std::move(e));
    }
  } catch (const nlohmann::json::exception& ex) {
    throw InputError("malformed record catalogue '" + path + "': " + ex.what());
  }
  return cat;
}

}  // namespace assess

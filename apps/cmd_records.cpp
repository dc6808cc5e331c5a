// cmd_records.cpp: `assess records`, the record library: build the catalogue
// from metadata.csv and the files, list/filter it, show one record, and
// select a spectrum-compatible set for a site without a mechanism (REXEL's
// use case). Parses, calls the library and prints.
#include "commands.hpp"

#include <assess/hazard/site.hpp>
#include <assess/records/library_selection.hpp>
#include <assess/report/records_report.hpp>
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_library.hpp>
#include <assess/records/record_selection.hpp>
#include <assess/records/record_spectra.hpp>
#include <assess/support/content_hash.hpp>
#include <assess/records/response_spectrum.hpp>
#include <assess/support/error.hpp>
#include <assess/support/output_file.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/units.hpp>
#include <assess/hazard/hazard.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace assess::cli {

namespace {

struct RecordsArgs {
  std::string catalogue, metadata, output;
  std::optional<double> mw_min, mw_max, r_min, r_max;
  std::vector<std::string> site_classes, countries;
  bool all = false, json = false, no_relax = false;
  std::string id;
  // select
  std::optional<double> lat, lon, ag_g, F0, Tc_star, t_min, t_max;
  std::string soil = "A", topography = "T1", limit_state = "SLV";
  double vn = 50.0, cu = 1.0;
  int count = 7, per_event = 3, per_station = 1;
  double max_scale = 3.0, max_mean_scale = 2.0, max_pga_ratio = 2.5, max_misfit = 0.5, near_fault_km = 10.0;
  std::string near_fault = "exclude";
};

std::string default_catalogue() { return data_dir() + "/spectra/records/catalogue.json"; }

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : slash == 0 ? std::string("/") : path.substr(0, slash);
}

std::string num(double v, const char* f = "%.3g") {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The filter options of the command line (report/records_report.hpp).
RecordFilterOptions filter_options(const RecordsArgs& a) {
  RecordFilterOptions o;
  o.mw_min = a.mw_min, o.mw_max = a.mw_max, o.r_min = a.r_min, o.r_max = a.r_max;
  o.site_classes = a.site_classes;
  o.countries = a.countries;
  o.relax = !a.no_relax;
  return o;
}

void run_build(const RecordsArgs& a) {
  const std::string table = a.metadata.empty() ? data_dir() + "/spectra/records/metadata.csv" : a.metadata;
  const std::string out = a.output.empty() ? directory_of(table) + "/catalogue.json" : a.output;
  const std::string spectra = directory_of(out) + "/" + library_spectra_file;
  // The two outputs, neither an input (the table, a record) nor each other
  // (--output DIR/spectra.bin), refused before the records are read.
  check_output_files({{out, "--output", ""}, {spectra, "the record spectra", ""}});
  RecordCatalogue cat = build_catalogue(table);
  // A catalogue written in another folder than the table's: its file paths
  // relative to where it is, so that they resolve (issue 39).
  std::error_code ec;
  if (!std::filesystem::equivalent(directory_of(out), cat.directory, ec)) relocate_catalogue(cat, directory_of(out));
  const std::string text = catalogue_json(cat);
  write_output_file(out, text, "--output");
  std::size_t usable = 0;
  for (const auto& e : cat.entries) usable += e.usable_for_design;
  std::cout << "wrote " << out << ": " << cat.entries.size() << " components, " << usable << " usable for design\n";
  // The precomputed spectra beside it, tied to this text by its hash (record_spectra.hpp).
  cat.text_hash = content_hash(text);
  const LibrarySpectra s = compute_library_spectra(cat);
  write_library_spectra(s, spectra);
  std::cout << "wrote " << spectra << ": 5 % PSA of " << s.ids.size() << " components at " << s.periods.size()
            << " periods (0, then " << spectra_grid_T_min_s << "-" << spectra_grid_T_max_s << " s, "
            << spectra_grid_per_decade << " per decade), catalogue hash " << hash_hex(cat.text_hash) << "\n";
}

void run_list(const RecordsArgs& a) {
  const RecordCatalogue cat = read_catalogue(a.catalogue.empty() ? default_catalogue() : a.catalogue);
  const std::vector<CatalogueEntry> shown = catalogue_listing(cat, filter_options(a), a.all);
  if (a.json) {
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (const auto& e : shown) j.push_back(catalogue_entry_json(e));
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::printf("%-34s %-38s %4s %-24s %-5s %7s %-4s %6s %2s %-6s %7s %6s %-6s %s\n", "id", "event", "Mw", "station",
              "comp", "R (km)", "kind", "Vs30", "cl", "basis", "PGA (g)", "D5-95", "usable", "near-fault");
  for (const auto& e : shown)
    std::printf("%-34s %-38.38s %4s %-24.24s %-5.5s %7s %-4s %6s %2s %-6s %7s %6s %-6s %s\n", e.id.c_str(),
                e.event.c_str(), num(e.Mw, "%.2f").c_str(), e.station.c_str(), e.component.c_str(),
                num(e.distance_km, "%.1f").c_str(), e.distance_kind.c_str(), num(e.vs30_m_s, "%.0f").c_str(),
                e.site_class.c_str(), e.site_class_basis.c_str(), num(e.pga_g, "%.4f").c_str(),
                num(e.significant_duration_s, "%.1f").c_str(), e.usable_for_design ? "yes" : "no",
                near_fault_reason(e).empty() ? "-" : "yes");
  std::printf("%zu of %zu components%s\n", shown.size(), cat.entries.size(),
              a.all ? "" : " (usable for design; --all lists every file)");
}

void run_show(const RecordsArgs& a) {
  const RecordCatalogue cat = read_catalogue(a.catalogue.empty() ? default_catalogue() : a.catalogue);
  const CatalogueEntry* e = cat.find(a.id);
  if (!e) throw InputError("record '" + a.id + "' is not in the catalogue " + cat.directory + "/catalogue.json");
  const Record r = cat.load(*e);
  const std::vector<double> T = {0.0, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0};
  const ResponseSpectrum rs = response_spectrum(r, T);
  if (a.json) {
    nlohmann::ordered_json j = catalogue_entry_json(*e);
    j["format"] = e->format;
    j["npts"] = e->npts;
    j["dt_s"] = e->dt_s;
    j["source"] = e->source;
    j["terms"] = e->terms;
    j["spectrum"] = {{"damping", 0.05}, {"periods_s", T}, {"psa_g", nlohmann::ordered_json::array()}};
    for (const auto& o : rs.ordinates) j["spectrum"]["psa_g"].push_back(o.PSA / units::g_n);
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << e->id << " (" << e->file << ", " << e->format << ")\n"
            << "  event      " << e->event << ", " << e->date << ", Mw " << num(e->Mw, "%.2f") << ", " << e->mechanism << "\n"
            << "  station    " << e->station << " (" << e->station_code << "), " << e->country << "\n"
            << "  component  " << e->component << ", positive toward " << e->positive_direction << "\n"
            << "  distance   " << num(e->distance_km, "%.1f") << " km (" << e->distance_kind << ")\n"
            << "  site       Vs30 " << num(e->vs30_m_s, "%.0f") << " m/s, class " << e->site_class << " ("
            << (e->site_class_basis == "stated" ? "stated by the source" + (e->vs30_class.empty() ? std::string()
                                                                             : "; Vs30 gives " + e->vs30_class)
                : e->site_class_basis == "Vs30" ? std::string("from Vs30, NTC 2018 Tab. 3.2.II")
                                                : std::string("unknown"))
            << ")\n"
            << "  usable to  " << (std::isfinite(e->lowest_usable_hz) && e->lowest_usable_hz > 0
                                       ? num(1.0 / e->lowest_usable_hz, "%.2f") + " s (1/lowest usable frequency)"
                                       : std::string("not given by the source"))
            << "\n"
            << "  pulse      " << (e->pulse.empty() ? std::string("not classified") : e->pulse)
            << (std::isfinite(e->pulse_period_s) ? ", Tp = " + num(e->pulse_period_s, "%.2f") + " s" : std::string())
            << "\n"
            << "  near-fault " << (near_fault_reason(*e).empty() ? std::string("no") : near_fault_reason(*e)) << "\n"
            << "  samples    " << e->npts << " x " << e->dt_s << " s, PGA " << num(e->pga_g, "%.4f")
            << " g, D5-95 " << num(e->significant_duration_s, "%.1f") << " s\n"
            << "  usable     " << (e->usable_for_design ? "yes" : "no") << (e->note.empty() ? "" : ": " + e->note) << "\n"
            << "  source     " << e->source << "\n  terms      " << e->terms << "\n"
            << "  5 % spectrum (PSA, g):\n";
  for (std::size_t j = 0; j < T.size(); ++j)
    std::printf("    T = %5.2f s  %.4f\n", T[j], rs.ordinates[j].PSA / units::g_n);
}

void run_select(const RecordsArgs& a) {
  SiteSpec spec;
  const bool ll = a.lat || a.lon, given = a.ag_g || a.F0 || a.Tc_star;
  if (ll == given) throw InputError("give the site as --lat/--lon or as --ag/--F0/--Tc-star (exactly one)");
  if (ll) {
    if (!a.lat || !a.lon) throw InputError("--lat and --lon must be given together (decimal degrees)");
    spec.lat = a.lat, spec.lon = a.lon;
  } else {
    if (!a.ag_g || !a.F0 || !a.Tc_star) throw InputError("--ag, --F0 and --Tc-star must be given together");
    for (LimitState ls : all_limit_states) spec.given[ls] = HazardParams{0.0, *a.ag_g, *a.F0, *a.Tc_star};
  }
  try {
    spec.conditions.soil = parse_soil_class(a.soil);
    spec.conditions.topography = parse_topography(a.topography);
  } catch (const InputError& e) {
    throw InputError(std::string("--soil/--topography: ") + e.what());
  }
  spec.vn_years = a.vn;
  spec.cu = a.cu;
  const Site site(spec);
  LimitState ls = LimitState::SLV;
  bool found = false;
  for (LimitState l : all_limit_states)
    if (to_string(l) == a.limit_state) ls = l, found = true;
  if (!found) throw InputError("--limit-state '" + a.limit_state + "': expected SLO, SLD, SLV or SLC");
  const std::shared_ptr<const RecordLibrary> lib =
      RecordLibrary::open(a.catalogue.empty() ? default_catalogue() : a.catalogue);
  LibrarySelectionRules rules;
  rules.filters = catalogue_filters(filter_options(a));
  rules.include_near_fault = parse_near_fault_option(a.near_fault);
  rules.near_fault_km = a.near_fault_km;
  SelectionOptions so;
  so.n_records = a.count;
  so.range = PeriodRange{a.t_min.value_or(0.15), a.t_max.value_or(2.0)};
  so.max_scale = a.max_scale;
  so.max_mean_scale = a.max_mean_scale;
  so.max_pga_ratio = a.max_pga_ratio;
  so.max_per_event = a.per_event;
  so.max_per_station = a.per_station;
  so.max_misfit = a.max_misfit;
  const SiteRecordSelection chosen = select_for_site(site, ls, *lib, rules, so);
  const LibrarySelection* sel = chosen.selection.get();
  const SelectionResult& res = sel->result;
  if (a.json) {
    std::cout << site_selection_json(chosen).dump(1) << "\n";
    return;
  }
  std::cout << "Target: " << to_string(ls) << " spectrum, " << site.describe() << ", soil " << a.soil
            << ", ag S = " << num(chosen.ag_S_g, "%.3f") << " g\n";
  for (const auto& w : sel->warnings) std::cout << "warning: " << w << "\n";
  std::cout << sel->candidates.size() << " candidates after the filters (" << sel->near_fault_excluded
            << " near-fault or pulse-like left out), " << res.eligible << " within the per-record limits; "
            << res.message << "\n";
  std::printf("%-30s %-34s %4s %-20s %6s %-4s %2s %6s %8s %6s %4s\n", "record", "event", "Mw", "station", "R (km)",
              "kind", "cl", "scale", "PGA (g)", "misfit", "rank");
  for (const auto& s : res.records) {
    const CatalogueEntry& e = sel->candidates[s.index];
    std::printf("%-30s %-34.34s %4s %-20.20s %6s %-4s %2s %6.3f %8.3f %6.3f %4d\n", e.id.c_str(), e.event.c_str(),
                num(e.Mw, "%.2f").c_str(), e.station.c_str(), num(e.distance_km, "%.1f").c_str(),
                e.distance_kind.c_str(), e.site_class.c_str(), s.scale, s.scaled_pga / units::g_n, s.deviation, s.rank);
    for (const std::string& f : selection_flags(chosen, s)) std::printf("  FLAG: %s\n", f.c_str());
  }
  std::printf("mean scale %.3f; largest scaled PGA %.3f g (guard %.2f ag S = %.3f g)\n", res.mean_scale,
              res.max_scaled_pga / units::g_n, so.max_pga_ratio, so.max_pga_ratio * chosen.ag_S_g);
}

}  // namespace

void add_records_command(CLI::App& app) {
  auto a = std::make_shared<RecordsArgs>();
  CLI::App* cmd = app.add_subcommand("records", "the record library: build, list, show, select");
  cmd->require_subcommand(1);
  // Every number option with its range and reason: the rules of the case
  // file's /dynamic/select (records/record_selection.hpp) and of its site
  // (support/number_rules.hpp), checked as the command line is parsed.
  namespace SR = selection_rules;
  static const NumberRule records_count{"records", 1.0, double(SR::count_max), false, false,
                                        "components of a set, of one event or of one station"};
  auto filters = [a](CLI::App* c) {
    with_rule(c->add_option("--mw-min", a->mw_min, "smallest moment magnitude"), SR::Mw);
    with_rule(c->add_option("--mw-max", a->mw_max, "largest moment magnitude"), SR::Mw);
    with_rule(c->add_option("--r-min", a->r_min, "smallest distance (km)"), SR::distance_km);
    with_rule(c->add_option("--r-max", a->r_max, "largest distance (km)"), SR::distance_km);
    c->add_option("--site-class", a->site_classes, "accepted site classes (A..E), repeatable");
    c->add_option("--country", a->countries, "accepted countries, repeatable");
    c->add_option("--catalogue", a->catalogue, "catalogue.json (default: the shipped spectra/records/catalogue.json)");
    c->add_flag("--json", a->json, "print JSON");
  };
  CLI::App* build = cmd->add_subcommand("build", "generate catalogue.json from metadata.csv and the record files");
  build->add_option("--metadata", a->metadata, "metadata table (default: spectra/records/metadata.csv)");
  build->add_option("--output", a->output, "catalogue to write (default: catalogue.json beside the table)");
  build->callback([a] { run_build(*a); });
  CLI::App* list = cmd->add_subcommand("list", "list the usable components, optionally filtered");
  filters(list);
  list->add_flag("--all", a->all, "every file, also those not usable for design");
  list->callback([a] { run_list(*a); });
  CLI::App* show = cmd->add_subcommand("show", "one record's metadata and 5 % spectrum");
  show->add_option("id", a->id, "record id or file")->required();
  show->add_option("--catalogue", a->catalogue, "catalogue.json");
  show->add_flag("--json", a->json, "print JSON");
  show->callback([a] { run_show(*a); });
  CLI::App* sel = cmd->add_subcommand("select", "select N records compatible with a site spectrum (no mechanism)");
  filters(sel);
  with_rule(sel->add_option("--lat", a->lat, "site latitude (decimal degrees)"), rules::latitude_deg);
  with_rule(sel->add_option("--lon", a->lon, "site longitude (decimal degrees)"), rules::longitude_deg);
  with_rule(sel->add_option("--ag", a->ag_g, "ag on rock (g), with --F0 and --Tc-star"), rules::ag_g);
  with_rule(sel->add_option("--F0", a->F0, "F0 (-)"), rules::F0);
  with_rule(sel->add_option("--Tc-star", a->Tc_star, "TC* (s)"), rules::Tc_star_s);
  sel->add_option("--soil", a->soil, "subsoil class A..E (default A); also the default site-class filter");
  sel->add_option("--topography", a->topography, "T1..T4 (default T1)");
  with_rule(sel->add_option("--vn", a->vn, "nominal life VN (years, default 50)"), rules::nominal_life_years);
  with_rule(sel->add_option("--cu", a->cu, "coefficient of use CU (default 1)"), rules::use_coefficient);
  sel->add_option("--limit-state", a->limit_state, "SLO|SLD|SLV|SLC (default SLV)");
  with_rule(sel->add_option("--count", a->count, "number of records N (default 7)"), records_count);
  with_rule(sel->add_option("--t-min", a->t_min, "shortest period of the range (s, default 0.15)"), SR::period_s);
  with_rule(sel->add_option("--t-max", a->t_max, "longest period of the range (s, default 2.0)"), SR::period_s);
  with_rule(sel->add_option("--max-scale", a->max_scale, "largest scale factor of a record (default 3)"), SR::max_scale);
  with_rule(sel->add_option("--max-misfit", a->max_misfit, "individual misfit flagged above it (default 0.5)"),
            SR::max_misfit);
  sel->add_option("--near-fault", a->near_fault, "exclude (default) or include near-fault and pulse-like records");
  with_rule(sel->add_option("--near-fault-km", a->near_fault_km,
                            "distance below which a record is near-fault (km, default 10)"),
            SR::near_fault_km);
  with_rule(sel->add_option("--max-mean-scale", a->max_mean_scale, "largest mean scale factor (default 2)"),
            SR::max_mean_scale);
  with_rule(sel->add_option("--max-pga-ratio", a->max_pga_ratio, "guard: scaled PGA <= ratio * ag S (default 2.5)"),
            SR::max_pga_ratio);
  with_rule(sel->add_option("--per-event", a->per_event, "components per event (default 3)"), records_count);
  with_rule(sel->add_option("--per-station", a->per_station, "components per station (default 1)"), records_count);
  sel->add_flag("--no-relax", a->no_relax, "do not widen the site classes when they give no compatible set");
  sel->callback([a] { run_select(*a); });
}

}  // namespace assess::cli

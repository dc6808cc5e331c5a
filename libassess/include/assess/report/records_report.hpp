// records_report.hpp: the record library as `assess records list|show|select`
// shows it, for every front end (the command line, the Python module's
// assess.records): the filters of the options, the entries listed, one
// entry's JSON, and a selection for a site with its flags and its JSON.
#pragma once

#include "assess/hazard/site.hpp"
#include "assess/records/library_selection.hpp"
#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_selection.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The filter options of `assess records list|select`.
struct RecordFilterOptions {
  std::optional<double> mw_min, mw_max;   ///< moment magnitude window (-)
  std::optional<double> r_min, r_max;     ///< distance window (km)
  std::vector<std::string> site_classes;  ///< accepted site classes A..E (empty: any; select: the site's)
  std::vector<std::string> countries;     ///< accepted countries (empty: any)
  bool relax = true;                      ///< select: widen the site classes when they give no compatible set
  /// True when any window, class or country is given.
  bool filtering() const;
};

/// The catalogue filters of the options.
/// @throws InputError "--site-class 'X': expected A, B, C, D or E"
CatalogueFilters catalogue_filters(const RecordFilterOptions& o);

/// The entries `assess records list` shows: with `all` and no filter every
/// entry; else the entries usable for design that pass the filters, with no
/// default magnitude or distance window and no widening of the site classes.
std::vector<CatalogueEntry> catalogue_listing(const RecordCatalogue& catalogue, const RecordFilterOptions& o, bool all);

/// One entry as `assess records list --json` prints it (null for an unknown number).
nlohmann::ordered_json catalogue_entry_json(const CatalogueEntry& e);

/// "exclude" (false) or "include" (true) near-fault and pulse-like records.
/// @throws InputError "--near-fault 'X': expected exclude or include"
bool parse_near_fault_option(const std::string& text);

/// A selection for a site without a mechanism (`assess records select`,
/// the Python module's assess.records.select; REXEL's use case).
struct SiteRecordSelection {
  LimitState limit_state = LimitState::SLV;
  std::string site;            ///< Site::describe()
  std::string soil;            ///< the site's soil class ("C")
  double ag_S_g = 0.0;         ///< the target's Se(0) = ag S (g)
  LibrarySelectionRules rules; ///< as used: the site classes default to the site's soil class
  SelectionOptions options;
  std::shared_ptr<const LibrarySelection> selection;
};

/// N records from `library` compatible with the elastic spectrum of limit
/// state `ls` at `site` (select_from_library, records/library_selection.hpp);
/// rules.filters.site_classes empty: the site's soil class first.
/// @throws InputError when no record of the catalogue passes the filters
SiteRecordSelection select_for_site(const Site& site, LimitState ls, const RecordLibrary& library,
                                    LibrarySelectionRules rules, const SelectionOptions& options);

/// Why a chosen record deserves a look: near-fault or pulse-like, a misfit
/// above the options' max_misfit, a site class other than the site's.
std::vector<std::string> selection_flags(const SiteRecordSelection& s, const SelectedRecord& r);

/// The JSON of `assess records select --json`: target, status and message,
/// warnings, the rules used, the chosen records (each entry with its scale,
/// scaled PGA, misfit, rank and flags), the records left out and why, the
/// check periods (s), the target and the set's mean spectrum (m/s^2).
nlohmann::ordered_json site_selection_json(const SiteRecordSelection& s);

}  // namespace assess

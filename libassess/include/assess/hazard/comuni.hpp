// comuni.hpp: the Italian comuni with the coordinates of their municipal
// seat, for giving a site by name as Spettri-NTC does (NTC 2018 §3.2: the
// hazard is read at the site's coordinates). Data: spectra/comuni.csv (ISTAT
// list, Wikidata coordinates; provenance and terms in spectra/README.md).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace assess {

struct Comune {
  std::string istat_code;   ///< 6 digits
  std::string name;         ///< official name (bilingual names as ISTAT writes them)
  std::string province;     ///< sigla, e.g. "AQ"
  std::string region;
  double lat = 0.0, lon = 0.0;         ///< municipal seat, decimal degrees (WGS84)
  std::vector<std::string> alt_names;  ///< other official forms (e.g. "Bozen")
  /// "L'Aquila (AQ), ISTAT 066049".
  std::string describe() const;
};

/// The list of comuni. Names are matched without regard to case, accents,
/// apostrophes, hyphens and blanks ("l aquila" = "L'Aquila"), against the
/// official name, its alternative forms and each part of a bilingual name
/// ("Duino Aurisina" in "Duino Aurisina-Devin Nabrežina").
class ComuneTable {
 public:
  /// Reads a CSV istat_code,name,province,region,lat,lon,alt_names (header
  /// line first; alt_names separated by ';'). InputError naming the file and line.
  static ComuneTable load(const std::string& path);
  /// The table shipped in data_dir()/spectra/comuni.csv (loaded once).
  static std::shared_ptr<const ComuneTable> shipped();

  /// The comune called `name`, in `province` (sigla; empty: any). InputError:
  /// an unknown name (with "did you mean" up to three close names), a name
  /// shared by comuni of several provinces without `province` (listing them),
  /// a province that does not hold the name.
  const Comune& find(const std::string& name, const std::string& province = "") const;
  std::size_t size() const { return comuni_.size(); }

 private:
  std::vector<Comune> comuni_;
};

/// The note printed with a site given by comune: the municipal seat is used;
/// give the building's own coordinates for the final check.
std::string comune_note();

}  // namespace assess

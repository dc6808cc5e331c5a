// Comune lookup (hazard/comuni.hpp): the shipped ISTAT list, names matched
// without case/accents/apostrophes, bilingual names, ambiguous names with and
// without the province, "did you mean". Reference coordinates: the shipped
// spectra/comuni.csv rows (Wikidata P625 via Samurai016/Comuni-ITA), checked
// against the spot checks of its provenance note (L'Aquila 42.354/13.392,
// Bolzano 46.4981/11.3548, within 1 km of an independent reference).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/hazard/site.hpp"
#include "assess/support/error.hpp"

#include <string>

using namespace assess;
using assess::test::abs_tol;

namespace {
// Coordinates are printed in the CSV to 4-6 decimals: compare to 1e-9 deg
// (they are copied, not computed).
const auto kDeg = abs_tol(1e-9);

std::string error_of(const std::string& name, const std::string& prov = "") {
  try {
    ComuneTable::shipped()->find(name, prov);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("the shipped list holds the 7896 comuni of the ISTAT list") {
  CHECK(ComuneTable::shipped()->size() == 7896);
}

TEST_CASE("L'Aquila, with any spelling of the apostrophe, case and blanks") {
  for (const char* name : {"L'Aquila", "l'aquila", "L AQUILA", "laquila", "L’Aquila"}) {
    CAPTURE(name);
    const Comune& c = ComuneTable::shipped()->find(name);
    CHECK(c.istat_code == "066049");
    CHECK(c.province == "AQ");
    CHECK_CLOSE(c.lat, 42.354, kDeg);
    CHECK_CLOSE(c.lon, 13.392, kDeg);
  }
}

TEST_CASE("bilingual comuni: German form of Bolzano, each half of Duino Aurisina-Devin Nabrežina") {
  const Comune& b = ComuneTable::shipped()->find("Bozen");
  CHECK(b.name == "Bolzano");
  CHECK(b.istat_code == "021008");
  CHECK_CLOSE(b.lat, 46.4981, kDeg);
  CHECK_CLOSE(b.lon, 11.3548, kDeg);
  CHECK(ComuneTable::shipped()->find("Bolzano").istat_code == "021008");  // not Bolzano Novarese / Vicentino
  CHECK(ComuneTable::shipped()->find("Duino Aurisina").istat_code == "032001");
  CHECK(ComuneTable::shipped()->find("Devin Nabrezina").istat_code == "032001");  // accent folded
  CHECK(ComuneTable::shipped()->find("Duino Aurisina-Devin Nabrežina").istat_code == "032001");
}

TEST_CASE("an ambiguous name needs the province") {
  const std::string e = error_of("Castro");
  CHECK(e.find("ambiguous") != std::string::npos);
  CHECK(e.find("Castro (BG)") != std::string::npos);
  CHECK(e.find("Castro (LE)") != std::string::npos);
  const Comune& le = ComuneTable::shipped()->find("Castro", "LE");
  CHECK(le.istat_code == "075096");
  CHECK_CLOSE(le.lat, 40.007, kDeg);
  const Comune& bg = ComuneTable::shipped()->find("castro", "bg");
  CHECK(bg.istat_code == "016065");
  CHECK_CLOSE(bg.lat, 45.803, kDeg);
  CHECK(error_of("Castro", "RM").find("not in province RM") != std::string::npos);
}

TEST_CASE("an unknown name gets did-you-mean suggestions") {
  const std::string e = error_of("Lakuila");
  CHECK(e.find("did you mean") != std::string::npos);
  CHECK(e.find("L'Aquila (AQ)") != std::string::npos);
  CHECK(error_of("").find("expected the name") != std::string::npos);
}

TEST_CASE("a site given by comune describes itself with the municipal seat") {
  const Comune& c = ComuneTable::shipped()->find("L'Aquila");
  SiteSpec s;
  s.lat = c.lat;
  s.lon = c.lon;
  s.comune = c.describe();
  const Site site(s);
  CHECK(site.describe() == "comune L'Aquila (AQ), ISTAT 066049: lat 42.354, lon 13.392 (municipal seat)");
  CHECK(comune_note().find("municipal seat") != std::string::npos);
}

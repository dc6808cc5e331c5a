// The record library spectra/records/: catalogue completeness (every usable
// component has Mw, distance, site class and a PGA that matches its file;
// issue 30: at least 350 of them, the doubtful records of batch 3 excluded
// with their reason, the class's basis, the pulse classification),
// one reader check per format variant in the library against the values its
// header declares, the site class rule, the catalogue tool reproducing the
// shipped catalogue.json, and the Arias quantities against closed forms.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_io.hpp>
#include <assess/records/strong_motion.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_files.hpp"

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

const std::string kDir = std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/";
// pga_g is written with 6 significant digits: relative rounding <= 5e-6 (-).
constexpr double kPgaRelTol = 5e-6;
// PGA printed in a file header (cor.acc "PGA (m/s/s)", 6-7 digits) vs computed (-).
constexpr double kHeaderPgaRelTol = 1e-5;
// Arias closed form vs the exact per-step integral: round-off (-).
constexpr double kAriasRelTol = 1e-12;

}  // namespace

TEST_CASE("catalogue completeness: every usable component has Mw, distance, site class and its file's PGA") {
  const RecordCatalogue cat = read_catalogue(kDir + "catalogue.json");
  REQUIRE(cat.entries.size() == 450);  // 24 files of batch 1 + 129 of records-2 + 297 of records-3
  std::size_t usable = 0;
  for (const CatalogueEntry& e : cat.entries) {
    CAPTURE(e.id);
    CHECK_FALSE(e.positive_direction.empty());
    CHECK_FALSE(e.source.empty());
    if (!e.usable_for_design) {
      CHECK_FALSE(e.note.empty());  // the reason
      continue;
    }
    ++usable;
    CHECK(std::isfinite(e.Mw));
    CHECK(std::isfinite(e.distance_km));
    CHECK((e.distance_kind == "Rjb" || e.distance_kind == "Repi" || e.distance_kind == "Rrup"));
    CHECK(std::string("ABCDE").find(e.site_class) != std::string::npos);
    CHECK_FALSE(e.site_class.empty());
    if (e.site_class_basis == "Vs30") CHECK(e.site_class == site_class_from_vs30(e.vs30_m_s));
    CHECK((e.site_class_basis == "Vs30" || e.site_class_basis == "stated"));
    CHECK(e.vs30_class == site_class_from_vs30(e.vs30_m_s));
    CHECK(e.content_hash.size() == 16);
    CHECK(e.pga_g >= weak_motion_pga_g);
    CHECK(e.significant_duration_s > 0.0);
    const Record r = cat.load(e);
    CHECK(long(r.size()) == e.npts);
    CHECK_CLOSE(r.dt, e.dt_s, rel_tol(1e-12));
    CHECK_CLOSE(r.pga() / units::g_n, e.pga_g, rel_tol(kPgaRelTol));
  }
  // Issue 30: 84 usable of batches 1-2, 288 of the 297 of batch 3 (9 doubtful).
  CHECK(usable == 372);
  CHECK(usable >= 350);
  // Batch 3's doubtful records: file PGA against the flatfile's RotD50 (both
  // components of RSN 197, 199, 223), unknown orientation (component NA).
  for (const char* id : {"RSN197_1", "RSN197_2", "RSN199_1", "RSN199_2", "RSN223_1", "RSN223_2"}) {
    CAPTURE(id);
    REQUIRE(cat.find(id));
    CHECK_FALSE(cat.find(id)->usable_for_design);
    CHECK(cat.find(id)->note.find("RotD50") != std::string::npos);
  }
  for (const char* id : {"RSN230_2", "RSN233_2", "RSN244_2"}) {
    CAPTURE(id);
    CHECK_FALSE(cat.find(id)->usable_for_design);
    CHECK(cat.find(id)->note.find("orientation unknown") != std::string::npos);
  }
  CHECK(cat.find("RSN230_1")->usable_for_design);  // its partner keeps its azimuth
  // Batch 3 gives no class: every class from Vs30; the distance kind as the source gives it.
  CHECK(cat.find("RSN160_IMPVALL.H_H-BCR140")->site_class == "C");
  CHECK(cat.find("RSN160_IMPVALL.H_H-BCR140")->site_class_basis == "Vs30");
  CHECK(cat.find("RSN160_IMPVALL.H_H-BCR140")->distance_kind == "Rjb");
  CHECK(cat.find("RSN183_1")->distance_kind == "Repi");
  // Issue 38: the class of the measured Vs30 comes first: Bagnoli Irpino, class A
  // in the seed paper, Vs30 649.67 m/s: B (unit.record_site_class checks every entry).
  const CatalogueEntry* bag = cat.find("RSN285_ITALY_A-BAG000");
  CHECK(bag->site_class == "B");
  CHECK(bag->site_class_basis == "Vs30");
  CHECK(bag->vs30_class == "B");
  // Pulse classification of the PEER search report: Bagnoli and Sturno pulse-like (Tp 1.71, 3.27 s).
  CHECK(bag->pulse == "pulse-like");
  CHECK_CLOSE(bag->pulse_period_s, 1.71332, rel_tol(1e-12));
  CHECK(cat.find("RSN292_ITALY_A-STU270")->pulse == "pulse-like");
  CHECK(cat.find("RSN283_ITALY_A-ARI000")->pulse == "non-pulse");
  CHECK(cat.find("RSN121_1")->pulse.empty());
  // The reasons: converted copies, weak motion, unprocessed, missing metadata.
  CHECK(cat.find("SortedEQFile_(120411)")->note.find("converted") != std::string::npos);
  CHECK(cat.find("16840_H1")->note.find("weak motion") != std::string::npos);
  CHECK(cat.find("19971014_152309ITDPC_NCR__WEX")->note.find("unprocessed") != std::string::npos);
  CHECK(cat.find("RSN1155_KOCAELI_BUR000")->note.find("no distance") != std::string::npos);
  // PEER 270 = positive West, ITACA WE = positive East.
  CHECK(cat.find("RSN292_ITALY_A-STU270")->positive_direction == "W");
  CHECK(cat.find("16837_H2")->positive_direction == "E");
}

TEST_CASE("site class from Vs30 (NTC 2018 Tab. 3.2.II): A > 800, B 360-800, C 180-360, D < 180 m/s") {
  // A is "superiori a 800 m/s": 800 itself is B (issue 30); on 360 and 180 the stiffer class.
  CHECK(site_class_from_vs30(800.1) == "A");
  CHECK(site_class_from_vs30(800.0) == "B");
  CHECK(site_class_from_vs30(799.9) == "B");
  CHECK(site_class_from_vs30(360.0) == "B");
  CHECK(site_class_from_vs30(359.9) == "C");
  CHECK(site_class_from_vs30(180.0) == "C");
  CHECK(site_class_from_vs30(179.9) == "D");
  CHECK(site_class_from_vs30(std::nan("")).empty());
}

TEST_CASE("one reader check per format variant in the library, against the header's own values") {
  // PEER AT2 NGA-West2 with CRLF (haselREC): NPTS = 3317, DT = .005 in the header.
  const std::string hasel = slurp(kDir + "haselREC/RSN121_1.AT2");
  CHECK(hasel.find("\r\n") != std::string::npos);
  const Record a = read_record(kDir + "haselREC/RSN121_1.AT2");
  CHECK(a.size() == 3317);
  CHECK(a.dt == 0.005);
  // Renamed haselREC copy with NS/WE labels and odd dt (Friuli-03).
  const Record b = read_record(kDir + "haselREC/RSN127_1.AT2");
  CHECK(b.component == "NS");
  // PEER AT2 with LF (EE-UQ), component 090.
  const Record c = read_record(kDir + "EE-UQ/RSN1160_KOCAELI_FAT090.AT2");
  CHECK(c.component == "90");
  // GEM cor.acc: the header's "PGA (m/s/s)" equals the computed peak.
  const std::string cor = slurp(kDir + "gmpe-smtk_LAquila/16858_H2.cor.acc");
  const auto p = cor.find("PGA (m/s/s)");
  REQUIRE(p != std::string::npos);
  const double header_pga = std::stod(cor.substr(cor.find(':', p) + 1));
  const Record d = read_record(kDir + "gmpe-smtk_LAquila/16858_H2.cor.acc");
  CHECK_CLOSE(d.pga(), std::fabs(header_pga), rel_tol(kHeaderPgaRelTol));
  // Headerless two-column text in g with a (0, 0) first row (FEMA P695 copies):
  // FEMA P695 Tab. A-4 gives PGA 0.82 g for Duzce-Bolu 090 (2 digits).
  const RecordCatalogue cat = read_catalogue(kDir + "catalogue.json");
  const Record e = cat.load("SortedEQFile_(120412)");
  CHECK(e.acc.front() == 0.0);
  CHECK_CLOSE(e.pga() / units::g_n, 0.82, abs_tol(0.005));
}

TEST_CASE("`build_catalogue` reproduces the shipped catalogue.json from metadata.csv and the files") {
  const RecordCatalogue cat = build_catalogue(kDir + "metadata.csv");
  CHECK(catalogue_json(cat) == slurp(kDir + "catalogue.json"));
}

TEST_CASE("build_catalogue names the row and column of a bad cell") {
  const std::string t = (std::filesystem::temp_directory_path() / "assess_bad_metadata.csv").string();
  std::string head = slurp(kDir + "metadata.csv");
  head = head.substr(0, head.find('\n') + 1);
  {
    std::ofstream o(t);
    o << head << "x.AT2,ev,2000-01-01,seven,,st,,000,N,10,Rjb,400,,Italy,,,,,,,src,terms,\n";
  }
  try {
    build_catalogue(t);
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("assess_bad_metadata.csv:2 column Mw") != std::string::npos);
  }
}

TEST_CASE("near-fault and pulse-like flags from the metadata (record-selection.md §2.4)") {
  CatalogueEntry e;
  e.distance_km = 25.0, e.distance_kind = "Repi";
  CHECK(near_fault_reason(e).empty());
  e.distance_km = 9.99;  // Rjb <= Repi: the rupture's projection is within 10 km too
  CHECK(near_fault_reason(e) == "near-fault: Repi 9.99 km < 10 km");
  e.distance_km = 10.0;  // on the threshold: not below it
  CHECK(near_fault_reason(e).empty());
  e.distance_kind = "Rjb", e.distance_km = 0.0;
  CHECK(near_fault_reason(e) == "near-fault: Rjb 0 km < 10 km");
  CHECK(near_fault_reason(e, 0.0).empty());  // a threshold of 0 km flags no distance
  e.distance_km = 30.0, e.pulse = "pulse-like", e.pulse_period_s = 3.27264;
  CHECK(near_fault_reason(e) == "pulse-like (source classification, Tp = 3.27 s)");
  e.pulse = "non-pulse", e.pulse_period_s = std::nan("");
  CHECK(near_fault_reason(e).empty());
  // Shipped: the L'Aquila stations on the rupture projection, Rinaldi, Sturno (pulse-like).
  const RecordCatalogue cat = read_catalogue(kDir + "catalogue.json");
  for (const char* id : {"16837_H1", "Rinaldi228", "RSN292_ITALY_A-STU270", "RSN160_IMPVALL.H_H-BCR140"}) {
    CAPTURE(id);
    CHECK_FALSE(near_fault_reason(*cat.find(id)).empty());
  }
  CHECK(near_fault_reason(*cat.find("RSN170_2")).empty());
}

TEST_CASE("the class of the measured Vs30 comes first; a stated class it contradicts gives way (issue 38)") {
  // tests/data/records_mini: Calitri with class C stated and Vs30 455.93 m/s (B).
  const RecordCatalogue cat = build_catalogue(std::string(ASSESS_TEST_DATA_DIR) + "/tests/data/records_mini/metadata.csv");
  const CatalogueEntry* clt = cat.find("RSN289_1");
  REQUIRE(clt);
  CHECK(clt->site_class == "B");
  CHECK(clt->site_class_basis == "Vs30");
  CHECK(clt->vs30_class == "B");
  CHECK(cat.find("ARL360")->site_class_basis == "Vs30");
  CHECK(cat.find("ARL360")->site_class == "C");  // Vs30 297.71 m/s
  CHECK(cat.find("RSN289_1")->pulse == "pulse-like");
  CHECK_FALSE(cat.find("SortedEQFile_(120111)")->usable_for_design);
}

TEST_CASE("Arias intensity and D5-95 of a constant and of a linear ramp (closed forms)") {
  Record r;
  r.dt = 0.01;
  r.acc.assign(1001, 2.0);  // 10 s at 2 m/s^2
  // I = pi/(2 g_n) a^2 T; the cumulative intensity is linear in t, so t(5 %) = 0.5 s, t(95 %) = 9.5 s.
  CHECK_CLOSE(arias_intensity(r), units::pi / (2 * units::g_n) * 4.0 * 10.0, rel_tol(kAriasRelTol));
  CHECK_CLOSE(significant_duration(r), 9.0, rel_tol(1e-9));
  // a = t on [0, 10]: I(t) ∝ t^3, so t(f) = 10 f^(1/3); the cubic is exact per step.
  for (std::size_t i = 0; i < r.acc.size(); ++i) r.acc[i] = 0.01 * double(i);
  CHECK_CLOSE(arias_intensity(r), units::pi / (2 * units::g_n) * 1000.0 / 3.0, rel_tol(kAriasRelTol));
  // arias_time interpolates linearly between samples: error <= one step (0.01 s).
  CHECK_CLOSE(arias_time(r, 0.999), 10.0 * std::cbrt(0.999), abs_tol(0.01));
  const Record cut = strong_motion_part(r, 0.5);
  CHECK_CLOSE(cut.duration(), 10.0 * std::cbrt(0.5), abs_tol(0.01 + 1e-12));
}

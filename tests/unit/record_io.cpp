// Record readers: every file of spectra/records/ reads its header's number of
// points and time step and its PGA to 4 digits; format variants; bad input;
// units, scaling and the catalogue.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/support/error.hpp>
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/units.hpp>

#include <string>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// PGA (g): "to 4 digits" = relative 5e-5. References computed independently
// (a regular-expression parser in Python over the raw files, max|a| / g_n).
constexpr double kPgaRelTol = 5e-5;
// dt (s): exact decimal values of the headers.
constexpr double kDtRelTol = 1e-15;

const std::string kDir = std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/";
const std::string kData = std::string(ASSESS_TEST_DATA_DIR) + "/tests/data/";

struct Ref {
  const char* file;
  const char* format;
  std::size_t npts;
  double dt, pga_g;
};

const Ref kRefs[] = {
    {"RSN285_ITALY_A-BAG000.AT2", "PEER AT2", 12712, 0.0029, 0.129652},
    {"RSN285_ITALY_A-BAG270.AT2", "PEER AT2", 12712, 0.0029, 0.1897467},
    {"RSN292_ITALY_A-STU000.AT2", "PEER AT2", 16392, 0.0024, 0.2266578},
    {"RSN292_ITALY_A-STU270.AT2", "PEER AT2", 16392, 0.0024, 0.320522},
    {"RSN289_1.AT2", "PEER AT2", 14672, 0.0024, 0.1264284},
    {"RSN4346_UBMARCHE.P_A-BEV000.AT2", "PEER AT2", 10102, 0.005, 0.07854513},
    {"RSN4346_UBMARCHE.P_A-BEV270.AT2", "PEER AT2", 10102, 0.005, 0.07307956},
    {"RSN125_FRIULI.A_A-TMZ000.AT2", "PEER AT2", 7277, 0.005, 0.357127},
    {"RSN125_FRIULI.A_A-TMZ270.AT2", "PEER AT2", 7279, 0.005, 0.3151205},
    {"ISE-WE.AT2", "PEER AT2", 6557, 0.00244, 0.06757362},
    {"elCentro.AT2", "PEER AT2", 1559, 0.02, 0.31882},
    {"ARL360.at2", "PEER AT2", 2000, 0.02, 0.3080574},
    {"Rinaldi228.AT2", "PEER AT2", 1991, 0.01, 0.8740596},
    {"RSN1106_KOBE_KJM000.AT2", "PEER AT2", 7500, 0.02, 0.8342289},
    {"RSN738_LOMAP_NAS180.AT2", "PEER AT2", 5919, 0.005, 0.268317},
    {"19971014_152309ITDPC_NCR__WEX.DAT", "ITACA ASCII", 6560, 0.005, 0.13735577},
    {"19971014_152309ITDPC_NCR__NSX.DAT", "ITACA ASCII", 6560, 0.005, 0.13314741},
    {"IT.ARL..HGE.D.20140120.071240.C.ACC.ASC", "ITACA ASCII", 8997, 0.005, 0.0011498228},
    {"16833_H1.cor.acc", "GEM cor.acc", 59220, 0.005, 0.51692773},
    {"16833_H2.cor.acc", "GEM cor.acc", 59220, 0.005, 0.47678270},
    {"16837_H1.cor.acc", "GEM cor.acc", 112600, 0.005, 0.54718623},
    {"16837_H2.cor.acc", "GEM cor.acc", 112600, 0.005, 0.66348370},
    {"16889_H1.cor.acc", "GEM cor.acc", 171200, 0.005, 0.31781793},
    {"16889_H2.cor.acc", "GEM cor.acc", 171200, 0.005, 0.29799081},
};

}  // namespace

TEST_CASE("every shared record reads its header's npts and dt and its PGA to 4 digits") {
  for (const Ref& ref : kRefs) {
    CAPTURE(ref.file);
    const Record r = read_record(kDir + ref.file);
    CHECK(r.format == ref.format);
    CHECK(r.size() == ref.npts);
    CHECK_CLOSE(r.dt, ref.dt, rel_tol(kDtRelTol));
    CHECK_CLOSE(r.pga() / units::g_n, ref.pga_g, rel_tol(kPgaRelTol));
  }
}

TEST_CASE("header fields: PEER event/station/component, ESM header PGA, cor.acc orientation") {
  const Record stu = read_record(kDir + "RSN292_ITALY_A-STU270.AT2");
  CHECK(stu.name == "RSN292_ITALY_A-STU270");
  CHECK(stu.event == "Irpinia Italy-01, 11/23/1980");
  CHECK(stu.station == "Sturno (STN)");
  CHECK(stu.component == "270");
  const Record ncr = read_record(kDir + "19971014_152309ITDPC_NCR__WEX.DAT");
  CHECK(ncr.component == "WE");
  CHECK_CLOSE(ncr.pga(), 1.347, rel_tol(1e-12));  // header PGA_CM/S^2 = -134.7
  CHECK_CLOSE(ncr.t_pga(), 0.87, abs_tol(1e-12));  // header TIME_PGA_S
  const Record aqv = read_record(kDir + "16837_H2.cor.acc");
  CHECK(aqv.component == "WE");
  CHECK_CLOSE(aqv.pga(), 6.5065524, rel_tol(1e-7));  // header PGA (m/s/s)
  const Record arl = read_record(kDir + "ARL360.at2");  // CR CR LF line endings
  CHECK(arl.station == "ARLETA");
  CHECK_CLOSE(arl.acc.front(), 0.1297983e-2 * units::g_n, rel_tol(1e-15));
  const Record nf = read_record(kData + "rocking_npts_first.AT2");  // "NPTS, DT" after the numbers
  CHECK(nf.size() == 4);
  CHECK_CLOSE(nf.dt, 0.01, rel_tol(kDtRelTol));
  CHECK_CLOSE(nf.acc[3], -0.4 * units::g_n, rel_tol(1e-15));
}

TEST_CASE("bad records are refused with the file, the line and what was expected") {
  CHECK_THROWS_WITH_AS(read_record(kData + "rocking_truncated.AT2"),
                       doctest::Contains("truncated record: the header declares 12 points, the file has 8"), InputError);
  CHECK_THROWS_WITH_AS(read_record(kData + "rocking_nonnumeric.AT2"),
                       doctest::Contains("rocking_nonnumeric.AT2:5: non-numeric value 'abc'"), InputError);
  CHECK_THROWS_WITH_AS(read_record(kData + "rocking_zero_dt.AT2"), doctest::Contains("time step must be positive"),
                       InputError);
  CHECK_THROWS_WITH_AS(read_record(kData + "no_such_file.AT2"), doctest::Contains("cannot open"), InputError);
  CHECK_THROWS_WITH_AS(read_record(kData + "rocking_plain_1col.txt"), doctest::Contains("unrecognised record format"),
                       InputError);
  CHECK_THROWS_WITH_AS(read_plain_record(kData + "rocking_plain_1col.txt", 0.0, AccelerationUnit::g),
                       doctest::Contains("time step must be positive"), InputError);
  CHECK_THROWS_WITH_AS(read_plain_record(kData + "rocking_plain_1col.txt", -0.01, AccelerationUnit::g),
                       doctest::Contains("time step must be positive"), InputError);
  CHECK_THROWS_WITH_AS(read_plain_record(kData + "rocking_plain_2col.txt", 0.02, AccelerationUnit::g),
                       doctest::Contains("differs from the declared time step"), InputError);
  CHECK_THROWS_AS(parse_acceleration_unit("furlong/fortnight^2"), InputError);
}

TEST_CASE("plain records, units and scaling") {
  const Record one = read_plain_record(kData + "rocking_plain_1col.txt", 0.01, parse_acceleration_unit("cm/s^2"));
  REQUIRE(one.size() == 4);
  CHECK_CLOSE(one.acc[2], -0.20, rel_tol(1e-15));  // -20 cm/s^2
  CHECK_CLOSE(one.duration(), 0.03, rel_tol(1e-15));
  const Record two = read_plain_record(kData + "rocking_plain_2col.txt", 0.01, parse_acceleration_unit("g"));
  REQUIRE(two.size() == 4);
  CHECK_CLOSE(two.acc[2], -0.2 * units::g_n, rel_tol(1e-15));
  CHECK(to_m_s2(parse_acceleration_unit("m/s2")) == 1.0);
  const Record stu = read_record(kDir + "RSN292_ITALY_A-STU270.AT2");
  const double f = scale_factor_to_pga(stu, 0.25 * units::g_n);
  CHECK_CLOSE(stu.scaled(f).pga(), 0.25 * units::g_n, rel_tol(1e-14));
  CHECK_CLOSE(stu.scaled(1.0, true).acc[100], -stu.acc[100], rel_tol(0.0));
}

TEST_CASE("the catalogue lists every record file and flags the files unfit for design") {
  const RecordCatalogue cat = read_catalogue(kDir + "catalogue.json");
  CHECK(cat.entries.size() >= std::size(kRefs));  // the 24 reference files plus the records-2 library
  for (const Ref& ref : kRefs) {
    CAPTURE(ref.file);
    const CatalogueEntry* e = cat.find(ref.file);
    REQUIRE(e != nullptr);
    CHECK(e->npts == long(ref.npts));
    CHECK_CLOSE(e->dt_s, ref.dt, rel_tol(kDtRelTol));
    CHECK_CLOSE(e->pga_g, ref.pga_g, rel_tol(kPgaRelTol));
  }
  CHECK_FALSE(cat.find("IT.ARL..HGE.D.20140120.071240.C.ACC")->usable_for_design);
  CHECK_FALSE(cat.find("19971014_152309ITDPC_NCR__WEX")->usable_for_design);
  CHECK_FALSE(cat.find("19971014_152309ITDPC_NCR__NSX")->usable_for_design);
  for (const auto& e : cat.design_candidates()) CHECK(e.usable_for_design);
  const Record r = cat.load("RSN292_ITALY_A-STU270");
  CHECK(r.size() == 16392);
  CHECK_THROWS_AS(cat.load("nope"), InputError);
}

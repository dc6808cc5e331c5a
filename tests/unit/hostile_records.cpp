// Hostile record files (issue 10, defects 1-4, 7, 12): each one is a named
// InputError (file, line or header field, what was expected), never a crash,
// an internal error or a silent inf. Every test here failed before its fix:
// a segfault (1, 2), std::bad_alloc (3), "stol" without a file (4), a PGA of
// inf (7), or a misleading message (12).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/record_io.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace assess;
using assess::test::rel_tol;

namespace {

namespace fs = std::filesystem;

// A file in a fresh temporary directory with the given content.
std::string write_temp(const std::string& name, const std::string& content) {
  const fs::path dir = fs::temp_directory_path() / ("assess_hostile_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string p = (dir / name).string();
  std::ofstream(p, std::ios::binary) << content;
  return p;
}

const std::string kAt2Head =
    "PEER NGA STRONG MOTION DATABASE RECORD\n"
    "Test, 1/1/2000, Station, 000\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n";

const std::string kEsmHead =
    "EVENT_NAME: test\n"
    "SAMPLING_INTERVAL_S: 0.01\n"
    "UNITS: cm/s^2\n";

const std::string kCorHead =
    "Event Date & Time : 2000-01-01\n"
    "Time Increment (s) : 0.005\n";

}  // namespace

TEST_CASE("defect 1: a plain record whose first data line holds only separators") {
  const std::string p = write_temp("sep.txt", ",\n0.1\n0.2\n");
  CHECK_THROWS_WITH_AS(read_plain_record(p, 0.01, AccelerationUnit::g),
                       doctest::Contains("sep.txt:1: no value on this line (only separators)"), InputError);
  const std::string q = write_temp("sep2.txt", "0.1\n , \t,\n");
  CHECK_THROWS_WITH_AS(read_plain_record(q, 0.01, AccelerationUnit::g), doctest::Contains("sep2.txt:2: no value"),
                       InputError);
}

TEST_CASE("defect 2: an AT2 header line of 30 000 digits or spaces after NPTS= is read without recursion") {
  // 30 000 spaces then a valid count: the header is still recognised.
  const std::string spaces = write_temp("spaces.AT2", kAt2Head + "NPTS=" + std::string(30000, ' ') +
                                                          "3, DT= 0.01 SEC\n0.1 0.2 -0.3\n");
  const Record r = read_record(spaces);
  REQUIRE(r.size() == 3);
  CHECK_CLOSE(r.acc[2], -0.3 * units::g_n, rel_tol(1e-15));
  // 30 000 digits: a count beyond the limit, named.
  const std::string digits =
      write_temp("digits.AT2", kAt2Head + "NPTS=" + std::string(30000, '9') + ", DT= 0.01 SEC\n0.1\n");
  CHECK_THROWS_WITH_AS(read_record(digits), doctest::Contains("digits.AT2: header field NPTS"), InputError);
  // A long line of repeated keys.
  std::string many;
  for (int i = 0; i < 10000; ++i) many += "NPTS DT ";
  const std::string keys = write_temp("keys.AT2", kAt2Head + many + "\n0.1\n");
  CHECK_THROWS_WITH_AS(read_record(keys), doctest::Contains("keys.AT2: PEER AT2 header without"), InputError);
}

TEST_CASE("defect 3: a huge NPTS is refused or costs no more memory than the file holds") {
  const std::string huge = write_temp("huge.AT2", kAt2Head + "NPTS=99999999999, DT= 0.01 SEC\n0.1 0.2\n");
  CHECK_THROWS_WITH_AS(read_record(huge), doctest::Contains("huge.AT2: header field NPTS: 99999999999 points is more than the limit"),
                       InputError);
  // Below the limit (8 GB if reserved as declared): truncated, with the counts.
  const std::string big = write_temp("big.AT2", kAt2Head + "NPTS=999999999, DT= 0.01 SEC\n0.1 0.2\n");
  CHECK_THROWS_WITH_AS(read_record(big), doctest::Contains("truncated record: the header declares 999999999 points, the file has 2"),
                       InputError);
}

TEST_CASE("defect 4: header counts that are not non-negative integers name the file and field") {
  const std::string overflow =
      write_temp("overflow.AT2", kAt2Head + "NPTS=99999999999999999999999, DT= 0.01 SEC\n0.1\n");
  CHECK_THROWS_WITH_AS(read_record(overflow), doctest::Contains("overflow.AT2: header field NPTS"), InputError);
  const std::string abc = write_temp("abc.ASC", kEsmHead + "NDATA: abc\n1.0\n2.0\n");
  CHECK_THROWS_WITH_AS(read_record(abc),
                       doctest::Contains("abc.ASC: header field NDATA: expected a number of points (a non-negative integer), got 'abc'"),
                       InputError);
  const std::string neg = write_temp("neg.ASC", kEsmHead + "NDATA: -3\n1.0\n2.0\n");
  CHECK_THROWS_WITH_AS(read_record(neg), doctest::Contains("neg.ASC: header field NDATA: expected a number of points"),
                       InputError);
  const std::string cor = write_temp("x.cor.acc", kCorHead + "Number of Data : x\n1.0\n");
  CHECK_THROWS_WITH_AS(read_record(cor), doctest::Contains("x.cor.acc: header field Number of Data"), InputError);
  // A good ESM header still reads (cm/s^2 -> m/s^2).
  const std::string ok = write_temp("ok.ASC", kEsmHead + "NDATA: 2\n100.0\n-50.0\n");
  const Record r = read_record(ok);
  REQUIRE(r.size() == 2);
  CHECK_CLOSE(r.acc[0], 1.0, rel_tol(1e-15));
}

TEST_CASE("defect 7: a value that overflows once converted to m/s^2 is refused") {
  const std::string at2 = write_temp("inf.AT2", kAt2Head + "NPTS= 2, DT= 0.01 SEC\n1e308 0.1\n");
  CHECK_THROWS_WITH_AS(read_record(at2), doctest::Contains("inf.AT2:5: value '1e308' overflows once converted to m/s^2"),
                       InputError);
  const std::string plain = write_temp("inf.txt", "0.1\n1e308\n");
  CHECK_THROWS_WITH_AS(read_plain_record(plain, 0.01, AccelerationUnit::g),
                       doctest::Contains("inf.txt:2: value overflows once converted to m/s^2"), InputError);
  const std::string range = write_temp("range.txt", "0.1\n1e400\n");
  CHECK_THROWS_WITH_AS(read_plain_record(range, 0.01, AccelerationUnit::m_s2),
                       doctest::Contains("range.txt:2: value '1e400' is out of the range of a double"), InputError);
}

TEST_CASE("defect 12: messages say what is wrong") {
  // A directory is not an "unrecognised format".
  const fs::path dir = fs::path(write_temp("x", "")).parent_path() / "a_directory.AT2";
  fs::create_directories(dir);
  CHECK_THROWS_WITH_AS(read_record(dir.string()), doctest::Contains("is a directory, expected a record file"), InputError);
  CHECK_THROWS_WITH_AS(read_plain_record(dir.string(), 0.01, AccelerationUnit::g),
                       doctest::Contains("is a directory"), InputError);
  // A subnormal value is a number (1e-310 g), not "non-numeric".
  const std::string sub = write_temp("sub.txt", "0.1\n1.0E-310\n");
  const Record r = read_plain_record(sub, 0.01, AccelerationUnit::m_s2);
  REQUIRE(r.size() == 2);
  CHECK(r.acc[1] > 0.0);
  CHECK(r.acc[1] < 1e-300);
  // An unknown ESM unit names the file and the field.
  const std::string unit = write_temp("unit.ASC",
                                      "EVENT_NAME: test\nSAMPLING_INTERVAL_S: 0.01\nUNITS: furlong\nNDATA: 1\n1.0\n");
  CHECK_THROWS_WITH_AS(read_record(unit), doctest::Contains("unit.ASC: header field UNITS: unknown acceleration unit 'furlong'"),
                       InputError);
}

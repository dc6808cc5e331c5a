// Hostile input, round four (issue 31): one regression test per defect class,
// with inputs made here (more than the issue's examples). Each failed before
// its fix: a read of /dev/zero until memory ran out, a segmentation fault on
// 100 000 nested levels, "free(): invalid pointer" in analyse_kinematic, a
// subnormal accepted as a unit weight, an output written over its input or
// through a link out of its folder, a write to a full disk that succeeded, a
// degenerate polygon diagnosed as "the load lies outside every block", an
// "inf" or "nan" in a message or a report (docs/reliability.md, "Round four").
#include <doctest/doctest.h>

#include <assess/assessment/building_case.hpp>
#include <assess/assessment/case_file.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/risk/fragility_job.hpp>
#include <assess/hazard/comuni.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/kinematic/chain.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/error.hpp>
#include <assess/support/input_file.hpp>
#include <assess/support/json_input.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/output_file.hpp>

#include "report/text_format.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "test_files.hpp"

using namespace assess;

namespace {

namespace fs = std::filesystem;

const std::string kRoot = std::string(ASSESS_TEST_DATA_DIR);

// The message of the InputError `f` throws ("" if none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// No "inf", "-inf", "nan" or "-nan" as a word in `s`.
bool has_inf_or_nan(const std::string& s) {
  for (const char* w : {"inf", "nan"})
    for (std::size_t at = s.find(w); at != std::string::npos; at = s.find(w, at + 1)) {
      const bool before = at > 0 && std::isalpha(static_cast<unsigned char>(s[at - 1]));
      const bool after = at + 3 < s.size() && std::isalpha(static_cast<unsigned char>(s[at + 3]));
      if (!before && !after) return true;
    }
  return false;
}

// A one-block explicit case (the free-standing wall of mechanisms/explicit_blocks.json).
nlohmann::json block_case() {
  return nlohmann::json::parse(R"({"schema_version": 1, "mechanism": {"type": "blocks",
    "blocks": [{"name": "wall", "polygon": [[-0.5, 0], [0, 0], [0, 6], [-0.5, 6]], "unit_weight": 18.0, "length": 1.0}],
    "constraints": [{"type": "ground_hinge", "block": "wall", "point": [0, 0]}],
    "loads": [{"type": "weight", "name": "floor", "point": [-0.35, 6], "weight": 10.0}]}})");
}

}  // namespace

TEST_CASE("class 1: every input reader refuses a device, a FIFO and a directory by name, in milliseconds") {
  const std::string dir = temp_dir("devices");
  const std::string fifo = dir + "/fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const auto t0 = std::chrono::steady_clock::now();
  for (const std::string& path : {std::string("/dev/zero"), fifo, dir}) {
    CAPTURE(path);
    const std::string rec = input_error([&] { read_record(path); });
    CHECK(rec.find(path + ": is a") == 0);
    CHECK(rec.find("expected a record file (a regular file)") != std::string::npos);
    CHECK(input_error([&] { read_plain_record(path, 0.01, AccelerationUnit::g); }).find("expected a record file") !=
          std::string::npos);
    CHECK(input_error([&] { read_json_file(path, input_kinds::case_file); }).find("expected a case file") !=
          std::string::npos);
    CHECK(input_error([&] { read_building_file(path); }).find(path + ": is a") == 0);
    CHECK(input_error([&] { HazardGrid::load(path); }).find("expected a hazard grid file") != std::string::npos);
    CHECK(input_error([&] { ComuneTable::load(path); }).find("expected a list of comuni") != std::string::npos);
  }
  CHECK(input_error([] { read_record("/dev/zero"); }).find("a character device") != std::string::npos);
  // The tool's own result files read back (--resume, the report) as well.
  CHECK(input_error([&] { read_campaign_csv(fifo); }).find("a FIFO") != std::string::npos);
  CHECK(input_error([&] { read_fragility_csv("/dev/zero"); }).find("a character device") != std::string::npos);
  CHECK(input_error([&] { read_record(fifo); }).find("a FIFO") != std::string::npos);
  CHECK(input_error([&] { read_record(dir); }).find("a directory") != std::string::npos);
  CHECK(seconds_since(t0) < 5.0);  // was: reading /dev/zero until 2 GB, 15 s
  fs::remove_all(dir);
}

TEST_CASE("class 1: the size limit of each kind of input file") {
  const std::string dir = temp_dir("size");
  const std::string f = write(dir + "/big.json", std::string(3000, ' ') + "{}");
  const InputKind small{"test file", 1000};
  const std::string e = input_error([&] { read_input_file(f, small); });
  CHECK(e.find(f + ": 3002 bytes is more than the limit of 1000 bytes for a test file") == 0);
  CHECK(read_input_file(f, InputKind{"test file", 3002}).size() == 3002);
  CHECK(input_error([&] { read_input_file(dir + "/missing.json", small); }).find("cannot open the test file") !=
        std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("class 1: a depth limit in every JSON parse, building files included") {
  const std::string deep_array = std::string(100000, '[') + std::string(100000, ']');
  std::string e = input_error([&] { parse_json_text(deep_array, "deep.json"); });
  CHECK(e.find("deep.json: /0/0/0") == 0);
  CHECK(e.find("nested more than 64 levels deep") != std::string::npos);
  // Deep inside a building: an object, the project, an analysis array (a
  // segmentation fault before: the building parser copies and merges trees).
  const std::string building = slurp(kRoot + "/mechanisms/building-house.json");
  for (const std::string& at : {std::string("\"project\""), std::string("\"analysis\""), std::string("\"walls\"")}) {
    std::string nested;
    for (int i = 0; i < 100000; ++i) nested += "{\"a\":";
    nested += "1" + std::string(100000, '}');
    std::string text = building;
    text.insert(1, "\"deep\": " + nested + ",");
    CAPTURE(at);
    e = input_error([&] { parse_building(parse_json_text(text, "b.json"), "b.json"); });
    CHECK(e.find("b.json: /deep/a/a/a") == 0);
  }
  // Strings holding brackets do not count; 64 levels pass.
  CHECK_NOTHROW(parse_json_text("[\"" + std::string(1000, '[') + "\"]", "s.json"));
  CHECK_NOTHROW(parse_json_text(std::string(64, '[') + std::string(64, ']'), "ok.json"));
  CHECK_THROWS_AS(parse_json_text(std::string(65, '[') + std::string(65, ']'), "no.json"), InputError);
  // The record catalogue uses the same parser.
  const std::string dir = temp_dir("deep");
  write(dir + "/catalogue.json", deep_array);
  CHECK(input_error([&] { read_catalogue(dir + "/catalogue.json"); }).find("nested more than 64 levels") !=
        std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("class 1: one numeric rule set: finite, in the physical range with its unit, no subnormals") {
  CHECK(number_rule_violation(1.0, rules::dimension_m).empty());
  CHECK(number_rule_violation(1e-320, rules::dimension_m).find("subnormal") != std::string::npos);
  CHECK(number_rule_violation(1e-300, rules::dimension_m).find("out of range: expected in [0.001, 1000] m") !=
        std::string::npos);
  CHECK(number_rule_violation(std::nan(""), rules::weight_kN) == "not a number: expected a finite number in [0, 1e+06] kN (0 to 1 GN: a weight or a tie force)");
  CHECK(number_rule_violation(0.0, rules::block_unit_weight_kN_m3).empty());
  CHECK(!number_rule_violation(1e-9, rules::block_unit_weight_kN_m3).empty());
  CHECK(!number_rule_violation(0.0, rules::damping_pct).empty());  // (0, 100]
  CHECK(number_for_message(std::numeric_limits<double>::infinity()) == "infinite");
  CHECK(number_for_message(-std::nan("")) == "not a number");
  // Case-file fields (the building and tie fields go through the same parser).
  struct Bad {
    const char* pointer;
    nlohmann::json value;
    const char* expect;
  };
  const Bad bad[] = {
      {"/mechanism/blocks/0/unit_weight", 1e-320, "/mechanism/blocks/0/unit_weight: value 9.99989e-321 is a subnormal"},
      {"/mechanism/blocks/0/length", 1e-300, "/mechanism/blocks/0/length: value 1e-300 out of range: expected in [0.001, 1000] m"},
      {"/mechanism/blocks/0/polygon/2/1", 1e150, "/mechanism/blocks/0/polygon/2/1: value 1e+150 out of range"},
      {"/mechanism/loads/0/weight", 1e300, "/mechanism/loads/0/weight: value 1e+300 out of range: expected in [0, 1e+06] kN"},
      {"/building", nlohmann::json{{"height_m", 8.0}, {"storeys", 2}, {"T1_s", 1e-320}}, "/building/T1_s: value"},
      {"/building", nlohmann::json{{"height_m", 8.0}, {"storeys", 2}, {"damping_pct", 1e308}}, "/building/damping_pct: value 1e+308 out of range"},
  };
  for (const Bad& b : bad) {
    nlohmann::json c = block_case();
    c[nlohmann::json::json_pointer(b.pointer)] = b.value;
    CAPTURE(b.pointer);
    const std::string e = input_error([&] { parse_case(c, "c.json"); });
    CHECK(e.find(std::string("c.json: ") + b.expect) == 0);
    CHECK(!has_inf_or_nan(e));
  }
  // A tie: spacing 1e-300 m, tau 1e-320 MPa, a rod of 1e200 mm (each gave
  // alpha0 = inf, "inf ties" or "rod area = inf").
  const nlohmann::json tie = nlohmann::json::parse(R"({"point": [-0.25, 5.5], "rod": {"diameter_mm": 20},
    "free_length_m": 6, "anchor": {"type": "plate", "a_mm": 200, "t_mm": 20},
    "masonry": {"fm_MPa": 2.4, "tau_MPa": 0.06, "thickness_m": 0.5}, "wall_length_m": 3, "spacing_m": 3})");
  const Bad tie_bad[] = {
      {"/spacing_m", 1e-300, "/ties/0/spacing_m: value 1e-300 out of range: expected in [0.1, 500] m"},
      {"/masonry/tau_MPa", 1e-320, "/ties/0/masonry/tau_MPa: value 9.99989e-321 is a subnormal"},
      {"/rod/diameter_mm", 1e200, "/ties/0/rod/diameter_mm: value 1e+200 out of range: expected in [6, 100] mm"},
      {"/free_length_m", -1.0, "/ties/0/free_length_m: value -1 out of range"},
  };
  for (const Bad& b : tie_bad) {
    nlohmann::json c = block_case();
    nlohmann::json t = tie;
    t[nlohmann::json::json_pointer(b.pointer)] = b.value;
    c["ties"] = nlohmann::json::array({t});
    CAPTURE(b.pointer);
    const std::string e = input_error([&] { parse_case(c, "c.json"); });
    CAPTURE(e);
    CHECK(e.find(std::string("c.json: ") + b.expect) == 0);
  }
}

TEST_CASE("class 1: a block index out of range and weights that are not finite never corrupt memory") {
  // Coordinates of 1e150 m made every weight and centroid not-a-number: no
  // seismic weight was found to move outward, no control point either, and
  // analyse_kinematic called position_jacobian with block -1, which wrote
  // outside its matrix ("free(): invalid pointer"; ASan: heap-buffer-overflow).
  Block b;
  b.name = "wall";
  b.polygon = {{-0.5, 0.0}, {0.0, 0.0}, {0.0, 6.0}, {-0.5, 6.0}};
  b.unit_weight = 18e3;
  b.length = 1.0;
  Constraint hinge;
  hinge.type = ConstraintType::GroundHinge;
  hinge.block = 0;
  hinge.point = {0.0, 0.0};
  const Chain chain({b}, {hinge}, {});
  CHECK_THROWS_AS(chain.position_jacobian(-1, {0.0, 0.0}, Eigen::VectorXd::Zero(3)), InputError);
  CHECK_THROWS_AS(chain.position_jacobian(1, {0.0, 0.0}, Eigen::VectorXd::Zero(3)), InputError);
  // The chain refuses coordinates whose products overflow, and the case file
  // its 1 km bound, with the JSON path.
  Block huge = b;
  huge.polygon = {{-1e150, 0.0}, {0.0, 0.0}, {0.0, 1e150}, {-1e150, 1e150}};
  CHECK(input_error([&] { Chain({huge}, {hinge}, {}); }).find("lies farther than 1e+06 m from the origin") !=
        std::string::npos);
  // Finite inputs whose weight overflows (1e300 N/m^3 over 1e10 m): a named
  // error before anything is divided by it.
  Block heavy = b;
  heavy.unit_weight = 1e300;
  heavy.length = 1e10;
  CHECK(!input_error([&] { analyse_kinematic(Chain({heavy}, {hinge}, {}), KinematicOptions{}); }).empty());
  CHECK(analyse_kinematic(chain, KinematicOptions{}).alpha0 > 0.0);
}

TEST_CASE("class 1: degenerate polygons are diagnosed as such") {
  struct Poly {
    const char* what;
    std::vector<std::vector<double>> v;
    const char* expect;
  };
  const Poly polys[] = {
      {"collinear", {{-0.5, 0}, {0, 0}, {0.5, 0}}, "vertices lie on one line"},
      {"collinear, four", {{0, 0}, {0, 1}, {0, 2}, {0, 3}}, "vertices lie on one line"},
      {"self-crossing (bow tie)", {{-0.5, 0}, {0, 6}, {0, 0}, {-0.5, 6}}, "its edges cross"},
      {"self-crossing (figure eight)", {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {1, 2}, {0, 2}}, "its edges cross"},
      {"tiny", {{-1e-5, 0}, {0, 0}, {0, 1e-5}}, "less than 0.001 m"},
      {"repeated vertex", {{-0.5, 0}, {0, 0}, {0, 0}, {0, 6}}, "are the same point"},
      {"two vertices", {{0, 0}, {0, 6}}, "at least 3"},
  };
  for (const Poly& p : polys) {
    CAPTURE(p.what);
    nlohmann::json c = block_case();
    c["mechanism"]["blocks"][0]["polygon"] = p.v;
    const std::string e = input_error([&] { parse_case(c, "c.json"); });
    CHECK(e.find(std::string("c.json: /mechanism/blocks/0/polygon")) == 0);
    CHECK(e.find(p.expect) != std::string::npos);
    CHECK(e.find("outside every block") == std::string::npos);
  }
  // A valid concave polygon (an L) passes.
  nlohmann::json c = block_case();
  c["mechanism"]["blocks"][0]["polygon"] = {{-0.5, 0}, {0, 0}, {0, 6}, {-0.2, 6}, {-0.2, 3}, {-0.5, 3}};
  c["mechanism"]["loads"] = nlohmann::json::array();
  CHECK_NOTHROW(parse_case(c, "c.json"));
}

TEST_CASE("class 1: names without control characters") {
  for (const char* name : {"wa\x01ll", "tab\there", "nul", "del\x7f", "c1\xc2\x85"}) {
    nlohmann::json c = block_case();
    std::string n = name;
    if (n == "nul") n = std::string("a\0b", 3);
    c["mechanism"]["blocks"][0]["name"] = n;
    CAPTURE(name);
    CHECK(input_error([&] { parse_case(c, "c.json"); }).find("/mechanism/blocks/0/name: the text holds a control character") !=
          std::string::npos);
  }
  nlohmann::json c = block_case();
  c["project"] = "Chiesa di Sant'Agata — facciata (è, ü, ß)";
  CHECK_NOTHROW(parse_case(c, "c.json"));
}

TEST_CASE("class 1: records: hexadecimal values, dt of 1e-320 and a decreasing time column") {
  const std::string dir = temp_dir("records");
  CHECK(input_error([&] { parse_plain_record_text("0.1\n0x1p-3\n", "r.txt", 0.01, AccelerationUnit::g); })
            .find("r.txt:2: hexadecimal value '0x1p-3'") == 0);
  CHECK(input_error([&] { parse_plain_record_text("0.1\n0.2\n", "r.txt", 1e-320, AccelerationUnit::g); })
            .find("r.txt: time step 9.99989e-321 s: expected a time step in [1e-06, 10] s") == 0);
  const std::string at2 = "PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    2, DT=  1E-320 SEC\n0.1 0.2\n";
  CHECK(input_error([&] { parse_record_text(at2, "r.AT2"); }).find("r.AT2: the header gives the time step") == 0);
  const std::string at2hex = "PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    2, DT=  0x1p-6 SEC\n0.1 0.2\n";
  CHECK(input_error([&] { parse_record_text(at2hex, "h.AT2"); }).find("h.AT2: time step must be positive (s): the header gives the time step 0 s") == 0);
  write(dir + "/down.txt", "0 0.1\n0.01 0.2\n0.02 0.1\n0.01 0.3\n");
  const std::string e = input_error([&] { read_plain_record(dir + "/down.txt", AccelerationUnit::g); });
  CHECK(e.find("down.txt:4: the time column must increase: t = 0.01 s after t = 0.02 s") != std::string::npos);
  CHECK(e.find("--unit") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("class 2: outputs are whole or absent, never over an input, never through a link out of their folder") {
  const std::string dir = temp_dir("outputs");
  // An input of this run (read by the bounded reader) is protected.
  const std::string kase = write(dir + "/case.json", "{}");
  read_input_file(kase, input_kinds::case_file);
  CHECK(input_error([&] { write_output_file(kase, "report", "--html"); })
            .find("--html: " + kase + " is an input of this run: refusing to replace it") == 0);
  CHECK(slurp(kase) == "{}");
  // A hard link to it, another spelling of its path: the same file.
  fs::create_hard_link(kase, dir + "/hard.json");
  CHECK(!input_error([&] { write_output_file(dir + "/hard.json", "x", "--html"); }).empty());
  CHECK(!input_error([&] { write_output_file(dir + "/./case.json", "x", "--html"); }).empty());
  // A link out of the asked folder (dangling or not) is refused; inside, followed.
  fs::create_directories(dir + "/out");
  fs::create_directories(dir + "/elsewhere");
  fs::create_symlink(dir + "/elsewhere/M1.json", dir + "/out/M1.json");
  fs::create_symlink("M9.json", dir + "/out/M2.json");
  CHECK(input_error([&] { write_output_file(dir + "/out/M1.json", "{}", "--expand out", dir + "/out"); })
            .find("is a symbolic link to " + dir + "/elsewhere/M1.json, outside") != std::string::npos);
  CHECK(!fs::exists(dir + "/elsewhere/M1.json"));
  write_output_file(dir + "/out/M2.json", "two", "--expand out", dir + "/out");
  CHECK(slurp(dir + "/out/M9.json") == "two");
  CHECK(fs::is_symlink(dir + "/out/M2.json"));
  // Atomic: the old content until the new one is complete; no temporary left.
  write(dir + "/r.html", "old");
  write_output_file(dir + "/r.html", std::string(1 << 20, 'x'), "--html");
  CHECK(slurp(dir + "/r.html").size() == (1u << 20));
  int left = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp.") != std::string::npos) ++left;
  CHECK(left == 0);
  // A directory, a missing folder, a file system that refuses: named errors.
  CHECK(input_error([&] { write_output_file(dir, "x", "--html"); }).find("is a directory") != std::string::npos);
  CHECK(input_error([&] { write_output_file(dir + "/no/such/r.html", "x", "--html"); }).find("no folder") !=
        std::string::npos);
  CHECK(!input_error([&] { write_output_file("/proc/assess-test.html", "x", "--html"); }).empty());
  // A full disk is a failure of the machine (SystemError, exit status 1), not a success.
  if (fs::exists("/dev/full")) {
    CHECK_THROWS_WITH_AS(write_output_file("/dev/full", "x", "--history"),
                         doctest::Contains("--history: /dev/full: cannot write: No space left on device"), SystemError);
  }
  CHECK_NOTHROW(write_output_file("/dev/null", "x", "--history"));
  // An output folder that is a regular file.
  CHECK(input_error([&] { make_output_folder(kase, "--out"); }).find("is a regular file, expected a folder") !=
        std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("class 3: building files: --mechanism selects by id; a name that reads as another id is refused") {
  nlohmann::json b = nlohmann::json::parse(slurp(kRoot + "/mechanisms/building-house.json"));
  b["walls"][0]["mechanisms"][0]["name"] = "M2";
  CHECK(input_error([&] { parse_building(b, "b.json"); })
            .find("b.json: /walls/0/mechanisms/0/name: \"M2\" reads as the id of another mechanism") == 0);
  b["walls"][0]["mechanisms"][0]["name"] = "M1";  // its own id: allowed
  b["walls"][0]["mechanisms"][1]["name"] = "Secondo piano";
  b.erase("dynamic");
  const BuildingCase bc = parse_building(b, "b.json");
  CHECK(find_mechanism(bc, "M2").name == "Secondo piano");
  CHECK(find_mechanism(bc, "Secondo piano").id == "M2");
  CHECK(find_mechanism(bc, "M1").id == "M1");
}

TEST_CASE("class 3: comuni: an unknown character matches nothing; a name shared with part of another needs the province") {
  const auto table = ComuneTable::shipped();
  for (const char* name : {"L'Aquila\xF0\x9F\x98\x80", "Norcia\xE2\x98\x83", "Roma?", "Nor\x01" "cia"}) {
    CAPTURE(name);
    CHECK(input_error([&] { table->find(name, ""); }).find("is not in the ISTAT list") != std::string::npos);
  }
  CHECK(table->find("L\xE2\x80\x99" "Aquila", "").istat_code == "066049");  // typographic apostrophe
  CHECK(input_error([&] { table->find("Vignola", ""); }).find("ambiguous") != std::string::npos);
  CHECK(table->find("Vignola", "MO").province == "MO");
  CHECK(input_error([&] { table->find("Cavallino", ""); }).find("ambiguous") != std::string::npos);
  CHECK(table->find("Bozen", "").province == "BZ");
}

TEST_CASE("class 4: the reports' number guard never prints inf or nan") {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  for (double bad : {inf, -inf, nan, -nan}) {
    const std::string row = format("%-8s|%8.3f|%*.*f|%d|%g", "D/C", bad, 7, 2, bad, 3, bad);
    CAPTURE(row);
    CHECK(!has_inf_or_nan(row));
    CHECK(row == std::string("D/C     |       ") + unbounded_mark + "|      " + unbounded_mark + "|3|" + unbounded_mark);
    const std::string m = fmt::format(fmt::runtime("N_Ed = {:.1f} kN, D/C {}"), detail::guard_arg(bad), detail::guard_arg(bad));
    CHECK(!has_inf_or_nan(m));
  }
  CHECK(format("%8.3f", 1.25) == "   1.250");
  CHECK(finite_or(inf, "%.1f kN", "non raggiungibile") == "non raggiungibile");
  CHECK(finite_or(12.345, "%.1f kN", "non raggiungibile") == "12.3 kN");
}

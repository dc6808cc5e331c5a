// Hostile input, round five (issue 39): one regression test per class, with
// inputs made here. Each failed before its fix: an exception through
// std::call_once (SIGABRT), a catalogue or spectra file read without bounds
// (a directory, /dev/zero, a FIFO that hangs, 64 GB asked by a 600 kB file),
// spectra trusted once their hash matched, two outputs of one run on one
// file, temporaries and children left by a signal, a metadata table or a
// catalogue outside the rules of case files, a horizontal-flexure search of
// a minute (docs/reliability.md, "Round five").
#include <doctest/doctest.h>

#include <assess/assessment/case_file.hpp>
#include <assess/kinematic/horizontal_flexure.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/records/library_selection.hpp>
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_library.hpp>
#include <assess/records/record_spectra.hpp>
#include <assess/risk/fragility_report.hpp>
#include <assess/support/content_hash.hpp>
#include <assess/support/error.hpp>
#include <assess/support/input_file.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/output_file.hpp>
#include <assess/support/termination.hpp>
#include <assess/support/units.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <csignal>
#include <sys/stat.h>
#include <unistd.h>

#include "test_files.hpp"

using namespace assess;

namespace {

namespace fs = std::filesystem;

const std::string kRoot = std::string(ASSESS_TEST_DATA_DIR);
const std::string kMini = kRoot + "/tests/data/records_mini/metadata.csv";

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

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A copy of the small library (3 usable records) in `dir`, with its catalogue
// and spectra as `assess records build` leaves them; returns the catalogue's path.
std::string mini_library(const std::string& dir) {
  RecordCatalogue cat = build_catalogue(kMini);
  for (CatalogueEntry& e : cat.entries) {
    fs::copy_file(cat.directory + "/" + e.file, dir + "/" + fs::path(e.file).filename().string(),
                  fs::copy_options::overwrite_existing);
    e.file = fs::path(e.file).filename().string();
  }
  cat.directory = dir;
  const std::string text = catalogue_json(cat);
  write(dir + "/catalogue.json", text);
  cat.text_hash = content_hash(text);
  write_library_spectra(compute_library_spectra(cat), dir + "/" + library_spectra_file);
  return dir + "/catalogue.json";
}

// A spectra file's bytes with their trailing content hash made right again.
std::string rehash(std::string bytes) {
  bytes.resize(bytes.size() - 8);
  const std::uint64_t h = content_hash(bytes);
  bytes.append(reinterpret_cast<const char*>(&h), 8);
  return bytes;
}

// Position of the first ordinate and of the periods in a spectra file (record_spectra.cpp's layout).
struct Layout {
  std::size_t periods = 0, psa = 0, np = 0;
};
Layout layout(const std::string& bytes) {
  Layout l;
  std::uint32_t np, nd, nr;
  std::memcpy(&np, bytes.data() + 32, 4);
  std::memcpy(&nd, bytes.data() + 36, 4);
  std::memcpy(&nr, bytes.data() + 40, 4);
  l.np = np;
  l.periods = 44;
  std::size_t pos = 44 + 8 * (std::size_t(np) + nd);
  for (std::uint32_t i = 0; i < nr; ++i) {
    std::uint32_t len;
    std::memcpy(&len, bytes.data() + pos, 4);
    pos += 4 + len;
  }
  l.psa = pos;
  return l;
}

// True while `pid` runs (a zombie left to a container's init that does not reap is not running).
bool running(pid_t pid) {
  const std::string status = slurp("/proc/" + std::to_string(pid) + "/status");
  return !status.empty() && status.find("\nState:\tZ") == std::string::npos;
}

void put_double(std::string& bytes, std::size_t at, double v) { std::memcpy(&bytes[at], &v, 8); }

}  // namespace

// First in this file: the protected inputs of the process are (device, inode)
// pairs, and the other cases read files they then delete, whose inodes the
// file system may give to this case's files.
TEST_CASE("class 4: the outputs of one run are distinct files, by identity") {
  const std::string dir = temp_dir("round5_outputs");
  const std::string r = dir + "/r.pdf";
  // The same name spelled three ways, existing or not.
  for (bool exists : {false, true}) {
    if (exists) write(r, "old");
    CHECK(contains(input_error([&] { check_output_files({{r, "--pdf", ""}, {r, "--docx", ""}}); }),
                   "--pdf " + r + " and --docx " + r + " are the same file"));
    CHECK(!input_error([&] { check_output_files({{r, "--html", ""}, {dir + "/./r.pdf", "--pdf", ""}}); }).empty());
    fs::create_directories(dir + "/sub");
    CHECK(!input_error([&] { check_output_files({{r, "--html", ""}, {dir + "/sub/../r.pdf", "--pdf", ""}}); }).empty());
  }
  // A hard link and a symbolic link (inside the folder) to it.
  fs::create_hard_link(r, dir + "/hard.pdf");
  fs::create_symlink("r.pdf", dir + "/soft.pdf");
  CHECK(!input_error([&] { check_output_files({{r, "--pdf", ""}, {dir + "/hard.pdf", "--txt", ""}}); }).empty());
  CHECK(!input_error([&] { check_output_files({{dir + "/soft.pdf", "--pdf", ""}, {r, "--txt", ""}}); }).empty());
  // An expanded case and a report on it.
  fs::create_directories(dir + "/D");
  CHECK(contains(input_error([&] {
                   check_output_files({{dir + "/D/M1.json", "--txt", ""}, {dir + "/D/M1.json", "--expand D", dir + "/D"}});
                 }),
                 "are the same file"));
  // Distinct files pass; /dev/null may be shared (written in place, nothing replaced).
  CHECK_NOTHROW(check_output_files({{r, "--pdf", ""}, {dir + "/r.html", "--html", ""}, {dir + "/D/M1.json", "--expand D", dir + "/D"}}));
  CHECK_NOTHROW(check_output_files({{"/dev/null", "--pdf", ""}, {"/dev/null", "--html", ""}}));
  fs::remove_all(dir);
}

TEST_CASE("class 1: no exception crosses std::call_once: the memoised selection and records give their error to every caller") {
  const std::string dir = temp_dir("round5_once");
  const std::string path = mini_library(dir);
  const auto lib = RecordLibrary::open(path);
  // A window the wrong way round (`records select --mw-min 7 --mw-max 5`
  // aborted with SIGABRT): every thread gets the same InputError, twice.
  LibrarySelectionRules rules;
  rules.filters.Mw_min = 7.0, rules.filters.Mw_max = 5.0, rules.filters.Mw_given = true;
  SelectionOptions so;
  so.n_records = 2;
  const auto target = [](double) { return 3.0; };
  std::vector<std::string> errors(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < errors.size(); ++i)
    threads.emplace_back([&, i] { errors[i] = input_error([&] { select_from_library(*lib, rules, target, so); }); });
  for (auto& t : threads) t.join();
  for (const std::string& e : errors) CHECK(contains(e, "Mw window: expected Mw_min <= Mw_max"));
  CHECK(contains(input_error([&] { select_from_library(*lib, rules, target, so); }), "Mw window"));
  // A record changed since the build: the same message for every caller of
  // record() and psa(), and from RecordCatalogue::load (`records show`).
  write(dir + "/ARL360.at2", slurp(dir + "/ARL360.at2") + "\n");
  const CatalogueEntry& e = *lib->catalogue().find("ARL360");
  std::string r1, r2;
  std::thread t([&] { r1 = input_error([&] { lib->record(e); }); });
  r2 = input_error([&] { lib->record(e); });
  t.join();
  CHECK(contains(r1, "ARL360.at2: the file changed since the catalogue was built"));
  CHECK(r1 == r2);
  CHECK(contains(input_error([&] { lib->psa(e, {0.5, 1.0}, 0.05); }), "changed since the catalogue was built"));
  CHECK(contains(input_error([&] { lib->catalogue().load(e); }), "changed since the catalogue was built"));
  // A record deleted since the build: named, not a crash.
  fs::remove(dir + "/RSN289_1.AT2");
  CHECK(contains(input_error([&] { lib->record(*lib->catalogue().find("RSN289_1")); }),
                 "RSN289_1.AT2: cannot open the record file: No such file or directory"));
  fs::remove_all(dir);
}

TEST_CASE("class 2: the record library reads through the bounded reader; spectra counts are checked in 64 bits first") {
  const std::string dir = temp_dir("round5_bounded");
  const auto t0 = std::chrono::steady_clock::now();
  // A directory, a character device, a FIFO as the catalogue or as one of its records.
  CHECK(contains(input_error([&] { RecordLibrary::open(dir); }), "is a directory, expected a record catalogue"));
  CHECK(contains(input_error([&] { RecordLibrary::open("/dev/zero"); }), "is a character device, expected a record catalogue"));
  CHECK(contains(input_error([&] { build_catalogue("/dev/zero"); }), "is a character device, expected a record metadata table"));
  const std::string path = mini_library(dir);
  fs::remove(dir + "/elCentro.AT2");
  REQUIRE(::mkfifo((dir + "/elCentro.AT2").c_str(), 0600) == 0);
  const auto lib = RecordLibrary::open(path);
  CHECK(contains(input_error([&] { lib->record(*lib->catalogue().find("elCentro")); }),
                 "elCentro.AT2: is a FIFO (named pipe), expected a record file"));
  CHECK(seconds_since(t0) < 10.0);  // nothing blocked, nothing read until memory ran out
  // spectra.bin whose three 32-bit counts multiply to 2^64 + 3: it asked for
  // 64 GB (a wrapped size check); now "do not fit" before any allocation.
  RecordCatalogue cat = read_catalogue(path);
  std::string bytes = slurp(dir + "/" + library_spectra_file);
  for (const auto& [np, nd, nr] : {std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>{65536u, 65536u, 65536u},
                                   {4294967295u, 4294967295u, 3u}, {602u, 1u, 4294967295u}}) {
    std::string b = bytes;
    std::memcpy(&b[32], &np, 4);
    std::memcpy(&b[36], &nd, 4);
    std::memcpy(&b[40], &nr, 4);
    CHECK(contains(input_error([&] { parse_library_spectra(rehash(b), "s.bin", cat); }), "do not fit the file"));
  }
  // The first id's length takes the whole payload: the next length lay in the
  // content hash, moved the reader past the file's end and the read after it
  // came from a wild address (the spectra fuzzer, a SEGV under ASan). The
  // reader now stops at the payload's end: "truncated file".
  {
    std::uint32_t np, nd;
    std::memcpy(&np, bytes.data() + 32, 4);
    std::memcpy(&nd, bytes.data() + 36, 4);
    const std::size_t first_id = 44 + 8 * (std::size_t(np) + nd);
    std::string b = bytes;
    const std::uint32_t len = std::uint32_t(b.size() - 8 - (first_id + 4));
    std::memcpy(&b[first_id], &len, 4);
    CHECK(contains(input_error([&] { parse_library_spectra(rehash(b), "s.bin", cat); }), "truncated file"));
  }
  fs::remove_all(dir);
}

TEST_CASE("class 3: spectra.bin is validated after its hash; the library then integrates and says why") {
  const std::string dir = temp_dir("round5_spectra");
  const std::string path = mini_library(dir);
  const RecordCatalogue cat = read_catalogue(path);
  const std::string good = slurp(dir + "/" + library_spectra_file);
  REQUIRE(input_error([&] { parse_library_spectra(good, "s.bin", cat); }).empty());
  const Layout l = layout(good);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Damage {
    std::size_t at;
    double value;
    const char* why;
  };
  const std::vector<Damage> damages = {
      {l.psa + 8 * 100, nan, "expected a positive value"},
      {l.psa + 8 * 100, 0.0, "expected a positive value"},
      {l.psa + 8 * 100, -1.0, "expected a positive value"},
      {l.psa + 8 * 100, 1e300, "at most PGA/(xi sqrt(1 - xi^2))"},
      {l.psa, 1.0, "is not its PGA"},  // T = 0 of the first record (elCentro: 0.32 g)
      {l.periods + 8 * 50, nan, "the period grid must start at 0 s and increase strictly"},
      {l.periods + 8 * 50, 0.0, "the period grid must start at 0 s and increase strictly"},  // repeated/decreasing
      {l.periods + 8 * (l.np + 0), 0.0, "is not a fraction of critical"},                   // damping 0
  };
  for (const Damage& d : damages) {
    std::string b = good;
    put_double(b, d.at, d.value);
    const std::string e = input_error([&] { parse_library_spectra(rehash(b), "s.bin", cat); });
    CAPTURE(d.why);
    CHECK(contains(e, d.why));
  }
  // Another number of records than the catalogue's usable ones.
  RecordCatalogue fewer = cat;
  fewer.entries.front().usable_for_design = false;
  CHECK(contains(input_error([&] { parse_library_spectra(good, "s.bin", fewer); }), "3 records, the catalogue has 2"));
  // The library with damaged spectra: not used, said why, the selection integrates.
  std::string b = good;
  put_double(b, l.psa + 8 * 200, 1e300);
  write(dir + "/" + library_spectra_file, rehash(b));
  const auto lib = RecordLibrary::open(path);
  CHECK(lib->spectra() == nullptr);
  CHECK(contains(lib->spectra_problem(), "at most PGA"));
  LibrarySelectionRules rules;
  rules.include_near_fault = true;
  rules.filters.Mw_min = 6.0, rules.filters.Mw_max = 7.0, rules.filters.Mw_given = true;
  rules.filters.R_max_km = 100.0, rules.filters.R_given = true;
  SelectionOptions so;
  so.n_records = 1;
  so.max_per_event = 1;
  const auto sel = select_from_library(*lib, rules, [](double) { return 2.0; }, so);
  CHECK(sel->spectra_source == "integrated");
  fs::remove_all(dir);
}

TEST_CASE("class 5: a child's time limit stops its whole process group; an unusable TMPDIR is named") {
  const std::string dir = temp_dir("round5_children");
  // Not found: the start error, not an exit status of a shell.
  const ProgramResult missing = run_program({"assess-no-such-program"}, dir + "/log", 10);
  CHECK(!missing.started);
  CHECK(missing.start_error == ENOENT);
  // A program that leaves a grandchild behind: both stopped at the limit.
  const auto t0 = std::chrono::steady_clock::now();
  const ProgramResult slow =
      run_program({"sh", "-c", "sleep 30 & echo $! > '" + dir + "/pid'; sleep 30"}, dir + "/log", 1);
  CHECK(slow.timed_out);
  CHECK(seconds_since(t0) < 10.0);
  const pid_t grandchild = std::atoi(slurp(dir + "/pid").c_str());
  REQUIRE(grandchild > 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  CHECK(!running(grandchild));
  // The exit status and the log.
  const ProgramResult ok = run_program({"sh", "-c", "echo hello; exit 3"}, dir + "/log", 10);
  CHECK(ok.started);
  CHECK(ok.exit_status == 3);
  CHECK(slurp(dir + "/log") == "hello\n");
  // A temporary folder under an unusable TMPDIR: the variable and the cause.
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  ::setenv("TMPDIR", (dir + "/no/such/folder").c_str(), 1);
  const std::string e = input_error([&] { make_temporary_folder("assess_test_"); });
  if (old) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  CHECK(contains(e, "cannot create a temporary folder in TMPDIR=" + dir + "/no/such/folder: No such file or directory"));
  const std::string made = make_temporary_folder("assess_test_");
  CHECK(fs::is_directory(made));
  fs::remove_all(made);
  release_temporary(made);
  fs::remove_all(dir);
}

TEST_CASE("class 6: a text that is not UTF-8 is refused by the text rule, named by its byte") {
  // The metadata fuzzer: a byte 0x88 in a station's name reached catalogue.json, whose writer threw
  // (nlohmann::json's type_error 316) through the build. UTF-8 that is valid passes; C1 controls do not.
  CHECK(control_character_violation("Bagnoli Irpino") == "");
  CHECK(control_character_violation("L'Aquila – Parco del Castello, Ø 16 €, 𝛼") == "");
  CHECK(control_character_violation("A\x88" "B") == "the text is not valid UTF-8 (byte 0x88 at character 2)");
  CHECK(contains(control_character_violation("\xC0\xAF"), "not valid UTF-8 (byte 0xC0"));      // overlong '/'
  CHECK(contains(control_character_violation("x\xED\xA0\x80"), "not valid UTF-8 (byte 0xED"));  // a surrogate
  CHECK(contains(control_character_violation("\xE2\x82"), "not valid UTF-8 (byte 0xE2"));       // cut short
  CHECK(contains(control_character_violation("\xF5\x80\x80\x80"), "not valid UTF-8"));       // beyond U+10FFFF
  CHECK(control_character_violation("a\xC2\x85" "b") == "the text holds a control character (U+0085) at character 2");
  CHECK(control_character_violation("\xC2\xB0" "C") == "");  // the degree sign
}

TEST_CASE("class 6: metadata.csv and catalogue.json under the number and text rules of case files") {
  const std::string dir = temp_dir("round5_metadata");
  const std::string table = slurp(kMini);
  const std::string header = table.substr(0, table.find('\n') + 1);
  const std::string row = table.substr(header.size(), table.find('\n', header.size()) - header.size() + 1);
  auto build = [&](const std::string& text) {
    // The rows name the shipped records relative to tests/data/records_mini.
    const std::string t = kRoot + "/tests/data/records_mini/round5_" + std::to_string(::getpid()) + ".csv";
    write(t, text);
    const std::string e = input_error([&] { build_catalogue(t); });
    fs::remove(t);
    return e;
  };
  auto with_cell = [&](std::size_t column, const std::string& value) {
    std::vector<std::string> cells;
    std::string r = row.substr(0, row.size() - 1), cur;
    bool q = false;
    for (char c : r) {
      if (c == '"') q = !q;
      if (c == ',' && !q) cells.push_back(cur), cur.clear();
      else cur += c;
    }
    cells.push_back(cur);
    cells[column] = value;
    std::string out;
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cells[i];
    return header + out + "\n";
  };
  CHECK(build(header + row).empty());
  // Control characters (ESC, BEL, NUL) refused with the row and the column.
  CHECK(contains(build(with_cell(1, std::string("Imperial\x1b[31mValley"))), ":2 column event: the text holds a control character (U+001B)"));
  CHECK(contains(build(with_cell(5, "Station\a")), "column station: the text holds a control character (U+0007)"));
  CHECK(contains(build(with_cell(13, std::string("US\0A", 4))), "column country: the text holds a control character (U+0000)"));
  // Hexadecimal, infinite, out-of-range numbers, with their units.
  CHECK(contains(build(with_cell(3, "0x1.bcp2")), "column Mw: must be a decimal number, got '0x1.bcp2' (a hexadecimal number)"));
  CHECK(contains(build(with_cell(3, "1e308")), "column Mw: value 1e+308 out of range: expected in [2, 10] -"));
  CHECK(contains(build(with_cell(9, "-5")), "column distance_km: value -5 out of range: expected in [0, 20000] km"));
  CHECK(contains(build(with_cell(11, "inf")), "column vs30_m_s: must be a finite number"));
  // A file named ".AT2": no record id.
  CHECK(contains(build(with_cell(0, "../../../spectra/records/.AT2")), "gives an empty record id"));
  // A byte order mark is not part of the first column's name; a column named twice is named.
  CHECK(build("\xEF\xBB\xBF" + header + row).empty());
  CHECK(contains(build(header.substr(0, header.size() - 1) + ",Mw\n" + row.substr(0, row.size() - 1) + ",6\n"),
                 "column 'Mw' is named twice (columns 4 and 24)"));

  // catalogue.json: the same rules, with the JSON path.
  const std::string path = mini_library(dir);
  const std::string text = slurp(path);
  auto read_with = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const std::size_t at = t.find(from);
    REQUIRE(at != std::string::npos);
    t.replace(at, from.size(), to);
    return input_error([&] { parse_catalogue_text(t, path); });
  };
  CHECK(contains(read_with("\"Mw\": 6.95", "\"Mw\": 1e308"), "/records/0/Mw: value 1e+308 out of range"));
  CHECK(contains(read_with("\"distance_km\": 6.09", "\"distance_km\": -5"), "/records/0/distance_km: value -5 out of range"));
  CHECK(contains(read_with("\"vs30_m_s\": 213.44", "\"vs30_m_s\": -1"), "/records/0/vs30_m_s: value -1 out of range"));
  CHECK(contains(read_with("\"dt_s\": 0.01", "\"dt_s\": 0"), "/dt_s: value 0 out of range"));
  CHECK(contains(read_with("\"station_code\": \"ELC\"", "\"station_code\": \"E\\u001b[2JLC\""),
                 "/records/0/station_code: the text holds a control character (U+001B)"));
  CHECK(contains(read_with("\"id\": \"ARL360\"", "\"id\": \"elCentro\""), "/records/1/id: duplicate record id"));
  CHECK(contains(read_with("\"Mw\": 6.95", "\"Mw\": null"), "/records/0/usable_for_design: true, but the entry has no Mw"));

  // `records build --output` in another folder: the paths are rewritten to resolve from there.
  RecordCatalogue cat = build_catalogue(kMini);
  fs::create_directories(dir + "/elsewhere/deeper");
  relocate_catalogue(cat, dir + "/elsewhere/deeper");
  for (const CatalogueEntry& e : cat.entries) CHECK_NOTHROW(cat.load(e));
  const RecordCatalogue back = parse_catalogue_text(catalogue_json(cat), dir + "/elsewhere/deeper/catalogue.json");
  CHECK_NOTHROW(back.load(back.entries.front()));
  fs::remove_all(dir);
}

TEST_CASE("class 7: inputs with their ranges: horizontal flexure, corner openings, a fragility summary") {
  const std::string dir = temp_dir("round5_ranges");
  // A fragility summary edited to beta = -1 is refused by `run --fragility`.
  const std::string kase = write(dir + "/case.json", "{}");
  const std::string summary = R"({"case": ")" + kase + R"(", "method": "multiple-stripe analysis", "VN_years": 50,
    "analyses": 10, "failed": 0, "code": {"SLV": {"TR_years": 475, "pga_m_s2": 2.5}},
    "governing": {"restitution": "housner", "theta_m_s2": 3.0, "beta": -1, "lambda_per_year": 0.001,
                  "return_period_years": 1000, "probability_in_VN": 0.05}})";
  fs::create_directories(dir + "/f");
  write(dir + "/f/summary.json", summary);
  CHECK(contains(input_error([&] { read_fragility_summary(dir + "/f", kase); }),
                 "/governing/beta: value -1 out of range: expected in (0, 10] -"));
  write(dir + "/f/summary.json", std::string(summary).replace(summary.find("\"beta\": -1"), 10, "\"beta\": 0.4"));
  CHECK_NOTHROW(read_fragility_summary(dir + "/f", kase));
  fs::remove_all(dir);
}

TEST_CASE("class 9: horizontal flexure: the closed-form alpha0 of the search is the chain's; its caps") {
  HorizontalFlexureParams p;
  p.span = 6.0, p.thickness = 0.45, p.unit_weight = 18e3, p.strength = 2.0e6;
  p.tie = 40e3;
  p.ring_beam_moment = 12e3;
  HorizontalStrip s;
  s.base_z = 3.0, s.height = 1.2, s.carried_weight = 6e3;
  s.openings = {{0.8, 1.9, 0.7}, {3.1, 3.9, 1.0}, {4.4, 5.5, 0.3}};
  p.strips = {s};
  for (StressBlock b : {StressBlock::Rectangular, StressBlock::Triangular}) {
    p.stress_block = b;
    for (double um : {0.37, 1.0, 1.9, 2.5, 3.05, 4.0, 5.6}) {
      HorizontalFlexureParams q = p;
      q.strips[0].middle_hinge = um;
      const MechanismSet set = horizontal_flexure(q);
      const double chain = activation_multiplier(set.candidates.front().chain);
      CAPTURE(um);
      // The same virtual work: equal to rounding (relative 1e-9).
      CHECK(strip_alpha0(p, s, um) == doctest::Approx(chain).epsilon(1e-9));
    }
  }
  // Its caps (issue 39): 20 strips of 6 openings (a case asking more is
  // refused with the path), 200 search points; the candidates are built in
  // milliseconds (a chain analysis per search point took 57 s of CPU at the
  // former caps, 50 strips of 20 openings).
  nlohmann::json c = nlohmann::json::parse(slurp(kRoot + "/tests/data/hostile/flexure_caps.json"));
  CHECK_NOTHROW(parse_case(c, "caps.json"));
  nlohmann::json more = c;
  more["mechanism"]["strips"].push_back(c["mechanism"]["strips"][0]);
  CHECK(contains(input_error([&] { parse_case(more, "caps.json"); }), "caps.json: /mechanism/strips: at most 20 strips"));
  more = c;
  more["mechanism"]["strips"][3]["openings"].push_back({{"from", 5.8}, {"to", 5.9}, {"height", 0.01}});
  CHECK(contains(input_error([&] { parse_case(more, "caps.json"); }),
                 "caps.json: /mechanism/strips/3/openings: at most 6 openings per strip"));
  HorizontalFlexureParams big = p;
  big.search_points = 200;
  big.strips.clear();
  for (int k = 0; k < 20; ++k) {
    HorizontalStrip st;
    st.base_z = 0.1 * k, st.height = 0.1;
    for (int j = 0; j < 6; ++j) st.openings.push_back({0.1 + 0.9 * j, 0.1 + 0.9 * j + 0.45, 0.01 + 0.012 * j});
    big.strips.push_back(st);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const MechanismSet set = horizontal_flexure(big);
  CHECK(set.candidates.size() == 20);
  MESSAGE("horizontal flexure at its caps: candidates built in " << seconds_since(t0) << " s");
}

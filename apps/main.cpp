// assess: command-line front end of libassess.
#include "commands.hpp"

#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/termination.hpp>
#include <assess/support/version.hpp>

#include <algorithm>
#include <vector>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <iostream>
#include <map>
#include <string>


namespace {

// The text of a number option as the user wrote it, without surrounding blanks.
std::string trimmed(const std::string& text) {
  const auto b = text.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return text.substr(b, text.find_last_not_of(" \t") - b + 1);
}

}  // namespace

void assess::cli::require_finite_numbers(CLI::App& app) {
  // The rule of every number a user writes (number_rules.hpp): decimal, finite, of normal size.
  const CLI::Validator decimal(
      [](std::string& text) -> std::string {
        double v = 0.0;
        const std::string t = trimmed(text);
        const std::string bad = assess::decimal_number_violation(t, v);
        return t.empty() ? "" : bad;  // an empty value: CLI11's own message
      },
      "DECIMAL");
  std::function<void(CLI::App&)> walk = [&](CLI::App& a) {
    for (CLI::Option* o : a.get_options()) {
      const std::string type = o->get_type_name();
      if (type == "FLOAT" || type == "INT" || type == "UINT") o->check(decimal);
    }
    for (CLI::App* sub : a.get_subcommands({})) walk(*sub);
  };
  walk(app);
}

CLI::Option* assess::cli::with_rule(CLI::Option* option, const assess::NumberRule& rule) {
  const assess::NumberRule r = rule;
  option->check(CLI::Validator(
      [r](std::string& text) -> std::string {
        double v = 0.0;
        const std::string t = trimmed(text);
        std::string bad = assess::decimal_number_violation(t, v);
        if (bad.empty()) bad = assess::number_rule_violation(v, r);
        return bad;
      },
      std::string(rule.lo_open ? "(" : "[") + assess::number_for_message(rule.lo) + ", " +
          assess::number_for_message(rule.hi) + "] " + rule.unit,
      "RULE"));
  return option;
}

std::vector<double> assess::cli::parse_number_list(const std::string& text, const char* option,
                                                  const assess::NumberRule& rule) {
  std::vector<double> out;
  std::size_t from = 0;
  for (std::size_t item = 1;; ++item) {
    const std::size_t comma = text.find(',', from);
    const std::string t = trimmed(text.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    double v = 0.0;
    std::string bad = assess::decimal_number_violation(t, v);
    if (bad.empty()) bad = assess::number_rule_violation(v, rule);
    if (!bad.empty())
      throw assess::InputError(std::string(option) + ": item " + std::to_string(item) + ": " + bad +
                               " (a comma-separated list of numbers in " + rule.unit + ")");
    out.push_back(v);
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return out;
}

namespace assess::cli::option_rules {
const NumberRule threads{"threads", 1.0, 4096.0, false, false, "worker threads; leave --threads out for all cores"};
const NumberRule seed{"-", 0.0, 18446744073709551615.0, false, false, "a 64-bit unsigned integer"};
}  // namespace assess::cli::option_rules

namespace {

// The name among `names` nearest to `typed` (Levenshtein, json_input.hpp), if near enough to be a typo.
std::string nearest(const std::string& typed, const std::vector<std::string>& names) {
  std::string best;
  std::size_t d = std::string::npos;
  for (const std::string& n : names) {
    const std::size_t e = assess::edit_distance(typed, n);
    if (e < d) d = e, best = n;
  }
  return d <= std::max<std::size_t>(2, typed.size() / 3) ? best : "";
}

// Issue 41: a mistyped subcommand or option names the nearest one, before
// CLI11 reads the line (which said only "A subcommand is required" for
// `assess rnu`, and for `run --htm r.html` complained that the case file
// r.html does not exist). InputError (exit 2).
void check_words(CLI::App& app, int argc, char** argv) {
  CLI::App* at = &app;
  std::string path = "assess";
  bool subcommand_seen = false;
  for (int i = 1; i < argc; ++i) {
    const std::string w = argv[i];
    if (w == "--") break;
    std::vector<std::string> subs;
    for (CLI::App* s : at->get_subcommands({})) subs.push_back(s->get_name());
    if (w.rfind("--", 0) == 0 && w.size() > 2 && std::isalpha(static_cast<unsigned char>(w[2]))) {
      const std::string name = w.substr(2, w.find('=') == std::string::npos ? std::string::npos : w.find('=') - 2);
      std::vector<std::string> names;
      for (const CLI::App* a = at; a; a = a->get_parent())
        for (const CLI::Option* o : a->get_options())
          for (const std::string& l : o->get_lnames()) names.push_back(l);
      if (std::find(names.begin(), names.end(), name) != names.end()) continue;
      const std::string near = nearest(name, names);
      throw assess::InputError("unknown option --" + name + " for `" + path + "`" +
                               (near.empty() ? "" : "; did you mean --" + near + "?") + " (`" + path +
                               " --help` lists its options)");
    }
    if (w[0] == '-') continue;
    if (std::find(subs.begin(), subs.end(), w) != subs.end()) {
      at = at->get_subcommand(w);
      path += " " + w;
      subcommand_seen = true;
      continue;
    }
    // A word where a subcommand is required: the first one, or the word after a command that has subcommands.
    if (!subs.empty() && (!subcommand_seen || at->get_require_subcommand_min() > 0)) {
      const std::string near = nearest(w, subs);
      std::string list;
      for (const std::string& s : subs) list += (list.empty() ? "" : ", ") + s;
      throw assess::InputError("unknown command '" + w + "' for `" + path + "`" +
                               (near.empty() ? "" : "; did you mean '" + near + "'?") + " (commands: " + list + ")");
    }
  }
}

}  // namespace

void assess::cli::print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << "assess: warning: " << assess::plain_numbers(w) << "\n";
}

int main(int argc, char** argv) {
  // Before any thread starts: SIGINT, SIGTERM and SIGHUP stop the programs
  // this run started and remove its temporaries; a write beyond `ulimit -f`
  // is a full disk, not SIGXFSZ (support/termination.hpp, issue 39).
  assess::install_termination_handling();
  CLI::App app{
      "assess: out-of-plane seismic assessment of masonry walls\n"
      "(NTC 2018 / Circolare 2019 spectra, kinematic checks, rocking dynamics)"};
  // "Usage: assess ..." whatever path the program was started from (help2man
  // builds the man page from this text).
  app.name("assess");
  app.set_version_flag("--version", std::string("assess ") + assess::version());
  app.require_subcommand(1);
  assess::cli::add_spectrum_command(app);
  assess::cli::add_kinematic_command(app);
  assess::cli::add_rocking_command(app);
  assess::cli::add_case_dynamic_command(app);
  assess::cli::add_run_command(app);
  assess::cli::add_campaign_command(app);
  assess::cli::add_fragility_command(app);
  assess::cli::add_records_command(app);
  // One example per subcommand (paths relative to the source tree or to
  // share/assess of an installed copy).
  const std::map<std::string, std::string> examples{
      {"spectrum", "assess spectrum --comune \"L'Aquila\" --soil B --limit-state SLV"},
      {"kinematic", "assess kinematic mechanisms/two_storey_facade.json"},
      {"rocking", "assess rocking --model rigid --thickness 0.5 --height 4 --unit-weight 18 --record "
                   "spectra/records/RSN285_ITALY_A-BAG000.AT2"},
      {"run", "assess run mechanisms/church-facade.json --lang it --html relazione.html --pdf relazione.pdf\n"
              "  assess run mechanisms/building-house.json --html casa.html   (a whole building)"},
      {"campaign", "assess campaign mechanisms/campaign-seed-3.2.json --out results --threads 2"},
      {"records", "assess records select --lat 43.44 --lon 12.64 --soil C --count 7"},
      {"fragility", "assess fragility mechanisms/church-facade.json --out church.fragility"},
  };
  std::string all = "Examples:\n";
  for (CLI::App* sub : app.get_subcommands({})) {
    const auto it = examples.find(sub->get_name());
    if (it == examples.end()) continue;
    sub->footer("Example:\n  " + it->second + "\n");
    all += "  " + it->second + "\n";
  }
  app.footer(all + "\nReport bugs and read the documentation at docs/README.md (installed in share/doc/assess).");
  // Every number option of every subcommand: a finite decimal number, never
  // "nan", "inf", a hexadecimal float or a subnormal (issue 31: --k nan was
  // taken for "no --k").
  assess::cli::require_finite_numbers(app);
  // Every subcommand's options in one page (the man page is built from it;
  // CLI11 would first ask for the required subcommand).
  app.set_help_all_flag("--help-all", "print the help of every subcommand");
  if (argc == 2 && std::string(argv[1]) == "--help-all") {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  }
  try {
    check_words(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // An option's value or a missing argument: the same "assess: error: "
    // line as every other input error (the Python module raises its text).
    std::cerr << "assess: error: " << assess::plain_numbers(e.what()) << "\n";
    return assess::cli::exit_input_error;
  } catch (const assess::InputError& e) {
    std::cerr << "assess: error: " << assess::plain_numbers(e.what()) << "\n";
    return assess::cli::exit_input_error;
  } catch (const assess::SystemError& e) {
    // A failure of the machine (disk full, I/O error): exit status 1.
    std::cerr << "assess: error: " << assess::plain_numbers(e.what()) << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "assess: error: out of memory (the input asks for more memory than the machine has)\n";
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // Every output goes through write_output_file; a file-system call left
    // elsewhere still names its paths and the system's reason.
    std::cerr << "assess: error: " << e.path1().string() << (e.path2().empty() ? "" : " -> " + e.path2().string())
              << ": " << e.code().message() << "\n";
    return assess::cli::exit_input_error;
  } catch (const std::exception& e) {
    std::cerr << "assess: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

// assess: command-line front end of libassess.
#include "commands.hpp"

#include <assess/support/error.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/version.hpp>

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


void assess::cli::require_finite_numbers(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) -> std::string {
        std::string t = text;
        t.erase(0, t.find_first_not_of(" \t"));
        const std::string lower = [&] {
          std::string l;
          for (char c : t) l += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
          return l;
        }();
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (end == t.c_str()) return "";  // not a number at all: CLI11's own message
        if (lower.find("0x") != std::string::npos)
          return "must be a decimal number, got '" + text + "' (a hexadecimal float)";
        if (!std::isfinite(v)) return "must be a finite number, got '" + text + "'";
        if (assess::is_subnormal(v))
          return "must be a number of normal size, got '" + text + "' (a subnormal number, |x| < 2.2e-308)";
        return "";
      },
      "FINITE");
  std::function<void(CLI::App&)> walk = [&](CLI::App& a) {
    for (CLI::Option* o : a.get_options())
      if (o->get_type_name() == "FLOAT") o->check(finite);
    for (CLI::App* sub : a.get_subcommands({})) walk(*sub);
  };
  walk(app);
}

void assess::cli::check_number_option(const char* option, double value, const assess::NumberRule& rule) {
  const std::string bad = assess::number_rule_violation(value, rule);
  if (!bad.empty()) throw assess::InputError(std::string(option) + ": " + bad);
}


void assess::cli::print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << "assess: warning: " << assess::plain_numbers(w) << "\n";
}

int main(int argc, char** argv) {
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : assess::cli::exit_input_error;
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

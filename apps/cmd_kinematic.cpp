// cmd_kinematic.cpp: `assess kinematic CASE.json [--json]`: linear and
// non-linear kinematic analysis of the case's mechanism and the checks of
// NTC 2008 / NTC 2018. Parses, calls the library, prints.
#include "commands.hpp"

#include <assess/assessment/building_case.hpp>
#include <assess/assessment/case_file.hpp>
#include <assess/support/json_input.hpp>
#include <assess/report/kinematic_report.hpp>
#include <assess/assessment/tie_intervention.hpp>
#include <assess/report/tie_report.hpp>
#include <assess/risk/run_report.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace assess::cli {
namespace {

struct KinematicArgs {
  std::string file;
  bool json = false, wide = false;
};

void run(const KinematicArgs& a) {
  const nlohmann::json doc = read_json_file(a.file, input_kinds::case_file);
  if (is_building_document(doc))
    throw InputError(a.file + ": a building case (key \"walls\"): `assess run " + a.file +
                     "` analyses and checks its mechanisms; `assess kinematic` takes a single-mechanism case "
                     "(`assess run " + a.file + " --expand DIR` writes each mechanism's; docs/user/building.md)");
  const CaseFile c = parse_case(doc, a.file);
  const KinematicCaseResult out = run_kinematic_case(c);  // alpha0 <= 0: InputError "statically unstable"
  print_warnings(out.warnings);
  // Issue 23: ties before/after and their checks (they need the site's hazard).
  std::vector<std::string> tie_warnings;
  const std::optional<TieInterventionResult> ties = kinematic_ties(c, tie_warnings);
  print_warnings(tie_warnings);
  if (a.json) {
    nlohmann::json j = kinematic_run_json(c, out, ties);
    std::cout << stamp_version(j).dump(2) << "\n";
  } else {
    std::cout << kinematic_text(c, out, a.wide ? TextWidth::wide : TextWidth::columns120);
    if (ties) std::cout << tie_text(*ties);
    if (!out.warnings.empty()) {
      std::cout << "\nwarnings:\n";
      for (const std::string& w : out.warnings)
        std::cout << (a.wide ? "  " + w : wrap_text("  " + w, 4)) << "\n";
    }
  }
}

}  // namespace

void add_kinematic_command(CLI::App& app) {
  auto args = std::make_shared<KinematicArgs>();
  auto* cmd = app.add_subcommand("kinematic",
                                 "linear and non-linear kinematic analysis of a local mechanism and its NTC checks");
  cmd->add_option("case", args->file, "case file (JSON, see docs/user/case-file.md)")->required()->check(CLI::ExistingFile);
  cmd->add_flag("--json", args->json, "print the results as JSON");
  cmd->add_flag("--wide", args->wide, "one line per table row however long (default: tables within 120 columns)");
  cmd->callback([args] { run(*args); });
}

}  // namespace assess::cli

// commands.hpp: the subcommands of the assess tool, one file each.
// Each add_*_command registers its options and a callback that parses,
// calls the library and prints; errors propagate as assess::InputError.
#pragma once

#include <CLI/CLI.hpp>
#include <assess/support/version.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace assess {
struct NumberRule;
}

namespace assess::cli {

void add_spectrum_command(CLI::App& app);   // cmd_spectrum.cpp
void add_kinematic_command(CLI::App& app);  // cmd_kinematic.cpp
void add_rocking_command(CLI::App& app);    // cmd_rocking.cpp
void add_case_dynamic_command(CLI::App& app);  // cmd_rocking.cpp: `assess dynamic CASE --record FILE`
void add_run_command(CLI::App& app);        // cmd_run.cpp
void add_campaign_command(CLI::App& app);   // cmd_campaign.cpp
void add_fragility_command(CLI::App& app);  // cmd_fragility.cpp
void add_records_command(CLI::App& app);    // cmd_records.cpp

/// Exit code for invalid input (InputError) and for a failed check of the
/// command line.
inline constexpr int exit_input_error = 2;

/// Prints warnings on stderr, one per line ("assess: warning: ...").
void print_warnings(const std::vector<std::string>& warnings);

/// Adds to every floating-point option of `app` and its subcommands (CLI11
/// type name FLOAT) a check that its value is a finite decimal number: "nan",
/// "inf", "0x1p-3" and subnormals (1e-320) are refused with the option's
/// name ("--k: must be a finite number, got 'nan'"), exit status 2 (main.cpp).
void require_finite_numbers(CLI::App& app);

/// InputError "<option>: <what is wrong>" when `value` breaks `rule`
/// (support/number_rules.hpp), e.g. "--tr: value 1e+308 out of range:
/// expected in [1, 1e+06] years".
void check_number_option(const char* option, double value, const NumberRule& rule);

}  // namespace assess::cli

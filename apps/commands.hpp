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

/// Adds to every number option of `app` and its subcommands (CLI11 type
/// names FLOAT, INT, UINT) a check that its value is a finite decimal number
/// (decimal_number_violation): "nan", "inf", "0x1p-3", "0x10" and subnormals
/// (1e-320) are refused with the option's name ("--k: must be a finite
/// number, got 'nan'"), exit status 2 (main.cpp). Each option's range is
/// its own (with_rule).
void require_finite_numbers(CLI::App& app);

/// Declares the range of a number option (issue 39: every option with its
/// range and reason): its text must be a decimal number (decimal_number_violation)
/// obeying `rule`, checked as the command line is parsed, before any file is
/// read ("--near-fault-km: value -1 out of range: expected in [0, 100] km
/// (...)"). tests/cli/scripts/option_ranges.py gives every number option of
/// every subcommand values beyond any range and expects this refusal.
CLI::Option* with_rule(CLI::Option* option, const NumberRule& rule);

/// The numbers of a comma-separated list option ("30,475,2475"), each a
/// decimal number obeying `rule`: InputError "--stripes: item 2: value 10 out
/// of range: expected in [30, 2475] years (...)", "--periods: item 1:
/// expected a number, got 'abc' (a comma-separated list of numbers in s)".
std::vector<double> parse_number_list(const std::string& text, const char* option, const NumberRule& rule);

/// The ranges of options that have no quantity of the library behind them.
namespace option_rules {
/// --threads: worker threads (the default, all cores, when not given).
extern const NumberRule threads;
/// --seed of a bootstrap: any 64-bit unsigned integer.
extern const NumberRule seed;
}  // namespace option_rules

}  // namespace assess::cli

// commands.hpp: the subcommands of the assess tool, one file each.
// Each add_*_command registers its options and a callback that parses,
// calls the library and prints; errors propagate as assess::InputError.
#pragma once

#include <CLI/CLI.hpp>

namespace assess::cli {

void add_spectrum_command(CLI::App& app);   // cmd_spectrum.cpp
void add_kinematic_command(CLI::App& app);  // cmd_kinematic.cpp
void add_rocking_command(CLI::App& app);    // cmd_rocking.cpp
void add_run_command(CLI::App& app);        // cmd_run.cpp
void add_campaign_command(CLI::App& app);   // cmd_campaign.cpp
void add_fragility_command(CLI::App& app);  // cmd_fragility.cpp

/// Exit code for invalid input (InputError) and for a failed check of the
/// command line.
inline constexpr int exit_input_error = 2;

}  // namespace assess::cli

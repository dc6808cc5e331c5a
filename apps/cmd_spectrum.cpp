// cmd_spectrum.cpp: placeholder until the spectrum subcommand lands.
#include "commands.hpp"

#include <assess/error.hpp>

namespace assess::cli {

void add_spectrum_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("spectrum", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([] { throw InputError("the 'spectrum' command is not available yet in this build"); });
}

}  // namespace assess::cli

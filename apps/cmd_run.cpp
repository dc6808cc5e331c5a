// cmd_run.cpp: placeholder until the run subcommand lands.
#include "commands.hpp"

#include <assess/error.hpp>

namespace assess::cli {

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([] { throw InputError("the 'run' command is not available yet in this build"); });
}

}  // namespace assess::cli

// cmd_rocking.cpp: placeholder until the rocking subcommand lands.
#include "commands.hpp"

#include <assess/error.hpp>

namespace assess::cli {

void add_rocking_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("rocking", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([] { throw InputError("the 'rocking' command is not available yet in this build"); });
}

}  // namespace assess::cli

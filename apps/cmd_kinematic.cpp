// cmd_kinematic.cpp: placeholder until the kinematic subcommand lands.
#include "commands.hpp"

#include <assess/error.hpp>

namespace assess::cli {

void add_kinematic_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("kinematic", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([] { throw InputError("the 'kinematic' command is not available yet in this build"); });
}

}  // namespace assess::cli

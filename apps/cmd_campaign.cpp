// cmd_campaign.cpp: placeholder until the campaign subcommand lands.
#include "commands.hpp"

#include <assess/error.hpp>

namespace assess::cli {

void add_campaign_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("campaign", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([] { throw InputError("the 'campaign' command is not available yet in this build"); });
}

}  // namespace assess::cli

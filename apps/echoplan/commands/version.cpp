#include <fmt/core.h>

#include "commands/commands.h"

namespace echoplan::cli {

void add_version_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the echoplan version");
  cmd->callback([] { fmt::print("echoplan {}\n", ECHOPLAN_VERSION); });
}

}  // namespace echoplan::cli

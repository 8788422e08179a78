// `echoplan merge`: join the shard folders of one campaign (`echoplan experiment --shard I/N`) into
// one report, identical to the folder an unsharded run writes.
#include <fmt/core.h>

#include "commands/commands.h"
#include "experiment/campaign.h"

namespace echoplan::cli {

void add_merge_command(CLI::App& app) {
  struct Flags {
    std::string out;
    std::vector<std::string> shards;
  };
  auto flags = std::make_shared<Flags>();
  auto* cmd = app.add_subcommand(
      "merge",
      "Join the shard folders of one campaign into one report (the same files an unsharded\n"
      "`echoplan experiment` writes). Example: echoplan merge --out results/chapter5 shards/*");
  cmd->add_option("--out", flags->out, "Folder for the joined campaign and its report")->required();
  cmd->add_option("SHARD_DIR", flags->shards,
                  "Shard folders written by `echoplan experiment --shard I/N`")
      ->required();
  cmd->callback([flags] {
    std::vector<std::filesystem::path> shards(flags->shards.begin(), flags->shards.end());
    const std::string summary = experiment::merge_campaigns(flags->out, shards);
    fmt::print("{}\nreport: {}/index.html\n", summary, flags->out);
  });
}

}  // namespace echoplan::cli

// sfcv plan: the work units of `sfcv check` with the same arguments (each property, each
// standard check) and their estimated costs, as JSON; with --shard I/N (N is what counts) the
// shard each unit goes to (docs/distributed.md). The units come from the check command's own
// pipeline (cmd_check.cpp, CheckMode::Plan), so plan and check cannot disagree.

#include "cli/check_shards.hpp"
#include "cli/commands.hpp"

namespace sfcv::cli {

void add_plan_command(CLI::App& app, CommandRunner& selected) {
  add_check_like_command(app, selected, CheckMode::Plan);
}

}  // namespace sfcv::cli

#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// What `sfcv check --shard`, `sfcv plan` and `sfcv merge` share with `sfcv check`
// (docs/distributed.md): plan and check take the same arguments, and merge renders through the
// check command itself, with the shards' answers in place of an engine run, so that its reports
// are those of a single run by construction.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "logic/check_result.hpp"
#include "logic/work_units.hpp"
#include "report/provenance.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::cli {

/// `sfcv check` runs the engines; `sfcv plan` stops at the work units and prints them.
enum class CheckMode { Check, Plan };

/// Registers `check` (or `plan`, with the same options) on `app` (cmd_check.cpp).
void add_check_like_command(CLI::App& app, CommandRunner& selected, CheckMode mode);

/// The shard of this run: which units it covers (docs/distributed.md).
struct ShardRun {
  std::optional<logic::ShardSpec> spec;  ///< unset without --shard
  bool diversify = false;
  std::vector<logic::WorkUnit> units;    ///< every unit of the run
  std::vector<logic::WorkUnit> covered;  ///< those this shard runs
  /// --diversify with --engine bmc: the depths this shard tries (BMC depth ranges).
  std::uint32_t min_depth = 0;
  std::uint32_t max_depth = 0;
};

/// Parses --shard and --diversify against the run's units (exit 2 for a bad I/N, or
/// --diversify without --shard or with an engine that has no diversified search).
ShardRun plan_shard(const std::vector<logic::WorkUnit>& units, const std::string& shard,
                    bool diversify, const std::string& engine, std::uint32_t depth);

/// `sfcv plan`: the units, their costs and shards as JSON on standard output; returns 0.
int print_plan(const std::vector<logic::WorkUnit>& units, const std::string& shard);

/// The answers `sfcv merge` hands to the check command in place of an engine run, and the
/// provenance of the run they stand for.
struct StoredRun {
  logic::CheckReport report;
  report::Provenance provenance;
  bool diversified = false;  ///< a swarm: every counterexample is replayed before it is shown
};
/// Set by merge before it runs the check command; null otherwise.
const StoredRun* stored_run();
void set_stored_run(const StoredRun* run);

/// Replays every trace of `report` on `ts` (logic/trace_replay.hpp): a trace from another
/// process is shown only if the semantics follows it; one that does not is an internal error
/// (exit 4) naming the property, never a verdict.
void replay_stored_traces(const logic::CheckReport& report, const semantics::TransitionSystem& ts);

}  // namespace sfcv::cli

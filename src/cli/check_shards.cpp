#include "cli/check_shards.hpp"

#include <iostream>

#include "cli/exit_code.hpp"
#include "logic/trace_replay.hpp"
#include "report/shard_result.hpp"

namespace sfcv::cli {

namespace {
const StoredRun* g_stored = nullptr;
}  // namespace

const StoredRun* stored_run() {
  return g_stored;
}

void set_stored_run(const StoredRun* run) {
  g_stored = run;
}

void replay_stored_traces(const logic::CheckReport& report, const semantics::TransitionSystem& ts) {
  for (const auto& r : report.results)
    if (r.trace)
      if (const auto why = logic::replay_failure(ts, *r.trace))
        throw InternalError("sfcv merge: the trace of '" + r.name +
                            "' from a shard does not replay on the model: " + *why);
}

ShardRun plan_shard(const std::vector<logic::WorkUnit>& units, const std::string& shard,
                    bool diversify, const std::string& engine, std::uint32_t depth) {
  ShardRun run;
  run.units = units;
  run.covered = units;
  if (shard.empty()) {
    if (diversify) throw UsageError("--diversify needs --shard I/N (docs/distributed.md)");
    return run;
  }
  std::string why;
  run.spec = logic::parse_shard(shard, &why);
  if (!run.spec) throw UsageError(why);
  run.diversify = diversify;
  if (!diversify) {
    run.covered = logic::shard_units(units, *run.spec);
    return run;
  }
  // A swarm: every shard asks every question, each in its own part of the search. BMC splits
  // its depths 0..depth into N consecutive ranges; the other engines have no knob yet.
  if (engine != "bmc")
    throw UsageError(
        "--diversify: only --engine bmc has a diversified search yet (depth ranges; "
        "docs/distributed.md), not --engine " +
        engine);
  const std::uint64_t n = run.spec->count, i = run.spec->index;
  run.min_depth = static_cast<std::uint32_t>((i - 1) * (std::uint64_t{depth} + 1) / n);
  run.max_depth = static_cast<std::uint32_t>(i * (std::uint64_t{depth} + 1) / n);
  run.max_depth = run.max_depth > 0 ? run.max_depth - 1 : 0;
  if (run.max_depth < run.min_depth)
    throw UsageError("--diversify: --depth " + std::to_string(depth) + " has fewer depths than " +
                     std::to_string(n) + " shards");
  return run;
}

int print_plan(const std::vector<logic::WorkUnit>& units, const std::string& shard) {
  std::uint32_t count = 1;
  if (!shard.empty()) {
    std::string why;
    const auto spec = logic::parse_shard(shard, &why);
    if (!spec) throw UsageError(why);
    count = spec->count;
  }
  std::uint64_t total = 0;
  for (const auto& u : units) total += u.cost;
  nlohmann::json j = {
      {"shards", count}, {"total_cost", total}, {"units", report::units_json(units, count)}};
  std::cout << j.dump(2) << "\n";
  return kHolds;
}

}  // namespace sfcv::cli

#pragma once
// The work units of a `sfcv check` run and their split into shards (docs/distributed.md): each
// property and each standard check is one unit, with a deterministic cost estimate (no clock,
// no machine: the same task gives the same units and costs everywhere), so that N processes on
// N machines, each given the same command line and `--shard I/N`, agree on who runs what.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "logic/check_task.hpp"

namespace sfcv::logic {

struct WorkUnit {
  /// "property/3" (the fourth property, in the order given) or "check/reachable": unique in the
  /// run, stable for the same command line.
  std::string id;
  std::string kind;       ///< "property" or "check"
  std::string name;       ///< the property's name (its text when given on the command line)
  std::size_t index = 0;  ///< into CheckTask::properties, or CheckTask::checks
  /// Relative cost: a weight for the question's kind (an invariant 2, a reachability 2, a
  /// nested CTL formula more with each temporal operator, LTL four times a CTL formula of its
  /// size, fairness twice) times the state bits of the system. Only the ratios matter.
  std::uint64_t cost = 0;
};

/// The units of `task` before vacuity questions are added: its properties in order, then its
/// standard checks in order (the order of the results of a single run).
std::vector<WorkUnit> work_units(const CheckTask& task);

/// A shard "I/N" (1 <= I <= N).
struct ShardSpec {
  std::uint32_t index = 1;
  std::uint32_t count = 1;
};

/// Parses "I/N"; nullopt with `error` set (naming what is wrong) for "0/4", "5/4", "x", "1/0".
std::optional<ShardSpec> parse_shard(const std::string& text, std::string* error);

/// Which shard (0-based) runs each unit: longest processing time first (units by decreasing
/// cost, ties by position), each to the least loaded shard (ties to the lowest index).
/// Deterministic; every unit goes to exactly one shard.
std::vector<std::uint32_t> assign_shards(const std::vector<WorkUnit>& units, std::uint32_t count);

/// The units shard `spec` runs, in the order of `units`.
std::vector<WorkUnit> shard_units(const std::vector<WorkUnit>& units, const ShardSpec& spec);

/// Keeps in `task` only the properties and checks of `units` (a subset of work_units(task)).
void restrict_task(CheckTask& task, const std::vector<WorkUnit>& units);

}  // namespace sfcv::logic

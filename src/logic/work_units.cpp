#include "logic/work_units.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>

namespace sfcv::logic {

namespace {

/// Temporal operators on the longest path from the root: nesting is what makes CTL costly.
std::uint32_t temporal_depth(const Formula& f) {
  std::uint32_t deepest = 0;
  for (const auto& a : f.args)
    if (a) deepest = std::max(deepest, temporal_depth(*a));
  return deepest + (is_temporal(f.op) ? 1 : 0);
}

std::uint64_t property_weight(const Formula& f, bool fair) {
  std::uint64_t w = 0;
  if (is_ltl(f))
    w = 8 + 4 * temporal_depth(f);  // a tableau product, then fair cycles
  else if ((f.op == Op::AG || f.op == Op::EF) && f.args.size() == 1 && f.args[0] &&
           is_propositional(*f.args[0]))
    w = 2;  // one reachability question, decided on the fly by several engines
  else
    w = 2 + 3 * temporal_depth(f);
  return fair ? 2 * w : w;
}

std::uint64_t check_weight(StandardCheck c) {
  switch (c) {
    case StandardCheck::Reachable:
    case StandardCheck::DeadTransitions:
    case StandardCheck::StoredActions:
    case StandardCheck::OutputConflicts:
    case StandardCheck::Conflicts:
    case StandardCheck::OrderDependence:
      return 2;  // one pass over the reached states or edges
    case StandardCheck::GlobalDeadlock:
    case StandardCheck::InitialReturn:
      return 3;  // a backward fixpoint
    case StandardCheck::Reentry:
    case StandardCheck::LocalDeadlock:
    case StandardCheck::Instability:
      return 5;  // one fixpoint per step, or cycles of transient evolutions
  }
  return 3;
}

}  // namespace

std::vector<WorkUnit> work_units(const CheckTask& task) {
  const std::uint64_t size =
      task.system ? std::max<std::uint32_t>(1, task.system->layout().bits()) : 1;
  const bool fair = !task.fairness.empty();
  std::vector<WorkUnit> units;
  for (std::size_t i = 0; i < task.properties.size(); ++i) {
    const auto& p = task.properties[i];
    units.push_back({"property/" + std::to_string(i), "property", p.name, i,
                     (p.formula ? property_weight(*p.formula, fair) : 2) * size});
  }
  for (std::size_t i = 0; i < task.checks.size(); ++i) {
    const auto name = std::string(to_string(task.checks[i]));
    units.push_back({"check/" + name, "check", name, i, check_weight(task.checks[i]) * size});
  }
  return units;
}

std::optional<ShardSpec> parse_shard(const std::string& text, std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<ShardSpec> {
    if (error) *error = "bad --shard '" + text + "': " + why;
    return std::nullopt;
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) return fail("expected I/N, e.g. 2/4");
  auto number = [](std::string_view s, std::uint32_t& out) {
    if (s.empty()) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
  };
  ShardSpec spec;
  const std::string_view all(text);
  if (!number(all.substr(0, slash), spec.index) || !number(all.substr(slash + 1), spec.count))
    return fail("expected I/N with two whole numbers, e.g. 2/4");
  if (spec.count == 0) return fail("N must be at least 1");
  if (spec.index == 0) return fail("shards are numbered from 1 (1/N to N/N)");
  if (spec.index > spec.count)
    return fail("I must not exceed N (shards 1/" + std::to_string(spec.count) + " to " +
                std::to_string(spec.count) + "/" + std::to_string(spec.count) + ")");
  return spec;
}

std::vector<std::uint32_t> assign_shards(const std::vector<WorkUnit>& units, std::uint32_t count) {
  std::vector<std::uint32_t> shard(units.size(), 0);
  if (count <= 1) return shard;
  std::vector<std::size_t> order(units.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return units[a].cost > units[b].cost; });
  std::vector<std::uint64_t> load(count, 0);
  for (const auto u : order) {
    const auto least = static_cast<std::uint32_t>(std::min_element(load.begin(), load.end()) -
                                                  load.begin());  // first of the least
    shard[u] = least;
    load[least] += units[u].cost;
  }
  return shard;
}

std::vector<WorkUnit> shard_units(const std::vector<WorkUnit>& units, const ShardSpec& spec) {
  const auto shard = assign_shards(units, spec.count);
  std::vector<WorkUnit> mine;
  for (std::size_t i = 0; i < units.size(); ++i)
    if (shard[i] + 1 == spec.index) mine.push_back(units[i]);
  return mine;
}

void restrict_task(CheckTask& task, const std::vector<WorkUnit>& units) {
  std::vector<Property> properties;
  std::vector<StandardCheck> checks;
  for (const auto& u : units) {
    if (u.kind == "property")
      properties.push_back(task.properties.at(u.index));
    else
      checks.push_back(task.checks.at(u.index));
  }
  task.properties = std::move(properties);
  task.checks = std::move(checks);
}

}  // namespace sfcv::logic

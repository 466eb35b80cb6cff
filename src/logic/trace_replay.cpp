#include "logic/trace_replay.hpp"

#include <algorithm>
#include <vector>

namespace sfcv::logic {

namespace {

/// Whether some successor (or initial state, `inputs` null) reaches `target`.
struct Finder final : semantics::SuccessorSink {
  const std::vector<semantics::StateWord>* target = nullptr;
  const std::vector<std::int64_t>* inputs = nullptr;
  bool found = false;
  std::vector<std::uint32_t> fired;  ///< of the successor found
  void successor(const semantics::Successor& s) override {
    if (found || !std::equal(s.target.begin(), s.target.end(), target->begin(), target->end()))
      return;
    found = !inputs || s.condition.holds(*inputs);
    if (found) fired.assign(s.fired.begin(), s.fired.end());
  }
};

/// The conditions and fired sets of every successor that reaches `target`.
struct Collect final : semantics::SuccessorSink {
  const std::vector<semantics::StateWord>* target = nullptr;
  std::vector<std::pair<semantics::InputCondition, std::vector<std::uint32_t>>> found;
  void successor(const semantics::Successor& s) override {
    if (std::equal(s.target.begin(), s.target.end(), target->begin(), target->end()))
      found.emplace_back(s.condition, std::vector<std::uint32_t>(s.fired.begin(), s.fired.end()));
  }
};

}  // namespace

std::optional<std::string> replay_failure(const semantics::TransitionSystem& ts,
                                          const Trace& trace) {
  if (trace.steps.empty()) return "the trace has no row";
  const auto words = ts.layout().words();
  for (std::size_t k = 0; k < trace.steps.size(); ++k)
    if (trace.steps[k].state.size() != words || trace.steps[k].inputs.size() != ts.inputs().size())
      return "row " + std::to_string(k) + " does not fit the system (another model or options?)";
  Finder init;
  init.target = &trace.steps.front().state;
  ts.initial_states(init);
  if (!init.found) return "its first row is not an initial situation";
  for (std::size_t k = 1; k < trace.steps.size(); ++k) {
    Finder next;
    next.target = &trace.steps[k].state;
    next.inputs = &trace.steps[k].inputs;
    ts.successors(trace.steps[k - 1].state, next);
    if (!next.found)
      return "row " + std::to_string(k) + ": no successor under its inputs reaches its state";
  }
  return std::nullopt;
}

void fire_as_replayed(const semantics::TransitionSystem& ts, Trace& trace) {
  const auto words = ts.layout().words();
  for (std::size_t k = 1; k < trace.steps.size(); ++k) {
    const auto& before = trace.steps[k - 1];
    auto& row = trace.steps[k];
    if (before.state.size() != words || row.inputs.size() != ts.inputs().size()) continue;
    Finder next;
    next.target = &row.state;
    next.inputs = &row.inputs;
    ts.successors(before.state, next);
    if (next.found) row.fired = std::move(next.fired);
  }
}

void minimise_input_changes(const semantics::TransitionSystem& ts, Trace& trace) {
  const auto words = ts.layout().words();
  for (std::size_t k = 1; k < trace.steps.size(); ++k) {
    const auto& before = trace.steps[k - 1];
    auto& row = trace.steps[k];
    if (before.state.size() != words || row.inputs.size() != ts.inputs().size() ||
        before.inputs.size() != row.inputs.size())
      continue;
    Collect next;
    next.target = &row.state;
    ts.successors(before.state, next);
    const auto reaches = [&](const std::vector<std::int64_t>& v) {
      return std::find_if(next.found.begin(), next.found.end(),
                          [&](const auto& c) { return c.first.holds(v); });
    };
    if (reaches(row.inputs) == next.found.end()) continue;  // replay_failure reports it
    for (std::size_t i = 0; i < row.inputs.size(); ++i) {
      if (row.inputs[i] == before.inputs[i]) continue;
      auto kept = row.inputs;
      kept[i] = before.inputs[i];
      if (reaches(kept) != next.found.end()) row.inputs = std::move(kept);
    }
    row.fired = reaches(row.inputs)->second;
  }
}

}  // namespace sfcv::logic

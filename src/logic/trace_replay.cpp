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
  void successor(const semantics::Successor& s) override {
    if (found || !std::equal(s.target.begin(), s.target.end(), target->begin(), target->end()))
      return;
    found = !inputs || s.condition.holds(*inputs);
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

}  // namespace sfcv::logic

#pragma once
// A run of the chart as data: a counterexample or a witness. Each step is one node of the
// graph (a configuration after a scan cycle, or a stable Grafcet situation) with the input
// valuation read on the way into it and the transitions fired. A lasso (AF/EG) repeats the
// state of steps[loop_start] as its last step, so the run continues forever from there.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "semantics/input_condition.hpp"
#include "semantics/state_layout.hpp"

namespace sfcv::logic {

struct TraceStep {
  std::vector<std::int64_t> inputs;  ///< values[i] of TransitionSystem::inputs()[i]
  std::vector<semantics::StateWord> state;
  std::vector<std::uint32_t> fired;  ///< transitions fired to get here (empty for step 0)
};

enum class TraceKind { Counterexample, Witness };

struct Trace {
  TraceKind kind = TraceKind::Counterexample;
  std::vector<TraceStep> steps;
  /// Lasso: the last step's state equals steps[*loop_start].state; the loop repeats forever.
  std::optional<std::size_t> loop_start;
  bool ends_in_deadlock = false;      ///< a finite maximal run: the last state has no successor
  std::vector<std::uint32_t> marked;  ///< observables of the property's atoms (shown marked)
  std::string note;                   ///< one line on how to read it
};

/// An input valuation inside `condition` that changes as few inputs as possible with respect to
/// `previous` (empty = none: inputs not constrained take their lowest value). A false condition
/// returns `previous` (or the lowest values).
std::vector<std::int64_t> pick_inputs(const semantics::InputCondition& condition,
                                      const std::vector<semantics::InputVariable>& inputs,
                                      const std::vector<std::int64_t>& previous);

/// pick_inputs over a condition given cube by cube (e.g. as successors are enumerated), without
/// keeping the cubes: pick() equals pick_inputs over every cube added, in order.
class InputPicker {
 public:
  InputPicker(const std::vector<semantics::InputVariable>& inputs,
              const std::vector<std::int64_t>& previous);
  void add(const semantics::InputCube& cube);
  /// No later cube can change the pick (one holds at the base valuation).
  bool settled() const { return best_changes_ == 0; }
  std::vector<std::int64_t> pick() const { return best_changes_ == kNone ? base_ : best_; }

 private:
  static constexpr std::size_t kNone = ~std::size_t{0};
  std::vector<std::int64_t> base_, best_;
  std::size_t best_changes_ = kNone;
};

}  // namespace sfcv::logic

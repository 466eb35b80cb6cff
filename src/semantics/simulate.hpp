#pragma once
// Following given inputs through a transition system, cycle by cycle (`sfcv simulate`, trace
// replay in `sfcv check`). Works for any TransitionSystem: in each cycle it takes the successor
// whose condition holds for that cycle's input valuation.

#include <cstdint>
#include <string>
#include <vector>

#include "semantics/transition_system.hpp"

namespace sfcv::semantics {

struct SimulationResult {
  /// states[0] is the start state; states[i] the configuration after cycle i.
  std::vector<std::vector<StateWord>> states;
  /// fired[i - 1]: the transitions fired in cycle i.
  std::vector<std::vector<std::uint32_t>> fired;
  bool ok = true;
  std::size_t failed_cycle = 0;  ///< 1-based cycle that had no successor (when !ok)
  std::string error;             ///< why (assumption violated, range error, ...)
};

/// Runs `inputs.size()` cycles from `start`; inputs[i][j] is the value of ts.inputs()[j] in
/// cycle i + 1. Stops at the first cycle with no successor (ok = false). When several
/// successors' conditions hold (a nondeterministic system), the first one is taken.
SimulationResult simulate(const TransitionSystem& ts, StateView start,
                          const std::vector<std::vector<std::int64_t>>& inputs);

/// The first initial state of `ts`.
std::vector<StateWord> first_initial_state(const TransitionSystem& ts);

}  // namespace sfcv::semantics

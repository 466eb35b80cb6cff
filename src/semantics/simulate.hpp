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

/// Grafcet (IEC 60848): one row per event. inputs[0] is the initial input valuation, under
/// which the initial situation is stabilised (states[0]); every later row is the input
/// valuation after one event, and states[i] the stable situation it leads to. A row that
/// changes nothing the grafcet reacts to keeps the situation (the RSG leaves such stuttering
/// implicit), unless `assumptions` is set, when it means the row violates an assumption.
/// Under `single_input_change`, a row that changes two inputs (pseudo-inputs, the delays'
/// elapses, aside) is an error: it is not an event of the RSG. fired[i - 1]: the
/// transitions cleared by event i, transient evolutions included.
SimulationResult simulate_events(const TransitionSystem& ts,
                                 const std::vector<std::vector<std::int64_t>>& inputs,
                                 bool single_input_change, bool assumptions = false);

/// The first initial state of `ts`.
std::vector<StateWord> first_initial_state(const TransitionSystem& ts);

}  // namespace sfcv::semantics

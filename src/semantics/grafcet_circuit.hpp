#pragma once
// One transient evolution of an IEC 60848 Grafcet (grafcet_system.cpp, docs/semantics.md
// Part 2) as a circuit over exactly the state bits of the explicit system. The BDD engine closes
// it symbolically into the relation between stable situations (engine/bdd/grafcet_closure.hpp).
//
// Latches, in order: one per bit of every StateLayout field (`field_latches`, value - lo, LSB
// first): the situation x of a micro-step (its input memory holds the inputs of the event);
// then `prev_latches`: a copy of the bits read under an edge (↑/↓ of steps, variables, delays,
// inputs), the situation before the micro-step. A latch's next function is one evolution:
// simultaneous clearing, forcing orders, enclosing steps, stored actions, delay phases; a
// prev latch's next function is its state latch (the current situation becomes the previous).
//
// The same latch literals are read as the SOURCE stable situation in `start_next`, the first
// situation of an event (input memory := the new inputs, running delays elapsed), whose prev
// copy is the source itself, so that input edges are seen in the first evolution only.

#include <vector>

#include "semantics/iec61131_circuit.hpp"

namespace sfcv::semantics {

struct GrafcetCircuit : TransitionCircuit {
  std::size_t num_state_latches = 0;  ///< latches [0, n) are the state bits
  /// prev_latches[k]: the state latch that prev latch n + k copies.
  std::vector<std::uint32_t> prev_of;
  /// Per state latch, over state latches (the source) and inputs: its value in the first
  /// situation of an event (input memory := inputs, elapse of running delays).
  std::vector<AigLit> start_next;
  /// Per state latch, over inputs only: its value in the initial situation before
  /// stabilisation, under the initial input valuation.
  std::vector<AigLit> initial_next;
  /// Per state latch, over state latches and inputs: its value in the emitted stable
  /// situation (continuous outputs computed; every other bit unchanged).
  std::vector<AigLit> final_next;
  AigLit event = Aig::kTrue;          ///< over source and inputs: the inputs form one event
  AigLit initial_event = Aig::kTrue;  ///< over inputs: a start valuation (no delay elapses)
  AigLit valid = Aig::kTrue;          ///< over state latches: every field value in its range
  AigLit stable = Aig::kFalse;        ///< one more evolution changes nothing
  /// range_error (inherited): this evolution raises an anomaly (forcing conflict, stored value
  /// out of range); fired (inherited): transitions cleared by this evolution.
  /// Inputs the closure must keep (read in evolutions, not stored in the input memory): their
  /// circuit input indices. The others only matter in start_next/event.
  std::vector<std::uint32_t> kept_inputs;
  std::size_t max_transient_steps = 10000;
};

/// `ts` must come from make_grafcet_system (throws std::invalid_argument otherwise). Throws
/// CircuitUnsupported for expressions the circuit cannot express (a product or quotient of
/// two non-constant values).
/// Past `deadline` it throws LimitReached(Time).
/// Past `max_memory_bytes` (0: none) of And-Inverter Graph it throws LimitReached(Memory).
GrafcetCircuit build_grafcet_circuit(const TransitionSystem& ts,
                                     std::optional<Deadline> deadline = std::nullopt,
                                     std::uint64_t max_memory_bytes = 0);

}  // namespace sfcv::semantics

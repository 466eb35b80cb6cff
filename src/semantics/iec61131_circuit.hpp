#pragma once
// The IEC 61131-3 scan cycle as a circuit (an Aig) over exactly the state bits of the explicit
// transition system: one latch per bit of every StateLayout field, one circuit input per bit of
// every (pseudo-)input. The BDD engine and the exports (AIGER, NuSMV, Promela) are built from
// it; differential tests check it against the explicit successor function.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "semantics/aig.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics {

struct TransitionCircuit {
  Aig aig;
  /// field_latches[f][k]: the latch holding bit k of layout field f (value - lo, LSB first).
  std::vector<std::vector<std::uint32_t>> field_latches;
  /// input_bits[i][k]: circuit input literal of bit k of input i (value - lo, LSB first).
  std::vector<BitVector> input_bits;
  /// Per observable of the system: its value as an encoded field (value - lo, LSB first) for
  /// integer variables, one literal for steps, actions and Boolean variables.
  std::vector<BitVector> observable_bits;
  std::vector<std::int64_t> observable_lo;
  std::vector<AigLit> fired;         ///< per transition of the system: it fires in this cycle
  AigLit allowed = Aig::kTrue;       ///< the inputs are in range and satisfy the assumptions
  AigLit range_error = Aig::kFalse;  ///< this cycle raises a range error (no successor)
  /// This cycle runs an ST loop to kMaxLoopIterations without its variables repeating (a part
  /// of range_error, under allowed): a limit of sfcv, not a finding, since the loop may still
  /// end (docs/semantics.md 1.9.1). An engine that cannot show it unreachable answers unknown
  /// where its verdict rests on the cut cycle; `loop_limit_where` names the loops.
  AigLit loop_limit = Aig::kFalse;
  std::string loop_limit_where;

  /// A cycle with a successor: allowed, without a range error (the step relation's guard).
  AigLit step_ok() { return aig.make_and(allowed, Aig::make_not(range_error)); }
  /// An allowed cycle that raises a range error or meets the loop bound: no successor.
  AigLit range_error_step() { return aig.make_and(allowed, range_error); }
  /// An allowed cycle that raises a range error and meets no loop bound: a finding.
  AigLit anomaly_step() { return aig.make_and(range_error_step(), Aig::make_not(loop_limit)); }
  /// The message of the unknown answers when a reachable cycle may meet the loop bound.
  std::string loop_limit_message() const {
    return "a loop (" + loop_limit_where + ") may run past " +
           "the bound kMaxLoopIterations (1000 iterations) without repeating its variables: "
           "it may still end, the verdict is unknown";
  }
};

/// A construct the circuit cannot express (a product of two variables, a division): the
/// message names it. Callers answer with a clear error, never a wrong model.
class CircuitUnsupported : public UnsupportedConstruct {
 public:
  using UnsupportedConstruct::UnsupportedConstruct;
};

/// `ts` must come from make_iec61131_system (throws std::invalid_argument otherwise).
/// Past `deadline` (the run's budget) it throws LimitReached(Time), past `max_memory_bytes`
/// (0: none) of And-Inverter Graph LimitReached(Memory).
using Deadline = std::chrono::steady_clock::time_point;
TransitionCircuit build_iec61131_circuit(const TransitionSystem& ts,
                                         std::optional<Deadline> deadline = std::nullopt,
                                         std::uint64_t max_memory_bytes = 0);

/// The packed state whose field values are the latch values `latches` (one bool per latch).
std::vector<StateWord> state_from_latches(const TransitionSystem& ts, const TransitionCircuit& c,
                                          const std::vector<bool>& latches);
/// The input valuation encoded by circuit input values `bits` (one bool per circuit input).
std::vector<std::int64_t> inputs_from_bits(const TransitionSystem& ts, const TransitionCircuit& c,
                                           const std::vector<bool>& bits);

}  // namespace sfcv::semantics

#pragma once
// The successor function compiled from the scan cycle's circuit (semantics/iec61131_circuit):
// its And-Inverter Graph, restricted to the cone of the next-state functions, the input range
// and assumption constraint and the range-error signal, levelised into a flat array of AND gates
// over 64-bit words. One evaluation runs the cycle for 64 input valuations at once, bit-parallel;
// the gates that read no input run once per state.
//
// Per state, a support pass finds the circuit inputs the cycle actually depends on in that state
// (an AND with a FALSE fan-in needs neither side), and only their valuations are enumerated, 64
// per pass. A state whose cycle depends on too many input bits (or on an input the interpreter
// would have to enumerate value by value, see SemanticsLimitError) falls back to the interpreted
// successor function, so the successors are always exactly those of TransitionSystem::successors.
// No semantic rule is written here: the circuit is the second copy of the semantics, held
// against the interpreter by its differential test, and this file only evaluates it.

#include <memory>

#include "engine/explicit/invariant_search.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::engine {

/// The compiled enumerator of an IEC 61131-3 system; null when `ts` is not one, its circuit
/// cannot be built (CircuitUnsupported), has more than 64 input bits or does not fit in the
/// run's memory budget (the interpreter then runs within it). Past the run's deadline, throws
/// LimitReached(Time). Not thread-safe.
std::unique_ptr<TargetEnumerator> make_compiled_enumerator(const semantics::TransitionSystem& ts,
                                                           const model::Budget& limits);

}  // namespace sfcv::engine

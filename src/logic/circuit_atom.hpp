#pragma once
// A propositional formula over observables as a literal of the system's circuit: the one
// mapping the BDD engine (as BDDs) and the SAT engines (as clauses) both use, so that an atom
// means the same in every engine built on the circuit.

#include "logic/formula.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::logic {

/// The circuit literal (over latches) of a propositional formula whose atoms are resolved; new
/// AND nodes are added to `circuit.aig` for comparisons. Throws std::invalid_argument for a
/// temporal operator.
semantics::AigLit circuit_literal(semantics::TransitionCircuit& circuit, const Formula& f);

/// The literal "observable `o` has value `value`" (FALSE when out of its encoded range).
semantics::AigLit observable_equals(semantics::TransitionCircuit& circuit, std::uint32_t o,
                                    std::int64_t value);

}  // namespace sfcv::logic

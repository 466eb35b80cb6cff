#pragma once
// LTL on the BDD engine: the product of the system with the generalised Büchi automaton of the
// negated property (logic/ltl_automaton.hpp, the tableau the explicit checker uses), kept
// symbolically as one set of system states per automaton node, and the fair EG true of Clarke,
// Grumberg and Hamaguchi on it (Emerson-Lei, one fairness set per acceptance set and per
// fairness constraint). A product state in that set and initial is the start of a
// counterexample; the lasso is cut out of the fixpoint by the Clarke-Grumberg-McMillan-Zhao loop
// search, as SymbolicCtl does for fair EG.
//
// The paths are those of the explicit checker (ltl_checker.hpp): a state without a successor
// repeats forever when `stutter` is set, and has no path at all otherwise (NuSMV's reading,
// docs/properties.md).

#include <optional>
#include <vector>

#include "engine/bdd/symbolic_ctl.hpp"
#include "engine/bdd/symbolic_system.hpp"
#include "logic/fwd.hpp"
#include "model/budget.hpp"

namespace sfcv::engine {

struct SymbolicLtlQuery {
  logic::FormulaPtr formula;                ///< LTL, resolved
  std::vector<logic::FormulaPtr> fairness;  ///< propositional, resolved
  bool stutter = true;                      ///< a state without a successor repeats forever
};

/// A run of `sys` from an initial state violating `q.formula` under the fairness constraints: a
/// lasso (loop_start set; consecutive equal states without a successor are a stutter), or
/// nullopt when every path from an initial state within `reached` satisfies it. `ctl` labels
/// the propositional subformulas. Time and memory limits throw LimitReached.
std::optional<SymbolicRun> symbolic_ltl_counterexample(SymbolicSystem& sys, SymbolicCtl& ctl,
                                                       const bdd::Bdd& reached,
                                                       const SymbolicLtlQuery& q,
                                                       const model::Budget& budget);

}  // namespace sfcv::engine

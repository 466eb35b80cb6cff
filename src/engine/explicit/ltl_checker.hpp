#pragma once
// Explicit LTL model checking (Vardi and Wolper): the negated property becomes a generalised
// Büchi automaton (logic/ltl_automaton.hpp); its product with the reachable situations graph is
// explored on the fly from the initial states, and Tarjan's SCC search looks for a reachable
// cycle meeting every acceptance set and every fairness constraint. One is a counterexample:
// a lasso (a prefix, then a loop repeated forever).
//
// Paths are infinite: a state without a successor (the assumptions exclude every input there)
// repeats forever, as Spin's stutter extension does, or, with DeadlockPaths::Drop, lies on no
// path at all, as NuSMV reads it (docs/properties.md). On an incomplete graph
// a lasso among the expanded states is still a real counterexample; otherwise the answer is
// unknown.

#include <vector>

#include "engine/explicit/ctl_checker.hpp"
#include "logic/check_result.hpp"
#include "logic/check_task.hpp"

namespace sfcv::engine {

/// Verdict and counterexample of the LTL property `p` on `checker`'s graph; `fairness` are the
/// task's (resolved, propositional) fairness constraints. The budget's time and memory limits
/// end in LimitReached (the graph was built within its state limit).
logic::PropertyResult check_ltl(CtlChecker& checker, const logic::Property& p,
                                const std::vector<logic::FormulaPtr>& fairness,
                                const model::Budget& budget,
                                logic::DeadlockPaths deadlocks = logic::DeadlockPaths::Stutter);

}  // namespace sfcv::engine

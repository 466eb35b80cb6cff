#pragma once
// CTL by fixpoints over a SymbolicSystem (EX, EU, EG; fairness by Emerson-Lei) and the
// explanation of a formula as a run, cut out of fixpoint approximants as NuSMV does: shortest
// EU paths from the backward onion rings of E[p U q], EG lassos by the Clarke-Grumberg-McMillan-
// Zhao loop search inside the EG set. The recursion follows CtlChecker::explain() of the
// explicit engine step for step, so both engines explain the same sub-formulas in the same order.
//
// Paths are maximal (a state without successor ends its paths) unless fairness constraints are
// given; then only infinite fair paths count (docs/semantics.md, Part 3), as the explicit engine.

#include <optional>
#include <unordered_map>
#include <vector>

#include "engine/bdd/symbolic_system.hpp"
#include "logic/fwd.hpp"

namespace sfcv::engine {

/// A run as concrete states (steps[k] is reached from steps[k - 1] in one cycle).
struct SymbolicRun {
  std::vector<std::vector<semantics::StateWord>> states;
  /// The last state repeats states[*loop_start]; the run loops from there.
  std::optional<std::size_t> loop_start;
  bool ends_in_deadlock = false;  ///< the last state has no successor (a finite maximal run)
};

class SymbolicCtl {
 public:
  using Bdd = bdd::Bdd;

  SymbolicCtl(SymbolicSystem& sys, std::vector<logic::FormulaPtr> fairness);

  /// The states satisfying `f` (resolved); memoised per formula node.
  Bdd sat(const logic::FormulaPtr& f);

  /// A run from one of `sources` explaining why `f` holds there: a witness for existential
  /// formulas (the counterexample of g is the witness of push_negation(g)). Empty when `f`
  /// holds at no source.
  SymbolicRun explain(const logic::FormulaPtr& f, const Bdd& sources);

 private:
  Bdd compute(const logic::Formula& f);
  Bdd fair_states() const;
  Bdd fair_and(const Bdd& s) const { return fair_sets_.empty() ? s : s & fair_; }
  Bdd ex(const Bdd& p);
  Bdd eu(const Bdd& p, const Bdd& q);
  Bdd eg(const Bdd& p);
  Bdd eg_fair(const Bdd& p);
  /// States with an infinite path through `p` (nu Y. p & EX Y), memoised.
  Bdd eg_infinite(const Bdd& p);

  using State = std::vector<semantics::StateWord>;
  /// A shortest run from a state of `sources` through `through` states to a `target` state,
  /// from the backward rings of E[through U target]: the states after the source (empty when
  /// the source is a target itself, and with `min_one_edge` at least one). A source need not
  /// be in `through`. Returns false when there is none; `start` is the source used.
  bool shortest(const Bdd& sources, const Bdd& through, const Bdd& target, bool min_one_edge,
                State& start, std::vector<State>& path);
  void explain_at(const logic::FormulaPtr& f, SymbolicRun& run, int depth);
  void explain_eu(const Bdd& through, const Bdd& target, const logic::FormulaPtr& then,
                  const Bdd& sources, SymbolicRun& run, int depth);
  void lasso(const logic::FormulaPtr& eg_formula, const Bdd& sources, SymbolicRun& run);
  /// From run.states.back() inside `region` (every state of it has a successor in it): a loop
  /// visiting every set of `fair`, closed in `run`.
  void close_loop(const Bdd& region, const std::vector<Bdd>& fair, SymbolicRun& run);

  SymbolicSystem& sys_;
  std::vector<logic::FormulaPtr> fairness_;
  std::vector<Bdd> fair_sets_;
  Bdd fair_;
  std::unordered_map<const logic::Formula*, Bdd> memo_;
  std::unordered_map<const logic::Formula*, Bdd> infinite_memo_;
  std::vector<logic::FormulaPtr> keep_;  ///< formulas made here, kept alive for the memo keys
  Bdd trace_sources_;                    ///< where explain_at starts when the run is empty
};

}  // namespace sfcv::engine

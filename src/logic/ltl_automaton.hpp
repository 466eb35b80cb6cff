#pragma once
// From an LTL formula to a generalised Büchi automaton that accepts exactly the infinite words
// (runs of the chart) satisfying it: the tableau of Gerth, Peled, Vardi and Wolper ("Simple
// on-the-fly automatic verification of linear temporal logic", 1995) on the negation normal
// form over X, U and R. The letters are states of the system; a node's label is a conjunction
// of propositional formulas that the state entering the node must satisfy (the maximal
// propositional subformulas, kept whole, so they are evaluated like CTL atoms).

#include <cstdint>
#include <vector>

#include "logic/fwd.hpp"
#include "model/budget.hpp"

namespace sfcv::logic {

struct BuchiNode {
  std::vector<FormulaPtr> label;  ///< all must hold in the state read on entering the node
  std::vector<std::uint32_t> successors;
  std::vector<std::uint32_t> accepting;  ///< the acceptance sets this node belongs to
};

struct BuchiAutomaton {
  std::vector<BuchiNode> nodes;
  std::vector<std::uint32_t> initial;
  /// A run is accepting when it visits each set 0..num_sets-1 infinitely often (one set per
  /// `a U b` subformula: no run may defer b forever); 0 sets: every infinite run accepts.
  std::uint32_t num_sets = 0;
};

/// The automaton of `f` (an LTL formula; its propositional subformulas are taken as letters).
/// The tableau can be exponential in the formula: `budget` bounds its time (LimitReached).
BuchiAutomaton ltl_to_buchi(const FormulaPtr& f, const model::Budget& budget = {});

}  // namespace sfcv::logic

#pragma once
// Explicit CTL model checking on a reachable situations graph, by the labelling algorithms:
// EX, EU backwards, EG by strongly connected components; the other operators by duality.
//
// Paths are the maximal paths of the graph: a state with no successor (all inputs excluded by
// the assumptions) ends its paths, so there EX p is false, AX p true, EG p = p, AF p = p.
// With fairness constraints F1..Fk (propositional), path quantifiers range over the fair paths
// only: infinite paths that visit every Fi infinitely often (fair states = E_fair G true).
//
// Unexpanded states of an incomplete graph are treated as having no successor; callers must
// not trust such answers (check_property() handles this).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/explicit/reachable_situation_graph.hpp"
#include "logic/check_result.hpp"
#include "logic/check_task.hpp"
#include "logic/fwd.hpp"

namespace sfcv::engine {

using StateSet = std::vector<std::uint8_t>;  ///< one flag per graph state

class CtlChecker {
 public:
  CtlChecker(const ReachableSituationGraph& graph, std::vector<logic::FormulaPtr> fairness = {});

  /// The states satisfying `f` (resolved); memoised per formula node.
  const StateSet& sat(const logic::FormulaPtr& f);
  /// States with a fair path (all states when there is no fairness constraint and no deadlock
  /// matters: without fairness every state has a maximal path).
  const StateSet& fair_states();
  bool has_fairness() const { return !fairness_.empty(); }

  /// Verdict and trace of one property on the graph (Unknown on an incomplete graph unless a
  /// reachable state already decides it: a violation of AG p, or a witness of EF p, p
  /// propositional).
  logic::PropertyResult check(const logic::Property& p);

  /// A run from one of `sources` explaining why `f` holds there (a witness for existential
  /// formulas; the counterexample of g is the witness of !g). Returns an empty trace when f
  /// holds at no source.
  logic::Trace explain(const logic::FormulaPtr& f, const std::vector<std::uint32_t>& sources);

  /// Shortest run from an initial state to `target` (BFS tree of the graph).
  logic::Trace path_to(std::uint32_t target);

  const ReachableSituationGraph& graph() const { return g_; }

 private:
  StateSet compute(const logic::Formula& f);
  StateSet ex(const StateSet& p);
  StateSet eu(const StateSet& p, const StateSet& q);
  StateSet eg(const StateSet& p);
  /// Per state: id of its SCC inside `mask` when that SCC is non-trivial and meets every fair
  /// set, else -1.
  std::vector<std::int32_t> good_sccs(const StateSet& mask);
  bool has_successor(std::uint32_t s) const { return g_.edges_end(s) > g_.edges_begin(s); }

  // Witness construction on (state, edge into it) pairs.
  struct Hop {
    std::uint32_t state;
    std::uint64_t edge;  ///< kNoEdge for the first
  };
  static constexpr std::uint64_t kNoEdge = ~std::uint64_t{0};
  /// BFS from `sources` through `allowed` states to a `target` state; with `min_one_edge` the
  /// path takes at least one edge. Returns the hops after the source (empty if none found) and
  /// sets `start` to the source used.
  std::vector<Hop> bfs(const std::vector<std::uint32_t>& sources, const StateSet& allowed,
                       const StateSet& target, bool min_one_edge, std::uint32_t& start,
                       bool& found);
  void explain_at(const logic::FormulaPtr& f, std::vector<Hop>& run, logic::Trace& trace,
                  int depth);
  void explain_eu(const StateSet& through, const StateSet& target, const logic::FormulaPtr& then,
                  const std::vector<std::uint32_t>& sources, std::vector<Hop>& run,
                  logic::Trace& trace, int depth);
  void lasso(const logic::FormulaPtr& p, const std::vector<std::uint32_t>& sources,
             std::vector<Hop>& run, logic::Trace& trace);
  logic::Trace to_trace(const std::vector<Hop>& run, logic::Trace base) const;

  const ReachableSituationGraph& g_;
  std::vector<logic::FormulaPtr> fairness_;
  std::vector<StateSet> fair_sets_;
  StateSet fair_;
  bool fair_computed_ = false;
  std::unordered_map<const logic::Formula*, StateSet> memo_;
  std::vector<logic::FormulaPtr> keep_;       ///< formulas created here, kept alive for memo_ keys
  std::vector<std::uint32_t> trace_sources_;  ///< where explain_at starts when the run is empty
};

}  // namespace sfcv::engine

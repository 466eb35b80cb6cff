#pragma once
// Evaluates compiled set queries (logic/query_compile.hpp) symbolically, with the same meaning
// as the explicit evaluator (engine/explicit/query_evaluator.hpp): a set of situations is a BDD
// over the current state variables inside the reachable set; a set of evolutions a BDD over
// (current, next) variables, one pair per explicit edge (the graph merges every input leading
// from x to x' into one edge); sets of steps stay explicit (they are few). Succ and Pred are
// fixpoints restricted to the given evolutions. Results convert back to explicit states and
// pairs, numbered in the canonical order (engine/state_order.hpp) by breadth-first depth.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include "engine/bdd/symbolic_system.hpp"
#include "logic/query_compile.hpp"
#include "model/dynamic_bitset.hpp"

namespace sfcv::engine {

using model::DynamicBitset;

/// A query or a system the symbolic evaluator cannot answer exactly (it never guesses).
/// (Its limits, --max-states and --timeout, are LimitReached.)
class SymbolicQueryError : public UnsupportedConstruct {
 public:
  using UnsupportedConstruct::UnsupportedConstruct;
};

/// A set of one sort: `bdd` for situations and evolutions, `steps` (observable ids) for steps.
struct SymbolicSet {
  logic::Sort sort = logic::Sort::Empty;
  bdd::Bdd bdd;
  DynamicBitset steps;
};

struct SymbolicQueryResult {
  logic::Sort sort = logic::Sort::Empty;
  SymbolicSet set;
  bool truth = false;
  std::int64_t number = 0;
  /// For a test `A = {}` / `A != {}`: the set A (as QueryResult::witness).
  std::optional<logic::Sort> witness_sort;
  SymbolicSet witness;
};

struct SymbolicQueryOptions {
  double timeout_seconds = 0;    ///< 0 = unlimited (reachability; then SymbolicQueryError)
  std::uint64_t max_states = 0;  ///< 0 = unlimited
};

class SymbolicQueryEvaluator {
 public:
  /// Computes the reachable situations (breadth-first layers) and the evolutions between them.
  /// Throws SymbolicQueryError when a limit is reached.
  explicit SymbolicQueryEvaluator(SymbolicSystem& sys, const SymbolicQueryOptions& options = {});

  SymbolicQueryResult evaluate(const logic::CompiledQuery& query);

  SymbolicSystem& system() { return sys_; }
  const bdd::Bdd& reachable() const { return reached_; }
  const bdd::Bdd& evolutions() const { return evolutions_; }
  double num_states() const { return sys_.count(reached_); }
  double num_evolutions() const { return sys_.count_pairs(evolutions_); }
  /// Breadth-first layers: layers()[d] are the situations at distance d from the initial ones.
  const std::vector<bdd::Bdd>& layers() const { return layers_; }

  /// The number of a reachable situation: its rank by (depth, canonical order). The explicit
  /// engine numbers the same way (canonical_state_ids), so both print the same ids.
  std::uint64_t state_id(semantics::StateView state) const;
  /// The rank of an evolution by (source id, target id) among all evolutions.
  std::uint64_t evolution_id(semantics::StateView source, semantics::StateView target) const;

  /// The elements of a set of situations / evolutions (unordered); throws std::length_error
  /// above `limit` elements.
  std::vector<std::vector<semantics::StateWord>> states_of(const bdd::Bdd& set,
                                                           std::uint64_t limit) const;
  std::vector<std::pair<std::vector<semantics::StateWord>, std::vector<semantics::StateWord>>>
  evolutions_of(const bdd::Bdd& set, std::uint64_t limit) const;

  /// Situations that raise a range error under some allowed input (the explicit graph reports
  /// these as anomalies).
  bdd::Bdd range_error_states() const { return reached_ & sys_.range_error_states(); }

 private:
  SymbolicSet set(const logic::Term& t);
  bool test(const logic::Term& t);
  std::int64_t number(const logic::Term& t);
  SymbolicSet make(logic::Sort sort, bdd::Bdd b) const;
  std::size_t layer_of(semantics::StateView state) const;
  bdd::Bdd ranked_before(semantics::StateView state) const;

  SymbolicSystem& sys_;
  bdd::Bdd reached_, evolutions_;
  std::vector<bdd::Bdd> layers_;
  std::vector<double> layer_counts_;
  std::vector<bdd::Bdd> below_;  ///< below_[d]: the union of the layers before d
  std::vector<std::uint32_t> slot_values_;
  std::optional<bdd::Bdd> clearing_;
};

}  // namespace sfcv::engine

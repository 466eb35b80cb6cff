#pragma once
// Evaluates compiled set queries (logic/query_compile.hpp) on an explicit reachable situations
// graph: sets of situations, evolutions and steps are bitsets over state, edge and observable
// indices; Succ and Pred are breadth-first searches restricted to the given evolutions.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include "engine/explicit/reachable_situation_graph.hpp"
#include "logic/query_compile.hpp"
#include "model/dynamic_bitset.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

using model::DynamicBitset;

/// A query that cannot be evaluated on this graph (e.g. Nec on a graph built without conditions).
class QueryEvaluationError : public UsageError {
 public:
  using UsageError::UsageError;
};

struct QueryResult {
  logic::Sort sort = logic::Sort::Empty;
  DynamicBitset set;        ///< States: state ids; Evolutions: edge ids; Steps: observable ids
  bool truth = false;       ///< Bool
  std::int64_t number = 0;  ///< Int
  /// For a test `A = {}` or `A != {}` (either side `{}`): the set A, the elements to show.
  std::optional<logic::Sort> witness_sort;
  DynamicBitset witness;
};

class QueryEvaluator {
 public:
  explicit QueryEvaluator(const ReachableSituationGraph& graph);

  QueryResult evaluate(const logic::CompiledQuery& query);

  /// The upstream situation of an edge.
  std::uint32_t source(std::uint64_t edge) const { return sources_[edge]; }
  const std::vector<std::uint32_t>& sources() const { return sources_; }
  const ReachableSituationGraph& graph() const { return g_; }

 private:
  DynamicBitset set(const logic::Term& t);
  bool test(const logic::Term& t);
  std::int64_t number(const logic::Term& t);
  std::uint64_t universe(logic::Sort s) const;

  DynamicBitset nec(const logic::Signal& s);
  DynamicBitset emis(const logic::Signal& s);
  std::int64_t signal_value(const logic::Signal& s, const std::vector<std::int64_t>& inputs,
                            semantics::StateView state) const;

  const ReachableSituationGraph& g_;
  std::vector<std::uint32_t> sources_;
  std::vector<std::uint32_t> slot_values_;  ///< current step of each set-builder variable
};

}  // namespace sfcv::engine

#pragma once
// Engine-independent numbering of a reachable situations graph for listings: situations by
// (breadth-first depth, canonical order of engine/state_order.hpp), evolutions by (source number,
// target number). The symbolic query evaluator numbers the same way, so `sfcv query` prints
// the same ids with either engine.

#include <cstdint>
#include <vector>

#include "engine/explicit/reachable_situation_graph.hpp"

namespace sfcv::engine {

struct CanonicalNumbering {
  std::vector<std::uint64_t> state;  ///< per RSG state id
  std::vector<std::uint64_t> edge;   ///< per RSG edge id
};

/// `sources[e]` is the upstream state of edge e (QueryEvaluator::source).
CanonicalNumbering canonical_numbering(const ReachableSituationGraph& g,
                                       const std::vector<std::uint32_t>& sources);

/// The label of the evolution source -> target as the graph stores it: the union of the
/// conditions of every successor of `source` that reaches `target` (cubes in the order the
/// semantics gives them) and the union of their fired transitions (sorted). For listing an
/// evolution found by another engine exactly as the explicit one shows it.
struct EvolutionLabel {
  semantics::InputCondition condition;
  std::vector<std::uint32_t> fired;
};
EvolutionLabel evolution_label(const semantics::TransitionSystem& ts, semantics::StateView source,
                               semantics::StateView target);

}  // namespace sfcv::engine

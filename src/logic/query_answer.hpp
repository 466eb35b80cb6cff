#pragma once
// Answers to set queries (docs/queries.md) as data, the same whichever engine computed them:
// situations numbered by (breadth-first depth, canonical order), evolutions by their (source,
// target) numbers, both sorted. Renderers live in src/report (query_render.hpp).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "logic/query_compile.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

/// A set of situations, evolutions or steps, ready to print.
struct QueryListing {
  struct State {
    std::uint64_t id = 0;
    std::vector<semantics::StateWord> state;
  };
  struct Edge {
    std::uint64_t id = 0;
    State source, target;
    semantics::InputCondition condition;
    std::vector<std::uint32_t> fired;
  };
  Sort sort = Sort::Empty;
  std::vector<State> states;
  std::vector<Edge> edges;
  std::vector<std::uint32_t> steps;  ///< observable indices
  std::uint64_t count() const { return states.size() + edges.size() + steps.size(); }
};

/// One query's answer: a set, a test or a number; a test `A = {}` also shows the set A.
struct QueryAnswer {
  Sort sort = Sort::Empty;
  QueryListing set;
  bool truth = false;
  std::int64_t number = 0;
  std::optional<Sort> witness_sort;
  QueryListing witness;
};

/// What an engine knows of the whole graph its answers are computed on.
struct QueryGraphSummary {
  std::uint64_t situations = 0, evolutions = 0;
  bool complete = true;
  std::string limit;  ///< the limit that stopped exploration when !complete
  std::vector<semantics::Anomaly> anomalies;
  /// Verdicts need the whole graph with no evolution cut by a range error.
  bool exact() const { return complete && anomalies.empty(); }
};

}  // namespace sfcv::logic

#pragma once
// The query-evaluation service (docs/queries.md), beside the model-checking contract
// (engine/model_checker.hpp): an engine holds the graph of one system and answers compiled set
// queries on it. make_query_service chooses the engine, `auto` included, in one place.

#include <functional>
#include <memory>
#include <string>

#include "engine/auto_policy.hpp"
#include "logic/query_answer.hpp"
#include "logic/query_compile.hpp"
#include "model/budget.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::engine {

class QueryService {
 public:
  virtual ~QueryService() = default;
  /// "explicit" or "bdd".
  virtual std::string_view name() const = 0;
  virtual const logic::QueryGraphSummary& graph() const = 0;
  /// Throws QueryEvaluationError / SymbolicQueryError for a query this engine cannot answer,
  /// std::length_error for a set too large to list, LimitReached when the budget ran out.
  virtual logic::QueryAnswer answer(const logic::CompiledQuery& query) = 0;
};

using QueryServicePtr = std::unique_ptr<QueryService>;

enum class QueryEngineChoice { Explicit, Bdd, Auto };

struct QueryServiceOptions {
  QueryEngineChoice engine = QueryEngineChoice::Explicit;
  const model::Budget* budget = nullptr;  ///< the run's one budget; null: no limit
  /// How `auto` decided ("using the explicit engine", "... switching to the bdd engine").
  std::function<void(const std::string&)> note;
};

/// Builds the graph of `ts` with the chosen engine. Throws UnsupportedConstruct when the BDD
/// engine was asked for and cannot encode `ts`, LimitReached when the budget runs out while the
/// symbolic graph is built; an explicit graph cut by a limit is returned incomplete.
QueryServicePtr make_query_service(const semantics::TransitionSystem& ts,
                                   const QueryServiceOptions& options);

}  // namespace sfcv::engine

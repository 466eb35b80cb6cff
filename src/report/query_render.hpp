#pragma once
// Renders query answers (logic/query_answer.hpp): the text `sfcv query` prints and its JSON
// (docs/queries.md), the same whichever engine computed them.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "logic/check_result.hpp"
#include "logic/query_answer.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

/// The verdict `--assert` gives: a test must be true, a set empty; only an exact graph decides.
logic::Verdict query_verdict(const logic::QueryAnswer& answer,
                             const logic::QueryGraphSummary& graph);

class QueryPrinter {
 public:
  /// `max_elements`: print at most this many elements of a set (0: all).
  QueryPrinter(const semantics::TransitionSystem& ts, std::uint64_t max_elements)
      : ts_(ts), max_elements_(max_elements) {}

  /// "graph: N situations, M evolutions (kind, complete)".
  std::string graph_line(const logic::QueryGraphSummary& graph, const std::string& semantics) const;
  /// One line per reason the answers below may be wrong (incomplete graph, cut evolutions).
  std::vector<std::string> graph_warnings(const logic::QueryGraphSummary& graph) const;
  nlohmann::json graph_json(const logic::QueryGraphSummary& graph) const;

  /// `verdict` is printed when set (--assert).
  void answer_text(const std::string& query, const logic::QueryAnswer& answer,
                   const std::optional<logic::Verdict>& verdict,
                   const logic::QueryGraphSummary& graph, std::ostream& out) const;
  nlohmann::json answer_json(const std::string& query, const logic::QueryAnswer& answer,
                             const std::optional<logic::Verdict>& verdict) const;

  void listing_text(const logic::QueryListing& l, std::ostream& out) const;
  nlohmann::json listing_json(const logic::QueryListing& l) const;

 private:
  std::string state(const logic::QueryListing::State& s) const;
  std::string edge(const logic::QueryListing::Edge& e) const;

  const semantics::TransitionSystem& ts_;
  std::uint64_t max_elements_ = 0;
};

}  // namespace sfcv::report

#include "report/query_render.hpp"

#include <set>

#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

/// Steps and true Boolean outputs (TransitionSystem::describe), then the other true Boolean
/// variables (for Grafcet: the input values the stable situation was reached with), which tell
/// apart states with the same situation.
std::string describe_state(const semantics::TransitionSystem& ts, semantics::StateView s) {
  std::string out = ts.describe(s), rest;
  const auto& obs = ts.observables();
  for (std::uint32_t i = 0; i < obs.size(); ++i) {
    if (obs[i].kind != semantics::ObservableKind::Variable || obs[i].is_output) continue;
    const auto v = ts.observe(s, i);
    if (obs[i].type.kind == model::TypeKind::Bool) {
      if (v) rest += " " + obs[i].name;
    } else {
      rest += " " + obs[i].name + "=" + std::to_string(v);
    }
  }
  return rest.empty() ? out : out + " |" + rest;
}

std::string sort_noun(logic::Sort s, std::uint64_t n) {
  switch (s) {
    case logic::Sort::States:
      return n == 1 ? "situation" : "situations";
    case logic::Sort::Evolutions:
      return n == 1 ? "evolution" : "evolutions";
    case logic::Sort::Steps:
      return n == 1 ? "step" : "steps";
    default:
      return n == 1 ? "element" : "elements";
  }
}

std::string sort_key(logic::Sort s) {
  switch (s) {
    case logic::Sort::States:
      return "situations";
    case logic::Sort::Evolutions:
      return "evolutions";
    case logic::Sort::Steps:
      return "steps";
    case logic::Sort::Empty:
      return "empty";
    case logic::Sort::Bool:
      return "test";
    case logic::Sort::Int:
      return "number";
  }
  return "?";
}

}  // namespace

logic::Verdict query_verdict(const logic::QueryAnswer& answer,
                             const logic::QueryGraphSummary& graph) {
  const bool holds = answer.sort == logic::Sort::Bool ? answer.truth : answer.set.count() == 0;
  if (!graph.exact()) return logic::Verdict::Unknown;
  return holds ? logic::Verdict::Holds : logic::Verdict::Violated;
}

std::string QueryPrinter::state(const logic::QueryListing::State& s) const {
  return "#" + std::to_string(s.id) + " " + describe_state(ts_, s.state);
}

std::string QueryPrinter::edge(const logic::QueryListing::Edge& e) const {
  return state(e.source) + " --[" + e.condition.to_string(ts_.inputs()) + "]--> " + state(e.target);
}

std::string QueryPrinter::graph_line(const logic::QueryGraphSummary& graph,
                                     const std::string& semantics) const {
  return "graph: " + std::to_string(graph.situations) + " situations, " +
         std::to_string(graph.evolutions) + " evolutions (" + semantics +
         (graph.complete ? ", complete" : ", INCOMPLETE") + ")";
}

std::vector<std::string> QueryPrinter::graph_warnings(const logic::QueryGraphSummary& graph) const {
  std::vector<std::string> lines;
  if (!graph.complete)
    lines.push_back("warning: the graph is incomplete (limit reached: " + graph.limit +
                    "): the sets below are computed on a partial graph and may be wrong in both "
                    "directions");
  for (const auto& a : graph.anomalies)
    lines.push_back("warning: " + a.message + " (under " + a.condition.to_string(ts_.inputs()) +
                    "): the evolutions it cuts are missing from the graph");
  return lines;
}

nlohmann::json QueryPrinter::graph_json(const logic::QueryGraphSummary& graph) const {
  return {{"situations", graph.situations},
          {"evolutions", graph.evolutions},
          {"complete", graph.complete},
          {"limit", graph.limit},
          {"anomalies", graph.anomalies.size()}};
}

void QueryPrinter::listing_text(const logic::QueryListing& l, std::ostream& out) const {
  const auto n = l.count();
  out << "  " << n << " " << sort_noun(l.sort, n);
  if (l.sort == logic::Sort::States && n) {
    // RSG states also hold the input values; say how many situations they are.
    std::set<std::vector<std::uint32_t>> situations;
    const auto& obs = ts_.observables();
    for (const auto& s : l.states) {
      std::vector<std::uint32_t> active;
      for (std::uint32_t o = 0; o < obs.size(); ++o)
        if (obs[o].kind == semantics::ObservableKind::Step && ts_.observe(s.state, o))
          active.push_back(o);
      situations.insert(std::move(active));
    }
    if (situations.size() != n) out << " (" << situations.size() << " distinct step sets)";
  }
  out << (n ? ":" : "") << "\n";
  std::uint64_t shown = 0;
  auto room = [&] { return !max_elements_ || shown++ < max_elements_; };
  for (const auto& s : l.states)
    if (room()) out << "    " << state(s) << "\n";
  for (const auto& e : l.edges)
    if (room()) out << "    " << edge(e) << "\n";
  for (const auto o : l.steps)
    if (room()) out << "    " << ts_.observables()[o].name << "\n";
  if (max_elements_ && n > max_elements_)
    out << "    ... and " << n - max_elements_ << " more (--max-elements)\n";
}

nlohmann::json QueryPrinter::listing_json(const logic::QueryListing& l) const {
  auto arr = nlohmann::json::array();
  const auto& obs = ts_.observables();
  for (const auto& s : l.states) {
    nlohmann::json steps = nlohmann::json::array(), outputs = nlohmann::json::object();
    for (std::uint32_t o = 0; o < obs.size(); ++o) {
      if (obs[o].kind == semantics::ObservableKind::Step) {
        if (ts_.observe(s.state, o)) steps.push_back(obs[o].name);
      } else if (obs[o].is_output) {
        outputs[obs[o].name] = ts_.observe(s.state, o);
      }
    }
    arr.push_back({{"id", s.id}, {"steps", steps}, {"outputs", outputs}, {"text", state(s)}});
  }
  for (const auto& e : l.edges) {
    nlohmann::json fired = nlohmann::json::array();
    for (auto t : e.fired) fired.push_back(ts_.transitions()[t].name);
    arr.push_back({{"id", e.id},
                   {"source", e.source.id},
                   {"target", e.target.id},
                   {"condition", e.condition.to_string(ts_.inputs())},
                   {"fired", fired},
                   {"text", edge(e)}});
  }
  for (const auto o : l.steps) arr.push_back(obs[o].name);
  return arr;
}

void QueryPrinter::answer_text(const std::string& query, const logic::QueryAnswer& r,
                               const std::optional<logic::Verdict>& verdict,
                               const logic::QueryGraphSummary& graph, std::ostream& out) const {
  out << "query: " << query << "\n";
  if (r.sort == logic::Sort::Bool) {
    out << "  " << (r.truth ? "true" : "false") << "\n";
    if (r.witness_sort) listing_text(r.witness, out);
  } else if (r.sort == logic::Sort::Int) {
    out << "  " << r.number << "\n";
  } else {
    listing_text(r.set, out);
  }
  if (!verdict) return;
  switch (*verdict) {
    case logic::Verdict::Holds:
      out << "  holds\n";
      break;
    case logic::Verdict::Violated:
      out << "  VIOLATED" << (r.sort == logic::Sort::Bool ? "" : " (the set is not empty)") << "\n";
      break;
    default:
      out << "  unknown: "
          << (graph.complete ? "the graph has anomalies" : "the graph is incomplete") << "\n";
      break;
  }
}

nlohmann::json QueryPrinter::answer_json(const std::string& query, const logic::QueryAnswer& r,
                                         const std::optional<logic::Verdict>& verdict) const {
  nlohmann::json jq;
  jq["query"] = query;
  jq["sort"] = sort_key(r.sort);
  if (r.sort == logic::Sort::Bool) {
    jq["value"] = r.truth;
    if (r.witness_sort) {
      jq["witness_sort"] = sort_key(*r.witness_sort);
      jq["count"] = r.witness.count();
      jq["elements"] = listing_json(r.witness);
    }
  } else if (r.sort == logic::Sort::Int) {
    jq["value"] = r.number;
  } else {
    jq["count"] = r.set.count();
    jq["elements"] = listing_json(r.set);
  }
  if (verdict) jq["verdict"] = std::string(logic::to_string(*verdict));
  make_valid_utf8(jq);  // names are bytes; the JSON is UTF-8
  return jq;
}

}  // namespace sfcv::report

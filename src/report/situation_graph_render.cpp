#include "report/situation_graph_render.hpp"

#include <iomanip>
#include <set>
#include <sstream>

#include "engine/bdd/condition_simplifier.hpp"
#include "report/markup.hpp"
#include "report/schema_versions.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

/// "{1,10} x y" -> ("{1,10}", "x y"): the situation and what it emits.
std::pair<std::string, std::string> split_description(const std::string& d) {
  const auto close = d.find('}');
  if (d.empty() || d[0] != '{' || close == std::string::npos) return {d, ""};
  std::string rest = d.substr(close + 1);
  while (!rest.empty() && rest.front() == ' ') rest.erase(rest.begin());
  return {d.substr(0, close + 1), rest};
}

std::string inputs_of(const semantics::TransitionSystem& ts, semantics::StateView s) {
  std::string out;
  for (std::uint32_t i = 0; i < ts.observables().size(); ++i) {
    const auto& o = ts.observables()[i];
    if (o.kind != semantics::ObservableKind::Variable || o.is_output) continue;
    bool is_input = false;
    for (const auto& in : ts.inputs())
      if (in.name == o.name) is_input = true;
    if (!is_input) continue;
    const auto v = ts.observe(s, i);
    if (!out.empty()) out += " ";
    out += o.type.kind == model::TypeKind::Bool ? (v ? "" : "!") + o.name
                                                : o.name + "=" + std::to_string(v);
  }
  return out;
}

/// Under the single-input-change rule: which input changed between two nodes ("a rises",
/// "n: 0 -> 5"), or "a delay elapses" when none did.
std::string event_of(const semantics::TransitionSystem& ts, semantics::StateView from,
                     semantics::StateView to) {
  for (std::uint32_t i = 0; i < ts.observables().size(); ++i) {
    const auto& o = ts.observables()[i];
    if (o.kind != semantics::ObservableKind::Variable || o.is_output) continue;
    bool is_input = false;
    for (const auto& in : ts.inputs())
      if (in.name == o.name && !in.pseudo) is_input = true;
    if (!is_input) continue;
    const auto a = ts.observe(from, i), b = ts.observe(to, i);
    if (a == b) continue;
    if (o.type.kind == model::TypeKind::Bool) return o.name + (b ? " rises" : " falls");
    return o.name + ": " + std::to_string(a) + " -> " + std::to_string(b);
  }
  return "a delay elapses";
}

std::string condition_text(const engine::ReachableSituationGraph& g,
                           const semantics::TransitionSystem& ts, std::uint64_t e) {
  return engine::simplify(g.condition(e), ts.inputs()).to_string(ts.inputs());
}

std::vector<bool> initial_marks(const engine::ReachableSituationGraph& g) {
  std::vector<bool> initial(g.num_states(), false);
  for (auto s : g.initial_states()) initial[s] = true;
  return initial;
}

}  // namespace

std::string situation_graph_text(const engine::ReachableSituationGraph& g,
                                 const semantics::TransitionSystem& ts,
                                 const SituationGraphText& options) {
  const std::string& sem = options.semantics;
  const bool single = options.single_input_change;
  auto state = [&g](std::uint32_t s) { return g.states().at(s); };

  // Distinct step situations: the states projected on the step fields (the seed's RSG nodes
  // do not hold the input values).
  std::set<std::vector<std::int64_t>> situations;
  std::set<std::pair<std::vector<std::int64_t>, std::vector<std::int64_t>>> moves;
  const auto& layout = ts.layout();
  auto project_steps = [&](std::uint32_t s) {
    std::vector<std::int64_t> v;
    for (std::uint32_t f = 0; f < layout.fields().size(); ++f) {
      const auto k = layout.fields()[f].kind;
      if (k == semantics::FieldKind::StepActive || k == semantics::FieldKind::StepReady)
        v.push_back(layout.get(state(s), f));
    }
    return v;
  };
  for (std::uint32_t s = 0; s < g.num_states(); ++s) {
    const auto p = project_steps(s);
    situations.insert(p);
    for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e) {
      const auto q = project_steps(g.target(e));
      if (q != p) moves.insert({p, q});
    }
  }

  std::ostringstream out;
  out << "semantics: " << sem
      << (sem == "grafcet" ? (single ? " (IEC 60848, single input change)"
                                     : " (IEC 60848, multiple input changes)")
                           : " (IEC 61131-3 scan cycle)")
      << "\n";
  out << (sem == "grafcet" ? "situations: " : "states: ") << g.num_states();
  if (sem == "grafcet") out << " (distinct step situations: " << situations.size() << ")";
  out << "\nevolutions: " << g.num_edges();
  if (sem == "grafcet") out << " (between distinct step situations: " << moves.size() << ")";
  out << "\ninitial: " << g.initial_states().size() << "\n";
  out << "build time: " << std::fixed << std::setprecision(3) << g.build_seconds() << " s\n";
  out.unsetf(std::ios::fixed);
  if (!options.list) return out.str();
  const auto initial = initial_marks(g);
  for (std::uint32_t s = 0; s < g.num_states(); ++s) {
    const auto [sit, emitted] = split_description(ts.describe(state(s)));
    out << "s" << s << (initial[s] ? " (initial)" : "") << ": " << sit;
    if (!emitted.empty()) out << " / " << emitted;
    const auto in = inputs_of(ts, state(s));
    if (!in.empty()) out << "   [inputs: " << in << "]";
    out << "\n";
  }
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e) {
      const auto t = g.target(e);
      const auto from = split_description(ts.describe(state(s))).first;
      const auto [to, emitted] = split_description(ts.describe(state(t)));
      out << "s" << s << " " << from << " --[" << condition_text(g, ts, e) << "]--> s" << t << " "
          << to;
      if (!emitted.empty()) out << " / " << emitted;
      if (single) out << "   (" << event_of(ts, state(s), state(t)) << ")";
      out << "\n";
    }
  return out.str();
}

nlohmann::json situation_graph_json(const engine::ReachableSituationGraph& g,
                                    const semantics::TransitionSystem& ts,
                                    const SituationGraphText& options) {
  const auto& inputs = ts.inputs();
  auto state = [&g](std::uint32_t s) { return g.states().at(s); };
  nlohmann::json j;
  j["schema_version"] = kSummaryJsonSchemaVersion;
  j["semantics"] = options.semantics;
  if (options.semantics == "grafcet") j["single_input_change"] = options.single_input_change;
  j["complete"] = g.complete();
  if (!g.complete()) j["limit"] = g.limit_reached();
  j["build_seconds"] = g.build_seconds();
  j["inputs"] = nlohmann::json::array();
  for (const auto& in : inputs) j["inputs"].push_back({{"name", in.name}, {"pseudo", in.pseudo}});
  j["states"] = nlohmann::json::array();
  const auto initial = initial_marks(g);
  for (std::uint32_t s = 0; s < g.num_states(); ++s) {
    const auto [sit, out] = split_description(ts.describe(state(s)));
    j["states"].push_back({{"id", s},
                           {"situation", sit},
                           {"outputs", out},
                           {"inputs", inputs_of(ts, state(s))},
                           {"initial", bool(initial[s])},
                           {"expanded", g.expanded(s)}});
  }
  j["edges"] = nlohmann::json::array();
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e) {
      nlohmann::json fired = nlohmann::json::array();
      for (auto t : g.fired(e)) fired.push_back(ts.transitions()[t].name);
      j["edges"].push_back({{"from", s},
                            {"to", g.target(e)},
                            {"condition", condition_text(g, ts, e)},
                            {"fired", fired}});
    }
  j["anomalies"] = nlohmann::json::array();
  for (const auto& a : g.anomalies()) {
    nlohmann::json cycle = nlohmann::json::array();
    for (const auto& c : a.cycle) cycle.push_back(ts.describe(c));
    j["anomalies"].push_back({{"message", a.message},
                              {"inputs", engine::simplify(a.condition, inputs).to_string(inputs)},
                              {"cycle", cycle}});
  }
  make_valid_utf8(j);  // names are bytes; the JSON is UTF-8
  return j;
}

std::string state_graph_dot(const engine::ReachableSituationGraph& g,
                            const semantics::TransitionSystem& ts) {
  std::ostringstream d;
  d << "digraph rsg {\n  rankdir=LR;\n  node [shape=box, fontname=\"monospace\"];\n";
  for (auto s : g.initial_states())
    d << "  init" << s << " [shape=point];\n  init" << s << " -> s" << s << ";\n";
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    d << "  s" << s << " [label=\"" << dot_escape(ts.describe(g.states().at(s))) << "\"];\n";
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e)
      d << "  s" << s << " -> s" << g.target(e) << " [label=\""
        << dot_escape(condition_text(g, ts, e)) << "\"];\n";
  d << "}\n";
  return d.str();
}

std::vector<std::string> anomaly_lines(const engine::ReachableSituationGraph& g,
                                       const semantics::TransitionSystem& ts,
                                       const std::string& model) {
  // One line per distinct anomaly (the same cycle is met from many nodes).
  std::vector<std::string> lines;
  std::set<std::string> printed;
  for (const auto& a : g.anomalies()) {
    std::string line = model + ": error: " + a.message + "; inputs: " +
                       engine::simplify(a.condition, ts.inputs()).to_string(ts.inputs());
    if (!a.cycle.empty()) {
      line += "; cycle:";
      for (const auto& c : a.cycle) line += " " + split_description(ts.describe(c)).first + " ->";
      line += " " + split_description(ts.describe(a.cycle.front())).first;
    }
    if (printed.insert(line).second) lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace sfcv::report

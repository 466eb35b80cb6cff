#include "report/situation_graph_dot.hpp"

#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "report/markup.hpp"

namespace sfcv::report {

namespace {

/// One node of the grouped graph: a set of active steps and what its stable situations emit.
struct Group {
  std::vector<std::uint32_t> steps;  ///< step observables, in observable order
  std::size_t members = 0;           ///< stable situations folded into it
  bool initial = false;
  std::map<std::uint32_t, std::size_t>
      emitted;  ///< Boolean output observable -> members emitting it
};

constexpr std::size_t kFiringsPerEdge = 3;  // firing sets on an edge label before "or n more"

}  // namespace

SituationGraphDot situation_graph_dot(const engine::ReachableSituationGraph& graph,
                                      const SituationGraphOptions& options) {
  const auto& ts = graph.system();
  const auto& obs = ts.observables();
  SituationGraphDot r;
  r.stable_situations = graph.num_states();

  // Groups in the order of their first stable situation (breadth-first).
  std::map<std::vector<std::uint32_t>, std::size_t> index;
  std::vector<Group> groups;
  std::vector<std::size_t> group_of(graph.num_states());
  for (std::uint32_t s = 0; s < graph.num_states(); ++s) {
    const auto state = graph.states().at(s);
    std::vector<std::uint32_t> steps;
    for (std::uint32_t o = 0; o < obs.size(); ++o)
      if (obs[o].kind == semantics::ObservableKind::Step && ts.observe(state, o))
        steps.push_back(o);
    auto [it, fresh] = index.emplace(steps, groups.size());
    if (fresh) groups.push_back({std::move(steps), 0, false, {}});
    auto& g = groups[it->second];
    group_of[s] = it->second;
    ++g.members;
    for (std::uint32_t o = 0; o < obs.size(); ++o)
      if (obs[o].kind == semantics::ObservableKind::Variable && obs[o].is_output &&
          obs[o].type.kind == model::TypeKind::Bool && ts.observe(state, o))
        ++g.emitted[o];
  }
  for (auto s : graph.initial_states()) groups[group_of[s]].initial = true;
  r.step_situations = groups.size();
  // The first max_nodes breadth-first, and every one the caller must see (a trace's).
  std::vector<bool> drawn(groups.size(), false);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    std::set<std::string> names;
    for (auto o : groups[i].steps) names.insert(obs[o].name);
    std::string key;
    for (const auto& n : names) key += (key.empty() ? "" : ",") + n;
    const bool first = options.max_nodes == 0 || i < options.max_nodes;
    const bool keep = options.keep.count(key) > 0;
    if (!first && !keep) continue;
    drawn[i] = true;
    kept += !first;
    r.node_ids[key] = "sg" + std::to_string(i);
    ++r.shown;
  }

  // Edges between distinct groups, each with the distinct sets of transitions fired (one line
  // per transition of a set, the transient situations crossed inside it; "or" between sets).
  std::map<std::pair<std::size_t, std::size_t>, std::set<std::string>> edges;
  for (std::uint32_t s = 0; s < graph.num_states(); ++s) {
    if (!graph.expanded(s)) continue;
    for (auto e = graph.edges_begin(s); e < graph.edges_end(s); ++e) {
      const auto from = group_of[s], to = group_of[graph.target(e)];
      if (from == to) continue;
      std::string fired;
      for (auto t : graph.fired(e)) fired += dot_escape(ts.transitions()[t].name) + "\\l";
      edges[{from, to}].insert(fired);
    }
  }

  const bool cut = r.shown < groups.size();
  std::ostringstream d;
  d << "digraph rsg {\n  id=\"situations\";\n  rankdir=TB;\n  nodesep=0.4;\n  ranksep=0.5;\n"
       "  node [shape=box, style=rounded, fontname=\"Helvetica\", fontsize=11];\n"
       "  edge [fontname=\"Helvetica\", fontsize=9];\n";
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (!drawn[i]) continue;
    const auto& g = groups[i];
    std::string steps, emitted;
    for (auto o : g.steps) steps += (steps.empty() ? "" : ", ") + obs[o].name;
    for (const auto& [o, n] : g.emitted)
      emitted += (emitted.empty() ? "" : " ") + obs[o].name + (n < g.members ? "?" : "");
    std::string label = "{" + dot_escape(steps) + "}";
    if (!emitted.empty()) label += "\\n" + dot_escape(emitted);
    if (g.members > 1) label += "\\n" + std::to_string(g.members) + " stable situations";
    d << "  g" << i << " [id=\"sg" << i << "\", label=\"" << label << "\""
      << (g.initial ? ", peripheries=2" : "") << "];\n";
    if (g.initial)
      d << "  init" << i << " [shape=point, label=\"\"];\n  init" << i << " -> g" << i << ";\n";
  }
  for (const auto& [key, firings] : edges) {
    const auto [from, to] = key;
    if (!drawn[from] || !drawn[to]) continue;
    std::string label;
    std::size_t n = 0;
    for (const auto& f : firings) {
      if (n++ == kFiringsPerEdge) {
        label += "or " + std::to_string(firings.size() - kFiringsPerEdge) + " more\\l";
        break;
      }
      label += (n > 1 ? "or\\l" : "") + f;
    }
    d << "  g" << from << " -> g" << to << " [id=\"se" << r.edges << "\", label=\"" << label
      << "\"];\n";
    ++r.edges;
  }
  if (cut) {
    // Every edge into a left-out situation goes to one node that says how many are missing.
    d << "  omitted [id=\"somitted\", shape=note, style=dashed, label=\"" << r.omitted()
      << " more step situations\\n(" << dot_escape(options.option_name) << ")\"];\n";
    std::set<std::size_t> sources;
    for (const auto& [key, firings] : edges)
      if (drawn[key.first] && !drawn[key.second]) sources.insert(key.first);
    for (auto s : sources) d << "  g" << s << " -> omitted [id=\"so" << s << "\", style=dashed];\n";
    r.truncation_note = std::to_string(r.shown) + " of " + std::to_string(groups.size()) +
                        " step situations are drawn (the first " + std::to_string(r.shown - kept) +
                        " breadth-first" +
                        (kept ? ", and " + std::to_string(kept) + " a trace visits" : "") + "), " +
                        std::to_string(r.omitted()) + " left out; " + options.option_name +
                        " N draws N, " + options.option_name + " 0 every one";
  }
  d << "}\n";
  r.dot = d.str();
  return r;
}

}  // namespace sfcv::report

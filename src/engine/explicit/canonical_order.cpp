#include "engine/explicit/canonical_order.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>

#include "engine/state_order.hpp"

namespace sfcv::engine {

CanonicalNumbering canonical_numbering(const ReachableSituationGraph& g,
                                       const std::vector<std::uint32_t>& sources) {
  const auto& layout = g.system().layout();
  CanonicalNumbering n;
  std::vector<std::uint32_t> order(g.num_states());
  std::iota(order.begin(), order.end(), 0U);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (g.depth(a) != g.depth(b)) return g.depth(a) < g.depth(b);
    return canonically_less(layout, g.states().at(a), g.states().at(b));
  });
  n.state.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) n.state[order[k]] = k;

  std::vector<std::uint64_t> edges(g.num_edges());
  std::iota(edges.begin(), edges.end(), 0U);
  std::sort(edges.begin(), edges.end(), [&](std::uint64_t a, std::uint64_t b) {
    const auto sa = n.state[sources[a]], sb = n.state[sources[b]];
    if (sa != sb) return sa < sb;
    return n.state[g.target(a)] < n.state[g.target(b)];
  });
  n.edge.resize(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) n.edge[edges[k]] = k;
  return n;
}

EvolutionLabel evolution_label(const semantics::TransitionSystem& ts, semantics::StateView source,
                               semantics::StateView target) {
  // The same merge as the graph's successor collector.
  struct Sink final : semantics::SuccessorSink {
    semantics::StateView target;
    EvolutionLabel label;
    semantics::ConditionBuilder condition;
    bool seen = false;
    void successor(const semantics::Successor& s) override {
      if (!std::equal(s.target.begin(), s.target.end(), target.begin(), target.end())) return;
      condition.add(s.condition.cubes);
      if (!seen || label.fired.empty()) {
        label.fired.assign(s.fired.begin(), s.fired.end());
      } else if (!std::equal(label.fired.begin(), label.fired.end(), s.fired.begin(),
                             s.fired.end())) {
        std::vector<std::uint32_t> merged;
        std::set_union(label.fired.begin(), label.fired.end(), s.fired.begin(), s.fired.end(),
                       std::back_inserter(merged));
        label.fired = std::move(merged);
      }
      seen = true;
    }
  } sink;
  sink.target = target;
  const std::vector<semantics::StateWord> copy(source.begin(), source.end());
  ts.successors(copy, sink);
  sink.label.condition = std::move(sink.condition).take();
  return std::move(sink.label);
}

}  // namespace sfcv::engine

#include "engine/explicit/canonical_order.hpp"

#include <algorithm>
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

}  // namespace sfcv::engine

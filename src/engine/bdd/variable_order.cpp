#include "engine/bdd/variable_order.hpp"

#include <algorithm>

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;

void aig_support(const Aig& aig, AigLit root, std::vector<bool>& seen,
                 std::vector<std::uint32_t>& inputs, std::vector<std::uint32_t>& latches) {
  std::vector<std::uint32_t> stack{Aig::node_of(root)};
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (seen[n]) continue;
    seen[n] = true;
    const auto& node = aig.nodes()[n];
    switch (node.kind) {
      case Aig::NodeKind::Input:
        inputs.push_back(node.index);
        break;
      case Aig::NodeKind::Latch:
        latches.push_back(node.index);
        break;
      case Aig::NodeKind::And:
        stack.push_back(Aig::node_of(node.left));
        stack.push_back(Aig::node_of(node.right));
        break;
      case Aig::NodeKind::Constant:
        break;
    }
  }
}

std::vector<std::uint32_t> force_order(const Aig& aig,
                                       const std::vector<std::vector<std::uint32_t>>& extra_ties) {
  // Static order by the FORCE heuristic: latches (their current and next copies adjacent) and
  // inputs are units; each next-state function ties its latch to the latches and inputs it
  // reads; a few rounds move every unit to the mean centre of gravity of its ties. Related bits
  // end up adjacent, which keeps the relation and the reachable sets small (with the layout's
  // own order, a chart's outputs sit far from its steps: exponential in independent branches).
  const std::size_t num_latches = aig.latches().size(), num_inputs = aig.inputs().size();
  const std::size_t units = num_latches + num_inputs;  // latch l = unit l, input i = L + i
  std::vector<std::vector<std::uint32_t>> ties = extra_ties;
  {
    std::vector<bool> seen(aig.nodes().size());
    for (std::size_t l = 0; l < num_latches; ++l) {
      std::fill(seen.begin(), seen.end(), false);
      std::vector<std::uint32_t> ins, lats;
      aig_support(aig, aig.latches()[l].next, seen, ins, lats);
      std::vector<std::uint32_t> tie{static_cast<std::uint32_t>(l)};
      for (auto x : lats)
        if (x != l) tie.push_back(x);
      for (auto i : ins) tie.push_back(static_cast<std::uint32_t>(num_latches + i));
      if (tie.size() > 1) ties.push_back(std::move(tie));
    }
  }
  std::vector<double> position(units);
  {
    // Start: the layout order with each input just before the first latch that reads it.
    std::vector<bool> placed(units, false);
    double at = 0;
    for (const auto& tie : ties) {
      for (std::size_t k = 1; k < tie.size(); ++k)
        if (tie[k] >= num_latches && !placed[tie[k]]) {
          position[tie[k]] = at++;
          placed[tie[k]] = true;
        }
      if (!placed[tie[0]]) {
        position[tie[0]] = at++;
        placed[tie[0]] = true;
      }
    }
    for (std::size_t u = 0; u < units; ++u)
      if (!placed[u]) position[u] = at++;
  }
  auto span = [&] {
    double total = 0;
    for (const auto& tie : ties) {
      double lo = position[tie[0]], hi = lo;
      for (auto u : tie) {
        lo = std::min(lo, position[u]);
        hi = std::max(hi, position[u]);
      }
      total += hi - lo;
    }
    return total;
  };
  std::vector<std::uint32_t> order(units);
  for (std::size_t u = 0; u < units; ++u) order[u] = static_cast<std::uint32_t>(u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return position[a] < position[b]; });
  double best_span = span();
  std::vector<std::uint32_t> best_order = order;
  for (int round = 0; round < 50 && !ties.empty(); ++round) {
    std::vector<double> sum(units, 0), count(units, 0);
    for (const auto& tie : ties) {
      double cog = 0;
      for (auto u : tie) cog += position[u];
      cog /= static_cast<double>(tie.size());
      for (auto u : tie) {
        sum[u] += cog;
        count[u] += 1;
      }
    }
    for (std::size_t u = 0; u < units; ++u)
      if (count[u] > 0) position[u] = sum[u] / count[u];
    std::stable_sort(order.begin(), order.end(),
                     [&](auto a, auto b) { return position[a] < position[b]; });
    for (std::size_t k = 0; k < units; ++k) position[order[k]] = static_cast<double>(k);
    const double now = span();
    if (now < best_span) {
      best_span = now;
      best_order = order;
    } else if (round > 5) {
      break;
    }
  }
  return best_order;
}

}  // namespace sfcv::engine

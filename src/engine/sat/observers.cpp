#include "engine/sat/observers.hpp"

#include <vector>

namespace sfcv::engine::sat {

using semantics::Aig;
using semantics::AigLit;

std::optional<AigLit> no_successor(Aig& aig, AigLit step_ok, std::size_t max_new_ands) {
  // The inputs in the cone of step_ok.
  std::vector<AigLit> support;
  std::vector<bool> seen(aig.nodes().size(), false);
  std::vector<std::uint32_t> stack{Aig::node_of(step_ok)};
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (seen[n]) continue;
    seen[n] = true;
    const auto& node = aig.nodes()[n];
    if (node.kind == Aig::NodeKind::Input) support.push_back(n * 2);
    if (node.kind == Aig::NodeKind::And) {
      stack.push_back(Aig::node_of(node.left));
      stack.push_back(Aig::node_of(node.right));
    }
  }
  const std::size_t start = aig.num_ands();
  AigLit dead = Aig::make_not(step_ok);
  for (const auto input : support) {
    dead = aig.make_and(aig.cofactor(dead, input, false), aig.cofactor(dead, input, true));
    if (aig.num_ands() - start > max_new_ands) return std::nullopt;
  }
  return dead;
}

AigLit bounded_response_target(Aig& aig, AigLit p, AigLit s, std::uint32_t n, AigLit dead,
                               const std::string& name) {
  std::uint32_t width = 1;
  while ((std::uint64_t{1} << width) <= n) ++width;
  auto latch = [&](const std::string& what) {
    const AigLit l = aig.add_latch(name + "." + what, false);
    return std::pair{l, static_cast<std::uint32_t>(aig.latches().size() - 1)};
  };
  // The latches carry the obligation of the state before into this one.
  const auto [carried, carried_index] = latch("pending");
  semantics::BitVector carried_age;
  std::vector<std::uint32_t> age_index;
  for (std::uint32_t b = 0; b < width; ++b) {
    const auto [l, i] = latch("age" + std::to_string(b));
    carried_age.push_back(l);
    age_index.push_back(i);
  }
  // In this state: pending unless s answers it, the age of the oldest obligation (0 for one
  // that p opens here).
  const AigLit pending = aig.make_and(Aig::make_not(s), aig.make_or(carried, p));
  const auto age = semantics::bv_mux(aig, carried, carried_age, semantics::bv_constant(0, width));
  const AigLit at_bound = semantics::bv_equal(aig, age, semantics::bv_constant(n, width));
  aig.set_next(carried_index, pending);
  const auto older = semantics::bv_mux(
      aig, at_bound, age, semantics::bv_add(aig, age, semantics::bv_constant(1, width)));
  for (std::uint32_t b = 0; b < width; ++b) aig.set_next(age_index[b], older[b]);
  return aig.make_and(pending, aig.make_or(at_bound, dead));
}

}  // namespace sfcv::engine::sat

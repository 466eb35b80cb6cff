#include "engine/sat/observers.hpp"

#include <unordered_map>
#include <vector>

namespace sfcv::engine::sat {

using semantics::Aig;
using semantics::AigLit;

namespace {

/// The input literals (positive) in the cone of `root`.
std::vector<AigLit> input_support(const Aig& aig, AigLit root) {
  std::vector<AigLit> support;
  std::vector<bool> seen(aig.nodes().size(), false);
  std::vector<std::uint32_t> stack{Aig::node_of(root)};
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
  return support;
}

/// `root` with every input of its cone universally quantified; nullopt once the expansion has
/// added more than `budget` AND nodes since `start`.
std::optional<AigLit> for_all_inputs(Aig& aig, AigLit root, std::size_t start, std::size_t budget) {
  for (const auto input : input_support(aig, root)) {
    root = aig.make_and(aig.cofactor(root, input, false), aig.cofactor(root, input, true));
    if (aig.num_ands() - start > budget) return std::nullopt;
  }
  return root;
}

}  // namespace

std::optional<AigLit> no_successor(Aig& aig, AigLit step_ok, std::size_t max_new_ands) {
  return for_all_inputs(aig, Aig::make_not(step_ok), aig.num_ands(), max_new_ands);
}

std::optional<AigLit> at_next_cycle(Aig& aig, AigLit root, std::size_t max_new_ands) {
  const std::size_t start = aig.num_ands();
  std::unordered_map<std::uint32_t, AigLit> done;  // node -> its literal one cycle later
  std::vector<std::uint32_t> stack{Aig::node_of(root)};
  while (!stack.empty()) {
    const auto n = stack.back();
    if (done.count(n)) {
      stack.pop_back();
      continue;
    }
    const auto node = aig.nodes()[n];  // a copy: make_and may grow the node table
    switch (node.kind) {
      case Aig::NodeKind::Constant:
        done[n] = Aig::kFalse;
        break;
      case Aig::NodeKind::Input:
        done[n] = n * 2;  // this cycle's input, read by the next-state functions too
        break;
      case Aig::NodeKind::Latch:
        done[n] = aig.latches()[node.index].next;
        break;
      case Aig::NodeKind::And: {
        const auto l = Aig::node_of(node.left), r = Aig::node_of(node.right);
        const auto dl = done.find(l), dr = done.find(r);
        if (dl == done.end() || dr == done.end()) {
          if (dl == done.end()) stack.push_back(l);
          if (dr == done.end()) stack.push_back(r);
          continue;
        }
        done[n] = aig.make_and(dl->second ^ (node.left & 1U), dr->second ^ (node.right & 1U));
        if (aig.num_ands() - start > max_new_ands) return std::nullopt;
        break;
      }
    }
    stack.pop_back();
  }
  return done.at(Aig::node_of(root)) ^ (root & 1U);
}

std::optional<AigLit> some_input_satisfies(Aig& aig, const std::vector<AigLit>& lits,
                                           std::size_t max_new_ands) {
  // Exists distributes over the disjunction: each literal alone keeps its cone small.
  const std::size_t start = aig.num_ands();
  std::vector<AigLit> each;
  for (const auto lit : lits) {
    const auto none = for_all_inputs(aig, Aig::make_not(lit), start, max_new_ands);
    if (!none) return std::nullopt;
    each.push_back(Aig::make_not(*none));
  }
  return aig.make_or(each);
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

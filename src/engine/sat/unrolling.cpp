#include "engine/sat/unrolling.hpp"

#include <algorithm>

namespace sfcv::engine::sat {

using semantics::Aig;
using semantics::AigLit;

Unrolling::Unrolling(const Aig& aig, Solver& solver, bool from_initial)
    : aig_(aig), solver_(solver), from_initial_(from_initial) {}

int Unrolling::literal(AigLit lit, std::size_t frame) {
  // Iterative post-order over (node, frame): a deep unrolling would overflow a recursive walk.
  struct Item {
    std::uint32_t node;
    std::size_t frame;
  };
  auto slot = [this](std::uint32_t node, std::size_t f) -> int& {
    if (lit_of_node_.size() <= f) lit_of_node_.resize(f + 1);
    auto& row = lit_of_node_[f];
    if (row.size() < aig_.nodes().size()) row.resize(aig_.nodes().size(), 0);
    return row[node];
  };
  std::vector<Item> stack{{Aig::node_of(lit), frame}};
  while (!stack.empty()) {
    const Item it = stack.back();
    if (slot(it.node, it.frame) != 0) {
      stack.pop_back();
      continue;
    }
    const auto& node = aig_.nodes()[it.node];
    int result = 0;
    switch (node.kind) {
      case Aig::NodeKind::Constant:
        result = -solver_.true_lit();
        break;
      case Aig::NodeKind::Input:
        result = solver_.new_var();
        break;
      case Aig::NodeKind::Latch:
        if (it.frame == 0) {
          result = solver_.new_var();
          if (from_initial_)
            solver_.add_clause({aig_.latches()[node.index].initial ? result : -result});
        } else {
          const AigLit next = aig_.latches()[node.index].next;
          const int prev = slot(Aig::node_of(next), it.frame - 1);
          if (prev == 0) {
            stack.push_back({Aig::node_of(next), it.frame - 1});
            continue;
          }
          result = Aig::is_negated(next) ? -prev : prev;
        }
        break;
      case Aig::NodeKind::And: {
        const int a = slot(Aig::node_of(node.left), it.frame);
        const int b = slot(Aig::node_of(node.right), it.frame);
        if (a == 0 || b == 0) {
          if (a == 0) stack.push_back({Aig::node_of(node.left), it.frame});
          if (b == 0) stack.push_back({Aig::node_of(node.right), it.frame});
          continue;
        }
        const int la = Aig::is_negated(node.left) ? -a : a;
        const int lb = Aig::is_negated(node.right) ? -b : b;
        result = solver_.new_var();
        solver_.add_clause({-result, la});
        solver_.add_clause({-result, lb});
        solver_.add_clause({result, -la, -lb});
        break;
      }
    }
    slot(it.node, it.frame) = result;
    stack.pop_back();
  }
  const int v = lit_of_node_[frame][Aig::node_of(lit)];
  return Aig::is_negated(lit) ? -v : v;
}

int Unrolling::latch(std::uint32_t index, std::size_t frame) {
  return literal(aig_.latches()[index].current, frame);
}

int Unrolling::literal_if_encoded(AigLit lit, std::size_t frame) const {
  if (frame >= lit_of_node_.size()) return 0;
  const auto node = Aig::node_of(lit);
  const auto& row = lit_of_node_[frame];
  const int v = node < row.size() ? row[node] : 0;
  return Aig::is_negated(lit) ? -v : v;
}

int Unrolling::input_if_encoded(std::uint32_t index, std::size_t frame) const {
  return literal_if_encoded(aig_.inputs()[index].literal, frame);
}

std::vector<bool> Unrolling::input_values(std::size_t frame) const {
  std::vector<bool> bits(aig_.inputs().size(), false);
  for (std::uint32_t i = 0; i < bits.size(); ++i)
    if (const int l = input_if_encoded(i, frame)) bits[i] = solver_.value(l);
  return bits;
}

void add_frames_differ(Unrolling& frames, const std::vector<std::uint32_t>& latches, std::size_t a,
                       std::size_t b) {
  Solver& solver = frames.solver();
  std::vector<int> differs;
  for (auto l : latches) {
    const int x = frames.latch(l, a), y = frames.latch(l, b);
    if (x == y) continue;
    if (x == -y) return;             // they always differ
    const int d = solver.new_var();  // d -> x != y
    solver.add_clause({-d, x, y});
    solver.add_clause({-d, -x, -y});
    differs.push_back(d);
  }
  solver.add_clause(differs);  // empty when the frames cannot differ: no simple path at all
}

std::vector<std::uint32_t> cone_latches(const Aig& aig, const std::vector<AigLit>& roots) {
  std::vector<bool> seen(aig.nodes().size(), false);
  std::vector<std::uint32_t> stack, latches;
  for (auto r : roots) stack.push_back(Aig::node_of(r));
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (seen[n]) continue;
    seen[n] = true;
    const auto& node = aig.nodes()[n];
    if (node.kind == Aig::NodeKind::And) {
      stack.push_back(Aig::node_of(node.left));
      stack.push_back(Aig::node_of(node.right));
    } else if (node.kind == Aig::NodeKind::Latch) {
      latches.push_back(node.index);
      stack.push_back(Aig::node_of(aig.latches()[node.index].next));
    }
  }
  std::sort(latches.begin(), latches.end());
  return latches;
}

}  // namespace sfcv::engine::sat

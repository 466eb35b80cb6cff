#include "engine/sat/unrolling.hpp"

#include <algorithm>

namespace sfcv::engine::sat {

using semantics::Aig;
using semantics::AigLit;

Unrolling::Unrolling(const Aig& aig, Solver& solver, bool from_initial, bool simplify)
    : aig_(aig), solver_(solver), from_initial_(from_initial), simplify_(simplify) {
  if (!simplify_) return;
  fanout_.assign(aig_.nodes().size(), 0);
  for (const auto& n : aig_.nodes())
    if (n.kind == Aig::NodeKind::And) {
      ++fanout_[Aig::node_of(n.left)];
      ++fanout_[Aig::node_of(n.right)];
    }
  for (const auto& l : aig_.latches()) ++fanout_[Aig::node_of(l.next)];
}

int Unrolling::conjunction(std::vector<int> lits) {
  const int t = solver_.true_lit();
  std::sort(lits.begin(), lits.end());
  lits.erase(std::unique(lits.begin(), lits.end()), lits.end());
  std::erase(lits, t);
  for (int l : lits)
    if (l == -t || std::binary_search(lits.begin(), lits.end(), -l)) return -t;
  if (lits.empty()) return t;
  if (lits.size() == 1) return lits[0];
  if (lits.size() == 2) {  // sorted: the key is unique
    const auto key = (std::uint64_t{static_cast<std::uint32_t>(lits[0])} << 32) |
                     std::uint64_t{static_cast<std::uint32_t>(lits[1])};
    int& pair = pairs_[key];
    if (pair == 0) {
      pair = solver_.new_var();
      solver_.add_clause({-pair, lits[0]});
      solver_.add_clause({-pair, lits[1]});
      solver_.add_clause({pair, -lits[0], -lits[1]});
    }
    return pair;
  }
  int& slot = gates_[lits];
  if (slot != 0) return slot;
  const int r = solver_.new_var();
  std::vector<int> all{r};
  for (int l : lits) {
    solver_.add_clause({-r, l});
    all.push_back(-l);
  }
  solver_.add_clause(all);
  slot = r;
  return r;
}

int Unrolling::ite(int s, int a, int b) {
  const int t = solver_.true_lit();
  if (s < 0) {
    s = -s;
    std::swap(a, b);
  }
  if (s == t) return a;
  if (a == b) return a;
  if (a == t || a == s) return -conjunction({-s, -b});  // s | b
  if (a == -t || a == -s) return conjunction({-s, b});
  if (b == t || b == -s) return -conjunction({s, -a});  // !s | a
  if (b == -t || b == s) return conjunction({s, a});
  int& slot = gates_[{0, s, a, b}];
  if (slot != 0) return slot;
  const int r = solver_.new_var();
  solver_.add_clause({-s, -a, r});
  solver_.add_clause({-s, a, -r});
  solver_.add_clause({s, -b, r});
  solver_.add_clause({s, b, -r});
  solver_.add_clause({-a, -b, r});  // redundant, helps propagation
  solver_.add_clause({a, b, -r});
  slot = r;
  return r;
}

bool Unrolling::ite_shape(std::uint32_t node, AigLit& s, AigLit& a, AigLit& b) const {
  const auto& n = aig_.nodes()[node];
  if (!Aig::is_negated(n.left) || !Aig::is_negated(n.right)) return false;
  const auto x = Aig::node_of(n.left), y = Aig::node_of(n.right);
  const auto& nx = aig_.nodes()[x];
  const auto& ny = aig_.nodes()[y];
  // A node made after the unrolling (x or y past fanout_) has an unknown fan-out: not merged.
  if (nx.kind != Aig::NodeKind::And || ny.kind != Aig::NodeKind::And || x >= fanout_.size() ||
      y >= fanout_.size() || fanout_[x] != 1 || fanout_[y] != 1)
    return false;
  const AigLit xs[2] = {nx.left, nx.right}, ys[2] = {ny.left, ny.right};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (xs[i] == (ys[j] ^ 1u)) {
        s = xs[i];
        a = xs[1 - i];
        b = ys[1 - j];
        return true;
      }
  return false;
}

std::vector<AigLit> Unrolling::tree_leaves(std::uint32_t node, std::size_t frame) {
  constexpr std::size_t kMaxLeaves = 16;  // long clauses propagate poorly
  const auto& n = aig_.nodes()[node];
  std::vector<AigLit> leaves, todo{n.right, n.left};
  while (!todo.empty()) {
    const AigLit l = todo.back();
    todo.pop_back();
    const auto c = Aig::node_of(l);
    const auto& cn = aig_.nodes()[c];
    if (!Aig::is_negated(l) && cn.kind == Aig::NodeKind::And && c < fanout_.size() &&
        fanout_[c] == 1 && literal_if_encoded(l, frame) == 0 &&
        leaves.size() + todo.size() + 2 <= kMaxLeaves) {
      todo.push_back(cn.right);
      todo.push_back(cn.left);
    } else {
      leaves.push_back(l);
    }
  }
  return leaves;
}

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
          if (from_initial_ && simplify_) {
            result = aig_.latches()[node.index].initial ? solver_.true_lit() : -solver_.true_lit();
            break;
          }
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
        if (simplify_) {
          AigLit ss = 0, sa = 0, sb = 0;
          const bool is_ite = ite_shape(it.node, ss, sa, sb);
          const auto leaves =
              is_ite ? std::vector<AigLit>{ss, sa, sb} : tree_leaves(it.node, it.frame);
          bool missing = false;
          for (auto l : leaves)
            if (slot(Aig::node_of(l), it.frame) == 0) {
              stack.push_back({Aig::node_of(l), it.frame});
              missing = true;
            }
          if (missing) continue;
          std::vector<int> lits;
          for (auto l : leaves) {
            const int v = slot(Aig::node_of(l), it.frame);
            lits.push_back(Aig::is_negated(l) ? -v : v);
          }
          // node = !(s & a) & !(!s & b) = !(s ? a : b)
          result = is_ite ? -ite(lits[0], lits[1], lits[2]) : conjunction(std::move(lits));
          break;
        }
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

#include "engine/sat/unrolling.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>

namespace sfcv::engine::sat {

using semantics::Aig;
using semantics::AigLit;

Unrolling::Unrolling(const Aig& aig, Solver& solver, bool from_initial, bool simplify,
                     std::shared_ptr<CutMapping> mapping)
    : aig_(aig),
      solver_(solver),
      from_initial_(from_initial),
      simplify_(simplify),
      mapping_(std::move(mapping)) {
  if (simplify_ && (!mapping_ || &mapping_->aig() != &aig_))
    mapping_ = std::make_shared<CutMapping>(aig_);
}

CutMapping::CutMapping(const Aig& aig) : aig_(aig) {
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

namespace {

// The variables of a 4-input truth table: bit m of kVar[i] is bit i of m.
constexpr std::uint16_t kVar[4] = {0xAAAA, 0xCCCC, 0xF0F0, 0xFF00};

std::uint16_t u16(unsigned v) {
  return static_cast<std::uint16_t>(v & 0xFFFFU);
}
/// The cofactors of f by variable v (v false, v true), as functions of all four variables.
std::uint16_t cofactor0(std::uint16_t f, int v) {
  const unsigned low = f & ~unsigned{kVar[v]};
  return u16(low | (low << (1U << v)));
}
std::uint16_t cofactor1(std::uint16_t f, int v) {
  const unsigned high = f & unsigned{kVar[v]};
  return u16(high | (high >> (1U << v)));
}
bool depends_on(std::uint16_t f, int v) {
  return cofactor0(f, v) != cofactor1(f, v);
}

/// Minato-Morreale: appends an irredundant cover c with on <= c <= upper (cubes as in
/// CutMapping::cover_of, each extending `cube`) and returns c. Requires on <= upper.
std::uint16_t isop(std::uint16_t on, std::uint16_t upper, int var, std::uint8_t cube,
                   std::vector<std::uint8_t>& out) {
  if (on == 0) return 0;
  if (upper == 0xFFFF) {
    out.push_back(cube);
    return 0xFFFF;
  }
  while (!depends_on(on, var) && !depends_on(upper, var)) --var;  // constants returned above
  const std::uint16_t on0 = cofactor0(on, var), on1 = cofactor1(on, var);
  const std::uint16_t up0 = cofactor0(upper, var), up1 = cofactor1(upper, var);
  const auto bit = static_cast<std::uint8_t>(1U << var);
  const std::uint16_t c0 = isop(u16(on0 & ~unsigned{up1}), up0, var - 1, cube | bit, out);
  const std::uint16_t c1 = isop(u16(on1 & ~unsigned{up0}), up1, var - 1,
                                static_cast<std::uint8_t>(cube | bit | bit << 4), out);
  const std::uint16_t rest =
      isop(u16((on0 & ~unsigned{c0}) | (on1 & ~unsigned{c1})), u16(up0 & up1), var - 1, cube, out);
  return u16((c0 & ~unsigned{kVar[var]}) | (c1 & kVar[var]) | rest);
}

}  // namespace

const std::vector<std::uint8_t>& CutMapping::cover_of(std::uint16_t truth) {
  auto [it, added] = covers_.try_emplace(truth);
  if (added) isop(truth, truth, 3, 0, it->second);
  return it->second;
}

int CutMapping::clauses_of(std::uint16_t truth) {
  return static_cast<int>(cover_of(truth).size() + cover_of(u16(~unsigned{truth})).size());
}

int Unrolling::gate(std::uint16_t truth, const std::vector<int>& lits) {
  const int t = solver_.true_lit();
  // The distinct solver variables the leaves read; constants are cofactored away.
  std::vector<int> vars;
  for (int l : lits)
    if (std::abs(l) != t) vars.push_back(std::abs(l));
  std::sort(vars.begin(), vars.end());
  vars.erase(std::unique(vars.begin(), vars.end()), vars.end());
  // The function of `vars` (at most four), then of the variables it depends on alone.
  auto rebase = [&](const std::vector<int>& over) {
    unsigned out = 0;
    for (unsigned m = 0; m < 16; ++m) {
      unsigned leaf_minterm = 0;
      for (std::size_t i = 0; i < lits.size(); ++i) {
        const int l = lits[i];
        bool value;
        if (std::abs(l) == t) {
          value = l > 0;
        } else {
          const auto at = std::lower_bound(over.begin(), over.end(), std::abs(l)) - over.begin();
          value = at < static_cast<std::ptrdiff_t>(over.size()) && over[at] == std::abs(l) &&
                  ((m >> at) & 1U);
          if (l < 0) value = !value;
        }
        if (value) leaf_minterm |= 1U << i;
      }
      if ((truth >> leaf_minterm) & 1U) out |= 1U << m;
    }
    return u16(out);
  };
  std::uint16_t f = rebase(vars);
  std::vector<int> support;
  for (std::size_t i = 0; i < vars.size(); ++i)
    if (depends_on(f, static_cast<int>(i))) support.push_back(vars[i]);
  if (support.size() != vars.size()) f = rebase(support);
  const auto n = support.size();
  if (n == 0) return f & 1U ? t : -t;
  // One minterm of f (or of !f) over the support: an AND of literals (or its negation).
  const auto ones = std::popcount(unsigned{f});
  const int one_minterm = 16 >> n;
  if (ones == one_minterm || ones == 16 - one_minterm) {
    const bool negated = ones != one_minterm;
    const unsigned g = negated ? ~unsigned{f} : f;
    const unsigned m = static_cast<unsigned>(std::countr_zero(g));
    std::vector<int> and_lits;
    for (std::size_t i = 0; i < n; ++i)
      and_lits.push_back((m >> i) & 1U ? support[i] : -support[i]);
    const int r = conjunction(std::move(and_lits));
    return negated ? -r : r;
  }
  // A fresh gate in the polarity false on all-false inputs (f and !f share one variable).
  const bool negated = f & 1U;
  if (negated) f = u16(~unsigned{f});
  std::vector<int> key{0, f};
  key.insert(key.end(), support.begin(), support.end());
  int& slot = gates_[key];
  if (slot == 0) {
    const int r = solver_.new_var();
    std::vector<int> clause;
    for (const bool positive : {true, false})
      for (const std::uint8_t cube : mapping_->cover_of(positive ? f : u16(~unsigned{f}))) {
        clause.assign(1, positive ? r : -r);  // cube -> r (cube of f), cube -> !r (of !f)
        for (std::size_t i = 0; i < n; ++i)
          if ((cube >> i) & 1U) clause.push_back((cube >> (i + 4)) & 1U ? -support[i] : support[i]);
        solver_.add_clause(clause);
      }
    slot = r;
  }
  return negated ? -slot : slot;
}

const CutMapping::Cut& CutMapping::best(std::uint32_t node) {
  if (cuts_.size() < aig_.nodes().size()) cuts_.resize(aig_.nodes().size());
  std::vector<std::uint32_t> stack{node};  // iterative post-order: cones may be deep
  while (!stack.empty()) {
    const auto n = stack.back();
    if (!cuts_[n].empty()) {
      stack.pop_back();
      continue;
    }
    const auto& nd = aig_.nodes()[n];
    bool missing = false;
    for (const AigLit in : {nd.left, nd.right}) {
      const auto c = Aig::node_of(in);
      if (aig_.nodes()[c].kind == Aig::NodeKind::And && cuts_[c].empty()) {
        stack.push_back(c);
        missing = true;
      }
    }
    if (missing) continue;
    enumerate(n);
    stack.pop_back();
  }
  return cuts_[node].front();
}

void CutMapping::enumerate(std::uint32_t node) {
  constexpr std::size_t kCutsPerNode = 6;
  const auto& nd = aig_.nodes()[node];
  // A leaf's share of the cone behind it: its best cut's flow over its readers.
  auto leaf_flow = [this](std::uint32_t c) -> float {
    if (aig_.nodes()[c].kind != Aig::NodeKind::And) return 0;
    const auto readers = c < fanout_.size() ? std::max<std::uint32_t>(fanout_[c], 1) : 1;
    return cuts_[c].front().flow / static_cast<float>(readers);
  };
  // A fan-in's stored cuts and its trivial cut, in place (no copy of the stored vector).
  struct FaninCuts {
    std::array<Cut, kCutsPerNode + 1> cut;
    std::size_t size = 0;
    const Cut* begin() const { return cut.data(); }
    const Cut* end() const { return cut.data() + size; }
  };
  auto fanin_cuts = [&](AigLit in) {
    const auto c = Aig::node_of(in);
    FaninCuts out;
    if (aig_.nodes()[c].kind == Aig::NodeKind::And)
      for (const auto& k : cuts_[c])
        if (out.size < kCutsPerNode) out.cut[out.size++] = k;
    Cut& trivial = out.cut[out.size++];
    trivial = Cut{};
    trivial.leaves[0] = c;
    trivial.size = 1;
    trivial.truth = kVar[0];
    return out;
  };
  // `truth` over `from`'s leaves, as a function of `to`'s (a superset).
  auto stretch = [](const Cut& from, const Cut& to) {
    unsigned at[4] = {0, 0, 0, 0};
    for (unsigned i = 0, j = 0; i < from.size; ++i) {
      while (to.leaves[j] != from.leaves[i]) ++j;
      at[i] = j;
    }
    unsigned out = 0;
    for (unsigned m = 0; m < 16; ++m) {
      unsigned fm = 0;
      for (unsigned i = 0; i < from.size; ++i) fm |= ((m >> at[i]) & 1U) << i;
      out |= ((from.truth >> fm) & 1U) << m;
    }
    return out;
  };
  const auto left = fanin_cuts(nd.left), right = fanin_cuts(nd.right);
  std::vector<Cut> cuts;
  for (const auto& a : left)
    for (const auto& b : right) {
      Cut c;
      std::size_t i = 0, j = 0;
      bool fits = true;
      while (i < a.size || j < b.size) {
        std::uint32_t next;
        if (j == b.size || (i < a.size && a.leaves[i] < b.leaves[j])) {
          next = a.leaves[i++];
        } else if (i == a.size || b.leaves[j] < a.leaves[i]) {
          next = b.leaves[j++];
        } else {
          next = a.leaves[i++];
          ++j;
        }
        if (c.size == 4) {
          fits = false;
          break;
        }
        c.leaves[c.size++] = next;
      }
      if (!fits) continue;
      const unsigned fa = stretch(a, c) ^ (Aig::is_negated(nd.left) ? 0xFFFFU : 0U);
      const unsigned fb = stretch(b, c) ^ (Aig::is_negated(nd.right) ? 0xFFFFU : 0U);
      c.truth = u16(fa & fb);
      c.flow = static_cast<float>(clauses_of(c.truth));
      for (std::uint8_t k = 0; k < c.size; ++k) c.flow += leaf_flow(c.leaves[k]);
      cuts.push_back(c);
    }
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) {
    if (x.flow != y.flow) return x.flow < y.flow;
    if (x.size != y.size) return x.size < y.size;
    return x.leaves < y.leaves;
  });
  // One cut per leaf set (the same function): the first, then the best few.
  auto same_leaves = [](const Cut& x, const Cut& y) {
    return x.size == y.size && x.leaves == y.leaves;
  };
  std::vector<Cut> kept;
  for (const auto& c : cuts) {
    if (kept.size() == kCutsPerNode) break;
    if (std::none_of(kept.begin(), kept.end(), [&](const Cut& k) { return same_leaves(k, c); }))
      kept.push_back(c);
  }
  cuts_[node] = std::move(kept);
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
          const auto& cut = mapping_->best(it.node);
          bool missing = false;
          for (std::uint8_t k = 0; k < cut.size; ++k)
            if (slot(cut.leaves[k], it.frame) == 0) {
              stack.push_back({cut.leaves[k], it.frame});
              missing = true;
            }
          if (missing) continue;
          std::vector<int> lits;
          for (std::uint8_t k = 0; k < cut.size; ++k) lits.push_back(slot(cut.leaves[k], it.frame));
          result = gate(cut.truth, lits);
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

#include "engine/explicit/ltl_checker.hpp"

#include <algorithm>
#include <deque>
#include <unordered_map>

#include "logic/formula.hpp"
#include "logic/ltl_automaton.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

namespace {

constexpr std::uint64_t kStutter = ~std::uint64_t{0};  ///< the self-loop of a deadlock state
constexpr std::uint32_t kNoProductState = ~0U;

/// The product of the graph and the automaton, built as far as it is explored.
class Product {
 public:
  Product(CtlChecker& checker, const logic::BuchiAutomaton& aut,
          const std::vector<logic::FormulaPtr>& fairness, const model::Budget& budget, bool stutter)
      : g_(checker.graph()), aut_(aut), budget_(budget), stutter_(stutter) {
    // A node's label, as the set of graph states satisfying all of it.
    for (const auto& node : aut.nodes) {
      StateSet ok(g_.num_states(), 1);
      for (const auto& f : node.label) {
        const auto& s = checker.sat(f);
        for (std::size_t i = 0; i < ok.size(); ++i) ok[i] = ok[i] && s[i];
      }
      labels_.push_back(std::move(ok));
    }
    for (const auto& f : fairness) fair_.push_back(checker.sat(f));
    num_sets_ = aut.num_sets + static_cast<std::uint32_t>(fair_.size());
  }

  struct Step {
    std::uint32_t to;
    std::uint64_t edge;
  };

  std::uint32_t size() const { return static_cast<std::uint32_t>(pairs_.size()); }
  std::uint32_t num_sets() const { return num_sets_; }
  std::uint32_t state(std::uint32_t v) const { return pairs_[v].first; }

  std::vector<std::uint32_t> initial() {
    std::vector<std::uint32_t> out;
    for (auto s : g_.initial_states())
      for (auto q : aut_.initial)
        if (labels_[q][s]) out.push_back(intern(s, q));
    return out;
  }

  std::vector<Step> successors(std::uint32_t v) {
    // Plain copies: a lambda may not capture a structured binding before C++20 in clang 15.
    const auto s = pairs_[v].first;
    const auto q = pairs_[v].second;
    std::vector<Step> out;
    auto add = [&](std::uint32_t t, std::uint64_t e) {
      for (auto q2 : aut_.nodes[q].successors)
        if (labels_[q2][t]) out.push_back({intern(t, q2), e});
    };
    if (!g_.expanded(s)) return out;  // beyond a limit: nothing known
    if (g_.edges_begin(s) == g_.edges_end(s)) {
      if (stutter_) add(s, kStutter);
      return out;
    }
    for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) add(g_.target(e), e);
    return out;
  }

  /// The acceptance sets product state v belongs to.
  void mark(std::uint32_t v, std::vector<bool>& seen) const {
    const auto [s, q] = pairs_[v];
    for (auto j : aut_.nodes[q].accepting) seen[j] = true;
    for (std::size_t k = 0; k < fair_.size(); ++k)
      if (fair_[k][s]) seen[aut_.num_sets + k] = true;
  }
  bool in_set(std::uint32_t v, std::uint32_t j) const {
    const auto [s, q] = pairs_[v];
    if (j < aut_.num_sets) {
      const auto& acc = aut_.nodes[q].accepting;
      return std::find(acc.begin(), acc.end(), j) != acc.end();
    }
    return fair_[j - aut_.num_sets][s] != 0;
  }

 private:
  std::uint32_t intern(std::uint32_t s, std::uint32_t q) {
    const std::uint64_t key = (std::uint64_t{s} << 32) | q;
    auto [it, fresh] = ids_.try_emplace(key, static_cast<std::uint32_t>(pairs_.size()));
    if (fresh) {
      pairs_.emplace_back(s, q);
      // --max-states bounds the graph, and so the product (at most states x nodes); memory is
      // what the product can still exhaust (a pair, its hash entry and the search's arrays).
      constexpr std::uint64_t kBytesPerPair = 64;
      if (budget_.max_memory_bytes > 0 && pairs_.size() * kBytesPerPair > budget_.max_memory_bytes)
        throw LimitReached(Limit::Memory, "the LTL product exceeded the memory limit at " +
                                              std::to_string(pairs_.size()) + " states");
    }
    return it->second;
  }

  const ReachableSituationGraph& g_;
  const logic::BuchiAutomaton& aut_;
  const model::Budget& budget_;
  bool stutter_;
  std::vector<StateSet> labels_;
  std::vector<StateSet> fair_;
  std::uint32_t num_sets_ = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
  std::unordered_map<std::uint64_t, std::uint32_t> ids_;
};

/// Tarjan's SCC algorithm over the product, iteratively, stopping at the first non-trivial SCC
/// that meets every acceptance set. Returns its members (empty: none exists).
std::vector<std::uint32_t> accepting_scc(Product& product, const model::Budget& budget) {
  std::vector<std::uint32_t> index, low;
  std::vector<bool> on_stack;
  std::vector<std::uint32_t> stack;
  struct Frame {
    std::uint32_t v;
    std::vector<Product::Step> next;
    std::size_t i = 0;
    bool self_loop = false;
  };
  std::vector<Frame> frames;
  std::uint32_t counter = 0;
  model::BudgetPoll poll(budget, 1024);
  auto grow = [&] {
    index.resize(product.size(), kNoProductState);
    low.resize(product.size(), kNoProductState);
    on_stack.resize(product.size(), false);
  };
  auto open = [&](std::uint32_t v) {
    grow();
    index[v] = low[v] = counter++;
    stack.push_back(v);
    on_stack[v] = true;
    frames.push_back({v, product.successors(v)});
    grow();
  };
  for (auto root : product.initial()) {
    grow();
    if (index[root] != kNoProductState) continue;
    open(root);
    while (!frames.empty()) {
      if (poll.tick()) budget.check_time("searching the LTL product");
      auto& f = frames.back();
      if (f.i < f.next.size()) {
        const auto w = f.next[f.i++].to;
        if (w == f.v) f.self_loop = true;
        if (index[w] == kNoProductState) {
          open(w);
        } else if (on_stack[w]) {
          low[f.v] = std::min(low[f.v], index[w]);
        }
        continue;
      }
      const auto v = f.v;
      const bool self_loop = f.self_loop;
      frames.pop_back();
      if (!frames.empty()) low[frames.back().v] = std::min(low[frames.back().v], low[v]);
      if (low[v] != index[v]) continue;
      std::vector<std::uint32_t> scc;
      std::uint32_t w;
      do {
        w = stack.back();
        stack.pop_back();
        on_stack[w] = false;
        scc.push_back(w);
      } while (w != v);
      if (scc.size() == 1 && !self_loop) continue;
      std::vector<bool> seen(product.num_sets(), false);
      for (auto x : scc) product.mark(x, seen);
      if (std::all_of(seen.begin(), seen.end(), [](bool b) { return b; })) return scc;
    }
  }
  return {};
}

struct Hop {
  std::uint32_t v;
  std::uint64_t edge;  ///< into v; kStutter, or kNoEdge for the first
};
constexpr std::uint64_t kNoEdge = kStutter - 1;

/// Shortest path (BFS) from one of `sources` through `allowed` product states to a state
/// satisfying `goal`, taking at least one edge (the goal may be a source: a cycle). Returns the
/// hops after the source, and the source in `source`; empty when there is none.
template <class Allowed, class Goal>
std::vector<Hop> bfs(Product& product, const std::vector<std::uint32_t>& sources, Allowed allowed,
                     Goal goal, std::uint32_t& source) {
  std::unordered_map<std::uint32_t, Hop> parent;  // v -> (its predecessor, the edge)
  std::unordered_map<std::uint32_t, bool> is_root;
  std::deque<std::uint32_t> queue;
  for (auto s : sources) {
    is_root[s] = true;
    queue.push_back(s);
  }
  while (!queue.empty()) {
    const auto u = queue.front();
    queue.pop_front();
    for (const auto& step : product.successors(u)) {
      if (!allowed(step.to)) continue;
      if (goal(step.to)) {
        std::vector<Hop> path{{step.to, step.edge}};
        auto x = u;
        while (!is_root.count(x)) {
          const auto p = parent.at(x);
          path.push_back({x, p.edge});
          x = p.v;
        }
        source = x;
        std::reverse(path.begin(), path.end());
        return path;
      }
      if (is_root.count(step.to) || parent.count(step.to)) continue;
      parent.emplace(step.to, Hop{u, step.edge});
      queue.push_back(step.to);
    }
  }
  return {};
}

/// The lasso as a trace: graph states with the inputs read and the transitions fired on the
/// way into each; the last step repeats steps[loop_start].
logic::Trace to_trace(const ReachableSituationGraph& g, const Product& product, std::uint32_t first,
                      const std::vector<Hop>& hops, std::size_t loop_start) {
  const auto& inputs = g.system().inputs();
  logic::Trace t;
  t.kind = logic::TraceKind::Counterexample;
  std::vector<std::int64_t> previous;
  bool stutters = false;
  auto push = [&](std::uint32_t v, std::uint64_t edge) {
    logic::TraceStep step;
    const auto s = product.state(v);
    const auto view = g.states().at(s);
    step.state.assign(view.begin(), view.end());
    if (edge == kNoEdge) {
      const auto& init = g.initial_states();
      const auto it = std::find(init.begin(), init.end(), s);
      step.inputs = logic::pick_inputs(it == init.end() ? semantics::InputCondition::always()
                                                        : g.initial_condition(it - init.begin()),
                                       inputs, {});
    } else if (edge == kStutter) {
      step.inputs = previous;
      stutters = true;
    } else {
      step.inputs = logic::pick_inputs(g.condition(edge), inputs, previous);
      const auto fired = g.fired(edge);
      step.fired.assign(fired.begin(), fired.end());
    }
    previous = step.inputs;
    t.steps.push_back(std::move(step));
  };
  push(first, kNoEdge);
  for (const auto& h : hops) push(h.v, h.edge);
  t.loop_start = loop_start;
  if (stutters)
    t.note = "the loop stays in a state without a successor: a deadlock repeats forever";
  return t;
}

}  // namespace

logic::PropertyResult check_ltl(CtlChecker& checker, const logic::Property& p,
                                const std::vector<logic::FormulaPtr>& fairness,
                                const model::Budget& budget, logic::DeadlockPaths deadlocks) {
  const auto& g = checker.graph();
  logic::PropertyResult r;
  r.name = p.name;
  r.formula = logic::to_string(p.formula);
  r.where = p.where;
  if (g.initial_states().empty()) {
    r.verdict = logic::Verdict::Unknown;
    r.message =
        "no initial state: the assumptions exclude every initial situation, or none is stable (see "
        "the instability check)";
    return r;
  }
  // A run violating p is an accepting run of the automaton of !p.
  const auto aut = logic::ltl_to_buchi(logic::make_not(p.formula), budget);
  Product product(checker, aut, fairness, budget, deadlocks == logic::DeadlockPaths::Stutter);
  const auto scc = accepting_scc(product, budget);
  if (scc.empty()) {
    if (g.complete()) {
      r.verdict = logic::Verdict::Holds;
    } else {
      r.verdict = logic::Verdict::Unknown;
      r.message = "exploration stopped at the " + g.limit_reached() + " limit after " +
                  std::to_string(g.num_states()) + " states (no counterexample among them)";
    }
    return r;
  }
  std::vector<bool> in_scc(product.size(), false);
  for (auto v : scc) in_scc[v] = true;
  auto inside = [&](std::uint32_t v) { return v < in_scc.size() && in_scc[v]; };
  auto any = [](std::uint32_t) { return true; };
  // Prefix: an initial state to the SCC (zero edges when an initial state is in it).
  const auto init = product.initial();
  std::uint32_t first = kNoProductState;
  std::vector<Hop> hops;
  for (auto v : init)
    if (inside(v)) first = v;
  if (first == kNoProductState) hops = bfs(product, init, any, inside, first);
  if (first == kNoProductState)
    throw InternalError("check_ltl: the accepting SCC is not reachable");
  const std::size_t loop_start = hops.size();
  const std::uint32_t entry = hops.empty() ? first : hops.back().v;
  // Cycle: from the entry, through a state of every acceptance set, back to the entry.
  auto at = entry;
  for (std::uint32_t j = 0; j < product.num_sets(); ++j) {
    bool met = product.in_set(entry, j);
    for (std::size_t k = loop_start; k < hops.size() && !met; ++k)
      met = product.in_set(hops[k].v, j);
    if (met) continue;
    std::uint32_t src = kNoProductState;
    auto leg = bfs(
        product, {at}, inside, [&](std::uint32_t v) { return product.in_set(v, j); }, src);
    hops.insert(hops.end(), leg.begin(), leg.end());
    at = hops.back().v;
  }
  std::uint32_t src = kNoProductState;
  auto back = bfs(
      product, {at}, inside, [&](std::uint32_t v) { return v == entry; }, src);
  if (back.empty()) throw InternalError("check_ltl: no cycle in the accepting SCC");
  hops.insert(hops.end(), back.begin(), back.end());
  r.verdict = logic::Verdict::Violated;
  r.trace = to_trace(g, product, first, hops, loop_start);
  r.trace->marked = logic::atom_observables(*p.formula);
  return r;
}

}  // namespace sfcv::engine

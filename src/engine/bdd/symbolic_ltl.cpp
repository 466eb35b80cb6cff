#include "engine/bdd/symbolic_ltl.hpp"

#include <algorithm>
#include <stdexcept>

#include "logic/formula.hpp"
#include "logic/ltl_automaton.hpp"

namespace sfcv::engine {

using bdd::Bdd;

namespace {

/// A set of product states: per automaton node, the system states paired with it.
using Sets = std::vector<Bdd>;
using State = std::vector<semantics::StateWord>;

struct ProductState {
  State s;
  std::uint32_t q = 0;
};

class Product {
 public:
  Product(SymbolicSystem& sys, SymbolicCtl& ctl, const Bdd& reached,
          const logic::BuchiAutomaton& aut, const std::vector<logic::FormulaPtr>& fairness,
          bool stutter, const model::Budget& budget)
      : sys_(sys), aut_(aut), budget_(budget), n_(aut.nodes.size()) {
    dead_ = stutter ? reached & !sys.has_successor() : Bdd::constant(false);
    predecessors_.resize(n_);
    for (std::uint32_t q = 0; q < n_; ++q) {
      Bdd ok = reached;
      for (const auto& f : aut.nodes[q].label) ok = ok & ctl.sat(f);
      labels_.push_back(ok);
      for (auto q2 : aut.nodes[q].successors) predecessors_[q2].push_back(q);
    }
    // One fairness set per acceptance set of the automaton, then one per constraint.
    for (std::uint32_t j = 0; j < aut.num_sets; ++j) {
      Sets f(n_, Bdd::constant(false));
      for (std::uint32_t q = 0; q < n_; ++q) {
        const auto& acc = aut.nodes[q].accepting;
        if (std::find(acc.begin(), acc.end(), j) != acc.end()) f[q] = labels_[q];
      }
      fair_.push_back(std::move(f));
    }
    for (const auto& c : fairness) {
      const Bdd states = ctl.sat(c);
      Sets f(n_);
      for (std::uint32_t q = 0; q < n_; ++q) f[q] = labels_[q] & states;
      fair_.push_back(std::move(f));
    }
  }

  const Sets& all() const { return labels_; }
  const std::vector<Sets>& fair() const { return fair_; }

  Sets initial() const {
    Sets out(n_, Bdd::constant(false));
    for (auto q : aut_.initial) out[q] = labels_[q] & sys_.initial();
    return out;
  }

  /// Product states with a successor in `v`.
  Sets pre(const Sets& v) const {
    tick();
    std::vector<Bdd> one(n_);
    std::vector<bool> done(n_, false);
    Sets out(n_, Bdd::constant(false));
    for (std::uint32_t q = 0; q < n_; ++q) {
      Bdd acc = Bdd::constant(false);
      for (auto q2 : aut_.nodes[q].successors) {
        if (v[q2].is_false()) continue;
        if (!done[q2]) {
          one[q2] = sys_.preimage(v[q2]) | (v[q2] & dead_);
          done[q2] = true;
        }
        acc = acc | one[q2];
      }
      out[q] = labels_[q] & acc;
    }
    return out;
  }

  /// The successors of the product states in `v`.
  Sets post(const Sets& v) const {
    tick();
    std::vector<Bdd> one(n_);
    for (std::uint32_t q = 0; q < n_; ++q)
      if (!v[q].is_false()) one[q] = sys_.image(v[q]) | (v[q] & dead_);
    Sets out(n_, Bdd::constant(false));
    for (std::uint32_t q2 = 0; q2 < n_; ++q2) {
      Bdd acc = Bdd::constant(false);
      for (auto q : predecessors_[q2])
        if (!v[q].is_false()) acc = acc | one[q];
      out[q2] = labels_[q2] & acc;
    }
    return out;
  }

  /// Fair EG true (Emerson-Lei): nu Z. AND_j EX E[true U (Z & F_j)], or nu Z. EX Z without
  /// fairness sets: the product states with an infinite path visiting every set infinitely often.
  Sets fair_eg() const {
    Sets z = labels_;
    for (;;) {
      Sets next = labels_;
      if (fair_.empty()) next = meet(next, pre(z));
      for (const auto& f : fair_) {
        const Sets target = meet(z, f);
        Sets u = target;
        for (;;) {
          const Sets step = join(target, pre(u));
          if (step == u) break;
          u = step;
        }
        next = meet(next, pre(u));
      }
      if (next == z) return z;
      z = next;
    }
  }

  Sets meet(const Sets& a, const Sets& b) const {
    Sets out(n_);
    for (std::size_t q = 0; q < n_; ++q) out[q] = a[q] & b[q];
    return out;
  }
  Sets join(const Sets& a, const Sets& b) const {
    Sets out(n_);
    for (std::size_t q = 0; q < n_; ++q) out[q] = a[q] | b[q];
    return out;
  }
  Sets minus(const Sets& a, const Sets& b) const {
    Sets out(n_);
    for (std::size_t q = 0; q < n_; ++q) out[q] = a[q] & !b[q];
    return out;
  }
  static bool empty(const Sets& v) {
    return std::all_of(v.begin(), v.end(), [](const Bdd& b) { return b.is_false(); });
  }
  bool contains(const Sets& v, const ProductState& p) const {
    return !(v[p.q] & sys_.singleton(p.s)).is_false();
  }
  Sets singleton(const ProductState& p) const {
    Sets out(n_, Bdd::constant(false));
    out[p.q] = sys_.singleton(p.s);
    return out;
  }
  ProductState pick(const Sets& v) const {
    for (std::uint32_t q = 0; q < n_; ++q)
      if (!v[q].is_false()) return {sys_.pick(v[q]), q};
    throw std::logic_error("symbolic LTL: a state picked from an empty set");
  }

 private:
  void tick() const { budget_.check_time("checking LTL on the BDD product"); }

  SymbolicSystem& sys_;
  const logic::BuchiAutomaton& aut_;
  const model::Budget& budget_;
  std::size_t n_;
  Bdd dead_;
  Sets labels_;
  std::vector<Sets> fair_;
  std::vector<std::vector<std::uint32_t>> predecessors_;
};

/// A shortest path from `src` through `through` to `target` (at least one edge with
/// `min_one_edge`): the states after `src`; false when there is none.
bool shortest(const Product& p, const ProductState& src, const Sets& through, const Sets& target,
              bool min_one_edge, std::vector<ProductState>& path) {
  path.clear();
  if (!min_one_edge && p.contains(target, src)) return true;
  std::vector<Sets> rings{target};
  Sets reached = target;
  for (;;) {
    const Sets pre = p.pre(rings.back());
    if (p.contains(pre, src)) {
      ProductState at = src;
      for (std::size_t j = rings.size(); j-- > 0;) {
        at = p.pick(p.meet(p.post(p.singleton(at)), rings[j]));
        path.push_back(at);
      }
      return true;
    }
    const Sets next = p.minus(p.meet(pre, through), reached);
    if (Product::empty(next)) return false;
    reached = p.join(reached, next);
    rings.push_back(next);
  }
}

bool same(const ProductState& a, const ProductState& b) {
  return a.q == b.q && a.s == b.s;
}

/// From a state of `region` (fair EG true): rounds through every fairness set and back (Clarke,
/// Grumberg, McMillan and Zhao). A round that cannot return ends in a lower SCC of the region,
/// where the next round starts, so the search ends.
std::vector<ProductState> fair_lasso(const Product& p, const Sets& region, ProductState start,
                                     std::size_t& loop_start) {
  std::vector<ProductState> run{std::move(start)};
  for (;;) {
    const std::size_t loop_at = run.size() - 1;
    const ProductState round = run.back();
    std::vector<ProductState> path;
    for (const auto& f : p.fair()) {
      bool met = false;
      for (std::size_t k = loop_at; k < run.size() && !met; ++k) met = p.contains(f, run[k]);
      if (met) continue;
      if (!shortest(p, run.back(), region, p.meet(region, f), false, path))
        throw std::logic_error("symbolic LTL: a fairness set out of reach in fair EG");
      run.insert(run.end(), path.begin(), path.end());
    }
    if (shortest(p, run.back(), region, p.singleton(round), true, path)) {
      run.insert(run.end(), path.begin(), path.end());
      loop_start = loop_at;
      return run;
    }
    if (!same(run.back(), round)) continue;
    const Sets succ = p.meet(p.post(p.singleton(run.back())), region);
    if (Product::empty(succ)) throw std::logic_error("symbolic LTL: a dead end in fair EG");
    run.push_back(p.pick(succ));
  }
}

}  // namespace

std::optional<SymbolicRun> symbolic_ltl_counterexample(SymbolicSystem& sys, SymbolicCtl& ctl,
                                                       const Bdd& reached,
                                                       const SymbolicLtlQuery& q,
                                                       const model::Budget& budget) {
  // A run violating the formula is an accepting run of the automaton of its negation.
  const auto aut = logic::ltl_to_buchi(logic::make_not(q.formula), budget);
  const Product product(sys, ctl, reached, aut, q.fairness, q.stutter, budget);
  const Sets fair = product.fair_eg();
  const Sets bad = product.meet(product.initial(), fair);
  if (Product::empty(bad)) return std::nullopt;
  std::size_t loop_start = 0;
  const auto lasso = fair_lasso(product, fair, product.pick(bad), loop_start);
  SymbolicRun run;
  for (const auto& s : lasso) run.states.push_back(s.s);
  run.loop_start = loop_start;
  return run;
}

}  // namespace sfcv::engine

#include "logic/ltl_automaton.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "logic/formula.hpp"
#include "model/errors.hpp"

namespace sfcv::logic {

namespace {

// Negation normal form over X, U, R with propositional leaves, hash-consed so that equal
// subformulas get one id (the tableau compares sets of ids).
enum class Kind { True, False, Leaf, And, Or, Next, Until, Release };

struct NnfNode {
  Kind kind = Kind::True;
  int a = -1, b = -1;
  FormulaPtr leaf;  ///< Leaf: a propositional formula, negated already when needed
};

class Nnf {
 public:
  int of(const FormulaPtr& f, bool negated) {
    if (f->op == Op::Not) return of(f->args[0], !negated);  // so that !a is a's complement
    if (is_propositional(*f)) {
      if (f->op == Op::True || f->op == Op::False)
        return make((f->op == Op::True) != negated ? Kind::True : Kind::False);
      // Keyed by text: `a & !a` parses `a` twice, and equal text resolves to one observable.
      const auto key = std::make_pair(to_string(*f), negated);
      if (auto it = leaves_.find(key); it != leaves_.end()) return it->second;
      NnfNode n;
      n.kind = Kind::Leaf;
      n.leaf = negated ? make_not(f) : f;
      nodes_.push_back(std::move(n));
      const int id = static_cast<int>(nodes_.size() - 1);
      leaves_.emplace(key, id);
      return id;
    }
    const auto& x = f->args;
    switch (f->op) {
      case Op::Not:
        return of(x[0], !negated);
      case Op::And:
        return make(negated ? Kind::Or : Kind::And, of(x[0], negated), of(x[1], negated));
      case Op::Or:
        return make(negated ? Kind::And : Kind::Or, of(x[0], negated), of(x[1], negated));
      case Op::Implies:  // !a | b
        return negated ? make(Kind::And, of(x[0], false), of(x[1], true))
                       : make(Kind::Or, of(x[0], true), of(x[1], false));
      case Op::Iff:
      case Op::Xor: {
        // a <-> b = (a & b) | (!a & !b); a xor b = (a & !b) | (!a & b)
        const bool same = (f->op == Op::Iff) != negated;
        return make(Kind::Or, make(Kind::And, of(x[0], false), of(x[1], !same)),
                    make(Kind::And, of(x[0], true), of(x[1], same)));
      }
      case Op::X:
        return make(Kind::Next, of(x[0], negated));
      case Op::F:  // F a = true U a;  !F a = false R !a
        return negated ? make(Kind::Release, make(Kind::False), of(x[0], true))
                       : make(Kind::Until, make(Kind::True), of(x[0], false));
      case Op::G:  // G a = false R a;  !G a = true U !a
        return negated ? make(Kind::Until, make(Kind::True), of(x[0], true))
                       : make(Kind::Release, make(Kind::False), of(x[0], false));
      case Op::U:  // !(a U b) = !a R !b
        return make(negated ? Kind::Release : Kind::Until, of(x[0], negated), of(x[1], negated));
      case Op::R:
        return make(negated ? Kind::Until : Kind::Release, of(x[0], negated), of(x[1], negated));
      case Op::W:  // a W b = b R (a | b);  !(a W b) = !b U (!a & !b)
        return negated ? make(Kind::Until, of(x[1], true),
                              make(Kind::And, of(x[0], true), of(x[1], true)))
                       : make(Kind::Release, of(x[1], false),
                              make(Kind::Or, of(x[0], false), of(x[1], false)));
      default:
        throw InternalError("ltl_to_buchi: a CTL operator in an LTL formula: " + to_string(*f));
    }
  }
  const NnfNode& operator[](int id) const { return nodes_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return nodes_.size(); }
  /// The id of `leaf`'s complement when it exists (p and !p in one node is a contradiction).
  int complement(int id) const {
    for (const auto& [key, other] : leaves_)
      if (other == id) {
        auto it = leaves_.find({key.first, !key.second});
        return it == leaves_.end() ? -1 : it->second;
      }
    return -1;
  }

 private:
  int make(Kind k, int a = -1, int b = -1) {
    // Light simplification keeps the tableau small: true & x = x, false | x = x, ...
    if (k == Kind::And || k == Kind::Or) {
      const Kind unit = k == Kind::And ? Kind::True : Kind::False;
      const Kind zero = k == Kind::And ? Kind::False : Kind::True;
      if ((*this)[a].kind == unit) return b;
      if ((*this)[b].kind == unit) return a;
      if ((*this)[a].kind == zero || (*this)[b].kind == zero) return make(zero);
      if (a == b) return a;
    }
    const auto key = std::make_tuple(k, a, b);
    if (auto it = ids_.find(key); it != ids_.end()) return it->second;
    NnfNode n;
    n.kind = k;
    n.a = a;
    n.b = b;
    nodes_.push_back(n);
    const int id = static_cast<int>(nodes_.size() - 1);
    ids_.emplace(key, id);
    return id;
  }

  std::vector<NnfNode> nodes_;
  std::map<std::tuple<Kind, int, int>, int> ids_;
  std::map<std::pair<std::string, bool>, int> leaves_;
};

using IdSet = std::set<int>;

struct TableauNode {
  std::set<int> incoming;  ///< ids of finished nodes; kInit for the initial pseudo-node
  IdSet fresh, old, next;  ///< GPVW's New, Old and Next
};

constexpr int kInit = -1;

}  // namespace

BuchiAutomaton ltl_to_buchi(const FormulaPtr& f, const model::Budget& budget) {
  Nnf nnf;
  const int root = nnf.of(f, false);
  std::vector<TableauNode> done;
  std::vector<TableauNode> work;
  work.push_back({{kInit}, {root}, {}, {}});
  model::BudgetPoll poll(budget, 64);
  while (!work.empty()) {
    if (poll.tick()) budget.check_time("building the LTL automaton");
    TableauNode node = std::move(work.back());
    work.pop_back();
    if (node.fresh.empty()) {
      auto same = std::find_if(done.begin(), done.end(), [&](const TableauNode& q) {
        return q.old == node.old && q.next == node.next;
      });
      if (same != done.end()) {
        same->incoming.insert(node.incoming.begin(), node.incoming.end());
        continue;
      }
      const int id = static_cast<int>(done.size());
      work.push_back({{id}, node.next, {}, {}});
      done.push_back(std::move(node));
      continue;
    }
    const int eta = *node.fresh.begin();
    node.fresh.erase(node.fresh.begin());
    if (node.old.count(eta)) {
      work.push_back(std::move(node));
      continue;
    }
    const auto& n = nnf[eta];
    auto add_fresh = [](TableauNode& t, int id) {
      if (!t.old.count(id)) t.fresh.insert(id);
    };
    switch (n.kind) {
      case Kind::True:
        work.push_back(std::move(node));
        break;
      case Kind::False:
        break;  // contradiction: the node is dropped
      case Kind::Leaf: {
        const int neg = nnf.complement(eta);
        if (neg >= 0 && node.old.count(neg)) break;
        node.old.insert(eta);
        work.push_back(std::move(node));
        break;
      }
      case Kind::And:
        node.old.insert(eta);
        add_fresh(node, n.a);
        add_fresh(node, n.b);
        work.push_back(std::move(node));
        break;
      case Kind::Next:
        node.old.insert(eta);
        node.next.insert(n.a);
        work.push_back(std::move(node));
        break;
      case Kind::Or:
      case Kind::Until:
      case Kind::Release: {
        node.old.insert(eta);
        TableauNode second = node;
        // Or: a | b.  Until a U b: (a & X(a U b)) | b.  Release a R b: (b & X(a R b)) | (a & b).
        if (n.kind == Kind::Or) {
          add_fresh(node, n.a);
          add_fresh(second, n.b);
        } else if (n.kind == Kind::Until) {
          add_fresh(node, n.a);
          node.next.insert(eta);
          add_fresh(second, n.b);
        } else {
          add_fresh(node, n.b);
          node.next.insert(eta);
          add_fresh(second, n.a);
          add_fresh(second, n.b);
        }
        work.push_back(std::move(second));
        work.push_back(std::move(node));
        break;
      }
    }
  }

  BuchiAutomaton aut;
  aut.nodes.resize(done.size());
  std::vector<int> untils;  // acceptance set j: nodes without untils[j], or with its right side
  for (std::size_t id = 0; id < nnf.size(); ++id)
    if (nnf[static_cast<int>(id)].kind == Kind::Until) untils.push_back(static_cast<int>(id));
  aut.num_sets = static_cast<std::uint32_t>(untils.size());
  for (std::size_t q = 0; q < done.size(); ++q) {
    auto& out = aut.nodes[q];
    for (int id : done[q].old)
      if (nnf[id].kind == Kind::Leaf) out.label.push_back(nnf[id].leaf);
    for (int from : done[q].incoming) {
      if (from == kInit)
        aut.initial.push_back(static_cast<std::uint32_t>(q));
      else
        aut.nodes[static_cast<std::size_t>(from)].successors.push_back(
            static_cast<std::uint32_t>(q));
    }
    for (std::uint32_t j = 0; j < untils.size(); ++j) {
      const auto& u = nnf[untils[j]];
      if (!done[q].old.count(untils[j]) || done[q].old.count(u.b)) out.accepting.push_back(j);
    }
  }
  return aut;
}

}  // namespace sfcv::logic

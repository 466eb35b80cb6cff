#include "engine/bdd/condition_simplifier.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "engine/bdd/bdd_manager.hpp"

namespace sfcv::engine {

using bdd::Bdd;
using semantics::InputCondition;
using semantics::InputCube;
using semantics::InputLiteral;

namespace {

/// A cube over BDD variables: (variable, polarity).
using VarCube = std::vector<std::pair<int, bool>>;

/// Minato-Morreale: an irredundant cover C with lower <= C <= upper; returns C's BDD.
Bdd isop(const Bdd& lower, const Bdd& upper, std::vector<VarCube>& out) {
  if (lower.is_false()) return Bdd::constant(false);
  if (upper.is_true()) {
    out.emplace_back();
    return Bdd::constant(true);
  }
  // The top variable of the two (by level: the order need not be the index order).
  int x = lower.is_true() ? upper.top() : lower.top();
  if (!upper.is_false() && !upper.is_true() && bdd::level_of(upper.top()) < bdd::level_of(x))
    x = upper.top();
  const Bdd l0 = lower.cofactor(x, false), l1 = lower.cofactor(x, true);
  const Bdd u0 = upper.cofactor(x, false), u1 = upper.cofactor(x, true);

  std::vector<VarCube> c0, c1, cs;
  const Bdd f0 = isop(l0 & !u1, u0, c0);
  const Bdd f1 = isop(l1 & !u0, u1, c1);
  const Bdd rest = (l0 & !f0) | (l1 & !f1);
  const Bdd fs = isop(rest, u0 & u1, cs);
  const Bdd vx = Bdd::variable(x);
  for (auto& c : c0) {
    c.emplace_back(x, false);
    out.push_back(std::move(c));
  }
  for (auto& c : c1) {
    c.emplace_back(x, true);
    out.push_back(std::move(c));
  }
  for (auto& c : cs) out.push_back(std::move(c));
  return ((!vx) & f0) | (vx & f1) | fs;
}

struct Atom {
  std::uint32_t input;
  std::int64_t lo, hi;
  bool operator<(const Atom& o) const {
    return std::tie(input, lo, hi) < std::tie(o.input, o.lo, o.hi);
  }
};

}  // namespace

InputCondition simplify(const InputCondition& condition,
                        const std::vector<semantics::InputVariable>& inputs) {
  if (condition.is_false()) return {};
  if (condition.is_true()) return InputCondition::always();
  auto is_bool = [&inputs](std::uint32_t i) {
    return inputs[i].type.kind == model::TypeKind::Bool || inputs[i].pseudo;
  };
  // Variables: the Boolean inputs in index order, then the integer atoms.
  std::map<Atom, int> var_of;
  for (const auto& cube : condition.cubes)
    for (const auto& l : cube.literals)
      var_of.emplace(is_bool(l.input) ? Atom{l.input, 0, 0} : Atom{l.input, l.lo, l.hi}, 0);
  std::vector<Atom> atoms;
  for (auto& [atom, var] : var_of) {
    var = static_cast<int>(atoms.size());
    atoms.push_back(atom);
  }
  bdd::ensure_variables(static_cast<int>(atoms.size()) + 1);

  Bdd f = Bdd::constant(false);
  for (const auto& cube : condition.cubes) {
    Bdd c = Bdd::constant(true);
    for (const auto& l : cube.literals) {
      if (is_bool(l.input)) {
        const Bdd v = Bdd::variable(var_of.at({l.input, 0, 0}));
        c = c & (l.lo ? v : (!v));
      } else {
        c = c & Bdd::variable(var_of.at({l.input, l.lo, l.hi}));
      }
    }
    f = f | c;
  }
  std::vector<VarCube> cover;
  isop(f, f, cover);

  // Back to input cubes. A negated atom is its complement: one or two intervals.
  InputCondition result;
  for (const auto& vc : cover) {
    std::vector<InputCube> partial{InputCube{}};
    for (const auto& [var, positive] : vc) {
      const Atom& a = atoms[static_cast<std::size_t>(var)];
      std::vector<InputLiteral> options;
      if (is_bool(a.input)) {
        options.push_back({a.input, positive ? 1 : 0, positive ? 1 : 0});
      } else if (positive) {
        options.push_back({a.input, a.lo, a.hi});
      } else {
        const auto& t = inputs[a.input].type;
        if (a.lo > t.lo) options.push_back({a.input, t.lo, a.lo - 1});
        if (a.hi < t.hi) options.push_back({a.input, a.hi + 1, t.hi});
      }
      std::vector<InputCube> next;
      for (const auto& pc : partial)
        for (const auto& lit : options) {
          InputCube c = pc;
          bool empty = false;
          auto it = std::find_if(c.literals.begin(), c.literals.end(),
                                 [&lit](const InputLiteral& x) { return x.input == lit.input; });
          if (it == c.literals.end()) {
            c.literals.push_back(lit);
          } else {
            it->lo = std::max(it->lo, lit.lo);
            it->hi = std::min(it->hi, lit.hi);
            empty = it->lo > it->hi;
          }
          if (!empty) next.push_back(std::move(c));
        }
      partial = std::move(next);
    }
    for (auto& c : partial) {
      std::sort(c.literals.begin(), c.literals.end(),
                [](const InputLiteral& a, const InputLiteral& b) { return a.input < b.input; });
      result.cubes.push_back(std::move(c));
    }
  }
  std::stable_sort(result.cubes.begin(), result.cubes.end(),
                   [](const InputCube& a, const InputCube& b) {
                     if (a.literals.size() != b.literals.size())
                       return a.literals.size() < b.literals.size();
                     for (std::size_t i = 0; i < a.literals.size(); ++i) {
                       const auto& x = a.literals[i];
                       const auto& y = b.literals[i];
                       if (x.input != y.input) return x.input < y.input;
                       if (x.lo != y.lo) return x.lo > y.lo;  // positive literals first
                     }
                     return false;
                   });
  return result;
}

}  // namespace sfcv::engine

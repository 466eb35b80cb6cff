#pragma once
// CTL and LTL formulas over the observables of a transition system (steps, actions, variables).
// A property is either CTL (path quantifiers E/A on every temporal operator) or LTL (the linear
// operators X F G U R W, implicitly for all paths); the parsers never mix the two.
// Immutable: constructors return shared nodes; resolution against a system makes new nodes.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "logic/fwd.hpp"

namespace sfcv::logic {

enum class Op {
  True,
  False,
  Atom,     ///< a Boolean observable: `name`
  Compare,  ///< `name cmp value` on an integer (or Boolean) observable
  Not,
  And,
  Or,
  Implies,
  Iff,
  Xor,
  EX,
  AX,
  EF,
  AF,
  EG,
  AG,
  EU,
  AU,  ///< args[0] U args[1]
  // LTL (logic/ltl_parser): X next, F eventually, G always; args[0] U/R/W args[1] are until,
  // release and weak until.
  X,
  F,
  G,
  U,
  R,
  W,
  // Comparisons of two expressions (`a = b`, `level + 1 <= limit`, docs/properties.md):
  // Relation compares the integer terms args[0] and args[1] with `cmp`. A term is Value (an
  // observable's value, `name`, `prev`), Number (`value`), or Neg/Add/Sub/Mul/Div/Mod of terms
  // (Mul needs a constant factor, Div and Mod a non-zero constant divisor; IEC truncation).
  // Terms are not formulas: only a Relation holds them.
  Relation,
  Value,
  Number,
  Neg,
  Add,
  Sub,
  Mul,
  Div,
  Mod,
};

enum class CompareOp { Eq, Ne, Lt, Le, Gt, Ge };

struct Formula {
  Op op = Op::True;
  std::string name;  ///< Atom, Compare: as written ("FILL_A.X", "level")
  CompareOp cmp = CompareOp::Eq;
  std::int64_t value = 0;  ///< Compare: the constant
  /// Compare: the enumerator written for the constant (`state = Filling`), empty for a number;
  /// resolve() sets `value` from the variable's type.
  std::string value_name;
  std::int32_t observable = -1;  ///< Atom, Compare: index into observables() once resolved
  /// Atom, Compare: the value `prev` cycles back (0 = now): prev(x) is 1, prev(prev(x)) is 2.
  std::uint32_t prev = 0;
  std::vector<FormulaPtr> args;
  int line = 0;  ///< where it was written (1-based; 0 = unknown)
  int column = 0;
  /// 1 for a leaf, else 1 + the largest height of `args` (set by make_op): the parser refuses
  /// formulas higher than model::kMaxNesting, so recursive passes stay shallow.
  std::uint32_t height = 1;
};

// Constructors.
FormulaPtr make_const(bool v, int line = 0, int column = 0);
FormulaPtr make_atom(std::string name, int line = 0, int column = 0);
FormulaPtr make_compare(std::string name, CompareOp cmp, std::int64_t value, int line = 0,
                        int column = 0);
FormulaPtr make_op(Op op, std::vector<FormulaPtr> args, int line = 0, int column = 0);
FormulaPtr make_not(FormulaPtr f);
FormulaPtr make_and(FormulaPtr a, FormulaPtr b);
FormulaPtr make_or(FormulaPtr a, FormulaPtr b);
/// A copy of an atom or comparison bound to observable `index`.
FormulaPtr with_observable(const Formula& f, std::int32_t index);
/// prev(f) for a propositional `f`: every atom and comparison `n` cycles further back.
FormulaPtr shifted_back(const FormulaPtr& f, std::uint32_t n = 1);
/// rise(p) = p & !prev(p), fall(p) = !p & prev(p), for a propositional `p`.
FormulaPtr make_rise(const FormulaPtr& p, int line = 0, int column = 0);
FormulaPtr make_fall(const FormulaPtr& p, int line = 0, int column = 0);
/// Some atom or comparison below reads a previous value (prev, rise, fall).
bool reads_previous(const Formula& f);

/// An integer term (Value, Number or arithmetic), the operand of a Relation.
bool is_term(Op op);
/// A node that names an observable: Atom, Compare, Value.
bool names_observable(Op op);
/// The value of a resolved term in a state, `observe(o)` reading observable o (int64 is exact:
/// resolve() refuses terms whose range does not fit). Throws std::invalid_argument on a formula.
std::int64_t evaluate_term(const Formula& t,
                           const std::function<std::int64_t(std::uint32_t)>& observe);
/// A resolved Relation in a state.
bool relation_holds(const Formula& f, const std::function<std::int64_t(std::uint32_t)>& observe);

bool is_temporal(Op op);
bool is_ltl_op(Op op);
/// Some LTL operator below: an LTL property (checked on paths, not by CTL labelling).
bool is_ltl(const Formula& f);
/// No temporal operator anywhere below.
bool is_propositional(const Formula& f);
/// Names of the atoms and compared variables, in order of first appearance, without repeats.
std::vector<std::string> atom_names(const Formula& f);
/// Indices of the resolved observables used, sorted, without repeats.
std::vector<std::uint32_t> atom_observables(const Formula& f);

/// NuSMV syntax, fully parenthesised where needed: "AG !(V1 & V3)".
std::string to_string(const Formula& f);
std::string to_string(const FormulaPtr& f);
std::string_view to_string(CompareOp c);

bool compare(CompareOp c, std::int64_t lhs, std::int64_t rhs);

}  // namespace sfcv::logic

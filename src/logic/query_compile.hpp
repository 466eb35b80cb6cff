#pragma once
// A query compiled against a transition system: names resolved (steps, inputs, outputs, library
// definitions, let bindings), sorts checked, definitions inlined. The result is independent of
// how the graph is stored: the explicit engine evaluates it on bitsets
// (engine/explicit/query_evaluator.hpp); the symbolic engine can evaluate the same terms.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "logic/query_ast.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

/// The sort of a query term.
enum class Sort {
  States,      ///< a set of situations (RSG states)
  Evolutions,  ///< a set of evolutions (RSG edges)
  Steps,       ///< a set of steps (the step observables)
  Empty,       ///< `{}` before it meets a set of a known sort
  Bool,        ///< a test
  Int,         ///< a count or a number
};
std::string to_string(Sort s);

enum class CmpOp { Eq, Ne, Lt, Le, Gt, Ge };
bool compare(CmpOp op, std::int64_t a, std::int64_t b);

/// An input/output expression (the argument of Nec and Emis), over the values of one evolution's
/// inputs (Nec) and of one situation's observables.
struct Signal {
  enum class Op { Const, Input, Observable, StepVar, Not, And, Or, Cmp } op = Op::Const;
  bool is_int = false;      ///< integer-valued (Const, Input, Observable)
  std::int64_t value = 0;   ///< Const
  std::uint32_t index = 0;  ///< Input: TransitionSystem::inputs(); Observable; StepVar: slot
  CmpOp cmp = CmpOp::Eq;    ///< Cmp
  std::vector<Signal> args;
};

struct Term {
  enum class Op {
    AllStates,
    AllEvolutions,
    Initial,
    AllSteps,
    Empty,        ///< Y, T, Y0, Steps, {}
    Clearing,     ///< Tclear: the evolutions that clear at least one transition
    StepLiteral,  ///< steps
    StepVar,      ///< {e} for the set-builder variable in `slot`
    Union,
    Inter,
    Diff,
    Int,
    Ext,
    Amont,
    Aval,
    Succ,
    Pred,
    Act,
    Des,
    Nec,
    Emis,        ///< signal
    SetBuilder,  ///< { slot in args[0] | args[1] }
    Count,
    Number,
    SetCmp,  ///< args[0] cmp args[1], sets (Eq / Ne)
    IntCmp,  ///< args[0] cmp args[1], integers
    And,
    Or,
    Not,  ///< tests
  } op = Op::Empty;
  Sort sort = Sort::Empty;
  std::vector<Term> args;
  std::vector<std::uint32_t> steps;  ///< StepLiteral: observable indices, sorted
  std::uint32_t slot = 0;            ///< StepVar, SetBuilder
  std::int64_t value = 0;            ///< Number
  CmpOp cmp = CmpOp::Eq;
  Signal signal;  ///< Nec, Emis
  QueryPos pos;
};

/// The named definitions available to queries; later additions replace earlier ones of the same
/// name (a user library can override the shipped one).
class QueryLibrary {
 public:
  void add(Definition d);
  /// Parses and adds the definitions of a library text; throws QueryError.
  void add_text(std::string_view text, const std::string& source_name);
  /// Reads and adds a library file; throws QueryError (position 0:0) when it cannot be read.
  void add_file(const std::string& path);
  const Definition* find(std::string_view name) const;
  const std::map<std::string, Definition>& definitions() const { return defs_; }

 private:
  std::map<std::string, Definition> defs_;  ///< by lower-case name
};

struct CompiledQuery {
  std::string text;  ///< the query as written
  Term root;
  std::uint32_t slots = 0;  ///< set-builder variables (evaluation scratch size)
};

/// For a test `A = {}` or `A != {}` (either side `{}`): A, whose elements are what a user wants
/// to see; null for any other term.
const Term* emptiness_tested_set(const Term& t);

/// The value of a test term (and, or, not, comparisons of numbers and of sets), written once
/// for every query evaluator: `number(term)` and `same_set(a, b)` are the evaluator's. Nullopt
/// when `t` (or a part of it) is not a test.
template <class Number, class SameSet>
std::optional<bool> judge_query_test(const Term& t, Number&& number, SameSet&& same_set) {
  auto sub = [&](const Term& x) { return judge_query_test(x, number, same_set); };
  switch (t.op) {
    case Term::Op::And: {
      const auto a = sub(t.args[0]);
      if (!a || !*a) return a;
      return sub(t.args[1]);
    }
    case Term::Op::Or: {
      const auto a = sub(t.args[0]);
      if (!a || *a) return a;
      return sub(t.args[1]);
    }
    case Term::Op::Not: {
      const auto a = sub(t.args[0]);
      if (!a) return a;
      return !*a;
    }
    case Term::Op::IntCmp:
      return compare(t.cmp, number(t.args[0]), number(t.args[1]));
    case Term::Op::SetCmp: {
      const bool eq = same_set(t.args[0], t.args[1]);
      return t.cmp == CmpOp::Eq ? eq : !eq;
    }
    default:
      return std::nullopt;
  }
}

/// Compiles `query` against `ts`. Throws QueryError (unknown names, sort errors, wrong arity).
CompiledQuery compile_query(const NodePtr& query, const QueryLibrary& library,
                            const semantics::TransitionSystem& ts);

/// Parses then compiles.
CompiledQuery compile_query(std::string_view text, const QueryLibrary& library,
                            const semantics::TransitionSystem& ts,
                            const std::string& source_name = "query");

/// Whether a name is a built-in operator or constant (definitions may not use these names).
bool is_builtin_name(std::string_view name);

}  // namespace sfcv::logic

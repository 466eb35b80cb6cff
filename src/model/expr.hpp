#pragma once
// Expressions of ST guards, action bodies and Grafcet receptivities: small immutable values
// shared between users (like spot::formula). Names are kept as written; the semantics resolves
// them against the POU's scope (variables, steps, FB instances).

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "model/source_location.hpp"

namespace sfcv::model {

enum class ExprKind {
  BoolConst,  ///< value: 0 or 1
  IntConst,   ///< value
  TimeConst,  ///< value in milliseconds (T#2s -> 2000)
  Name,       ///< name: a variable, a step (Grafcet X12 or IEC step used as a Boolean), ...
  Member,     ///< name.member: step.X, step.T, fb_instance.Q, action.A ... (args empty)
  Not,
  Neg,  ///< unary: args[0]
  And,
  Or,
  Xor,  ///< n-ary (>= 2 args)
  Add,
  Sub,
  Mul,
  Div,
  Mod,  ///< binary
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,       ///< binary comparisons
  Rising,   ///< Grafcet ↑e: args[0]
  Falling,  ///< Grafcet ↓e: args[0]
  Delay,    ///< Grafcet t1/e/t2: args[0] = e, value = t1 (ms), value2 = t2 (ms)
  Call,     ///< function call name(args...): a standard function (MAX, INT_TO_BOOL, ...)
  /// An array element chosen by a non-constant index, before model::lower_data_types: `name`
  /// is the path with one `[*]` where args (one per dimension) go: `a[i].x` is ("a[*].x", i).
  /// Constant indices are part of names (`a[3]`), so after lowering no Index remains.
  Index,
  /// A STRING literal, `name` its characters ('$' escapes decoded), before
  /// model::lower_data_types replaces it by its code (docs/semantics.md 1.7a).
  StringConst,
  /// A literal of a type sfcv does not model (REAL `1.5`, `REAL#2`, dates): `name` is its
  /// text. It parses so that a write nothing modelled reads can be left out (io reads it);
  /// anywhere else the validator refuses it.
  UnmodelledConst,
};

struct Expr;
using ExprPtr = std::shared_ptr<const Expr>;

struct Expr {
  ExprKind kind = ExprKind::BoolConst;
  std::int64_t value = 0;
  std::int64_t value2 = 0;
  std::string name;    ///< Name, Member, Call (the function's name)
  std::string member;  ///< Member: the part after the dot, as written ("X", "T", "Q")
  std::vector<ExprPtr> args;
  /// Call: the parameter names of a formal call `f(a := x, b := y)`, one per argument; empty
  /// for a positional call `f(x, y)`.
  std::vector<std::string> arg_names;
  SourceLocation where;
  /// 1 for a leaf, else 1 + the largest height of `args` (set by the constructors below):
  /// parsers refuse trees higher than model::kMaxNesting, so recursive passes stay shallow.
  std::uint32_t height = 1;
};

// Constructors (free functions returning shared immutable nodes).
ExprPtr make_bool(bool v, SourceLocation where = {});
ExprPtr make_int(std::int64_t v, SourceLocation where = {});
ExprPtr make_time(std::int64_t ms, SourceLocation where = {});
ExprPtr make_name(std::string name, SourceLocation where = {});
ExprPtr make_member(std::string name, std::string member, SourceLocation where = {});
ExprPtr make_unary(ExprKind kind, ExprPtr arg, SourceLocation where = {});
ExprPtr make_binary(ExprKind kind, ExprPtr lhs, ExprPtr rhs, SourceLocation where = {});
ExprPtr make_nary(ExprKind kind, std::vector<ExprPtr> args, SourceLocation where = {});
ExprPtr make_call(std::string function, std::vector<ExprPtr> args, SourceLocation where = {});
/// `function(names[0] := args[0], ...)`.
ExprPtr make_formal_call(std::string function, std::vector<std::string> names,
                         std::vector<ExprPtr> args, SourceLocation where = {});
/// `path` holds one "[*]", replaced by the indices when printed: make_index("a[*]", {i}).
ExprPtr make_index(std::string path, std::vector<ExprPtr> indices, SourceLocation where = {});
ExprPtr make_string(std::string characters, SourceLocation where = {});
ExprPtr make_unmodelled_literal(std::string text, SourceLocation where = {});
ExprPtr make_delay(std::int64_t t1_ms, ExprPtr e, std::int64_t t2_ms, SourceLocation where = {});

/// Structural equality (ignores source locations).
/// True when evaluating `e` reads `variable` (case-insensitive): a name `x`, a member `x.m`
/// (so an instance's name covers all its members) or its written form `x.m`, or an element
/// of an array `x`.
bool reads(const Expr& e, std::string_view variable);

bool equal(const Expr& a, const Expr& b);
bool equal(const ExprPtr& a, const ExprPtr& b);

/// Prints as IEC 61131-3 ST (Rising/Falling/Delay in the native Grafcet syntax: `RE x`, `FE x`,
/// `2s/X3/0s`), fully parenthesised where precedence requires.
std::string to_st(const Expr& e);
std::string to_st(const ExprPtr& e);

}  // namespace sfcv::model

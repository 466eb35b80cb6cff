#pragma once
// Statements of ST action bodies: assignments, IF/ELSIF/ELSE, CASE, calls of FB instances, the
// loops FOR/WHILE/REPEAT and EXIT/CONTINUE/RETURN. Anything else is rejected by the importers
// with an "unsupported" diagnostic.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/expr.hpp"
#include "model/source_location.hpp"

namespace sfcv::model {

enum class StmtKind {
  Assign,
  If,
  Case,
  FbCall,
  For,       ///< FOR target := value TO limit [BY step] DO bodies[0] END_FOR
  While,     ///< WHILE conditions[0] DO bodies[0] END_WHILE
  Repeat,    ///< REPEAT bodies[0] UNTIL conditions[0] END_REPEAT
  Exit,      ///< EXIT: leaves the innermost loop
  Continue,  ///< CONTINUE: ends the innermost loop's current iteration
  Return,    ///< RETURN: ends the body (of the POU, action or function) being executed
};

struct Stmt;
using StmtPtr = std::shared_ptr<const Stmt>;
using StmtList = std::vector<StmtPtr>;

struct CaseLabel {
  std::int64_t lo = 0, hi = 0;  ///< a single value has lo == hi
  /// An enumerator written as the bound (`Idle:`, `E_State.Idle:`), before
  /// model::lower_data_types sets lo/hi to its value; empty for an integer literal.
  std::string lo_name, hi_name;
  bool operator==(const CaseLabel&) const = default;
};

struct Stmt {
  StmtKind kind = StmtKind::Assign;
  SourceLocation where;

  // Assign: target := value (target may be dotted: `inst.x`). FbCall: target is the instance.
  std::string target;
  ExprPtr value;

  // If: conditions[i] guards bodies[i] (IF, ELSIF...); else_body. Case: selector = value,
  // labels[i] select bodies[i]; else_body.
  std::vector<ExprPtr> conditions;
  std::vector<std::vector<CaseLabel>> labels;
  std::vector<StmtList> bodies;
  StmtList else_body;

  // FbCall: named inputs (IN := x, PT := T#1s, ...).
  std::vector<std::pair<std::string, ExprPtr>> arguments;

  // For: the TO bound and the BY increment (null when BY is omitted, i.e. 1).
  ExprPtr limit;
  ExprPtr step;
  // Assign to an array element chosen by non-constant indices (before model::lower_data_types):
  // target holds one "[*]" where these go, as in ExprKind::Index.
  std::vector<ExprPtr> target_indices;
  // FbCall: output bindings `Q => y` (the instance's output, the variable it is copied to).
  std::vector<std::pair<std::string, std::string>> outputs;
};

StmtPtr make_assign(std::string target, ExprPtr value, SourceLocation where = {});
StmtPtr make_fb_call(std::string instance, std::vector<std::pair<std::string, ExprPtr>> arguments,
                     SourceLocation where = {});

/// A loop statement (FOR, WHILE, REPEAT).
bool is_loop(StmtKind k);

/// True when executing `body` evaluates an expression that reads `variable` (model::reads).
bool reads(const StmtList& body, std::string_view variable);

bool equal(const Stmt& a, const Stmt& b);
bool equal(const StmtList& a, const StmtList& b);

/// Prints as ST, one statement per line, with `indent` leading spaces.
std::string to_st(const StmtList& body, int indent = 0);

}  // namespace sfcv::model

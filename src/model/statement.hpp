#pragma once
// Statements of ST action bodies: assignments, IF/ELSIF/ELSE, CASE, and calls of standard FB
// instances. Anything else is rejected by the importers with an "unsupported" diagnostic.

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "model/expr.hpp"
#include "model/source_location.hpp"

namespace sfcv::model {

enum class StmtKind { Assign, If, Case, FbCall };

struct Stmt;
using StmtPtr = std::shared_ptr<const Stmt>;
using StmtList = std::vector<StmtPtr>;

struct CaseLabel {
  std::int64_t lo = 0, hi = 0;  ///< a single value has lo == hi
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
  // FbCall: output bindings `Q => y` (the instance's output, the variable it is copied to).
  std::vector<std::pair<std::string, std::string>> outputs;
};

StmtPtr make_assign(std::string target, ExprPtr value, SourceLocation where = {});
StmtPtr make_fb_call(std::string instance, std::vector<std::pair<std::string, ExprPtr>> arguments,
                     SourceLocation where = {});

bool equal(const Stmt& a, const Stmt& b);
bool equal(const StmtList& a, const StmtList& b);

/// Prints as ST, one statement per line, with `indent` leading spaces.
std::string to_st(const StmtList& body, int indent = 0);

}  // namespace sfcv::model

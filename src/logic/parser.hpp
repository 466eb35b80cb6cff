#pragma once
// Parsers of the property language (NuSMV-like syntax) and of specification files. They return
// their errors as diagnostics with line:col and print nothing (like spot::parse_infix_psl).
//
// Precedence, weakest first: <->, -> (right associative), | and xor, &, comparisons, then the
// unary operators ! EX AX EF AF EG AG (so `AG p & q` is `(AG p) & q`, as in NuSMV).
// Temporal keywords are upper case; TRUE/FALSE and xor are case-insensitive.

#include <string>
#include <string_view>

#include "logic/fwd.hpp"
#include "logic/pattern.hpp"
#include "logic/spec.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::logic {

struct ParsedFormula {
  FormulaPtr formula;  ///< null when there were errors
  model::Diagnostics diagnostics;
  bool ok() const { return formula != nullptr; }
};

/// Parses one formula; `source` names it in diagnostics ("--ctl", a file name).
ParsedFormula parse_formula(std::string_view text, std::string source = "<formula>");

/// Parses one LTL formula: X F G (unary, like !) and U R W (binary, tighter than &, right
/// associative) over the same atoms; the CTL operators are errors.
ParsedFormula parse_ltl(std::string_view text, std::string source = "<ltl>");

/// Parses a formula that must be propositional (assumptions, fairness): a temporal operator is
/// an error pointing at it.
ParsedFormula parse_propositional(std::string_view text, std::string source = "<expr>");

struct ParsedSpec {
  Spec spec;
  model::Diagnostics diagnostics;
  bool ok() const { return !model::has_errors(diagnostics); }
};

/// `pattern name: ...;` statements are read by parse_pattern with `patterns`.
ParsedSpec parse_spec(std::string_view text, std::string file = "<spec>",
                      const PatternOptions& patterns = {});

}  // namespace sfcv::logic

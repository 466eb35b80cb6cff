#pragma once
// From what the user wrote (--ctl, --spec, --fair, --assume) to what the semantics and the
// engines take: assumptions as chart expressions (before the system is built), then resolved
// properties and fairness constraints (once it is).

#include <string>
#include <vector>

#include "logic/check_result.hpp"
#include "logic/check_task.hpp"
#include "logic/pattern.hpp"
#include "logic/spec.hpp"
#include "model/diagnostic.hpp"
#include "model/expr.hpp"

namespace sfcv::logic {

struct CheckInputs {
  std::vector<std::string> ctl;       ///< --ctl formulas
  std::string spec_text;              ///< contents of --spec (empty when none)
  std::string spec_file;              ///< its name, for diagnostics
  std::vector<std::string> fair;      ///< --fair
  std::vector<std::string> assume;    ///< --assume
  std::vector<std::string> patterns;  ///< --pattern (logic/pattern.hpp)
  PatternOptions pattern_options;     ///< for --pattern and the spec's `pattern` statements
  std::vector<std::string> ltl;       ///< --ltl formulas
};

struct ParsedInputs {
  Spec spec;  ///< every property, assumption and fairness constraint, spec file ones first
  model::Diagnostics diagnostics;
};

/// Parses everything; properties from --ctl, --pattern and --ltl are named by their text.
ParsedInputs parse_check_inputs(const CheckInputs& in);

/// The assumptions as chart expressions, for semantics::*Options::assumptions.
std::vector<model::ExprPtr> assumption_exprs(const Spec& spec);

/// The system to resolve against when a property or fairness constraint names an input or a
/// previous value (prev, rise, fall): `ts` with exactly that history (semantics/
/// history_system.hpp); null when none is needed or when some name cannot be kept (the
/// error, at the atom, goes to `diagnostics`). `ts` must outlive the result.
semantics::TransitionSystemPtr history_system_for(const Spec& spec,
                                                  const semantics::TransitionSystem& ts,
                                                  model::Diagnostics& diagnostics);

/// Resolves properties and fairness against `ts`; errors go to `diagnostics`.
/// Names a property in diagnostics: "--ctl 'AG p'", "--pattern '...'", or its spec file.
std::string property_source(const std::string& name, const model::SourceLocation& where);

/// Carries the patterns' English sentences (NamedFormula::description) to the results of the
/// properties of the same name.
void describe_results(CheckReport& report, const Spec& spec);

void resolve_into(const Spec& spec, const semantics::TransitionSystem& ts, CheckTask& task,
                  model::Diagnostics& diagnostics);

}  // namespace sfcv::logic

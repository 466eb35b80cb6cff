#pragma once
// From what the user wrote (--ctl, --spec, --fair, --assume) to what the semantics and the
// engines take: assumptions as chart expressions (before the system is built), then resolved
// properties and fairness constraints (once it is).

#include <string>
#include <vector>

#include "logic/check_task.hpp"
#include "logic/spec.hpp"
#include "model/diagnostic.hpp"
#include "model/expr.hpp"

namespace sfcv::logic {

struct CheckInputs {
  std::vector<std::string> ctl;      ///< --ctl formulas
  std::string spec_text;             ///< contents of --spec (empty when none)
  std::string spec_file;             ///< its name, for diagnostics
  std::vector<std::string> fair;     ///< --fair
  std::vector<std::string> assume;   ///< --assume
};

struct ParsedInputs {
  Spec spec;  ///< every property, assumption and fairness constraint, spec file ones first
  model::Diagnostics diagnostics;
};

/// Parses everything; properties from --ctl are named by their text.
ParsedInputs parse_check_inputs(const CheckInputs& in);

/// The assumptions as chart expressions, for semantics::*Options::assumptions.
std::vector<model::ExprPtr> assumption_exprs(const Spec& spec);

/// Resolves properties and fairness against `ts`; errors go to `diagnostics`.
void resolve_into(const Spec& spec, const semantics::TransitionSystem& ts, CheckTask& task,
                  model::Diagnostics& diagnostics);

}  // namespace sfcv::logic

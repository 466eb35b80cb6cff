#pragma once
// Static validation of a loaded project (`sfcv lint`, and every command after loading): names,
// chart structure, hierarchy, types. Returns located diagnostics and prints nothing.
//
// Errors (Severity::Error) are defects that make the model meaningless or ambiguous: duplicate
// or undeclared names, a chart without initial step, ill-formed parallel structure (IEC 61131-3
// "unsafe" / "unreachable" SFCs), hierarchy cycles, type errors, assignments to inputs, timed
// qualifiers without a duration, dangling Grafcet references. Warnings (Severity::Warning) are
// legal but suspicious: steps that the chart structure can never reach.

#include "model/budget.hpp"
#include "model/chart.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::model {

/// Every check, in document order within each POU. Past `budget`'s deadline (when given),
/// throws LimitReached(Time).
Diagnostics validate(const Project& project, const Budget* budget = nullptr);

}  // namespace sfcv::model

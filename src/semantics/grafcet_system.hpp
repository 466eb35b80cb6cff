#pragma once
// IEC 60848 Grafcet as a transition system whose states are the stable situations of the
// Reachable Situations Graph (seed 002). docs/semantics.md, Part 2, states every rule.
//
// State layout (in field order, see GrafcetSystem::layout()):
//   StepActive   one bit per step that has its own activity (every step but macro-steps, whose
//                activity is derived: a macro-step is active while a step of its expansion is);
//   Variable     the memory of each variable written by a stored action (Boolean or integer);
//   Variable     the value of each output written by continuous actions, as emitted in the
//                stable situation (so the node is a Mealy state whose outputs are observable);
//   InputMemory  the input values: every input read by the grafcet under the single-input-change
//                hypothesis (the rule needs the previous values), only the inputs read under an
//                edge otherwise; an integer input is stored as the index of its region (the
//                intervals between the constants it is compared with);
//   Timer        the phase of each delay t1/e/t2 (0 off, 1 rising wait, 2 on, 3 falling wait).
//
// Delays use the abstract time mode: a running delay may elapse at any later event. Elapse is
// modelled by one pseudo-input per delay (InputVariable::pseudo), so each input valuation still
// gives one successor. Inputs that the grafcet never reads are not part of the system.

#include <string_view>

#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "semantics/options.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics {

/// A Boolean variable written by both continuous and stored actions has two Variable fields:
/// its name holds the continuous assignation as emitted, its name with this suffix the value
/// the stored actions keep; the variable reads 1 when either does (docs/semantics.md 2.7).
inline constexpr std::string_view kStoredFieldSuffix = ".stored";

/// Compiles every POU of `project` that has charts into one Grafcet system (the partial grafcets
/// run together). Returns null and adds diagnostics when the model is out of scope (unknown
/// names, arithmetic on inputs, comparisons between inputs, conflicting writers...).
TransitionSystemPtr make_grafcet_system(const model::Project& project,
                                        const GrafcetOptions& options,
                                        model::Diagnostics& diagnostics);

}  // namespace sfcv::semantics

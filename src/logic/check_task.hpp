#pragma once
// What an engine is asked to check, as a value (like Storm's CheckTask): the system, the
// resolved properties, fairness, the standard checks, and the limits.

#include <string>
#include <vector>

#include "logic/check_result.hpp"
#include "logic/formula.hpp"
#include "logic/fwd.hpp"
#include "logic/standard_checks.hpp"
#include "model/budget.hpp"
#include "model/chart.hpp"
#include "model/errors.hpp"
#include "model/source_location.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

struct Property {
  std::string name;
  FormulaPtr formula;  ///< resolved (every atom bound to an observable)
  model::SourceLocation where;
};

/// Progress of a long run, for the CLI's progress line.
using Progress = model::Progress;

/// --timeout, --memory, --max-states and the progress callback: one budget for the whole run,
/// shared by every phase and, under --engine auto, by both engines.
using CheckLimits = model::Budget;

/// The paths through a state without a successor (docs/properties.md): the state repeats
/// forever (Stutter, as Spin reads them), or no path passes there (Drop, NuSMV's reading: only
/// infinite paths count).
enum class DeadlockPaths { Stutter, Drop };

struct CheckTask {
  const semantics::TransitionSystem* system = nullptr;
  const model::Project* project = nullptr;  ///< optional: locations, loops, actions
  std::vector<Property> properties;
  std::vector<FormulaPtr> fairness;  ///< resolved propositional formulas
  std::vector<StandardCheck> checks;
  /// True when the semantics resolves alternative conflicts by a priority order
  /// (PriorityMode::Standard): conflicts are then invisible in the graph.
  bool priority_resolves_conflicts = true;
  /// Findings kept per standard check (0 = every one); PropertyResult::findings_total counts all.
  std::size_t max_findings = 20;
  CheckLimits limits;
  /// LTL paths through deadlocks; Drop also makes CTL quantify over infinite paths only.
  DeadlockPaths deadlock_paths = DeadlockPaths::Stutter;
  /// Also measure the coverage of steps, transitions and actions (explicit engine).
  bool coverage = false;
};

/// The first LTL property of `task`, or null: engines that check CTL only refuse the task with
/// ltl_refusal(), never skip the property.
inline const Property* first_ltl_property(const CheckTask& task) {
  for (const auto& p : task.properties)
    if (p.formula && is_ltl(*p.formula)) return &p;
  return nullptr;
}
/// Sets how paths treat deadlocks. Drop also adds the fairness constraint TRUE when there is
/// none, so that CTL's path quantifiers, like NuSMV's, range over infinite paths only (a state
/// without any is then outside every quantifier's reach, as in docs/properties.md).
inline void set_deadlock_paths(CheckTask& task, DeadlockPaths paths) {
  task.deadlock_paths = paths;
  if (paths == DeadlockPaths::Drop && task.fairness.empty())
    task.fairness.push_back(make_const(true));
}

/// The report of an engine that stopped on a limit before it had one of its own: every question
/// of `task` (its properties, then its standard checks) unknown for `why`, except a standard
/// check without meaning on the system, which stays n/a; so the text and every report still
/// list every question.
CheckReport unknown_report(const CheckTask& task, const std::string& engine,
                           const LimitReached& why);

inline std::string ltl_refusal(std::string_view engine, const Property& p) {
  return "the " + std::string(engine) + " engine does not check LTL properties ('" + p.name +
         "'); use --engine explicit (or auto)";
}

}  // namespace sfcv::logic

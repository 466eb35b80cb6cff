#pragma once
// What an engine is asked to check, as a value (like Storm's CheckTask): the system, the
// resolved properties, fairness, the standard checks, and the limits.

#include <string>
#include <vector>

#include "logic/formula.hpp"
#include "logic/fwd.hpp"
#include "logic/standard_checks.hpp"
#include "model/budget.hpp"
#include "model/chart.hpp"
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
inline std::string ltl_refusal(std::string_view engine, const Property& p) {
  return "the " + std::string(engine) + " engine does not check LTL properties ('" + p.name +
         "'); use --engine explicit (or auto)";
}

}  // namespace sfcv::logic

#pragma once
// What an engine is asked to check, as a value (like Storm's CheckTask): the system, the
// resolved properties, fairness, the standard checks, and the limits.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "logic/fwd.hpp"
#include "logic/standard_checks.hpp"
#include "model/chart.hpp"
#include "model/source_location.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

struct Property {
  std::string name;
  FormulaPtr formula;  ///< resolved (every atom bound to an observable)
  model::SourceLocation where;
};

struct Progress {
  std::uint64_t states = 0;
  std::uint64_t edges = 0;
  std::uint32_t depth = 0;
  double seconds = 0;
};

struct CheckLimits {
  std::uint64_t max_states = 0;     ///< 0 = unlimited
  double timeout_seconds = 0;       ///< 0 = unlimited
  std::uint64_t max_memory_bytes = 0;
  std::function<void(const Progress&)> progress;  ///< may be empty
};

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

}  // namespace sfcv::logic

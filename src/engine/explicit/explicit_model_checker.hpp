#pragma once
// The explicit engine: builds the reachable situations graph (BFS, packed states) and checks
// CTL properties and the standard checks on it by labelling (ctl_checker.hpp).

#include <vector>

#include "engine/explicit/ctl_checker.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "engine/model_checker.hpp"

namespace sfcv::engine {

struct ExplicitEngineOptions {
  /// Threads generating successors in the on-the-fly invariant search (the only phase that
  /// runs in parallel; 0: one per core). Results do not depend on it.
  unsigned threads = 1;
  /// Under a deadline, stop exploring once the states waiting cannot be expanded in the time
  /// left (ExplorationOptions::forecast): set for the probe of --engine auto only.
  bool forecast = false;
};

class ExplicitModelChecker final : public ModelChecker {
 public:
  explicit ExplicitModelChecker(ExplicitEngineOptions options = {}) : options_(options) {}
  std::string_view name() const override { return "explicit"; }
  bool can_handle(const logic::CheckTask& task, std::string* why = nullptr) const override;
  logic::CheckReport check(const logic::CheckTask& task) const override;

 private:
  ExplicitEngineOptions options_;
};

ModelCheckerPtr make_explicit_model_checker(const ExplicitEngineOptions& options = {});

/// The standard checks of `task.checks` on a built graph; `checker` carries the task's
/// fairness (used for the AG AF part of re-entry only).
std::vector<logic::PropertyResult> run_standard_checks(const ReachableSituationGraph& graph,
                                                       CtlChecker& checker,
                                                       const logic::CheckTask& task);

}  // namespace sfcv::engine

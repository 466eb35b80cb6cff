#pragma once
// The symbolic engine (`--engine bdd`): forward reachability with frontier sets (onion rings),
// CTL by fixpoints over BDDs (EX, EU, EG; fairness by Emerson-Lei), counterexamples and
// witnesses for every formula cut out of the onion rings and fixpoint approximants
// (symbolic_ctl.hpp), in the explicit engine's trace format. Same CheckTask, same CheckReport.

#include "engine/bdd/reorder_mode.hpp"
#include "engine/model_checker.hpp"

namespace sfcv::engine {

struct BddEngineOptions {
  ReorderMode reorder = ReorderMode::Dynamic;  ///< `--reorder` (reorder_mode.hpp)
  /// Initial node table (0: sized from the circuit). Dynamic reordering first sifts when this
  /// many nodes are live: tests set it small to make sifting run on small charts.
  int initial_nodes = 0;
  /// Under a deadline: the share of the time left when a check starts by which the system's
  /// BDDs and transition relation must be built, else every answer is unknown (SymbolicOptions::
  /// relation_deadline). 0: no share of its own (the deadline only).
  double relation_share = 0;
};

/// The node table is sized from CheckTask::limits.max_memory_bytes (`--memory`): when it is
/// full, the answers not yet decided are unknown.
ModelCheckerPtr make_bdd_model_checker(const BddEngineOptions& options = {});

}  // namespace sfcv::engine

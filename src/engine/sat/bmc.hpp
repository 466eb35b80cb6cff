#pragma once
// Bounded model checking: one incremental unrolling from the initial state shared by all
// targets. At depth k every target not yet reached is tried under an assumption (its literal
// at frame k); then the transition out of frame k is added for good. Depths are tried in
// order, so the first run found is a shortest one.

#include <functional>
#include <vector>

#include "engine/sat/reachability.hpp"
#include "engine/sat/sat_solver.hpp"

namespace sfcv::engine::sat {

struct BoundOptions {
  std::uint32_t max_depth = 200;  ///< the deepest frame tried (BMC) or k bound (k-induction)
  /// BMC only: the shallowest frame tried (a swarm shard's depth range, docs/distributed.md);
  /// the runs it finds are then shortest among those of at least min_depth cycles.
  std::uint32_t min_depth = 0;
  Deadline deadline;
  /// Called with each depth as it starts (the progress line); may be empty.
  std::function<void(std::uint32_t)> on_depth;
};

/// Per target: Reached (with a shortest run) or Unknown (no run up to the bound, or the
/// deadline passed). BMC alone never answers Unreachable.
std::vector<ReachResult> bmc(const ReachQuery& query, const BoundOptions& options);

}  // namespace sfcv::engine::sat

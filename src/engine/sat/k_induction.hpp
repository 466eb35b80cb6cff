#pragma once
// k-induction (Sheeran, Singh, Stålmarck) with simple-path constraints: the base case is the
// BMC unrolling from the initial state; the step case, one incremental solver per target, asks
// for a loop-free run of k frames without the target followed by a frame with it (states
// compared on the target's cone of influence). When the base case found nothing up to k - 1
// and the step case is unsatisfiable, no run reaches the target: the shortest one would be
// loop-free and its last k + 1 frames would satisfy the step case.

#include <vector>

#include "engine/sat/bmc.hpp"

namespace sfcv::engine::sat {

/// Per target: Reached (a shortest run), Unreachable (a KInduction certificate, already
/// re-checked by certificate.hpp as soon as it was found), or Unknown (bound or deadline).
std::vector<ReachResult> k_induction(const ReachQuery& query, const BoundOptions& options);

}  // namespace sfcv::engine::sat

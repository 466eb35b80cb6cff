#pragma once
// The depth-by-depth loop that BMC and k-induction share: one incremental unrolling from the
// initial state; at depth k each open target is tried at frame k (the base case, which finds
// shortest runs because depths go in order), then whatever else the algorithm does at that
// depth, then the transition out of frame k is added for good.

#include <string>
#include <vector>

#include "engine/sat/bmc.hpp"
#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

/// What the algorithm did with an open target at depth k, after its base case found no run
/// (Decided: reached, unreachable, or left unknown with its `why` set for good).
enum class DepthStep { Open, Decided, Interrupted };

/// Runs the loop over `results` (one per target of `query`) in `base`/`frames`. `after_base(t,
/// k)` is called for an open target whose base case at depth k is unsatisfiable; `bound_why`
/// is the reason left on the targets still open past options.max_depth.
template <class AfterBase>
void deepen(const ReachQuery& query, const BoundOptions& options, Solver& base, Unrolling& frames,
            std::vector<ReachResult>& results, const std::string& bound_why,
            AfterBase&& after_base) {
  std::size_t open = results.size();
  auto give_up = [&](std::uint32_t depth, const std::string& why) {
    for (auto& r : results)
      if (r.kind == ReachResult::Kind::Unknown && r.why.empty()) {
        r.depth = depth;
        r.why = why;
      }
  };
  for (std::uint32_t k = 0; open > 0; ++k) {
    if (options.on_depth) options.on_depth(k);
    if (k > options.max_depth) {
      give_up(options.max_depth, bound_why);
      break;
    }
    if (k < options.min_depth) {  // below this shard's depth range: unroll only
      base.add_clause({frames.literal(query.step_ok, k)});
      continue;
    }
    bool interrupted = false;
    for (std::size_t t = 0; t < results.size() && !interrupted; ++t) {
      auto& r = results[t];
      if (r.kind != ReachResult::Kind::Unknown || !r.why.empty()) continue;  // decided
      switch (base.solve({frames.literal(query.targets[t], k)})) {
        case SatResult::Sat:
          r.kind = ReachResult::Kind::Reached;
          r.depth = k;
          for (std::uint32_t j = 0; j <= k; ++j) r.inputs.push_back(frames.input_values(j));
          --open;
          continue;
        case SatResult::Unsat:
          break;
        case SatResult::Interrupted:
          interrupted = true;
          continue;
      }
      switch (after_base(t, k)) {
        case DepthStep::Open:
          break;
        case DepthStep::Decided:
          --open;
          break;
        case DepthStep::Interrupted:
          interrupted = true;
          break;
      }
    }
    if (interrupted) {
      give_up(k, "the time limit passed at depth " + std::to_string(k));
      break;
    }
    base.add_clause({frames.literal(query.step_ok, k)});
  }
}

}  // namespace sfcv::engine::sat

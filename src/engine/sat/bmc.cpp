#include "engine/sat/bmc.hpp"

#include "engine/sat/deepening.hpp"

namespace sfcv::engine::sat {

std::vector<ReachResult> bmc(const ReachQuery& query, const BoundOptions& options) {
  Solver solver(options.deadline, SolverProfile::Deepening);
  Unrolling frames(*query.aig, solver, true, query.simplify, query.cuts);
  std::vector<ReachResult> results(query.targets.size());
  deepen(
      query, options, solver, frames, results,
      options.min_depth == 0
          ? "no run reaches it within " + std::to_string(options.max_depth) + " cycles (the bound)"
          : "no run of " + std::to_string(options.min_depth) + " to " +
                std::to_string(options.max_depth) + " cycles reaches it (this shard's depths)",
      [](std::size_t, std::uint32_t) { return DepthStep::Open; });
  return results;
}

}  // namespace sfcv::engine::sat

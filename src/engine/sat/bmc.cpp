#include "engine/sat/bmc.hpp"

#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

std::vector<ReachResult> bmc(const ReachQuery& query, const BoundOptions& options) {
  Solver solver(options.deadline);
  Unrolling frames(*query.aig, solver, true);
  std::vector<ReachResult> results(query.targets.size());
  std::size_t open = results.size();
  auto give_up = [&](std::uint32_t depth, const std::string& why) {
    for (auto& r : results)
      if (r.kind == ReachResult::Kind::Unknown && r.why.empty()) {
        r.depth = depth;
        r.why = why;
      }
  };
  for (std::uint32_t k = 0; open > 0; ++k) {
    if (k > options.max_depth) {
      give_up(options.max_depth, "no run reaches it within " + std::to_string(options.max_depth) +
                                     " cycles (the bound)");
      break;
    }
    bool interrupted = false;
    for (std::size_t t = 0; t < results.size() && !interrupted; ++t) {
      if (results[t].kind != ReachResult::Kind::Unknown) continue;
      const int target = frames.literal(query.targets[t], k);
      switch (solver.solve({target})) {
        case SatResult::Sat:
          results[t].kind = ReachResult::Kind::Reached;
          results[t].depth = k;
          for (std::uint32_t j = 0; j <= k; ++j) results[t].inputs.push_back(frames.input_values(j));
          --open;
          break;
        case SatResult::Unsat: break;
        case SatResult::Interrupted: interrupted = true; break;
      }
    }
    if (interrupted) {
      give_up(k, "the time limit passed at depth " + std::to_string(k));
      break;
    }
    solver.add_clause({frames.literal(query.step_ok, k)});
  }
  return results;
}

}  // namespace sfcv::engine::sat

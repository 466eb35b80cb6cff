#include "engine/sat/houdini.hpp"

#include <algorithm>

#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

std::vector<LatchClause> houdini(const ReachQuery& query, std::vector<LatchClause> candidates,
                                 Deadline deadline) {
  const auto& aig = *query.aig;
  // The initial state: a candidate it breaks is no invariant.
  std::erase_if(candidates, [&](const LatchClause& c) {
    for (const auto& l : c)
      if (aig.latches()[l.latch].initial == l.value) return false;
    return true;
  });
  if (candidates.empty()) return {};
  Solver solver(deadline, SolverProfile::ManySmallQueries);
  Unrolling frames(aig, solver, false);
  const int step = frames.literal(query.step_ok, 0);
  // Per candidate: an activation literal that switches it on in frame 0, and a literal that
  // implies its negation in frame 1.
  std::vector<int> on(candidates.size()), broken(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    on[i] = solver.new_var();
    broken[i] = solver.new_var();
    std::vector<int> now{-on[i]};
    for (const auto& l : candidates[i]) {
      const int x = frames.latch(l.latch, 0);
      now.push_back(l.value ? x : -x);
      const int y = frames.latch(l.latch, 1);
      solver.add_clause({-broken[i], l.value ? -y : y});
    }
    solver.add_clause(now);
  }
  std::vector<bool> kept(candidates.size(), true);
  for (;;) {
    std::vector<int> assume{step}, some_broken;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (kept[i]) {
        assume.push_back(on[i]);
        some_broken.push_back(broken[i]);
      }
    if (some_broken.empty()) return {};
    const auto r = solver.solve(assume, some_broken);
    if (r == SatResult::Interrupted) return {};
    if (r == SatResult::Unsat) break;
    // Every candidate the model's step breaks goes (not only the one the solver picked).
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (!kept[i]) continue;
      bool holds = false;
      for (const auto& l : candidates[i]) {
        const int y = frames.latch(l.latch, 1);
        if (solver.value(l.value ? y : -y)) holds = true;
      }
      if (!holds) kept[i] = false;
    }
  }
  std::vector<LatchClause> out;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (kept[i]) out.push_back(std::move(candidates[i]));
  return out;
}

std::vector<LatchClause> step_exclusion_candidates(
    const std::vector<std::vector<std::uint32_t>>& groups, std::size_t max_candidates) {
  std::vector<LatchClause> out;
  for (const auto& g : groups)
    for (std::size_t a = 0; a < g.size(); ++a)
      for (std::size_t b = a + 1; b < g.size(); ++b) {
        if (out.size() >= max_candidates) return out;
        LatchClause c{{g[a], false}, {g[b], false}};
        std::sort(c.begin(), c.end());
        out.push_back(std::move(c));
      }
  return out;
}

}  // namespace sfcv::engine::sat

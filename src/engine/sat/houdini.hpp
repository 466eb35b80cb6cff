#pragma once
// Candidate invariants kept by Houdini (Flanagan and Leino 2001): from a set of clauses over
// latches that hold in the initial state, the largest subset that is inductive as a whole, by
// dropping every candidate that some step from a state satisfying all of them breaks, until
// none is broken. A chart's steps are its candidates: "not both steps a and b" for each pair of
// steps of one instance holds wherever the chart is safe, and proves in one pass what IC3
// otherwise learns again, pair by pair, for each target (one step of a sequence active at a
// time: PPU scenario 10's 513 output-conflict targets).

#include <vector>

#include "engine/sat/reachability.hpp"
#include "engine/sat/sat_solver.hpp"

namespace sfcv::engine::sat {

/// The inductive subset of `candidates` under `query`'s step relation (`query.step_ok`; the
/// targets are not read): it holds in the initial state and in every successor of a state where
/// it holds, so in every reachable state. A candidate false initially is dropped at once. Empty
/// when `deadline` passes first (a subset not yet closed under the steps proves nothing).
std::vector<LatchClause> houdini(const ReachQuery& query, std::vector<LatchClause> candidates,
                                 Deadline deadline);

/// The candidates "steps a and b are not both active" for each pair of the latches in each of
/// `groups` (one group per chart instance), at most `max_candidates` of them in all.
std::vector<LatchClause> step_exclusion_candidates(
    const std::vector<std::vector<std::uint32_t>>& groups, std::size_t max_candidates);

}  // namespace sfcv::engine::sat

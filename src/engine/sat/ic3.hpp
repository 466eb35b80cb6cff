#pragma once
// IC3 / property-directed reachability (Bradley 2011; Eén, Mishchenko, Brayton 2011) for one
// target: frames F_0 = init, F_1 ... F_k as sets of blocked cubes over the latches of the
// target's cone of influence, one incremental solver per frame, proof obligations in a priority
// queue (lowest frame first), inductive generalisation (failed assumptions, then MIC-style
// literal dropping), propagation of blocked cubes forward, and predecessors lifted by a
// failed-assumption query before they become obligations.

#include <functional>

#include "engine/sat/reachability.hpp"
#include "engine/sat/sat_solver.hpp"

namespace sfcv::engine::sat {

struct Ic3Options {
  Deadline deadline;
  std::uint32_t max_frames = 100000;
  /// Called with the index of each frame as it is opened (the progress line); may be empty.
  std::function<void(std::uint32_t)> on_frame;
  /// Clauses already proved of every reachable state (re-checked invariants of earlier
  /// targets over the same latches): every frame past the initial one assumes them, and a proof's
  /// certificate includes them, so that it is inductive alone. The step invariants one target's
  /// proof learns (one step of a chart active at a time) are then not learned again for each of the
  /// next hundred targets.
  const std::vector<LatchClause>* known_invariant = nullptr;
};

struct Ic3Stats {
  std::size_t frames = 0, obligations = 0, cubes = 0, sat_calls = 0;
};

/// Whether `query.targets[target]` is reachable: Unreachable comes with the inductive invariant
/// (a Certificate::Invariant, not yet re-checked: certificate.hpp does that); Reached with the
/// depth of the run IC3 found and, when the chain of proof obligations replays on the circuit
/// (every step allowed, the target met at the end), its inputs for frames 0..depth: a valid
/// run, not necessarily a shortest one. When the replay fails, `inputs` stays empty and the
/// caller rebuilds a run up to that depth by BMC.
ReachResult ic3(const ReachQuery& query, std::size_t target, const Ic3Options& options,
                Ic3Stats* stats = nullptr);

}  // namespace sfcv::engine::sat

#pragma once
// The SAT engines (`--engine bmc|kind|ic3`) on the IEC 61131-3 circuit: invariants (AG p),
// reachability (EF p) and the invariant-shaped standard checks (reachable steps, dead
// transitions, range errors), each as a target of engine/sat/reachability.hpp. Everything
// else is not checked by these engines (unknown, never a guess). Counterexamples and witnesses
// are traces in the other engines' format; every "holds" of kind and ic3 carries its
// certificate, re-checked by fresh solvers before it is reported.

#include <cstdint>

#include "engine/model_checker.hpp"

namespace sfcv::engine {

enum class SatAlgorithm { Bmc, KInduction, Ic3 };

struct SatEngineOptions {
  SatAlgorithm algorithm = SatAlgorithm::Ic3;
  std::uint32_t max_depth = 200;  ///< bmc and kind: the deepest unrolling
  /// bmc only: the shallowest depth tried (a swarm shard's range, docs/distributed.md)
  std::uint32_t min_depth = 0;
};

ModelCheckerPtr make_sat_model_checker(const SatEngineOptions& options);

}  // namespace sfcv::engine

#pragma once
// Deep runs by repeating a short loop. An INT counter that a step increments while it waits
// overflows only after thousands of cycles (corpus 06: 32 768), far beyond BMC and, frame by
// frame, beyond IC3 within a minute. But such a run is a short prefix followed by one short
// loop repeated: the loop returns every latch outside the counters to its value at the loop's
// start and changes some counter. BMC finds such a lasso of a few frames; simulating the
// prefix and then the loop's inputs over and over shows whether a target is met, and where.
// Every run this returns was simulated on the circuit (every step allowed, the target met in
// the last frame): pumping can miss a run, never invent one.

#include <cstdint>
#include <vector>

#include "engine/sat/reachability.hpp"
#include "engine/sat/sat_solver.hpp"

namespace sfcv::engine::sat {

struct PumpOptions {
  Deadline deadline;
  std::uint32_t max_lasso = 8;   ///< frames of prefix and loop together
  std::uint32_t max_lassos = 8;  ///< distinct loops tried
  /// Frames simulated per loop: an INT counter stepped every second cycle overflows within
  /// 2^17 (corpus 06 needs 32 768).
  std::uint64_t max_frames = 1 << 17;
};

/// For each target with `wanted[t]`: Reached with a run (inputs of frames 0..depth, simulated)
/// when repeating one of the loops found meets it, else Unknown. `counters` are the latches
/// a loop may change (the bits of integer fields); every other latch must come back.
std::vector<ReachResult> pump_loops(const ReachQuery& query,
                                    const std::vector<std::uint32_t>& counters,
                                    const std::vector<bool>& wanted, const PumpOptions& options);

}  // namespace sfcv::engine::sat

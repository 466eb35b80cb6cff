#pragma once
// Scalable chart families for benchmarks and tests, emitted as text in the formats sfcv reads.

#include <cstdint>
#include <string>

namespace sfcv::bench {

/// N parallel branches (one simultaneous divergence), each a two-step loop A_i <-> B_i with
/// output O_i active in B_i. With `selector`, one integer input `sel` (0..N-1) picks the single
/// branch that may toggle in a cycle (the synchronous analogue of N interleaved toggles:
/// 2^N + 1 states, N + 1 successors each). Without it, branch i toggles on its own Boolean input
/// t_i (2^N + 1 states, 2^N successors each: a family for symbolic engines).
std::string parallel_branches_iec(std::uint32_t n, bool selector);

/// The seed's chemical plant generalised to N reactors sharing one feed valve pair per reactor;
/// `flawed` keeps the original flaw (the emptying step does not wait for the filling branch),
/// so that AG !(V2_i & V4_i) is violated for every i.
std::string tanks_iec(std::uint32_t n, bool flawed);

/// N nested charts: action A_k of level k holds the chart of level k+1, each a two-step loop.
std::string nested_charts_iec(std::uint32_t n);

/// What random_chart_iec may use beyond the untimed qualifiers N, S, R, P1 and P0.
struct RandomChartFeatures {
  bool timed_qualifiers = false;  ///< also L, D, SD, DS and SL with durations of 10 to 40 ms
  bool nested_chart = false;      ///< an action holding its own chart, started and stopped by steps
  /// CODESYS's implicit flags: SFCInit a free input, and SFCReset either a free input or set by
  /// a step's P1 action and cleared by the initial step's N action (a CODESYS idiom).
  bool sfc_flags = false;
  /// Three actions W0..W2 whose bodies write the output Y (INT(0..3)), two with constants (one
  /// conditionally), associated to random steps with N, S or R: output conflicts and stored
  /// actions with bodies.
  bool writing_actions = false;
  /// An output C : INT(0..3) counted up by an action Up (N) of random steps, guarded against
  /// overflow in half of the charts only (a range error, reachable or not), cleared while S0 is
  /// active, and read by some transition guards.
  bool counter = false;
};

/// A deep counter: an n-bit variable `c` (INT(0..2^n - 1)) counts up by one on `tick`, every
/// second cycle, while below 2^n - 2, so AG c <= 2^n - 2 holds and its runs are 2^(n+1) cycles
/// deep (the BDD engine's breadth-first rings grow with the depth, IC3 needs none of them).
std::string counter_iec(std::uint32_t n);

/// N tanks with INT levels: tank i has `lvl_i` (INT(0..2L+1)), filled by one unit (step F_i,
/// P1) on `fill_i` while below `level`, drained by one unit (step D_i, P1) on `drain_i` while
/// above 0; each fill or drain takes two cycles, and draining tank i (i < N-1) pours one unit
/// into tank i+1 when it has room. AG lvl_0 <= L holds and needs a strengthened invariant (the
/// type allows more); AG lvl_0 <= L - 1 is violated after 2L cycles. Tank i+1 is filled by its
/// own step and by the drain of tank i in one cycle when both start together (docs/benchmarks.md).
std::string level_tanks_iec(std::uint32_t n, std::uint32_t level);

/// A random well-formed chart with `steps` steps (sequences, selection and simultaneous
/// branches) over `inputs` Boolean inputs, reproducible from `seed`.
std::string random_chart_iec(std::uint32_t steps, std::uint32_t inputs, std::uint64_t seed,
                             const RandomChartFeatures& features = {});

/// An N-station transfer line in the spirit of seed 002's pallet transfer, as a Grafcet `.g7`:
/// one partial grafcet per station (steps 10i empty, 10i+1 machining, 10i+2 done, 10i+3
/// releasing). A pallet arrives on RE pal_i, is machined until done_i, is released only when
/// station i+1 is empty (X10(i+1); the last station releases freely) and has left on FE pal_i.
/// The stopper stop_i is a stored action (raised on entering 10i, lowered on entering 10i+3).
/// `unused` adds that many declared inputs the grafcet never reads (the RSG must not grow).
std::string transfer_line_g7(std::uint32_t n, std::uint32_t unused);

}  // namespace sfcv::bench

#pragma once
// The one policy of `--engine auto`, for every subcommand (check, query): the explicit engine
// answers first, within kAutoProbeStates states; only a chart it cannot finish within them
// goes to the symbolic engines (check: the portfolio, engine/portfolio; query: the BDD
// evaluator). Header only: engine/query and engine/portfolio both read it.

#include <cstdint>

#include "model/budget.hpp"

namespace sfcv::engine {

/// States the explicit probe may enumerate. Measured (docs/engines.md, "how auto chooses"):
/// the explicit engine answers every standard check of a chart within this bound in about a
/// second, before the symbolic engines would have built their relations.
inline constexpr std::uint64_t kAutoProbeStates = 200'000;

/// Input valuations the probe may enumerate for the successors of one state (the leaves of the
/// scan cycle's input decisions, model::Budget::max_valuations). A state past it is "too wide"
/// for the explicit engine: a cycle that reads 20 free Boolean inputs has 2^20 leaves, seconds
/// per state, and a chart of such states has no hope of 200 000 states within a budget.
/// Measured: 65 536 leaves take the interpreter 0.1 s (24 XORed inputs, 2 us a leaf) to
/// 0.8 s (corpus 11, 12 us a leaf).
inline constexpr std::uint64_t kAutoProbeValuations = 65'536;

/// Under --timeout: the share of the time left when the probe starts that it may use. A probe
/// still short of its bounds then explores too slowly (corpus 09: 5 000 states/s, so 200 000
/// states need 40 s) and the symbolic engines get the other half.
inline constexpr double kAutoProbeTimeShare = 0.5;

/// The probe's state bound: the user's --max-states when it is tighter (then nothing follows
/// the probe: the user asked for no more states than that), else kAutoProbeStates.
struct AutoProbe {
  std::uint64_t max_states = kAutoProbeStates;
  bool user_bound = false;  ///< the user's --max-states bounds the probe: no engine follows
};
/// `probe_states` other than kAutoProbeStates: tests only (a race on a small chart).
inline AutoProbe auto_probe(const model::Budget& budget,
                            std::uint64_t probe_states = kAutoProbeStates) {
  if (budget.max_states > 0 && budget.max_states <= probe_states) return {budget.max_states, true};
  return {probe_states, false};
}

}  // namespace sfcv::engine

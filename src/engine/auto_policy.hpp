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

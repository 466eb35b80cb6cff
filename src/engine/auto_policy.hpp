#pragma once
// The one policy of `--engine auto`, for every subcommand (check, query): the explicit engine
// answers first, within kAutoProbeStates states; only a chart it cannot finish within them
// goes to the symbolic engines (check: the portfolio, engine/portfolio; query: the BDD
// evaluator). Header only: engine/query and engine/portfolio both read it.

#include <cstdint>
#include <optional>

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

/// Under --timeout: the share of the time left when the race starts by which the BDD engine
/// must have built its transition relation, else it stops and leaves the two cores to IC3 and
/// BMC (BddEngineOptions::relation_share). On the xPPU scenarios the relation is never built
/// while the engine held a core to the end (scenario 2 at --timeout 60: BMC reaches depth 50
/// with the share, 46 without); on the PPU scenarios it is built in 0.01-0.04 s.
inline constexpr double kRaceRelationShare = 0.5;

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

/// A Grafcet whose initial situations are estimated (TransitionSystem::estimate_initial_states,
/// before any engine runs) at more than this many times the probe's state bound skips the probe:
/// the probe would spend its share enumerating initial situations and stop at its bound before
/// expanding any (AGRAFE's production-system grafcets: hundreds of thousands; corpus 22: 524 799).
/// A factor above 1 because the estimate is a sample mean.
inline constexpr double kAutoSkipProbeFactor = 2.0;

/// Which engines `--engine auto` starts with.
enum class AutoStart {
  Probe,  ///< the explicit probe, then (if it hands over) the race
  Race,   ///< the bdd, ic3 and bmc race at once: the probe could not finish
};

/// auto's first choice from what is known of the model before any engine runs: the probe,
/// unless the estimated initial states alone are past its bound (and the bound is auto's own:
/// under the user's --max-states the probe is the only engine).
inline AutoStart auto_start(const AutoProbe& probe, std::optional<double> initial_states) {
  if (probe.user_bound || !initial_states) return AutoStart::Probe;
  return *initial_states > kAutoSkipProbeFactor * static_cast<double>(probe.max_states)
             ? AutoStart::Race
             : AutoStart::Probe;
}

/// The probe's forecast (ExplorationOptions::forecast): `expanded` states took `spent` seconds,
/// `found - expanded` wait; at that rate they alone need more than the `left` seconds of the
/// probe's share, so the probe cannot finish and hands over now rather than at its deadline.
/// Only once the rate is measured (32 states and a tenth of a second).
inline bool exploration_cannot_finish(std::uint64_t expanded, std::uint64_t found, double spent,
                                      double left) {
  if (expanded < 32 || spent < 0.1 || found <= expanded) return false;
  const double waiting = static_cast<double>(found - expanded);
  return waiting * (spent / static_cast<double>(expanded)) > left;
}

}  // namespace sfcv::engine

#pragma once
// `--engine auto` as a portfolio (docs/engines.md, "how auto chooses"): the explicit engine
// first, within kAutoProbeStates states (engine/auto_policy.hpp); a chart it cannot finish
// within them goes to the BDD engine, IC3 and BMC (bugs, up to 200 cycles) side by side, each
// in its own thread within the run's one budget. Per property the first definite answer wins
// (PropertyResult::decided_by names its engine); once every property is decided the other engines
// are cancelled (model::Budget::cancel). Verdicts do not depend on which engine wins: each engine
// is sound, and one that is cancelled or runs out of budget answers unknown, never holds.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "engine/auto_policy.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/model_checker.hpp"

namespace sfcv::engine {

struct PortfolioOptions {
  BddEngineOptions bdd;
  ExplicitEngineOptions explicit_engine;  ///< the probe's (--threads)
  /// How auto decided, one line each ("using the explicit engine", ...); may be empty.
  std::function<void(const std::string&)> note;
  /// The explicit probe's bound: kAutoProbeStates (engine/auto_policy.hpp), the one policy;
  /// tests set a smaller one to make small charts race (0: no probe).
  std::uint64_t probe_states = kAutoProbeStates;
  /// Input valuations per state the probe may enumerate: kAutoProbeValuations; tests set a
  /// smaller one (0: unbounded).
  std::uint64_t probe_valuations = kAutoProbeValuations;
  /// Seconds a racer may run past the deadline, or past the moment every question is decided,
  /// before the race reports without it (its questions unknown); none: wait for every racer.
  /// A racer left behind runs on in its thread and reads the task's system and project: while
  /// abandoned_racers() > 0 the caller keeps them alive, or ends the process once its report is
  /// out (the CLI does).
  std::optional<double> abandon_after;
  /// The race's BDD slot (null: the BDD engine); tests put an engine there that does not stop.
  std::shared_ptr<const ModelChecker> bdd_racer;
  /// The race's IC3 and BMC slots (null: those engines); tests put engines there whose partial
  /// answers they choose.
  std::shared_ptr<const ModelChecker> ic3_racer, bmc_racer;
};

/// Racer threads that a race left behind (PortfolioOptions::abandon_after) and that still run.
std::size_t abandoned_racers();

ModelCheckerPtr make_portfolio_model_checker(PortfolioOptions options = {});

}  // namespace sfcv::engine

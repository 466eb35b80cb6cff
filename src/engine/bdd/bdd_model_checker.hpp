#pragma once
// The symbolic engine (`--engine bdd`): forward reachability with frontier sets (onion rings),
// CTL by fixpoints over BDDs (EX, EU, EG; fairness by Emerson-Lei), counterexamples and
// witnesses cut out of the onion rings and replayed through the explicit successor function, so
// that they read exactly like the explicit engine's. Same CheckTask, same CheckReport.

#include "engine/model_checker.hpp"

namespace sfcv::engine {

ModelCheckerPtr make_bdd_model_checker();

}  // namespace sfcv::engine

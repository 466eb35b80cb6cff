// The built-in engines by the names `--engine` gives them (explicit, bdd, bmc, kind, ic3, auto),
// made from one set of options, so that every command that checks (check, equiv) chooses alike.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/model_checker.hpp"

namespace sfcv::engine {

struct EngineSelection {
  BddEngineOptions bdd;
  ExplicitEngineOptions explicit_engine;
  std::uint32_t max_depth = 200;  ///< bmc and kind: the deepest unrolling
  std::uint32_t min_depth = 0;    ///< bmc: the shallowest depth tried (a swarm shard's range)
  /// auto: how it decided, one line each; may be empty.
  std::function<void(const std::string&)> note;
  /// auto: PortfolioOptions::abandon_after.
  std::optional<double> abandon_after;
};

/// True for the names make_engine_by_name() knows.
bool is_builtin_engine(std::string_view name);

/// The engine called `name`; std::invalid_argument for a name it does not know (external tools
/// such as NuSMV are made by their own factories).
ModelCheckerPtr make_engine_by_name(std::string_view name, const EngineSelection& selection);

}  // namespace sfcv::engine

#pragma once
// Replaying a trace on the semantics: a trace that another process found (a shard of
// `sfcv check --shard`, docs/distributed.md) is believed only if the successor function of the
// system, the one `sfcv simulate` follows, leads from an initial situation through each of its
// rows under the row's inputs.

#include <optional>
#include <string>

#include "logic/trace.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

/// nullopt when `trace` replays on `ts`: its first state is initial and each later state is a
/// successor of the one before whose condition holds for the row's inputs; else why not
/// ("row 3: no successor under its inputs reaches its state").
std::optional<std::string> replay_failure(const semantics::TransitionSystem& ts,
                                          const Trace& trace);

}  // namespace sfcv::logic

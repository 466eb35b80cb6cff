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

/// Sets the fired transitions of each row after the first to those of the successor that the
/// row's inputs take from the row before to the row's state: the transitions `sfcv simulate`
/// lists for that row. An engine whose graph keeps one edge per pair of states (the explicit
/// RSG merges their conditions and unions their fired sets, docs/semantics.md 2.1) would
/// otherwise list transitions that only another valuation of the edge clears (issue 53: with
/// `--multi-input-change`, c rising from {1,21} kept the situation's steps with nothing cleared
/// while a valuation where X21 -> X22 -> X23 -> X21 cycle transiently reached the same node).
/// A row that no successor explains is left as it is (replay_failure reports it).
void fire_as_replayed(const semantics::TransitionSystem& ts, Trace& trace);

/// Keeps each input of each row after the first at the row before's value wherever a successor
/// from the row before's state to the row's state still takes the valuation so changed, then
/// lists the transitions that the final valuation clears (fire_as_replayed). An engine that reads
/// a row's valuation off a model (the SAT engines) may move an input within values the system
/// does not tell apart (an integer input inside one region, docs/semantics.md 2.9) together with
/// the input the event changes: two inputs changing in one row, which `sfcv simulate` refuses
/// under the single-input-change hypothesis (issue 53: bmc on random grafcet 153, b falling
/// while n went from 9 to 7 inside its region n >= 5).
void minimise_input_changes(const semantics::TransitionSystem& ts, Trace& trace);

}  // namespace sfcv::logic

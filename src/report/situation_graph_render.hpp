#pragma once
// Renders an explicit reachable situations graph (Grafcet) or cycle state graph (IEC 61131-3)
// for `sfcv rsg`: its size, its listing, JSON (docs/formats.md), a DOT graph with one node per
// state, and one line per anomaly. The graph grouped by step situation is
// situation_graph_dot.hpp.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/explicit/reachable_situation_graph.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

struct SituationGraphText {
  std::string semantics;  ///< "grafcet" or "iec61131"
  /// Grafcet under the single-input-change rule: listed evolutions name the input that changed.
  bool single_input_change = false;
  bool list = false;  ///< every situation and evolution, after the summary
};

/// The summary (semantics, counts, build time) and, with `list`, every situation and evolution.
std::string situation_graph_text(const engine::ReachableSituationGraph& g,
                                 const semantics::TransitionSystem& ts,
                                 const SituationGraphText& options);
nlohmann::json situation_graph_json(const engine::ReachableSituationGraph& g,
                                    const semantics::TransitionSystem& ts,
                                    const SituationGraphText& options);
/// One node per state, labelled with its description; edges with their input conditions.
std::string state_graph_dot(const engine::ReachableSituationGraph& g,
                            const semantics::TransitionSystem& ts);
/// One line per distinct anomaly: "MODEL: error: MESSAGE; inputs: ...; cycle: ...".
std::vector<std::string> anomaly_lines(const engine::ReachableSituationGraph& g,
                                       const semantics::TransitionSystem& ts,
                                       const std::string& model);

}  // namespace sfcv::report

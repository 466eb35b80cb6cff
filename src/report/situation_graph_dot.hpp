#pragma once
// The reachable situations graph of a Grafcet grouped by step situation, in Graphviz DOT: one
// node per set of active steps (the stable situations that differ only in their input values
// folded into it, and the transient situations crossed inside an evolution folded into its
// edge), one edge per pair of step situations with the transitions that fire between them. A
// size cap keeps the picture readable and quick to lay out.

#include <cstddef>
#include <map>
#include <set>
#include <string>

#include "engine/explicit/reachable_situation_graph.hpp"

namespace sfcv::report {

struct SituationGraphOptions {
  std::size_t max_nodes = 60;  ///< step situations drawn (breadth-first order); 0: all of them
  std::string option_name = "--max-nodes";  ///< named in the truncation note
  /// Step situations drawn beyond the cap (the ones a trace visits), as node_ids keys.
  std::set<std::string> keep;
};

struct SituationGraphDot {
  std::string dot;
  std::size_t stable_situations = 0;  ///< the RSG's nodes
  std::size_t step_situations = 0;    ///< distinct sets of active steps among them
  std::size_t shown = 0;              ///< step situations drawn
  std::size_t edges = 0;              ///< edges drawn between step situations
  /// Empty unless the cap left situations out: "60 of 159 step situations are drawn ...".
  std::string truncation_note;
  /// DOT (and SVG) id of each drawn node ("sg3"), by its active steps' observable names,
  /// sorted and joined by ",": how a page finds a trace's situation.
  std::map<std::string, std::string> node_ids;
  std::size_t omitted() const { return step_situations - shown; }
};

SituationGraphDot situation_graph_dot(const engine::ReachableSituationGraph& graph,
                                      const SituationGraphOptions& options = {});

}  // namespace sfcv::report

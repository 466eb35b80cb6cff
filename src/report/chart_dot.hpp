#pragma once
// A picture of a chart in Graphviz DOT: steps as boxes (initial steps doubled), transitions as
// bars labelled with their guards, simultaneous divergences and convergences as double bars,
// action blocks beside their steps with qualifier and action name, nested charts as clusters.

#include <map>
#include <ostream>
#include <string>

#include "model/chart.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

/// Every node carries a DOT id ("p0c1s3": POU 0, chart 1, step 3; "p0c1t2" a transition) that
/// graphviz keeps in its SVG, so that a page can address it.
void print_chart_dot(std::ostream& out, const model::Project& project);

/// The DOT ids of a system's steps (by observable name) and transitions (by transition name).
struct ChartNodeIds {
  std::map<std::string, std::string> steps, transitions;
};
ChartNodeIds chart_node_ids(const model::Project& project, const semantics::TransitionSystem& ts);

}  // namespace sfcv::report

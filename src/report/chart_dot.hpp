#pragma once
// A picture of a chart in Graphviz DOT: steps as boxes (initial steps doubled), transitions as
// bars labelled with their guards, simultaneous divergences and convergences as double bars,
// action blocks beside their steps with qualifier and action name, nested charts as clusters.

#include <ostream>

#include "model/chart.hpp"

namespace sfcv::report {

void print_chart_dot(std::ostream& out, const model::Project& project);

}  // namespace sfcv::report

#pragma once
// The HTML report (`sfcv check --html`, `sfcv report result.json --html`): one self-contained
// page, no network access: a summary of every property and check, the chart as SVG, and a
// player for each counterexample or witness (steps and fired transitions highlighted on the
// chart cycle by cycle, the cycle's inputs and values, a waveform with a cursor).

#include <string>

#include <nlohmann/json.hpp>

#include "report/chart_dot.hpp"

namespace sfcv::report {

struct HtmlReport {
  nlohmann::json result;   ///< `sfcv check --json` (check_json)
  std::string chart_svg;   ///< graphviz SVG of the chart (dot_to_svg); empty: chart_note says why
  std::string chart_note;
  ChartNodeIds node_ids;   ///< SVG node ids of the steps and transitions the traces name
};

std::string check_html(const HtmlReport& report);

/// The report of `result` on `project`: the chart DOT laid out once by graphviz (a missing
/// `dot` is said on the page), and the node ids of `ts`'s steps and transitions.
HtmlReport html_report(nlohmann::json result, const model::Project& project,
                       const semantics::TransitionSystem& ts);

}  // namespace sfcv::report

#pragma once
// The HTML report (`sfcv check --html`, `sfcv report result.json --html`): one self-contained
// page, no network access: a summary of every property and check, the chart as SVG, and a
// player for each counterexample or witness (steps and fired transitions highlighted on the
// chart cycle by cycle, the cycle's inputs and values, a waveform with a cursor).

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "report/chart_dot.hpp"

namespace sfcv::report {

struct HtmlReport {
  nlohmann::json result;  ///< `sfcv check --json` (check_json)
  std::string chart_svg;  ///< graphviz SVG of the chart (dot_to_svg); empty: chart_note says why
  std::string chart_note;
  ChartNodeIds node_ids;  ///< SVG node ids of the steps and transitions the traces name
  /// Grafcet only: the reachable situations graph grouped by step situation, as SVG
  /// (situation_graph_dot); empty: situation_graph_note says why (empty too for IEC 61131-3).
  std::string situation_graph_svg;
  std::string situation_graph_note;
  std::map<std::string, std::string> situation_node_ids;  ///< SituationGraphDot::node_ids
};

std::string check_html(const HtmlReport& report);

/// `sfcv query --html`: the answers (the `sfcv query --json` document) with the same chart and
/// situation graph as the check report.
std::string query_html(const nlohmann::json& answers, const HtmlReport& pictures);

/// How much time and layout the pictures of a report may take. A report written at the end of
/// a run with --timeout gets the time left (after the deadline: no picture, a note says why);
/// graphviz's layout grows faster than the chart (a 500-step loop: 3 s, 2,000 steps: 221 s), so
/// a chart larger than max_chart_elements is not laid out, with a note.
struct PictureLimits {
  double seconds = 60;                    ///< for each of the chart layout and the situation graph
  std::size_t max_chart_elements = 1000;  ///< steps + transitions of the chart layout
};

/// The situation graph of a Grafcet system for a report: explored within kReportMaxSituations
/// stable situations (a larger graph is not drawn and the note says so), grouped and laid out:
/// the first kReportMaxNodes step situations breadth-first and those in `keep`.
void add_situation_graph(HtmlReport& report, const semantics::TransitionSystem& ts,
                         const std::set<std::string>& keep = {}, const PictureLimits& limits = {});
inline constexpr std::uint64_t kReportMaxSituations = 100'000;
inline constexpr std::size_t kReportMaxNodes = 40;  ///< step situations drawn on a report

/// The report of `result` on `project`: the chart DOT laid out once by graphviz (a missing
/// `dot` is said on the page), the node ids of `ts`'s steps and transitions, and for Grafcet
/// the situation graph (add_situation_graph).
/// The pictures of a report without a result: the chart, its node ids, the situation graph.
/// `keep`: step situations to draw on the situation graph even beyond its cap.
HtmlReport html_pictures(const model::Project& project, const semantics::TransitionSystem& ts,
                         const std::set<std::string>& keep = {}, const PictureLimits& limits = {});

HtmlReport html_report(nlohmann::json result, const model::Project& project,
                       const semantics::TransitionSystem& ts, const PictureLimits& limits = {});

}  // namespace sfcv::report

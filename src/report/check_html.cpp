#include "report/check_html.hpp"

#include <chrono>
#include <cstdio>
#include <optional>
#include <sstream>

#include "engine/explicit/reachable_situation_graph.hpp"
#include "report/graphviz_svg.hpp"
#include "report/html_page.hpp"
#include "report/markup.hpp"
#include "report/numbers.hpp"
#include "report/provenance.hpp"
#include "report/report_assets.hpp"
#include "report/situation_graph_dot.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

using nlohmann::json;

std::string seconds_cell(const json& j) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", j.is_number() ? j.get<double>() : 0.0);
  return buf;
}

/// A count of the result ("states", "edges"): a number, a decimal string past 64 bits, or
/// nothing when the engine did not count (null: SAT engines, --engine auto's race).
std::optional<std::string> count_text(const json& j, const char* key) {
  if (!j.contains(key)) return std::nullopt;
  const auto& v = j[key];
  if (v.is_number_unsigned()) return std::to_string(v.get<std::uint64_t>());
  if (v.is_number_integer()) return std::to_string(v.get<std::int64_t>());
  if (v.is_string()) return html_escape(v.get<std::string>());
  return std::nullopt;
}

/// JSON inside <script>: "</" would end the element early.
std::string script_json(const json& j) {
  std::string text = j.dump();
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

/// The one place the summary takes a property's English from: a "description" string of its
/// result (e.g. a requirement pattern's text), shown under its name; empty when there is none.
std::string description_of(const json& property) {
  return json_text(property, "description");
}

std::string summary(const json& result) {
  std::string rows;
  const std::string engine = json_text(result, "engine");
  const auto& props = result["properties"];
  for (std::size_t i = 0; i < props.size(); ++i) {
    const auto& p = props[i];
    const std::string verdict = json_text(p, "verdict");
    std::string what = json_text(p, "message");
    if (p["kind"] == "property" && json_text(p, "formula") != json_text(p, "name"))
      what = "<code>" + html_escape(json_text(p, "formula")) + "</code> " + html_escape(what);
    else
      what = html_escape(what);
    if (p.contains("description")) what = html_escape(json_text(p, "description")) + " " + what;
    // Two findings in the table, the rest folded away.
    std::string findings, more;
    std::size_t n = 0;
    for (const auto& f : p["findings"])
      (n++ < 2 ? findings : more) += "<li>" + html_escape(f.get<std::string>()) + "</li>";
    if (!more.empty())
      findings += "<li><details><summary>" + std::to_string(n - 2) + " more</summary><ul>" + more +
                  "</ul></details></li>";
    if (p.contains("findings_total") &&
        p["findings_total"].get<std::size_t>() > p["findings"].size())
      findings += "<li>" + std::to_string(p["findings"].size()) + " of " +
                  std::to_string(p["findings_total"].get<std::size_t>()) +
                  " findings shown; --all for every one</li>";
    std::string trace;
    if (p["trace"].is_object())
      trace = "<a class=\"play\" href=\"#player\" data-property=\"" + std::to_string(i) + "\">" +
              html_escape(json_text(p["trace"], "kind")) + " (" +
              counted(p["trace"]["steps"].size(), "situation") + ")</a>";
    const std::string description = description_of(p);
    const std::string justification = json_text(p, "justification");
    rows += "<tr><td class=\"name\">" + html_escape(json_text(p, "name")) +
            (description.empty()
                 ? ""
                 : "<div class=\"description\">" + html_escape(description) + "</div>") +
            (justification.empty() ? ""
                                   : "<div class=\"description\">justification: " +
                                         html_escape(justification) + "</div>") +
            "</td><td>" + html_verdict(verdict) + "</td><td>" + html_escape(engine) +
            "</td><td class=\"time\">" + seconds_cell(p["seconds"]) + "</td><td>" + what +
            (findings.empty() ? "" : "<ul class=\"findings\">" + findings + "</ul>") + "</td><td>" +
            trace + "</td></tr>\n";
  }
  return "<div class=\"scroll\"><table class=\"summary\" id=\"summary-table\">\n<tr><th>property "
         "or check</th><th>verdict</th>"
         "<th>engine</th><th>time</th><th>what was found</th><th>trace</th></tr>\n" +
         rows + "</table></div>\n";
}

/// The Grafcet situation graph's section; nothing for IEC 61131-3.
std::string situation_graph_section(const HtmlReport& report) {
  if (report.situation_graph_svg.empty() && report.situation_graph_note.empty()) return "";
  std::string out =
      "<section id=\"situations\">\n<h2>Reachable situations, grouped by step situation</h2>\n"
      "<p class=\"note\">One node per set of active steps (a doubled border: initial), the stable "
      "situations that differ only in their inputs folded into it; an edge lists the transitions "
      "fired between two step situations, the transient situations crossed included. An output "
      "with ? is emitted in some of the node's stable situations only.</p>\n";
  if (!report.situation_graph_note.empty())
    out += "<p class=\"note" + std::string(report.situation_graph_svg.empty() ? " warn" : "") +
           "\" id=\"situations-note\">" + html_escape(report.situation_graph_note) + "</p>\n";
  if (!report.situation_graph_svg.empty())
    out +=
        "<div id=\"situations-svg\" class=\"fit\">\n" + report.situation_graph_svg + "\n</div>\n";
  return out + "</section>\n";
}

std::string chart_section(const HtmlReport& report) {
  // Fitted to their boxes; a click toggles the natural size (the pages' scripts).
  std::string out =
      "<section id=\"chart\">\n<h2>Chart</h2>\n<div id=\"chart-svg\" class=\"fit\">\n";
  out += report.chart_svg.empty()
             ? "<p class=\"note warn\">" + html_escape(report.chart_note) + "</p>\n"
             : report.chart_svg + "\n";
  return out + "</div>\n</section>\n";
}

/// One query's answer: its value or its set, the elements listed (the first ones shown, the
/// rest folded away).
/// "1 situation", "12 situations", "0 steps": a set's count with its sort's noun ("empty": the
/// empty set's sort, no noun to agree).
std::string set_count(std::uint64_t n, const std::string& sort) {
  if (sort.size() > 1 && sort.back() == 's')
    return counted(n, sort.substr(0, sort.size() - 1), sort);
  return std::to_string(n) + " " + sort;
}

std::string query_row(const json& q) {
  constexpr std::size_t kShown = 10, kListed = 200;  // shown, then folded; the JSON has all
  const std::string sort = json_text(q, "sort");
  std::string answer;
  if (sort == "test") {
    answer = q.value("value", false) ? "true" : "false";
    if (q.contains("count"))
      answer += ", witness: " + html_escape(set_count(q["count"].get<std::uint64_t>(),
                                                      json_text(q, "witness_sort")));
  } else if (sort == "number") {
    answer = std::to_string(q["value"].get<std::int64_t>());
  } else {
    answer = html_escape(set_count(q.value("count", 0ULL), sort));
  }
  std::string shown, more;
  std::size_t n = 0;
  if (q.contains("elements"))
    for (const auto& e : q["elements"]) {
      if (n == kListed) break;
      const std::string text = e.is_string() ? e.get<std::string>() : json_text(e, "text");
      (n++ < kShown ? shown : more) += "<li><code>" + html_escape(text) + "</code></li>";
    }
  const std::size_t total = q.contains("elements") ? q["elements"].size() : 0;
  if (total > kListed)
    more += "<li>" + std::to_string(total - kListed) +
            " more not listed here; sfcv query --json lists every one</li>";
  if (!more.empty())
    shown += "<li><details><summary>" + std::to_string(total - kShown) + " more</summary><ul>" +
             more + "</ul></details></li>";
  const std::string verdict = json_text(q, "verdict");
  return "<tr class=\"query\"><td class=\"name\"><code>" + html_escape(json_text(q, "query")) +
         "</code></td><td class=\"answer\">" + answer + "</td><td>" +
         (verdict.empty() ? "" : html_verdict(verdict)) + "</td><td>" +
         (shown.empty() ? "" : "<ul class=\"elements\">" + shown + "</ul>") + "</td></tr>\n";
}

}  // namespace

HtmlReport html_report(nlohmann::json result, const model::Project& project,
                       const semantics::TransitionSystem& ts, const PictureLimits& limits) {
  // The situations the traces visit are drawn on the situation graph whatever its cap.
  std::set<std::string> visited;
  if (result.contains("properties"))
    for (const auto& p : result["properties"])
      if (p.contains("trace") && p["trace"].is_object())
        for (const auto& step : p["trace"]["steps"]) {
          std::set<std::string> names;
          for (const auto& n : step["active_steps"]) names.insert(n.get<std::string>());
          std::string key;
          for (const auto& n : names) key += (key.empty() ? "" : ",") + n;
          visited.insert(key);
        }
  HtmlReport r = html_pictures(project, ts, visited, limits);
  r.result = std::move(result);
  return r;
}

namespace {

using Clock = std::chrono::steady_clock;

std::size_t chart_elements(const model::Project& project) {
  std::size_t n = 0;
  for (const auto& pou : project.pous)
    for (const auto& chart : pou.charts) n += chart.steps.size() + chart.transitions.size();
  return n;
}

std::string limit_seconds_text(double s) {
  std::ostringstream out;
  out << (s >= 10 ? static_cast<double>(static_cast<long long>(s)) : s);
  return out.str();
}

}  // namespace

HtmlReport html_pictures(const model::Project& project, const semantics::TransitionSystem& ts,
                         const std::set<std::string>& keep, const PictureLimits& limits) {
  const auto start = Clock::now();
  HtmlReport r;
  r.node_ids = chart_node_ids(project, ts);
  if (const auto n = chart_elements(project); n > limits.max_chart_elements) {
    r.chart_note = "the chart (" + std::to_string(n) +
                   " steps and transitions) is not drawn: a report lays out at most " +
                   std::to_string(limits.max_chart_elements) +
                   " (graphviz needed 221 s for a 2,000-step loop); `sfcv export --to dot` "
                   "gives the whole chart as DOT";
  } else if (limits.seconds <= 0) {
    r.chart_note = "the chart is not drawn: the run's time limit had passed";
  } else {
    std::ostringstream dot;
    print_chart_dot(dot, project);
    auto svg = dot_to_svg(dot.str(), limits.seconds);
    r.chart_svg = std::move(svg.svg);
    r.chart_note = std::move(svg.error);
  }
  // The situation graph gets what the chart's layout left.
  PictureLimits rest = limits;
  rest.seconds = limits.seconds - std::chrono::duration<double>(Clock::now() - start).count();
  add_situation_graph(r, ts, keep, rest);
  return r;
}

void add_situation_graph(HtmlReport& report, const semantics::TransitionSystem& ts,
                         const std::set<std::string>& keep, const PictureLimits& limits) {
  if (ts.kind() != semantics::SemanticsKind::Grafcet) return;
  if (limits.seconds <= 0) {
    report.situation_graph_note =
        "the reachable situations graph was not drawn: the run's time limit had passed";
    return;
  }
  const auto start = Clock::now();
  engine::ExplorationOptions eo;
  eo.max_states = kReportMaxSituations;
  eo.timeout_seconds = limits.seconds;
  eo.keep_conditions = false;
  const auto graph = engine::build_reachable_situation_graph(ts, eo);
  if (!graph.complete()) {
    report.situation_graph_note = "the reachable situations graph was not drawn: its " +
                                  graph.limit_reached() + " limit (" +
                                  std::to_string(kReportMaxSituations) + " stable situations, " +
                                  limit_seconds_text(limits.seconds) + " s) was reached";
    return;
  }
  SituationGraphOptions so;
  so.max_nodes = kReportMaxNodes;
  so.option_name = "sfcv rsg --dot FILE --max-nodes";
  so.keep = keep;
  const auto grouped = situation_graph_dot(graph, so);
  const double left = limits.seconds - std::chrono::duration<double>(Clock::now() - start).count();
  if (left <= 0) {
    report.situation_graph_note =
        "the reachable situations graph was not drawn: the report's time ran out";
    return;
  }
  auto svg = dot_to_svg(grouped.dot, left);
  report.situation_graph_svg = std::move(svg.svg);
  if (!report.situation_graph_svg.empty()) report.situation_node_ids = grouped.node_ids;
  report.situation_graph_note = svg.error.empty() ? grouped.truncation_note : svg.error;
  std::string counts = std::to_string(grouped.step_situations) + " step situations, " +
                       std::to_string(grouped.stable_situations) + " stable situations";
  report.situation_graph_note =
      counts + (report.situation_graph_note.empty() ? "" : "; ") + report.situation_graph_note;
}

namespace {
/// Who ran what, when, on which files (the result's "provenance"), folded under the summary;
/// nothing for a result saved before sfcv recorded it.
std::string provenance_section(const json& result) {
  const auto it = result.find("provenance");
  if (it == result.end() || !it->is_object()) return {};
  return "<details class=\"provenance\"><summary>Provenance: sfcv " +
         html_escape(it->value("version", std::string())) + ", " +
         html_escape(it->value("date", std::string())) + "</summary>\n<pre>" +
         html_escape(provenance_text(provenance_from_json(*it))) + "</pre></details>\n";
}
}  // namespace

std::string check_html(const HtmlReport& report) {
  const auto& r = report.result;
  const std::string model = json_text(r, "model");
  std::string meta = html_escape(json_text(r, "semantics")) + " semantics &middot; " +
                     html_escape(json_text(r, "engine")) + " engine";
  const auto states = count_text(r, "states");
  meta += " &middot; " + (states ? *states + " states" : std::string("states not counted"));
  if (const auto edges = count_text(r, "edges")) meta += " &middot; " + *edges + " edges";
  meta += " &middot; " + seconds_cell(r["seconds"]);
  if (r.contains("complete") && !r["complete"].get<bool>())
    meta += json_text(r, "limit") == "interrupted"
                ? std::string(" &middot; <strong>incomplete: interrupted</strong>")
                : " &middot; <strong>incomplete: the " + html_escape(json_text(r, "limit")) +
                      " limit was reached</strong>";

  json nodes;
  nodes["steps"] = report.node_ids.steps;
  nodes["transitions"] = report.node_ids.transitions;
  nodes["situations"] = report.situation_node_ids;
  json data;
  data["result"] = r;
  data["nodes"] = nodes;
  make_valid_utf8(data);  // a result read back by `sfcv report`, names of the chart: bytes

  std::string out = html_page_head("sfcv report: " + model);
  std::vector<std::pair<std::string, std::string>> nav = {
      {"properties", "Properties"}, {"chart", "Chart"}, {"player", "Trace player"}};
  if (!report.situation_graph_svg.empty() || !report.situation_graph_note.empty())
    nav.emplace_back("situations", "Situations");
  out += html_page_nav(nav);
  out += "<h1>sfcv check: " + html_escape(model) + "</h1>\n<p class=\"meta\">" + meta + "</p>\n";
  out += "<h2 id=\"properties\">Properties and standard checks</h2>\n" + summary(r) +
         provenance_section(r);
  out += "<div class=\"layout\">\n" + chart_section(report);
  out += R"html(<section id="player" hidden>
<h2>Trace player</h2>
<p><select id="trace-select" aria-label="trace"></select></p>
<p id="trace-title"></p>
<p class="note" id="trace-note"></p>
<p class="controls"><button id="first" title="first cycle (Home)">&#x25C0;&#x25C0;</button><button id="prev" title="previous cycle (&#8592;)">&#x25C0;</button><button id="next" title="next cycle (&#8594;)">&#x25B6;</button><button id="last" title="last cycle (End)">&#x25B6;&#x25B6;</button><span id="cycle-label"></span></p>
<p class="note">Keys: <kbd>&#8592;</kbd> <kbd>&#8594;</kbd> <kbd>Home</kbd> <kbd>End</kbd>. Active steps are blue on the chart, the transitions fired into the cycle orange.</p>
<dl class="cycle">
<dt>active steps</dt><dd id="active-steps"></dd>
<dt>fired to get here</dt><dd id="fired"></dd>
<dt>inputs (changed ones outlined)</dt><dd id="inputs"></dd>
<dt>outputs and values (the property's atoms in bold)</dt><dd id="values"></dd>
</dl>
<div id="waveform"></div>
</section>
</div>
)html";
  out += situation_graph_section(report);
  out += "<script type=\"application/json\" id=\"sfcv-data\">" + script_json(data) + "</script>\n";
  out += "<script>\n" + std::string(report_script()) + "</script>\n" + html_pictures_script() +
         html_layout_probe();
  out += "</body>\n</html>\n";
  return valid_utf8(out);  // names are bytes; the page says charset=utf-8
}

std::string query_html(const nlohmann::json& answers, const HtmlReport& pictures) {
  const std::string model = json_text(answers, "model");
  std::string meta = html_escape(json_text(answers, "semantics")) + " semantics";
  if (answers.contains("graph")) {
    const auto& g = answers["graph"];
    meta += " &middot; " + counted(g.value("situations", 0ULL), "situation") + " &middot; " +
            counted(g.value("evolutions", 0ULL), "evolution");
    if (!g.value("complete", true))
      meta += " &middot; <strong>incomplete: the " + html_escape(json_text(g, "limit")) +
              " limit was reached; the sets may be wrong in both directions</strong>";
    if (g.value("anomalies", 0ULL) > 0)
      meta += " &middot; <strong>" +
              counted(g["anomalies"].get<std::uint64_t>(), "anomaly", "anomalies") +
              ": the evolutions they cut are missing</strong>";
  }
  std::string rows;
  for (const auto& q : answers["queries"]) rows += query_row(q);
  std::string out = html_page_head("sfcv query: " + model);
  std::vector<std::pair<std::string, std::string>> nav = {{"answers", "Answers"}};
  if (!pictures.situation_graph_svg.empty() || !pictures.situation_graph_note.empty())
    nav.emplace_back("situations", "Situations");
  nav.emplace_back("chart", "Chart");
  out += html_page_nav(nav);
  out += "<h1>sfcv query: " + html_escape(model) + "</h1>\n<p class=\"meta\">" + meta + "</p>\n";
  out +=
      "<h2 id=\"answers\">Query answers</h2>\n<div class=\"scroll\"><table class=\"summary\" "
      "id=\"query-table\">\n<tr><th>query</th>"
      "<th>answer</th><th>verdict</th><th>elements</th></tr>\n" +
      rows + "</table></div>\n";
  out += situation_graph_section(pictures);
  out += chart_section(pictures);
  out += html_pictures_script();
  return valid_utf8(out + html_layout_probe() + "</body>\n</html>\n");
}

}  // namespace sfcv::report

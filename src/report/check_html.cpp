#include "report/check_html.hpp"

#include <cstdio>
#include <sstream>

#include "report/graphviz_svg.hpp"
#include "report/report_assets.hpp"

namespace sfcv::report {

namespace {

using nlohmann::json;

std::string escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '&': r += "&amp;"; break;
      case '"': r += "&quot;"; break;
      default: r += c;
    }
  }
  return r;
}

std::string str(const json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

std::string seconds(const json& j) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", j.is_number() ? j.get<double>() : 0.0);
  return buf;
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

std::string summary(const json& result) {
  std::string rows;
  const std::string engine = str(result, "engine");
  const auto& props = result["properties"];
  for (std::size_t i = 0; i < props.size(); ++i) {
    const auto& p = props[i];
    const std::string verdict = str(p, "verdict");
    std::string cls = verdict;
    for (auto& c : cls)
      if (c == ' ') c = '-';
    std::string what = str(p, "message");
    if (p["kind"] == "property" && str(p, "formula") != str(p, "name"))
      what = "<code>" + escape(str(p, "formula")) + "</code> " + escape(what);
    else
      what = escape(what);
    if (p.contains("description")) what = escape(str(p, "description")) + " " + what;
    // Two findings in the table, the rest folded away.
    std::string findings, more;
    std::size_t n = 0;
    for (const auto& f : p["findings"])
      (n++ < 2 ? findings : more) += "<li>" + escape(f.get<std::string>()) + "</li>";
    if (!more.empty())
      findings += "<li><details><summary>" + std::to_string(n - 2) + " more</summary><ul>" + more +
                  "</ul></details></li>";
    if (p.contains("findings_total") && p["findings_total"].get<std::size_t>() > p["findings"].size())
      findings += "<li>" + std::to_string(p["findings"].size()) + " of " +
                  std::to_string(p["findings_total"].get<std::size_t>()) +
                  " findings shown; --all for every one</li>";
    std::string trace;
    if (p["trace"].is_object())
      trace = "<a class=\"play\" href=\"#player\" data-property=\"" + std::to_string(i) + "\">" +
              escape(str(p["trace"], "kind")) + " (" + std::to_string(p["trace"]["steps"].size()) +
              " situations)</a>";
    rows += "<tr><td class=\"name\">" + escape(str(p, "name")) + "</td><td><span class=\"verdict " + escape(cls) +
            "\">" + escape(verdict) + "</span></td><td>" + escape(engine) + "</td><td class=\"time\">" +
            seconds(p["seconds"]) + "</td><td>" + what +
            (findings.empty() ? "" : "<ul class=\"findings\">" + findings + "</ul>") + "</td><td>" +
            trace + "</td></tr>\n";
  }
  return "<table class=\"summary\" id=\"summary-table\">\n<tr><th>property or check</th><th>verdict</th>"
         "<th>engine</th><th>time</th><th>what was found</th><th>trace</th></tr>\n" +
         rows + "</table>\n";
}

}  // namespace

HtmlReport html_report(nlohmann::json result, const model::Project& project,
                       const semantics::TransitionSystem& ts) {
  HtmlReport r;
  r.result = std::move(result);
  std::ostringstream dot;
  print_chart_dot(dot, project);
  auto svg = dot_to_svg(dot.str());
  r.chart_svg = std::move(svg.svg);
  r.chart_note = std::move(svg.error);
  r.node_ids = chart_node_ids(project, ts);
  return r;
}

std::string check_html(const HtmlReport& report) {
  const auto& r = report.result;
  const std::string model = str(r, "model");
  std::string meta = escape(str(r, "semantics")) + " semantics &middot; " + escape(str(r, "engine")) +
                     " engine &middot; " + std::to_string(r.value("states", 0ULL)) + " states";
  if (r.contains("edges") && r["edges"].is_number())
    meta += " &middot; " + std::to_string(r["edges"].get<std::uint64_t>()) + " edges";
  meta += " &middot; " + seconds(r["seconds"]);
  if (r.contains("complete") && !r["complete"].get<bool>())
    meta += " &middot; <strong>incomplete: the " + escape(str(r, "limit")) + " limit was reached</strong>";

  json nodes;
  nodes["steps"] = report.node_ids.steps;
  nodes["transitions"] = report.node_ids.transitions;
  json data;
  data["result"] = r;
  data["nodes"] = nodes;

  std::string out;
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>sfcv report: " + escape(model) + "</title>\n<style>\n" + std::string(report_style()) +
         "</style>\n</head>\n<body>\n";
  out += "<h1>sfcv check: " + escape(model) + "</h1>\n<p class=\"meta\">" + meta + "</p>\n";
  out += "<h2>Properties and standard checks</h2>\n" + summary(r);
  out += "<div class=\"layout\">\n<section id=\"chart\">\n<h2>Chart</h2>\n<div id=\"chart-svg\">\n";
  out += report.chart_svg.empty() ? "<p class=\"note warn\">" + escape(report.chart_note) + "</p>\n"
                                  : report.chart_svg + "\n";
  out += "</div>\n</section>\n";
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
  out += "<script type=\"application/json\" id=\"sfcv-data\">" + script_json(data) + "</script>\n";
  out += "<script>\n" + std::string(report_script()) + "</script>\n</body>\n</html>\n";
  return out;
}

}  // namespace sfcv::report

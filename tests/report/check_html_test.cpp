#include "report/check_html.hpp"

#include <gtest/gtest.h>

namespace sfcv::report {
namespace {

nlohmann::json result() {
  return nlohmann::json::parse(R"json({
    "model": "plant.st", "semantics": "iec61131", "engine": "explicit", "states": 2, "edges": 1,
    "complete": true, "seconds": 0.25,
    "properties": [
      {"name": "AG !(a & b)", "kind": "property", "formula": "AG !(a & b)", "verdict": "violated",
       "message": "", "findings": [], "findings_total": 0, "seconds": 0.5,
       "trace": {"kind": "counterexample", "loop_start": null, "marked": ["a"], "note": "</script>",
                 "steps": [{"index": 0, "inputs": {"go": false}, "changed": [], "fired": [],
                            "active_steps": ["P.S0"], "values": {"a": false}}]}},
      {"name": "reachable", "kind": "standard-check", "check": "reachable", "formula": "",
       "verdict": "not checked", "message": "x < y", "findings": ["f1", "f2", "f3"],
       "findings_total": 25, "seconds": 0, "trace": null}
    ]})json");
}

TEST(CheckHtml, SummaryChartAndPlayerData) {
  HtmlReport r;
  r.result = result();
  r.chart_svg = "<svg id=\"chart\"></svg>";
  r.node_ids.steps["P.S0"] = "p0c0s0";
  const auto html = check_html(r);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<span class=\"verdict violated\">violated</span>"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"verdict not-checked\">not checked</span>"), std::string::npos);
  EXPECT_NE(html.find("x &lt; y"), std::string::npos);                   // escaped
  EXPECT_NE(html.find("<summary>1 more</summary>"), std::string::npos);  // f3 folded away
  EXPECT_NE(html.find("3 of 25 findings shown; --all for every one"), std::string::npos);
  EXPECT_NE(html.find("data-property=\"0\">counterexample (1 situation)</a>"), std::string::npos);
  EXPECT_NE(html.find("<svg id=\"chart\"></svg>"), std::string::npos);
  EXPECT_NE(html.find("\"steps\":{\"P.S0\":\"p0c0s0\"}"), std::string::npos);
  // Data inside <script> cannot close it early; nothing is fetched from the network.
  EXPECT_EQ(html.find("</script>\"}"), std::string::npos);
  EXPECT_NE(html.find("<\\/script>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_NE(html.find("document.getElementById(\"sfcv-data\")"), std::string::npos);  // the script
}

TEST(CheckHtml, StatesNotCountedOrPast64BitsAndTheNotApplicableVerdict) {
  // The SAT engines and --engine auto's race count no states: "states": null (the report used
  // to stop with "type must be number, but is null"); a symbolic count past 2^64 is a string.
  HtmlReport r;
  r.result = result();
  r.result["engine"] = "ic3";
  r.result["states"] = nullptr;
  r.result["edges"] = nullptr;
  r.result["properties"][1]["verdict"] = "n/a";
  auto html = check_html(r);
  EXPECT_NE(html.find("ic3 engine &middot; states not counted &middot;"), std::string::npos);
  EXPECT_EQ(html.find(" edges"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"verdict n-a\">n/a</span>"), std::string::npos);
  r.result["states"] = "36893488147419103232";
  r.result["edges"] = 7;
  html = check_html(r);
  EXPECT_NE(html.find("36893488147419103232 states &middot; 7 edges"), std::string::npos);
}

TEST(CheckHtml, InvalidUtf8InNamesGivesAUtf8Page) {
  HtmlReport r;
  r.result = result();
  r.result["properties"][0]["name"] = "S\xFF";
  r.node_ids.steps["P.S\xE4"] = "p0c0s1";
  const auto html = check_html(r);  // threw in the JSON dump of the player's data
  EXPECT_NE(html.find("S\xEF\xBF\xBD</td>"), std::string::npos);
  EXPECT_NE(html.find("\"P.S\xEF\xBF\xBD\":\"p0c0s1\""), std::string::npos);
  EXPECT_EQ(html.find('\xFF'), std::string::npos);
  EXPECT_EQ(html.find('\xE4'), std::string::npos);
}

TEST(CheckHtml, ShowsAPropertysDescriptionUnderItsName) {
  HtmlReport r;
  r.result = result();
  r.result["properties"][0]["description"] = "a & b never hold <together>";
  const auto html = check_html(r);
  EXPECT_NE(
      html.find(
          "AG !(a &amp; b)<div class=\"description\">a &amp; b never hold &lt;together&gt;</div>"),
      std::string::npos);
  EXPECT_EQ(check_html(HtmlReport{result(), "", "", {}, "", "", {}}).find("class=\"description\""),
            std::string::npos);
}

TEST(CheckHtml, SituationGraphSectionAndQueryPage) {
  HtmlReport r;
  r.result = result();
  const auto iec = check_html(r);
  EXPECT_EQ(iec.find("id=\"situations\""), std::string::npos);  // IEC 61131-3: no situation graph
  r.situation_graph_svg = "<svg id=\"rsg\"></svg>";
  r.situation_graph_note = "5 step situations, 96 stable situations";
  r.situation_node_ids["X10,X20"] = "sg0";
  const auto html = check_html(r);
  EXPECT_NE(html.find("<div id=\"situations-svg\" class=\"fit\">\n<svg id=\"rsg\"></svg>"),
            std::string::npos);
  EXPECT_NE(html.find("5 step situations, 96 stable situations"), std::string::npos);
  EXPECT_NE(html.find("\"situations\":{\"X10,X20\":\"sg0\"}"), std::string::npos);

  const auto answers = nlohmann::json::parse(R"json({
    "model": "p.g7", "semantics": "grafcet",
    "graph": {"situations": 96, "evolutions": 480, "complete": true, "limit": "", "anomalies": 0},
    "queries": [
      {"query": "Y0", "sort": "situations", "count": 12,
       "elements": [{"text": "#0 {X10, X20}"}, {"text": "#1"}, {"text": "#2"}, {"text": "#3"},
                    {"text": "#4"}, {"text": "#5"}, {"text": "#6"}, {"text": "#7"}, {"text": "#8"},
                    {"text": "#9"}, {"text": "#10"}, {"text": "#11 <last>"}]},
      {"query": "card(Y)", "sort": "number", "value": 96},
      {"query": "Y0 = {}", "sort": "test", "value": false, "verdict": "violated"}
    ]})json");
  const auto page = query_html(answers, r);
  EXPECT_NE(page.find("<h1>sfcv query: p.g7</h1>"), std::string::npos);
  EXPECT_NE(page.find("96 situations &middot; 480 evolutions"), std::string::npos);
  EXPECT_NE(
      page.find("<td class=\"name\"><code>Y0</code></td><td class=\"answer\">12 situations</td>"),
      std::string::npos)
      << page;
  EXPECT_NE(page.find("<summary>2 more</summary>"), std::string::npos);
  EXPECT_NE(page.find("<code>#11 &lt;last&gt;</code>"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"answer\">96</td>"), std::string::npos);
  EXPECT_NE(
      page.find(
          "<td class=\"answer\">false</td><td><span class=\"verdict violated\">violated</span>"),
      std::string::npos);
  EXPECT_NE(page.find("<svg id=\"rsg\"></svg>"), std::string::npos);
  EXPECT_EQ(page.find("src=\"http"), std::string::npos);
}

TEST(CheckHtml, OneIsSingularOnTheQueryPage) {
  // Issue 48: "1 situations". A count of one takes the singular noun, in the header and in
  // the answers (a set, a test's witness).
  const auto answers = nlohmann::json::parse(R"json({
    "model": "p.g7", "semantics": "grafcet",
    "graph": {"situations": 1, "evolutions": 1, "complete": true, "limit": "", "anomalies": 1},
    "queries": [
      {"query": "Y0", "sort": "situations", "count": 1, "elements": [{"text": "#0"}]},
      {"query": "{1}", "sort": "steps", "count": 1, "elements": ["X1"]},
      {"query": "Y0 != {}", "sort": "test", "value": true, "witness_sort": "situations",
       "count": 1, "elements": [{"text": "#0"}]}
    ]})json");
  const auto page = query_html(answers, HtmlReport{});
  EXPECT_NE(page.find("1 situation &middot; 1 evolution &middot; <strong>1 anomaly:"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("<td class=\"answer\">1 situation</td>"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"answer\">1 step</td>"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"answer\">true, witness: 1 situation</td>"), std::string::npos);
  EXPECT_EQ(page.find("1 situations"), std::string::npos);
}

TEST(CheckHtml, EveryPageIsResponsiveAndCarriesTheLayoutProbe) {
  // The viewport, the section navigation, the one-column rule and print styles, the probe the
  // browser test reads (inert without #test), and wide tables in their own scrolling boxes.
  HtmlReport r;
  r.result = result();
  for (const auto& page : {check_html(r), query_html(nlohmann::json::parse(R"json({
         "model": "p.g7", "semantics": "grafcet", "queries": []})json"),
                                                     r)}) {
    EXPECT_NE(page.find("<meta name=\"viewport\" content=\"width=device-width"), std::string::npos);
    EXPECT_NE(page.find("<nav class=\"sections\""), std::string::npos);
    EXPECT_NE(page.find("@media (max-width: 1000px)"), std::string::npos);
    EXPECT_NE(page.find("@media print"), std::string::npos);
    EXPECT_NE(page.find("doc.dataset.sfcvLayout = "), std::string::npos);
    EXPECT_NE(page.find("<div class=\"scroll\"><table class=\"summary\""), std::string::npos);
  }
}

TEST(CheckHtml, SaysWhyThereIsNoChart) {
  HtmlReport r;
  r.result = result();
  r.chart_note = "graphviz's 'dot' is not installed";
  const auto html = check_html(r);
  EXPECT_NE(html.find("<p class=\"note warn\">graphviz's 'dot' is not installed</p>"),
            std::string::npos);
}

}  // namespace
}  // namespace sfcv::report

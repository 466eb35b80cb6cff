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
  EXPECT_NE(html.find("x &lt; y"), std::string::npos);                  // escaped
  EXPECT_NE(html.find("<summary>1 more</summary>"), std::string::npos);  // f3 folded away
  EXPECT_NE(html.find("3 of 25 findings shown; --all for every one"), std::string::npos);
  EXPECT_NE(html.find("data-property=\"0\">counterexample (1 situations)</a>"), std::string::npos);
  EXPECT_NE(html.find("<svg id=\"chart\"></svg>"), std::string::npos);
  EXPECT_NE(html.find("\"steps\":{\"P.S0\":\"p0c0s0\"}"), std::string::npos);
  // Data inside <script> cannot close it early; nothing is fetched from the network.
  EXPECT_EQ(html.find("</script>\"}"), std::string::npos);
  EXPECT_NE(html.find("<\\/script>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_NE(html.find("document.getElementById(\"sfcv-data\")"), std::string::npos);  // the script
}

TEST(CheckHtml, SaysWhyThereIsNoChart) {
  HtmlReport r;
  r.result = result();
  r.chart_note = "graphviz's 'dot' is not installed";
  const auto html = check_html(r);
  EXPECT_NE(html.find("<p class=\"note warn\">graphviz's 'dot' is not installed</p>"), std::string::npos);
}

}  // namespace
}  // namespace sfcv::report

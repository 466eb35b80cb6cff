// `sfcv equiv OLD NEW --html FILE` (issue 50: the counterexample "shown side by side ... in the
// HTML report"): the page has the verdict and, for a planted change, a row per cycle of the
// shortest counterexample with OLD's and NEW's steps and each compared signal as OLD and NEW
// cells, marked where they differ: the same cells the JSON's "differs" names.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

/// A filler chart; `guard` is the guard of Fill -> Done (the planted change edits it) and
/// `first` the initial step's name (the refactored copy renames it).
std::string filler(const std::string& guard = "full", const std::string& first = "Idle") {
  return "PROGRAM Filler\n  VAR_INPUT\n    start : BOOL;\n    full : BOOL;\n  END_VAR\n"
         "  VAR_OUTPUT\n    valve : BOOL;\n    lamp : BOOL;\n  END_VAR\n"
         "  INITIAL_STEP " +
         first +
         ": lamp(N); END_STEP\n  STEP Fill: valve(N); END_STEP\n  STEP Done: END_STEP\n"
         "  TRANSITION FROM " +
         first + " TO Fill := start; END_TRANSITION\n  TRANSITION FROM Fill TO Done := " + guard +
         "; END_TRANSITION\n  TRANSITION FROM Done TO " + first +
         " := NOT full; END_TRANSITION\nEND_PROGRAM\n";
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(EquivHtml, RefactoredCopyIsEquivalentOnThePage) {
  const auto a = write_temp(filler(), ".st");
  const auto b = write_temp(filler("full", "Waiting"), ".st");
  const auto html = write_temp("", ".html");
  const auto r = run_sfcv("-q equiv " + a + " " + b + " --engine explicit --html " + html);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto page = read_file(html);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<span class=\"verdict equivalent\">equivalent</span>"), std::string::npos);
  EXPECT_EQ(page.find("id=\"difference-"), std::string::npos);  // no counterexample
  EXPECT_NE(page.find("<code>valve</code>, <code>lamp</code>"), std::string::npos);
  EXPECT_EQ(page.find("src=\"http"), std::string::npos);  // self-contained
  EXPECT_NE(page.find("<style>"), std::string::npos);
}

TEST(EquivHtml, PlantedChangeIsShownSideBySideAsTheJsonSays) {
  const auto a = write_temp(filler(), ".st");
  const auto b = write_temp(filler("full AND start"), ".st");
  const auto html = write_temp("", ".html");
  const auto r = run_sfcv("-q equiv " + a + " " + b + " --engine explicit --json --html " + html);
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& trace = j["results"][0]["trace"];
  const auto page = read_file(html);
  ASSERT_NE(page.find("<table class=\"summary side\" id=\"difference-0\">"), std::string::npos);
  EXPECT_NE(page.find("<span class=\"verdict differ\">differ</span>"), std::string::npos);
  // The shortest difference: start, then full; OLD has reached Done, NEW still fills.
  EXPECT_EQ(trace["length"], 2);
  EXPECT_NE(page.find("differ after 2 cycles"), std::string::npos);
  EXPECT_NE(page.find("<tr><td>2</td><td>full</td><td class=\"old\">Filler.Done</td>"
                      "<td>Filler.Fill</td><td class=\"old differs\">0</td>"
                      "<td class=\"differs\">1</td><td class=\"old\">0</td><td>0</td></tr>"),
            std::string::npos)
      << page;
  // A row per cycle of the JSON's trace, and a pair of marked cells per signal it says differs.
  std::size_t differing = 0;
  for (const auto& c : trace["cycles"]) differing += c["differs"].size();
  const auto table = page.substr(page.find("id=\"difference-0\""));
  EXPECT_EQ(count(table.substr(0, table.find("</table>")), "<tr><td>"), trace["cycles"].size());
  EXPECT_EQ(count(page, "<td class=\"old differs\">"), differing);
  EXPECT_EQ(count(page, "<td class=\"differs\">"), differing);
}

TEST(EquivHtml, UnwritableHtmlPathIsRefusedBeforeTheRun) {
  const auto a = write_temp(filler(), ".st");
  const auto r = run_sfcv("-q equiv " + a + " " + a + " --html /nonexistent-dir/e.html");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--html"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sfcv::test

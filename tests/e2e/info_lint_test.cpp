// End-to-end: `sfcv info` (text and JSON), `sfcv lint` (diagnostics, summary, exit codes) and
// validation on loading.

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::source_path;
using sfcv::test::write_temp;

const std::string kPump = "tests/data/info_pump.st";

std::string q(const std::string& path) {
  return "'" + path + "'";
}

/// A one-POU IEC text model around `body` (declarations and chart).
std::string program(const std::string& body) {
  return "PROGRAM P\n  VAR_INPUT go : BOOL; n : INT; END_VAR\n  VAR_OUTPUT lamp : BOOL; END_VAR\n" +
         body + "END_PROGRAM\n";
}

// Line 4 is the first line of `body`.
const std::string kValidLoop =
    "  INITIAL_STEP S0: END_STEP\n"
    "  STEP S1: END_STEP\n"
    "  TRANSITION FROM S0 TO S1 := go; END_TRANSITION\n"
    "  TRANSITION FROM S1 TO S0 := NOT go; END_TRANSITION\n";

// ------------------------------------------------------------------------------------- info

TEST(Info, TextSummarisesPousChartsActionsVariables) {
  const auto r = run_sfcv("info " + q(source_path(kPump)));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* want : {"steps: 4, transitions: 4", "PROGRAM Pump: 4 steps, 4 transitions",
                           "chart Pump: 4 steps, 4 transitions, 1 network; initial: Idle",
                           "actions: 2 (statements 2)", "by qualifier: N 1, R 1, S 1",
                           "variables: 4 (input 2, output 1, local 1; by type: BOOL 3, TON 1)"})
    EXPECT_NE(r.out.find(want), std::string::npos) << want << " missing from:\n" << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(Info, JsonMatchesTheDocumentedExample) {
  // docs/formats.md documents the schema with the output on tests/data/info_pump.st: the
  // example there must stay exactly what sfcv prints (bar the path given on the command line).
  std::ifstream doc(source_path("docs/formats.md"));
  std::stringstream ss;
  ss << doc.rdbuf();
  const std::string text = ss.str();
  const auto heading = text.find("## sfcv info --json");
  ASSERT_NE(heading, std::string::npos);
  const auto open = text.find("```json\n", heading);
  const auto close = text.find("```", open + 8);
  ASSERT_NE(open, std::string::npos);
  auto documented = nlohmann::json::parse(text.substr(open + 8, close - open - 8));

  const auto r = run_sfcv("info --json " + q(source_path(kPump)));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto printed = nlohmann::json::parse(r.out);
  EXPECT_EQ(printed["model"], source_path(kPump));
  printed["model"] = documented["model"];
  EXPECT_EQ(printed, documented) << r.out;
  EXPECT_EQ(printed["steps"], 4);
  EXPECT_EQ(printed["transitions"], 4);
}

TEST(Info, CountsNestedChartsAndNetworks) {
  const std::string path =
      write_temp(program("  INITIAL_STEP A: Sub(N); END_STEP\n"
                         "  STEP B: END_STEP\n"
                         "  TRANSITION FROM A TO B := go; END_TRANSITION\n"
                         "  TRANSITION FROM B TO A := NOT go; END_TRANSITION\n"
                         "  INITIAL_STEP C: END_STEP\n"
                         "  TRANSITION FROM C TO C := go; END_TRANSITION\n"
                         "  ACTION Sub:\n"
                         "    INITIAL_STEP X: END_STEP\n"
                         "    STEP Y: END_STEP\n"
                         "    TRANSITION FROM X TO Y := go; END_TRANSITION\n"
                         "    TRANSITION FROM Y TO X := NOT go; END_TRANSITION\n"
                         "  END_ACTION\n"),
                 ".st");
  const auto r = run_sfcv("info --json " + q(path));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["steps"], 5);
  EXPECT_EQ(j["transitions"], 5);
  const auto& charts = j["pous"][0]["charts"];
  ASSERT_EQ(charts.size(), 2u) << r.out;
  EXPECT_EQ(charts[0]["networks"], 2);
  EXPECT_EQ(charts[0]["initial_steps"], nlohmann::json::array({"A", "C"}));
  EXPECT_TRUE(charts[0]["parent_action"].is_null());
  EXPECT_EQ(charts[1]["parent_action"], "Sub");
  EXPECT_EQ(j["pous"][0]["actions"]["by_kind"]["chart"], 1);
}

// Issue 48: under --json an error is a JSON error object on standard output (it was nothing),
// the exit code unchanged, the diagnostics on standard error.
TEST(Info, InvalidModelExitsTwoWithOnlyAJsonErrorOnStdout) {
  const std::string path = write_temp(
      program(kValidLoop + "  TRANSITION FROM S1 TO Nowhere := go; END_TRANSITION\n"), ".st");
  const auto r = run_sfcv("info --json " + q(path));
  EXPECT_EQ(r.exit_code, 2);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["kind"], "input");
  EXPECT_EQ(j["exit_code"], 2);
  EXPECT_FALSE(j.contains("pous"));
  EXPECT_NE(r.err.find(path + ":8:3: error: transition to undeclared step 'Nowhere'"),
            std::string::npos)
      << r.err;
}

TEST(Info, WarningsGoToStderrUnlessQuiet) {
  const std::string path = write_temp(program(kValidLoop + "  STEP Lonely: END_STEP\n"), ".st");
  const auto loud = run_sfcv("info --json " + q(path));
  EXPECT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_NE(loud.err.find(path + ":8:3: warning: step 'Lonely' is unreachable"), std::string::npos)
      << loud.err;
  EXPECT_TRUE(nlohmann::json::accept(loud.out)) << loud.out;
  const auto quiet = run_sfcv("info -q --json " + q(path));
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.err, "");
}

// ------------------------------------------------------------------------------------- lint

TEST(Lint, CleanModelExitsZero) {
  const auto r = run_sfcv("lint " + q(source_path(kPump)));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "0 errors, 0 warnings\n");
}

TEST(Lint, WarningsAloneExitZero) {
  const std::string path = write_temp(program(kValidLoop + "  STEP Lonely: END_STEP\n"), ".st");
  const auto r = run_sfcv("lint " + q(path));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(path + ":8:3: warning: step 'Lonely' is unreachable"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("0 errors, 1 warning\n"), std::string::npos) << r.out;
}

// A Grafcet output written by both continuous and stored actions: lint warns once, at its
// first stored action; check loads it and output-conflicts is violated (exit 1).
TEST(Lint, GrafcetOutputWrittenBothWaysIsAWarningAndAFinding) {
  const std::string path = write_temp(
      "project lamp;\ninput a, b;\noutput y;\ngrafcet G {\n  step 1 initial;\n  step 2, 3;\n"
      "  transition 1: 1 -> 2 when a;\n  transition 2: 2 -> 3 when b;\n"
      "  transition 3: 3 -> 1 when !a;\n  action 2: y;\n  action 3 on_enter: y := 1;\n"
      "  action 1 on_enter: y := 0;\n}\n",
      ".g7");
  const auto lint = run_sfcv("lint " + q(path));
  EXPECT_EQ(lint.exit_code, 0) << lint.out;
  EXPECT_NE(lint.out.find(path + ":11:3: warning: variable 'y' is written by both continuous and "
                                 "stored actions"),
            std::string::npos)
      << lint.out;
  EXPECT_NE(lint.out.find("0 errors, 1 warning\n"), std::string::npos) << lint.out;
  for (const char* engine : {"explicit", "bdd"}) {
    const auto check =
        run_sfcv("check " + q(path) + " --engine " + engine + " --checks output-conflicts");
    EXPECT_EQ(check.exit_code, 1) << check.out << check.err;
    EXPECT_NE(check.out.find("its stored value is 1 while no continuous action assigns it"),
              std::string::npos)
        << check.out;
  }
}

TEST(Lint, ErrorsExitTwoWithEveryDiagnosticLocated) {
  const std::string path = write_temp(
      program(kValidLoop +
              "  STEP S1: END_STEP\n"                                   // line 8: duplicate
              "  TRANSITION FROM S1 TO S0 := n; END_TRANSITION\n"       // line 9: INT guard
              "  TRANSITION FROM S0 TO S1 := go = n; END_TRANSITION\n"  // line 10: BOOL = INT
              "  ACTION Act: go := TRUE; END_ACTION\n"                  // line 11: input
              "  STEP S2: Act(N); END_STEP\n"                           // line 12: unreachable
              ),
      ".st");
  const auto r = run_sfcv("lint " + q(path));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  for (const std::string want :
       {":8:3: error: duplicate step 'S1'", ":9:", "the guard has type integer, expected BOOL",
        ":10:", "comparison of BOOL with integer", ":11:", "assignment to input variable 'go'",
        ":12:3: warning: step 'S2' is unreachable"})
    EXPECT_NE(r.out.find(want), std::string::npos) << want << " missing from:\n" << r.out;
  // Writing an input is a warning for IEC charts (CODESYS and TwinCAT accept it).
  EXPECT_NE(r.out.find(":11:15: warning: assignment to input variable 'go'"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("3 errors, 2 warnings\n"), std::string::npos) << r.out;
}

TEST(Lint, JsonListsLocatedDiagnosticsUnderItsSchemaVersion) {
  const std::string path = write_temp(
      program(kValidLoop + "  TRANSITION FROM S1 TO Nowhere := go; END_TRANSITION\n"), ".st");
  const auto r = run_sfcv("lint --json " + q(path));
  EXPECT_EQ(r.exit_code, 2);
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["schema_version"], "1.0");
  EXPECT_EQ(doc["errors"], 1);
  EXPECT_EQ(doc["warnings"], 0);
  const auto& j = doc["diagnostics"];
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 1u) << r.out;
  EXPECT_EQ(j[0]["file"], path);
  EXPECT_EQ(j[0]["line"], 8);
  EXPECT_EQ(j[0]["column"], 3);
  EXPECT_EQ(j[0]["severity"], "error");
  EXPECT_EQ(j[0]["message"], "transition to undeclared step 'Nowhere'");

  const auto clean = run_sfcv("lint --json " + q(source_path(kPump)));
  EXPECT_EQ(clean.exit_code, 0);
  const auto clean_doc = nlohmann::json::parse(clean.out);
  EXPECT_EQ(clean_doc["diagnostics"], nlohmann::json::array());
  EXPECT_EQ(clean_doc["errors"], 0);
}

TEST(Lint, MissingFileExitsTwo) {
  const auto r = run_sfcv("lint /nonexistent/chart.st");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("/nonexistent/chart.st: error: cannot open the model"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 error, 0 warnings"), std::string::npos) << r.out;
}

TEST(Lint, OtherCommandsRefuseAnInvalidModel) {
  const std::string path = write_temp(
      program(kValidLoop + "  TRANSITION FROM S1 TO S0 := ghost; END_TRANSITION\n"), ".st");
  const auto r = run_sfcv("check " + q(path));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(":8:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("unknown name 'ghost'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 error in the model"), std::string::npos) << r.err;
}

// ------------------------------------------------------------------------------------ corpus

TEST(LintCorpus, IllFormedDelayGivesOneLocatedErrorPerDefect) {
  SFCV_REQUIRE_CORPUS(corpus);
  const std::string path = (corpus / "14_verifaps_delay1_right_illformed.sfc").string();
  const auto r = run_sfcv("lint --json " + q(path));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::vector<std::pair<int, std::string>> errors, warnings;
  for (const auto& d : j["diagnostics"])
    (d["severity"] == "error" ? errors : warnings)
        .emplace_back(d["line"].get<int>(), d["message"].get<std::string>());
  const std::vector<std::pair<int, std::string>> expected_errors{
      {33, "duplicate step 'I1' (first declared at line 27:5)"},
      {45, "transition to undeclared step 'I1a' (also named by the transition at line 47:5)"},
      {46, "transition to undeclared step 'I1b' (also named by the transition at line 48:5)"},
      {47,
       "transition to undeclared step 'I2' (also named by the transitions at line 48:5, "
       "line 49:5)"},
      {49, "transition to undeclared step 'Boing'"},
  };
  EXPECT_EQ(errors, expected_errors) << r.out;
  // The unused step I; I1 and Boin are unreachable too (nothing leads to them).
  ASSERT_FALSE(warnings.empty()) << r.out;
  EXPECT_EQ(warnings[0].first, 24);
  EXPECT_NE(warnings[0].second.find("step 'I' is unreachable"), std::string::npos);
  for (const auto& d : j["diagnostics"]) EXPECT_EQ(d["column"], 5) << d.dump();

  const auto text = run_sfcv("lint " + q(path));
  EXPECT_EQ(text.exit_code, 2);
  EXPECT_NE(text.out.find(path + ":33:5: error: duplicate step 'I1'"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("5 errors, 3 warnings"), std::string::npos) << text.out;
}

TEST(LintCorpus, WellFormedTextualChartsAreClean) {
  SFCV_REQUIRE_CORPUS(corpus);
  for (const char* f : {"04_matiec_sfc_syntax.st", "13_verifaps_loopunwinding1_left.sfc",
                        "15_verifaps_transition2_left.sfc"}) {
    const auto r = run_sfcv("lint " + q((corpus / f).string()));
    EXPECT_EQ(r.exit_code, 0) << f << "\n" << r.out;
    EXPECT_NE(r.out.find("0 errors, 0 warnings"), std::string::npos) << f << "\n" << r.out;
  }
}

}  // namespace

// sfcv check end to end: verdicts, exit codes, output formats, and replay of a counterexample
// with sfcv simulate.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kPlant =
    "'" + std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st'";

TEST(CheckCommand, ChemicalPlantPaperResults) {
  const auto r = run_sfcv("check " + kPlant +
                          " --checks reachable --ctl 'AG !(V1 & V3)' --ctl 'AG !(V2 & V4)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("reachable      holds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("all 13 steps are reachable"), std::string::npos);
  EXPECT_NE(r.out.find("AG !(V1 & V3)  holds"), std::string::npos);
  EXPECT_NE(r.out.find("AG !(V2 & V4)  violated"), std::string::npos);
  EXPECT_NE(r.out.find("counterexample"), std::string::npos);
  EXPECT_NE(r.out.find("V2* V4*"), std::string::npos);
}

TEST(CheckCommand, DefaultRunsTheStandardChecks) {
  const auto r = run_sfcv("check " + kPlant + " --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  for (const char* name : {"reachable", "dead-transitions", "reentry", "global-deadlock",
                           "local-deadlock", "initial-return", "conflicts", "stored-actions",
                           "output-conflicts", "order-dependence", "instability"})
    EXPECT_NE(r.out.find(std::string("\n") + name + " "), std::string::npos) << name << "\n"
                                                                             << r.out;
  // Conflicts under the standard priority: n/a (was "not checked", which now counts as unknown).
  EXPECT_NE(r.out.find("\nconflicts         n/a "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("not checked"), std::string::npos) << r.out;
}

TEST(CheckCommand, HoldsGivesExitZero) {
  const auto r = run_sfcv("check " + kPlant + " --ctl 'AG !(V1 & V3)' --ctl 'EF (V2 & V4)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("witness"), std::string::npos);
}

TEST(CheckCommand, JsonOutput) {
  const auto r = run_sfcv("check " + kPlant + " --json --ctl 'AG !(V2 & V4)' --checks reachable");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["semantics"], "iec61131");
  EXPECT_EQ(j["engine"], "explicit");
  EXPECT_GT(j["states"].get<int>(), 0);
  EXPECT_EQ(j["complete"], true);
  ASSERT_EQ(j["properties"].size(), 2u);
  EXPECT_EQ(j["properties"][0]["formula"], "AG !(V2 & V4)");
  EXPECT_EQ(j["properties"][0]["verdict"], "violated");
  EXPECT_GT(j["properties"][0]["trace"]["steps"].size(), 1u);
  EXPECT_EQ(j["properties"][1]["check"], "reachable");
}

TEST(CheckCommand, TraceFormatsAndReplayWithSimulate) {
  const auto csv = write_temp("", ".csv");
  auto r = run_sfcv("check " + kPlant +
                    " --quiet --ctl 'AG !(V2 & V4)' --trace csv --trace-file '" + csv + "'");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto sim = run_sfcv("simulate " + kPlant + " --inputs '" + csv + "'");
  ASSERT_EQ(sim.exit_code, 0) << sim.out << sim.err;
  // The last cycle of the replay has both valves open.
  const auto last = sim.out.substr(sim.out.rfind('\n', sim.out.size() - 2) + 1);
  EXPECT_NE(last.find("V2=1"), std::string::npos) << sim.out;
  EXPECT_NE(last.find("V4=1"), std::string::npos) << sim.out;

  r = run_sfcv("check " + kPlant + " --ctl 'AG !(V2 & V4)' --trace vcd");
  EXPECT_NE(r.out.find("$enddefinitions $end"), std::string::npos);
  r = run_sfcv("check " + kPlant + " --ctl 'AG !(V2 & V4)' --trace json");
  EXPECT_NE(r.out.find("\"active_steps\""), std::string::npos);
}

TEST(CheckCommand, JunitReportForCi) {
  const auto xml = write_temp("", ".xml");
  const auto r = run_sfcv("check " + kPlant +
                          " --quiet --ctl 'AG !(V1 & V3)' --ctl 'AG !(V2 & V4)' "
                          "--junit '" +
                          xml + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::ifstream f(xml);
  const std::string report((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("<testsuites name=\"sfcv check\" tests=\"2\" failures=\"1\" errors=\"0\""),
            std::string::npos)
      << report;
  // The suite (and so the class) names the model and the run (issue 48: runs on one model
  // must not share a suite); Jenkins' junit-10.xsd has no file or line on a test case, so the
  // model file is named in system-out.
  EXPECT_NE(report.find("<testcase classname=\"chemical_plant.st [auto "), std::string::npos)
      << report;
  EXPECT_NE(report.find("].properties\" name=\"AG !(V1 &amp; V3)\""), std::string::npos) << report;
  EXPECT_NE(report.find("<failure message=\"violated"), std::string::npos) << report;
  EXPECT_EQ(report.find("file=\""), std::string::npos) << report;
  EXPECT_EQ(report.find("line=\""), std::string::npos) << report;
  EXPECT_NE(report.find("where: " + std::string(SFCV_SOURCE_DIR) +
                        "/examples/chemical_plant/chemical_plant.st\n"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("counterexample ("), std::string::npos) << report;
}

TEST(CheckCommand, LimitsGiveUnknownNeverHolds) {
  const auto r = run_sfcv("check " + kPlant + " --max-states 3 --ctl 'AG !(V1 & V3)'");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.out.find("unknown"), std::string::npos);
  EXPECT_EQ(r.out.find(" holds"), std::string::npos) << r.out;
}

TEST(CheckCommand, BadInputsExitTwo) {
  auto r = run_sfcv("check " + kPlant + " --ctl 'AG !(V1 & )'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(":1:11: error: expected a formula"), std::string::npos) << r.err;
  r = run_sfcv("check " + kPlant + " --ctl 'AG !(V1 & V9)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown name 'V9'"), std::string::npos) << r.err;
  r = run_sfcv("check " + kPlant + " --engine magic");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad --engine 'magic'"), std::string::npos) << r.err;
  r = run_sfcv("check " + kPlant + " --checks bogus");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown check 'bogus'"), std::string::npos);
  const auto spec = write_temp("property p AG V1;\n", ".spec");
  r = run_sfcv("check " + kPlant + " --spec '" + spec + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(spec + ":1:12: error"), std::string::npos) << r.err;
}

TEST(CheckCommand, SpecFileAssumptionsAndFairness) {
  const auto spec = write_temp(
      "-- the plant with physically consistent level sensors\n"
      "assume !(LIS1plus & LIS1minus) & !(LIS2plus & LIS2minus);\n"
      "property no_overfill_T1: AG !(V1 & V3);\n"
      "property t2_overlap: AG !(V2 & V4);\n",
      ".spec");
  auto r = run_sfcv("check " + kPlant + " --spec '" + spec + "'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("no_overfill_T1  holds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("t2_overlap      violated"), std::string::npos) << r.out;
  // Under free inputs the plant may idle forever before s10; fairness on s8 rules that out.
  r = run_sfcv("check " + kPlant + " --engine auto --checks none --ctl 'AG AF s10'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("AG AF s10  violated"), std::string::npos) << r.out;
  r = run_sfcv("check " + kPlant + " --engine auto --checks none --ctl 'AG AF s10' --fair s8");
  EXPECT_NE(r.err.find("using the explicit engine"), std::string::npos);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("AG AF s10  holds"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

TEST(CheckCommand, PalletTransferCollisionBeforeAndAfterTheFix) {
  const std::string dir = "'" + std::string(SFCV_SOURCE_DIR) + "/examples/pallet_transfer/";
  auto r =
      run_sfcv("check " + dir + "pallet_transfer.g7' --ctl 'AG !(X10 & X25)' --checks reachable");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("AG !(X10 & X25)  violated"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("X10* "), std::string::npos) << r.out;
  // Steps crossed only during transient evolutions are reachable, and said so.
  EXPECT_NE(r.out.find("only during transient evolutions"), std::string::npos) << r.out;
  r = run_sfcv("check " + dir + "pallet_transfer_fixed.g7' --ctl 'AG !(X10 & X25)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("AG !(X10 & X25)  holds"), std::string::npos) << r.out;
}

// Grafcet traces: transitions as IEC 60848 writes them, the CSV starts with the initial inputs.
TEST(CheckCommand, GrafcetTraceNamesAndCsv) {
  const auto path = write_temp(R"(project three;
input a, b;
output y;
grafcet G {
  step 1 initial;
  step 2;
  step 3;
  transition 5: 1 -> 2 when a;
  transition 6: 2 -> 3 when !a;
  transition 7: 3 -> 1 when b;
  action 3: y;
}
)",
                               ".g7");
  auto r = run_sfcv("check " + path + " --quiet --ctl 'AG !y'");
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("| (6) X2 -> X3 |"), std::string::npos) << r.out;
  r = run_sfcv("check " + path + " --quiet --ctl 'AG !y' --trace csv");
  EXPECT_NE(
      r.out.find("one row per stable situation, the first the initial inputs\na,b\n1,0\n0,0\n"),
      std::string::npos)
      << r.out;
}

// More than 20 findings: a count and --all.
TEST(CheckCommand, FindingsCutWithACountAndAll) {
  std::string g7 = "project many;\ninput a;\ngrafcet G {\n  step 1 initial;\n";
  for (int s = 2; s <= 26; ++s) g7 += "  step " + std::to_string(s) + ";\n";
  g7 += "  transition 1: 1 -> 2 when a & !a;\n";
  for (int s = 2; s <= 25; ++s)
    g7 += "  transition " + std::to_string(s) + ": " + std::to_string(s) + " -> " +
          std::to_string(s + 1) + " when a;\n";
  g7 += "}\n";
  const auto path = write_temp(g7, ".g7");
  auto r = run_sfcv("check " + path + " --quiet --checks reachable");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("  (20 of 25 findings shown; --all for every one)\n"), std::string::npos)
      << r.out;
  r = run_sfcv("check " + path + " --quiet --checks reachable --all");
  EXPECT_EQ(r.out.find("findings shown"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("X26"), std::string::npos) << r.out;
}

// SARIF: a rule per check and property, a located result per violation, the trace as a code flow.
TEST(CheckCommand, SarifLocatesViolationsAndTheirTraces) {
  const auto sarif = write_temp("", ".sarif");
  const auto run =
      run_sfcv("check '" + source_path("examples/chemical_plant/chemical_plant.st") +
               "' --quiet --checks local-deadlock --ctl 'AG !(V2 & V4)' --trace none --sarif '" +
               sarif + "' --sarif-root '" + SFCV_SOURCE_DIR + "'");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  std::ifstream f(sarif);
  const auto log = nlohmann::json::parse(f);
  EXPECT_EQ(log["version"], "2.1.0");
  const auto& rules = log["runs"][0]["tool"]["driver"]["rules"];
  ASSERT_EQ(rules.size(), 2u);
  // Issue 48: a stable id, not the raw formula text (code scanning cannot take it).
  EXPECT_TRUE(
      std::regex_match(rules[0]["id"].get<std::string>(), std::regex("property/ctl-[0-9a-f]{12}")))
      << rules[0]["id"];
  EXPECT_EQ(rules[1]["id"], "check/local-deadlock");
  const auto& results = log["runs"][0]["results"];
  ASSERT_EQ(results.size(), 2u);
  // The deadlocked step S9 is at line 39, column 3 of the chart.
  const auto& deadlock = results[1]["locations"][0]["physicalLocation"];
  // Issue 48: relative to --sarif-root, for GitHub code scanning.
  EXPECT_EQ(deadlock["artifactLocation"]["uri"], "examples/chemical_plant/chemical_plant.st");
  EXPECT_EQ(deadlock["artifactLocation"]["uriBaseId"], "SRCROOT");
  EXPECT_EQ(deadlock["region"]["startLine"], 39);
  EXPECT_EQ(deadlock["region"]["startColumn"], 3);
  const auto& v2v4 = results[0];
  EXPECT_EQ(v2v4["level"], "error");
  const auto& flow = v2v4["codeFlows"][0]["threadFlows"][0]["locations"];
  ASSERT_GE(flow.size(), 2u);
  const std::string last = flow.back()["location"]["message"]["text"];
  EXPECT_NE(last.find("outputs"), std::string::npos) << last;
  EXPECT_NE(last.find("V2"), std::string::npos) << last;
  EXPECT_NE(last.find("V4"), std::string::npos) << last;
  EXPECT_GE(v2v4["relatedLocations"].size(), 3u);
  EXPECT_GT(v2v4["locations"][0]["physicalLocation"]["region"]["startLine"].get<int>(), 0);
}

}  // namespace
}  // namespace sfcv::test

// CODESYS/TwinCAT implicit SFC flags end to end (issue 14, docs/semantics.md "Implicit SFC
// flags"): SFCReset/SFCInit reset the chart, so a state reachable only through a reset is
// found; other vendor flags are a located error (exit 2) in every subcommand. The inputs are
// written here, mimicking CODESYS exports.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

std::string q(const std::string& s) {
  return "'" + s + "'";
}

std::string bool_vars(const std::string& section, const std::vector<std::string>& names) {
  std::string s = "<" + section + ">";
  for (const auto& n : names) s += "<variable name=\"" + n + "\"><type><BOOL/></type></variable>";
  return s + "</" + section + ">";
}

std::string st(const std::string& text) {
  return "<ST><xhtml:p><![CDATA[" + text + "]]></xhtml:p></ST>";
}

std::string transition(int id, int from, const std::string& guard) {
  return "<transition localId=\"" + std::to_string(id) + "\"><connectionPointIn><connection " +
         "refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn><connectionPointOut/><condition><inline name=\"\">" + st(guard) +
         "</inline></condition></transition>\n";
}

std::string step(int id, const std::string& name, int from) {
  const std::string in = from < 0 ? "<connectionPointIn/>"
                                  : "<connectionPointIn><connection refLocalId=\"" +
                                        std::to_string(from) + "\"/></connectionPointIn>";
  return "<step localId=\"" + std::to_string(id) + "\" name=\"" + name + "\"" +
         (from < 0 ? " initialStep=\"true\"" : "") + ">" + in + "<connectionPointOut/></step>\n";
}

std::string action_block(int id, int step_id, const std::string& action) {
  return "<actionBlock localId=\"" + std::to_string(id) +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(step_id) +
         "\"/></connectionPointIn><action localId=\"" + std::to_string(id + 1) +
         "\" qualifier=\"N\"><reference name=\"" + action + "\"/></action></actionBlock>\n";
}

// A CODESYS-like program: Idle --go--> Feed --go--> Clamp --go--> Feed; Clamp's action sets
// `armed` for good. Idle is never entered again but through a reset, so AG !(Idle.X & armed)
// holds exactly when no implicit flag is declared. `flags` are extra input variables.
std::string plcopen(const std::vector<std::string>& flags) {
  std::vector<std::string> inputs = {"go"};
  inputs.insert(inputs.end(), flags.begin(), flags.end());
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\" "
         "xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n"
         "<fileHeader companyName=\"t\" productName=\"CODESYS\" productVersion=\"3.5\" "
         "creationDateTime=\"2026-01-01T00:00:00\"/>\n<contentHeader name=\"cell\"/>\n"
         "<types><dataTypes/><pous>\n<pou name=\"Cell\" pouType=\"program\">\n<interface>" +
         bool_vars("inputVars", inputs) + bool_vars("outputVars", {"armed", "feeding"}) +
         "</interface>\n<actions><action name=\"Arm\"><body>" + st("armed := TRUE;") +
         "</body></action><action name=\"Run\"><body>" + st("feeding := TRUE;") +
         "</body></action></actions>\n<body><SFC>\n" + step(1, "Idle", -1) +
         transition(2, 1, "go") + step(3, "Feed", 2) + transition(4, 3, "go") +
         step(5, "Clamp", 4) + transition(6, 5, "go") +
         "<jumpStep localId=\"7\" targetName=\"Feed\"><connectionPointIn><connection "
         "refLocalId=\"6\"/></connectionPointIn></jumpStep>\n" +
         action_block(10, 3, "Run") + action_block(12, 5, "Arm") +
         "</SFC></body>\n</pou>\n</pous></types>\n</project>\n";
}

TEST(SfcFlags, ResetReachesAStateTheChartAloneNeverDoes) {
  const std::string ctl = " --checks none --ctl 'AG !(Idle.X & armed)'";
  // A plain variable name: the property holds.
  const auto plain = write_temp(plcopen({"restart"}), ".xml");
  auto r = run_sfcv("check " + q(plain) + ctl);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // SFCReset / SFCInit: a reset returns to Idle with `armed` still TRUE.
  for (const char* flag : {"SFCReset", "SFCInit"}) {
    SCOPED_TRACE(flag);
    const auto path = write_temp(plcopen({flag}), ".xml");
    for (const char* engine : {"explicit", "bdd", "ic3"}) {
      r = run_sfcv("check " + q(path) + ctl + " --engine " + engine);
      EXPECT_EQ(r.exit_code, 1) << engine << "\n" << r.out << r.err;
      EXPECT_NE(r.out.find("violated"), std::string::npos) << r.out;
    }
  }
}

TEST(SfcFlags, IecTextInitHeldFreezesTheChart) {
  // SFCInit held TRUE from the start: the chart never leaves its initial step.
  const auto path = write_temp(R"(PROGRAM Cell
  VAR_INPUT go : BOOL; END_VAR
  VAR SFCInit : BOOL := TRUE; END_VAR
  INITIAL_STEP Idle : END_STEP
  STEP Feed : END_STEP
  TRANSITION FROM Idle TO Feed := go; END_TRANSITION
  TRANSITION FROM Feed TO Idle := go; END_TRANSITION
END_PROGRAM
)",
                               ".st");
  auto r = run_sfcv("check " + q(path) + " --checks none --ctl 'AG Idle.X'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // SFCReset held TRUE: each cycle restarts at Idle and may still move on to Feed.
  const auto reset = write_temp(R"(PROGRAM Cell
  VAR_INPUT go : BOOL; END_VAR
  VAR SFCReset : BOOL := TRUE; END_VAR
  INITIAL_STEP Idle : END_STEP
  STEP Feed : END_STEP
  STEP Done : END_STEP
  TRANSITION FROM Idle TO Feed := go; END_TRANSITION
  TRANSITION FROM Feed TO Done := go; END_TRANSITION
  TRANSITION FROM Done TO Idle := go; END_TRANSITION
END_PROGRAM
)",
                                ".st");
  r = run_sfcv("check " + q(reset) + " --checks none --ctl 'AG !Done.X' --ctl 'EF Feed.X'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(SfcFlags, UnmodelledVendorFlagIsAnErrorInEverySubcommand) {
  const auto path = write_temp(plcopen({"SFCPause"}), ".xml");
  const std::string file = q(path);
  const auto inputs = write_temp("go\n1\n0\n", ".csv");
  for (const std::string& cmd :
       {"check " + file, "check " + file + " --ctl 'AG !(Idle.X & armed)'", "lint " + file,
        "export " + file + " --to nusmv", "simulate " + file + " --inputs " + q(inputs),
        "query " + file + " Steps", "rsg " + file}) {
    const auto r = run_sfcv(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("'SFCPause' in Cell is a CODESYS/TwinCAT implicit SFC flag"),
              std::string::npos)
        << cmd << "\n"
        << r.out << r.err;
    EXPECT_NE((r.out + r.err).find(path), std::string::npos) << cmd << "\n" << r.out << r.err;
  }
}

// An instance of an SFC function block has its own flags: the caller's SFCReset := r resets
// that instance's chart, so the state reachable only through the reset is found on every
// engine (and, without the flag, the property holds).
TEST(SfcFlags, AnInstanceIsResetThroughItsOwnFlag) {
  const std::string fb = R"(FUNCTION_BLOCK Seq
  VAR_INPUT go : BOOL; SFCReset : BOOL; END_VAR
  VAR_OUTPUT armed : BOOL; END_VAR
  INITIAL_STEP Idle : END_STEP
  STEP Run : Arm(S); END_STEP
  STEP Done : END_STEP
  TRANSITION FROM Idle TO Run := go; END_TRANSITION
  TRANSITION FROM Run TO Done := TRUE; END_TRANSITION
  ACTION Arm : armed := TRUE; END_ACTION
END_FUNCTION_BLOCK
)";
  const auto with_flag = write_temp(fb + R"(PROGRAM Main
  VAR_INPUT g, r : BOOL; END_VAR
  VAR s : Seq; END_VAR
  s(go := g, SFCReset := r);
END_PROGRAM
)",
                                    ".st");
  const std::string ctl = " --checks none --trace none --ctl " + q("AG !(s.Idle.X & s.armed)");
  for (const char* engine : {"explicit", "bdd", "ic3", "bmc"}) {
    const auto r = run_sfcv("check " + q(with_flag) + ctl + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
  }
  const auto without = write_temp(R"(FUNCTION_BLOCK Seq
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT armed : BOOL; END_VAR
  INITIAL_STEP Idle : END_STEP
  STEP Run : Arm(S); END_STEP
  STEP Done : END_STEP
  TRANSITION FROM Idle TO Run := go; END_TRANSITION
  TRANSITION FROM Run TO Done := TRUE; END_TRANSITION
  ACTION Arm : armed := TRUE; END_ACTION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT g : BOOL; END_VAR
  VAR s : Seq; END_VAR
  s(go := g);
END_PROGRAM
)",
                                  ".st");
  const auto r = run_sfcv("check " + q(without) + ctl + " --engine explicit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace sfcv::test

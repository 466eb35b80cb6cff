// Numeric literals end to end (issue 53 item 5, docs/semantics.md 1.7): a literal past its
// type's range is exit 2 with its place, never a verdict on a wrapped value; the command line's
// own numbers (--cycle, bounds of patterns, formula and query constants) follow the same rule.

#include <gtest/gtest.h>

#include <string>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

/// S0 (initial, `y` under L with `duration`) -a-> S1 -NOT a-> S0.
std::string l_action(const std::string& duration) {
  return kPlcopenHeader +
         "<pou name=\"P\" pouType=\"program\"><interface>"
         "<inputVars><variable name=\"a\"><type><BOOL/></type></variable></inputVars>"
         "<outputVars><variable name=\"y\"><type><BOOL/></type></variable></outputVars>"
         "<localVars><variable name=\"n\"><type><LINT/></type></variable></localVars>"
         "</interface><body><SFC>\n"
         "<step localId=\"1\" name=\"S0\" initialStep=\"true\"><connectionPointOut/></step>\n"
         "<actionBlock localId=\"20\"><connectionPointIn><connection refLocalId=\"1\"/>"
         "</connectionPointIn><action localId=\"0\" qualifier=\"L\" duration=\"" +
         duration +
         "\"><reference name=\"y\"/></action></actionBlock>\n"
         "<transition localId=\"2\"><connectionPointIn><connection refLocalId=\"1\"/>"
         "</connectionPointIn><connectionPointOut/><condition><inline name=\"\">" +
         plcopen_st("a") +
         "</inline></condition></transition>\n"
         "<step localId=\"3\" name=\"S1\"><connectionPointIn><connection refLocalId=\"2\"/>"
         "</connectionPointIn><connectionPointOut/></step>\n"
         "<transition localId=\"4\"><connectionPointIn><connection refLocalId=\"3\"/>"
         "</connectionPointIn><connectionPointOut/><condition><inline name=\"\">" +
         plcopen_st("NOT a") +
         "</inline></condition></transition>\n"
         "<jumpStep localId=\"5\" targetName=\"S0\"><connectionPointIn><connection "
         "refLocalId=\"4\"/></connectionPointIn></jumpStep>\n"
         "</SFC></body></pou>\n" +
         kPlcopenFooter;
}

// The issue's measurement: `T#9223372036854775807ms` became -1 ms, so the L action never acted
// and `EF y` was "violated" (exit 1). The IEC text and .g7 readers refused the same literal.
TEST(Literals, TheIssuesXmlDurationIsExitTwoWithItsPlace) {
  const auto path = write_temp(l_action("T#9223372036854775807ms"), ".xml");
  const auto r = run_sfcv("check '" + path + "' --ctl 'EF y' --checks none");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("actionBlock[@localId='20']/action[@localId='0']): error: cannot read "
                       "the duration 'T#9223372036854775807ms': TIME literal "
                       "T#9223372036854775807ms is outside TIME (T#0ms..T#24d20h31m23s647ms)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.find("violated"), std::string::npos) << r.out;
}

TEST(Literals, ASaneLargeDurationIsStillAccepted) {
  for (const char* d : {"T#24d20h31m23s647ms", "T#2s", "T#1h_30m", "T#1.5s"}) {
    const auto path = write_temp(l_action(d), ".xml");
    const auto r = run_sfcv("check '" + path + "' --ctl 'EF y' --checks none");
    EXPECT_EQ(r.exit_code, 0) << d << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("EF y  holds"), std::string::npos) << d << "\n" << r.out;
  }
}

TEST(Literals, TheCycleOptionIsCheckedNotWrapped) {
  const auto path = write_temp(l_action("T#2s"), ".xml");
  // 9223372036854775807 * 1000 wrapped around.
  auto r =
      run_sfcv("check '" + path + "' --time discrete --cycle 9223372036854775807s --ctl 'EF y'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("bad --cycle '9223372036854775807s': TIME literal --cycle "
                       "9223372036854775807s is outside TIME"),
            std::string::npos)
      << r.err;
  r = run_sfcv("check '" + path + "' --time discrete --cycle 2147483648ms --ctl 'EF y'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = run_sfcv("check '" + path + "' --time discrete --cycle -5ms --ctl 'EF y'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--cycle must be positive"), std::string::npos) << r.err;
  r = run_sfcv("check '" + path + "' --time discrete --cycle 2147483647ms --ctl 'EF y'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("check '" + path + "' --time discrete --cycle 1s --ctl 'EF y'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(Literals, FormulaConstantsAtTheLimitsAndPast) {
  const auto path = write_temp(l_action("T#2s"), ".xml");
  auto r = run_sfcv("check '" + path +
                    "' --checks none --ctl 'AG n > -9223372036854775808' --ctl 'AG n < "
                    "9223372036854775807'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("check '" + path + "' --checks none --ctl 'AG n < 9223372036854775808'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("integer literal 9223372036854775808 is outside LINT"), std::string::npos)
      << r.err;
}

TEST(Literals, PatternBoundsInTimeDoNotWrap) {
  const auto path = write_temp(l_action("T#2s"), ".xml");
  // 9223372036854775807 s * 1000 wrapped around to -1000 ms: a bound under the cap on cycles.
  auto r = run_sfcv("check '" + path +
                    "' --time discrete --cycle 10ms --pattern "
                    "'response(a, y, within 9223372036854775807 s)'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("is outside TIME"), std::string::npos) << r.err;
  r = run_sfcv("check '" + path +
               "' --time discrete --cycle 10ms --pattern "
               "'response(a, y, within 99999999999999999999 cycles)'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("is outside LINT"), std::string::npos) << r.err;
}

TEST(Literals, QueryConstantsAtTheLimitsAndPast) {
  const std::string g7 =
      "input n : -9223372036854775808..9223372036854775807;\n"
      "grafcet G { step 1 initial; step 2;\n"
      "  transition 1 -> 2 when n > 0; transition 2 -> 1 when n < 0; }\n";
  const auto path = write_temp(g7, ".g7");
  auto r = run_sfcv("query '" + path + "' 'Nec(n > -9223372036854775808)'");
  EXPECT_NE(r.exit_code, 2) << r.out << r.err;
  r = run_sfcv("query '" + path + "' 'Nec(n > -9223372036854775809)'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("integer literal 9223372036854775809 is outside LINT"), std::string::npos)
      << r.err;
  r = run_sfcv("query '" + path + "' 'Nec(n > 9223372036854775808)'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
}

TEST(Literals, EveryTextReaderRefusesTheOverflowingLiteralWithExitTwo) {
  const auto st = write_temp(
      "PROGRAM p\n  VAR n : INT := 40000; END_VAR\n  INITIAL_STEP s0: END_STEP\nEND_PROGRAM\n",
      ".st");
  auto r = run_sfcv("lint '" + st + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(
      (r.out + r.err).find(":2:18: error: initial value 40000 is outside INT (-32768..32767)"),
      std::string::npos)
      << r.out << r.err;
  const auto g7 = write_temp(
      "grafcet G { step 1 initial; step 2;\n  transition 1 -> 2 when 9223372036854775807ms/X1; }\n",
      ".g7");
  r = run_sfcv("lint '" + g7 + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE((r.out + r.err)
                .find(":2:26: error: duration TIME literal '9223372036854775807ms' is "
                      "outside TIME"),
            std::string::npos)
      << r.out << r.err;
}

}  // namespace
}  // namespace sfcv::test

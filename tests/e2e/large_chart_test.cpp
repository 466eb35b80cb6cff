// A 10,000-step chart through every subcommand and engine: name look-ups are by index, so no
// pass is quadratic in the steps (resolving each step's name by a linear search took 20-53 s
// under --timeout 2, and the SAT engines were killed at 60 s). The bounds are CPU seconds of
// the sfcv child (getrusage), which a loaded machine does not inflate as it does wall time.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/cpu_run.hpp"
#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::cpu_run;
using sfcv::test::kSlowdown;
using sfcv::test::run_sfcv;

/// A loop of `n` steps S0 -> S1 -> ... -> S0, each transition on input a; o in the last step.
std::string chain(int n) {
  std::string text =
      "PROGRAM Chain\n  VAR_INPUT a : BOOL; END_VAR\n  VAR_OUTPUT o : BOOL; END_VAR\n"
      "  INITIAL_STEP S0:\n  END_STEP\n";
  for (int i = 1; i < n; ++i)
    text +=
        "  STEP S" + std::to_string(i) + ":\n" + (i == n - 1 ? "    o(N);\n" : "") + "  END_STEP\n";
  for (int i = 0; i < n; ++i)
    text += "  TRANSITION FROM S" + std::to_string(i) + " TO S" + std::to_string((i + 1) % n) +
            " := a;\n  END_TRANSITION\n";
  return sfcv::test::write_temp(text + "END_PROGRAM\n", ".st");
}

TEST(LargeChart, EverySubcommandAndEngineStaysWithinItsBudgetOnTenThousandSteps) {
  const std::string file = chain(10000);
  for (const char* cmd : {"lint", "info", "info --json"}) {
    const auto r = cpu_run(std::string(cmd) + " '" + file + "'");
    EXPECT_EQ(r.run.exit_code, 0) << cmd << ": " << r.run.err;
    EXPECT_LT(r.cpu, 3.0 * kSlowdown) << cmd;
  }
  for (const char* engine : {"explicit", "bdd", "bmc", "kind", "ic3", "auto"}) {
    const auto r = cpu_run("check '" + file + "' --engine " + engine + " --timeout 2 --quiet");
    EXPECT_TRUE(r.run.exit_code == 0 || r.run.exit_code == 3)
        << engine << ": exit " << r.run.exit_code << "\n"
        << r.run.err;
    // 2 s of budget, then 1 s + 5 % to stop and report, and room for a loaded machine.
    EXPECT_LT(r.cpu, 6.0 * kSlowdown) << engine;
    EXPECT_NE(r.run.out.find("reachable"), std::string::npos) << engine << ": " << r.run.out;
  }
}

TEST(LargeChart, TheHtmlReportLaysOutABoundedChartWithinTheRunsTime) {
  // graphviz needs 3 s for a 500-step loop and 221 s for 2,000 steps: a report of a larger
  // chart says it is not drawn, instead of running dot for minutes past --timeout.
  const auto html = sfcv::test::write_temp("", ".html");
  const auto big = cpu_run("check '" + chain(2000) + "' --checks none --ctl 'AG !(S1 & S2)' " +
                           "--timeout 5 --quiet --html '" + html + "'");
  EXPECT_EQ(big.run.exit_code, 0) << big.run.err;
  EXPECT_LT(big.cpu, 8.0 * kSlowdown);
  const auto page = sfcv::test::read_file(html);
  EXPECT_NE(page.find("is not drawn: a report lays out at most 1000"), std::string::npos);
  // A small chart is drawn (when graphviz is installed, as in CI).
  const auto small = run_sfcv("check '" + chain(20) + "' --checks none --ctl 'AG !(S1 & S2)' " +
                              "--timeout 5 --quiet --html '" + html + "'");
  EXPECT_EQ(small.exit_code, 0) << small.err;
  EXPECT_EQ(sfcv::test::read_file(html).find("is not drawn"), std::string::npos);
}

TEST(LargeChart, TheBddQueryEngineHoldsTheDeadlineInsideItsOperations) {
  // Twelve tanks: building the evolutions is one and_exist that ran 400 s past --timeout 5.
  const std::string file = sfcv::test::write_temp("", ".st");
  const std::string gen = std::string("'") + SFCV_GEN + "' tanks 12 -o '" + file + "'";
  ASSERT_EQ(std::system(gen.c_str()), 0);
  const auto r = cpu_run("query '" + file + "' 'Y - Pred(Y0, T)' --engine bdd --timeout 2");
  EXPECT_EQ(r.run.exit_code, 3) << r.run.err;
  EXPECT_NE(r.run.err.find("time limit"), std::string::npos) << r.run.err;
  EXPECT_LT(r.cpu, 6.0 * kSlowdown);
}

TEST(LargeChart, NestedEdgesCostOneEvaluationPerLevel) {
  // RE RE ... RE a, 199 levels (the nesting limit is 200): each level evaluated the one below
  // twice, now and before, so check, rsg and query hung on a 1.2 KB file.
  std::string edges;
  for (int i = 0; i < 199; ++i) edges += "RE ";
  const std::string file = sfcv::test::write_temp(
      "project edges;\ninput a, b;\noutput o;\ngrafcet g {\n  step 0 initial;\n  step 1;\n"
      "  transition 1: 0 -> 1 when " +
          edges + "a;\n  transition 2: 1 -> 0 when b;\n  action 1: o;\n}\n",
      ".g7");
  for (const std::string& cmd :
       {"check '" + file + "' --engine explicit", "check '" + file + "' --engine bdd",
        "check '" + file + "' --engine ic3 --checks none --ctl 'AG !X1'", "rsg '" + file + "'",
        "query '" + file + "' 'Y - Pred(Y0, T)'"}) {
    const auto r = cpu_run(cmd + " --timeout 2 --quiet");
    // Seen from the previous situation an edge is false, so RE RE ... RE a reads as RE a.
    EXPECT_TRUE(r.run.exit_code == 0 || r.run.exit_code == 1) << cmd << ": " << r.run.err;
    EXPECT_LT(r.cpu, 2.0 * kSlowdown) << cmd;
  }
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    const auto reached = run_sfcv("check '" + file + "' --engine " + engine +
                                  " --checks none --ctl 'AG !X1' --quiet");
    EXPECT_EQ(reached.exit_code, 1) << engine << ": " << reached.out << reached.err;
  }
}

}  // namespace

// An input too wide for the explicit engine to enumerate (a DINT used in arithmetic) is a limit
// of that engine, reported as one: `--engine explicit` prints a report of unknowns naming the
// input (exit 3), and `auto` races the symbolic engines, which decide. Both once printed
// nothing on standard output, even under --json.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;

const char* const kWide = R"(PROGRAM Wide
  VAR_INPUT x : DINT; y : DINT; END_VAR
  VAR_OUTPUT o : BOOL; END_VAR
  INITIAL_STEP S0:
  END_STEP
  STEP S1:
    o(N);
  END_STEP
  TRANSITION FROM S0 TO S1 := x + y = 123456;
  END_TRANSITION
  TRANSITION FROM S1 TO S0 := x * 3 = y;
  END_TRANSITION
END_PROGRAM
)";

TEST(WideInputs, TheExplicitEngineReportsTheInputAsItsLimit) {
  const auto file = sfcv::test::write_temp(kWide, ".st");
  const auto r = run_sfcv("check " + file +
                          " --engine explicit --checks none --ctl 'AG !(S0 & S1)' --json --quiet");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("properties").size(), 1u);
  EXPECT_EQ(j["properties"][0].at("verdict"), "unknown");
  EXPECT_NE(j["properties"][0].at("message").get<std::string>().find("input 'x'"),
            std::string::npos);
}

TEST(WideInputs, AutoGivesTheInvariantToTheSymbolicEngines) {
  const auto file = sfcv::test::write_temp(kWide, ".st");
  const auto holds =
      run_sfcv("check " + file + " --checks none --ctl 'AG !(S0 & S1)' --json --quiet");
  EXPECT_EQ(holds.exit_code, 0) << holds.err;
  EXPECT_EQ(nlohmann::json::parse(holds.out)["properties"][0].at("verdict"), "holds");
  const auto violated = run_sfcv("check " + file + " --checks none --ctl 'AG !S1' --json --quiet");
  EXPECT_EQ(violated.exit_code, 1) << violated.err;
  EXPECT_EQ(nlohmann::json::parse(violated.out)["properties"][0].at("verdict"), "violated");
}

}  // namespace

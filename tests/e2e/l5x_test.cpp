// Rockwell Studio 5000 .L5X through the binary: the demo chart (tests/support/l5x_text.hpp) and
// its IEC 61131-3 text twin give the same verdicts, on the explicit and BDD engines; what is
// not modelled is exit 2 naming the construct.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/l5x_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

TEST(L5xE2E, DemoChartAndItsIecTwinGiveTheSameVerdicts) {
  const auto native =
      write_temp(rockwell::l5x(rockwell::demo_tags(), rockwell::demo_sfc()), ".L5X");
  const auto twin = write_temp(rockwell::demo_twin(), ".st");
  // Read from the drawing: the selection legs exclude each other, the simultaneous legs run
  // together and the join waits for both; S2 is reachable (stop). In the situation where S1
  // has just become active its action has not run yet (a scan runs the actions of the steps
  // active at its start, then their transitions), so lamp may still be FALSE there; Merge is
  // reached before P1 ever set valve.
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG !(S1 & S2)", "holds"},
      {"AG (P1 <-> P2)", "holds"},
      {"AG !(P1 & Init)", "holds"},
      {"EF S2", "holds"},
      {"AG !S2", "violated"},
      {"AG (S1 -> lamp)", "violated"},
      {"AG (Merge -> valve)", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"}) {
    expect_ctl_verdicts_in_one_run(native, engine, verdicts);
    expect_ctl_verdicts_in_one_run(twin, engine, verdicts);
  }
  const auto r = run_sfcv("info " + native);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("rockwell-l5x 32.01"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("steps: 6, transitions: 6"), std::string::npos) << r.out;
}

TEST(L5xE2E, AStepTimerBitIsExitTwoNamingIt) {
  auto sfc = rockwell::demo_sfc();
  sfc.replace(sfc.find("NOT a"), 5, "S1.DN");
  const auto file = write_temp(rockwell::l5x(rockwell::demo_tags(), sfc), ".L5X");
  const auto r = run_sfcv("check " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'S1.DN': member DN of the SFC_STEP tag"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sfcv::test

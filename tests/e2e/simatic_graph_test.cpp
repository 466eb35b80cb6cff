// Siemens SimaticML through the binary: the S7-GRAPH and LAD demo blocks
// (tests/support/simatic_text.hpp) and their IEC 61131-3 text twins give the same verdicts on
// the explicit and BDD engines; what is not modelled is exit 2 naming the construct.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/sfcv_test.hpp"
#include "support/simatic_text.hpp"

namespace sfcv::test {
namespace {

TEST(SimaticGraphE2E, DemoBlockAndItsIecTwinGiveTheSameVerdicts) {
  const auto native = write_temp(simatic::demo(), ".xml");
  const auto twin = write_temp(simatic::demo_twin(), ".st");
  // Read from the drawing: Fill's alternatives exclude each other, the simultaneous legs run
  // together and the join waits for both; Idle resets the motor that Fill sets; L and D are
  // timed (heater goes off while Heat may still be active, lamp comes on in Done).
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG !(Fill & Done)", "holds"},
      {"AG (Mix <-> Heat)", "holds"},
      {"EF Done", "holds"},
      {"AG (Fill -> motor)", "holds"},
      {"AG (Idle -> !motor)", "holds"},
      {"AG (valve -> Fill)", "holds"},
      {"AG !lamp", "violated"},
      {"AG (Heat -> heater)", "violated"},
      {"AG (Mix -> valve)", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"}) {
    expect_ctl_verdicts_in_one_run(native, engine, verdicts);
    expect_ctl_verdicts_in_one_run(twin, engine, verdicts);
  }
  const auto r = run_sfcv("info " + native);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("simaticml-graph V20 (GRAPH 6.0)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("steps: 5, transitions: 5"), std::string::npos) << r.out;
}

// The LAD demo (a start pulse from a hand-kept edge, a run latch that stop resets last, a
// second motor after a TON) and its IEC text twin give the same verdicts, each read from the
// networks as drawn.
TEST(SimaticLadE2E, DemoBlockAndItsIecTwinGiveTheSameVerdicts) {
  const auto native = write_temp(simatic::lad_demo(), ".xml");
  const auto twin = write_temp(simatic::lad_demo_twin(), ".st");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG (pulse -> start & start_prev)", "holds"},  // the edge memory is written last
      {"AG (stop -> !running)", "holds"},             // reset after set: stop wins
      {"AG (motor2 -> running)", "holds"},
      {"EF motor2", "holds"},
      {"AG EF !running", "holds"},
      {"AG (running -> motor2)", "violated"},  // the delay
      {"AG !motor2", "violated"},
      {"AG (start -> pulse)", "violated"},  // held down: one pulse only
  };
  for (const char* engine : {"explicit", "bdd"}) {
    expect_ctl_verdicts_in_one_run(native, engine, verdicts);
    expect_ctl_verdicts_in_one_run(twin, engine, verdicts);
  }
  const auto r = run_sfcv("info " + native);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("simaticml-lad V20"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("siemens"), std::string::npos) << r.out;
}

TEST(SimaticGraphE2E, ASupervisionIsExitTwoNamingIt) {
  auto text = simatic::demo();
  const std::string empty_sv =
      "<FlgNet><Parts><Part Name=\"SvCoil\" UId=\"21\" /></Parts><Wires /></FlgNet>\n";
  text.replace(text.find(empty_sv), empty_sv.size(), simatic::lad({{"trip"}}, "SvCoil"));
  const auto file = write_temp(text, ".xml");
  const auto r = run_sfcv("check " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the supervision of step 'Idle' (trip)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sfcv::test

// Issue 45 (auto tuned on the public sets) and issue 52 item 2 (initial situations never
// enumerated past the run's limits): a Grafcet of 40 free inputs, each read by the initial
// situation's receptivities, has 2^40 initial situations.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::write_temp;

std::string wide_grafcet(int n) {
  std::string g7 = "project wide;\ninput a0";
  for (int i = 1; i < n; ++i) g7 += ", a" + std::to_string(i);
  g7 += ";\n";
  for (int i = 0; i < n; ++i) {
    const auto k = std::to_string(i);
    g7 += "grafcet G" + k + " {\n  step 0 initial;\n  step 1;\n  transition t" + k +
          "a: 0 -> 1 when a" + k + ";\n  transition t" + k + "b: 1 -> 0 when !a" + k + ";\n}\n";
  }
  return write_temp(g7, ".g7");
}

// The enumeration of the initial situations reads --max-states as it goes: it stops at the
// bound with unknown (exit 3), under every engine that enumerates them, instead of
// materialising 2^40 situations first.
TEST(AutoWideGrafcet, MaxStatesStopsTheInitialSituations) {
  const auto file = wide_grafcet(40);
  for (const std::string engine : {"explicit", "auto"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv("check " + file + " --engine " + engine +
                            " --max-states 1000 --trace none --quiet");
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.out.find("states limit"), std::string::npos) << r.out;
  }
}

// auto estimates the initial situations before it starts (2^40, far past the probe's 200 000
// states) and gives the budget to the race at once; IC3 proves the invariant. Before, the
// probe first enumerated 200 000 initial situations.
TEST(AutoWideGrafcet, AutoSkipsTheProbeAndTheRaceDecides) {
  const auto file = wide_grafcet(40);
  const auto r =
      run_sfcv("check " + file + " --checks none --ctl 'AG !(G0.X1 & !a0)' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.err.find("initial situations (estimated)"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("holds"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("[explicit]"), std::string::npos) << r.out;
}

}  // namespace

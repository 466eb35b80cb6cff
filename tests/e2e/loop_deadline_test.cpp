// A run ends at its --timeout even when each state is costly (issue 53's loop-bound examples,
// docs/semantics.md 1.9.1): an ST loop bounded by a 16-bit input runs up to 900 iterations for
// each class of the input, so one interpreted state takes tens of milliseconds while a search
// reads the clock only every few hundred states. On this program the explicit invariant search
// (alone, and as --engine auto's probe) ran 52 s past --timeout 10 before it read the clock;
// since the run's backstop it is ended at the deadline + 2 s with no report at all.

#include <gtest/gtest.h>

#include <string>

#include "support/cpu_run.hpp"
#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::kSlowdown;
using sfcv::test::write_temp;

constexpr const char* kInputBoundLoop = R"(PROGRAM Count
  VAR_INPUT n : INT; END_VAR
  VAR_OUTPUT total : INT; END_VAR
  VAR i : INT; END_VAR
  total := 0;
  i := 0;
  WHILE i < n AND i < 900 DO
    i := i + 1;
    total := total + 1;
  END_WHILE;
END_PROGRAM
)";

TEST(LoopDeadline, ExplicitSearchOfCostlyStatesStopsAtTheDeadlineWithItsReport) {
  const auto file = write_temp(kInputBoundLoop, ".st");
  const auto r = sfcv::test::cpu_run("check '" + file +
                                     "' --engine explicit --threads 1 --timeout 1 --trace none "
                                     "--ctl 'AG total < 1000'");
  // Unknown (exit 3) with the report printed, not ended by the backstop ("did not stop by
  // itself", nothing on standard output).
  EXPECT_EQ(r.run.exit_code, 3) << r.run.out << r.run.err;
  EXPECT_NE(r.run.out.find("AG total < 1000"), std::string::npos) << r.run.out << r.run.err;
  EXPECT_NE(r.run.out.find("unknown"), std::string::npos) << r.run.out;
  EXPECT_EQ(r.run.err.find("did not stop by itself"), std::string::npos) << r.run.err;
  // Within the timeout + 1 s + 5 % (CPU seconds: a loaded machine does not inflate them).
  EXPECT_LT(r.cpu, (1.0 + 1.0 + 0.05) * kSlowdown) << r.run.err;
}

}  // namespace

// `sfcv check --checks order-dependence` (issue 47, docs/semantics.md §1.2a) end to end: the
// two orders in the finding and the trace's note, the exit codes (violated 1, n/a under a total
// order 0, not checked on the SAT engines: unknown, 3).

#include <gtest/gtest.h>

#include <string>

#include "support/press_chart.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

TEST(OrderDependenceCli, ExitCodesAndTheTwoOrders) {
  const auto chart = "'" + write_temp(kPressChart, ".st") + "'";
  const std::string checks = " --checks order-dependence --quiet";
  for (const std::string engine : {"explicit", "bdd", "auto"}) {
    SCOPED_TRACE(engine);
    const auto r =
        run_sfcv("check " + chart + checks + " --action-order unordered --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("order-dependence  violated"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("order:motor=Start<Stop gives motor = 0, order:motor=Stop<Start gives "
                         "motor = 1"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("the last cycle runs order:motor=Start<Stop; under "
                         "order:motor=Stop<Start it would end with motor = 1"),
              std::string::npos)
        << r.out;
  }
  // A total order: nothing to choose, not applicable (exit 0).
  auto r = run_sfcv("check " + chart + checks);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("order-dependence  n/a"), std::string::npos) << r.out;
  // The SAT engines do not decide it: unknown among other checks, never "holds"; alone, the
  // run decides nothing asked (a usage error, issue 53).
  r = run_sfcv(
      "check " + chart +
      " --checks reachable,order-dependence --quiet --action-order unordered --engine ic3");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.out.find("not checked by the ic3 engine"), std::string::npos) << r.out;
  r = run_sfcv("check " + chart + checks + " --action-order unordered --engine ic3");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
}

}  // namespace
}  // namespace sfcv::test

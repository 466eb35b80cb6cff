// --threads is capped at the cores available: a request for 100,000 threads (which once
// exhausted the machine's process table) runs the same search, to the same report, as one thread.

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "support/generate.hpp"
#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::generate;
using sfcv::test::run_sfcv;

TEST(ThreadLimits, AHugeThreadCountIsCappedAndGivesTheOneThreadReport) {
  const std::string chart = generate("parallel 12 --selector", ".st");
  const std::string args =
      "check '" + chart +
      "' --engine explicit --checks none --ctl 'AG !(Init & B0)' --json --quiet";
  const auto one = run_sfcv(args + " --threads 1");
  const auto many = run_sfcv(args + " --threads 100000");
  ASSERT_TRUE(one.exit_code == 0 || one.exit_code == 1) << one.err;
  EXPECT_EQ(many.exit_code, one.exit_code) << many.err;
  const auto a = nlohmann::json::parse(one.out), b = nlohmann::json::parse(many.out);
  EXPECT_EQ(a.at("states"), b.at("states"));
  ASSERT_EQ(a.at("properties").size(), b.at("properties").size());
  for (std::size_t i = 0; i < a.at("properties").size(); ++i)
    EXPECT_EQ(a["properties"][i].at("verdict"), b["properties"][i].at("verdict"));
}

}  // namespace

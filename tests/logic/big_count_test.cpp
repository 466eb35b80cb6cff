#include "logic/big_count.hpp"

#include <gtest/gtest.h>

namespace sfcv::logic {
namespace {

BigCount power_of_two(unsigned k) {
  return BigCount(1).shifted_left(k);
}

TEST(BigCount, PrintsPowersOfTwoPastSixtyFourBits) {
  EXPECT_EQ(BigCount().str(), "0");
  EXPECT_EQ(BigCount(1'000'000'000).str(), "1000000000");  // a whole 10^9 chunk
  EXPECT_EQ(power_of_two(63).str(), "9223372036854775808");
  EXPECT_EQ(power_of_two(64).str(), "18446744073709551616");
  EXPECT_EQ(power_of_two(100).str(), "1267650600228229401496703205376");
  EXPECT_EQ(power_of_two(64).to_u64(), std::nullopt);
  EXPECT_EQ(power_of_two(63).to_u64(), std::optional<std::uint64_t>(std::uint64_t{1} << 63));
  EXPECT_DOUBLE_EQ(power_of_two(100).to_double(), 1267650600228229401496703205376.0);
}

TEST(BigCount, AddsWithCarriesAcrossLimbs) {
  BigCount c(~std::uint64_t{0});
  c += 1;
  EXPECT_EQ(c, power_of_two(64));
  c += power_of_two(64);
  EXPECT_EQ(c.str(), "36893488147419103232");
  BigCount d(3);
  d += d.shifted_left(33);  // 3 + 3 * 2^33
  EXPECT_EQ(d.str(), "25769803779");
  EXPECT_EQ(BigCount(5).shifted_left(0), BigCount(5));
  EXPECT_EQ(BigCount().shifted_left(70), BigCount());
}

}  // namespace
}  // namespace sfcv::logic

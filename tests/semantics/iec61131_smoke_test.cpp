#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

TEST(Iec61131Smoke, SequenceWithBooleanAction) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT v : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "NOT a");
  b.action_var("A1", "v").assoc("S2", "A1", "N");
  auto ts = b.build();
  ASSERT_TRUE(ts);
  Runner r(*ts);
  EXPECT_EQ(r["S1"], 1);
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["S2"], 1);
  EXPECT_EQ(r["S1"], 0);
  EXPECT_EQ(r["v"], 1);
  auto c = successors_of(*ts, r.state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!a", "a"}));
}

}  // namespace
}  // namespace sfcv::test

// Priorities and conflicts (docs/semantics.md, Part 1, "Priorities and conflicts").

#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

IecBuilder fork(std::optional<int> p2 = {}, std::optional<int> p3 = {}) {
  IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR");
  b.step("S1", true).step("S2").step("S3");
  b.trans("S1", "S2", "a", p2).trans("S1", "S3", "b", p3);
  b.trans("S2", "S1", "TRUE").trans("S3", "S1", "TRUE");
  return b;
}

std::string target_of(const semantics::TransitionSystem& ts, const CollectedSuccessor& s) {
  return ts.describe(s.target);
}

TEST(Iec61131Priority, StandardDocumentOrderDecidesConflicts) {
  auto b = fork();
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}, {"b", 1}}));
  EXPECT_EQ(r["S2"], 1);
  EXPECT_EQ(r["S3"], 0);
  auto c = successors_of(*ts, Runner(*ts).state());
  ASSERT_EQ(c.all.size(), 3u);
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!a & !b", "!a & b", "a"}));
  EXPECT_EQ(target_of(*ts, c.all[1]), "{MAIN.S3}");
  EXPECT_EQ(target_of(*ts, c.all[2]), "{MAIN.S2}");
}

TEST(Iec61131Priority, ExplicitPriorityBeatsDocumentOrder) {
  auto b = fork(2, 1);
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}, {"b", 1}}));
  EXPECT_EQ(r["S3"], 1);
  auto c = successors_of(*ts, Runner(*ts).state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!a & !b", "a & !b", "b"}));
}

TEST(Iec61131Priority, NoOrderMakesConflictsNondeterministicViaAChoiceInput) {
  auto b = fork(2, 1);  // priorities are ignored in this mode
  semantics::Iec61131Options o;
  o.priority = semantics::PriorityMode::None;
  auto ts = b.build(o);
  const auto ci = input_index(*ts, "choice:MAIN.S1");
  EXPECT_TRUE(ts->inputs()[ci].pseudo);
  auto c = successors_of(*ts, Runner(*ts).state());
  ASSERT_EQ(c.all.size(), 3u);
  EXPECT_EQ(conditions(c),
            (std::vector<std::string>{"!a & !b", "!a & b | a & b & choice:MAIN.S1 = 1",
                                      "a & !b | a & b & choice:MAIN.S1 = 0"}));
  EXPECT_EQ(target_of(*ts, c.all[1]), "{MAIN.S3}");
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}, {"b", 1}, {"choice:MAIN.S1", 1}}));
  EXPECT_EQ(r["S3"], 1);
  Runner r0(*ts);
  ASSERT_TRUE(r0.cycle({{"a", 1}, {"b", 1}}));  // choice defaults to the first alternative
  EXPECT_EQ(r0["S2"], 1);
}

TEST(Iec61131Priority, NoOrderWithoutConflictReadsNoChoice) {
  auto b = fork();
  semantics::Iec61131Options o;
  o.priority = semantics::PriorityMode::None;
  auto ts = b.build(o);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  auto c = successors_of(*ts, r.state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"TRUE"}));
}

TEST(Iec61131Priority, ParallelBranchesFireTogether) {
  IecBuilder b("VAR_INPUT a, b, go : BOOL; END_VAR");
  b.step("S0", true).step("A1").step("A2").step("B1").step("B2").step("J");
  b.trans("S0", "A1,B1", "go")
      .trans("A1", "A2", "a")
      .trans("B1", "B2", "b")
      .trans("A2,B2", "J", "TRUE");
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"go", 1}}));
  EXPECT_EQ(r["A1"] + r["B1"], 2);
  ASSERT_TRUE(r.cycle({{"a", 1}, {"b", 1}}));
  EXPECT_EQ(r["A2"] + r["B2"], 2);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["J"], 1);
  EXPECT_EQ(r["A2"] + r["B2"], 0);
}

TEST(Iec61131Priority, NoOrderRejectsConflictsInvolvingASynchronisation) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR");
  b.step("S0", true).step("S1", true).step("S2");
  b.trans("S0,S1", "S2", "a").trans("S0", "S2", "NOT a");
  semantics::Iec61131Options o;
  o.priority = semantics::PriorityMode::None;
  EXPECT_NE(b.build_error(o).find("cannot model this conflict"), std::string::npos);
}

}  // namespace
}  // namespace sfcv::test

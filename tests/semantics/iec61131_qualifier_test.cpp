// Action qualifiers (docs/semantics.md, Part 1, "Qualifiers"): N, S, R, P, P1, P0 and the timed
// ones L, D, SD, DS, SL in abstract and discrete time.

#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

// S1 -a-> S2 -b-> S3 -c-> S1, one Boolean output v driven by action A.
IecBuilder ring(const std::string& step, const std::string& q, std::optional<std::int64_t> d = {}) {
  IecBuilder b("VAR_INPUT a, b, c : BOOL; END_VAR VAR_OUTPUT v : BOOL; END_VAR");
  b.step("S1", true).step("S2").step("S3");
  b.trans("S1", "S2", "a").trans("S2", "S3", "b").trans("S3", "S1", "c");
  b.action_var("A", "v").assoc(step, "A", q, d);
  return b;
}

TEST(Iec61131Qualifier, NFollowsStepActivityInTheSameConfiguration) {
  auto b = ring("S2", "N");
  auto ts = b.build();
  Runner r(*ts);
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["S2"], 1);
  EXPECT_EQ(r["v"], 1);
  EXPECT_EQ(r["A"], 1);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  EXPECT_EQ(r["S3"], 1);
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131Qualifier, SStoresUntilR) {
  auto b = ring("S2", "S");
  b.assoc("S1", "A", "R");
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));  // S3: still stored
  EXPECT_EQ(r["S3"], 1);
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"c", 1}}));  // S1 resets
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131Qualifier, ROverridesSAndN) {
  auto b = ring("S2", "S");
  b.assoc("S2", "A", "R");
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["S2"], 1);
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131Qualifier, P1IsActiveOnceWhenTheStepBecomesReady) {
  for (const char* q : {"P1", "P"}) {
    auto b = ring("S2", q);
    auto ts = b.build();
    Runner r(*ts);
    ASSERT_TRUE(r.cycle({{"a", 1}}));
    EXPECT_EQ(r["v"], 1) << q;
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["S2"], 1);
    EXPECT_EQ(r["v"], 0) << q;
  }
}

TEST(Iec61131Qualifier, P1BodyExecutesExactlyOncePerEntry) {
  IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR VAR_OUTPUT n : INT; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
  b.action_st("Count", "n := n + 1;").assoc("S2", "Count", "P1");
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));  // enters S2: Count active, not executed yet
  EXPECT_EQ(r["n"], 0);
  ASSERT_TRUE(r.cycle());  // Count runs once
  EXPECT_EQ(r["n"], 1);
  ASSERT_TRUE(r.cycle());
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["n"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["n"], 2);
}

TEST(Iec61131Qualifier, ASelfLoopIsNotAReadinessChange) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT v, w : BOOL; END_VAR");
  b.step("S1", true).trans("S1", "S1", "a");
  b.action_var("A", "v").assoc("S1", "A", "P1");
  b.action_var("B", "w").assoc("S1", "B", "P0");
  auto ts = b.build();
  Runner r(*ts);
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r.fired.size(), 1u);
  EXPECT_EQ(r["v"], 0);
  EXPECT_EQ(r["w"], 0);
}

TEST(Iec61131Qualifier, P0IsActiveOnceWhenTheStepStopsBeingReady) {
  auto b = ring("S2", "P0");
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  EXPECT_EQ(r["S3"], 1);
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131Qualifier, InitialStepActionsAreActiveFromTheStart) {
  auto b = ring("S1", "P1");
  auto ts = b.build();
  Runner r(*ts);
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["v"], 0);
}

// ------------------------------------------------------------------------- timed, abstract

const char* kTimeout = "timeout:MAIN.S2.A.";

TEST(Iec61131QualifierAbstract, LIsActiveUntilItsTimerExpires) {
  auto b = ring("S2", "L", 1000);
  auto ts = b.build();
  const std::string to = std::string(kTimeout) + "L";
  EXPECT_TRUE(ts->inputs()[input_index(*ts, to)].pseudo);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{to, 0}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{to, 1}}));
  EXPECT_EQ(r["S2"], 1);
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle({{to, 0}}));  // expired stays expired
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131QualifierAbstract, DBecomesActiveWhenItsTimerExpires) {
  auto b = ring("S2", "D", 1000);
  auto ts = b.build();
  const std::string to = std::string(kTimeout) + "D";
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle({{to, 1}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131QualifierAbstract, TheTimeoutIsOnlyAnInputWhileTheTimerRuns) {
  auto b = ring("S2", "D", 1000);
  auto ts = b.build();
  Runner r(*ts);
  // In S1 the timer is idle: the successors do not mention the timeout.
  auto c = successors_of(*ts, r.state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!a", "a"}));
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  c = successors_of(*ts, r.state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!b & !timeout:MAIN.S2.A.D",
                                                     "!b & timeout:MAIN.S2.A.D", "b"}));
}

TEST(Iec61131QualifierAbstract, SDStaysSetAfterTheStepAndActsAfterTheDelay) {
  auto b = ring("S2", "SD", 1000);
  b.assoc("S1", "A", "R");
  auto ts = b.build();
  const std::string to = std::string(kTimeout) + "SD";
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle({{"b", 1}}));  // left S2, still set
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle({{to, 1}}));
  EXPECT_EQ(r["S3"], 1);
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"c", 1}}));  // reset in S1
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131QualifierAbstract, DSStoresOnlyIfTheStepLastsTheDelay) {
  auto b = ring("S2", "DS", 1000);
  b.assoc("S1", "A", "R");
  auto ts = b.build();
  const std::string to = std::string(kTimeout) + "DS";
  {
    Runner r(*ts);
    ASSERT_TRUE(r.cycle({{"a", 1}}));
    ASSERT_TRUE(r.cycle({{"b", 1}}));  // left before the timeout
    ASSERT_TRUE(r.cycle({{to, 1}}));
    EXPECT_EQ(r["v"], 0);
  }
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle({{to, 1}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  EXPECT_EQ(r["v"], 1);  // stored
  ASSERT_TRUE(r.cycle({{"c", 1}}));
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131QualifierAbstract, SLIsActiveForItsDurationEvenAfterTheStep) {
  auto b = ring("S2", "SL", 1000);
  auto ts = b.build();
  const std::string to = std::string(kTimeout) + "SL";
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  EXPECT_EQ(r["S3"], 1);
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{to, 1}}));
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["v"], 0);
}

// ------------------------------------------------------------------------- timed, discrete

/// v over `n` cycles after entering S2 at cycle 1 (and leaving it at cycle `leave`, 0 = never).
std::string trace(const semantics::TransitionSystem& ts, int n, int leave = 0, bool reset = false) {
  Runner r(ts);
  std::string out;
  for (int i = 1; i <= n; ++i) {
    std::map<std::string, std::int64_t> in;
    if (i == 1) in["a"] = 1;
    if (leave && i == leave) in["b"] = 1;
    if (reset && leave && i == leave + 4) in["c"] = 1;
    EXPECT_TRUE(r.cycle(in));
    out += std::to_string(r["v"]);
  }
  return out;
}

TEST(Iec61131QualifierDiscrete, LLastsItsDuration) {
  auto b = ring("S2", "L", 30);
  auto ts = b.build(discrete(10));
  EXPECT_EQ(trace(*ts, 6), "111000");
}

TEST(Iec61131QualifierDiscrete, DStartsAfterItsDuration) {
  auto b = ring("S2", "D", 20);
  auto ts = b.build(discrete(10));
  EXPECT_EQ(trace(*ts, 5), "00111");
  EXPECT_EQ(trace(*ts, 5, 2), "00000");  // left before the delay
}

TEST(Iec61131QualifierDiscrete, SDActsAfterTheDelayUntilReset) {
  auto b = ring("S2", "SD", 20);
  b.assoc("S1", "A", "R");
  auto ts = b.build(discrete(10));
  // Enter S2 at 1, leave at 2 (S3), reset when S1 is entered at 6.
  EXPECT_EQ(trace(*ts, 7, 2, true), "0011100");
}

TEST(Iec61131QualifierDiscrete, DSStoresAfterTheDelay) {
  auto b = ring("S2", "DS", 20);
  b.assoc("S1", "A", "R");
  auto ts = b.build(discrete(10));
  EXPECT_EQ(trace(*ts, 8, 4, true), "00111110");
  EXPECT_EQ(trace(*ts, 6, 2), "000000");
}

TEST(Iec61131QualifierDiscrete, SLLastsItsDurationAfterTheStep) {
  auto b = ring("S2", "SL", 30);
  auto ts = b.build(discrete(10));
  EXPECT_EQ(trace(*ts, 6, 2), "111000");
}

TEST(Iec61131Qualifier, DLIsRejected) {
  auto b = ring("S2", "DL", 30);
  EXPECT_NE(b.build_error().find("DL is not defined by IEC 61131-3"), std::string::npos);
}

}  // namespace
}  // namespace sfcv::test

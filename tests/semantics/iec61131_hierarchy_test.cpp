// Nested charts (docs/semantics.md, Part 1, "Nested charts and history").

#include <algorithm>
#include <random>

#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

// Top: S1 -a-> S2 (holds A3, N) -b-> S1. A3: N1 -x-> N2 -y-> N3 -z-> N1; N2 has p (P1), w (P0).
IecBuilder nested() {
  IecBuilder b("VAR_INPUT a, b, x, y, z : BOOL; END_VAR VAR_OUTPUT p, w, v2 : BOOL; END_VAR");
  b.step("S1", true).step("S2").step("S3");
  b.trans("S1", "S2", "a")
      .trans("S2", "S1", "b")
      .trans("S2", "S3", "N3.X")
      .trans("S3", "S1", "TRUE");
  b.assoc("S2", "A3", "N");
  b.chart("A3", "A3");
  b.step("N1", true).step("N2").step("N3");
  b.trans("N1", "N2", "x").trans("N2", "N3", "y").trans("N3", "N1", "z");
  b.action_var("P", "p").assoc("N2", "P", "P1");
  b.action_var("W", "w").assoc("N2", "W", "P0");
  b.action_var("V", "v2").assoc("N2", "V", "N");
  return b;
}

TEST(Iec61131Hierarchy, NestedStepsAreActiveOnlyWhileTheirActionIs) {
  auto b = nested();
  auto ts = b.build();
  Runner r(*ts);
  EXPECT_EQ(r["MAIN.A3.N1"], 0);     // ready (history) but A3 inactive
  ASSERT_TRUE(r.cycle({{"x", 1}}));  // the nested chart does not evolve while A3 is inactive
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["S2"], 1);
  EXPECT_EQ(r["A3"], 1);
  EXPECT_EQ(r["N1"], 1);
}

TEST(Iec61131Hierarchy, LeftAndResumedAtItsHistoryStep) {
  auto b = nested();
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle({{"x", 1}}));
  EXPECT_EQ(r["N2"], 1);
  EXPECT_EQ(r["v2"], 1);
  EXPECT_EQ(r["p"], 1);              // P1: N2 became ready
  ASSERT_TRUE(r.cycle({{"b", 1}}));  // leave S2: A3 inactive, N2 stays ready as history
  EXPECT_EQ(r["S1"], 1);
  EXPECT_EQ(r["A3"], 0);
  EXPECT_EQ(r["N2"], 0);
  EXPECT_EQ(r["v2"], 0);
  EXPECT_EQ(r["w"], 0);              // suspension is not a readiness change: no P0
  ASSERT_TRUE(r.cycle({{"y", 1}}));  // frozen
  ASSERT_TRUE(r.cycle({{"a", 1}}));  // resume at N2, not N1
  EXPECT_EQ(r["N2"], 1);
  EXPECT_EQ(r["N1"], 0);
  EXPECT_EQ(r["p"], 0);  // no P1 on resume
  EXPECT_EQ(r["v2"], 1);
  ASSERT_TRUE(r.cycle({{"y", 1}}));
  EXPECT_EQ(r["N3"], 1);
  EXPECT_EQ(r["w"], 1);  // P0: N2 stopped being ready
}

TEST(Iec61131Hierarchy, TopLevelAndNestedTransitionsFireInTheSameCycle) {
  auto b = nested();
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle({{"b", 1}, {"x", 1}}));
  EXPECT_EQ(r.fired.size(), 2u);
  EXPECT_EQ(r["S1"], 1);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["N2"], 1);  // the nested transition fired although its chart was being left
  // The successor conditions show the joint firing as one successor.
  Runner r2(*ts);
  ASSERT_TRUE(r2.cycle({{"a", 1}}));
  auto c = successors_of(*ts, r2.state());
  bool both = false;
  for (const auto& s : c.all)
    if (s.fired.size() == 2 && s.condition == "b & x") both = true;
  EXPECT_TRUE(both);
}

TEST(Iec61131Hierarchy, GuardsSeeTheCurrentActivityOfNestedSteps) {
  auto b = nested();
  auto ts = b.build();
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle({{"x", 1}}));
  ASSERT_TRUE(r.cycle({{"y", 1}}));  // N3 entered now: S2 -> S3 (N3.X) must wait a cycle
  EXPECT_EQ(r["N3"], 1);
  EXPECT_EQ(r["S2"], 1);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["S3"], 1);
}

TEST(Iec61131Hierarchy, ObservableNamesAndAmbiguity) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "NOT a");
  b.assoc("S1", "X1", "N").assoc("S2", "X2", "N");
  b.chart("X1", "X1");
  b.step("Init", true).step("Run").trans("Init", "Run", "a");
  b.chart("X2", "X2");
  b.step("Init", true).step("Run").trans("Init", "Run", "a");
  auto ts = b.build();
  std::string err;
  EXPECT_TRUE(semantics::find_observable(*ts, "MAIN.X1.Init", &err));
  EXPECT_TRUE(semantics::find_observable(*ts, "MAIN.X2.Init.X", &err));
  EXPECT_TRUE(semantics::find_observable(*ts, "S2.X", &err));
  EXPECT_TRUE(semantics::find_observable(*ts, "main.s2", &err));
  EXPECT_FALSE(semantics::find_observable(*ts, "Init", &err));
  EXPECT_NE(err.find("ambiguous"), std::string::npos);
  EXPECT_NE(err.find("MAIN.X1.Init"), std::string::npos);
  // A guard naming an ambiguous nested step is an error, not a guess.
  b.in(0).trans("S2", "S1", "Run.X");
  EXPECT_NE(b.build_error().find("ambiguous"), std::string::npos);
}

TEST(Iec61131Hierarchy, ObservablesReadOnlyTheFieldsTheyName) {
  // The explicit search memoises an invariant's verdicts on the bits of observed_fields(): a
  // field observe() reads and that list misses would make it reuse a wrong verdict.
  auto b = nested();
  auto ts = b.build();
  const auto& layout = ts->layout();
  std::mt19937_64 rng(7);
  std::vector<semantics::StateWord> state(layout.words()), other(layout.words());
  for (std::uint32_t o = 0; o < ts->observables().size(); ++o) {
    SCOPED_TRACE(ts->observables()[o].name);
    const auto fields = ts->observed_fields(o);
    ASSERT_TRUE(fields);
    std::vector<semantics::StateWord> kept(layout.words(), 0);
    for (const auto f : *fields)
      for (std::uint32_t bit = 0; bit < layout.fields()[f].width; ++bit) {
        const auto at = layout.fields()[f].offset + bit;
        kept[at / 64] |= semantics::StateWord{1} << (at % 64);
      }
    for (int trial = 0; trial < 200; ++trial) {
      for (std::size_t w = 0; w < state.size(); ++w) {
        state[w] = rng();
        other[w] = (state[w] & kept[w]) | (rng() & ~kept[w]);
      }
      EXPECT_EQ(ts->observe(other, o), ts->observe(state, o));
    }
  }
}

}  // namespace
}  // namespace sfcv::test

// IEC 60848 evolution rules, each on a small grafcet whose RSG is computed by hand in the
// comments (docs/semantics.md, Part 2, cites these tests). States are (situation, inputs).

#include <gtest/gtest.h>

#include "model/errors.hpp"
#include "support/grafcet_builder.hpp"

namespace sfcv::test {
namespace {

using model::ExprKind;
using model::StoredWhen;

// 1 --a--> 2 --!a--> 1. Initial: a=0 gives ({1},0), a=1 clears t1 at once: ({2},1).
TEST(GrafcetRules, InitialSituationIsStabilisedUnderEachInitialValuation) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, not_(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_TRUE(r.graph.complete());
  EXPECT_EQ(r.graph.num_states(), 2u);
  EXPECT_EQ(r.graph.num_edges(), 2u);
  ASSERT_EQ(r.graph.initial_states().size(), 2u);
  EXPECT_EQ(r.graph.initial_condition(0).to_string(r.system->inputs()), "!a");
  EXPECT_EQ(r.system->describe(r.graph.states().at(r.graph.initial_states()[1])), "{2}");
  EXPECT_EQ(rsg_lines(r), (std::vector<std::string>{"{1} --[a]--> {2}", "{2} --[!a]--> {1}"}));
}

// 1 --a--> 2 and 1 --a--> 3: both clearable, both cleared (no priority in Grafcet): {2,3}.
TEST(GrafcetRules, SimultaneouslyClearableTransitionsClearTogether) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, v("a")).transition({"1"}, {"3"}, v("a"));
  const auto r = build_rsg(b.project());
  // ({1},0) --a--> ({2,3},1) <--> ({2,3},0); the initial a=1 gives ({2,3},1) directly.
  EXPECT_EQ(r.graph.num_states(), 3u);
  EXPECT_EQ(r.graph.num_edges(), 3u);
  EXPECT_EQ(count_states(r, {"X2", "X3"}), 2u);
  EXPECT_EQ(count_states(r, {"X2"}, {"X3"}), 0u);
}

// Steps 1 and 2 initial; t1: 1 --RE a--> 2, t2: 2 --RE a--> 3. When a rises both clear: step 2
// is deactivated by t2 and activated by t1, so it stays active: {2,3} (not {3}). In {2,3}, the
// next rise of a clears t2 alone: {3}.
// States: ({1,2},0) ({1,2},1) ({2,3},1) ({2,3},0) ({3},1) ({3},0); one edge each.
TEST(GrafcetRules, ActivatedAndDeactivatedStepStaysActive) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2", true).step("3");
  b.transition({"1"}, {"2"}, rise(v("a"))).transition({"2"}, {"3"}, rise(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 6u);
  EXPECT_EQ(r.graph.num_edges(), 6u);
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1,2} --[a]--> {2,3}"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2,3} --[a]--> {3}"), lines.end());
  EXPECT_EQ(count_states(r, {"X3"}, {"X2"}), 2u);
}

// 1 --a--> 2 --b--> 3 --!a--> 1, inputs a, b. Transient evolutions run until stability:
// from ({2},00) raising b goes 2 -> 3 -> 1 in one event, so {3} is not a node there.
// Six states: ({1},00) ({1},01) ({2},10) ({3},11) ({2},00) ({3},10), two toggles each.
TEST(GrafcetRules, TransientEvolutionsRunToAStableSituation) {
  GrafcetBuilder b;
  b.input("a").input("b").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"3"}, v("b"));
  b.transition({"3"}, {"1"}, not_(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 6u);
  EXPECT_EQ(r.graph.num_edges(), 12u);
  const auto lines = rsg_lines(r);
  // ({2},00) --b--> ({1},01): through 3 without stopping; fired: t2 and t3.
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2} --[!a & b]--> {1}"), lines.end());
  bool found = false;
  for (std::uint64_t e = 0; e < r.graph.num_edges(); ++e)
    if (r.graph.fired(e).size() == 2) found = true;
  EXPECT_TRUE(found);
}

// t1: 1 --RE a--> 2, t2: 2 --RE a--> 1. The edge is true only in the first evolution after
// the event, so one rise of a moves one step (with a level condition it would be unstable).
// States: ({1},0) ({1},1) ({2},1) ({2},0), one edge each.
TEST(GrafcetRules, EdgesHoldOnlyInTheFirstEvolutionAfterTheEvent) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, rise(v("a"))).transition({"2"}, {"1"}, rise(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_TRUE(r.graph.anomalies().empty());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 4u);
  EXPECT_EQ(rsg_lines(r), (std::vector<std::string>{"{1} --[!a]--> {1}", "{1} --[a]--> {2}",
                                                    "{2} --[!a]--> {2}", "{2} --[a]--> {1}"}));
}

// Level receptivities: t1: 1 --a--> 2, t2: 2 --a--> 1. With a true the situation alternates
// {1} {2} {1}... forever: an instability, reported with its cycle and its inputs, and no node.
TEST(GrafcetRules, InstabilityIsReportedNotLooped) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, v("a"));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 1u);  // ({1},0) only
  EXPECT_EQ(r.graph.num_edges(), 0u);
  ASSERT_EQ(r.graph.anomalies().size(), 2u);  // at start with a=1, and when a rises in ({1},0)
  for (const auto& a : r.graph.anomalies()) {
    EXPECT_EQ(a.kind, semantics::Anomaly::Kind::Instability);
    EXPECT_EQ(a.condition.to_string(r.system->inputs()), "a");
    ASSERT_EQ(a.cycle.size(), 2u);
    EXPECT_NE(r.system->describe(a.cycle[0]), r.system->describe(a.cycle[1]));
  }
}

// A bound of the semantics is not a finding (docs/semantics.md 2.11): the chain
// 0 --a--> 1 --1--> 2 ... --1--> n --!a--> 0 needs exactly n evolutions when a rises (and at
// start under a). With max_transient_steps = n it stabilises in {n}, no anomaly; with n - 1 the
// run stops with a LimitReached that names the bound (unknown), never an instability.
model::Project chain_of_evolutions(int n) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("0", true);
  for (int i = 1; i <= n; ++i) b.step(std::to_string(i));
  b.transition({"0"}, {"1"}, v("a"));
  for (int i = 1; i < n; ++i) b.transition({std::to_string(i)}, {std::to_string(i + 1)}, lit(true));
  b.transition({std::to_string(n)}, {"0"}, not_(v("a")));
  return b.project();
}

TEST(GrafcetRules, TransientBoundReachedIsALimitNotAnInstability) {
  constexpr int n = 40;
  semantics::GrafcetOptions exact;
  exact.max_transient_steps = n;
  const auto r = build_rsg(chain_of_evolutions(n), exact);
  EXPECT_TRUE(r.graph.anomalies().empty());
  EXPECT_EQ(r.graph.num_states(), 2u);  // ({0},0) ({40},1)
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{0} --[a]--> {40}"), lines.end());

  semantics::GrafcetOptions short_bound;
  short_bound.max_transient_steps = n - 1;
  try {
    build_rsg(chain_of_evolutions(n), short_bound);
    ADD_FAILURE() << "no limit reported";
  } catch (const LimitReached& e) {
    EXPECT_NE(std::string(e.what()).find("no stable situation after 39 transient evolutions"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("max_transient_steps"), std::string::npos) << e.what();
  }
}

// 1 --a--> 2 --TRUE--> 3 --!a--> 1; step 2 (transient) stores x := 1 on activation and holds
// the continuous action y; step 1 stores x := 0 on activation. The stored action of the
// transient step is executed (x = 1 in {3}); the continuous one is never emitted.
TEST(GrafcetRules, StoredActionsRunInTransientStepsContinuousOnesDoNot) {
  GrafcetBuilder b;
  b.input("a").output("x").output("y").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"3"}, lit(true));
  b.transition({"3"}, {"1"}, not_(v("a")));
  b.stored("2", StoredWhen::Activation, "x", num(1))
      .stored("1", StoredWhen::Activation, "x", num(0));
  b.continuous("2", "y");
  const auto r = build_rsg(b.project());
  EXPECT_EQ(rsg_lines(r), (std::vector<std::string>{"{1} --[a]--> {3} x", "{3} x --[!a]--> {1}"}));
  EXPECT_EQ(count_states(r, {"y"}), 0u);
  EXPECT_EQ(count_states(r, {"X3", "x"}), 1u);
}

// G1: 1 --a--> 2 --!a--> 1; G2: 10 --X2--> 11 --X1--> 10: step variables in receptivities.
TEST(GrafcetRules, StepVariablesInReceptivities) {
  GrafcetBuilder b;
  b.input("a").chart("G1").step("1", true).step("2");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, not_(v("a")));
  b.chart("G2").step("10", true).step("11");
  b.transition({"10"}, {"11"}, v("X2")).transition({"11"}, {"10"}, v("X1"));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(rsg_lines(r),
            (std::vector<std::string>{"{1,10} --[a]--> {2,11}", "{2,11} --[!a]--> {1,10}"}));
}

// 1 --a--> 2 --2s/X2--> 3 --!a--> 1 in abstract time: the delay may elapse at any later event,
// a pseudo-input. States: ({1},0,off) ({2},1,wait) ({2},0,wait) ({3},1,off); 6 edges, two of
// them the elapse of the delay.
TEST(GrafcetRules, DelaysElapseAsAPseudoInputEvent) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, v("a"));
  b.transition({"2"}, {"3"}, model::make_delay(2000, v("X2"), 0));
  b.transition({"3"}, {"1"}, not_(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 6u);
  const auto& in = r.system->inputs();
  ASSERT_EQ(in.size(), 2u);
  EXPECT_TRUE(in[1].pseudo);
  std::size_t elapse = 0;
  for (std::uint64_t e = 0; e < r.graph.num_edges(); ++e)
    for (const auto& c : r.graph.condition(e).cubes)
      for (const auto& l : c.literals)
        if (l.input == 1 && l.lo == 1) ++elapse;
  EXPECT_EQ(elapse, 2u);
}

}  // namespace
}  // namespace sfcv::test

// Grafcet structure: forcing orders, enclosing steps, macro-steps (docs/semantics.md, Part 2).

#include <gtest/gtest.h>

#include "support/grafcet_builder.hpp"

namespace sfcv::test {
namespace {

using model::ForcingKind;
using model::StepKind;

// G1: 10 --f--> 11 --!f--> 10, step 11 holds a forcing order on G2;
// G2: 20 --a--> 21 --!a--> 20. Inputs a, f.
GrafcetBuilder forcing_model(ForcingKind kind, std::vector<std::string> situation = {}) {
  GrafcetBuilder b;
  b.input("a").input("f");
  b.chart("G1").step("10", true).step("11");
  b.transition({"10"}, {"11"}, v("f")).transition({"11"}, {"10"}, not_(v("f")));
  b.forcing("11", "G2", kind, std::move(situation));
  b.chart("G2").step("20", true).step("21");
  b.transition({"20"}, {"21"}, v("a")).transition({"21"}, {"20"}, not_(v("a")));
  return b;
}

// G{21}: while 11 is active G2 is {21} whatever a is (forcing takes precedence over G2's
// own transition 21 --!a--> 20). States ({10,20},00) ({10,21},10) ({11,21},01) ({11,21},11).
TEST(GrafcetStructure, ForcingASituationTakesPrecedence) {
  const auto r = build_rsg(forcing_model(ForcingKind::Situation, {"21"}).project());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 8u);
  EXPECT_EQ(count_states(r, {"X11"}, {"X21"}), 0u);
  EXPECT_EQ(count_states(r, {"X11", "X21"}), 2u);
  const auto lines = rsg_lines(r);
  // From ({11,21},01), f falls: G1 returns to 10, G2 (no longer forced) then leaves 21.
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{11,21} --[!a & !f]--> {10,20}"), lines.end());
}

// G{}: G2 is emptied and stays empty after the order ends. Six states, twelve edges.
TEST(GrafcetStructure, ForcingTheEmptySituation) {
  const auto r = build_rsg(forcing_model(ForcingKind::Empty).project());
  EXPECT_EQ(r.graph.num_states(), 6u);
  EXPECT_EQ(r.graph.num_edges(), 12u);
  EXPECT_EQ(count_states(r, {"X10"}, {"X20", "X21"}), 2u);
}

// G{INIT}: G2 is held in {20}. States ({10,20},00) ({10,21},10) ({11,20},01) ({11,20},11).
TEST(GrafcetStructure, ForcingTheInitialSituation) {
  const auto r = build_rsg(forcing_model(ForcingKind::Initial).project());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 8u);
  EXPECT_EQ(count_states(r, {"X11", "X21"}), 0u);
}

// G{*}: G2 is frozen in its current situation. Six states, twelve edges; both {11,20} and
// {11,21} occur, and a change of a in them changes nothing but the input.
TEST(GrafcetStructure, ForcingTheCurrentSituationFreezes) {
  const auto r = build_rsg(forcing_model(ForcingKind::Current).project());
  EXPECT_EQ(r.graph.num_states(), 6u);
  EXPECT_EQ(r.graph.num_edges(), 12u);
  EXPECT_EQ(count_states(r, {"X11", "X20"}), 2u);
  EXPECT_EQ(count_states(r, {"X11", "X21"}), 2u);
}

// G1: 1 --e--> 2 --!e--> 1, step 2 encloses G3: 30 --a--> 31 --!a--> 30 (30 is activated with
// the enclosing step). States ({1},00) ({1},01) ({2,30},10) ({2,31},11), 8 edges.
TEST(GrafcetStructure, EnclosingStepActivatesAndDeactivatesItsPartialGrafcet) {
  GrafcetBuilder b;
  b.input("e").input("a");
  b.chart("G1").step("1", true).step("2", false, StepKind::Enclosing, {"G3"});
  b.transition({"1"}, {"2"}, v("e")).transition({"2"}, {"1"}, not_(v("e")));
  b.chart("G3").step("30", true).step("31");
  b.transition({"30"}, {"31"}, v("a")).transition({"31"}, {"30"}, not_(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 8u);
  EXPECT_EQ(count_states(r, {"X30"}, {"X2"}), 0u);
  EXPECT_EQ(count_states(r, {"X31"}, {"X2"}), 0u);
  EXPECT_EQ(count_states(r, {"X1"}, {"X30", "X31"}), 2u);
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2,31} --[e & !a]--> {2,30}"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2,31} --[!e & a]--> {1}"), lines.end());
}

// G1: 1 --a--> M2 --!a--> 1, expansion X2: E2 --b--> S2. The transition after M2 waits for the
// exit step S2. States ({1},00) ({1},01) ({E2},10) ({S2},11) ({E2},00) ({S2},10), 12 edges.
TEST(GrafcetStructure, MacroStepEntersAtEntryAndLeavesFromExit) {
  GrafcetBuilder b;
  b.input("a").input("b");
  b.chart("G1").step("1", true).step("M2", false, StepKind::MacroStep, {"X2"});
  b.transition({"1"}, {"M2"}, v("a")).transition({"M2"}, {"1"}, not_(v("a")));
  b.chart("X2").step("E2").step("S2");
  b.transition({"E2"}, {"S2"}, v("b"));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 6u);
  EXPECT_EQ(r.graph.num_edges(), 12u);
  EXPECT_EQ(count_states(r, {"XE2"}, {"XM2"}), 0u);  // the macro-step is active with its expansion
  EXPECT_EQ(count_states(r, {"XE2"}, {"a"}), 1u);    // ({E2},00): !a does not leave M2 yet
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{E2,M2} --[!a & b]--> {1}"), lines.end());
}

}  // namespace
}  // namespace sfcv::test

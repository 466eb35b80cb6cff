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

// IEC 60848 activation links (docs/semantics.md 2.12 a): when an enclosing step is activated,
// each grafcet it encloses takes its steps marked `*`. The minimal case: Main
// 1 --a--> 2 --b--> 1, 2 encloses G0: 10 (linked) --c--> 11 --!c--> 10, no initial step in G0.
// Entering 2 gives {2,10} (c false) or {2,11} (c true, 10 --c--> 11 transiently); in 1 no step
// of G0 is active.
GrafcetBuilder linked_model() {
  GrafcetBuilder b;
  b.input("a").input("b").input("c");
  b.chart("Main").step("1", true).step("2", false, StepKind::Enclosing, {"G0"});
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, v("b"));
  b.chart("G0").step("10").step("11");
  b.pou().charts.back().steps[0].activation_link = true;
  b.transition({"10"}, {"11"}, v("c")).transition({"11"}, {"10"}, not_(v("c")));
  return b;
}

TEST(GrafcetStructure, LinkedStepIsActivatedWithItsEnclosingStep) {
  const auto r = build_rsg(linked_model().project());
  EXPECT_EQ(count_states(r, {"X2"}, {"X10", "X11"}), 0u);  // AG (X2 -> X10 | X11)
  EXPECT_GT(count_states(r, {"X2", "X10"}), 0u);           // EF X10
  EXPECT_GT(count_states(r, {"X2", "X11"}), 0u);
  EXPECT_EQ(count_states(r, {"X10"}, {"X2"}), 0u);
  EXPECT_EQ(count_states(r, {"X11"}, {"X2"}), 0u);
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a & !b & !c]--> {2,10}"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a & !b & c]--> {2,11}"), lines.end());
}

// 2.12 a: the linked steps, not the initial ones, are the entry of an enclosed grafcet that has
// both. G0: 10 initial, 11 linked, 11 --c--> 10. Entering 2 with c false gives {2,11}.
TEST(GrafcetStructure, LinkedStepsTakePrecedenceOverInitialStepsOnActivation) {
  GrafcetBuilder b;
  b.input("a").input("b").input("c");
  b.chart("Main").step("1", true).step("2", false, StepKind::Enclosing, {"G0"});
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, v("b"));
  b.chart("G0").step("10", true).step("11");
  b.pou().charts.back().steps[1].activation_link = true;
  b.transition({"11"}, {"10"}, v("c"));
  const auto r = build_rsg(b.project());
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a & !b & !c]--> {2,11}"), lines.end());
  EXPECT_EQ(std::find(lines.begin(), lines.end(), "{1} --[a & !b & !c]--> {2,10}"), lines.end());
  EXPECT_EQ(count_states(r, {"X2", "X10", "X11"}), 0u);
}

// 2.2 (b): at start an initially active enclosing step has its enclosed grafcets take their
// initial steps; one without an initial step takes its linked steps. Main: 1 (initial) encloses
// G0 (10 initial, 11 linked) and G5 (50 linked, 51), 1 --a--> 3 --!a--> 1. Start: {1,10,50};
// once 1 is left and re-entered (a activation), G0 enters at 11.
TEST(GrafcetStructure, InitialEnclosingStepTakesInitialStepsElseLinkedOnes) {
  GrafcetBuilder b;
  b.input("a");
  b.chart("Main").step("1", true, StepKind::Enclosing, {"G0", "G5"}).step("3");
  b.transition({"1"}, {"3"}, v("a")).transition({"3"}, {"1"}, not_(v("a")));
  b.chart("G0").step("10", true).step("11");
  b.pou().charts.back().steps[1].activation_link = true;
  b.chart("G5").step("50").step("51");
  b.pou().charts.back().steps[0].activation_link = true;
  const auto r = build_rsg(b.project());
  std::vector<std::string> initial;
  for (auto s : r.graph.initial_states())
    initial.push_back(r.system->describe(r.graph.states().at(s)));
  ASSERT_EQ(initial.size(), 2u);  // under !a, and a (left at once: {3})
  EXPECT_NE(std::find(initial.begin(), initial.end(), "{1,10,50}"), initial.end());
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{3} --[!a]--> {1,11,50}"), lines.end());
  EXPECT_EQ(count_states(r, {"X1", "X10"}), 1u);  // only the start
}

// 2.12 a, recursively: 2 encloses G0 whose linked step 10 encloses G5 (linked 50). Entering 2
// activates 10 and 50 in the same evolution; leaving 2 (2.12 c) deactivates both.
TEST(GrafcetStructure, NestedEnclosuresEnterAtTheirLinkedSteps) {
  GrafcetBuilder b;
  b.input("a");
  b.chart("Main").step("1", true).step("2", false, StepKind::Enclosing, {"G0"});
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, not_(v("a")));
  b.chart("G0").step("10", false, StepKind::Enclosing, {"G5"});
  b.pou().charts.back().steps[0].activation_link = true;
  b.chart("G5").step("50").step("51");
  b.pou().charts.back().steps[0].activation_link = true;
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 2u);
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a]--> {2,10,50}"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2,10,50} --[!a]--> {1}"), lines.end());
}

// 2.12 a through a macro-step entry: M2's entry step E2 encloses G0 (linked 10); entering M2
// activates E2, hence 10.
TEST(GrafcetStructure, MacroStepEntryThatEnclosesActivatesTheLinkedSteps) {
  GrafcetBuilder b;
  b.input("a");
  b.chart("Main").step("1", true).step("M2", false, StepKind::MacroStep, {"X2"});
  b.transition({"1"}, {"M2"}, v("a")).transition({"M2"}, {"1"}, not_(v("a")));
  b.chart("X2").step("E2", false, StepKind::Enclosing, {"G0"}).step("S2");
  b.transition({"E2"}, {"S2"}, lit(true));
  b.chart("G0").step("10").step("11");
  b.pou().charts.back().steps[0].activation_link = true;
  b.transition({"10"}, {"11"}, v("a"));
  const auto r = build_rsg(b.project());
  // E2 --1--> S2 at once: E2 is crossed, G0 entered at 10 and left with E2 (10 --a--> 11 is
  // cleared in the same evolution as E2 --1--> S2, then G0 is cleared as E2 is inactive).
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a]--> {M2,S2}"), lines.end());
  EXPECT_EQ(count_states(r, {"X10"}), 0u);
  EXPECT_EQ(count_states(r, {"X11"}), 0u);
}

// The same without the immediate exit: E2 --b--> S2; entering M2 gives {E2,M2,10}, and G0
// evolves inside (10 --a--> 11 in the next evolution, a still true): {E2,M2,11}.
TEST(GrafcetStructure, MacroStepEntryThatEnclosesKeepsItsGrafcetWhileActive) {
  GrafcetBuilder b;
  b.input("a").input("b");
  b.chart("Main").step("1", true).step("M2", false, StepKind::MacroStep, {"X2"});
  b.transition({"1"}, {"M2"}, v("a")).transition({"M2"}, {"1"}, not_(v("a")));
  b.chart("X2").step("E2", false, StepKind::Enclosing, {"G0"}).step("S2");
  b.transition({"E2"}, {"S2"}, v("b"));
  b.chart("G0").step("10").step("11");
  b.pou().charts.back().steps[0].activation_link = true;
  b.transition({"10"}, {"11"}, v("a"));
  const auto r = build_rsg(b.project());
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a & !b]--> {11,E2,M2}"), lines.end());
  EXPECT_EQ(count_states(r, {"XE2"}, {"X10", "X11"}), 0u);
  EXPECT_EQ(count_states(r, {"X11"}, {"XE2"}), 0u);
}

// A macro-step's expansion enters at the step the file marks `entry` and leaves from the one
// marked `exit` (model::Chart::macro_entry/macro_exit), whatever their names and order:
// expansion X2 declares S first, then E; 1 --a--> M2 --!a--> 1, E --b--> S.
TEST(GrafcetStructure, MacroStepUsesTheMarkedEntryAndExitSteps) {
  GrafcetBuilder b;
  b.input("a").input("b");
  b.chart("Main").step("1", true).step("M2", false, StepKind::MacroStep, {"X2"});
  b.transition({"1"}, {"M2"}, v("a")).transition({"M2"}, {"1"}, not_(v("a")));
  b.chart("X2").step("out").step("in");
  b.pou().charts.back().macro_entry = "in";
  b.pou().charts.back().macro_exit = "out";
  b.transition({"in"}, {"out"}, v("b"));
  const auto r = build_rsg(b.project());
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[a & !b]--> {M2,in}"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{M2,out} --[!a & b]--> {1}"), lines.end());
  EXPECT_EQ(count_states(r, {"Xin", "Xout"}), 0u);
}

// Forcing to a situation that contains an enclosing step (2.12): G1 10 --f--> 11 --!f--> 10,
// 11 forces G2{21}; 21 encloses G3 (30 linked --c--> 31 --!c--> 30). The order activates 21,
// so G3 enters at 30; while the order holds, 21 stays active and G3 evolves on its own (31 is
// reached under the order); when 21 is left, G3 is emptied.
TEST(GrafcetStructure, ForcingAnEnclosingStepActivatesItsLinkedSteps) {
  GrafcetBuilder b;
  b.input("f").input("c");
  b.chart("G1").step("10", true).step("11");
  b.transition({"10"}, {"11"}, v("f")).transition({"11"}, {"10"}, not_(v("f")));
  b.forcing("11", "G2", ForcingKind::Situation, {"21"});
  b.chart("G2").step("20", true).step("21", false, StepKind::Enclosing, {"G3"});
  b.transition({"20"}, {"21"}, lit(false)).transition({"21"}, {"20"}, not_(v("f")));
  b.chart("G3").step("30").step("31");
  b.pou().charts.back().steps[0].activation_link = true;
  b.transition({"30"}, {"31"}, v("c")).transition({"31"}, {"30"}, not_(v("c")));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(count_states(r, {"X21"}, {"X30", "X31"}), 0u);
  EXPECT_GT(count_states(r, {"X11", "X21", "X30"}), 0u);
  EXPECT_GT(count_states(r, {"X11", "X21", "X31"}), 0u);
  EXPECT_EQ(count_states(r, {"X30"}, {"X21"}), 0u);
  EXPECT_EQ(count_states(r, {"X31"}, {"X21"}), 0u);
}

}  // namespace
}  // namespace sfcv::test

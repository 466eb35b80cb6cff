// What one evolution of a grafcet crosses (docs/semantics.md 2.5): the steps active in one of
// its situations but in neither its source nor its target (semantics::Successor::entered), and
// the evolutions that end in their source (SuccessorSink::returning: no edge, 2.1, but what they
// fire and cross). The RSG keeps them per state; the standard checks read them.

#include <gtest/gtest.h>

#include "support/grafcet_builder.hpp"

namespace sfcv::test {
namespace {

/// The layout names ("G.2") of the steps the evolutions of the state described `from` cross.
std::vector<std::string> crossed_from(const BuiltRsg& r, const std::string& from) {
  std::vector<std::string> out;
  const auto& states = r.graph.crossing_states();
  for (std::size_t i = 0; i < states.size(); ++i)
    if (r.system->describe(r.graph.states().at(states[i])) == from)
      for (auto f : r.graph.crossed(i)) out.push_back(r.system->layout().fields()[f].name);
  return out;
}

// 1 --a--> 2 --1--> 3 --!a--> 1: a rise of a in {1} runs {1} -> {2} -> {3}; 2 is crossed.
TEST(GrafcetCrossedSteps, AnEvolutionReportsTheStepsActiveInItsTransientSituations) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"3"}, lit(true));
  b.transition({"3"}, {"1"}, not_(v("a")));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(crossed_from(r, "{1}"), std::vector<std::string>{"G.2"});
  EXPECT_TRUE(crossed_from(r, "{3}").empty());  // a falls: {3} -> {1}, nothing in between
  // At the start under a: {1} -> {2} -> {3}, the initial step and 2 crossed.
  EXPECT_EQ(r.graph.entered_initially(), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_TRUE(r.graph.returning_states().empty());
}

// 2.12 c is applied after the clearing: `1 --a--> 3 --b--> 1`, 3 encloses G3 `32* --b--> 31`. A
// rise of b in {3,32} clears both; 3 is left, so G3 is emptied in the same evolution: 31 is in
// no situation, and no evolution reports it (32 -> 31 is still fired).
TEST(GrafcetCrossedSteps, AStepEmptiedWithItsEnclosingStepInTheEvolutionThatEntersItIsNotCrossed) {
  GrafcetBuilder b;
  b.input("a").input("b").chart("G1").step("1", true).step("3", false, model::StepKind::Enclosing,
                                                           {"G3"});
  b.transition({"1"}, {"3"}, v("a")).transition({"3"}, {"1"}, v("b"));
  b.chart("G3").step("31").step("32");
  b.transition({"32"}, {"31"}, v("b"));
  b.pou().charts.back().steps[1].activation_link = true;
  const auto r = build_rsg(b.project());
  EXPECT_EQ(count_states(r, {"X31"}), 0u);
  bool fired = false;
  for (std::uint64_t e = 0; e < r.graph.num_edges(); ++e)
    for (auto t : r.graph.fired(e))
      fired = fired || r.system->transitions()[t].name == "X32 -> X31";
  EXPECT_TRUE(fired);
  for (std::size_t i = 0; i < r.graph.crossing_states().size(); ++i)
    for (auto f : r.graph.crossed(i)) EXPECT_NE(r.system->layout().fields()[f].name, "G3.31");
  for (auto f : r.graph.entered_initially())
    EXPECT_NE(r.system->layout().fields()[f].name, "G3.31");
}

// `1 --a--> 2 --1s/X2--> 1`, `2 --!a--> 3 --a--> 2`: in {2} (a true) the elapse runs
// {2} -> {1} -> {2} and the delay restarts: the same stable situation, no edge, but an evolution
// back to the source that fired 2 -> 1 and 1 -> 2 and crossed 1.
TEST(GrafcetCrossedSteps, AnEvolutionBackToItsSourceIsReportedWithoutAnEdge) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, v("a"))
      .transition({"2"}, {"1"}, model::make_delay(1000, v("X2"), 0))
      .transition({"2"}, {"3"}, not_(v("a")))
      .transition({"3"}, {"2"}, v("a"));
  const auto r = build_rsg(b.project());
  const auto& back = r.graph.returning_states();
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(r.system->describe(r.graph.states().at(back[0])), "{2}");
  std::vector<std::string> fired;
  for (auto t : r.graph.returning_fired(0)) fired.push_back(r.system->transitions()[t].name);
  EXPECT_EQ(fired, (std::vector<std::string>{"X1 -> X2", "X2 -> X1"}));
  EXPECT_EQ(crossed_from(r, "{2}"), std::vector<std::string>{"G.1"});
  for (std::uint32_t s = 0; s < r.graph.num_states(); ++s)
    for (auto e = r.graph.edges_begin(s); e < r.graph.edges_end(s); ++e)
      EXPECT_NE(r.graph.target(e), s);  // stuttering is still no edge
}

}  // namespace
}  // namespace sfcv::test

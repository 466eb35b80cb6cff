// Inputs of the Grafcet semantics: the single-input-change hypothesis on and off, assignment
// conditions of continuous actions, integer inputs (docs/semantics.md, Part 2).

#include <gtest/gtest.h>

#include "engine/bdd/condition_simplifier.hpp"
#include "semantics/simulate.hpp"
#include "support/grafcet_builder.hpp"

namespace sfcv::test {
namespace {

using model::ExprKind;

// 1 --a--> 2 --!a--> 1; step 1 emits w if b, step 2 emits z.
GrafcetBuilder assignment_model() {
  GrafcetBuilder b;
  b.input("a").input("b").output("w").output("z");
  b.chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, v("a")).transition({"2"}, {"1"}, not_(v("a")));
  b.continuous("1", "w", v("b")).continuous("2", "z");
  return b;
}

// Single change: states ({1},00) ({1},01) w ({2},10) z ({2},11) z, two toggles each.
TEST(GrafcetInputs, SingleInputChangeKeepsInputsInTheState) {
  const auto r = build_rsg(assignment_model().project());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 8u);
  const auto lines = rsg_lines(r);
  // Never both inputs at once: ({1},00) cannot reach ({2},11).
  EXPECT_EQ(std::find(lines.begin(), lines.end(), "{1} --[a & b]--> {2} z"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{1} --[!a & b]--> {1} w"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2} z --[!a & !b]--> {1}"), lines.end());
}

// Multi-change (the seed's primary RSG): inputs are not in the state (none is under an edge):
// A = {1}, B = {1} w, C = {2} z; A->C [a], A->B [!a & b], B->C [a], B->A [!a & !b],
// C->A [!a & !b], C->B [!a & b]: 3 states, 6 edges, conditions split only where they matter.
TEST(GrafcetInputs, MultiInputChangeEnumeratesFromTheReceptivities) {
  semantics::GrafcetOptions o;
  o.single_input_change = false;
  const auto r = build_rsg(assignment_model().project(), o);
  EXPECT_EQ(r.graph.num_states(), 3u);
  EXPECT_EQ(r.graph.num_edges(), 6u);
  EXPECT_EQ(rsg_lines(r),
            (std::vector<std::string>{"{1} --[!a & b]--> {1} w", "{1} --[a]--> {2} z",
                                      "{1} w --[!a & !b]--> {1}", "{1} w --[a]--> {2} z",
                                      "{2} z --[!a & !b]--> {1}", "{2} z --[!a & b]--> {1} w"}));
  ASSERT_EQ(r.graph.initial_states().size(), 3u);
}

// n : 0..9, 1 --n >= 5--> 2 --n < 3--> 1. Regions [0,2] [3,4] [5,9]; a change of n moves it to
// another region. States ({1},r0) ({1},r1) ({2},r2) ({2},r1), 8 edges.
TEST(GrafcetInputs, IntegerInputsAreAbstractedByTheirComparisons) {
  GrafcetBuilder b;
  b.input("n", model::Type::integer("INT(0..9)", 0, 9));
  b.chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, cmp(ExprKind::Ge, v("n"), num(5)));
  b.transition({"2"}, {"1"}, cmp(ExprKind::Lt, v("n"), num(3)));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.graph.num_states(), 4u);
  EXPECT_EQ(r.graph.num_edges(), 8u);
  const auto lines = rsg_lines(r);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2} --[n <= 2]--> {1}"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "{2} --[3 <= n <= 4]--> {2}"), lines.end());
}

// An integer input used as a Boolean is refused; compared with another input it keeps its
// exact value (GrafcetBdd.IntegerInputsComputedWithKeepTheirExactValues).
TEST(GrafcetInputs, IntegerInputUsedAsABooleanIsRejected) {
  GrafcetBuilder b;
  b.input("n", model::Type::integer("INT(0..9)", 0, 9)).input("a");
  b.chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, and_(v("a"), v("n")));
  model::Diagnostics d;
  EXPECT_EQ(semantics::make_grafcet_system(b.project(), {}, d), nullptr);
  ASSERT_FALSE(d.empty());
  EXPECT_NE(d.back().message.find("integer input 'n' used as a Boolean"), std::string::npos)
      << d.back().message;
}

// Unused inputs are not part of the system: they cannot change the RSG.
TEST(GrafcetInputs, UnusedInputsDoNotEnterTheState) {
  auto b = assignment_model();
  for (int i = 0; i < 20; ++i) b.input("unused" + std::to_string(i));
  const auto r = build_rsg(b.project());
  EXPECT_EQ(r.system->inputs().size(), 2u);
  EXPECT_EQ(r.graph.num_states(), 4u);
}

TEST(ConditionSimplifier, ProducesAnIrredundantSumOfProducts) {
  std::vector<semantics::InputVariable> in{
      {"a", model::Type::boolean()}, {"b", model::Type::boolean()}, {"c", model::Type::boolean()}};
  using semantics::InputCondition;
  using semantics::InputCube;
  auto cube = [](std::vector<std::pair<std::uint32_t, int>> l) {
    InputCube c;
    for (auto [i, val] : l) c.literals.push_back({i, val, val});
    return c;
  };
  // a&b | a&!b  ==  a
  InputCondition c1{{cube({{0, 1}, {1, 1}}), cube({{0, 1}, {1, 0}})}};
  EXPECT_EQ(engine::simplify(c1, in).to_string(in), "a");
  // a&b&c | a&b&!c | !a&b  ==  b
  InputCondition c2{
      {cube({{0, 1}, {1, 1}, {2, 1}}), cube({{0, 1}, {1, 1}, {2, 0}}), cube({{0, 0}, {1, 1}})}};
  EXPECT_EQ(engine::simplify(c2, in).to_string(in), "b");
  // a&!b | !a&b | a&b == a | b
  InputCondition c3{{cube({{0, 1}, {1, 0}}), cube({{0, 0}, {1, 1}}), cube({{0, 1}, {1, 1}})}};
  EXPECT_EQ(engine::simplify(c3, in).to_string(in), "a | b");
  // a | !a == TRUE; nothing == FALSE
  InputCondition c4{{cube({{0, 1}}), cube({{0, 0}})}};
  EXPECT_TRUE(engine::simplify(c4, in).is_true());
  EXPECT_TRUE(engine::simplify(InputCondition{}, in).is_false());
}

TEST(ConditionSimplifier, KeepsIntegerLiteralsAsAtoms) {
  std::vector<semantics::InputVariable> in{{"a", model::Type::boolean()},
                                           {"n", model::Type::integer("INT(0..9)", 0, 9)}};
  using semantics::InputCondition;
  using semantics::InputCube;
  // a & n in [3,4]  |  !a & n in [3,4]  ==  3 <= n <= 4
  InputCondition c{{InputCube{{{0, 1, 1}, {1, 3, 4}}}, InputCube{{{0, 0, 0}, {1, 3, 4}}}}};
  EXPECT_EQ(engine::simplify(c, in).to_string(in), "3 <= n <= 4");
  // Every valuation agrees before and after.
  const auto s = engine::simplify(c, in);
  for (std::int64_t a = 0; a <= 1; ++a)
    for (std::int64_t n = 0; n <= 9; ++n) EXPECT_EQ(c.holds({a, n}), s.holds({a, n}));
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// `sfcv simulate` on a Grafcet follows the valuation of its rows: the start of 48 charts
// `1 --aK--> 2` and one `1 --n >= 5--> 2 --n < 3--> 3` has 2^48 * 3 initial situations, and the
// simulation used to walk them all to pick the one of its first row (an AGRAFE production
// system with 45 inputs never answered). Now it splits on the row's regions only.
TEST(GrafcetInputs, SimulationFollowsItsRowsNotEveryInitialSituation) {
  constexpr int kCharts = 48;
  GrafcetBuilder b;
  for (int k = 0; k < kCharts; ++k) b.input("a" + std::to_string(k));
  b.input("n", model::Type::integer("INT(0..9)", 0, 9));
  for (int k = 0; k < kCharts; ++k) {
    const auto id = std::to_string(k);
    b.chart("G" + id).step("1" + id, true).step("2" + id);
    b.transition({"1" + id}, {"2" + id}, v("a" + id));
  }
  b.chart("H").step("h1", true).step("h2").step("h3");
  b.transition({"h1"}, {"h2"}, cmp(ExprKind::Ge, v("n"), num(5)));
  b.transition({"h2"}, {"h3"}, cmp(ExprKind::Lt, v("n"), num(3)));
  model::Diagnostics d;
  semantics::GrafcetOptions o;
  const auto ts = semantics::make_grafcet_system(b.project(), o, d);
  ASSERT_TRUE(ts);
  // Every aK true but a0, n = 7: the start stabilises in {10, 2K for K > 0, h2}; then a0 rises,
  // then n falls to 2 (h2 -> h3).
  std::vector<std::int64_t> row(ts->inputs().size(), 0);
  std::size_t a0 = 0, n = 0;
  for (std::size_t i = 0; i < row.size(); ++i) {
    const auto& name = ts->inputs()[i].name;
    if (name == "n") n = i;
    if (name == "a0") a0 = i;
    if (name.starts_with("a") && name != "a0") row[i] = 1;
  }
  row[n] = 7;
  auto rise = row;
  rise[a0] = 1;
  auto fall = rise;
  fall[n] = 2;
  const auto run = semantics::simulate_events(*ts, {row, rise, fall}, true);
  ASSERT_TRUE(run.ok) << run.error;
  ASSERT_EQ(run.states.size(), 3u);
  // "{10,21,...,h2}": the step names between '{' or ',' and ',' or '}'.
  const auto active = [&](std::size_t k, const std::string& step) {
    const auto text = ts->describe(run.states[k]);
    const auto end = text.find('}');
    std::string token;
    for (std::size_t i = text.find('{') + 1; i <= end; ++i) {
      if (text[i] == ',' || text[i] == '}') {
        if (token == step) return true;
        token.clear();
      } else {
        token += text[i];
      }
    }
    return false;
  };
  EXPECT_TRUE(active(0, "10"));
  EXPECT_TRUE(active(0, "247"));
  EXPECT_TRUE(active(0, "h2"));
  EXPECT_FALSE(active(0, "20"));
  EXPECT_TRUE(active(1, "20"));
  EXPECT_TRUE(active(1, "h2"));
  EXPECT_TRUE(active(2, "h3"));
}

}  // namespace
}  // namespace sfcv::test

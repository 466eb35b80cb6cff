// Each operator of the query language on the hand-built graph of query_test_support.hpp.

#include <gtest/gtest.h>

#include "logic/query_test_support.hpp"

namespace sfcv::test {
namespace {

using Edges = std::set<std::pair<std::uint32_t, std::uint32_t>>;
using States = std::set<std::uint32_t>;
using StepNames = std::set<std::string>;

class QueryOperators : public ::testing::Test {
 protected:
  QueryFixture f{make_query_toy()};
};

TEST_F(QueryOperators, Constants) {
  EXPECT_EQ(f.S("Y"), (States{0, 1, 2, 3, 4}));
  EXPECT_EQ(f.S("Y0"), (States{0}));
  EXPECT_EQ(f.E("T"), (Edges{{0, 1}, {1, 2}, {1, 3}, {2, 0}, {3, 4}}));
  EXPECT_EQ(f.St("Steps"), (StepNames{"X1", "X2", "X3"}));  // outputs are not steps
}

TEST_F(QueryOperators, UnionIntersectionDifference) {
  EXPECT_EQ(f.S("Act({X1}) + Act({X3})"), (States{0, 2, 3}));
  EXPECT_EQ(f.S("Act({X2}) * Act({X3})"), (States{3}));
  EXPECT_EQ(f.S("Y - Act({X2})"), (States{0, 2, 4}));
  EXPECT_EQ(f.E("T - Int(Y0)"), (Edges{{1, 2}, {1, 3}, {2, 0}, {3, 4}}));
  EXPECT_EQ(f.St("Steps - {X1}"), (StepNames{"X2", "X3"}));
  // Left-associative difference, * binds tighter than + and -.
  EXPECT_EQ(f.S("Y - Y0 - Act({X2})"), (States{2, 4}));
  EXPECT_EQ(f.S("Y0 + Y * Act({X3})"), (States{0, 2, 3}));
  EXPECT_EQ(f.S("Y + {}"), (States{0, 1, 2, 3, 4}));
}

TEST_F(QueryOperators, IntAndExtFollowTheUpstreamAndDownstreamSituation) {
  // semantics-notes item 9: Int(Y) upstream in Y, Ext(Y) downstream in Y.
  EXPECT_EQ(f.E("Int(Act({X2}))"), (Edges{{1, 2}, {1, 3}, {3, 4}}));
  EXPECT_EQ(f.E("Ext(Act({X2}))"), (Edges{{0, 1}, {1, 3}}));
  EXPECT_EQ(f.E("Ext(Y0)"), (Edges{{2, 0}}));
  EXPECT_EQ(f.E("Int({})"), Edges{});
}

TEST_F(QueryOperators, AmontAndAvalAndTheirAliases) {
  EXPECT_EQ(f.S("Amont(T)"), (States{0, 1, 2, 3}));
  EXPECT_EQ(f.S("Aval(Int(Y0))"), (States{1}));
  EXPECT_EQ(f.S("Upstream(Ext(Y0))"), (States{2}));
  EXPECT_EQ(f.S("Downstream(Ext(Y0))"), (States{0}));
  EXPECT_EQ(f.S("Aval(T)"), (States{0, 1, 2, 3, 4}));
}

TEST_F(QueryOperators, SuccAndPredIncludeTheStartSet) {
  EXPECT_EQ(f.S("Succ(Y0, {})"), (States{0}));
  EXPECT_EQ(f.S("Pred(Y0, {})"), (States{0}));
  EXPECT_EQ(f.S("Succ(Y0, T)"), (States{0, 1, 2, 3, 4}));
  EXPECT_EQ(f.S("Pred(Y0, T)"), (States{0, 1, 2}));
  EXPECT_EQ(f.S("Succ(Y0, Nec(a))"), (States{0, 1, 3}));
  EXPECT_EQ(f.S("Pred(Act({X3}) - Act({X2}), T)"), (States{0, 1, 2}));
  EXPECT_EQ(f.S("Pred(Y - Amont(T), T - Nec(b))"), (States{4}));
  EXPECT_EQ(f.S("Pred(Y - Amont(T), T)"), (States{0, 1, 2, 3, 4}));
}

TEST_F(QueryOperators, ActAndDes) {
  EXPECT_EQ(f.S("Act({X2, X3})"), (States{3}));
  EXPECT_EQ(f.S("Des({X1, X2})"), (States{2, 4}));
  EXPECT_EQ(f.S("Act(X2)"), (States{1, 3}));           // one step without braces
  EXPECT_EQ(f.S("Act({})"), (States{0, 1, 2, 3, 4}));  // vacuous
  EXPECT_EQ(f.S("Des(Steps)"), (States{4}));
  EXPECT_EQ(f.S("Act(Steps - {X1})"), (States{3}));
}

TEST_F(QueryOperators, NecIsImplicationOfTheEvolutionCondition) {
  EXPECT_EQ(f.E("Nec(a)"), (Edges{{0, 1}, {1, 3}}));
  EXPECT_EQ(f.E("Nec(!b)"), (Edges{{1, 3}}));
  EXPECT_EQ(f.E("Nec(!a)"), (Edges{{2, 0}}));
  EXPECT_EQ(f.E("Nec(a | b)"), (Edges{{0, 1}, {1, 2}, {1, 3}, {3, 4}}));
  EXPECT_EQ(f.E("Nec(a & !b)"), (Edges{{1, 3}}));
  EXPECT_EQ(f.E("Nec(TRUE)"), (Edges{{0, 1}, {1, 2}, {1, 3}, {2, 0}, {3, 4}}));
  EXPECT_EQ(f.E("Nec(FALSE)"), Edges{});
  // Step and output names inside Nec are read in the upstream situation.
  EXPECT_EQ(f.E("Nec(b & O1)"), (Edges{{1, 2}, {3, 4}}));
}

TEST_F(QueryOperators, Emis) {
  EXPECT_EQ(f.S("Emis(O1 & O2)"), (States{3}));
  EXPECT_EQ(f.S("Emis(O1 | X1)"), (States{0, 1, 3}));
  EXPECT_EQ(f.S("Emis(!O1)"), (States{0, 2, 4}));
  EXPECT_EQ(f.S("Emis(O1 = O2)"), (States{0, 3, 4}));
  EXPECT_EQ(f.S("Emis(O1 != O2)"), (States{1, 2}));
}

TEST_F(QueryOperators, TestsAndCounts) {
  EXPECT_TRUE(f.B("Y - Amont(T) != {}"));
  EXPECT_FALSE(f.B("Y - Amont(T) = {}"));
  EXPECT_TRUE(f.B("{} = Emis(O1 & !O1)"));
  EXPECT_TRUE(f.B("Act({X2}) * Act({X3}) = Emis(O1 & O2)"));
  EXPECT_TRUE(f.B("Y0 = {} | #T = 5"));
  EXPECT_FALSE(f.B("Y0 = {} & #T = 5"));
  EXPECT_TRUE(f.B("!(Y0 = {})"));
  auto r = f.run("#Y");
  EXPECT_EQ(r.sort, logic::Sort::Int);
  EXPECT_EQ(r.number, 5);
  EXPECT_TRUE(f.B("#Pred(Y0, T) < #Y"));
  // The witnesses of an emptiness test are the set tested.
  r = f.run("Y - Pred(Y0, T) = {}");
  EXPECT_FALSE(r.truth);
  ASSERT_TRUE(r.witness_sort.has_value());
  EXPECT_EQ(*r.witness_sort, logic::Sort::States);
  EXPECT_EQ(f.states(r.witness), (States{3, 4}));
}

TEST_F(QueryOperators, LetBindings) {
  EXPECT_EQ(f.S("let dead = Y - Amont(T); Pred(dead, T) - dead"), (States{0, 1, 2, 3}));
  EXPECT_EQ(f.S("let o = O1 & O2; Emis(o)"), (States{3}));  // bound expressions are closures
  EXPECT_EQ(f.S("let a = Y0; let b = Aval(Int(a)); a + b"), (States{0, 1}));
  // An inner let shadows an outer one.
  EXPECT_EQ(f.S("let a = Y0; let a = Act({X3}); a"), (States{2, 3}));
}

TEST_F(QueryOperators, SetBuilderLocalDeadlock) {
  // Seed 002's local dead-lock: steps that, from some situation, can never change state again.
  const std::string local =
      "{e in Steps | (Act({e}) - Pred(Des({e}), T)) + (Des({e}) - Pred(Act({e}), T)) != {}}";
  EXPECT_EQ(f.St(local), (StepNames{"X1", "X2", "X3"}));  // all are stuck once in state 4
  EXPECT_EQ(f.St("{e | Act({e}) * Y0 != {}}"), (StepNames{"X1"}));
  EXPECT_EQ(f.St("{e in Steps - {X1} | #Act(e) = 2}"), (StepNames{"X2", "X3"}));
  EXPECT_EQ(f.St("{e | Emis(e & O2) != {}}"), (StepNames{"X2", "X3"}));
  // Nested builders see both variables.
  EXPECT_EQ(f.St("{e | {g | Act({e, g}) != {} } = {e}}"), (StepNames{"X1"}));
}

TEST(QueryClearing, TclearIsTheEvolutionsThatFireATransition) {
  // 0 -[t0]-> 1, then 1 and 2 exchange without clearing anything (input events).
  ToySystem ts(3, {"a"}, {"X1", "X2"});
  ts.set_true(0, 0);
  ts.set_true(1, 1);
  ts.set_true(2, 1);
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(1, 2, ToySystem::lit(0, false));
  ts.add_arc(2, 1, ToySystem::lit(0, true));
  QueryFixture f{std::move(ts)};
  using E = std::set<std::pair<std::uint32_t, std::uint32_t>>;
  EXPECT_EQ(f.E("Tclear"), (E{{0, 1}}));
  EXPECT_EQ(f.E("T - Tclear"), (E{{1, 2}, {2, 1}}));
  EXPECT_EQ(f.S("Y - Amont(T)"), States{});
  EXPECT_EQ(f.S("Y - Pred(Amont(Tclear), T)"), (States{1, 2}));
  f.library().add_file(std::string(SFCV_SOURCE_DIR) + "/share/sfcv/properties.sfq");
  EXPECT_EQ(f.S("global_deadlock()"), (States{1, 2}));
  EXPECT_EQ(f.S("no_successor()"), States{});
}

TEST(QueryLocalDeadlock, EmptyOnAFreeCycle) {
  ToySystem ts(2, {"a"}, {"X1", "X2"});
  ts.set_true(0, 0);
  ts.set_true(1, 1);
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true));
  ts.add_arc(1, 0, ToySystem::lit(0, false));
  QueryFixture f{std::move(ts)};
  EXPECT_EQ(f.St("{e | (Act({e}) - Pred(Des({e}), T)) + (Des({e}) - Pred(Act({e}), T)) != {}}"),
            StepNames{});
  EXPECT_EQ(f.S("Y - Amont(T)"), States{});
  EXPECT_EQ(f.S("Y - Pred(Y0, T)"), States{});
}

TEST(QueryNec, IntegerInputsAreSplitAtTheirConstants) {
  ToySystem ts(4, {"n"}, {"X0", "X1", "X2", "X3"});
  ts.set_input_type(0, model::Type::integer("INT", 0, 10));
  for (std::uint32_t s = 0; s < 4; ++s) ts.set_true(s, s);
  ts.set_initial({0});
  ts.add_arc(0, 1, cube({{0, 3, 5}}));
  ts.add_arc(0, 2, cube({{0, 6, 10}}));
  ts.add_arc(0, 3, cube({{0, 0, 2}}));
  ts.add_arc(1, 0);  // free input: n anywhere in 0..10
  QueryFixture f{std::move(ts)};
  using E = std::set<std::pair<std::uint32_t, std::uint32_t>>;
  EXPECT_EQ(f.E("Nec(n >= 3)"), (E{{0, 1}, {0, 2}}));
  EXPECT_EQ(f.E("Nec(n > 5)"), (E{{0, 2}}));
  EXPECT_EQ(f.E("Nec(5 < n)"), (E{{0, 2}}));  // constant on the left
  EXPECT_EQ(f.E("Nec(n != 4)"), (E{{0, 2}, {0, 3}}));
  EXPECT_EQ(f.E("Nec(n < 3 | n > 5)"), (E{{0, 2}, {0, 3}}));
  EXPECT_EQ(f.E("Nec(n <= 10)"), (E{{0, 1}, {0, 2}, {0, 3}, {1, 0}}));
  EXPECT_EQ(f.E("Nec(n = 4)"), E{});
}

}  // namespace
}  // namespace sfcv::test

#include "engine/explicit/ctl_checker.hpp"

#include <gtest/gtest.h>

#include "logic/formula.hpp"
#include "logic/parser.hpp"
#include "logic/push_negation.hpp"
#include "logic/resolve.hpp"
#include "support/toy_system.hpp"

namespace sfcv::engine {
namespace {

using logic::Verdict;
using test::ToySystem;

logic::FormulaPtr formula(const ToySystem& ts, const std::string& text) {
  auto parsed = logic::parse_formula(text);
  EXPECT_TRUE(parsed.ok()) << text;
  auto r = logic::resolve(parsed.formula, ts, "test");
  EXPECT_TRUE(r.formula) << text;
  return r.formula;
}

struct Run {
  logic::PropertyResult result;
  std::vector<std::uint32_t> toy_states;  ///< the trace's states as toy state numbers
};

Run check(const ToySystem& ts, const std::string& text, std::vector<std::string> fair = {},
          ExplorationOptions opts = {}) {
  const auto g = build_reachable_situation_graph(ts, opts);
  std::vector<logic::FormulaPtr> fairness;
  for (const auto& f : fair) fairness.push_back(formula(ts, f));
  CtlChecker checker(g, fairness);
  Run run;
  run.result = checker.check(logic::Property{"p", formula(ts, text), {}});
  if (run.result.trace)
    for (const auto& s : run.result.trace->steps) run.toy_states.push_back(ts.state_of(s.state));
  return run;
}

Verdict verdict(const ToySystem& ts, const std::string& text, std::vector<std::string> fair = {}) {
  return check(ts, text, std::move(fair)).result.verdict;
}

using States = std::vector<std::uint32_t>;

// 0 -> 1 (p), 0 -> 2.
TEST(CtlChecker, NextOperators) {
  ToySystem ts(3, {}, {"p", "q"});
  ts.set_initial({0});
  ts.add_arc(0, 1);
  ts.add_arc(0, 2);
  ts.add_arc(1, 1);
  ts.add_arc(2, 2);
  ts.set_true(1, 0);
  EXPECT_EQ(verdict(ts, "EX p"), Verdict::Holds);
  EXPECT_EQ(check(ts, "EX p").toy_states, (States{0, 1}));
  EXPECT_EQ(verdict(ts, "AX p"), Verdict::Violated);
  EXPECT_EQ(check(ts, "AX p").toy_states, (States{0, 2}));
  EXPECT_EQ(verdict(ts, "AX (p | !p)"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "EX EX p"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AX AX !q"), Verdict::Holds);
}

// 0 -> 1 -> 2 (p) -> 2; 0 -> 3 -> 3.
ToySystem chain() {
  ToySystem ts(4, {"go"}, {"p"});
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(0, 3, ToySystem::lit(0, false), {1});
  ts.add_arc(1, 2, semantics::InputCondition::always(), {2});
  ts.add_arc(2, 2);
  ts.add_arc(3, 3);
  ts.set_true(2, 0);
  return ts;
}

TEST(CtlChecker, FinallyAndGloballyWithShortestTraces) {
  const auto ts = chain();
  EXPECT_EQ(verdict(ts, "EF p"), Verdict::Holds);
  const auto ef = check(ts, "EF p");
  EXPECT_EQ(ef.toy_states, (States{0, 1, 2}));
  EXPECT_EQ(ef.result.trace->kind, logic::TraceKind::Witness);
  const auto ag = check(ts, "AG !p");
  EXPECT_EQ(ag.result.verdict, Verdict::Violated);
  EXPECT_EQ(ag.toy_states, (States{0, 1, 2}));
  EXPECT_EQ(ag.result.trace->kind, logic::TraceKind::Counterexample);
  // The inputs of the trace: go = 1 to take 0 -> 1; fired transitions recorded.
  ASSERT_EQ(ag.result.trace->steps.size(), 3u);
  EXPECT_EQ(ag.result.trace->steps[1].inputs, (std::vector<std::int64_t>{1}));
  EXPECT_EQ(ag.result.trace->steps[1].fired, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(ag.result.trace->marked, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(verdict(ts, "AF p"), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "AG (p -> AG p)"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "EG !p"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AG EF p"), Verdict::Violated);
  // Nested counterexample: the run reaches 3, from where p is unreachable.
  EXPECT_EQ(check(ts, "AG EF p").toy_states, (States{0, 3}));
}

TEST(CtlChecker, LassoForAfAndEg) {
  // 0 (p) loops on itself or moves to 1 (q) which loops.
  ToySystem ts(2, {"a"}, {"p", "q"});
  ts.set_initial({0});
  ts.add_arc(0, 0, ToySystem::lit(0, false));
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(1, 1);
  ts.set_true(0, 0);
  ts.set_true(1, 1);
  const auto af = check(ts, "AF q");
  EXPECT_EQ(af.result.verdict, Verdict::Violated);
  ASSERT_TRUE(af.result.trace->loop_start);
  EXPECT_EQ(*af.result.trace->loop_start, 0u);
  EXPECT_EQ(af.toy_states, (States{0, 0}));
  EXPECT_EQ(af.result.trace->steps[1].inputs, (std::vector<std::int64_t>{0}));
  const auto eg = check(ts, "EG p");
  EXPECT_EQ(eg.result.verdict, Verdict::Holds);
  ASSERT_TRUE(eg.result.trace && eg.result.trace->loop_start);
  EXPECT_EQ(verdict(ts, "EG q"), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "EF EG q"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AG (q -> AG q)"), Verdict::Holds);
}

TEST(CtlChecker, UntilOperators) {
  // 0 (p) -> 1 (p) -> 2 (q); 1 -> 3 (neither) once branch is enabled.
  ToySystem ts(4, {}, {"p", "q"});
  ts.set_initial({0});
  ts.add_arc(0, 1);
  ts.add_arc(1, 2);
  ts.add_arc(2, 2);
  ts.add_arc(3, 3);
  ts.set_true(0, 0);
  ts.set_true(1, 0);
  ts.set_true(2, 1);
  EXPECT_EQ(verdict(ts, "A[p U q]"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "E[p U q]"), Verdict::Holds);
  EXPECT_EQ(check(ts, "E[p U q]").toy_states, (States{0, 1, 2}));
  EXPECT_EQ(verdict(ts, "E[q U p]"), Verdict::Holds);  // p holds at once
  EXPECT_EQ(verdict(ts, "A[q U p]"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "E[!p U q]"), Verdict::Violated);
  ts.add_arc(1, 3);
  EXPECT_EQ(verdict(ts, "A[p U q]"), Verdict::Violated);
  EXPECT_EQ(check(ts, "A[p U q]").toy_states, (States{0, 1, 3}));
  EXPECT_EQ(verdict(ts, "E[p U q]"), Verdict::Holds);
}

TEST(CtlChecker, FairnessRestrictsPathQuantifiers) {
  // 0 idle, 1 busy (b), 2 done (q): 0->0, 0->1, 1->0, 1->2, 2->0.
  ToySystem ts(3, {"x"}, {"b", "q"});
  ts.set_initial({0});
  ts.add_arc(0, 0, ToySystem::lit(0, false));
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(1, 0, ToySystem::lit(0, false), {1});
  ts.add_arc(1, 2, ToySystem::lit(0, true), {2});
  ts.add_arc(2, 0, semantics::InputCondition::always(), {3});
  ts.set_true(1, 0);
  ts.set_true(2, 1);
  EXPECT_EQ(verdict(ts, "AG AF q"), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "AG EF q"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AG AF q", {"b"}), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "AG AF q", {"q"}), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AG AF b", {"b"}), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "EG !q", {"b"}), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "EG !q", {"q"}), Verdict::Violated);
  // The fair lasso visits b on its loop.
  const auto eg = check(ts, "EG !q", {"b"});
  ASSERT_TRUE(eg.result.trace && eg.result.trace->loop_start);
  bool visits_b = false;
  for (std::size_t i = *eg.result.trace->loop_start; i < eg.toy_states.size(); ++i)
    visits_b |= eg.toy_states[i] == 1;
  EXPECT_TRUE(visits_b);
  // Two fairness constraints: the loop must visit both.
  const auto both = check(ts, "EG TRUE", {"b", "q"});
  ASSERT_TRUE(both.result.trace && both.result.trace->loop_start);
  bool sees_q = false;
  for (std::size_t i = *both.result.trace->loop_start; i < both.toy_states.size(); ++i)
    sees_q |= both.toy_states[i] == 2;
  EXPECT_TRUE(sees_q);
  // Fair EX / EF: the target must be a fair state. Under "fair q" the state 0 has fair runs.
  EXPECT_EQ(verdict(ts, "EX b", {"q"}), Verdict::Holds);
}

TEST(CtlChecker, DeadlockStatesEndMaximalPaths) {
  // 0 -> 1 (p), and 1 has no successor.
  ToySystem ts(2, {}, {"p"});
  ts.set_initial({0});
  ts.add_arc(0, 1);
  ts.set_true(1, 0);
  EXPECT_EQ(verdict(ts, "AF p"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "EG !p"), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "EG TRUE"), Verdict::Holds);
  const auto eg = check(ts, "EG TRUE");
  ASSERT_TRUE(eg.result.trace);
  EXPECT_TRUE(eg.result.trace->ends_in_deadlock);
  EXPECT_EQ(verdict(ts, "AG EX TRUE"), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "AX AX FALSE"), Verdict::Holds);  // vacuous at the deadlock
  // Under fairness a deadlock has no fair path: A-formulas hold vacuously there.
  EXPECT_EQ(verdict(ts, "AF FALSE", {"TRUE"}), Verdict::Holds);
}

TEST(CtlChecker, IncompleteGraphIsUnknownUnlessDecidedByAReachableState) {
  // A long chain: 0 -> 1 -> ... -> 99 -> 99, p at 3, q at 99.
  ToySystem ts(100, {}, {"p", "q"});
  ts.set_initial({0});
  for (std::uint32_t s = 0; s + 1 < 100; ++s) ts.add_arc(s, s + 1);
  ts.add_arc(99, 99);
  ts.set_true(3, 0);
  ts.set_true(99, 1);
  ExplorationOptions opts;
  opts.max_states = 10;
  EXPECT_EQ(check(ts, "AG !p", {}, opts).result.verdict, Verdict::Violated);
  EXPECT_EQ(check(ts, "AG !p", {}, opts).toy_states, (States{0, 1, 2, 3}));
  EXPECT_EQ(check(ts, "EF p", {}, opts).result.verdict, Verdict::Holds);
  EXPECT_EQ(check(ts, "AG !q", {}, opts).result.verdict, Verdict::Unknown);
  EXPECT_EQ(check(ts, "EF q", {}, opts).result.verdict, Verdict::Unknown);
  EXPECT_EQ(check(ts, "AF p", {}, opts).result.verdict, Verdict::Unknown);
  EXPECT_NE(check(ts, "AF p", {}, opts).result.message.find("states limit"), std::string::npos);
  // Complete: the answers are definite.
  EXPECT_EQ(verdict(ts, "AG !q"), Verdict::Violated);
  EXPECT_EQ(verdict(ts, "AF q"), Verdict::Holds);
}

TEST(CtlChecker, BooleanConnectivesAndComparisons) {
  ToySystem ts(2, {}, {"p", "q"});
  ts.set_initial({0});
  ts.add_arc(0, 1);
  ts.add_arc(1, 0);
  ts.set_true(0, 0);
  EXPECT_EQ(verdict(ts, "p xor q"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "p <-> !q"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "q -> FALSE"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "p = 1 & q != 1"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AG (p | AX p)"), Verdict::Holds);
  EXPECT_EQ(verdict(ts, "AG p"), Verdict::Violated);
}

TEST(PushNegation, DualsOfTemporalOperators) {
  auto f = logic::parse_formula("A[p U q]").formula;
  EXPECT_EQ(logic::to_string(logic::push_negation(f)), "E[!q U !p & !q] | EG !q");
  EXPECT_EQ(logic::to_string(logic::push_negation(logic::parse_formula("AG p").formula)), "EF !p");
  EXPECT_EQ(logic::to_string(logic::push_negation(logic::parse_formula("AF p").formula)), "EG !p");
}

}  // namespace
}  // namespace sfcv::engine

// model::validate: each check on a model that violates it and on one that does not.

#include "model/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "model/networks.hpp"
#include "support/model_builder.hpp"

namespace sfcv::model {
namespace {

using test::PouBuilder;

std::string dump(const Diagnostics& ds) {
  std::string s;
  for (const auto& d : ds) s += d.str() + "\n";
  return s;
}

std::size_t count(const Diagnostics& ds, Severity sev) {
  return static_cast<std::size_t>(
      std::count_if(ds.begin(), ds.end(), [&](const Diagnostic& d) { return d.severity == sev; }));
}

/// The diagnostics of severity `sev` on `line` whose message contains `text`.
std::size_t count_at(const Diagnostics& ds, Severity sev, int line, const std::string& text) {
  return static_cast<std::size_t>(std::count_if(ds.begin(), ds.end(), [&](const Diagnostic& d) {
    return d.severity == sev && d.where.line == line && d.message.find(text) != std::string::npos;
  }));
}

#define EXPECT_CLEAN(ds) EXPECT_TRUE((ds).empty()) << dump(ds)

/// A two-step loop S0 -> S1 -> S0: the smallest valid chart.
PouBuilder loop() {
  PouBuilder b;
  b.input("go", "BOOL").chart("main").initial("S0").step("S1");
  b.trans({"S0"}, {"S1"}, make_name("go"))
      .trans({"S1"}, {"S0"}, make_unary(ExprKind::Not, make_name("go")));
  return b;
}

TEST(Validate, ValidLoopIsClean) {
  EXPECT_CLEAN(validate(loop().project()));
}

// ------------------------------------------------------------------------------------ names

TEST(Validate, DuplicateStepIsLocatedAtTheRepetition) {
  auto b = loop();
  const int dup = b.line();
  b.step("s1");  // case-insensitive repetition of S1
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, dup, "duplicate step 's1'"), 1u) << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 1u) << dump(ds);
  EXPECT_NE(dump(ds).find("first declared at line"), std::string::npos) << dump(ds);
}

TEST(Validate, SameStepNameInTwoChartsIsFine) {
  auto b = loop();
  b.action_chart("Sub", 1).chart("sub", "Sub").initial("S0").trans({"S0"}, {"S0"});
  b.assoc("main", "S1", "Sub");
  EXPECT_CLEAN(validate(b.project()));
}

TEST(Validate, DuplicateTransitionName) {
  PouBuilder b;
  b.chart("main").initial("A").step("B");
  b.trans({"A"}, {"B"}, nullptr, "T1");
  const int dup = b.line();
  b.trans({"B"}, {"A"}, nullptr, "t1");
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, dup, "duplicate transition 't1'"), 1u) << dump(ds);

  PouBuilder ok;
  ok.chart("main").initial("A").step("B");
  ok.trans({"A"}, {"B"}, nullptr, "T1").trans({"B"}, {"A"}, nullptr, "T2");
  EXPECT_CLEAN(validate(ok.project()));
}

TEST(Validate, DuplicateVariableAndAction) {
  auto b = loop();
  const int var_line = b.line();
  b.var("GO", "INT");
  b.action_st("A", {});
  const int act_line = b.line();
  b.action_st("a", {});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, var_line, "duplicate variable 'GO'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, act_line, "duplicate action 'a'"), 1u) << dump(ds);
}

TEST(Validate, UndeclaredStepIsOneErrorAtItsFirstReference) {
  PouBuilder b;
  b.chart("main").initial("A");
  const int t1 = b.line();
  b.trans({"A"}, {"B", "B"});  // B named twice
  const int t2 = b.line();
  b.trans({"b"}, {"C"});  // and again, in another case
  const int t3 = b.line();
  b.trans({"C"}, {"A"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, t1,
                     "transition to undeclared step 'B' (also named by the "
                     "transition at line " +
                         std::to_string(t2) + ":1)"),
            1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, t2,
                     "transition to undeclared step 'C' (also named by the transition at line " +
                         std::to_string(t3) + ":1)"),
            1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 2u) << dump(ds);
}

// --------------------------------------------------------------------------- initial steps

TEST(Validate, ChartWithoutInitialStepIsAnError) {
  PouBuilder b;
  b.input("go", "BOOL");
  const int chart_line = b.line();
  b.chart("main").step("A").step("B").trans({"A"}, {"B"}, make_name("go"));
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, chart_line, "has no initial step"), 1u) << dump(ds);
}

TEST(Validate, SeveralNetworksEachWithItsInitialStepAreFine) {
  PouBuilder b;
  b.chart("main").initial("A").step("B").initial("C").step("D");
  b.trans({"A"}, {"B"}).trans({"B"}, {"A"}).trans({"C"}, {"D"}).trans({"D"}, {"C"});
  EXPECT_CLEAN(validate(b.project()));
  EXPECT_EQ(count_networks(b.project().pous[0].charts[0]), 2u);
}

TEST(Validate, TwoInitialStepsInOneIecNetworkIsAnError) {
  PouBuilder b;
  b.chart("main").initial("A");
  const int second = b.line();
  b.initial("B").trans({"A"}, {"B"}).trans({"B"}, {"A"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, second, "second initial step 'B'"), 1u) << dump(ds);
  // Grafcet: an initial situation of several steps is ordinary.
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));
}

TEST(Validate, GrafcetEnclosedChartMayStartEmpty) {
  PouBuilder b;
  b.chart("G0").enclosing_step("E", {"G1"}, true).step("F").trans({"E"}, {"F"}).trans({"F"}, {"E"});
  b.chart("G1").step("10").linked().step("11").trans({"10"}, {"11"}).trans({"11"}, {"10"});
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));

  PouBuilder lonely;
  lonely.chart("G0").initial("1").trans({"1"}, {"1"});
  const int g1 = lonely.line();
  lonely.chart("G1").step("10").trans({"10"}, {"10"});
  const auto ds = validate(lonely.project(Dialect::Grafcet));
  EXPECT_EQ(count_at(ds, Severity::Error, g1, "chart 'G1' has no initial step"), 1u) << dump(ds);
}

// An enclosed grafcet without an activation-linked step is entered at its initial steps
// (docs/semantics.md 2.12): a warning at the enclosing step naming both; none with a link.
TEST(Validate, GrafcetEnclosedChartWithoutLinkedStepIsAWarning) {
  PouBuilder b;
  b.chart("G0").initial("1");
  const int enclosing = b.line();
  b.enclosing_step("2", {"G1", "G2"}).trans({"1"}, {"2"}).trans({"2"}, {"1"});
  b.chart("G1").initial("10").step("11").trans({"10"}, {"11"}).trans({"11"}, {"10"});
  b.chart("G2").step("20").trans({"20"}, {"20"});
  const auto ds = validate(b.project(Dialect::Grafcet));
  EXPECT_EQ(count(ds, Severity::Error), 0u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, enclosing,
                     "partial grafcet 'G1' enclosed by step '2' has no activation-linked step"),
            1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, enclosing, "its initial steps are activated with '2'"),
            1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, enclosing, "no step of it is activated with '2'"), 1u)
      << dump(ds);

  PouBuilder ok;
  ok.chart("G0").initial("1").enclosing_step("2", {"G1"}).trans({"1"}, {"2"}).trans({"2"}, {"1"});
  ok.chart("G1").initial("10").step("11").linked().trans({"10"}, {"11"}).trans({"11"}, {"10"});
  EXPECT_CLEAN(validate(ok.project(Dialect::Grafcet)));
}

// ----------------------------------------------------------------------------- reachability

TEST(Validate, UnreachableStepIsAWarning) {
  auto b = loop();
  const int lonely = b.line();
  b.step("Lonely");
  const int after = b.line();
  b.step("After").trans({"Lonely"}, {"After"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count(ds, Severity::Error), 0u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, lonely, "step 'Lonely' is unreachable"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, after, "step 'After' is unreachable"), 1u) << dump(ds);
}

TEST(Validate, ConvergenceNeedsAllItsSourcesReachable) {
  // B is reachable, C is not: the convergence (B, C) -> D never fires, so D is unreachable.
  PouBuilder b;
  b.chart("main").initial("A").step("B").step("C");
  const int d = b.line();
  b.step("D").trans({"A"}, {"B"}).trans({"B", "C"}, {"D"});
  const auto ds = validate(b.project(Dialect::Grafcet));
  EXPECT_EQ(count_at(ds, Severity::Warning, d, "step 'D' is unreachable"), 1u) << dump(ds);
}

TEST(Validate, GrafcetSourceAndSinkTransitions) {
  PouBuilder b;
  b.input("a", "BOOL").chart("G0").initial("1").step("2");
  const int source = b.line();
  b.trans({}, {"2"}, make_unary(ExprKind::Rising, make_name("a")));  // source transition
  const int sink = b.line();
  b.trans({"2"}, {}, make_name("a"));  // sink transition
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, source, "transition has no source step"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, sink, "transition has no target step"), 1u) << dump(ds);
}

TEST(Validate, GrafcetForcingSituationSeedsReachability) {
  PouBuilder b;
  b.chart("G0").initial("1").step("2").trans({"1"}, {"2"}).trans({"2"}, {"1"});
  b.chart("G1").initial("10").step("11").step("12").trans({"10"}, {"11"}).trans({"11"}, {"10"});
  b.forcing("G0", "2", "G1", {"12"});
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));
}

// ------------------------------------------------------------------------ parallel structure

/// S0 -> fork (A1, B1); A1 -> A2; (A2, B1) -> join S0.
PouBuilder fork_join() {
  PouBuilder b;
  b.chart("main").initial("S0").step("A1").step("A2").step("B1");
  b.trans({"S0"}, {"A1", "B1"}, nullptr, "fork").trans({"A1"}, {"A2"});
  b.trans({"A2", "B1"}, {"S0"}, nullptr, "join");
  return b;
}

TEST(Validate, WellFormedParallelStructureIsClean) {
  EXPECT_CLEAN(validate(fork_join().project()));

  // Nested divergence inside a branch, a loop inside a branch, a selection inside a branch.
  PouBuilder b;
  b.chart("main").initial("S0").step("A").step("B").step("A1").step("A2").step("A3").step("J");
  b.trans({"S0"}, {"A", "B"});
  b.trans({"A"}, {"A1", "A2"});
  b.trans({"A1"}, {"A3"}).trans({"A1"}, {"A1"});  // selection: loop or go on
  b.trans({"A3", "A2"}, {"J"});
  b.trans({"J", "B"}, {"S0"});
  EXPECT_CLEAN(validate(b.project()));
}

TEST(Validate, JumpOutOfAParallelBranch) {
  auto b = fork_join();
  const int jump = b.line();
  b.trans({"A1"}, {"S0"});  // leaves branch 1 for the step before the divergence
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, jump, "jump out of a parallel branch"), 1u) << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 1u) << dump(ds);
}

TEST(Validate, JumpBetweenParallelBranches) {
  auto b = fork_join();
  const int jump = b.line();
  b.trans({"A1"}, {"B1"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, jump, "different parallel branches"), 1u) << dump(ds);
}

TEST(Validate, ConvergenceOfDifferentDivergences) {
  // Two forks; the join takes one branch of each.
  PouBuilder b;
  b.chart("main").initial("S0").step("A").step("B").step("C").step("D").step("E").step("J");
  b.trans({"S0"}, {"A", "B"});
  b.trans({"A"}, {"C", "D"});
  const int join = b.line();
  b.trans({"C", "B"}, {"J"});
  b.trans({"D"}, {"E"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, join, "not branches of one simultaneous divergence"), 1u)
      << dump(ds);
}

TEST(Validate, ConvergenceOfASelection) {
  // Alternative branches joined by a simultaneous convergence: waits forever.
  PouBuilder b;
  b.input("x", "BOOL").chart("main").initial("S0").step("A").step("B").step("J");
  b.trans({"S0"}, {"A"}, make_name("x"))
      .trans({"S0"}, {"B"}, make_unary(ExprKind::Not, make_name("x")));
  const int join = b.line();
  b.trans({"A", "B"}, {"J"}).trans({"J"}, {"S0"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, join, "simultaneous convergence"), 1u) << dump(ds);
}

TEST(Validate, ConvergenceOfSomeBranchesOnly) {
  PouBuilder b;
  b.chart("main").initial("S0").step("A").step("B").step("C").step("J");
  b.trans({"S0"}, {"A", "B", "C"});
  const int join = b.line();
  b.trans({"A", "B"}, {"J"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, join, "joins 2 of the 3 branches"), 1u) << dump(ds);
}

TEST(Validate, DivergenceIntoAStepOutsideTheBranch) {
  // S0 -> A; A forks into (B, S0): S0 would hold a second token.
  PouBuilder b;
  b.chart("main").initial("S0").step("A").step("B");
  b.trans({"S0"}, {"A"});
  const int fork = b.line();
  b.trans({"A"}, {"B", "S0"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, fork, "simultaneous divergence into step 'S0'"), 1u)
      << dump(ds);
}

TEST(Validate, ConvergenceOfStepsOutsideAnyBranch) {
  PouBuilder b;
  b.chart("main").initial("S0").step("A").trans({"S0"}, {"A"});
  const int join = b.line();
  b.trans({"S0", "A"}, {"S0"});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, join,
                     "joins steps 'S0' and 'A', which are not parallel branches"),
            1u)
      << dump(ds);
}

TEST(Validate, GrafcetIsNotHeldToTheIecParallelRule) {
  auto b = fork_join();
  b.trans({"A1"}, {"S0"});
  EXPECT_EQ(count(validate(b.project(Dialect::Grafcet)), Severity::Error), 0u);
}

// --------------------------------------------------------------------------------- hierarchy

TEST(Validate, HierarchyCycleThroughNestedCharts) {
  // main -S1-> Outer's chart -I0-> Inner's chart -J0-> Outer again.
  auto b = loop();
  b.action_chart("Outer", 1).action_chart("Inner", 2);
  b.chart("outer", "Outer").initial("I0").trans({"I0"}, {"I0"});
  b.chart("inner", "Inner").initial("J0").trans({"J0"}, {"J0"});
  b.assoc("main", "S1", "Outer").assoc("outer", "I0", "Inner");
  EXPECT_CLEAN(validate(b.project()));
  const int back = b.line();
  b.assoc("inner", "J0", "outer");  // action names are case-insensitive
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, back, "hierarchy cycle"), 1u) << dump(ds);
  EXPECT_NE(dump(ds).find("'Outer' -> 'Inner' -> 'Outer'"), std::string::npos) << dump(ds);
}

TEST(Validate, ChartThatActivatesItself) {
  auto b = loop();
  b.action_chart("Self", 1).chart("self", "Self").initial("X0").trans({"X0"}, {"X0"});
  b.assoc("main", "S0", "Self");
  const int back = b.line();
  b.assoc("self", "X0", "Self");
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, back, "hierarchy cycle"), 1u) << dump(ds);
}

TEST(Validate, EnclosingCycleInGrafcet) {
  PouBuilder b;
  b.chart("G0").enclosing_step("E", {"G1"}, true).trans({"E"}, {"E"});
  b.chart("G1").initial("10");
  const int back = b.line();
  b.enclosing_step("11", {"G1"}).trans({"10"}, {"11"});
  const auto ds = validate(b.project(Dialect::Grafcet));
  EXPECT_EQ(count_at(ds, Severity::Error, back, "hierarchy cycle"), 1u) << dump(ds);
}

// ------------------------------------------------------------------------------- associations

TEST(Validate, AssociationNamesActionOrBooleanVariable) {
  auto b = loop();
  b.output("lamp", "BOOL").var("count", "INT").action_st("Work", {});
  b.assoc("main", "S0", "Work").assoc("main", "S1", "LAMP");
  EXPECT_CLEAN(validate(b.project()));
  const int undeclared = b.line();
  b.assoc("main", "S1", "Nothing");
  const int integer = b.line();
  b.assoc("main", "S1", "count");
  const int input = b.line();
  b.assoc("main", "S1", "go");
  const int bad_step = b.line();
  b.assoc("main", "S9", "Work");
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, undeclared, "undeclared action 'Nothing'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, integer, "not BOOL"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, input, "input variable 'go'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, bad_step, "undeclared step 'S9'"), 1u) << dump(ds);
}

TEST(Validate, ActionOfAnUndeclaredInstanceIsOutsideTheModel) {
  // TwinCAT: `Motor.ACT_Stop` is an action of an instance of a user function block, which the
  // importers cannot model: a warning (once per name), not an error.
  auto b = loop();
  const int first = b.line();
  b.assoc("main", "S1", "Table.Motor.ACT_Stop").assoc("main", "S0", "Table.Motor.ACT_Stop");
  const auto ds = validate(b.project());
  EXPECT_EQ(count(ds, Severity::Error), 0u) << dump(ds);
  EXPECT_EQ(
      count_at(ds, Severity::Warning, first, "of 'Table.Motor', which this model does not declare"),
      1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Warning), 1u) << dump(ds);
  // A dotted action of a declared variable is still an error.
  auto c = loop();
  c.var("n", "INT").assoc("main", "S1", "n.ACT_Stop");
  EXPECT_EQ(count(validate(c.project()), Severity::Error), 1u);
}

TEST(Validate, VariableActionMustDriveABooleanNonInput) {
  auto b = loop();
  b.output("lamp", "BOOL").action_var("Light", "lamp").assoc("main", "S1", "Light");
  EXPECT_CLEAN(validate(b.project()));
  const int bad = b.line();
  b.action_var("Bad", "go");
  const auto ds = validate(b.project());
  // CODESYS and TwinCAT let a POU write its inputs: a warning for IEC charts, an error for Grafcet.
  EXPECT_EQ(count_at(ds, Severity::Warning, bad, "drives input variable 'go'"), 1u) << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 0u) << dump(ds);
  EXPECT_EQ(count_at(validate(b.project(Dialect::Grafcet)), Severity::Error, bad,
                     "drives input variable 'go' (inputs are read-only)"),
            1u);
}

TEST(Validate, TimedQualifierNeedsADuration) {
  auto b = loop();
  b.output("lamp", "BOOL").var("delay", "TIME").var("n", "INT");
  const int missing = b.line();
  b.assoc("main", "S1", "lamp", Qualifier::L);
  b.assoc("main", "S1", "lamp", Qualifier::D);
  b.last_assoc().duration_ms = 2000;
  b.assoc("main", "S1", "lamp", Qualifier::SD);
  b.last_assoc().duration_variable = "delay";
  const int wrong = b.line();
  b.assoc("main", "S1", "lamp", Qualifier::DS);
  b.last_assoc().duration_variable = "n";
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, missing, "qualifier L of action 'lamp' needs a duration"),
            1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, wrong, "duration variable 'n' has type INT"), 1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 2u) << dump(ds);
}

// ------------------------------------------------------------------------------------- types

TEST(Validate, GuardMustBeBoolean) {
  PouBuilder b;
  b.input("n", "INT").chart("main").initial("A").step("B");
  const int bad = b.line();
  b.trans({"A"}, {"B"}, make_name("n"));
  b.trans({"B"}, {"A"}, make_binary(ExprKind::Gt, make_name("N"), make_int(3)));
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, bad, "the guard has type integer, expected BOOL"), 1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 1u) << dump(ds);
}

TEST(Validate, ComparisonsMustNotMixTypes) {
  PouBuilder b;
  b.input("ok", "BOOL").input("n", "INT").chart("main").initial("A").step("B").step("C");
  const int bool_int = b.line();
  b.trans({"A"}, {"B"}, make_binary(ExprKind::Eq, make_name("ok"), make_int(2)));
  const int time_int = b.line();
  b.trans({"B"}, {"C"}, make_binary(ExprKind::Gt, make_member("B", "T"), make_int(500)));
  b.trans(
      {"C"}, {"A"},
      make_nary(ExprKind::And,
                {make_binary(ExprKind::Ge, make_member("c", "t"), make_time(500)),
                 make_binary(ExprKind::Eq, make_name("ok"), make_int(1))}));  // 1 is a BOOL literal
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, bool_int, "comparison of BOOL with integer"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, time_int, "comparison of TIME with integer"), 1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 2u) << dump(ds);
}

TEST(Validate, LogicMustNotMixBoolAndInt) {
  PouBuilder b;
  b.input("ok", "BOOL").input("n", "INT").chart("main").initial("A");
  const int bad = b.line();
  b.trans({"A"}, {"A"}, make_nary(ExprKind::And, {make_name("ok"), make_name("n")}));
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, bad, "mixes BOOL and integer"), 1u) << dump(ds);
}

TEST(Validate, NamesResolveCaseInsensitivelyToVariablesStepsAndFbMembers) {
  PouBuilder b;
  b.input("Start", "BOOL").var("T1", "TON").var("C1", "CTU").var("w", "WORD");
  b.chart("main").initial("S1").step("S2").step("S3").step("S4");
  b.trans({"S1"}, {"S2"}, make_nary(ExprKind::And, {make_name("START"), make_member("s1", "x")}));
  b.trans({"S2"}, {"S3"},
          make_nary(ExprKind::Or,
                    {make_member("t1", "q"),
                     make_binary(ExprKind::Ge, make_member("T1", "ET"), make_time(100))}));
  b.trans({"S3"}, {"S4"},
          make_nary(ExprKind::And, {make_binary(ExprKind::Gt, make_member("C1", "CV"), make_int(3)),
                                    make_member("w", "3"), make_name("S2")}));
  b.trans({"S4"}, {"S1"}, make_unary(ExprKind::Rising, make_name("start")));
  b.action_st("Run", {make_fb_call("T1", {{"IN", make_member("S2", "X")}, {"PT", make_time(5000)}}),
                      make_fb_call("c1", {{"CU", make_name("Start")}, {"PV", make_int(10)}})});
  b.assoc("main", "S2", "Run");
  EXPECT_CLEAN(validate(b.project()));
}

TEST(Validate, UnknownNamesAndMembers) {
  PouBuilder b;
  b.var("T1", "TON").chart("main").initial("S1").step("S2");
  const int unknown = b.line();
  b.trans({"S1"}, {"S2"}, make_name("nowhere"));
  const int bad_member = b.line();
  b.trans({"S2"}, {"S1"},
          make_nary(ExprKind::Or,
                    {make_member("T1", "DONE"), make_member("S1", "Y"), make_name("T1")}));
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, unknown, "unknown name 'nowhere'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, bad_member, "TON has no member 'DONE'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, bad_member, "step 'S1' has no member 'Y'"), 1u)
      << dump(ds);
  EXPECT_EQ(
      count_at(ds, Severity::Error, bad_member, "function block instance 'T1' used as a value"), 1u)
      << dump(ds);
}

TEST(Validate, GrafcetStepVariables) {
  PouBuilder b;
  b.chart("G").initial("1").step("12");
  b.trans({"1"}, {"12"}, make_name("x1")).trans({"12"}, {"1"}, make_name("X12"));
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));

  PouBuilder iec;  // in IEC 61131-3 X12 is just an unknown name
  iec.chart("main").initial("12");
  const int bad = iec.line();
  iec.trans({"12"}, {"12"}, make_name("X12"));
  const auto ds = validate(iec.project());
  EXPECT_EQ(count_at(ds, Severity::Error, bad, "unknown name 'X12'"), 1u) << dump(ds);
}

TEST(Validate, AssignmentTypesAndTargets) {
  auto b = loop();
  b.output("lamp", "BOOL").var("n", "INT").var("t", "TIME").var("T1", "TON");
  const auto at = [](int line) { return SourceLocation{"test.sfc", line, 3, {}}; };
  b.var("Other", "BOOL");
  b.action_st("Act",
              {
                  make_assign("lamp", make_name("go"), at(100)),  // fine
                  make_assign("n", make_binary(ExprKind::Add, make_name("n"), make_int(1)),
                              at(101)),  // fine
                  make_assign("t", make_binary(ExprKind::Mul, make_time(10), make_int(3)),
                              at(102)),                            // fine
                  make_assign("T1.PT", make_time(10), at(103)),    // fine
                  make_assign("lamp", make_int(1), at(111)),       // fine: 1 is a BOOL literal
                  make_assign("lamp", make_int(2), at(104)),       // INT into BOOL
                  make_assign("n", make_name("lamp"), at(105)),    // BOOL into INT
                  make_assign("go", make_bool(true), at(106)),     // input
                  make_assign("T1.Q", make_bool(true), at(107)),   // FB output
                  make_assign("S0.X", make_bool(true), at(108)),   // step flag
                  make_assign("ghost", make_bool(true), at(109)),  // undeclared
                  make_assign("t", make_binary(ExprKind::Add, make_time(10), make_int(3)),
                              at(110)),                               // TIME+INT
                  make_assign("GVL.Flag", make_bool(true), at(112)),  // outside the model: warning
              });
  const auto ds = validate(b.project());
  for (int line = 100; line <= 103; ++line)
    EXPECT_EQ(count_at(ds, Severity::Error, line, ""), 0u) << line << "\n" << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 104, "assignment of a integer value to BOOL 'lamp'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 105, "assignment of a BOOL value to integer 'n'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, 106, "assignment to input variable 'go'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 111, ""), 0u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, 112, "'GVL.Flag' refers to 'GVL'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 107, "assignment to output 'T1.Q'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 108, "step flags are read-only"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 109, "undeclared variable 'ghost'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 110, "arithmetic on TIME and integer"), 1u) << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 6u) << dump(ds);
}

TEST(Validate, QualifiedNamesOutsideTheModelAreWarnings) {
  // The second POU's variable is readable as Main.flag; GVL.x and inst.y (an instance of a type
  // the importer dropped) are outside the model; S9.X on an undeclared step is a typo.
  PouBuilder main("Main");
  main.var("flag", "BOOL").var("count", "INT");
  auto b = loop();
  const int g1 = b.line();
  b.trans(
      {"S0"}, {"S1"},
      make_nary(ExprKind::And, {make_member("main", "FLAG"), make_member("GVL", "IsResetting")}));
  const int g2 = b.line();
  b.trans({"S1"}, {"S0"},
          make_nary(ExprKind::Or,
                    {make_member("gvl", "isresetting"), make_member("Table.Motor", "Stopped"),
                     make_binary(ExprKind::Gt, make_member("Main", "count"), make_int(3))}));
  const int g3 = b.line();
  b.trans({"S1"}, {"S0"},
          make_nary(ExprKind::Or, {make_member("S9", "X"), make_member("Main", "nothing"),
                                   make_member("Main", "flag")}));
  auto p = b.project();
  p.pous.push_back(main.pou());
  const auto ds = validate(p);
  EXPECT_EQ(count_at(ds, Severity::Warning, g1, "'GVL.IsResetting' refers to 'GVL'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Warning, g2, "'Table.Motor.Stopped' refers to 'Table'"), 1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Warning), 2u) << dump(ds);  // GVL.IsResetting once
  EXPECT_EQ(count_at(ds, Severity::Error, g3, "unknown step 'S9' in S9.X"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, g3, "POU 'Main' declares no variable 'nothing'"), 1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 2u) << dump(ds);
}

TEST(Validate, ControlStatementsAndFbCalls) {
  auto b = loop();
  b.var("n", "INT").output("lamp", "BOOL").var("T1", "TON");
  auto if_stmt = std::make_shared<Stmt>();
  if_stmt->kind = StmtKind::If;
  if_stmt->where = {"test.sfc", 200, 1, {}};
  if_stmt->conditions = {make_name("n")};  // not BOOL
  if_stmt->bodies = {{make_assign("lamp", make_bool(true), if_stmt->where)}};
  auto case_stmt = std::make_shared<Stmt>();
  case_stmt->kind = StmtKind::Case;
  case_stmt->where = {"test.sfc", 201, 1, {}};
  case_stmt->value = make_name("lamp");  // not an integer
  case_stmt->labels = {{{1, 1, {}, {}}}};
  case_stmt->bodies = {{}};
  b.action_st("Act", {if_stmt, case_stmt,
                      make_fb_call("T1", {{"IN", make_int(5)}, {"XX", make_bool(true)}},
                                   {"test.sfc", 202, 1, {}}),
                      make_fb_call("n", {}, {"test.sfc", 203, 1, {}})});
  const auto ds = validate(b.project());
  EXPECT_EQ(count_at(ds, Severity::Error, 200, "the IF condition has type integer"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 201, "CASE selector has type BOOL"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 202, "parameter IN of TON expects BOOL"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 202, "no parameter 'XX'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, 203, "not a function block instance"), 1u) << dump(ds);
}

// ----------------------------------------------------------------------------- Grafcet extras

PouBuilder grafcet_base() {
  PouBuilder b;
  b.input("a", "BOOL").output("lamp", "BOOL").var("c", "INT");
  b.chart("G0").initial("1").step("2").trans({"1"}, {"2"}, make_name("a")).trans({"2"}, {"1"});
  b.chart("G1").initial("10").step("11").trans({"10"}, {"11"}).trans({"11"}, {"10"});
  return b;
}

TEST(Validate, GrafcetStoredActions) {
  auto b = grafcet_base();
  b.stored("G0", "1", "lamp", make_int(1))
      .stored("G0", "2", "lamp", make_int(0), StoredWhen::Deactivation);
  b.stored("G0", "2", "c", make_binary(ExprKind::Add, make_name("c"), make_int(1)));
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));
  const int ghost = b.line();
  b.stored("G0", "1", "ghost", make_int(1));
  const int input = b.line();
  b.stored("G0", "1", "a", make_int(1));
  const int type = b.line();
  b.stored("G0", "1", "c", make_bool(true));
  const int step = b.line();
  b.stored("G0", "7", "lamp", make_int(1));
  const auto ds = validate(b.project(Dialect::Grafcet));
  EXPECT_EQ(count_at(ds, Severity::Error, ghost, "undeclared variable 'ghost'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, input, "input variable 'a'"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, type, "assigns a BOOL value to integer"), 1u) << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, step, "undeclared step '7'"), 1u) << dump(ds);
}

TEST(Validate, GrafcetForcingOrders) {
  auto b = grafcet_base();
  b.forcing("G0", "2", "G1", {"11"});
  EXPECT_CLEAN(validate(b.project(Dialect::Grafcet)));
  const int chart = b.line();
  b.forcing("G0", "2", "G9", {"11"});
  const int step = b.line();
  b.forcing("G0", "2", "G1", {"11", "99"});
  const auto ds = validate(b.project(Dialect::Grafcet));
  EXPECT_EQ(count_at(ds, Severity::Error, chart, "undeclared partial grafcet 'G9'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, step, "step '99'"), 1u) << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 2u) << dump(ds);
}

TEST(Validate, GrafcetEnclosingAndMacroSteps) {
  PouBuilder b;
  b.chart("G0").initial("1");
  const int enclosing = b.line();
  b.enclosing_step("2", {"G1", "G7"});
  const int macro = b.line();
  b.macro_step("M3", "");
  const int macro2 = b.line();
  b.macro_step("M4", "NoSuchChart");
  b.trans({"1"}, {"2"}).trans({"2"}, {"M3"}).trans({"M3"}, {"M4"}).trans({"M4"}, {"1"});
  b.chart("G1").step("10").trans({"10"}, {"10"});
  const auto ds = validate(b.project(Dialect::Grafcet));
  EXPECT_EQ(count_at(ds, Severity::Error, enclosing, "encloses undeclared chart 'G7'"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, macro, "macro-step 'M3' has no expansion"), 1u)
      << dump(ds);
  EXPECT_EQ(count_at(ds, Severity::Error, macro2, "undeclared chart 'NoSuchChart'"), 1u)
      << dump(ds);
  EXPECT_EQ(count(ds, Severity::Error), 3u) << dump(ds);
}

TEST(Validate, DiagnosticsComeInDocumentOrder) {
  PouBuilder b;
  b.chart("main").initial("A").trans({"A"}, {"Z"}).step("A");
  const auto ds = validate(b.project());
  ASSERT_GE(ds.size(), 2u) << dump(ds);
  for (std::size_t i = 1; i < ds.size(); ++i) EXPECT_LE(ds[i - 1].where.line, ds[i].where.line);
}

}  // namespace
}  // namespace sfcv::model

#include "logic/standard_checks.hpp"

#include <gtest/gtest.h>

#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "model/statement.hpp"
#include "support/toy_system.hpp"

namespace sfcv::engine {
namespace {

using logic::StandardCheck;
using logic::Verdict;
using semantics::InputCondition;
using test::ToySystem;

logic::PropertyResult run(const semantics::TransitionSystem& ts, StandardCheck id,
                          const model::Project* project = nullptr, bool priority = true,
                          std::vector<logic::FormulaPtr> fair = {}) {
  const auto g = build_reachable_situation_graph(ts);
  CtlChecker checker(g, std::move(fair));
  logic::CheckTask task;
  task.system = &ts;
  task.project = project;
  task.checks = {id};
  task.priority_resolves_conflicts = priority;
  auto results = run_standard_checks(g, checker, task);
  EXPECT_GE(results.size(), 1u);
  return results.front();
}

// A cycle A -> B -> A with fired transitions t0, t1; state 2 (step C) unreachable unless
// `all_reachable` drops C's observable.
ToySystem cycle(bool all_reachable = false) {
  ToySystem ts(
      3, {"go"},
      all_reachable ? std::vector<std::string>{"A", "B"} : std::vector<std::string>{"A", "B", "C"});
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(0, 0, ToySystem::lit(0, false));
  ts.add_arc(1, 0, ToySystem::lit(0, true), {1});
  ts.add_arc(1, 1, ToySystem::lit(0, false));
  ts.add_arc(2, 0, InputCondition::always(), {2});
  ts.set_true(0, 0);
  ts.set_true(1, 1);
  if (!all_reachable) ts.set_true(2, 2);
  return ts;
}

// A -> B and B stays forever (B absorbing, nothing fires any more).
ToySystem absorbing() {
  ToySystem ts(2, {"go"}, {"A", "B"});
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(0, 0, ToySystem::lit(0, false));
  ts.add_arc(1, 1);
  ts.set_true(0, 0);
  ts.set_true(1, 1);
  return ts;
}

TEST(StandardChecks, Reachable) {
  auto r = run(cycle(), StandardCheck::Reachable);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_NE(r.findings[0].find("step C is never active"), std::string::npos);
  EXPECT_EQ(run(absorbing(), StandardCheck::Reachable).verdict, Verdict::Holds);
}

TEST(StandardChecks, DeadTransitions) {
  auto r = run(cycle(), StandardCheck::DeadTransitions);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_NE(r.findings[0].find("transition t2 never fires"), std::string::npos);
  EXPECT_EQ(run(absorbing(), StandardCheck::DeadTransitions).verdict, Verdict::Holds);
}

TEST(StandardChecks, ReentryAndItsFairVersion) {
  EXPECT_EQ(run(cycle(true), StandardCheck::Reentry).verdict, Verdict::Holds);
  auto r = run(absorbing(), StandardCheck::Reentry);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_NE(r.findings[0].find("step A"), std::string::npos);
  ASSERT_TRUE(r.trace);
  // The counterexample ends in B, from where A is unreachable.
  const auto ts = absorbing();
  EXPECT_EQ(ts.state_of(r.trace->steps.back().state), 1u);
  // AG AF only under fairness: without it the check is not reported.
  const auto g = build_reachable_situation_graph(ts);
  {
    CtlChecker plain(g);
    logic::CheckTask task;
    task.system = &ts;
    task.checks = {StandardCheck::Reentry};
    EXPECT_EQ(run_standard_checks(g, plain, task).size(), 1u);
  }
  // On the cycle, AG AF A fails without fairness (go may stay false), also when runs must only
  // visit B infinitely often (they may stay in B), and holds when they must visit A and B.
  const auto c = cycle(true);
  const auto gc = build_reachable_situation_graph(c);
  {
    CtlChecker only_b(gc, {logic::observable_atom(c, 1)});
    logic::CheckTask task;
    task.system = &c;
    task.checks = {StandardCheck::Reentry};
    const auto results = run_standard_checks(gc, only_b, task);
    ASSERT_EQ(results.size(), 2u);
    EXPECT_EQ(results[1].verdict, Verdict::Violated);
    ASSERT_EQ(results[1].findings.size(), 1u);
    EXPECT_NE(results[1].findings[0].find("step A"), std::string::npos);
    ASSERT_TRUE(results[1].trace && results[1].trace->loop_start);
  }
  CtlChecker fair(gc, {logic::observable_atom(c, 0), logic::observable_atom(c, 1)});
  logic::CheckTask task;
  task.system = &c;
  task.checks = {StandardCheck::Reentry};
  const auto results = run_standard_checks(gc, fair, task);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[1].name, "reentry-fair");
  EXPECT_EQ(results[1].verdict, Verdict::Holds);
}

TEST(StandardChecks, GlobalDeadlock) {
  auto r = run(absorbing(), StandardCheck::GlobalDeadlock);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_TRUE(r.trace);
  EXPECT_EQ(r.trace->steps.size(), 2u);
  EXPECT_EQ(run(cycle(), StandardCheck::GlobalDeadlock).verdict, Verdict::Holds);
  // A state without any successor is a deadlock too.
  ToySystem stuck(2, {}, {"A", "B"});
  stuck.set_initial({0});
  stuck.add_arc(0, 1, InputCondition::always(), {0});
  auto s = run(stuck, StandardCheck::GlobalDeadlock);
  EXPECT_EQ(s.verdict, Verdict::Violated);
  EXPECT_NE(s.findings[0].find("no successor"), std::string::npos);
}

TEST(StandardChecks, LocalDeadlock) {
  auto r = run(absorbing(), StandardCheck::LocalDeadlock);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  bool b_never_left = false, a_never_back = false;
  for (const auto& f : r.findings) {
    b_never_left |= f.find("step B, once active, is never left") != std::string::npos;
    a_never_back |=
        f.find("step A, once inactive, never becomes active again") != std::string::npos;
  }
  EXPECT_TRUE(b_never_left);
  EXPECT_TRUE(a_never_back);
  EXPECT_EQ(run(cycle(true), StandardCheck::LocalDeadlock).verdict, Verdict::Holds);
}

TEST(StandardChecks, InitialReturn) {
  EXPECT_EQ(run(cycle(), StandardCheck::InitialReturn).verdict, Verdict::Holds);
  auto r = run(absorbing(), StandardCheck::InitialReturn);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_TRUE(r.trace);
  EXPECT_EQ(absorbing().state_of(r.trace->steps.back().state), 1u);
}

TEST(StandardChecks, ConflictsUnderNoPriority) {
  // From A, t0 and t1 can both fire when go is true.
  ToySystem ts(3, {"go", "x"}, {"A", "B", "C"});
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(0, 2, ToySystem::lit(0, true), {1});
  ts.add_arc(1, 1);
  ts.add_arc(2, 2);
  auto r = run(ts, StandardCheck::Conflicts, nullptr, false);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_NE(r.findings[0].find("{t0} and {t1}"), std::string::npos);
  // With the standard priority the question has no meaning (the priority orders every set of
  // alternatives): n/a, never "holds" (it was "not checked", which now counts as unknown).
  EXPECT_EQ(run(ts, StandardCheck::Conflicts, nullptr, true).verdict, Verdict::NotApplicable);
  // Exclusive guards: no conflict.
  ToySystem ok(3, {"go", "x"}, {"A", "B", "C"});
  ok.set_initial({0});
  ok.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ok.add_arc(0, 2, ToySystem::lit(0, false), {1});
  ok.add_arc(1, 1);
  ok.add_arc(2, 2);
  EXPECT_EQ(run(ok, StandardCheck::Conflicts, nullptr, false).verdict, Verdict::Holds);
}

model::Project stored_project(bool with_reset) {
  model::Project p;
  model::Pou pou;
  pou.name = "P";
  model::Chart chart;
  chart.name = "C";
  for (const char* n : {"A", "B"}) {
    model::Step s;
    s.name = n;
    chart.steps.push_back(s);
  }
  pou.charts.push_back(chart);
  model::ActionAssociation set;
  set.chart = "C";
  set.step = "A";
  set.action = "M";
  set.qualifier = model::Qualifier::S;
  pou.associations.push_back(set);
  if (with_reset) {
    auto reset = set;
    reset.step = "B";
    reset.qualifier = model::Qualifier::R;
    pou.associations.push_back(reset);
  }
  p.pous.push_back(pou);
  return p;
}

TEST(StandardChecks, StoredActions) {
  // Without the chart: not checked, never "holds".
  EXPECT_EQ(run(cycle(), StandardCheck::StoredActions).verdict, Verdict::NotChecked);
  // Set and never reset.
  const auto no_reset = stored_project(false);
  auto r = run(cycle(), StandardCheck::StoredActions, &no_reset);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  EXPECT_NE(r.findings[0].find("never reset"), std::string::npos);
  // Set (A) and reset (B) in one situation.
  ToySystem both(2, {}, {"A", "B"});
  both.set_initial({0});
  both.add_arc(0, 1, InputCondition::always(), {0});
  both.add_arc(1, 0, InputCondition::always(), {1});
  both.set_true(0, 0);
  both.set_true(1, 0);
  both.set_true(1, 1);
  const auto with_reset = stored_project(true);
  r = run(both, StandardCheck::StoredActions, &with_reset);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_FALSE(r.findings.empty());
  EXPECT_NE(r.findings[0].find("set (S at A) and reset (R at B) in the same situation"),
            std::string::npos);
  // Correct use, but the toy system has no stored flag: the unchecked part is said.
  r = run(cycle(), StandardCheck::StoredActions, &with_reset);
  EXPECT_EQ(r.verdict, Verdict::NotChecked);
  EXPECT_NE(r.message.find("not checked: set again while stored"), std::string::npos);
}

TEST(StandardChecks, OutputConflicts) {
  model::Project p;
  model::Pou pou;
  pou.name = "P";
  for (auto [name, value] : {std::pair{"A1", true}, std::pair{"A2", false}}) {
    model::Action a;
    a.name = name;
    a.kind = model::ActionBodyKind::Statements;
    a.body.push_back(model::make_assign("V", model::make_bool(value)));
    pou.actions.push_back(a);
  }
  p.pous.push_back(pou);
  auto system = [](bool together) {
    ToySystem ts(2, {}, {"A1", "A2"});
    ts.set_kind(0, semantics::ObservableKind::Action);
    ts.set_kind(1, semantics::ObservableKind::Action);
    ts.set_initial({0});
    ts.add_arc(0, 1, InputCondition::always(), {0});
    ts.add_arc(1, 0, InputCondition::always(), {1});
    ts.set_true(0, 0);
    ts.set_true(1, 1);
    if (together) ts.set_true(1, 0);
    return ts;
  };
  auto r = run(system(true), StandardCheck::OutputConflicts, &p);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_FALSE(r.findings.empty());
  EXPECT_NE(r.findings[0].find("variable V is written by A1 (:= 1) and A2 (:= 0)"),
            std::string::npos);
  EXPECT_EQ(run(system(false), StandardCheck::OutputConflicts, &p).verdict, Verdict::Holds);
  EXPECT_EQ(run(system(true), StandardCheck::OutputConflicts).verdict, Verdict::NotChecked);
}

TEST(StandardChecks, OutputConflictsCountLoopIndicesAndOutputBindingsAsWrites) {
  // A FOR loop assigns its index and `t(Q => y)` assigns y: two actions doing so, or one of
  // them beside an assignment, write the same variable in one cycle (they were not counted).
  model::Pou pou;
  pou.name = "P";
  auto action = [&](const std::string& name, model::StmtPtr st) {
    model::Action a;
    a.name = name;
    a.kind = model::ActionBodyKind::Statements;
    a.body.push_back(std::move(st));
    pou.actions.push_back(a);
  };
  auto loop = std::make_shared<model::Stmt>();
  loop->kind = model::StmtKind::For;
  loop->target = "i";
  loop->value = model::make_int(1);
  loop->limit = model::make_int(3);
  loop->bodies.push_back({});
  action("Count", loop);
  action("Reset", model::make_assign("I", model::make_int(0)));
  auto call = std::make_shared<model::Stmt>();
  call->kind = model::StmtKind::FbCall;
  call->target = "t";
  call->outputs = {{"Q", "y"}};
  action("Timer", call);
  action("Set", model::make_assign("y", model::make_bool(true)));
  const auto conflicts = logic::write_conflicts(pou);
  ASSERT_EQ(conflicts.size(), 2u);
  EXPECT_EQ(conflicts[0].variable, "I");
  EXPECT_EQ(conflicts[0].first.action, "Count");
  EXPECT_EQ(conflicts[0].second.action, "Reset");
  EXPECT_EQ(conflicts[1].variable, "Y");
  EXPECT_EQ(conflicts[1].first.action, "Timer");
  EXPECT_EQ(conflicts[1].second.action, "Set");
}

TEST(StandardChecks, OutputConflictsFollowCallsOfActionsFunctionsAndInstances) {
  // Writes made through calls are the calling action's: `Helper();` assigns y for Fill, the
  // function Bump assigns the global g for Count, and Open and Close both call the timer t (a
  // call changes the instance). Before, none of these was seen, so two actions writing through
  // them were never reported.
  const auto loaded = io::load_iec_text(R"(
FUNCTION Bump : INT
  VAR_INPUT k : INT; END_VAR
  VAR_EXTERNAL g : INT; END_VAR
  g := g + k;
  Bump := g;
END_FUNCTION
PROGRAM P
  VAR_INPUT go : BOOL; END_VAR
  VAR_GLOBAL g : INT; END_VAR
  VAR y : BOOL; n : INT; t : TON; END_VAR
  INITIAL_STEP S0 : Fill; Drain; Count; Reset; Open; Close; END_STEP
  TRANSITION FROM S0 TO S0 := go; END_TRANSITION
  ACTION Helper : y := TRUE; END_ACTION
  ACTION Fill : Helper(); END_ACTION
  ACTION Drain : y := FALSE; END_ACTION
  ACTION Count : IF go THEN n := Bump(1); END_IF; END_ACTION
  ACTION Reset : g := 0; END_ACTION
  ACTION Open : t(IN := TRUE, PT := T#1s); END_ACTION
  ACTION Close : t(IN := FALSE, PT := T#1s); END_ACTION
END_PROGRAM
)",
                                        "calls.st");
  ASSERT_TRUE(loaded.ok());
  const auto& project = *loaded.project;
  const auto* pou = project.find_pou("P");
  ASSERT_NE(pou, nullptr);
  std::vector<std::string> found;
  for (const auto& c : logic::write_conflicts(*pou, &project))
    found.push_back(c.variable + ":" + c.first.action + "/" + c.second.action);
  // Helper alone also writes y: its pairs are asked too (it is active only if a step names it).
  EXPECT_EQ(found, (std::vector<std::string>{"G:Count/Reset", "T:Open/Close", "Y:Helper/Fill",
                                             "Y:Helper/Drain", "Y:Fill/Drain"}));
  // Without the project the function's writes are unknown, the others are still seen.
  found.clear();
  for (const auto& c : logic::write_conflicts(*pou))
    found.push_back(c.variable + ":" + c.first.action + "/" + c.second.action);
  EXPECT_EQ(found, (std::vector<std::string>{"T:Open/Close", "Y:Helper/Fill", "Y:Helper/Drain",
                                             "Y:Fill/Drain"}));
}

// A system that reports an instability from its initial state.
class Unstable final : public semantics::TransitionSystem {
 public:
  explicit Unstable(bool unstable) : unstable_(unstable), toy_(cycle()) {}
  semantics::SemanticsKind kind() const override { return semantics::SemanticsKind::Grafcet; }
  const semantics::StateLayout& layout() const override { return toy_.layout(); }
  const std::vector<semantics::InputVariable>& inputs() const override { return toy_.inputs(); }
  const std::vector<semantics::Observable>& observables() const override {
    return toy_.observables();
  }
  const std::vector<semantics::TransitionInfo>& transitions() const override {
    return toy_.transitions();
  }
  void initial_states(semantics::SuccessorSink& sink) const override { toy_.initial_states(sink); }
  void successors(semantics::StateView s, semantics::SuccessorSink& sink) const override {
    toy_.successors(s, sink);
    if (unstable_ && toy_.state_of(s) == 1) {
      semantics::Anomaly a;
      a.message = "transient evolution X1 -> X2 -> X1 never stabilises";
      a.condition = ToySystem::lit(0, true);
      sink.anomaly(a);
    }
  }
  std::int64_t observe(semantics::StateView s, std::uint32_t i) const override {
    return toy_.observe(s, i);
  }

 private:
  bool unstable_;
  ToySystem toy_;
};

TEST(StandardChecks, Instability) {
  auto r = run(Unstable(true), StandardCheck::Instability);
  EXPECT_EQ(r.verdict, Verdict::Violated);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_NE(r.findings[0].find("instability: transient evolution"), std::string::npos);
  EXPECT_NE(r.findings[0].find("(inputs go)"), std::string::npos);
  EXPECT_EQ(run(Unstable(false), StandardCheck::Instability).verdict, Verdict::Holds);
}

TEST(StandardChecks, IncompleteGraphNeverHolds) {
  ToySystem ts(50, {}, {"A"});
  ts.set_initial({0});
  for (std::uint32_t s = 0; s + 1 < 50; ++s) ts.add_arc(s, s + 1, InputCondition::always(), {s});
  ts.add_arc(49, 0, InputCondition::always(), {49});
  ts.set_true(49, 0);
  ExplorationOptions opts;
  opts.max_states = 5;
  const auto g = build_reachable_situation_graph(ts, opts);
  ASSERT_FALSE(g.complete());
  CtlChecker checker(g);
  logic::CheckTask task;
  task.system = &ts;
  task.checks = *logic::parse_check_selection("all", nullptr);
  for (const auto& r : run_standard_checks(g, checker, task))
    EXPECT_NE(r.verdict, Verdict::Holds) << r.name << ": " << r.message;
}

TEST(StandardChecks, NotApplicableOnlyWhereTheQuestionHasNoMeaning) {
  // A system without steps or transitions (a program without SFC): the step checks and the
  // transition checks have no meaning; initial-return and instability still do.
  ToySystem plain(2, {"go"});
  plain.set_initial({0});
  plain.add_arc(0, 1, ToySystem::lit(0, true));
  plain.add_arc(0, 0, ToySystem::lit(0, false));
  plain.add_arc(1, 0);
  for (auto id : {StandardCheck::Reachable, StandardCheck::Reentry, StandardCheck::LocalDeadlock}) {
    const auto r = run(plain, id);
    EXPECT_EQ(r.verdict, Verdict::NotApplicable) << logic::to_string(id);
    EXPECT_EQ(r.message, "the system has no steps");
  }
  for (auto id : {StandardCheck::DeadTransitions, StandardCheck::GlobalDeadlock}) {
    const auto r = run(plain, id);
    EXPECT_EQ(r.verdict, Verdict::NotApplicable) << logic::to_string(id);
    EXPECT_EQ(r.message, "the system has no transitions");
  }
  EXPECT_EQ(run(plain, StandardCheck::InitialReturn).verdict, Verdict::Holds);
  EXPECT_EQ(run(plain, StandardCheck::Instability).verdict, Verdict::Holds);
  // Steps but no transitions: the step checks apply (a step that is never active is a finding).
  ToySystem frozen(1, {}, {"A", "B"});
  frozen.set_initial({0});
  frozen.add_arc(0, 0);
  frozen.set_true(0, 0);
  EXPECT_EQ(run(frozen, StandardCheck::Reachable).verdict, Verdict::Violated);
  EXPECT_EQ(run(frozen, StandardCheck::DeadTransitions).verdict, Verdict::NotApplicable);
  // Conflicts: n/a under the standard priority of IEC 61131-3 only; Grafcet has no priority.
  EXPECT_TRUE(logic::not_applicable(StandardCheck::Conflicts, frozen, true));
  EXPECT_FALSE(logic::not_applicable(StandardCheck::Conflicts, frozen, false));
  frozen.set_semantics(semantics::SemanticsKind::Grafcet);
  EXPECT_FALSE(logic::not_applicable(StandardCheck::Conflicts, frozen, true));
  // The answer is the system's, not the engine's: also when exploration failed at once.
  for (auto c :
       {StandardCheck::Reachable, StandardCheck::InitialReturn, StandardCheck::StoredActions,
        StandardCheck::OutputConflicts, StandardCheck::Instability})
    EXPECT_FALSE(logic::not_applicable(c, frozen, true)) << logic::to_string(c);
}

TEST(StandardChecks, SelectionByName) {
  std::string error;
  auto sel = logic::parse_check_selection("reachable,local-deadlock", &error);
  ASSERT_TRUE(sel);
  EXPECT_EQ(*sel,
            (std::vector<StandardCheck>{StandardCheck::Reachable, StandardCheck::LocalDeadlock}));
  EXPECT_TRUE(logic::parse_check_selection("none", &error)->empty());
  EXPECT_EQ(logic::parse_check_selection("all", &error)->size(), logic::standard_checks().size());
  EXPECT_FALSE(logic::parse_check_selection("reachable,bogus", &error));
  EXPECT_NE(error.find("unknown check 'bogus'"), std::string::npos);
}

TEST(StandardChecks, NoInitialStateIsNeverAVerdict) {
  // Issue 45: an AGRAFE file whose first situation overflowed had no initial state, and
  // "reachable" said every step is never active while "global-deadlock" held, vacuously.
  auto ts = cycle();
  ts.set_initial({});
  for (const auto id :
       {StandardCheck::Reachable, StandardCheck::DeadTransitions, StandardCheck::GlobalDeadlock,
        StandardCheck::LocalDeadlock, StandardCheck::Reentry}) {
    const auto r = run(ts, id);
    EXPECT_EQ(r.verdict, Verdict::Unknown) << logic::to_string(id);
    EXPECT_NE(r.message.find("no initial state"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace sfcv::engine

// The BDD engine on Grafcet (the stable-situation relation as the symbolic closure of the
// micro-step circuit) against the explicit RSG: identical reachable counts and verdicts on many
// generated grafcets (edges, delays, stored and continuous actions, forcing orders,
// macro-steps, enclosing steps, integer inputs, both input hypotheses), traces that replay
// through `simulate`, the same instability verdicts, and the files of examples/ and the corpus.

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/bdd/symbolic_system.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/grafcet_circuit.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/simulate.hpp"
#include "support/check_findings.hpp"
#include "support/ctl_task.hpp"
#include "support/grafcet_builder.hpp"
#include "support/random_grafcet.hpp"
#include "support/sfcv_test.hpp"
#include "support/trace_replay.hpp"

namespace sfcv::engine {
namespace {

using model::ExprKind;
using model::ExprPtr;
using test::GrafcetBuilder;

using test::FormulaGenerator;
using test::task_for;

// Atoms: steps and outputs (the input memory and internal variables make dull formulas).
bool step_or_output(const semantics::Observable& o) {
  return o.kind == semantics::ObservableKind::Step || o.is_output;
}

struct Built {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Built make(model::Project p, bool single) {
  Built b{std::move(p), nullptr};
  semantics::GrafcetOptions o;
  o.single_input_change = single;
  model::Diagnostics d;
  b.ts = semantics::make_grafcet_system(b.project, o, d);
  for (const auto& x : d)
    if (x.severity == model::Severity::Error) ADD_FAILURE() << x.str();
  return b;
}

struct Tally {
  int unstable = 0, traces = 0, violated = 0, stored = 0, conflicts = 0, mixed = 0;
};

/// Explicit and BDD reports on the same task: equal states and verdicts, BDD traces replay.
void compare(const Built& b, std::uint64_t seed, bool with_fairness, Tally& tally) {
  FormulaGenerator gen(*b.ts, seed, step_or_output);
  std::vector<std::string> ctl;
  for (int i = 0; i < 10; ++i) ctl.push_back(gen.formula(3));
  ctl.push_back("AG !(" + gen.atom() + " & " + gen.atom() + ")");
  ctl.push_back("EF (" + gen.atom() + " & " + gen.atom() + ")");
  ctl.push_back("AG " + gen.atom());
  ctl.push_back("EF " + gen.atom());
  std::vector<std::string> fair;
  if (with_fairness) fair = {gen.atom(), "!" + gen.atom()};
  auto task = task_for(b.project, *b.ts, ctl, fair);
  if (!with_fairness)
    task.checks = {logic::StandardCheck::Reachable,       logic::StandardCheck::DeadTransitions,
                   logic::StandardCheck::Reentry,         logic::StandardCheck::GlobalDeadlock,
                   logic::StandardCheck::LocalDeadlock,   logic::StandardCheck::InitialReturn,
                   logic::StandardCheck::Conflicts,       logic::StandardCheck::StoredActions,
                   logic::StandardCheck::OutputConflicts, logic::StandardCheck::Instability};
  else
    task.checks = {logic::StandardCheck::Reentry};  // and its AG AF row under fairness
  const auto e = make_explicit_model_checker()->check(task);
  const auto bdd = make_bdd_model_checker();
  ASSERT_TRUE(bdd->can_handle(task));
  const auto s = bdd->check(task);
  ASSERT_TRUE(e.complete);
  ASSERT_TRUE(s.complete);
  EXPECT_EQ(e.states, s.states);
  ASSERT_EQ(e.results.size(), s.results.size());
  for (std::size_t i = 0; i < e.results.size(); ++i) {
    EXPECT_EQ(e.results[i].verdict, s.results[i].verdict)
        << e.results[i].name << " " << e.results[i].formula << ": explicit "
        << logic::to_string(e.results[i].verdict) << ", bdd "
        << logic::to_string(s.results[i].verdict)
        << (e.results[i].findings.empty() ? ""
                                          : " (explicit: " + e.results[i].findings.front() + ")")
        << (s.results[i].findings.empty() ? "" : " (bdd: " + s.results[i].findings.front() + ")");
    if (s.results[i].trace) {
      ++tally.traces;
      test::expect_trace_replays(*b.ts, *s.results[i].trace);
    }
    if (i >= task.properties.size()) test::expect_same_check(e.results[i], s.results[i]);
    tally.violated += s.results[i].verdict == logic::Verdict::Violated;
    tally.stored +=
        s.results[i].check == "stored-actions" && s.results[i].verdict == logic::Verdict::Violated;
    tally.unstable +=
        s.results[i].check == "instability" && s.results[i].verdict == logic::Verdict::Violated;
    tally.conflicts +=
        s.results[i].check == "conflicts" && s.results[i].verdict == logic::Verdict::Violated;
    tally.mixed += s.results[i].check == "output-conflicts" &&
                   s.results[i].verdict == logic::Verdict::Violated;
  }
}

TEST(GrafcetBdd, RandomGrafcetsAgreeWithTheExplicitRsg) {
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    for (bool single : {true, false}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (single ? "" : " --multi-input-change"));
      const auto b = make(test::random_grafcet(seed), single);
      ASSERT_TRUE(b.ts);
      compare(b, seed, false, tally);
      if (seed % 4 == 0) compare(b, seed + 1000, true, tally);
    }
  }
  // The generator does reach the interesting cases.
  EXPECT_GT(tally.unstable, 5);
  EXPECT_GT(tally.traces, 100);
  EXPECT_GT(tally.violated, 100);
  EXPECT_GT(tally.stored, 2) << tally.stored;  // stored actions set to different values at once
  EXPECT_GT(tally.conflicts, 5) << tally.conflicts;  // two transitions of one step fire together
  EXPECT_GT(tally.mixed, 5) << tally.mixed;          // y's continuous and stored writers disagree
}

/// The circuit's reachable set, counted by the symbolic system alone, equals the RSG's nodes
/// (the very sets, not only their sizes: every explicit node is in the BDD set).
TEST(GrafcetBdd, ReachableSetsAreTheRsgNodes) {
  for (std::uint64_t seed = 100; seed < 130; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto b = make(test::random_grafcet(seed), true);
    ASSERT_TRUE(b.ts);
    const auto g = build_reachable_situation_graph(*b.ts);
    ASSERT_TRUE(g.complete());
    auto sys = make_symbolic_system(*b.ts);
    auto reached = sys->initial(), frontier = reached;
    while (!frontier.is_false()) {
      frontier = sys->image(frontier) & !reached;
      reached = reached | frontier;
    }
    EXPECT_EQ(sys->count(reached), static_cast<double>(g.num_states()));
    bdd::Bdd explicit_set = bdd::Bdd::constant(false);
    for (std::uint32_t s = 0; s < g.num_states(); ++s)
      explicit_set = explicit_set | sys->singleton(g.states().at(s));
    EXPECT_TRUE(explicit_set == reached);
    // Initial states: the stabilised initial situations.
    bdd::Bdd initial = bdd::Bdd::constant(false);
    for (auto s : g.initial_states()) initial = initial | sys->singleton(g.states().at(s));
    EXPECT_TRUE(initial == sys->initial());
    // Successors of every node: the explicit edges (without stutter).
    sys->restrict_sources(reached);
    for (std::uint32_t s = 0; s < g.num_states(); ++s) {
      bdd::Bdd succ = bdd::Bdd::constant(false);
      for (auto e = g.edges_begin(s); e < g.edges_end(s); ++e)
        succ = succ | sys->singleton(g.states().at(g.target(e)));
      const auto one = sys->singleton(g.states().at(s));
      EXPECT_TRUE(sys->image(one) == succ) << b.ts->describe(g.states().at(s));
      EXPECT_EQ(!(sys->has_successor() & one).is_false(), g.edges_begin(s) < g.edges_end(s));
    }
  }
}

// 1 --a--> 2 --a--> 1 is unstable when a is true: at the start under a, and when a rises. Both
// engines report the instability check violated; the BDD engine names the situation.
TEST(GrafcetBdd, InstabilityIsDetectedSymbolically) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, test::v("a")).transition({"2"}, {"1"}, test::v("a"));
  const auto built = make(b.project(), true);
  auto sys = make_symbolic_system(*built.ts);
  EXPECT_TRUE(sys->initial_unstable());
  EXPECT_FALSE(sys->initial_range_error());
  // Only !a starts stable: {1} with a false.
  EXPECT_EQ(sys->count(sys->initial()), 1.0);
  sys->restrict_sources(sys->initial());
  EXPECT_TRUE(sys->unstable_states() == sys->initial());  // a rising never stabilises
  EXPECT_TRUE(sys->image(sys->initial()).is_false());
  auto task = task_for(built.project, *built.ts, {}, {});
  task.checks = {logic::StandardCheck::Instability};
  const auto e = make_explicit_model_checker()->check(task);
  const auto s = make_bdd_model_checker()->check(task);
  ASSERT_EQ(s.results.size(), 1u);
  EXPECT_EQ(e.results[0].verdict, logic::Verdict::Violated);
  EXPECT_EQ(s.results[0].verdict, logic::Verdict::Violated);
  EXPECT_FALSE(s.results[0].findings.empty());
}

// Integer inputs compared with each other and computed with (an AGRAFE project writes
// `i1 < e3 - 1`): they keep their exact value (docs/semantics.md 2.9). 1 --n < m--> 2
// --n + m = 18--> 3 --n - m = 9--> 1, and 1 --2 * n = m + 19--> 3 can never fire (2n <= 18).
// Both engines give the same states and verdicts; t3 from 3 needs n = 9 and m = 0 while 3 is
// entered with n = m = 9: two input changes, so it fires only after m fell to 0.
TEST(GrafcetBdd, IntegerInputsComputedWithKeepTheirExactValues) {
  using model::ExprKind;
  GrafcetBuilder b;
  b.input("n", model::Type::integer("INT(0..9)", 0, 9))
      .input("m", model::Type::integer("INT(0..9)", 0, 9));
  b.chart("G").step("1", true).step("2").step("3");
  const auto add = [](model::ExprPtr x, model::ExprPtr y) {
    return model::make_binary(ExprKind::Add, std::move(x), std::move(y));
  };
  b.transition({"1"}, {"2"}, test::cmp(ExprKind::Lt, test::v("n"), test::v("m")));
  b.transition({"2"}, {"3"},
               test::cmp(ExprKind::Eq, add(test::v("n"), test::v("m")), test::num(18)));
  b.transition(
      {"3"}, {"1"},
      test::cmp(ExprKind::Eq, model::make_binary(ExprKind::Sub, test::v("n"), test::v("m")),
                test::num(9)));
  b.transition(
      {"1"}, {"3"},
      test::cmp(ExprKind::Eq, model::make_binary(ExprKind::Mul, test::num(2), test::v("n")),
                add(test::v("m"), test::num(19))));
  const auto built = make(b.project(), true);
  ASSERT_TRUE(built.ts);
  Tally tally;
  compare(built, 7, false, tally);
  auto task = task_for(built.project, *built.ts, {"EF X3", "AG (X3 -> !X2)"}, {});
  task.checks = {logic::StandardCheck::DeadTransitions};
  const auto e = make_explicit_model_checker()->check(task);
  ASSERT_EQ(e.results.size(), 3u);
  EXPECT_EQ(e.results[0].verdict, logic::Verdict::Holds);  // n = m = 9 is reached
  EXPECT_EQ(e.results[1].verdict, logic::Verdict::Holds);
  EXPECT_EQ(e.results[2].verdict, logic::Verdict::Violated);  // 2 * n = m + 19 never holds
  ASSERT_EQ(e.results[2].findings.size(), 1u);
  EXPECT_NE(e.results[2].findings[0].find("X1 -> X3"), std::string::npos)
      << e.results[2].findings[0];
  // Each input keeps one region per value: 10 x 10 valuations at most per step.
  EXPECT_GT(e.states.to_double(), 100.0);
  // Used as a Boolean, or too wide to keep exactly: located errors.
  GrafcetBuilder bad;
  bad.input("n", model::Type::integer("INT", -32768, 32767))
      .input("m", model::Type::integer("INT(0..9)", 0, 9));
  bad.chart("G").step("1", true).step("2");
  bad.transition({"1"}, {"2"}, test::cmp(ExprKind::Lt, test::v("n"), test::v("m")));
  model::Diagnostics d;
  semantics::GrafcetOptions o;
  EXPECT_EQ(semantics::make_grafcet_system(bad.project(), o, d), nullptr);
  ASSERT_FALSE(d.empty());
  EXPECT_NE(d.back().message.find("has more than 1024 values"), std::string::npos)
      << d.back().message;
}

// 1 --1--> 2 --a--> 3 --1--> 4 --!a--> 2: step 1 is active only while the initial situation
// stabilises, step 3 only during the evolutions after a rises. Both count as reached, apart,
// and `1 -> 2` fires (docs/semantics.md 2.5); X1 is still left for good (local-deadlock).
TEST(GrafcetBdd, StepsCrossedAtTheStartAreReachedApart) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2").step("3").step("4");
  b.transition({"1"}, {"2"}, test::lit(true))
      .transition({"2"}, {"3"}, test::v("a"))
      .transition({"3"}, {"4"}, test::lit(true))
      .transition({"4"}, {"2"}, test::not_(test::v("a")));
  const auto built = make(b.project(), true);
  ASSERT_TRUE(built.ts);
  auto task = task_for(built.project, *built.ts, {}, {});
  task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions,
                 logic::StandardCheck::LocalDeadlock};
  const auto e = make_explicit_model_checker()->check(task);
  const auto s = make_bdd_model_checker()->check(task);
  for (const auto* r : {&e, &s}) {
    ASSERT_EQ(r->results.size(), 3u);
    EXPECT_EQ(r->results[0].verdict, logic::Verdict::Holds) << r->results[0].message;
    EXPECT_NE(r->results[0].message.find(
                  "1 only during transient evolutions, 1 only while the initial situation "
                  "stabilises"),
              std::string::npos)
        << r->results[0].message;
    EXPECT_EQ(r->results[1].verdict, logic::Verdict::Holds) << r->results[1].message;
    EXPECT_EQ(r->results[2].verdict, logic::Verdict::Violated);
    ASSERT_EQ(r->results[2].findings.size(), 1u);
    EXPECT_NE(r->results[2].findings[0].find("X1"), std::string::npos);
  }
}

// A Boolean output written by both continuous and stored actions (IEC 60848 gives a variable
// one mode) loads; it reads 1 when either mode gives 1, and output-conflicts reports both ways
// the modes disagree, on both engines (docs/semantics.md 2.7):
// 1 --a--> 2 --b--> 3 --!a--> 1, y continuous in 2, stored y := 1 entering 3, y := 0 entering 1.
TEST(GrafcetBdd, VariableWrittenByContinuousAndStoredActionsIsReadAsEither) {
  GrafcetBuilder b;
  b.input("a").input("b").output("y").chart("G").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, test::v("a"))
      .transition({"2"}, {"3"}, test::v("b"))
      .transition({"3"}, {"1"}, test::not_(test::v("a")));
  b.continuous("2", "y");
  b.stored("3", model::StoredWhen::Activation, "y", test::lit(true));
  b.stored("1", model::StoredWhen::Activation, "y", test::lit(false));
  const auto built = make(b.project(), true);
  ASSERT_TRUE(built.ts);
  auto task = task_for(built.project, *built.ts,
                       {"AG (X2 -> y)", "AG (X3 -> y)", "AG (X1 -> !y)", "EF (X1 & y)"}, {});
  task.checks = {logic::StandardCheck::OutputConflicts};
  const auto e = make_explicit_model_checker()->check(task);
  const auto s = make_bdd_model_checker()->check(task);
  EXPECT_EQ(e.states, s.states);
  // IC3 too: a target per disagreement, read in the stable situations of its machine.
  const auto c = make_sat_model_checker({SatAlgorithm::Ic3, 200})->check(task);
  for (const auto* r : {&e, &s, &c}) {
    SCOPED_TRACE(r->engine);
    ASSERT_EQ(r->results.size(), 5u);
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_EQ(r->results[i].verdict, logic::Verdict::Holds) << r->results[i].formula;
    EXPECT_EQ(r->results[3].verdict, logic::Verdict::Violated);
    const auto& oc = r->results[4];
    EXPECT_EQ(oc.verdict, logic::Verdict::Violated);
    ASSERT_EQ(oc.findings.size(), 2u);
    EXPECT_NE(oc.findings[0].find("y is written by continuous actions (step 2) and by stored "
                                  "actions (steps 3, 1): a continuous action assigns it 1 while "
                                  "its stored value is 0, in situation {2}"),
              std::string::npos)
        << oc.findings[0];
    EXPECT_NE(oc.findings[1].find("its stored value is 1 while no continuous action assigns it"),
              std::string::npos)
        << oc.findings[1];
    ASSERT_TRUE(oc.trace);
    test::expect_trace_replays(*built.ts, *oc.trace);
  }
  // Without the stored actions the check has nothing to judge and holds.
  GrafcetBuilder plain;
  plain.input("a").output("y").chart("G").step("1", true).step("2");
  plain.transition({"1"}, {"2"}, test::v("a")).transition({"2"}, {"1"}, test::not_(test::v("a")));
  plain.continuous("2", "y");
  const auto p = make(plain.project(), true);
  ASSERT_TRUE(p.ts);
  auto plain_task = task_for(p.project, *p.ts, {}, {});
  plain_task.checks = {logic::StandardCheck::OutputConflicts};
  for (const auto& r : {make_explicit_model_checker()->check(plain_task),
                        make_bdd_model_checker()->check(plain_task),
                        make_sat_model_checker({SatAlgorithm::Ic3, 200})->check(plain_task)}) {
    ASSERT_EQ(r.results.size(), 1u);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds) << r.results[0].message;
  }
}

// An integer counter cannot also be a continuous action's output: a located error.
TEST(GrafcetBdd, IntegerVariableWithAContinuousActionIsRejected) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.local("k", model::Type::integer("INT", 0, 3));
  b.transition({"1"}, {"2"}, test::v("a")).transition({"2"}, {"1"}, test::not_(test::v("a")));
  b.stored("2", model::StoredWhen::Activation, "k", test::num(1));
  b.continuous("1", "k");
  b.pou().associations.back().where = {"k.g7", 7, 3, ""};
  semantics::GrafcetOptions o;
  model::Diagnostics d;
  const auto project = b.project();
  EXPECT_FALSE(semantics::make_grafcet_system(project, o, d));
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d.front().str(), "k.g7:7:3: error: continuous action on non-Boolean variable 'k'");
}

// A counter stored out of its range is a range error, not a successor.
TEST(GrafcetBdd, StoredValueOutOfRangeIsARangeError) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.local("k", model::Type::integer("INT", 0, 1));
  b.transition({"1"}, {"2"}, test::rise(test::v("a")))
      .transition({"2"}, {"1"}, test::fall(test::v("a")));
  b.stored("2", model::StoredWhen::Activation, "k",
           model::make_binary(ExprKind::Add, test::v("k"), test::num(1)));
  const auto built = make(b.project(), true);
  auto task = task_for(built.project, *built.ts, {"EF k = 1"}, {});
  task.checks = {logic::StandardCheck::Instability};
  const auto e = make_explicit_model_checker()->check(task);
  const auto s = make_bdd_model_checker()->check(task);
  EXPECT_EQ(e.states, s.states);
  ASSERT_EQ(s.results.size(), 2u);
  EXPECT_EQ(s.results[0].verdict, logic::Verdict::Holds);
  EXPECT_EQ(e.results[1].verdict, logic::Verdict::Violated);
  EXPECT_EQ(s.results[1].verdict, logic::Verdict::Violated);
}

Built load_file(const std::string& path, bool single = true) {
  auto loaded = io::load_file(path);
  if (!loaded.project) {
    ADD_FAILURE() << "not loaded: " << path;
    return {};
  }
  return make(std::move(*loaded.project), single);
}

void expect_same_counts(const Built& b) {
  ASSERT_TRUE(b.ts);
  auto task = task_for(b.project, *b.ts, {}, {});
  const auto e = make_explicit_model_checker()->check(task);
  const auto s = make_bdd_model_checker()->check(task);
  EXPECT_TRUE(e.complete);
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(e.states, s.states);
}

TEST(GrafcetBdd, PalletTransferExample) {
  for (const char* f : {"examples/pallet_transfer/pallet_transfer.g7",
                        "examples/pallet_transfer/pallet_transfer_fixed.g7"}) {
    SCOPED_TRACE(f);
    const auto b = load_file(test::source_path(f));
    ASSERT_TRUE(b.ts);
    // The collision of seed 002: reachable in the flawed chart, not in the fixed one.
    auto task = task_for(b.project, *b.ts,
                         {"AG !(X10 & X25)", "EF (X1 & X10 & X20 & X25 & X31 & X40)"}, {});
    task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions,
                   logic::StandardCheck::GlobalDeadlock, logic::StandardCheck::Instability};
    const auto e = make_explicit_model_checker()->check(task);
    const auto s = make_bdd_model_checker()->check(task);
    EXPECT_EQ(s.states, std::string(f).find("fixed") == std::string::npos ? 9192u : 8272u);
    EXPECT_EQ(e.states, s.states);
    ASSERT_EQ(e.results.size(), s.results.size());
    for (std::size_t i = 0; i < e.results.size(); ++i) {
      EXPECT_EQ(e.results[i].verdict, s.results[i].verdict) << e.results[i].name;
      if (s.results[i].trace) test::expect_trace_replays(*b.ts, *s.results[i].trace);
    }
  }
  expect_same_counts(load_file(test::source_path("examples/pistons/pistons.g7")));
}

TEST(GrafcetBdd, TransferLineFamily) {
  for (std::uint32_t n : {1u, 2u, 3u, 4u}) {
    auto loaded = io::load_g7(bench::transfer_line_g7(n, 2), "line.g7");
    ASSERT_TRUE(loaded.project);
    expect_same_counts(make(std::move(*loaded.project), true));
  }
}

TEST(GrafcetBdd, CorpusGrafcets) {
  SFCV_REQUIRE_CORPUS(corpus);
  for (const char* f :
       {"24_agrafe_exclusive_selection.grafcet", "25_agrafe_hierarchical_conflict1.grafcet",
        "26_agrafe_step_reachability3.grafcet"})
    for (bool single : {true, false}) {
      SCOPED_TRACE(std::string(f) + (single ? "" : " --multi-input-change"));
      expect_same_counts(load_file((corpus / f).string(), single));
    }
}

}  // namespace
}  // namespace sfcv::engine

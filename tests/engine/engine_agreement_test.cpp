// The explicit and the BDD engine on the same tasks (like Storm's typed suites, and mCRL2's
// random tests): identical reachable-state and edge counts and verdicts on generated charts,
// for random CTL formulas (every operator) with and without fairness and for the standard
// checks both answer; every BDD trace starts in an initial state, replays through `simulate`,
// and is a genuine counterexample or witness: judged against the explicit engine's labelling,
// step by step along the structure both engines explain.

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>
#include <sstream>

#include "chart_families.hpp"
#include "engine/bdd/bdd_manager.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/bdd/symbolic_system.hpp"
#include "engine/explicit/ctl_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "logic/push_negation.hpp"
#include "model/errors.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/check_findings.hpp"
#include "support/ctl_task.hpp"

namespace sfcv::engine {
namespace {

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  bool standard_priority = true;  ///< false: --priority none, conflicts are checked
};

Setup load(const std::string& text, semantics::Iec61131Options options = {},
           const std::vector<std::string>& assume = {}) {
  Setup s;
  auto loaded = io::load_iec_text(text, "generated.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  model::Diagnostics diags;
  if (!assume.empty()) {
    logic::CheckInputs in;
    in.assume = assume;
    auto parsed = logic::parse_check_inputs(in);
    for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
    options.assumptions = logic::assumption_exprs(parsed.spec);
  }
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts) << (diags.empty() ? "" : diags.front().str());
  s.standard_priority = options.priority == semantics::PriorityMode::Standard;
  return s;
}

using test::FormulaGenerator;

logic::CheckTask task_for(const Setup& s, const std::vector<std::string>& ctl,
                          const std::vector<std::string>& fair) {
  return test::task_for(s.project, *s.ts, ctl, fair);
}

void expect_replays(const semantics::TransitionSystem& ts, const logic::Trace& trace) {
  ASSERT_FALSE(trace.steps.empty());
  std::vector<std::vector<std::int64_t>> inputs;
  for (std::size_t k = 1; k < trace.steps.size(); ++k) inputs.push_back(trace.steps[k].inputs);
  const auto run = semantics::simulate(ts, trace.steps.front().state, inputs);
  ASSERT_TRUE(run.ok) << run.error;
  ASSERT_EQ(run.states.size(), trace.steps.size());
  for (std::size_t k = 0; k < trace.steps.size(); ++k)
    EXPECT_EQ(run.states[k], trace.steps[k].state) << "cycle " << k;
  if (trace.loop_start) {
    ASSERT_LT(*trace.loop_start, trace.steps.size() - 1);
    EXPECT_EQ(trace.steps.back().state, trace.steps[*trace.loop_start].state);
  }
}

/// Judges a trace against the explicit labelling: it must explain `f` from its first state the
/// way CtlChecker::explain() does (EX: the next state; E[p U q]: p states up to the first q
/// state; EG p: p states to the end, which loops through every fair set or is a deadlock).
class TraceJudge {
 public:
  TraceJudge(const ReachableSituationGraph& g, CtlChecker& c) : g_(g), c_(c) {}

  std::string judge(const logic::FormulaPtr& f, const logic::Trace& t) {
    t_ = &t;
    index_.clear();
    for (const auto& step : t.steps) {
      const auto i = g_.states().find(step.state);
      if (i == StateStore::kAbsent) return "a trace state is not reachable";
      index_.push_back(i);
    }
    const auto& init = g_.initial_states();
    if (std::find(init.begin(), init.end(), index_.front()) == init.end())
      return "the trace does not start in an initial state";
    lasso_seen_ = false;
    end_ = 0;
    auto why = at(f, 0, 0);
    if (!why.empty()) return why;
    if ((t.loop_start || t.ends_in_deadlock) && !lasso_seen_) return "a lasso no EG asked for";
    if (end_ + 1 != t.steps.size())
      return "the trace goes on after its explanation ends (at step " + std::to_string(end_) + ")";
    return "";
  }

 private:
  bool holds(const logic::FormulaPtr& f, std::size_t i) { return c_.sat(f)[index_[i]] != 0; }
  bool fair(std::size_t i) { return !c_.has_fairness() || c_.fair_states()[index_[i]] != 0; }

  std::string at(const logic::FormulaPtr& f, std::size_t i, int depth) {
    using logic::Op;
    end_ = i;
    if (!holds(f, i))
      return "step " + std::to_string(i) + " does not satisfy " + logic::to_string(f);
    if (depth > 8) return "";
    const auto& a = f->args;
    switch (f->op) {
      case Op::Not: {
        auto pushed = logic::push_negation(a[0]);
        if (pushed->op == Op::Not) return "";
        keep_.push_back(pushed);
        return at(pushed, i, depth + 1);
      }
      case Op::And: {
        const auto& pick = logic::is_propositional(*a[0]) ? a[1] : a[0];
        return logic::is_propositional(*pick) ? "" : at(pick, i, depth + 1);
      }
      case Op::Or:
      case Op::Implies: {
        auto first = f->op == Op::Implies ? logic::make_not(a[0]) : a[0];
        keep_.push_back(first);
        std::vector<logic::FormulaPtr> order = {first, a[1]};
        if (logic::is_propositional(*first)) std::swap(order[0], order[1]);
        for (const auto& cand : order)
          if (holds(cand, i)) return logic::is_propositional(*cand) ? "" : at(cand, i, depth + 1);
        return "no disjunct holds";
      }
      case Op::EX:
        if (i + 1 >= index_.size()) return "EX: the trace ends";
        if (!fair(i + 1)) return "EX: the next state is not fair";
        return at(a[0], i + 1, depth + 1);
      case Op::EF:
      case Op::EU: {
        const auto& target = f->op == Op::EF ? a[0] : a[1];
        for (std::size_t j = i; j < index_.size(); ++j) {
          if (holds(target, j) && fair(j)) return at(target, j, depth + 1);
          if (f->op == Op::EU && !holds(a[0], j))
            return "E[p U q]: step " + std::to_string(j) + " satisfies neither";
        }
        return "E[p U q] / EF: the trace ends before its target";
      }
      case Op::EG: {
        for (std::size_t j = i; j < index_.size(); ++j)
          if (!holds(a[0], j)) return "EG: step " + std::to_string(j) + " leaves p";
        lasso_seen_ = true;
        end_ = index_.size() - 1;
        if (t_->loop_start) {
          if (*t_->loop_start < i) return "EG: the loop starts before the EG state";
          if (c_.has_fairness()) {
            const auto& fairness = fairness_;
            for (const auto& fs : fairness) {
              bool met = false;
              for (std::size_t j = *t_->loop_start; j < index_.size(); ++j) met |= holds(fs, j);
              if (!met) return "EG: the loop misses a fairness constraint";
            }
          }
          return "";
        }
        if (t_->ends_in_deadlock) {
          if (c_.has_fairness()) return "EG: a finite run under fairness";
          const auto last = index_.back();
          if (g_.edges_end(last) > g_.edges_begin(last))
            return "EG: the last state has a successor";
          return "";
        }
        return "EG: neither a loop nor a deadlock";
      }
      default:
        return "";
    }
  }

 public:
  std::vector<logic::FormulaPtr> fairness_;

 private:
  const ReachableSituationGraph& g_;
  CtlChecker& c_;
  const logic::Trace* t_ = nullptr;
  std::vector<std::uint32_t> index_;
  std::vector<logic::FormulaPtr> keep_;
  bool lasso_seen_ = false;
  std::size_t end_ = 0;
};

struct Tally {
  int traces = 0, lassos = 0, deadlocks = 0;
  int check_violations = 0, stored_violations = 0, conflict_violations = 0;
};
Tally g_tally;

void compare_engines(const Setup& s, std::uint64_t seed, bool with_fairness,
                     const BddEngineOptions& bdd_options = {},
                     const std::vector<std::string>& extra = {}) {
  FormulaGenerator gen(*s.ts, seed);
  std::vector<std::string> ctl;
  for (int i = 0; i < 12; ++i) ctl.push_back(gen.formula(3));
  ctl.push_back("AG !(" + gen.atom() + " & " + gen.atom() + ")");
  ctl.push_back("EF (" + gen.atom() + " & " + gen.atom() + ")");
  ctl.push_back("AF " + gen.atom());
  ctl.push_back("EG " + gen.atom());
  ctl.push_back("A[" + gen.atom() + " U " + gen.atom() + "]");
  ctl.push_back("AG (" + gen.atom() + " -> AX EX " + gen.atom() + ")");
  for (const auto& e : extra) ctl.push_back(e);
  std::vector<std::string> fair;
  if (with_fairness) fair = {gen.atom(), "!" + gen.atom()};
  auto task = task_for(s, ctl, fair);
  task.priority_resolves_conflicts = s.standard_priority;
  // Under fairness re-entry adds its AG AF row (reentry-fair).
  if (!with_fairness)
    task.checks = {logic::StandardCheck::Reachable,       logic::StandardCheck::DeadTransitions,
                   logic::StandardCheck::Reentry,         logic::StandardCheck::GlobalDeadlock,
                   logic::StandardCheck::LocalDeadlock,   logic::StandardCheck::InitialReturn,
                   logic::StandardCheck::Conflicts,       logic::StandardCheck::StoredActions,
                   logic::StandardCheck::OutputConflicts, logic::StandardCheck::Instability};
  else
    task.checks = {logic::StandardCheck::Reentry};
  const auto explicit_report = make_explicit_model_checker()->check(task);
  const auto bdd = make_bdd_model_checker(bdd_options);
  ASSERT_TRUE(bdd->can_handle(task));
  const auto bdd_report = bdd->check(task);
  EXPECT_EQ(explicit_report.states, bdd_report.states);
  EXPECT_TRUE(bdd_report.edges_known);
  EXPECT_EQ(explicit_report.edges, bdd_report.edges);
  const auto graph = build_reachable_situation_graph(*s.ts);
  CtlChecker labelling(graph, task.fairness);
  TraceJudge judge(graph, labelling);
  judge.fairness_ = task.fairness;
  ASSERT_EQ(explicit_report.results.size(), bdd_report.results.size());
  for (std::size_t i = 0; i < explicit_report.results.size(); ++i) {
    const auto& e = explicit_report.results[i];
    const auto& b = bdd_report.results[i];
    SCOPED_TRACE(e.name + " " + e.formula);
    EXPECT_EQ(e.verdict, b.verdict)
        << "explicit " << logic::to_string(e.verdict) << ", bdd " << logic::to_string(b.verdict);
    if (b.trace) expect_replays(*s.ts, *b.trace);
    if (i >= task.properties.size()) {
      test::expect_same_check(e, b);
      g_tally.check_violations += b.verdict == logic::Verdict::Violated;
      g_tally.stored_violations +=
          b.check == "stored-actions" && b.verdict == logic::Verdict::Violated;
      g_tally.conflict_violations +=
          b.check == "conflicts" && b.verdict == logic::Verdict::Violated;
      continue;
    }
    // Both engines give a trace for the same verdicts, and the BDD's explains the formula.
    EXPECT_EQ(e.trace.has_value(), b.trace.has_value());
    if (!b.trace) continue;
    const auto& f = task.properties[i].formula;
    const bool violated = b.verdict == logic::Verdict::Violated;
    EXPECT_EQ(b.trace->kind,
              violated ? logic::TraceKind::Counterexample : logic::TraceKind::Witness);
    const auto explained = violated ? logic::push_negation(f) : f;
    EXPECT_EQ(judge.judge(explained, *b.trace), "");
    ++g_tally.traces;
    g_tally.lassos += b.trace->loop_start.has_value();
    g_tally.deadlocks += b.trace->ends_in_deadlock;
    // Shortest runs to a state: the same length as the explicit engine's BFS.
    if ((f->op == logic::Op::AG || f->op == logic::Op::EF) &&
        logic::is_propositional(*f->args[0]) && e.trace) {
      EXPECT_EQ(e.trace->steps.size(), b.trace->steps.size());
    }
  }
}

TEST(EngineAgreement, RandomChartsAndFormulas) {
  g_tally = {};
  for (std::uint64_t seed = 1; seed <= 15; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s =
        load(bench::random_chart_iec(10 + static_cast<std::uint32_t>(seed % 7), 3, seed));
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false);
    compare_engines(s, seed + 100, true);
  }
  // The judge saw every kind of trace: runs to a state, and lassos.
  EXPECT_GT(g_tally.traces, 200);
  EXPECT_GT(g_tally.lassos, 10);
  // The standard checks were compared on charts that fail them, stored actions included.
  EXPECT_GT(g_tally.check_violations, 20) << g_tally.check_violations;
  EXPECT_GT(g_tally.stored_violations, 2) << g_tally.stored_violations;
}

// The checks that read AG EF from the bottom components of the reached graph (reentry,
// local-deadlock, global-deadlock, initial-return: engine/standard_check_runner.hpp) against
// what they mean, judged without the runner: each step's formula labelled by the explicit CTL
// checker, and backward closures on the explicit graph, on charts with one or several bottom
// components and, under an assumption, with situations left without a successor.
TEST(EngineAgreement, BottomComponentChecksAgreeWithTheirFormulas) {
  int mixed = 0, stuck = 0, deadlocked = 0, unreturning = 0;
  for (std::uint64_t seed = 200; seed < 320; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s =
        load(bench::random_chart_iec(10 + static_cast<std::uint32_t>(seed % 9), 3, seed), {},
             seed % 4 == 0 ? std::vector<std::string>{"!S3"} : std::vector<std::string>{});
    ASSERT_TRUE(s.ts);
    auto task = task_for(s, {}, {});
    task.max_findings = 0;
    task.checks = {logic::StandardCheck::Reentry, logic::StandardCheck::GlobalDeadlock,
                   logic::StandardCheck::LocalDeadlock, logic::StandardCheck::InitialReturn};
    const auto g = build_reachable_situation_graph(*s.ts);
    ASSERT_TRUE(g.complete());
    CtlChecker labelling(g, {});
    auto initially = [&](const logic::FormulaPtr& f) {
      const auto sat = labelling.sat(f);
      for (auto i : g.initial_states())
        if (!sat[i]) return false;
      return true;
    };
    // Whether some reached state cannot reach a state of `target` (a backward closure).
    auto some_cannot_reach = [&](std::vector<bool> reaches) {
      for (bool changed = true; changed;) {
        changed = false;
        for (std::uint32_t x = 0; x < g.num_states(); ++x)
          for (auto e = g.edges_begin(x); e < g.edges_end(x) && !reaches[x]; ++e)
            if (reaches[g.target(e)]) reaches[x] = changed = true;
      }
      return std::find(reaches.begin(), reaches.end(), false) != reaches.end();
    };
    std::vector<bool> fires(g.num_states()), initial_activity(g.num_states());
    const auto steps = logic::step_refs(*s.ts, &s.project);
    for (std::uint32_t x = 0; x < g.num_states(); ++x) {
      for (auto e = g.edges_begin(x); e < g.edges_end(x); ++e)
        fires[x] = fires[x] || !g.fired(e).empty();
      bool same = true;
      for (const auto& step : steps)
        same =
            same && s.ts->observe(g.states().at(x), step.observable) ==
                        s.ts->observe(g.states().at(g.initial_states().front()), step.observable);
      initial_activity[x] = same;
      stuck += g.edges_begin(x) == g.edges_end(x);
    }
    const bool dead = some_cannot_reach(fires), no_return = some_cannot_reach(initial_activity);
    deadlocked += dead;
    unreturning += no_return;
    auto flagged = [](const logic::PropertyResult& r, const std::string& prefix) {
      return std::any_of(r.findings.begin(), r.findings.end(),
                         [&](const std::string& f) { return f.rfind(prefix, 0) == 0; });
    };
    std::size_t reentrant = 0, not_reentrant = 0;
    for (const auto& engine : {make_explicit_model_checker(), make_bdd_model_checker()}) {
      const auto report = engine->check(task);
      ASSERT_EQ(report.results.size(), 4u);
      const auto& reentry = report.results[0];
      const auto& global = report.results[1];
      const auto& local = report.results[2];
      const auto& back = report.results[3];
      SCOPED_TRACE(std::string(engine->name()));
      EXPECT_EQ(global.verdict == logic::Verdict::Violated, dead);
      EXPECT_EQ(back.verdict == logic::Verdict::Violated, no_return);
      reentrant = not_reentrant = 0;
      for (const auto& step : steps) {
        const auto name = "step " + logic::describe_step(step);
        SCOPED_TRACE(name);
        if (flagged(reentry, name + " (crossed only")) continue;  // transient: another rule
        const auto x = logic::observable_atom(*s.ts, step.observable);
        const bool holds = initially(logic::reentry_formula(*s.ts, step.observable));
        if (step.on_loop) {
          EXPECT_EQ(flagged(reentry, name + ":"), !holds);
          ++(holds ? reentrant : not_reentrant);
        }
        const auto never_left =
            logic::make_op(logic::Op::EF, {logic::make_and(x, logic::make_op(logic::Op::AG, {x}))});
        const auto nx = logic::make_not(x);
        const auto never_back = logic::make_op(
            logic::Op::EF, {logic::make_and(nx, logic::make_op(logic::Op::AG, {nx}))});
        EXPECT_EQ(flagged(local, name + ", once active, is never left"),
                  !initially(logic::make_not(never_left)));
        EXPECT_EQ(flagged(local, name + ", once inactive, never becomes active again"),
                  !initially(logic::make_not(never_back)));
      }
    }
    mixed += reentrant > 0 && not_reentrant > 0;
  }
  // The charts exercise what the components decide: steps that can and cannot be re-entered
  // side by side, deadlocks, no return, and situations without a successor.
  EXPECT_GT(mixed, 5) << mixed;
  EXPECT_GT(deadlocked, 2) << deadlocked;
  EXPECT_GT(unreturning, 5) << unreturning;
  EXPECT_GT(stuck, 0) << stuck;
}

TEST(EngineAgreement, NondeterministicConflicts) {
  semantics::Iec61131Options options;
  options.priority = semantics::PriorityMode::None;
  for (std::uint64_t seed = 30; seed <= 35; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(12, 3, seed), options);
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false);
  }
}

// `conflicts` under --priority none: the same findings on both engines (the BDD engine finds
// the situations on its sets and expands them), on charts of several sizes, some of them with
// timed qualifiers and nested charts.
TEST(EngineAgreement, ConflictsWithoutPriority) {
  g_tally = {};
  semantics::Iec61131Options options;
  options.priority = semantics::PriorityMode::None;
  for (std::uint64_t seed = 50; seed <= 65; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    bench::RandomChartFeatures features;
    features.timed_qualifiers = seed % 3 == 0;
    features.nested_chart = seed % 4 == 0;
    const auto s =
        load(bench::random_chart_iec(8 + static_cast<std::uint32_t>(seed % 9), 3, seed, features),
             options);
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false);
  }
  EXPECT_GT(g_tally.conflict_violations, 5) << g_tally.conflict_violations;
}

TEST(EngineAgreement, TimedQualifiersAndNestedCharts) {
  bench::RandomChartFeatures features;
  features.timed_qualifiers = true;
  features.nested_chart = true;
  for (std::uint64_t seed = 40; seed <= 49; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    semantics::Iec61131Options options;
    options.time = seed % 2 == 0 ? semantics::TimeMode::Abstract : semantics::TimeMode::Discrete;
    const auto s = load(bench::random_chart_iec(12, 3, seed, features), options);
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false);
    compare_engines(s, seed + 100, true);
  }
}

// CODESYS's SFCInit/SFCReset: the resets add runs the engines must all see.
TEST(EngineAgreement, SfcInitAndSfcReset) {
  bench::RandomChartFeatures features;
  features.sfc_flags = true;
  for (std::uint64_t seed = 60; seed <= 67; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    features.nested_chart = seed % 2 == 0;
    const auto s = load(bench::random_chart_iec(10, 2, seed, features));
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false);
  }
}

TEST(EngineAgreement, Families) {
  for (const auto& text :
       {bench::tanks_iec(2, true), bench::tanks_iec(2, false), bench::nested_charts_iec(3),
        bench::parallel_branches_iec(5, true), bench::parallel_branches_iec(4, false)}) {
    const auto s = load(text);
    ASSERT_TRUE(s.ts);
    compare_engines(s, 77, false);
    compare_engines(s, 78, true);
  }
}

// Assumptions on the state leave some reachable states without successor: maximal finite runs,
// EG witnesses that end in a deadlock.
TEST(EngineAgreement, DeadlocksEndRuns) {
  g_tally = {};
  const std::string cycle = R"(PROGRAM Cycle
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; END_VAR
  INITIAL_STEP S0: END_STEP
  STEP S1: q(N); END_STEP
  STEP S2: END_STEP
  STEP S3: END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
  TRANSITION FROM S1 TO S2 := go; END_TRANSITION
  TRANSITION FROM S1 TO S3 := NOT go; END_TRANSITION
  TRANSITION FROM S3 TO S0 := go; END_TRANSITION
  TRANSITION FROM S2 TO S0 := go; END_TRANSITION
END_PROGRAM
)";
  const auto s = load(cycle, {}, {"!S2"});
  ASSERT_TRUE(s.ts);
  const std::vector<std::string> extra = {"AG AF S1",
                                          "EG !S1",
                                          "AF S0",
                                          "AG EX TRUE",
                                          "E[!S1 U S2]",
                                          "EF EG q",
                                          "AG (S1 -> EX EG !q)",
                                          "EF EG S2",
                                          "AG AF !S2",
                                          "AG (S1 -> AX AF S0)"};
  compare_engines(s, 1, false, {}, extra);
  compare_engines(s, 2, true, {}, extra);
  for (std::uint64_t seed = 40; seed <= 45; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto r = load(bench::random_chart_iec(9, 2, seed), {}, {"!(S3 & i0)", "!S4"});
    ASSERT_TRUE(r.ts);
    compare_engines(r, seed, false, {}, {"AG AF S0", "EG !S0", "AG EF S4"});
    compare_engines(r, seed + 7, true);
  }
  EXPECT_GT(g_tally.deadlocks, 1);
}

// Charts for the simulated edges and images: random charts with abstract-time, choice and
// SFCReset inputs among the circuit's, with and without priorities, and two of the families.
struct SimulatedChart {
  std::string text;
  semantics::Iec61131Options options;
};
std::vector<SimulatedChart> simulated_charts() {
  std::vector<SimulatedChart> charts;
  for (std::uint64_t seed = 70; seed <= 81; ++seed) {
    bench::RandomChartFeatures features;
    features.timed_qualifiers = seed % 2 == 0;
    features.nested_chart = seed % 3 == 0;
    features.sfc_flags = seed % 4 == 1;
    features.writing_actions = seed % 5 == 2;
    semantics::Iec61131Options options;
    if (seed % 3 == 1) options.priority = semantics::PriorityMode::None;
    charts.push_back(
        {bench::random_chart_iec(10 + static_cast<std::uint32_t>(seed % 7), 3, seed, features),
         options});
  }
  charts.push_back({bench::tanks_iec(2, true), {}});
  charts.push_back({bench::parallel_branches_iec(5, true), {}});
  return charts;
}

/// Runs `check` on each chart of simulated_charts(), loaded, under a trace naming it.
template <class Check>
void for_each_simulated_chart(Check&& check) {
  const auto charts = simulated_charts();
  for (std::size_t k = 0; k < charts.size(); ++k) {
    SCOPED_TRACE("chart " + std::to_string(k));
    const auto s = load(charts[k].text, charts[k].options);
    ASSERT_TRUE(s.ts);
    check(s);
  }
}

// Edges are counted on the relation or by simulating the circuit on every reached state (the
// default on small sets with about a node per state): the same number both ways, and the
// explicit engine's.
TEST(EngineAgreement, EdgeCountsBySimulationAndOnTheRelation) {
  using How = SymbolicSystem::EdgeCounting;
  int simulated = 0;
  for_each_simulated_chart([&](const auto& s) {
    const auto task = task_for(s, {"AG TRUE"}, {});
    const auto explicit_report = make_explicit_model_checker()->check(task);
    const auto sys = make_symbolic_system(*s.ts);
    auto reached = sys->initial();
    for (auto frontier = reached; !frontier.is_false();) {
      frontier = sys->image(frontier) & !reached;
      reached = reached | frontier;
    }
    const auto on_relation = sys->count_edges(reached, How::Symbolic);
    const auto by_simulation = sys->count_edges(reached, How::Simulation);
    ASSERT_TRUE(on_relation.has_value());
    EXPECT_EQ(on_relation->str(), explicit_report.edges.str());
    if (by_simulation) {
      ++simulated;
      EXPECT_EQ(by_simulation->str(), on_relation->str());
    }
    EXPECT_EQ(sys->count_edges(reached)->str(), on_relation->str());
  });
  EXPECT_GE(simulated, 12);
}

// Images are computed on the relation or by simulating the circuit on every state of the set
// and building the successors' BDD from their sorted list (the default on sets of many nodes
// and few states per node): the same set both ways, for every ring of the reachability, for
// the whole reached set, and after a reordering has changed the variable levels.
TEST(EngineAgreement, ImagesBySimulationAndOnTheRelation) {
  using How = SymbolicSystem::ImageMethod;
  int rings = 0;
  for_each_simulated_chart([&](const auto& s) {
    const auto sys = make_symbolic_system(*s.ts);
    auto reached = sys->initial();
    for (auto frontier = reached; !frontier.is_false();) {
      const auto on_relation = sys->image(frontier, How::Symbolic);
      std::optional<std::uint64_t> edges;
      ASSERT_TRUE(sys->image(frontier, How::Simulation, &edges) == on_relation);
      // A simulated image counts the ring's edges as count_edges does on the relation.
      ASSERT_TRUE(edges.has_value());
      EXPECT_EQ(std::to_string(*edges),
                sys->count_edges(frontier, SymbolicSystem::EdgeCounting::Symbolic)->str());
      sys->image(frontier, How::Symbolic, &edges);
      EXPECT_FALSE(edges.has_value());
      ++rings;
      frontier = on_relation & !reached;
      reached = reached | frontier;
    }
    EXPECT_TRUE(sys->image(reached, How::Simulation) == sys->image(reached, How::Symbolic));
    bdd::reorder_now();
    EXPECT_TRUE(sys->image(reached, How::Simulation) == sys->image(reached, How::Symbolic));
    EXPECT_TRUE(sys->image(reached) == sys->image(reached, How::Symbolic));
  });
  EXPECT_GE(rings, 60);
}

// Reachability steps keep the reached states as keys while every ring is simulated: each
// step gives the ring and reached set of images on the relation, and the edges out of its
// frontier when it counts them, through a reordering (which drops the keys) and when fed a
// set that is not the previous step's.
TEST(EngineAgreement, ReachabilityStepsBySimulationAndOnTheRelation) {
  int counted = 0;
  for_each_simulated_chart([&](const auto& s) {
    const auto sys = make_symbolic_system(*s.ts);
    // The steps first: an image on the relation builds it, after which small rings are imaged
    // on it too.
    std::vector<SymbolicSystem::Step> steps;
    for (auto frontier = sys->initial(), reached = frontier; !frontier.is_false();) {
      steps.push_back(sys->step(frontier, reached));
      if (steps.size() == 3) bdd::reorder_now();
      frontier = steps.back().ring;
      reached = steps.back().reached;
    }
    auto frontier = sys->initial(), reached = frontier;
    for (std::size_t depth = 0; depth < steps.size(); ++depth) {
      SCOPED_TRACE("depth " + std::to_string(depth));
      const auto ring = sys->image(frontier, SymbolicSystem::ImageMethod::Symbolic) & !reached;
      ASSERT_TRUE(steps[depth].ring == ring);
      ASSERT_TRUE(steps[depth].reached == (reached | ring));
      if (steps[depth].edges) {
        ++counted;
        EXPECT_EQ(std::to_string(*steps[depth].edges),
                  sys->count_edges(frontier, SymbolicSystem::EdgeCounting::Symbolic)->str());
      }
      frontier = ring;
      reached = reached | ring;
    }
    EXPECT_TRUE(frontier.is_false());
    // A step from a set that no step gave: the keys are not used, the answer is the same.
    const auto all = sys->step(reached, reached);
    EXPECT_TRUE(all.ring.is_false());
    EXPECT_TRUE(all.reached == reached);
    const auto from_initial = sys->step(sys->initial(), sys->initial());
    EXPECT_TRUE(
        from_initial.ring ==
        (sys->image(sys->initial(), SymbolicSystem::ImageMethod::Symbolic) & !sys->initial()));
  });
  EXPECT_GE(counted, 40);
}

// After reachability by simulated steps, pre-images within the reached set are computed on the
// graph of the reached states' keys, without the relation: the same sets as the states whose
// successors (imaged one by one on the relation) meet the target, also after a reordering.
// Images of its subsets, and their edges, are the relation's; searches on the graph (closures,
// E[p U q]) are the fixpoints of those pre-images and images.
TEST(EngineAgreement, PreimagesOnTheReachedGraph) {
  int compared = 0;
  for_each_simulated_chart([&](const auto& s) {
    const auto sys = make_symbolic_system(*s.ts);
    std::vector<SymbolicSystem::Bdd> rings{sys->initial()};
    auto reached = sys->initial();
    for (auto frontier = reached; !frontier.is_false();) {
      auto step = sys->step(frontier, reached);
      frontier = step.ring;
      reached = step.reached;
      if (!frontier.is_false()) rings.push_back(frontier);
    }
    sys->restrict_sources(reached);
    std::vector<SymbolicSystem::Bdd> targets = rings;
    targets.push_back(reached);
    targets.push_back(reached & !sys->has_successor());
    std::vector<SymbolicSystem::Bdd> on_graph;
    for (const auto& t : targets) on_graph.push_back(sys->preimage(t));
    if (sys->has_relation()) return;  // a ring was imaged on the relation: no graph
    const auto states = sys->enumerate(reached, 100'000);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      auto expected = SymbolicSystem::Bdd::constant(false);
      for (const auto& state : states) {
        const auto one = sys->singleton(state);
        if (!(sys->image(one, SymbolicSystem::ImageMethod::Symbolic) & targets[t]).is_false())
          expected = expected | one;
      }
      EXPECT_TRUE(on_graph[t] == expected) << "target " << t;
      ++compared;
    }
    // Images of subsets of the (closed) reached set too, with their edges.
    for (std::size_t t = 0; t < targets.size(); ++t) {
      std::optional<std::uint64_t> edges;
      EXPECT_TRUE(sys->image(targets[t], SymbolicSystem::ImageMethod::Auto, &edges) ==
                  sys->image(targets[t], SymbolicSystem::ImageMethod::Symbolic))
          << "image of target " << t;
      ASSERT_TRUE(edges.has_value());
      EXPECT_EQ(std::to_string(*edges),
                sys->count_edges(targets[t], SymbolicSystem::EdgeCounting::Symbolic)->str());
    }
    // Searches on the graph: the fixpoints of those pre-images and images, through every
    // reached state or through the even rings only (E[p U q]).
    auto even_rings = SymbolicSystem::Bdd::constant(false);
    for (std::size_t r = 0; r < rings.size(); r += 2) even_rings = even_rings | rings[r];
    for (std::size_t t = 0; t < targets.size(); ++t) {
      for (const auto& through : {SymbolicSystem::Bdd::constant(true), even_rings}) {
        for (const bool backward : {true, false}) {
          if (!backward && !through.is_true()) continue;
          auto z = targets[t] & reached;
          for (auto previous = !z; !(previous == z);) {
            previous = z;
            z = z | (reached & through & (backward ? sys->preimage(z) : sys->image(z)));
          }
          const auto searched = sys->reach_on_reached_graph(targets[t], through, backward);
          ASSERT_TRUE(searched.has_value());
          EXPECT_TRUE(*searched == z) << "target " << t << (backward ? " backward" : " forward");
        }
      }
    }
    bdd::reorder_now();
    for (std::size_t t = 0; t < targets.size(); ++t)
      EXPECT_TRUE(sys->preimage(targets[t]) == on_graph[t]) << "after reordering, target " << t;
  });
  EXPECT_GE(compared, 60);
}

// A simulated step reads the clock: past the deadline it throws LimitReached(Time) and leaves
// no half-made keys behind, so the next step is still right. The deadline check is the
// run's (--timeout), which a simulation would otherwise outlast (it makes no BDD node).
TEST(EngineAgreement, SimulatedStepsMeetTheDeadline) {
  const auto s = load(bench::random_chart_iec(30, 4, 2));
  ASSERT_TRUE(s.ts);
  const auto sys = make_symbolic_system(*s.ts);
  const auto first = sys->step(sys->initial(), sys->initial());
  ASSERT_TRUE(first.edges.has_value());  // simulated: the keys are kept
  {
    const bdd::DeadlineScope past(std::chrono::steady_clock::now() - std::chrono::seconds(1));
    EXPECT_THROW(sys->step(first.ring, first.reached), LimitReached);
  }
  const auto second = sys->step(first.ring, first.reached);
  EXPECT_TRUE(second.ring ==
              (sys->image(first.ring, SymbolicSystem::ImageMethod::Symbolic) & !first.reached));
  EXPECT_TRUE(second.reached == (first.reached | second.ring));
}

// The relation is built on first use. Small random charts explore by simulation alone (and
// report the explicit engine's states and edges); a counter's thousands of one-state rings
// build it after a few dozen images; a pre-image builds it, and then agrees with the images.
TEST(EngineAgreement, RelationBuiltOnlyWhenNeeded) {
  auto explore = [](const SymbolicSystem& sys) {
    auto reached = sys.initial();
    for (auto frontier = reached; !frontier.is_false();) {
      frontier = sys.image(frontier) & !reached;
      reached = reached | frontier;
    }
    return reached;
  };
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(30, 4, seed));
    ASSERT_TRUE(s.ts);
    const auto task = task_for(s, {"AG TRUE"}, {});
    const auto explicit_report = make_explicit_model_checker()->check(task);
    const auto bdd_report = make_bdd_model_checker()->check(task);
    EXPECT_EQ(bdd_report.states, explicit_report.states);
    ASSERT_TRUE(bdd_report.edges_known);
    EXPECT_EQ(bdd_report.edges, explicit_report.edges);
    const auto sys = make_symbolic_system(*s.ts);
    const auto reached = explore(*sys);
    EXPECT_FALSE(sys->has_relation());
    EXPECT_EQ(sys->count_exact(reached), explicit_report.states);
    // Every reached state but the initial ones has a predecessor among the reached states.
    sys->restrict_sources(reached);
    const auto successors = sys->image(reached);
    EXPECT_TRUE((reached & !sys->initial() & !successors).is_false());
    EXPECT_TRUE((successors & !reached).is_false());
    EXPECT_TRUE((sys->preimage(successors) & reached) == (reached & sys->has_successor()));
    EXPECT_TRUE(sys->has_relation());
    EXPECT_TRUE(sys->image(reached, SymbolicSystem::ImageMethod::Symbolic) == successors);
  }
  const auto counter = load(bench::counter_iec(8));
  ASSERT_TRUE(counter.ts);
  const auto sys = make_symbolic_system(*counter.ts);
  explore(*sys);
  EXPECT_TRUE(sys->has_relation());
}

// Reordering changes the variable order, never an answer, a count or a trace's validity.
TEST(EngineAgreement, ReorderingOnAndOff) {
  BddEngineOptions reorder;
  reorder.reorder = ReorderMode::Once;
  const int before = bdd::reorderings();
  for (std::uint64_t seed = 50; seed <= 53; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(14, 3, seed));
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false, reorder);
    compare_engines(s, seed + 1, true, reorder);
  }
  const auto s = load(bench::parallel_branches_iec(6, true));
  ASSERT_TRUE(s.ts);
  compare_engines(s, 9, false, reorder);
  EXPECT_GE(bdd::reorderings(), before + 9);  // sifting ran under every one of them
}

// The three --reorder modes: the same verdicts and state counts on random charts (and each
// agrees with the explicit engine, traces included). A 1 K-node initial table makes dynamic
// sifting start during reachability and the fixpoints instead of never on charts this small.
TEST(EngineAgreement, ReorderModesGiveTheSameAnswers) {
  const int before = bdd::reorderings();
  for (std::uint64_t seed = 60; seed <= 65; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(18, 3, seed));
    ASSERT_TRUE(s.ts);
    FormulaGenerator gen(*s.ts, seed);
    std::vector<std::string> ctl;
    for (int i = 0; i < 10; ++i) ctl.push_back(gen.formula(3));
    ctl.push_back("AG !(" + gen.atom() + " & " + gen.atom() + ")");
    const auto task = task_for(s, ctl, {});
    std::vector<logic::CheckReport> reports;
    for (const auto mode : {ReorderMode::None, ReorderMode::Once, ReorderMode::Dynamic}) {
      BddEngineOptions o;
      o.reorder = mode;
      if (mode == ReorderMode::Dynamic) o.initial_nodes = 1 << 10;
      reports.push_back(make_bdd_model_checker(o)->check(task));
      compare_engines(s, seed, false, o);
    }
    for (std::size_t m = 1; m < reports.size(); ++m) {
      SCOPED_TRACE("mode " + std::to_string(m));
      EXPECT_EQ(reports[0].states, reports[m].states);
      EXPECT_EQ(reports[0].edges, reports[m].edges);
      ASSERT_EQ(reports[0].results.size(), reports[m].results.size());
      for (std::size_t i = 0; i < reports[0].results.size(); ++i)
        EXPECT_EQ(reports[0].results[i].verdict, reports[m].results[i].verdict)
            << reports[0].results[i].formula;
    }
  }
  // Once sifts 6 times; dynamic sifted on top of that.
  EXPECT_GT(bdd::reorderings(), before + 12);
}

// A node table too small for the relation: every answer unknown, no crash, no "holds"; the
// manager recovers for the next system. Four tanks read 16 inputs, too many to simulate: the
// first image already needs the relation.
TEST(EngineAgreement, TinyMemoryBudgetGivesUnknown) {
  const auto s = load(bench::tanks_iec(4, false));
  ASSERT_TRUE(s.ts);
  auto task = task_for(s, {"AG !(V1_0 & V3_0)", "EF (FA_0 & FA_1)"}, {});
  task.checks = {logic::StandardCheck::Reachable};
  task.limits.max_memory_bytes = 64 * 1024;
  const auto r = make_bdd_model_checker()->check(task);
  EXPECT_FALSE(r.complete);
  EXPECT_EQ(r.limit, "memory");
  EXPECT_FALSE(r.edges_known);
  ASSERT_EQ(r.results.size(), 3u);
  for (const auto& p : r.results) EXPECT_EQ(p.verdict, logic::Verdict::Unknown) << p.name;
  EXPECT_EQ(logic::exit_code(r), 3);
  task.limits.max_memory_bytes = 0;
  const auto again = make_bdd_model_checker()->check(task);
  EXPECT_TRUE(again.complete);
  EXPECT_EQ(again.results[2].verdict, logic::Verdict::Holds);
  EXPECT_EQ(bdd::live_bdds(), 0);
}

// Small budgets on a chart whose images are simulated (no relation needed to explore): each
// answer is the explicit engine's or unknown, the states are the explicit engine's whenever
// exploration completes, and edges are only reported when right. A budget that fits nothing
// ends with the memory limit.
TEST(EngineAgreement, SmallMemoryBudgetsAgreeOrAreUnknown) {
  const auto s = load(bench::parallel_branches_iec(8, true));
  ASSERT_TRUE(s.ts);
  auto task = task_for(s, {"AG !(B1 & B2)", "EF (B3 & O4)", "AG EF B1"}, {});
  task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::GlobalDeadlock};
  const auto reference = make_explicit_model_checker()->check(task);
  ASSERT_TRUE(reference.complete);
  int decided = 0, unknown = 0;
  for (const std::uint64_t kb : {1, 16, 32, 64, 128, 256, 1024}) {
    SCOPED_TRACE(std::to_string(kb) + " KB");
    task.limits.max_memory_bytes = kb * 1024;
    const auto r = make_bdd_model_checker()->check(task);
    if (kb == 1) {
      EXPECT_EQ(r.limit, "memory");
    }
    if (r.complete) {
      EXPECT_EQ(r.states, reference.states);
    }
    if (r.edges_known) {
      EXPECT_EQ(r.edges, reference.edges);
    }
    ASSERT_EQ(r.results.size(), reference.results.size());
    for (std::size_t i = 0; i < r.results.size(); ++i) {
      if (r.results[i].verdict == logic::Verdict::Unknown) {
        ++unknown;
        continue;
      }
      ++decided;
      EXPECT_EQ(r.results[i].verdict, reference.results[i].verdict) << r.results[i].name;
    }
  }
  EXPECT_GT(decided, 0);
  EXPECT_GT(unknown, 0);
  EXPECT_EQ(bdd::live_bdds(), 0);
}

TEST(EngineAgreement, ChemicalPlantVerdicts) {
  std::ifstream f(std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st");
  std::stringstream text;
  text << f.rdbuf();
  const auto s = load(text.str());
  ASSERT_TRUE(s.ts);
  auto task = task_for(s, {"AG !(V1 & V3)", "AG !(V2 & V4)"}, {});
  const auto r = make_bdd_model_checker()->check(task);
  ASSERT_EQ(r.results.size(), 2u);
  EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds);
  EXPECT_EQ(r.results[1].verdict, logic::Verdict::Violated);
  ASSERT_TRUE(r.results[1].trace);
  expect_replays(*s.ts, *r.results[1].trace);
  // The last state of the counterexample opens V2 and V4 together.
  const auto& last = r.results[1].trace->steps.back().state;
  std::string error;
  const auto v2 = semantics::find_observable(*s.ts, "V2", &error);
  const auto v4 = semantics::find_observable(*s.ts, "V4", &error);
  ASSERT_TRUE(v2 && v4) << error;
  EXPECT_EQ(s.ts->observe(last, *v2), 1);
  EXPECT_EQ(s.ts->observe(last, *v4), 1);
}

}  // namespace
}  // namespace sfcv::engine

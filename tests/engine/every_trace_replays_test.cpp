// Every counterexample and witness of every engine (explicit, bdd, bmc, kind, ic3, and auto's
// portfolio with the explicit probe skipped, so that bdd, ic3 and bmc race) on random
// IEC 61131-3 charts and random grafcets (both input hypotheses) replays through the library
// behind `sfcv simulate` from the trace's own rows, as the CSV and JSON traces give them:
// cycle by cycle from the initial configuration (semantics::simulate), or for a Grafcet event
// by event from the first row's initial inputs under the run's hypothesis
// (semantics::simulate_events: one input change per row under the single-input-change one,
// docs/semantics.md 2.15). Each row reaches the trace's situation, and the last row is where
// the property says: an AG p counterexample's last row violates p, an EF p witness's satisfies
// it. Issue 53 item 9: 146 of 253 BDD traces on Grafcet did not replay (a first row of zeros
// while the run started from a situation stabilised under other inputs; two inputs changing
// in one row).

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <map>
#include <optional>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/portfolio/portfolio_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/g7_writer.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/trace_replay.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/ctl_task.hpp"
#include "support/random_grafcet.hpp"

namespace sfcv::engine {
namespace {

using logic::Op;
using logic::Verdict;
using State = std::vector<semantics::StateWord>;

struct Chart {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  bool grafcet = false;
  bool single = true;  ///< Grafcet: the single-input-change hypothesis
  std::string kind() const {
    return !grafcet ? "iec" : single ? "grafcet" : "grafcet --multi-input-change";
  }
};

Chart iec_chart(std::uint64_t seed) {
  bench::RandomChartFeatures features;
  features.timed_qualifiers = seed % 3 == 0;
  features.writing_actions = seed % 4 == 1;
  Chart c;
  auto loaded = io::load_iec_text(
      bench::random_chart_iec(4 + static_cast<std::uint32_t>(seed % 4), 2, seed, features),
      "generated.st");
  EXPECT_TRUE(loaded.ok());
  c.project = std::move(*loaded.project);
  semantics::Iec61131Options options;
  if (seed % 4 == 2) options.priority = semantics::PriorityMode::None;
  model::Diagnostics d;
  c.ts = semantics::make_iec61131_system(c.project, options, d);
  EXPECT_TRUE(c.ts) << (d.empty() ? "" : d.front().str());
  return c;
}

Chart grafcet_chart(std::uint64_t seed, bool single) {
  Chart c;
  c.grafcet = true;
  c.single = single;
  c.project = test::random_grafcet(seed);
  semantics::GrafcetOptions o;
  o.single_input_change = single;
  model::Diagnostics d;
  c.ts = semantics::make_grafcet_system(c.project, o, d);
  EXPECT_TRUE(c.ts) << (d.empty() ? "" : d.front().str());
  return c;
}

/// A propositional formula in a state, from the system's own observe() (nullopt: the formula
/// reads something else, a previous value or a temporal operator).
std::optional<bool> evaluate(const semantics::TransitionSystem& ts, const logic::Formula& f,
                             const State& s) {
  auto arg = [&](std::size_t i) { return evaluate(ts, *f.args[i], s); };
  switch (f.op) {
    case Op::True:
      return true;
    case Op::False:
      return false;
    case Op::Atom:
    case Op::Compare: {
      if (f.observable < 0 || f.prev != 0) return std::nullopt;
      const auto v = ts.observe(s, static_cast<std::uint32_t>(f.observable));
      if (f.op == Op::Atom) return v != 0;
      switch (f.cmp) {
        case logic::CompareOp::Eq:
          return v == f.value;
        case logic::CompareOp::Ne:
          return v != f.value;
        case logic::CompareOp::Lt:
          return v < f.value;
        case logic::CompareOp::Le:
          return v <= f.value;
        case logic::CompareOp::Gt:
          return v > f.value;
        case logic::CompareOp::Ge:
          return v >= f.value;
      }
      return std::nullopt;
    }
    case Op::Not:
      if (auto a = arg(0)) return !*a;
      return std::nullopt;
    case Op::And:
    case Op::Or:
    case Op::Implies:
    case Op::Iff:
    case Op::Xor: {
      const auto a = arg(0), b = arg(1);
      if (!a || !b) return std::nullopt;
      if (f.op == Op::And) return *a && *b;
      if (f.op == Op::Or) return *a || *b;
      if (f.op == Op::Implies) return !*a || *b;
      if (f.op == Op::Iff) return *a == *b;
      return *a != *b;
    }
    default:
      return std::nullopt;
  }
}

/// Replays the trace's rows as `sfcv simulate` reads them: every row reaches the trace's
/// situation with the trace's fired transitions.
void expect_rows_replay(const Chart& c, const logic::Trace& trace) {
  // Failures here are not fatal: a long run (REPLAY_GRAFCET_SEEDS=300) lists every trace that
  // does not replay instead of stopping at the first.
  if (trace.steps.empty()) {
    ADD_FAILURE() << "a trace without rows";
    return;
  }
  semantics::SimulationResult run;
  std::vector<std::vector<std::int64_t>> rows;
  if (c.grafcet) {
    // The first row gives the initial inputs: the start is stabilised under them.
    for (const auto& s : trace.steps) rows.push_back(s.inputs);
    run = semantics::simulate_events(*c.ts, rows, c.single);
  } else {
    if (semantics::first_initial_state(*c.ts) != trace.steps.front().state) {
      ADD_FAILURE() << "the first row is not the initial configuration";
      return;
    }
    for (std::size_t k = 1; k < trace.steps.size(); ++k) rows.push_back(trace.steps[k].inputs);
    run = semantics::simulate(*c.ts, trace.steps.front().state, rows);
  }
  // On a failure, the grafcet and the trace's rows, to reproduce it with `sfcv simulate`.
  const auto dump = [&] {
    if (!c.grafcet) return std::string();
    std::string out = "\n";
    try {
      out += io::write_g7(c.project);
    } catch (const std::exception& e) {
      out += std::string("(no .g7: ") + e.what() + ")\n";
    }
    for (const auto& in : c.ts->inputs()) out += in.name + ",";
    out += "\n";
    for (const auto& s : trace.steps) {
      for (auto v : s.inputs) out += std::to_string(v) + ",";
      out += " state";
      for (auto w : s.state) out += " " + std::to_string(w);
      out += " fired";
      for (auto t : s.fired) out += " " + c.ts->transitions()[t].name;
      out += "\n";
    }
    return out;
  };
  if (!run.ok || run.states.size() != trace.steps.size()) {
    ADD_FAILURE() << "row " << run.failed_cycle << ": " << run.error << dump();
    return;
  }
  for (std::size_t k = 0; k < trace.steps.size(); ++k) {
    EXPECT_EQ(run.states[k], trace.steps[k].state) << "row " << k;
    if (k > 0) {
      EXPECT_EQ(run.fired[k - 1], trace.steps[k].fired) << "row " << k << dump();
    }
  }
}

struct Count {
  int traces = 0;     ///< traces replayed
  int last_rows = 0;  ///< of which the last row was judged (AG p violated, EF p witnessed)
};
using Tally = std::map<std::string, Count>;  // by "engine / kind of chart"

/// Replays every trace of `report`, and judges the last row of AG p counterexamples and EF p
/// witnesses.
void replay_all(const Chart& c, const logic::CheckTask& task, const logic::CheckReport& report,
                Count& count) {
  for (std::size_t i = 0; i < report.results.size(); ++i) {
    const auto& r = report.results[i];
    if (!r.trace) continue;
    SCOPED_TRACE(r.name + " " + r.formula);
    expect_rows_replay(c, *r.trace);
    ++count.traces;
    if (i >= task.properties.size()) continue;  // a standard check
    const auto& f = *task.properties[i].formula;
    const bool ag = f.op == Op::AG && r.verdict == Verdict::Violated;
    const bool ef = f.op == Op::EF && r.verdict == Verdict::Holds;
    if (!ag && !ef) continue;
    const auto at_end = evaluate(*c.ts, *f.args[0], r.trace->steps.back().state);
    if (!at_end) continue;
    EXPECT_EQ(*at_end, ef) << (ag ? "the counterexample's last row satisfies p"
                                  : "the witness's last row does not satisfy p");
    ++count.last_rows;
  }
}

bool step_or_output(const semantics::Observable& o) {
  return o.kind == semantics::ObservableKind::Step || o.is_output;
}

void check_chart(const Chart& c, std::uint64_t seed, Tally& tally) {
  test::FormulaGenerator gen(
      *c.ts, seed, c.grafcet ? test::FormulaGenerator::AtomFilter(step_or_output) : nullptr);
  const std::vector<std::string> ctl = {"AG !(" + gen.atom() + " & " + gen.atom() + ")",
                                        "AG (" + gen.atom() + " | " + gen.atom() + ")",
                                        "AG " + gen.atom(),
                                        "EF (" + gen.atom() + " & " + gen.atom() + ")",
                                        "EF " + gen.atom(),
                                        "AF " + gen.atom(),
                                        gen.formula(2),
                                        gen.formula(2)};
  auto task = test::task_for(c.project, *c.ts, ctl, {});
  task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions,
                 logic::StandardCheck::GlobalDeadlock, logic::StandardCheck::LocalDeadlock,
                 logic::StandardCheck::Instability};
  std::vector<std::pair<std::string, std::unique_ptr<ModelChecker>>> engines;
  engines.emplace_back("explicit", make_explicit_model_checker());
  engines.emplace_back("bdd", make_bdd_model_checker());
  for (auto [name, algorithm] :
       {std::pair{"bmc", SatAlgorithm::Bmc}, std::pair{"kind", SatAlgorithm::KInduction},
        std::pair{"ic3", SatAlgorithm::Ic3}}) {
    SatEngineOptions options;
    options.algorithm = algorithm;
    options.max_depth = 12;
    engines.emplace_back(name, make_sat_model_checker(options));
  }
  // --engine auto: on charts this small the explicit probe would answer (its traces are the
  // explicit engine's); without the probe the symbolic engines race and any of them may give
  // a property's trace.
  PortfolioOptions race;
  race.probe_states = 0;
  engines.emplace_back("auto", make_portfolio_model_checker(race));
  for (const auto& [name, engine] : engines) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(engine->can_handle(task));
    replay_all(c, task, engine->check(task), tally[name + " / " + c.kind()]);
    if (testing::Test::HasFatalFailure()) return;
  }
  // LTL lassos (explicit, and bdd on IEC 61131-3; bdd refuses LTL on a Grafcet).
  logic::CheckInputs in;
  in.ltl = {"G (" + gen.atom() + " -> F " + gen.atom() + ")", "F G " + gen.atom()};
  auto parsed = logic::parse_check_inputs(in);
  ASSERT_TRUE(parsed.diagnostics.empty());
  logic::CheckTask ltl;
  ltl.system = c.ts.get();
  ltl.project = &c.project;
  model::Diagnostics diags;
  logic::resolve_into(parsed.spec, *c.ts, ltl, diags);
  ASSERT_TRUE(diags.empty());
  for (const auto& [name, engine] : engines) {
    if (name != "explicit" && name != "bdd") continue;
    if (!engine->can_handle(ltl)) continue;
    SCOPED_TRACE(name + " LTL");
    replay_all(c, ltl, engine->check(ltl), tally[name + " LTL / " + c.kind()]);
    if (testing::Test::HasFatalFailure()) return;
  }
}

Chart g7_chart(const char* text, bool single) {
  Chart c;
  c.grafcet = true;
  c.single = single;
  auto loaded = io::load_g7(text, "hand.g7");
  EXPECT_TRUE(loaded.ok());
  c.project = std::move(*loaded.project);
  semantics::GrafcetOptions o;
  o.single_input_change = single;
  model::Diagnostics d;
  c.ts = semantics::make_grafcet_system(c.project, o, d);
  EXPECT_TRUE(c.ts) << (d.empty() ? "" : d.front().str());
  return c;
}

std::uint32_t transition_named(const semantics::TransitionSystem& ts, const std::string& name) {
  for (std::uint32_t t = 0; t < ts.transitions().size(); ++t)
    if (ts.transitions()[t].name.find(name) != std::string::npos) return t;
  ADD_FAILURE() << "no transition " << name;
  return 0;
}

// docs/semantics.md 2.15: a trace row lists the transitions that its own inputs clear, the ones
// `sfcv simulate` lists for it. Under --multi-input-change, from {1,20} with a and b false, a
// rising reaches the node {3,20} (a memorised) whether b is true (20 -> 21 -> 20 is crossed
// transiently: transitions 1, 2 and 3 fire) or false (only 1 fires). The explicit RSG keeps one
// edge per pair of nodes with the union of the fired sets, and its witness of EF X3 listed 1, 2
// and 3 for the row a = 1, b = 0 (issue 53: random grafcets 31 and 85, --multi-input-change).
TEST(EveryTraceReplays, ExplicitGrafcetRowListsWhatItsOwnInputsClear) {
  const char* text =
      "project p;\ninput a;\ninput b;\n"
      "grafcet G1 { step 1 initial; step 3; transition 1: 1 -> 3 when RE a; }\n"
      "grafcet G2 { step 20 initial; step 21; transition 2: 20 -> 21 when RE a & b;\n"
      "  transition 3: 21 -> 20 when 1; }\n";
  const auto c = g7_chart(text, false);
  ASSERT_TRUE(c.ts);
  const auto t1 = transition_named(*c.ts, "1"), t2 = transition_named(*c.ts, "2"),
             t3 = transition_named(*c.ts, "3");
  auto task = test::task_for(c.project, *c.ts, {"EF X3"}, {});
  const auto report = make_explicit_model_checker()->check(task);
  ASSERT_EQ(report.results.size(), 1U);
  ASSERT_EQ(report.results[0].verdict, Verdict::Holds);
  ASSERT_TRUE(report.results[0].trace);
  const auto& trace = *report.results[0].trace;
  expect_rows_replay(c, trace);
  const auto a = 0U, b = 1U;  // inputs in declaration order
  ASSERT_EQ(c.ts->inputs()[a].name, "a");
  ASSERT_EQ(c.ts->inputs()[b].name, "b");
  bool entered = false;
  for (std::size_t k = 1; k < trace.steps.size(); ++k) {
    const auto& row = trace.steps[k];
    if (trace.steps[k - 1].inputs[a] != 0 || row.inputs[a] != 1) continue;  // not a rise of a
    entered = true;
    const std::vector<std::uint32_t> expected =
        row.inputs[b] ? std::vector<std::uint32_t>{t1, t2, t3} : std::vector<std::uint32_t>{t1};
    EXPECT_EQ(row.fired, expected) << "row " << k << ", b = " << row.inputs[b];
  }
  EXPECT_TRUE(entered) << "the witness does not go through a rise of a";
}

std::size_t input_named(const semantics::TransitionSystem& ts, const std::string& name) {
  for (std::size_t i = 0; i < ts.inputs().size(); ++i)
    if (ts.inputs()[i].name == name) return i;
  ADD_FAILURE() << "no input " << name;
  return 0;
}

// docs/semantics.md 2.9 and 2.15: under the single-input-change hypothesis a trace row differs
// from the row before in one input; an integer input compared only with constants is kept as
// its region, so a value moving inside its region is no event of the RSG, yet a row that moves
// it while another input changes is two changes for `sfcv simulate`. With n : 0..9 read only
// as n >= 5 and `1 --n >= 5--> 2 --↑b--> 3`, the rows (b, n) = (0, 0) (0, 9) (1, 7) reach
// {1} {2} {3} but change b and n at once in the last row; minimise_input_changes keeps n at 9
// there (the bmc engine wrote such a row: issue 53, random grafcet 153).
const char* kRegionChart =
    "project p;\ninput b;\ninput n : 0..9;\n"
    "grafcet G { step 1 initial; step 2; step 3; transition 1: 1 -> 2 when n >= 5;\n"
    "  transition 2: 2 -> 3 when RE b; transition 3: 3 -> 1 when !b; }\n";

TEST(EveryTraceReplays, RowKeepsAnIntegerInputInsideItsRegionWhileAnotherChanges) {
  const auto c = g7_chart(kRegionChart, true);
  ASSERT_TRUE(c.ts);
  const auto b = input_named(*c.ts, "b"), n = input_named(*c.ts, "n");
  auto row = [&](std::int64_t bv, std::int64_t nv) {
    std::vector<std::int64_t> v(c.ts->inputs().size(), 0);
    v[b] = bv;
    v[n] = nv;
    return v;
  };
  const std::vector<std::vector<std::int64_t>> one_event = {row(0, 0), row(0, 9), row(1, 9)};
  const auto run = semantics::simulate_events(*c.ts, one_event, true);
  ASSERT_TRUE(run.ok) << run.error;
  logic::Trace trace;
  for (std::size_t k = 0; k < one_event.size(); ++k)
    trace.steps.push_back(
        {one_event[k], run.states[k], k ? run.fired[k - 1] : std::vector<std::uint32_t>{}});
  trace.steps[2].inputs = row(1, 7);  // the same region of n, the same situation {3}
  std::vector<std::vector<std::int64_t>> rows;
  for (const auto& s : trace.steps) rows.push_back(s.inputs);
  EXPECT_FALSE(semantics::simulate_events(*c.ts, rows, true).ok) << "b and n change at once";
  logic::minimise_input_changes(*c.ts, trace);
  EXPECT_EQ(trace.steps[2].inputs, row(1, 9));
  EXPECT_EQ(trace.steps[1].inputs, row(0, 9)) << "n must leave its region to reach {2}";
  expect_rows_replay(c, trace);
}

// The same chart on every engine: each row after the first changes one input (2.15). Whether a
// SAT model moves n inside its region is the solver's choice; the test above is the
// deterministic one.
TEST(EveryTraceReplays, GrafcetRowsChangeOneInputOnEveryEngine) {
  const auto c = g7_chart(kRegionChart, true);
  ASSERT_TRUE(c.ts);
  auto task = test::task_for(c.project, *c.ts, {"AG !X3", "AG !(X3 & n >= 5)"}, {});
  std::vector<std::pair<std::string, std::unique_ptr<ModelChecker>>> engines;
  engines.emplace_back("explicit", make_explicit_model_checker());
  engines.emplace_back("bdd", make_bdd_model_checker());
  for (auto [name, algorithm] :
       {std::pair{"bmc", SatAlgorithm::Bmc}, std::pair{"kind", SatAlgorithm::KInduction},
        std::pair{"ic3", SatAlgorithm::Ic3}}) {
    SatEngineOptions options;
    options.algorithm = algorithm;
    options.max_depth = 12;
    engines.emplace_back(name, make_sat_model_checker(options));
  }
  for (const auto& [name, engine] : engines) {
    SCOPED_TRACE(name);
    const auto report = engine->check(task);
    ASSERT_EQ(report.results.size(), 2U);
    for (const auto& r : report.results) {
      ASSERT_TRUE(r.trace) << r.formula;
      EXPECT_GE(r.trace->steps.size(), 2U) << r.formula;  // b rises at least
      expect_rows_replay(c, *r.trace);
      for (std::size_t k = 1; k < r.trace->steps.size(); ++k) {
        int changed = 0;
        for (std::size_t i = 0; i < c.ts->inputs().size(); ++i)
          changed += !c.ts->inputs()[i].pseudo &&
                     r.trace->steps[k].inputs[i] != r.trace->steps[k - 1].inputs[i];
        EXPECT_EQ(changed, 1) << r.formula << " row " << k;
      }
    }
  }
}

// REPLAY_SEEDS=N runs N IEC charts and N grafcets (each under both hypotheses) instead of CI's
// 12 and 16, REPLAY_FIRST=K from seed K (docs/exports.md records a run with 500);
// REPLAY_IEC_SEEDS and REPLAY_GRAFCET_SEEDS set one kind's count (0: none of that kind).
std::uint64_t env_or(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::stoull(v) : fallback;
}

TEST(EveryTraceReplays, EveryEngineOnRandomChartsAndGrafcets) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  const auto first = env_or("REPLAY_FIRST", 1);
  const auto iec_last = first - 1 + env_or("REPLAY_IEC_SEEDS", env_or("REPLAY_SEEDS", 12));
  const auto grafcet_last = first - 1 + env_or("REPLAY_GRAFCET_SEEDS", env_or("REPLAY_SEEDS", 16));
  for (std::uint64_t seed = first; seed <= iec_last; ++seed) {
    SCOPED_TRACE("iec seed " + std::to_string(seed));
    const auto c = iec_chart(seed);
    ASSERT_TRUE(c.ts);
    check_chart(c, seed, tally);
    if (HasFatalFailure()) return;
  }
  for (std::uint64_t seed = first; seed <= grafcet_last; ++seed)
    for (bool single : {true, false}) {
      SCOPED_TRACE("grafcet seed " + std::to_string(seed) +
                   (single ? "" : " --multi-input-change"));
      const auto c = grafcet_chart(seed, single);
      ASSERT_TRUE(c.ts);
      check_chart(c, seed, tally);
      if (HasFatalFailure()) return;
    }
  // Enough traces were replayed, by every engine on every kind of chart, and enough last rows
  // judged: a generator or an engine that stopped giving traces fails here, not silently.
  int total = 0;
  for (const auto& [key, n] : tally) {
    std::cout << "[ replayed ] " << key << ": " << n.traces << " traces, " << n.last_rows
              << " last rows judged\n";
    total += n.traces;
  }
  for (const std::string kind : {"iec", "grafcet", "grafcet --multi-input-change"}) {
    if ((kind == "iec" ? iec_last : grafcet_last) < first) continue;  // none of that kind run
    for (const std::string engine : {"explicit", "bdd", "bmc", "kind", "ic3", "auto"}) {
      const auto& n = tally[engine + " / " + kind];
      EXPECT_GE(n.traces, 20) << engine << " / " << kind;
      EXPECT_GE(n.last_rows, 10) << engine << " / " << kind;
    }
    EXPECT_GE(tally["explicit LTL / " + kind].traces, 5) << kind;
  }
  if (iec_last >= first) {
    EXPECT_GE(tally["bdd LTL / iec"].traces, 5);
  }
  if (iec_last >= first && grafcet_last >= first) {
    EXPECT_GE(total, 800);
  }
  std::cout << "[ replayed ] " << total << " traces in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
}

}  // namespace
}  // namespace sfcv::engine

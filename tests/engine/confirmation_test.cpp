// Confirmation of sfcv's invariant verdicts by outside checkers on the exports: Spin on the
// Promela export, ABC (pdr) on the AIGER export. Every verdict must agree with sfcv's explicit
// engine, and every counterexample they give must replay in semantics::simulate (the library
// behind `sfcv simulate`) to a state that violates the property. Skipped, visibly, when spin
// or berkeley-abc is not installed (scripts/install-deps.sh installs both).

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "chart_families.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/external/abc_runner.hpp"
#include "engine/external/export_model.hpp"
#include "engine/external/spin_runner.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/boolean_action_chart.hpp"
#include "support/hostile_names.hpp"
#include "support/loop_limit_chart.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::engine {
namespace {

struct Checked {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  logic::CheckTask task;
  logic::CheckReport report;  ///< sfcv's own verdicts (explicit engine)
};

std::unique_ptr<Checked> check_project(
    model::Project project, const std::vector<std::string>& ctl,
    const std::vector<std::string>& assume = {},
    semantics::VendorDialect dialect = semantics::VendorDialect::Iec) {
  auto c = std::make_unique<Checked>();
  c->project = std::move(project);
  logic::CheckInputs in;
  in.ctl = ctl;
  in.assume = assume;
  auto parsed = logic::parse_check_inputs(in);
  EXPECT_TRUE(parsed.diagnostics.empty());
  semantics::Iec61131Options opts;
  semantics::set_dialect(opts, dialect);
  opts.assumptions = logic::assumption_exprs(parsed.spec);
  model::Diagnostics diags;
  c->ts = semantics::make_iec61131_system(c->project, opts, diags);
  EXPECT_TRUE(c->ts);
  if (!c->ts) return nullptr;
  c->task.system = c->ts.get();
  c->task.project = &c->project;
  logic::resolve_into(parsed.spec, *c->ts, c->task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  c->report = make_explicit_model_checker()->check(c->task);
  return c;
}

std::unique_ptr<Checked> check_text(
    const std::string& text, const std::vector<std::string>& ctl,
    const std::vector<std::string>& assume = {},
    semantics::VendorDialect dialect = semantics::VendorDialect::Iec) {
  auto loaded = io::load_iec_text(text, "chart.st");
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) return nullptr;
  return check_project(std::move(*loaded.project), ctl, assume, dialect);
}

bool holds_in(const semantics::TransitionSystem& ts, const logic::Formula& f,
              semantics::StateView s) {
  using logic::Op;
  switch (f.op) {
    case Op::True:
      return true;
    case Op::False:
      return false;
    case Op::Atom:
      return ts.observe(s, static_cast<std::uint32_t>(f.observable)) != 0;
    case Op::Compare:
      return logic::compare(f.cmp, ts.observe(s, static_cast<std::uint32_t>(f.observable)),
                            f.value);
    case Op::Not:
      return !holds_in(ts, *f.args[0], s);
    case Op::And:
      return holds_in(ts, *f.args[0], s) && holds_in(ts, *f.args[1], s);
    case Op::Or:
      return holds_in(ts, *f.args[0], s) || holds_in(ts, *f.args[1], s);
    case Op::Implies:
      return !holds_in(ts, *f.args[0], s) || holds_in(ts, *f.args[1], s);
    case Op::Iff:
      return holds_in(ts, *f.args[0], s) == holds_in(ts, *f.args[1], s);
    case Op::Xor:
      return holds_in(ts, *f.args[0], s) != holds_in(ts, *f.args[1], s);
    default:
      ADD_FAILURE() << "not propositional";
      return false;
  }
}

// The frames replayed from the initial state end in a state violating invariant AG p.
void expect_counterexample(const Checked& c, const ExportedModel& e, const logic::Formula& ag,
                           const std::vector<std::vector<bool>>& frames, const char* tool) {
  const auto inputs = frames_to_inputs(*c.ts, e.circuit, frames);
  const auto sim = semantics::simulate(*c.ts, semantics::first_initial_state(*c.ts), inputs);
  ASSERT_TRUE(sim.ok) << tool << ": the counterexample does not replay: " << sim.error;
  EXPECT_FALSE(holds_in(*c.ts, *ag.args[0], sim.states.back()))
      << tool << ": the replayed run ends in " << c.ts->describe(sim.states.back());
}

const char* to_text(logic::Verdict v) {
  return v == logic::Verdict::Holds      ? "holds"
         : v == logic::Verdict::Violated ? "violated"
                                         : "other";
}

// Spin and ABC on every invariant of `c`.
void confirm(const Checked& c, bool use_spin = true, bool use_abc = true) {
  const auto spin = find_spin();
  const auto abc = find_abc();
  ExportRequest request;
  request.target = ExportTarget::Circuit;
  request.properties = c.task.properties;
  const auto e = build_export(*c.ts, request);
  const auto aig = aiger_circuit(e.model);
  ASSERT_EQ(e.bad_property.size(), c.task.properties.size());
  for (std::size_t b = 0; b < e.bad_property.size(); ++b) {
    const auto p = static_cast<std::size_t>(e.bad_property[b]);
    const auto& prop = c.task.properties[p];
    const auto expected = c.report.results[p].verdict;
    ASSERT_TRUE(expected == logic::Verdict::Holds || expected == logic::Verdict::Violated);
    SCOPED_TRACE(prop.name + ": sfcv says " + to_text(expected));
    if (use_spin && spin) {
      const auto v = check_with_spin(*spin, e.model, b);
      ASSERT_NE(v.kind, SpinVerdict::Kind::Unknown) << v.log;
      EXPECT_EQ(v.kind == SpinVerdict::Kind::Violated, expected == logic::Verdict::Violated)
          << "Spin disagrees\n"
          << v.log;
      if (v.kind == SpinVerdict::Kind::Violated)
        expect_counterexample(c, e, *prop.formula, v.frames, "spin");
    }
    if (use_abc && abc) {
      const auto v = check_with_abc(*abc, aig, b, "pdr");
      ASSERT_NE(v.kind, AbcVerdict::Kind::Unknown) << v.log;
      EXPECT_EQ(v.kind == AbcVerdict::Kind::Violated, expected == logic::Verdict::Violated)
          << "ABC disagrees\n"
          << v.log;
      if (v.kind == AbcVerdict::Kind::Violated) {
        // Frame k holds the inputs of cycle k + 1; the last frame is the bad state's own.
        ASSERT_FALSE(v.frames.empty());
        auto frames = v.frames;
        frames.pop_back();
        expect_counterexample(c, e, *prop.formula, frames, "abc");
      }
    }
  }
}

#define REQUIRE_TOOLS()                                                                       \
  if (!find_spin() && !find_abc()) GTEST_SKIP() << "neither spin nor berkeley-abc installed"; \
  if (!find_spin()) std::cerr << "[ NOTE ] spin not installed: only ABC confirms\n";          \
  if (!find_abc()) std::cerr << "[ NOTE ] berkeley-abc not installed: only Spin confirms\n"

std::string read_source(const std::string& relative) {
  std::ifstream f(test::source_path(relative));
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

TEST(Confirmation, ChemicalPlantInvariantsAgreeWithSpinAndAbc) {
  REQUIRE_TOOLS();
  const auto c = check_text(read_source("examples/chemical_plant/chemical_plant.st"),
                            {"AG !(V1 & V3)", "AG !(V2 & V4)"});
  ASSERT_TRUE(c);
  // The seed's verdicts: T1 is protected, T2 is not.
  ASSERT_EQ(c->report.results.at(0).verdict, logic::Verdict::Holds);
  ASSERT_EQ(c->report.results.at(1).verdict, logic::Verdict::Violated);
  confirm(*c);
}

// A cut cycle keeps its state: n reaches 3 and the next cycle raises a range error, so the
// state n = 3 has no successor, yet it is reachable and violates AG n < 3. AIGER constraints
// would hide it (they must hold in the last frame too); the export's valid latch does not.
TEST(Confirmation, StatesWithoutSuccessorStayReachable) {
  REQUIRE_TOOLS();
  const auto c = check_text(R"(
PROGRAM Counter
  VAR_OUTPUT n : INT(0..3); END_VAR
  INITIAL_STEP S: Inc(N); END_STEP
  ACTION Inc: n := n + 1; END_ACTION
END_PROGRAM
)",
                            {"AG n < 3", "AG n <= 3"});
  ASSERT_TRUE(c);
  ASSERT_EQ(c->report.results.at(0).verdict, logic::Verdict::Violated);
  ASSERT_EQ(c->report.results.at(1).verdict, logic::Verdict::Holds);
  confirm(*c);
}

// The same with an assumption over the state: no input is allowed once S2 is active.
TEST(Confirmation, AssumptionsOverTheStateCutButKeepTheState) {
  REQUIRE_TOOLS();
  const auto c = check_text(R"(
PROGRAM Cut
  VAR_INPUT go : BOOL; END_VAR
  INITIAL_STEP S1: END_STEP
  STEP S2: END_STEP
  TRANSITION FROM S1 TO S2 := go; END_TRANSITION
  TRANSITION FROM S2 TO S1 := TRUE; END_TRANSITION
END_PROGRAM
)",
                            {"AG !S2"}, {"!S2.X"});
  ASSERT_TRUE(c);
  ASSERT_EQ(c->report.results.at(0).verdict, logic::Verdict::Violated);
  confirm(*c);
}

// Generated charts: two invariants each (mutual exclusion of two steps, a step unreachable),
// chosen from the chart's steps by the seed.
TEST(Confirmation, GeneratedChartsAgreeWithSpinAndAbc) {
  REQUIRE_TOOLS();
  struct Case {
    std::string text;
    std::uint64_t seed;
  };
  std::vector<Case> cases;
  for (std::uint64_t seed : {3, 5, 8, 13})
    cases.push_back({bench::random_chart_iec(8, 3, seed), seed});
  cases.push_back({bench::tanks_iec(1, true), 1});
  cases.push_back({bench::tanks_iec(1, false), 2});
  std::size_t violated = 0, holds = 0;
  for (const auto& k : cases) {
    SCOPED_TRACE("chart seed " + std::to_string(k.seed) + "\n" + k.text);
    // Step names first, from a system without properties.
    const auto probe = check_text(k.text, {});
    ASSERT_TRUE(probe);
    std::vector<std::string> steps;
    for (const auto& o : probe->ts->observables())
      if (o.kind == semantics::ObservableKind::Step) steps.push_back(o.name);
    ASSERT_GE(steps.size(), 3u);
    const auto n = steps.size();
    const auto& a = steps[(k.seed * 7 + 1) % n];
    const auto& b = steps[(k.seed * 3 + 2) % n == (k.seed * 7 + 1) % n ? (k.seed * 3 + 3) % n
                                                                       : (k.seed * 3 + 2) % n];
    const auto& last = steps[n - 1 - k.seed % 2];
    const auto c = check_text(k.text, {"AG !(" + a + " & " + b + ")", "AG !" + last});
    ASSERT_TRUE(c);
    for (const auto& r : c->report.results) {
      violated += r.verdict == logic::Verdict::Violated;
      holds += r.verdict == logic::Verdict::Holds;
    }
    confirm(*c);
  }
  // The sample must exercise both verdicts.
  EXPECT_GT(violated, 0u);
  EXPECT_GT(holds, 0u);
}

// Issue 53: a cycle whose ST loop meets sfcv's bound (1000 iterations) has no successor in
// sfcv, which answers unknown (the loop may still end: here it does, after 2000 iterations, and
// sets bad). The exports once cut that cycle too, and Spin and ABC proved AG !bad. Now the cycle
// sets the latch sfcv_loop_limit, where every property fails: both tools report a violation
// whose trace ends in the flag (read back as unknown), and the run before that cycle replays.
TEST(Confirmation, ALoopLimitCycleIsNeverProvedSafe) {
  REQUIRE_TOOLS();
  const auto c = check_text(test::kLoopLimitChart, {"AG !bad"});
  ASSERT_TRUE(c);
  for (const auto& r : c->report.results) ASSERT_EQ(r.verdict, logic::Verdict::Unknown) << r.name;
  ExportRequest request;
  request.target = ExportTarget::Circuit;
  request.properties = c->task.properties;
  const auto e = build_export(*c->ts, request);
  ASSERT_TRUE(e.loop_limit_latch);
  const auto aig = aiger_circuit(e.model);
  auto expect_ends_in_flag = [&](std::vector<std::vector<bool>> frames, const char* tool) {
    ASSERT_FALSE(frames.empty()) << tool;
    EXPECT_TRUE(ends_in_loop_limit(e, frames)) << tool;
    // Every cycle but the last replays; the last one meets the loop bound.
    auto inputs = frames_to_inputs(*c->ts, e.circuit, frames);
    EXPECT_THROW(semantics::simulate(*c->ts, semantics::first_initial_state(*c->ts), inputs),
                 LimitReached)
        << tool;
    inputs.pop_back();
    const auto before = semantics::simulate(*c->ts, semantics::first_initial_state(*c->ts), inputs);
    EXPECT_TRUE(before.ok) << tool << ": " << before.error;
  };
  for (std::size_t b = 0; b < e.bad_property.size(); ++b) {
    SCOPED_TRACE(e.model.aig.bad()[b].name);
    if (const auto spin = find_spin()) {
      const auto v = check_with_spin(*spin, e.model, b);
      ASSERT_EQ(v.kind, SpinVerdict::Kind::Violated) << v.log;
      expect_ends_in_flag(v.frames, "spin");
    }
    if (const auto abc = find_abc()) {
      const auto v = check_with_abc(*abc, aig, b, "pdr");
      ASSERT_EQ(v.kind, AbcVerdict::Kind::Violated) << v.log;
      auto frames = v.frames;  // the last frame is the bad state's own
      ASSERT_FALSE(frames.empty());
      frames.pop_back();
      expect_ends_in_flag(frames, "abc");
    }
  }
}

// A loop that could meet the bound in an unreachable state: the flag stays unset, and the
// verdicts are exact (AG !bad holds, AG !alarm is violated with a counterexample that replays).
TEST(Confirmation, AnUnreachableLoopLimitKeepsTheVerdicts) {
  REQUIRE_TOOLS();
  const auto c = check_text(R"(
PROGRAM Guard
  VAR_INPUT go : BOOL; END_VAR
  VAR lock : BOOL; n : INT; bad : BOOL; alarm : BOOL; END_VAR
  n := 0;
  WHILE lock AND go AND n < 2000 DO
    n := n + 1;
  END_WHILE;
  IF n >= 2000 THEN
    bad := TRUE;
  END_IF;
  lock := FALSE;
  alarm := go;
END_PROGRAM
)",
                            {"AG !bad", "AG !alarm"});
  ASSERT_TRUE(c);
  ASSERT_EQ(c->report.results.at(0).verdict, logic::Verdict::Holds);
  ASSERT_EQ(c->report.results.at(1).verdict, logic::Verdict::Violated);
  ExportRequest request;
  request.target = ExportTarget::Circuit;
  request.properties = c->task.properties;
  ASSERT_TRUE(build_export(*c->ts, request).loop_limit_latch);  // the loop is in the circuit
  confirm(*c);
}

// A Boolean action of an instance and the variable it drives are two observables of one name,
// "Main.Lift.Extend". Under TwinCAT's reading the variable keeps what action Hold wrote while
// the Boolean action is inactive, so `Lift.Extend` (the variable) is TRUE in Idle. The export
// once cached its outputs by name and gave the variable's atom the action's latch: ABC proved
// `AG (Lift.Idle -> !Lift.Extend)`, which sfcv's every engine refutes.
TEST(Confirmation, ABooleanActionAndItsVariableAgreeWithSpinAndAbc) {
  REQUIRE_TOOLS();
  const auto c = check_text(test::kCylinderWithHoldChart,
                            {"AG (Lift.Idle -> !Lift.Extend)", "AG (Lift.Out -> Lift.Extend)"}, {},
                            semantics::VendorDialect::Twincat);
  ASSERT_TRUE(c);
  ASSERT_EQ(c->report.results.at(0).verdict, logic::Verdict::Violated);
  ASSERT_EQ(c->report.results.at(1).verdict, logic::Verdict::Holds);
  confirm(*c);
}

// Names that once changed the exports' meaning (issue 53): in Promela, "*/" then
// "#define assert(x) skip" turned every assertion into skip and Spin found no error; a name
// with a line break split an AIGER symbol line. Each hostile name is an input, a step or a
// variable on the way to Bad: Spin and ABC must find what sfcv finds, with counterexamples
// that replay.
TEST(Confirmation, HostileNamesAgreeWithSpinAndAbc) {
  REQUIRE_TOOLS();
  const auto c = check_project(test::hostile_chart().project, {"AG !Bad", "AG !(Start & Bad)"});
  ASSERT_TRUE(c);
  ASSERT_EQ(c->report.results.at(0).verdict, logic::Verdict::Violated);
  ASSERT_EQ(c->report.results.at(1).verdict, logic::Verdict::Holds);
  confirm(*c);
}

}  // namespace
}  // namespace sfcv::engine

// The SAT engines decide AG (p -> AX q) (the next_cycle and between_cycles patterns) on IEC
// 61131-3 charts through an observer latch (docs/engines.md): on random charts (timers,
// priorities off, assumptions) every verdict agrees with the explicit engine's CTL labelling,
// every counterexample replays and ends with p one cycle before a state where q fails, and a
// property that fails only if the observer were set in the initial state is not violated.

#include <gtest/gtest.h>

#include "chart_families.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/circuit_atom.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/ctl_task.hpp"

namespace sfcv::engine {
namespace {

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Setup load(const std::string& text, semantics::Iec61131Options options = {},
           const std::vector<std::string>& assume = {}) {
  Setup s;
  auto loaded = io::load_iec_text(text, "generated.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  if (!assume.empty()) {
    logic::CheckInputs in;
    in.assume = assume;
    auto parsed = logic::parse_check_inputs(in);
    for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
    options.assumptions = logic::assumption_exprs(parsed.spec);
  }
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts) << (diags.empty() ? "" : diags.front().str());
  return s;
}

/// A propositional formula in a state, on the circuit.
bool holds_in(const semantics::TransitionSystem& ts, const logic::Formula& f,
              const std::vector<semantics::StateWord>& state) {
  auto circuit = semantics::build_iec61131_circuit(ts);
  const auto lit = logic::circuit_literal(circuit, f);
  std::vector<bool> latches(circuit.aig.latches().size());
  const auto& layout = ts.layout();
  for (std::uint32_t k = 0; k < circuit.field_latches.size(); ++k) {
    const auto v = static_cast<std::uint64_t>(layout.get(state, k) - layout.fields()[k].lo);
    for (std::size_t b = 0; b < circuit.field_latches[k].size(); ++b)
      latches[circuit.field_latches[k][b]] = ((v >> b) & 1U) != 0;
  }
  const std::vector<bool> inputs(circuit.aig.inputs().size(), false);
  return semantics::Aig::value_of(circuit.aig.evaluate(inputs, latches), lit);
}

TEST(SatNextCycle, RandomChartsAgreeWithTheExplicitEngine) {
  int decided = 0, holds = 0, violated = 0, traces = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    bench::RandomChartFeatures features;
    features.timed_qualifiers = seed % 3 == 0;
    semantics::Iec61131Options options;
    if (seed % 4 == 1) options.priority = semantics::PriorityMode::None;
    options.time = seed % 2 == 0 ? semantics::TimeMode::Abstract : semantics::TimeMode::Discrete;
    std::vector<std::string> assume;
    if (seed % 5 == 2) assume = {"!(S3 & i0)"};
    const auto s =
        load(bench::random_chart_iec(4 + static_cast<std::uint32_t>(seed % 5), 2, seed, features),
             options, assume);
    ASSERT_TRUE(s.ts);
    test::FormulaGenerator gen(*s.ts, seed);
    const std::vector<std::string> ctl = {
        "AG (" + gen.atom() + " -> AX " + gen.atom() + ")",
        "AG (" + gen.atom() + " -> AX !" + gen.atom() + ")",
        "AG (" + gen.atom() + " -> AX (" + gen.atom() + " -> " + gen.atom() + "))",
        "AG (" + gen.atom() + " | " + gen.atom() + " -> AX (" + gen.atom() + " | " + gen.atom() +
            "))"};
    auto task = test::task_for(s.project, *s.ts, ctl, {});
    const auto reference = make_explicit_model_checker()->check(task);
    ASSERT_TRUE(reference.complete);
    for (auto algorithm : {SatAlgorithm::Bmc, SatAlgorithm::KInduction, SatAlgorithm::Ic3}) {
      SatEngineOptions o;
      o.algorithm = algorithm;
      o.max_depth = 12;
      const auto checker = make_sat_model_checker(o);
      ASSERT_TRUE(checker->can_handle(task));
      const auto report = checker->check(task);
      ASSERT_EQ(report.results.size(), reference.results.size());
      for (std::size_t i = 0; i < report.results.size(); ++i) {
        const auto& e = reference.results[i];
        const auto& r = report.results[i];
        SCOPED_TRACE(std::string(checker->name()) + ": " + e.formula);
        if (r.verdict == logic::Verdict::Unknown) {
          EXPECT_NE(algorithm, SatAlgorithm::Ic3) << r.message;  // IC3 decides every one
          continue;
        }
        ++decided;
        ASSERT_EQ(e.verdict, r.verdict) << r.message << " (explicit: " << e.message << ")";
        holds += r.verdict == logic::Verdict::Holds;
        violated += r.verdict == logic::Verdict::Violated;
        if (r.verdict != logic::Verdict::Violated) continue;
        ASSERT_TRUE(r.trace);
        ++traces;
        const auto& steps = r.trace->steps;
        ASSERT_GE(steps.size(), 2u);  // p one cycle before: never in the initial state alone
        std::vector<std::vector<std::int64_t>> inputs;
        for (std::size_t k = 1; k < steps.size(); ++k) inputs.push_back(steps[k].inputs);
        const auto run = semantics::simulate(*s.ts, steps.front().state, inputs);
        ASSERT_TRUE(run.ok) << run.error;
        ASSERT_EQ(run.states.size(), steps.size());
        for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_EQ(run.states[k], steps[k].state);
        const auto& body = *task.properties[i].formula->args[0];
        EXPECT_TRUE(holds_in(*s.ts, *body.args[0], steps[steps.size() - 2].state));
        EXPECT_FALSE(holds_in(*s.ts, *body.args[1]->args[0], steps.back().state));
        if (algorithm == SatAlgorithm::Bmc && e.trace) {
          EXPECT_EQ(e.trace->steps.size(), steps.size()) << "BMC's run is not shortest";
        }
      }
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(decided, 1000);
  EXPECT_GT(holds, 200);
  EXPECT_GT(violated, 200);
  EXPECT_GT(traces, 200);
}

// In the initial state no cycle has run: AG (p -> AX q) with p and !q true there, and q true
// in every later state, holds (an observer that copied p into the initial state would report
// a false violation).
TEST(SatNextCycle, TheInitialStateHasNoPreviousCycle) {
  const auto s = load(R"(PROGRAM P
  VAR_INPUT go : BOOL; END_VAR
  INITIAL_STEP A : END_STEP
  STEP B : END_STEP
  TRANSITION FROM A TO B := TRUE; END_TRANSITION
  TRANSITION FROM B TO A := FALSE; END_TRANSITION
END_PROGRAM
)");
  ASSERT_TRUE(s.ts);
  auto task = test::task_for(s.project, *s.ts, {"AG (A -> AX B)", "AG (B -> AX A)"}, {});
  const auto reference = make_explicit_model_checker()->check(task);
  ASSERT_EQ(reference.results[0].verdict, logic::Verdict::Holds);
  ASSERT_EQ(reference.results[1].verdict, logic::Verdict::Violated);
  for (auto algorithm : {SatAlgorithm::Bmc, SatAlgorithm::KInduction, SatAlgorithm::Ic3}) {
    SatEngineOptions o;
    o.algorithm = algorithm;
    const auto report = make_sat_model_checker(o)->check(task);
    SCOPED_TRACE(std::string(make_sat_model_checker(o)->name()));
    if (algorithm != SatAlgorithm::Bmc) {
      EXPECT_EQ(report.results[0].verdict, logic::Verdict::Holds) << report.results[0].message;
    } else {
      EXPECT_NE(report.results[0].verdict, logic::Verdict::Violated);
    }
    EXPECT_EQ(report.results[1].verdict, logic::Verdict::Violated);
  }
}

}  // namespace
}  // namespace sfcv::engine

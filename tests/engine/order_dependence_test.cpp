// The order-dependence standard check (issue 47, docs/semantics.md §1.2a), from seed 000's text:
// under a partial order "actions unordered by ⊏ that write a common variable may run in any
// order"; the check reports a reachable situation where two admissible orders give different
// results, and holds when none is reachable. output-conflicts judges the writes syntactically:
// two writers that commute are its finding, never order-dependence's.

#include <gtest/gtest.h>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/ctl_task.hpp"
#include "support/press_chart.hpp"

namespace sfcv::engine {
namespace {

using logic::StandardCheck;
using logic::Verdict;

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Setup load(const std::string& text, semantics::ActionOrder order) {
  Setup s;
  auto loaded = io::load_iec_text(text, "order.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  semantics::Iec61131Options options;
  options.action_order = order;
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts) << (diags.empty() ? "" : diags.front().str());
  return s;
}

logic::CheckTask checks_task(const Setup& s) {
  auto task = test::task_for(s.project, *s.ts, {}, {});
  task.checks = {StandardCheck::OrderDependence, StandardCheck::OutputConflicts};
  return task;
}

// Two latches of one lamp, both active in Watch: `lamp OR go` then `lamp OR stop` is the same
// as the other way round. Clear (in Reset) resets it alone.
constexpr const char* kLatches = R"(
PROGRAM Panel
  VAR_INPUT go : BOOL; stop : BOOL; done : BOOL; END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP Reset: Clear(N); END_STEP
  STEP Watch: OnGo(N); OnStop(N); END_STEP
  TRANSITION FROM Reset TO Watch := go; END_TRANSITION
  TRANSITION FROM Watch TO Reset := done; END_TRANSITION
  ACTION Clear: lamp := FALSE; END_ACTION
  ACTION OnGo: lamp := lamp OR go; END_ACTION
  ACTION OnStop: lamp := lamp OR stop; END_ACTION
END_PROGRAM
)";

TEST(OrderDependence, WritersThatCommuteHoldWhileOutputConflictsWarns) {
  const auto s = load(kLatches, semantics::ActionOrder::Unordered);
  // The group {OnGo, OnStop} is unordered: the system has a choice.
  bool has_order = false;
  for (const auto& in : s.ts->inputs()) has_order |= in.name.starts_with("order:");
  ASSERT_TRUE(has_order);
  const auto task = checks_task(s);
  for (const bool bdd : {false, true}) {
    SCOPED_TRACE(bdd ? "bdd" : "explicit");
    const auto report =
        (bdd ? make_bdd_model_checker() : make_explicit_model_checker())->check(task);
    ASSERT_EQ(report.results.size(), 2u);
    EXPECT_EQ(report.results[0].verdict, Verdict::Holds) << report.results[0].message;
    EXPECT_TRUE(report.results[0].findings.empty());
    // The syntactic check cannot tell: both assign lamp an expression, active together.
    EXPECT_EQ(report.results[1].verdict, Verdict::Violated) << report.results[1].message;
  }
}

TEST(OrderDependence, SetAndResetDependOnTheOrderAndTheTraceShowsBothOrders) {
  const auto s = load(test::kPressChart, semantics::ActionOrder::Unordered);
  const auto task = checks_task(s);
  for (const bool bdd : {false, true}) {
    SCOPED_TRACE(bdd ? "bdd" : "explicit");
    const auto report =
        (bdd ? make_bdd_model_checker() : make_explicit_model_checker())->check(task);
    const auto& r = report.results.at(0);
    ASSERT_EQ(r.verdict, Verdict::Violated) << r.message;
    ASSERT_EQ(r.findings.size(), 1u);
    const auto& f = r.findings.front();
    EXPECT_NE(f.find("Press.Halt"), std::string::npos) << f;
    EXPECT_NE(f.find("order:motor=Start<Stop gives motor = 0"), std::string::npos) << f;
    EXPECT_NE(f.find("order:motor=Stop<Start gives motor = 1"), std::string::npos) << f;
    // The trace runs to Halt, then the cycle under the first order; the note names the second.
    ASSERT_TRUE(r.trace);
    ASSERT_EQ(r.trace->steps.size(), 4u);
    EXPECT_NE(r.trace->note.find("order:motor=Stop<Start"), std::string::npos) << r.trace->note;
    std::vector<std::vector<std::int64_t>> inputs;
    for (std::size_t k = 1; k < r.trace->steps.size(); ++k)
      inputs.push_back(r.trace->steps[k].inputs);
    const auto run = semantics::simulate(*s.ts, r.trace->steps.front().state, inputs);
    ASSERT_TRUE(run.ok) << run.error;
    ASSERT_EQ(run.states.size(), r.trace->steps.size());
    for (std::size_t k = 0; k < run.states.size(); ++k)
      EXPECT_EQ(run.states[k], r.trace->steps[k].state) << "cycle " << k;
    // Under the first order (Start<Stop: Stop runs last) the motor ends off.
    const auto motor = semantics::find_observable(*s.ts, "motor");
    ASSERT_TRUE(motor);
    EXPECT_EQ(s.ts->observe(r.trace->steps.back().state, *motor), 0);
  }
  // The SAT engines do not enumerate evolutions: not checked (unknown for the exit code).
  SatEngineOptions ic3;
  ic3.algorithm = SatAlgorithm::Ic3;
  const auto report = make_sat_model_checker(ic3)->check(task);
  EXPECT_EQ(report.results.at(0).verdict, Verdict::NotChecked);
}

TEST(OrderDependence, NotApplicableUnderATotalOrder) {
  for (auto order : {semantics::ActionOrder::Declaration, semantics::ActionOrder::Alphabetical}) {
    const auto s = load(test::kPressChart, order);
    const auto report = make_explicit_model_checker()->check(checks_task(s));
    EXPECT_EQ(report.results.at(0).verdict, Verdict::NotApplicable);
  }
}

// The explicit and BDD engines agree on random charts whose actions write one output.
TEST(OrderDependence, EnginesAgreeOnRandomChartsWithSharedOutputs) {
  int violated = 0, holds = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    bench::RandomChartFeatures features;
    features.writing_actions = true;
    features.counter = seed % 2 == 0;
    const auto text =
        bench::random_chart_iec(5 + static_cast<std::uint32_t>(seed % 4), 2, seed, features);
    const auto s = load(text, semantics::ActionOrder::Unordered);
    ASSERT_TRUE(s.ts);
    auto task = checks_task(s);
    task.checks = {StandardCheck::OrderDependence};
    const auto reference = make_explicit_model_checker()->check(task);
    const auto symbolic = make_bdd_model_checker()->check(task);
    const auto& a = reference.results.at(0);
    const auto& b = symbolic.results.at(0);
    EXPECT_EQ(a.verdict, b.verdict) << a.message << " / " << b.message;
    violated += a.verdict == Verdict::Violated;
    holds += a.verdict == Verdict::Holds;
    if (a.verdict == Verdict::Violated && b.verdict == Verdict::Violated) {
      // The shallowest finding: both engines' traces end at the same depth.
      ASSERT_TRUE(a.trace && b.trace);
      EXPECT_EQ(a.trace->steps.size(), b.trace->steps.size());
    }
  }
  // Both verdicts occur: the generator's shared writers sometimes commute, sometimes not.
  EXPECT_GT(violated, 2) << violated;
  EXPECT_GT(holds, 0) << holds;
}

}  // namespace
}  // namespace sfcv::engine

// Counterexamples replayed with semantics::simulate (the library behind `sfcv simulate`) reach
// the state the checker reported, for every kind of trace.

#include <gtest/gtest.h>

#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::engine {
namespace {

struct Plant {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  Plant() {
    auto loaded = io::load_file(test::source_path("examples/chemical_plant/chemical_plant.st"));
    EXPECT_TRUE(loaded.project);
    project = std::move(*loaded.project);
    model::Diagnostics diags;
    ts = semantics::make_iec61131_system(project, {}, diags);
    EXPECT_TRUE(ts);
  }
};

logic::CheckReport check(const Plant& p, std::vector<std::string> ctl) {
  logic::CheckInputs in;
  in.ctl = std::move(ctl);
  auto parsed = logic::parse_check_inputs(in);
  EXPECT_TRUE(parsed.diagnostics.empty());
  logic::CheckTask task;
  task.system = p.ts.get();
  task.project = &p.project;
  model::Diagnostics diags;
  logic::resolve_into(parsed.spec, *p.ts, task, diags);
  EXPECT_TRUE(diags.empty());
  return make_explicit_model_checker()->check(task);
}

void expect_replays(const semantics::TransitionSystem& ts, const logic::Trace& trace) {
  ASSERT_FALSE(trace.steps.empty());
  const auto start = semantics::first_initial_state(ts);
  ASSERT_EQ(start, trace.steps.front().state);
  std::vector<std::vector<std::int64_t>> inputs;
  for (std::size_t i = 1; i < trace.steps.size(); ++i) inputs.push_back(trace.steps[i].inputs);
  const auto sim = semantics::simulate(ts, start, inputs);
  ASSERT_TRUE(sim.ok) << sim.error;
  ASSERT_EQ(sim.states.size(), trace.steps.size());
  for (std::size_t i = 0; i < trace.steps.size(); ++i)
    EXPECT_EQ(sim.states[i], trace.steps[i].state) << "cycle " << i;
}

TEST(TraceReplay, SafetyCounterexampleReachesTheViolation) {
  Plant p;
  const auto report = check(p, {"AG !(V2 & V4)"});
  ASSERT_EQ(report.results.size(), 1u);
  ASSERT_EQ(report.results[0].verdict, logic::Verdict::Violated);
  const auto& trace = *report.results[0].trace;
  expect_replays(*p.ts, trace);
  const auto v2 = *semantics::find_observable(*p.ts, "V2");
  const auto v4 = *semantics::find_observable(*p.ts, "V4");
  EXPECT_EQ(p.ts->observe(trace.steps.back().state, v2), 1);
  EXPECT_EQ(p.ts->observe(trace.steps.back().state, v4), 1);
}

TEST(TraceReplay, LassoAndNestedCounterexamplesReplay) {
  Plant p;
  // AF s8 fails (inputs may keep the plant waiting): a lasso.
  auto report = check(p, {"AF s8", "AG EF s9", "EF (V2 & V4)"});
  ASSERT_EQ(report.results.size(), 3u);
  ASSERT_EQ(report.results[0].verdict, logic::Verdict::Violated);
  ASSERT_TRUE(report.results[0].trace->loop_start);
  expect_replays(*p.ts, *report.results[0].trace);
  const auto& lasso = *report.results[0].trace;
  EXPECT_EQ(lasso.steps.back().state, lasso.steps[*lasso.loop_start].state);
  ASSERT_EQ(report.results[1].verdict, logic::Verdict::Violated);
  expect_replays(*p.ts, *report.results[1].trace);
  ASSERT_EQ(report.results[2].verdict, logic::Verdict::Holds);
  expect_replays(*p.ts, *report.results[2].trace);
}

TEST(ChemicalPlant, PaperResults) {
  Plant p;
  logic::CheckTask task;
  task.system = p.ts.get();
  task.project = &p.project;
  task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::Reentry,
                 logic::StandardCheck::DeadTransitions};
  const auto report = make_explicit_model_checker()->check(task);
  ASSERT_EQ(report.results.size(), 3u);
  EXPECT_EQ(report.results[0].verdict, logic::Verdict::Holds) << report.results[0].message;
  EXPECT_EQ(report.results[1].verdict, logic::Verdict::Holds) << report.results[1].findings.size();
  EXPECT_EQ(report.results[2].verdict, logic::Verdict::Holds);
  const auto props = check(p, {"AG !(V1 & V3)", "AG !(V2 & V4)"});
  EXPECT_EQ(props.results[0].verdict, logic::Verdict::Holds);
  EXPECT_EQ(props.results[1].verdict, logic::Verdict::Violated);
}

}  // namespace
}  // namespace sfcv::engine

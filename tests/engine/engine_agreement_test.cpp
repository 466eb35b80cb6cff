// The explicit and the BDD engine on the same tasks (like Storm's typed suites, and mCRL2's
// random tests): identical reachable-state counts and verdicts on generated charts, for random
// CTL formulas with and without fairness and for the standard checks both answer; every BDD
// trace replays through `simulate` to the state it claims.

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"

namespace sfcv::engine {
namespace {

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Setup load(const std::string& text, semantics::Iec61131Options options = {}) {
  Setup s;
  auto loaded = io::load_iec_text(text, "generated.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts) << (diags.empty() ? "" : diags.front().str());
  return s;
}

// Random CTL over the chart's step and Boolean output observables.
class FormulaGenerator {
 public:
  FormulaGenerator(const semantics::TransitionSystem& ts, std::uint64_t seed) : rng_(seed) {
    for (const auto& o : ts.observables())
      if (o.type.kind == model::TypeKind::Bool) atoms_.push_back(o.name);
  }
  std::string formula(int depth) {
    if (depth == 0 || pick(4) == 0) return atom();
    static const char* unary[] = {"!", "EX ", "AX ", "EF ", "AF ", "EG ", "AG "};
    static const char* binary[] = {" & ", " | ", " -> "};
    switch (pick(3)) {
      case 0: return std::string(unary[pick(7)]) + "(" + formula(depth - 1) + ")";
      case 1: return "(" + formula(depth - 1) + binary[pick(3)] + formula(depth - 1) + ")";
      default:
        return std::string(pick(2) ? "E[" : "A[") + formula(depth - 1) + " U " +
               formula(depth - 1) + "]";
    }
  }
  std::string atom() { return atoms_.empty() ? "TRUE" : atoms_[pick(static_cast<std::uint32_t>(atoms_.size()))]; }

 private:
  std::uint32_t pick(std::uint32_t n) { return static_cast<std::uint32_t>(rng_() % n); }
  std::mt19937_64 rng_;
  std::vector<std::string> atoms_;
};

logic::CheckTask task_for(const Setup& s, const std::vector<std::string>& ctl,
                          const std::vector<std::string>& fair) {
  logic::CheckInputs in;
  in.ctl = ctl;
  in.fair = fair;
  auto parsed = logic::parse_check_inputs(in);
  for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
  logic::CheckTask task;
  task.system = s.ts.get();
  task.project = &s.project;
  model::Diagnostics diags;
  logic::resolve_into(parsed.spec, *s.ts, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  return task;
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
}

void compare_engines(const Setup& s, std::uint64_t seed, bool with_fairness) {
  FormulaGenerator gen(*s.ts, seed);
  std::vector<std::string> ctl;
  for (int i = 0; i < 12; ++i) ctl.push_back(gen.formula(3));
  ctl.push_back("AG !(" + gen.atom() + " & " + gen.atom() + ")");
  ctl.push_back("EF (" + gen.atom() + " & " + gen.atom() + ")");
  std::vector<std::string> fair;
  if (with_fairness) fair = {gen.atom(), "!" + gen.atom()};
  auto task = task_for(s, ctl, fair);
  if (!with_fairness)
    task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions,
                   logic::StandardCheck::Reentry, logic::StandardCheck::GlobalDeadlock,
                   logic::StandardCheck::LocalDeadlock, logic::StandardCheck::InitialReturn};
  const auto explicit_report = make_explicit_model_checker()->check(task);
  const auto bdd = make_bdd_model_checker();
  ASSERT_TRUE(bdd->can_handle(task));
  const auto bdd_report = bdd->check(task);
  EXPECT_EQ(explicit_report.states, bdd_report.states);
  ASSERT_EQ(explicit_report.results.size(), bdd_report.results.size());
  for (std::size_t i = 0; i < explicit_report.results.size(); ++i) {
    const auto& e = explicit_report.results[i];
    const auto& b = bdd_report.results[i];
    EXPECT_EQ(e.verdict, b.verdict) << e.name << " " << e.formula << ": explicit "
                                    << logic::to_string(e.verdict) << ", bdd "
                                    << logic::to_string(b.verdict);
    if (b.trace) expect_replays(*s.ts, *b.trace);
  }
}

TEST(EngineAgreement, RandomChartsAndFormulas) {
  for (std::uint64_t seed = 1; seed <= 15; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(10 + static_cast<std::uint32_t>(seed % 7), 3, seed));
    ASSERT_TRUE(s.ts);
    compare_engines(s, seed, false);
    compare_engines(s, seed + 100, true);
  }
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

TEST(EngineAgreement, Families) {
  for (const auto& text : {bench::tanks_iec(2, true), bench::tanks_iec(2, false),
                           bench::nested_charts_iec(3), bench::parallel_branches_iec(5, true),
                           bench::parallel_branches_iec(4, false)}) {
    const auto s = load(text);
    ASSERT_TRUE(s.ts);
    compare_engines(s, 77, false);
    compare_engines(s, 78, true);
  }
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

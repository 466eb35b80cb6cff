// The choice logic of --engine auto (engine/auto_policy.hpp, docs/engines.md "how auto
// chooses"): from an estimate of the model made before any engine runs (a Grafcet's initial
// situations), whether the explicit probe runs first or the bdd/ic3/bmc race starts at once;
// the probe's forecast that hands a hopeless exploration over before its deadline; and the
// estimate itself (GrafcetSystem::estimate_initial_states) against the enumeration it forecasts.

#include "engine/auto_policy.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/portfolio/portfolio_model_checker.hpp"
#include "io/load.hpp"
#include "semantics/grafcet_system.hpp"
#include "support/ctl_task.hpp"

namespace sfcv::engine {
namespace {

TEST(AutoPolicy, TheProbeRunsUnlessTheInitialSituationsAlonePassItsBound) {
  const AutoProbe own{kAutoProbeStates, false};
  // No estimate (an IEC 61131-3 program: one initial state per initial input valuation class).
  EXPECT_EQ(auto_start(own, std::nullopt), AutoStart::Probe);
  EXPECT_EQ(auto_start(own, 1.0), AutoStart::Probe);
  // Within the bound, or near it (the estimate is a sample mean): the probe may finish.
  EXPECT_EQ(auto_start(own, 150'000.0), AutoStart::Probe);
  EXPECT_EQ(auto_start(own, kAutoSkipProbeFactor * kAutoProbeStates), AutoStart::Probe);
  // Corpus 22's 524 799 initial situations: the probe would stop at its bound before
  // expanding any, so the race gets the whole budget.
  EXPECT_EQ(auto_start(own, 524'799.0), AutoStart::Race);
  EXPECT_EQ(auto_start(own, 1e12), AutoStart::Race);
  // Under the user's --max-states the probe is the only engine, however wide the chart.
  EXPECT_EQ(auto_start({1000, true}, 1e12), AutoStart::Probe);
}

TEST(AutoPolicy, TheForecastHandsOverOnlyWhatCannotFinish) {
  // Not yet measured: too few states expanded, or too little time.
  EXPECT_FALSE(exploration_cannot_finish(10, 100'000, 5.0, 1.0));
  EXPECT_FALSE(exploration_cannot_finish(1000, 100'000, 0.05, 0.01));
  // xPPU-like: 50 ms a state, 2 000 states waiting, 10 s left: 100 s needed.
  EXPECT_TRUE(exploration_cannot_finish(40, 2040, 2.0, 10.0));
  // 100 000 states a second, 50 000 waiting, 10 s left: 0.5 s needed.
  EXPECT_FALSE(exploration_cannot_finish(100'000, 150'000, 1.0, 10.0));
  // Nothing waiting: the exploration is about to finish.
  EXPECT_FALSE(exploration_cannot_finish(500, 500, 30.0, 0.001));
}

struct Loaded {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

/// `n` partial grafcets, each leaving its initial step on its own input: the initial situation
/// stabilises under each of the 2^n initial input valuations into a distinct situation.
Loaded wide_grafcet(int n) {
  std::string g7 = "project wide;\ninput a0";
  for (int i = 1; i < n; ++i) g7 += ", a" + std::to_string(i);
  g7 += ";\n";
  for (int i = 0; i < n; ++i) {
    const auto k = std::to_string(i);
    g7 += "grafcet G" + k + " {\n  step 0 initial;\n  step 1;\n  transition t" + k +
          "a: 0 -> 1 when a" + k + ";\n  transition t" + k + "b: 1 -> 0 when !a" + k + ";\n}\n";
  }
  Loaded l;
  auto r = io::load_g7(g7, "wide.g7");
  EXPECT_TRUE(r.ok());
  l.project = std::move(*r.project);
  model::Diagnostics d;
  l.ts = semantics::make_grafcet_system(l.project, {}, d);
  EXPECT_TRUE(l.ts);
  return l;
}

class Counter final : public semantics::SuccessorSink {
 public:
  void successor(const semantics::Successor&) override { ++count; }
  std::uint64_t count = 0;
};

TEST(AutoPolicy, TheGrafcetEstimateMatchesTheEnumeration) {
  const auto small = wide_grafcet(8);
  Counter c;
  small.ts->initial_states(c);
  EXPECT_EQ(c.count, 256u);
  ASSERT_TRUE(small.ts->estimate_initial_states());
  EXPECT_DOUBLE_EQ(*small.ts->estimate_initial_states(), 256.0);
  // 40 inputs: 2^40 initial situations, estimated without enumerating them.
  const auto wide = wide_grafcet(40);
  ASSERT_TRUE(wide.ts->estimate_initial_states());
  EXPECT_DOUBLE_EQ(*wide.ts->estimate_initial_states(), 1099511627776.0);
}

TEST(AutoPolicy, AutoSkipsTheProbeOnTooManyInitialSituations) {
  const auto wide = wide_grafcet(20);  // 2^20 > 2 x 200 000
  auto task = test::task_for(wide.project, *wide.ts, {"AG !(G0.X1 & !a0)"}, {});
  std::vector<std::string> notes;
  PortfolioOptions options;
  options.note = [&notes](const std::string& n) { notes.push_back(n); };
  const auto report = make_portfolio_model_checker(options)->check(task);
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.front().find("initial situations (estimated)"), std::string::npos)
      << notes.front();
  ASSERT_EQ(report.results.size(), 1u);
  EXPECT_EQ(report.results[0].verdict, logic::Verdict::Holds);
  EXPECT_NE(report.results[0].decided_by, "explicit");
}

}  // namespace
}  // namespace sfcv::engine

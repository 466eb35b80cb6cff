// --engine auto as a portfolio (engine/portfolio): on random charts of both semantics its
// verdicts equal the explicit and the BDD engine's, whether the explicit probe answers or the
// BDD engine, IC3 and BMC race (a probe bound of 0), and each definite answer names the engine that
// gave it; an engine cancelled mid-run (model::Budget::cancel) stops promptly with unknown
// answers, never holds; the run's deadline still bounds the race.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/portfolio/portfolio_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/load.hpp"
#include "logic/standard_checks.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"
#include "support/ctl_task.hpp"
#include "support/random_grafcet.hpp"
#include "support/trace_replay.hpp"

namespace sfcv::engine {
namespace {

using logic::Verdict;
using Clock = std::chrono::steady_clock;

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Setup load_iec(const std::string& text, semantics::Iec61131Options options = {}) {
  Setup s;
  auto loaded = io::load_iec_text(text, "generated.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts) << (diags.empty() ? "" : diags.front().str());
  return s;
}

bool definite(Verdict v) {
  return v == Verdict::Holds || v == Verdict::Violated;
}

struct Tally {
  int decided = 0, by_bdd = 0, by_ic3 = 0, by_explicit = 0;
};

void compare(const Setup& s, std::uint64_t seed, Tally& tally) {
  test::FormulaGenerator gen(*s.ts, seed);
  // Invariants and reachability (both racers answer), and CTL beyond them (the BDD engine only).
  std::vector<std::string> ctl = {"AG !(" + gen.atom() + " & " + gen.atom() + ")",
                                  "EF (" + gen.atom() + " & " + gen.atom() + ")",
                                  "AF " + gen.atom(), gen.formula(3)};
  auto task = test::task_for(s.project, *s.ts, ctl, {});
  // Reentry, local-deadlock and initial-return too: the engines fill in their formula once
  // decided, which the race must still read as the answer to the question (issue 15).
  task.checks = {logic::StandardCheck::Reachable,    logic::StandardCheck::DeadTransitions,
                 logic::StandardCheck::Instability,  logic::StandardCheck::GlobalDeadlock,
                 logic::StandardCheck::Reentry,      logic::StandardCheck::LocalDeadlock,
                 logic::StandardCheck::InitialReturn};
  const auto reference = make_explicit_model_checker()->check(task);
  ASSERT_TRUE(reference.complete);
  const auto symbolic = make_bdd_model_checker()->check(task);
  for (std::uint64_t probe : {kAutoProbeStates, std::uint64_t{0}}) {
    PortfolioOptions options;
    options.probe_states = probe;
    const auto report = make_portfolio_model_checker(options)->check(task);
    ASSERT_EQ(report.results.size(), reference.results.size());
    for (std::size_t i = 0; i < report.results.size(); ++i) {
      const auto& r = report.results[i];
      const auto& e = reference.results[i];
      SCOPED_TRACE("probe " + std::to_string(probe) + ": " + e.name + " " + e.formula);
      EXPECT_EQ(r.name, e.name);
      if (!definite(r.verdict)) {
        // Undecided only where the BDD engine (which answers all the racers do) is too.
        EXPECT_FALSE(definite(symbolic.results[i].verdict)) << r.message;
        continue;
      }
      ++tally.decided;
      EXPECT_EQ(r.verdict, e.verdict) << "auto (" << r.decided_by << ") " << r.message;
      if (definite(symbolic.results[i].verdict)) {
        EXPECT_EQ(r.verdict, symbolic.results[i].verdict);
      }
      if (probe == 0) {
        EXPECT_TRUE(r.decided_by == "bdd" || r.decided_by == "ic3" || r.decided_by == "bmc")
            << r.decided_by;
        tally.by_bdd += r.decided_by == "bdd";
        tally.by_ic3 += r.decided_by != "bdd";
      } else {
        EXPECT_EQ(r.decided_by, "explicit");  // small charts: the probe answers everything
        ++tally.by_explicit;
      }
      if (r.trace) test::expect_trace_replays(*s.ts, *r.trace);
    }
    if (probe == 0) {
      EXPECT_EQ(report.engine, "auto");
    }
  }
}

TEST(Portfolio, AgreesWithEachEngineOnRandomCharts) {
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    bench::RandomChartFeatures features;
    features.timed_qualifiers = seed % 3 == 0;
    semantics::Iec61131Options options;
    if (seed % 4 == 1) options.priority = semantics::PriorityMode::None;
    const auto s = load_iec(
        bench::random_chart_iec(4 + static_cast<std::uint32_t>(seed % 5), 2, seed, features),
        options);
    ASSERT_TRUE(s.ts);
    compare(s, seed, tally);
    if (HasFatalFailure()) return;
  }
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("grafcet seed " + std::to_string(seed));
    engine::Setup s;
    s.project = test::random_grafcet(seed);
    model::Diagnostics d;
    s.ts = semantics::make_grafcet_system(s.project, {}, d);
    ASSERT_TRUE(s.ts) << (d.empty() ? "" : d.front().str());
    compare(s, seed, tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.decided, 800);
  EXPECT_GT(tally.by_explicit, 400);
  // The race is real: both racers win some answers (whichever wins, the verdict is the same).
  EXPECT_GT(tally.by_bdd + tally.by_ic3, 400);
}

/// A counter whose bound is reached only after 2^(n+1) cycles: `AG c < top - 1` is violated
/// that deep, out of reach of every engine within a test's time.
logic::CheckTask deep_task(const Setup& s, std::uint32_t n) {
  const auto top = (std::uint64_t{1} << n) - 1;
  return test::task_for(s.project, *s.ts, {"AG c < " + std::to_string(top - 1)}, {});
}

TEST(Portfolio, EveryEngineStopsPromptlyWhenCancelled) {
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  std::vector<ModelCheckerPtr> engines;
  engines.push_back(make_explicit_model_checker());
  engines.push_back(make_bdd_model_checker());
  engines.push_back(make_sat_model_checker({SatAlgorithm::Ic3, 200}));
  engines.push_back(make_sat_model_checker({SatAlgorithm::Bmc, 100'000}));
  engines.push_back(make_portfolio_model_checker());
  for (const auto& engine : engines) {
    SCOPED_TRACE(std::string(engine->name()));
    auto task = deep_task(s, 30);
    task.limits.cancel = std::make_shared<std::atomic<bool>>(false);
    std::jthread canceller([flag = task.limits.cancel] {
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      flag->store(true);
    });
    const auto t0 = Clock::now();
    const auto report = engine->check(task);
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    // Generous for a shared machine; uncancelled, each engine runs for minutes at least.
    EXPECT_LT(seconds, 10.0);
    ASSERT_EQ(report.results.size(), 1u);
    EXPECT_EQ(report.results[0].verdict, Verdict::Unknown) << report.results[0].message;
  }
}

TEST(Portfolio, TheDeadlineBoundsTheRace) {
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  auto task = deep_task(s, 30);
  task.limits.set_timeout(1.0);
  PortfolioOptions options;
  options.probe_states = 0;
  const auto t0 = Clock::now();
  const auto report = make_portfolio_model_checker(options)->check(task);
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_LT(seconds, 10.0);
  EXPECT_FALSE(report.complete);
  EXPECT_EQ(report.limit, "time");
  EXPECT_EQ(report.results[0].verdict, Verdict::Unknown);
}

/// The checks only the BDD engine decides in the race (IC3 and BMC do not check them).
std::vector<logic::StandardCheck> bdd_only_checks() {
  return {logic::StandardCheck::Reentry, logic::StandardCheck::LocalDeadlock,
          logic::StandardCheck::InitialReturn};
}

TEST(Portfolio, TheBddEnginesAnswerToACheckOnlyItDecidesCounts) {
  // 40 branches on their own inputs, 2^40 + 1 states: the BDD engine decides these at once; it
  // used to be dropped for IC3's "not checked" (and a violated local-deadlock exited 0).
  const auto s = load_iec(bench::parallel_branches_iec(40, false));
  ASSERT_TRUE(s.ts);
  auto task = test::task_for(s.project, *s.ts, {}, {});
  task.checks = bdd_only_checks();
  const auto symbolic = make_bdd_model_checker()->check(task);
  PortfolioOptions options;
  options.probe_states = 0;
  const auto report = make_portfolio_model_checker(options)->check(task);
  ASSERT_EQ(report.results.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& r = report.results[i];
    SCOPED_TRACE(r.name);
    ASSERT_TRUE(definite(symbolic.results[i].verdict)) << symbolic.results[i].message;
    EXPECT_EQ(r.verdict, symbolic.results[i].verdict) << r.message;
    EXPECT_EQ(r.decided_by, "bdd");
  }
}

TEST(Portfolio, AnUndecidedCheckNamesTheLimitOfAnEngineThatChecksIt) {
  // The BDD engine runs out of time on the deep counter; IC3 and BMC do not check these: the
  // answer is the BDD engine's unknown with its limit, not "not checked by the ic3 engine".
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  auto task = test::task_for(s.project, *s.ts, {}, {});
  task.checks = bdd_only_checks();
  task.limits.set_timeout(1.0);
  PortfolioOptions options;
  options.probe_states = 0;
  const auto report = make_portfolio_model_checker(options)->check(task);
  EXPECT_EQ(report.limit, "time");
  ASSERT_EQ(report.results.size(), 3u);
  for (const auto& r : report.results) {
    SCOPED_TRACE(r.name);
    EXPECT_EQ(r.verdict, Verdict::Unknown);
    EXPECT_NE(r.message.find("time limit"), std::string::npos) << r.message;
    EXPECT_EQ(r.message.find("not checked"), std::string::npos) << r.message;
  }
}

TEST(Portfolio, AWinnerCancelsTheOtherEngine) {
  // IC3 proves AG c <= top - 1 at once; the BDD engine would need 2^31 rings: once IC3 has
  // answered, the BDD engine is cancelled and the run ends (no deadline set).
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  const auto top = (std::uint64_t{1} << 30) - 1;
  auto task = test::task_for(s.project, *s.ts, {"AG c <= " + std::to_string(top - 1)}, {});
  const auto t0 = Clock::now();
  const auto report = make_portfolio_model_checker()->check(task);
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_LT(seconds, 30.0);
  ASSERT_EQ(report.results.size(), 1u);
  EXPECT_EQ(report.results[0].verdict, Verdict::Holds);
  EXPECT_EQ(report.results[0].decided_by, "ic3");
  EXPECT_FALSE(report.results[0].certificate.empty());
  EXPECT_TRUE(report.complete);
}

/// A racer that does not stop: it ignores the deadline and the cancel flag until the test
/// releases it (as one long BDD operation on a loaded machine once did, corpus 02).
class StuckEngine final : public ModelChecker {
 public:
  std::string_view name() const override { return "stuck"; }
  bool can_handle(const logic::CheckTask&, std::string*) const override { return true; }
  logic::CheckReport check(const logic::CheckTask& task) const override {
    running = true;
    const auto give_up = Clock::now() + std::chrono::seconds(120);
    while (!released && Clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    running = false;
    return logic::unknown_report(task, "stuck", LimitReached(Limit::Time, "released"));
  }
  mutable std::atomic<bool> running{false}, released{false};
};

/// Releases the stuck racer and waits until its thread has ended, so that the system it reads
/// outlives it (the CLI ends the process instead).
void release(StuckEngine& stuck) {
  stuck.released = true;
  const auto give_up = Clock::now() + std::chrono::seconds(60);
  while (abandoned_racers() > 0 && Clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(abandoned_racers(), 0u);
}

/// A race without the explicit probe whose BDD slot is `stuck`, left behind 0.2 s after the
/// deadline or the last answer.
PortfolioOptions race_with_stuck_bdd(std::shared_ptr<StuckEngine> stuck) {
  PortfolioOptions options;
  options.probe_states = 0;
  options.abandon_after = 0.2;
  options.bdd_racer = std::move(stuck);
  return options;
}

TEST(Portfolio, ARacerThatDoesNotStopIsLeftBehindOnceEveryQuestionIsDecided) {
  // IC3 proves the invariant at once and cancels the race; the BDD slot never stops. With
  // abandon_after the report comes without it, and IC3's answer stands.
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  const auto top = (std::uint64_t{1} << 30) - 1;
  auto task = test::task_for(s.project, *s.ts, {"AG c <= " + std::to_string(top - 1)}, {});
  auto stuck = std::make_shared<StuckEngine>();
  const auto report = make_portfolio_model_checker(race_with_stuck_bdd(stuck))->check(task);
  EXPECT_TRUE(stuck->running) << "the race waited for the racer that does not stop";
  EXPECT_EQ(abandoned_racers(), 1u);
  ASSERT_EQ(report.results.size(), 1u);
  EXPECT_EQ(report.results[0].verdict, Verdict::Holds) << report.results[0].message;
  EXPECT_EQ(report.results[0].decided_by, "ic3");
  release(*stuck);
}

TEST(Portfolio, ARacerThatDoesNotStopPastTheDeadlineLeavesItsQuestionsUnknown) {
  // The BDD slot does not stop at the deadline (and IC3 does not decide these in the time):
  // past it and the grace, the report comes with the questions unknown and says why, the BDD
  // slot's account first, never with a verdict.
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  auto task = test::task_for(s.project, *s.ts, {}, {});
  task.checks = bdd_only_checks();
  task.limits.set_timeout(0.3);
  auto stuck = std::make_shared<StuckEngine>();
  const auto report = make_portfolio_model_checker(race_with_stuck_bdd(stuck))->check(task);
  EXPECT_TRUE(stuck->running) << "the race waited for the racer that does not stop";
  EXPECT_FALSE(report.complete);
  EXPECT_EQ(report.limit, "time");
  ASSERT_EQ(report.results.size(), 3u);
  for (const auto& r : report.results) {
    SCOPED_TRACE(r.name);
    EXPECT_EQ(r.verdict, Verdict::Unknown);
    EXPECT_EQ(r.message.rfind(
                  "bdd: time limit reached; the bdd engine had not stopped 0.2 s after it", 0),
              0u)
        << r.message;
  }
  release(*stuck);
}

TEST(Portfolio, AnUndecidedPropertyGivesEveryEnginesAccount) {
  // AG c < top - 1 on the 30-bit counter is violated after 2^31 cycles: no racer decides it
  // in 0.3 s. The answer says what stopped each of them, not the BDD slot's reason alone
  // (an AGRAFE plant read "time limit reached in a BDD operation" where IC3 had decided 50
  // of its 64 steps).
  const auto s = load_iec(bench::counter_iec(30));
  ASSERT_TRUE(s.ts);
  auto task = deep_task(s, 30);
  task.limits.set_timeout(0.3);
  auto stuck = std::make_shared<StuckEngine>();
  const auto report = make_portfolio_model_checker(race_with_stuck_bdd(stuck))->check(task);
  ASSERT_EQ(report.results.size(), 1u);
  const auto& r = report.results[0];
  EXPECT_EQ(r.verdict, Verdict::Unknown) << r.message;
  EXPECT_EQ(r.message.rfind("bdd: time limit reached; the bdd engine had not stopped", 0), 0u)
      << r.message;
  EXPECT_NE(r.message.find("; ic3: "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("; bmc: "), std::string::npos) << r.message;
  release(*stuck);
}

TEST(Portfolio, TheBddEngineStopsWhenItsRelationIsNotBuiltInItsShare) {
  // In the race the BDD engine has kRaceRelationShare of the time left to build its system's
  // BDDs and relation (xPPU: never built, while it held one of the two cores to the end). A
  // share no build fits in (a microsecond of 10 s) stops it at once, every answer unknown and
  // saying why; without a share of its own the same run decides everything.
  const auto s = load_iec(bench::parallel_branches_iec(3, false));
  ASSERT_TRUE(s.ts);
  auto task = test::task_for(s.project, *s.ts, {"AG !(Init & A0)"}, {});
  task.checks = bdd_only_checks();
  task.limits.set_timeout(10.0);
  BddEngineOptions options;
  options.relation_share = 1e-7;
  const auto t0 = Clock::now();
  const auto stopped = make_bdd_model_checker(options)->check(task);
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 5.0);
  EXPECT_FALSE(stopped.complete);
  EXPECT_EQ(stopped.limit, "time");
  ASSERT_EQ(stopped.results.size(), 1 + task.checks.size());
  for (const auto& r : stopped.results) {
    SCOPED_TRACE(r.name);
    EXPECT_EQ(r.verdict, Verdict::Unknown);
    EXPECT_EQ(r.message.rfind("the transition relation was not built in the bdd engine's share", 0),
              0u)
        << r.message;
  }
  options.relation_share = 0;
  const auto whole = make_bdd_model_checker(options)->check(task);
  EXPECT_TRUE(whole.complete);
  for (const auto& r : whole.results) EXPECT_TRUE(definite(r.verdict)) << r.name << r.message;
}

/// A racer that decides nothing and records the checks it was asked.
class AskedChecksRecorder final : public ModelChecker {
 public:
  std::string_view name() const override { return "recorder"; }
  bool can_handle(const logic::CheckTask&, std::string*) const override { return true; }
  logic::CheckReport check(const logic::CheckTask& task) const override {
    const std::lock_guard lock(mutex_);
    asked_ = task.checks;
    return logic::unknown_report(task, "recorder", LimitReached(Limit::Time, "the test's"));
  }
  std::vector<logic::StandardCheck> asked() const {
    const std::lock_guard lock(mutex_);
    return asked_;
  }

 private:
  mutable std::mutex mutex_;
  mutable std::vector<logic::StandardCheck> asked_;
};

TEST(Portfolio, TheRacersAskOnlyWhatTheProbeLeftOpen) {
  // `conflicts` is n/a under the standard priority, which the probe decides at once; `reachable`
  // stays open when the probe stops at its bound (9 states, a bound of 3). The racers get only
  // `reachable` (xPPU: IC3 worked through the hundreds of output-conflict targets the probe had
  // already decided), and the report still answers both.
  const auto s = load_iec(bench::parallel_branches_iec(3, false));
  ASSERT_TRUE(s.ts);
  auto task = test::task_for(s.project, *s.ts, {}, {});
  task.checks = {logic::StandardCheck::Reachable, logic::StandardCheck::Conflicts};
  auto bdd = std::make_shared<AskedChecksRecorder>(), ic3 = std::make_shared<AskedChecksRecorder>(),
       bmc = std::make_shared<AskedChecksRecorder>();
  PortfolioOptions options;
  options.probe_states = 3;
  options.bdd_racer = bdd;
  options.ic3_racer = ic3;
  options.bmc_racer = bmc;
  const auto report = make_portfolio_model_checker(options)->check(task);
  for (const auto& racer : {bdd, ic3, bmc})
    EXPECT_EQ(racer->asked(), std::vector<logic::StandardCheck>{logic::StandardCheck::Reachable});
  ASSERT_EQ(report.results.size(), 2u);
  EXPECT_EQ(report.results[0].check, "reachable");
  EXPECT_EQ(report.results[0].verdict, Verdict::Unknown) << report.results[0].message;
  EXPECT_EQ(report.results[1].check, "conflicts");
  EXPECT_EQ(report.results[1].verdict, Verdict::NotApplicable) << report.results[1].message;
}

/// A racer that decides part of `reachable`: its answer is unknown, with the steps it reached
/// (`clear`, by index of logic::step_refs).
class PartlyReachingEngine final : public ModelChecker {
 public:
  PartlyReachingEngine(std::string name, std::vector<bool> clear)
      : name_(std::move(name)), clear_(std::move(clear)) {}
  std::string_view name() const override { return name_; }
  bool can_handle(const logic::CheckTask&, std::string*) const override { return true; }
  logic::CheckReport check(const logic::CheckTask& task) const override {
    auto report = logic::unknown_report(task, name_, LimitReached(Limit::Time, "the test's"));
    for (auto& r : report.results) {
      if (r.check != "reachable") continue;
      for (bool c : clear_)
        r.target_answers.push_back(c ? logic::TargetAnswer::Clear : logic::TargetAnswer::Undecided);
    }
    return report;
  }

 private:
  std::string name_;
  std::vector<bool> clear_;
};

/// The race's answer to `reachable` on `s` when the BDD, IC3 and BMC slots reach the steps
/// `by_bdd`, `by_ic3` and `by_bmc` (by step index).
logic::PropertyResult joined_reachable(const Setup& s, const std::vector<bool>& by_bdd,
                                       const std::vector<bool>& by_ic3,
                                       const std::vector<bool>& by_bmc) {
  auto task = test::task_for(s.project, *s.ts, {}, {});
  task.checks = {logic::StandardCheck::Reachable};
  PortfolioOptions options;
  options.probe_states = 0;
  options.bdd_racer = std::make_shared<PartlyReachingEngine>("bdd", by_bdd);
  options.ic3_racer = std::make_shared<PartlyReachingEngine>("ic3", by_ic3);
  options.bmc_racer = std::make_shared<PartlyReachingEngine>("bmc", by_bmc);
  const auto report = make_portfolio_model_checker(options)->check(task);
  EXPECT_EQ(report.results.size(), 1u);
  return report.results.empty() ? logic::PropertyResult{} : report.results.front();
}

TEST(Portfolio, StepsReachedByDifferentEnginesJoinIntoReachable) {
  // xPPU scenario 2: the explicit probe reached 99 of 102 steps, BMC 101, IC3 90; each alone
  // left `reachable` unknown. Every step reached by some engine is reachable: once every step
  // is, the check holds, and the answer says who reached how many.
  const auto s = load_iec(bench::parallel_branches_iec(3, false));
  ASSERT_TRUE(s.ts);
  const auto n = logic::step_refs(*s.ts, &s.project).size();
  ASSERT_GE(n, 4u);
  std::vector<bool> by_bdd(n), by_ic3(n), by_bmc(n, false);
  std::size_t bdd_steps = 0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    by_bdd[k] = k % 2 == 0;
    by_ic3[k] = k % 2 == 1;
    bdd_steps += by_bdd[k] ? 1 : 0;
  }
  by_bmc[n - 1] = true;
  const auto r = joined_reachable(s, by_bdd, by_ic3, by_bmc);
  EXPECT_EQ(r.verdict, Verdict::Holds) << r.message;
  EXPECT_EQ(r.message.rfind("all " + std::to_string(n) +
                                " steps are reachable (the engines "
                                "together: ",
                            0),
            0u)
      << r.message;
  EXPECT_NE(r.message.find("bdd " + std::to_string(bdd_steps)), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("bmc 1"), std::string::npos) << r.message;
  std::vector<std::string> engines;
  for (std::size_t from = 0; from <= r.decided_by.size();) {
    const auto plus = std::min(r.decided_by.find('+', from), r.decided_by.size());
    engines.push_back(r.decided_by.substr(from, plus - from));
    from = plus + 1;
  }
  std::sort(engines.begin(), engines.end());
  EXPECT_EQ(engines, (std::vector<std::string>{"bdd", "bmc", "ic3"})) << r.decided_by;
  EXPECT_TRUE(r.findings.empty());

  // One step no engine reached: unknown, never holds.
  by_bmc[n - 1] = false;
  const auto open = joined_reachable(s, by_bdd, by_ic3, by_bmc);
  EXPECT_EQ(open.verdict, Verdict::Unknown) << open.message;
  EXPECT_TRUE(open.decided_by.empty());
}

}  // namespace
}  // namespace sfcv::engine

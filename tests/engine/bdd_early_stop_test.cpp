// The bdd engine checks invariants ring by ring: when every property is an invariant and each
// has met a bad state, it stops there (CheckReport::stopped_early, depth = rings computed - 1)
// with a shortest counterexample, instead of computing the whole reachable set first.

#include <gtest/gtest.h>

#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_system.hpp"
#include "support/ctl_task.hpp"

namespace sfcv::engine {
namespace {

// S0 -> S1 -> ... -> S<n-1> -> S0, each on `go`: S1 is reached at depth 1, the last step at
// depth n - 1.
std::string ring_chart(int n) {
  std::string t = "PROGRAM Ring\n  VAR_INPUT go : BOOL; END_VAR\n  INITIAL_STEP S0: END_STEP\n";
  for (int k = 1; k < n; ++k) t += "  STEP S" + std::to_string(k) + ": END_STEP\n";
  for (int k = 0; k < n; ++k)
    t += "  TRANSITION FROM S" + std::to_string(k) + " TO S" + std::to_string((k + 1) % n) +
         " := go; END_TRANSITION\n";
  return t + "END_PROGRAM\n";
}

struct Ring {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  explicit Ring(int n) {
    auto loaded = io::load_iec_text(ring_chart(n), "ring.st");
    EXPECT_TRUE(loaded.ok());
    project = std::move(*loaded.project);
    model::Diagnostics diags;
    ts = semantics::make_iec61131_system(project, {}, diags);
    EXPECT_TRUE(ts);
  }
  logic::CheckReport check(const std::vector<std::string>& ctl, bool bdd = true) const {
    const auto task = test::task_for(project, *ts, ctl, {});
    return bdd ? make_bdd_model_checker()->check(task) : make_explicit_model_checker()->check(task);
  }
};

TEST(BddEarlyStop, AnInvariantFailingAtDepthOneStopsAfterTwoRings) {
  const Ring ring(30);
  // (The explicit engine also stops at a violated invariant: count the ring under EF.)
  const auto full = ring.check({"EF S1"}, false);
  ASSERT_EQ(full.states, logic::BigCount(30));
  const auto r = ring.check({"AG !S1"});
  EXPECT_TRUE(r.stopped_early);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.depth, 1u);  // rings 0 and 1 only, of 30
  EXPECT_EQ(r.states, logic::BigCount(2));
  EXPECT_FALSE(r.edges_known);
  ASSERT_EQ(r.results.size(), 1u);
  EXPECT_EQ(r.results[0].verdict, logic::Verdict::Violated);
  ASSERT_TRUE(r.results[0].trace);
  EXPECT_EQ(r.results[0].trace->steps.size(), 2u);  // the shortest run: S0, S1
  EXPECT_EQ(logic::exit_code(r), 1);
}

TEST(BddEarlyStop, WaitsForTheLastInvariantToFail) {
  const Ring ring(30);
  const auto r = ring.check({"AG !S1", "AG !S7"});
  EXPECT_TRUE(r.stopped_early);
  EXPECT_EQ(r.depth, 7u);
  ASSERT_EQ(r.results.size(), 2u);
  ASSERT_TRUE(r.results[1].trace);
  EXPECT_EQ(r.results[1].trace->steps.size(), 8u);
  EXPECT_EQ(r.results[0].trace->steps.size(), 2u);
}

TEST(BddEarlyStop, ExploresEverythingWhenAnInvariantHoldsOrAnotherPropertyNeedsIt) {
  const Ring ring(30);
  for (const auto& ctl : {std::vector<std::string>{"AG !S1", "AG !(S1 & S2)"},
                          std::vector<std::string>{"AG !S1", "EF S29"}}) {
    const auto r = ring.check(ctl);
    EXPECT_FALSE(r.stopped_early) << ctl[1];
    EXPECT_EQ(r.depth, 29u) << ctl[1];
    EXPECT_EQ(r.states, logic::BigCount(30)) << ctl[1];
    EXPECT_TRUE(r.edges_known);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Violated);
  }
}

TEST(BddEarlyStop, AnInitialBadStateStopsAtTheFirstRing) {
  const Ring ring(30);
  const auto r = ring.check({"AG !S0"});
  EXPECT_TRUE(r.stopped_early);
  EXPECT_EQ(r.depth, 0u);
  EXPECT_EQ(r.results[0].verdict, logic::Verdict::Violated);
  ASSERT_TRUE(r.results[0].trace);
  EXPECT_EQ(r.results[0].trace->steps.size(), 1u);
}

}  // namespace
}  // namespace sfcv::engine

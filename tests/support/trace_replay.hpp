#pragma once
// Trace replay for the engine differential tests: a trace is believed only if the semantics
// itself (semantics::simulate) follows it.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "logic/trace.hpp"
#include "semantics/simulate.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::test {

/// The trace's first situation is initial, and each row's inputs lead from the previous
/// situation to the row's, firing the row's transitions (for Grafcet: along the whole transient
/// evolution).
inline void expect_trace_replays(const semantics::TransitionSystem& ts, const logic::Trace& trace) {
  ASSERT_FALSE(trace.steps.empty());
  struct Initial final : semantics::SuccessorSink {
    std::vector<std::vector<semantics::StateWord>> states;
    void successor(const semantics::Successor& s) override {
      states.emplace_back(s.target.begin(), s.target.end());
    }
  } init;
  ts.initial_states(init);
  EXPECT_NE(std::find(init.states.begin(), init.states.end(), trace.steps.front().state),
            init.states.end())
      << "the trace does not start in an initial situation";
  for (std::size_t k = 1; k < trace.steps.size(); ++k) {
    const auto run = semantics::simulate(ts, trace.steps[k - 1].state, {trace.steps[k].inputs});
    ASSERT_TRUE(run.ok) << "row " << k << ": " << run.error;
    EXPECT_EQ(run.states.back(), trace.steps[k].state) << "row " << k;
    EXPECT_EQ(run.fired.back(), trace.steps[k].fired) << "row " << k;
  }
}

}  // namespace sfcv::test

#include "logic/check_result.hpp"

#include <gtest/gtest.h>

#include <initializer_list>

namespace sfcv::logic {
namespace {

CheckReport report_of(std::initializer_list<Verdict> verdicts) {
  CheckReport r;
  for (auto v : verdicts) {
    PropertyResult p;
    p.name = "p" + std::to_string(r.results.size());
    p.verdict = v;
    r.results.push_back(p);
  }
  return r;
}

// Issue 53: exit 0 only when every question asked was decided and holds; a question the engine
// did not check is not a pass (CI would pass with nothing verified); one without meaning on the
// system counts neither way.
TEST(CheckResult, NotCheckedCountsAsUnknownNotApplicableNeither) {
  using V = Verdict;
  EXPECT_EQ(exit_code(report_of({V::Holds, V::Holds})), 0);
  EXPECT_EQ(exit_code(report_of({V::Holds, V::NotApplicable})), 0);
  EXPECT_EQ(exit_code(report_of({V::Holds, V::NotChecked})), 3);
  EXPECT_EQ(exit_code(report_of({V::NotApplicable, V::NotChecked})), 3);
  EXPECT_EQ(exit_code(report_of({V::Holds, V::Unknown, V::NotApplicable})), 3);
  EXPECT_EQ(exit_code(report_of({V::NotChecked, V::Violated})), 1);  // a violation is certain
  EXPECT_EQ(exit_code(report_of({V::Unknown, V::Violated, V::NotApplicable})), 1);
  EXPECT_EQ(to_string(V::NotApplicable), "n/a");
  EXPECT_EQ(to_string(V::NotChecked), "not checked");
}

TEST(CheckResult, NothingDecidedWhenEveryAnswerIsNotCheckedOrNotApplicable) {
  using V = Verdict;
  EXPECT_TRUE(nothing_decided(report_of({V::NotChecked, V::NotChecked})));
  EXPECT_TRUE(nothing_decided(report_of({V::NotChecked, V::NotApplicable})));
  // Something was decided, or a limit stopped a question the engine can decide.
  EXPECT_FALSE(nothing_decided(report_of({V::NotChecked, V::Holds})));
  EXPECT_FALSE(nothing_decided(report_of({V::NotChecked, V::Unknown})));
  EXPECT_FALSE(nothing_decided(report_of({V::NotChecked, V::Violated})));
  // Nothing to decide is not an engine's failure: n/a only, or no question at all.
  EXPECT_FALSE(nothing_decided(report_of({V::NotApplicable})));
  EXPECT_FALSE(nothing_decided(report_of({})));
}

}  // namespace
}  // namespace sfcv::logic

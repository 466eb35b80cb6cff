#include "logic/check_inputs.hpp"

#include <gtest/gtest.h>

#include "logic/formula.hpp"
#include "logic/trace.hpp"
#include "support/toy_system.hpp"

namespace sfcv::logic {
namespace {

TEST(CheckInputs, CollectsSpecCtlFairAndAssume) {
  CheckInputs in;
  in.spec_text = "property a: AG S1;\nfair S2;\nassume !go;\n";
  in.spec_file = "p.spec";
  in.ctl = {"EF S2"};
  in.fair = {"S1"};
  in.assume = {"go -> stop"};
  const auto parsed = parse_check_inputs(in);
  ASSERT_TRUE(parsed.diagnostics.empty());
  ASSERT_EQ(parsed.spec.properties.size(), 2u);
  EXPECT_EQ(parsed.spec.properties[0].name, "a");
  EXPECT_EQ(parsed.spec.properties[1].name, "EF S2");  // --ctl: named by its text
  EXPECT_EQ(parsed.spec.fairness.size(), 2u);
  const auto exprs = assumption_exprs(parsed.spec);
  ASSERT_EQ(exprs.size(), 2u);
  EXPECT_EQ(exprs[0]->kind, model::ExprKind::Not);
  EXPECT_EQ(exprs[1]->kind, model::ExprKind::Or);

  test::ToySystem ts(2, {"go", "stop"}, {"S1", "S2"});
  CheckTask task;
  model::Diagnostics diags;
  resolve_into(parsed.spec, ts, task, diags);
  EXPECT_TRUE(diags.empty());
  EXPECT_EQ(task.properties.size(), 2u);
  EXPECT_EQ(task.fairness.size(), 2u);
  EXPECT_EQ(task.properties[0].formula->args[0]->observable, 0);
}

TEST(CheckInputs, ErrorsNameTheirSource) {
  CheckInputs in;
  in.ctl = {"AG (p"};
  in.fair = {"EF p"};
  const auto parsed = parse_check_inputs(in);
  ASSERT_EQ(parsed.diagnostics.size(), 2u);
  EXPECT_EQ(parsed.diagnostics[0].str().rfind("--ctl 'AG (p':1:6", 0), 0u)
      << parsed.diagnostics[0].str();
  EXPECT_EQ(parsed.diagnostics[1].str().rfind("--fair 'EF p':1:1", 0), 0u)
      << parsed.diagnostics[1].str();
}

TEST(PickInputs, ChangesAsFewInputsAsPossible) {
  const std::vector<semantics::InputVariable> inputs = {
      {"a", model::Type::boolean()},
      {"b", model::Type::boolean()},
      {"n", model::Type::integer("INT(0..9)", 0, 9)}};
  semantics::InputCondition c;
  c.cubes.push_back(semantics::InputCube{{{0, 1, 1}, {1, 1, 1}}});  // a & b
  c.cubes.push_back(semantics::InputCube{{{2, 5, 9}}});             // n >= 5
  // From nothing: the first cube needing the fewest changes from the lowest values.
  EXPECT_EQ(pick_inputs(c, inputs, {}), (std::vector<std::int64_t>{0, 0, 5}));
  // A previous valuation inside the condition is kept.
  EXPECT_EQ(pick_inputs(c, inputs, {1, 1, 0}), (std::vector<std::int64_t>{1, 1, 0}));
  // Otherwise the closest: only b changes.
  EXPECT_EQ(pick_inputs(c, inputs, {1, 0, 2}), (std::vector<std::int64_t>{1, 1, 2}));
  EXPECT_TRUE(c.holds(pick_inputs(c, inputs, {0, 1, 3})));
}

}  // namespace
}  // namespace sfcv::logic

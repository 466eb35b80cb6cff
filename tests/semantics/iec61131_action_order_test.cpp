// Seed 000's partial order on actions (docs/semantics.md §1.2a): "the partial order ...
// distinguishes the execution order on actions modifying the same variable. Note, if this
// order is empty all actions are non-ordered". Actions the order leaves unordered that write a
// common variable run in every order consistent with it: a pseudo-input `order:<variable>`
// (an enumeration naming each order) picks one per cycle.

#include <set>

#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

semantics::ActionPair pair(const std::string& a, const std::string& b, int line = 1) {
  semantics::ActionPair p{a, b, {}};
  p.where.file = "order.txt";
  p.where.line = line;
  p.where.column = 1;
  return p;
}

semantics::Iec61131Options order(semantics::ActionOrder o,
                                 std::vector<semantics::ActionPair> pairs = {}) {
  semantics::Iec61131Options opts;
  opts.action_order = o;
  opts.action_pairs = std::move(pairs);
  return opts;
}

// Zeta `out := 1` and Alpha `out := 2`, declared in this order, both N in S1.
IecBuilder two_writers() {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT out : INT; other : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a");
  b.action_st("Zeta", "out := 1;").action_st("Alpha", "out := 2;");
  b.action_st("Lone", "other := TRUE;");
  b.assoc("S1", "Zeta", "N").assoc("S1", "Alpha", "N").assoc("S1", "Lone", "N");
  return b;
}

const semantics::InputVariable* order_input(const semantics::TransitionSystem& ts) {
  for (const auto& in : ts.inputs())
    if (in.name.starts_with("order:")) return &in;
  return nullptr;
}

std::set<std::int64_t> outs_after_one_cycle(const semantics::TransitionSystem& ts) {
  std::set<std::int64_t> outs;
  const auto init = semantics::first_initial_state(ts);
  for (const auto& s : successors_of(ts, init).all)
    outs.insert(ts.observe(s.target, obs(ts, "out")));
  return outs;
}

TEST(Iec61131ActionOrder, TotalOrdersNeedNoChoice) {
  for (auto o : {semantics::ActionOrder::Declaration, semantics::ActionOrder::Alphabetical}) {
    auto b = two_writers();
    auto ts = b.build(order(o));
    ASSERT_TRUE(ts);
    EXPECT_EQ(order_input(*ts), nullptr);
    EXPECT_EQ(outs_after_one_cycle(*ts),
              (std::set<std::int64_t>{o == semantics::ActionOrder::Declaration ? 2 : 1}));
  }
}

TEST(Iec61131ActionOrder, UnorderedWritersOfOneVariableRunInEitherOrder) {
  auto b = two_writers();
  auto ts = b.build(order(semantics::ActionOrder::Unordered));
  ASSERT_TRUE(ts);
  const auto* in = order_input(*ts);
  ASSERT_NE(in, nullptr);
  EXPECT_TRUE(in->pseudo);
  EXPECT_EQ(in->name, "order:out");
  // Each order is named, the declaration order first; Lone writes nothing shared.
  ASSERT_EQ(in->type.enumerators.size(), 2u);
  EXPECT_EQ(in->type.enumerators[0].first, "Zeta<Alpha");
  EXPECT_EQ(in->type.enumerators[1].first, "Alpha<Zeta");
  EXPECT_EQ(outs_after_one_cycle(*ts), (std::set<std::int64_t>{1, 2}));
  // Replaying an order: Alpha then Zeta leaves 1.
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"order:out", 1}}));
  EXPECT_EQ(r["out"], 1);
}

TEST(Iec61131ActionOrder, AUserPairFixesTheOrderOfItsGroup) {
  auto b = two_writers();
  auto ts = b.build(order(semantics::ActionOrder::Partial, {pair("Alpha", "Main.Zeta")}));
  ASSERT_TRUE(ts);
  EXPECT_EQ(order_input(*ts), nullptr);  // total on the group: no extra input
  EXPECT_EQ(outs_after_one_cycle(*ts), (std::set<std::int64_t>{1}));
}

TEST(Iec61131ActionOrder, NoSharedVariableNoExtraInput) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT x : INT; y : INT; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a");
  b.action_st("A", "x := 1;").action_st("B", "y := x;");
  b.assoc("S1", "A", "N").assoc("S1", "B", "N");
  auto plain = b.build();
  auto unordered = b.build(order(semantics::ActionOrder::Unordered));
  ASSERT_TRUE(plain && unordered);
  EXPECT_EQ(plain->inputs().size(), unordered->inputs().size());
}

TEST(Iec61131ActionOrder, APartialOrderLeavesEveryLinearisation) {
  // A, B, C write n; only A < C: A<B<C, A<C<B, B<A<C.
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT n : INT; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a");
  b.action_st("A", "n := 1;").action_st("B", "n := 2;").action_st("C", "n := 3;");
  b.assoc("S1", "A", "N").assoc("S1", "B", "N").assoc("S1", "C", "N");
  auto ts = b.build(order(semantics::ActionOrder::Partial, {pair("A", "C")}));
  ASSERT_TRUE(ts);
  const auto* in = order_input(*ts);
  ASSERT_NE(in, nullptr);
  std::vector<std::string> names;
  for (const auto& [n, v] : in->type.enumerators) names.push_back(n);
  EXPECT_EQ(names, (std::vector<std::string>{"A<B<C", "A<C<B", "B<A<C"}));
  std::set<std::int64_t> outs;
  const auto init = semantics::first_initial_state(*ts);
  for (const auto& s : successors_of(*ts, init).all)
    outs.insert(ts->observe(s.target, obs(*ts, "n")));
  EXPECT_EQ(outs, (std::set<std::int64_t>{2, 3}));  // never A last
}

TEST(Iec61131ActionOrder, OneRunningWriterDecidesNothing) {
  // In S2 only Alpha runs: one successor per plant input, whatever the order input.
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT out : INT; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "a");
  b.action_st("Zeta", "out := 1;").action_st("Alpha", "out := 2;");
  b.assoc("S1", "Zeta", "N").assoc("S1", "Alpha", "N").assoc("S2", "Alpha", "N");
  auto ts = b.build(order(semantics::ActionOrder::Unordered));
  ASSERT_TRUE(ts);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_EQ(r["S2"], 1);
  const auto c = successors_of(*ts, r.state());
  for (const auto& cond : conditions(c)) EXPECT_EQ(cond.find("order:"), std::string::npos) << cond;
}

TEST(Iec61131ActionOrder, ACycleIsALocatedError) {
  auto b = two_writers();
  const auto err = b.build_error(
      order(semantics::ActionOrder::Partial, {pair("Zeta", "Alpha", 1), pair("Alpha", "Zeta", 2)}));
  EXPECT_NE(err.find("order.txt:2:1"), std::string::npos) << err;
  EXPECT_NE(err.find("closes a cycle"), std::string::npos) << err;
}

TEST(Iec61131ActionOrder, AnUnknownActionIsALocatedError) {
  auto b = two_writers();
  const auto err =
      b.build_error(order(semantics::ActionOrder::Partial, {pair("Zeta", "Omega", 3)}));
  EXPECT_NE(err.find("order.txt:3:1"), std::string::npos) << err;
  EXPECT_NE(err.find("unknown action 'Omega'"), std::string::npos) << err;
}

}  // namespace
}  // namespace sfcv::test

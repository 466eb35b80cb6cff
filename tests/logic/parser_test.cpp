#include "logic/parser.hpp"

#include <gtest/gtest.h>

#include "logic/formula.hpp"
#include "logic/resolve.hpp"
#include "logic/to_expr.hpp"
#include "support/toy_system.hpp"

namespace sfcv::logic {
namespace {

std::string round_trip(const std::string& text) {
  auto r = parse_formula(text);
  if (!r.ok()) return "error: " + r.diagnostics.front().str();
  return to_string(r.formula);
}

TEST(FormulaParser, PrecedenceFollowsNuSmv) {
  EXPECT_EQ(round_trip("AG !(V1 & V3)"), "AG !(V1 & V3)");
  EXPECT_EQ(round_trip("a | b & c"), "a | b & c");
  EXPECT_EQ(round_trip("(a | b) & c"), "(a | b) & c");
  EXPECT_EQ(round_trip("a -> b -> c"), "a -> b -> c");
  EXPECT_EQ(round_trip("(a -> b) -> c"), "(a -> b) -> c");
  EXPECT_EQ(round_trip("a <-> b -> c"), "a <-> b -> c");
  // Unary temporal operators bind like !: AG p & q is (AG p) & q.
  auto f = parse_formula("AG p & q").formula;
  ASSERT_TRUE(f);
  EXPECT_EQ(f->op, Op::And);
  EXPECT_EQ(f->args[0]->op, Op::AG);
  EXPECT_EQ(round_trip("AG (p -> AF q)"), "AG (p -> AF q)");
  EXPECT_EQ(round_trip("a xor b"), "a xor b");
}

TEST(FormulaParser, UntilAtomsAndComparisons) {
  auto f = parse_formula("E[ FILL_A.X U level >= 3 ]").formula;
  ASSERT_TRUE(f);
  EXPECT_EQ(f->op, Op::EU);
  EXPECT_EQ(f->args[0]->op, Op::Atom);
  EXPECT_EQ(f->args[0]->name, "FILL_A.X");
  EXPECT_EQ(f->args[1]->op, Op::Compare);
  EXPECT_EQ(f->args[1]->cmp, CompareOp::Ge);
  EXPECT_EQ(f->args[1]->value, 3);
  EXPECT_EQ(round_trip("A[p U q]"), "A[p U q]");
  EXPECT_EQ(round_trip("3 < n"), "n > 3");
  EXPECT_EQ(round_trip("n = -2"), "n = -2");
  EXPECT_EQ(round_trip("TRUE & !false"), "TRUE & !FALSE");
  EXPECT_EQ(round_trip("EX AX EF AF EG AG X12"), "EX AX EF AF EG AG X12");
}

TEST(FormulaParser, ErrorsPointAtTheColumn) {
  auto r = parse_formula("AG !(V1 & )", "--ctl");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].where.column, 11);
  EXPECT_NE(r.diagnostics[0].message.find("expected a formula"), std::string::npos);
  EXPECT_EQ(r.diagnostics[0].str().rfind("--ctl:1:11", 0), 0u) << r.diagnostics[0].str();

  r = parse_formula("AG (p");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 6);
  r = parse_formula("E[p q]");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 5);
  r = parse_formula("p $ q");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 3);
  r = parse_formula("level >= )");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 10);
  // `level >= x` names an enumerator, resolved against level's type (an error there if none).
  EXPECT_TRUE(parse_formula("level >= x").ok());
  r = parse_formula("AG 3");
  ASSERT_FALSE(r.ok());
  r = parse_formula("p q");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 3);
}

TEST(FormulaParser, PropositionalRejectsTemporalOperators) {
  EXPECT_TRUE(parse_propositional("!(a & b) | n >= 2").ok());
  auto r = parse_propositional("a & EF b");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 5);
}

TEST(SpecParser, PropertiesAssumptionsFairnessAndComments) {
  const auto r = parse_spec(
      "-- plant spec\n"
      "property no_overfill_T1: AG !(V1 & V3);  // tank 1\n"
      "assume !(LIS1 & LIS2);\n"
      "fair S1;\n"
      "property live: AG EF S1;\n",
      "plant.spec");
  ASSERT_TRUE(r.ok()) << r.diagnostics.front().str();
  ASSERT_EQ(r.spec.properties.size(), 2u);
  EXPECT_EQ(r.spec.properties[0].name, "no_overfill_T1");
  EXPECT_EQ(to_string(r.spec.properties[0].formula), "AG !(V1 & V3)");
  EXPECT_EQ(r.spec.properties[0].where.line, 2);
  EXPECT_EQ(r.spec.properties[1].name, "live");
  ASSERT_EQ(r.spec.assumptions.size(), 1u);
  ASSERT_EQ(r.spec.fairness.size(), 1u);
  EXPECT_EQ(to_string(r.spec.fairness[0].formula), "S1");
}

TEST(SpecParser, ErrorsHaveLineAndColumnAndRecover) {
  const auto r = parse_spec(
      "property a: AG p;\n"
      "property b AG q;\n"
      "assume EF x;\n"
      "property a: p;\n"
      "bogus;\n"
      "property c: EF r;\n",
      "x.spec");
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 4u);
  EXPECT_EQ(r.diagnostics[0].str().rfind("x.spec:2:12", 0), 0u) << r.diagnostics[0].str();
  EXPECT_EQ(r.diagnostics[1].where.line, 3);
  EXPECT_EQ(r.diagnostics[1].where.column, 8);
  EXPECT_NE(r.diagnostics[2].message.find("defined twice"), std::string::npos);
  EXPECT_EQ(r.diagnostics[3].where.line, 5);
  // Recovery: c is still parsed.
  ASSERT_EQ(r.spec.properties.size(), 2u);
  EXPECT_EQ(r.spec.properties[1].name, "c");
}

TEST(ToExpr, ConvertsPropositionalFormulas) {
  auto f = parse_propositional("!(LIS1 & S2.X) | n >= 3 -> a <-> b").formula;
  ASSERT_TRUE(f);
  const auto e = to_expr(*f);
  ASSERT_EQ(e->kind, model::ExprKind::Eq);  // <->
  const auto& imp = e->args[0];
  ASSERT_EQ(imp->kind, model::ExprKind::Or);  // a -> b is !a | b
  EXPECT_EQ(imp->args[0]->kind, model::ExprKind::Not);
  EXPECT_EQ(imp->args[0]->args[0]->kind, model::ExprKind::Or);
  EXPECT_EQ(imp->args[1]->kind, model::ExprKind::Name);
  EXPECT_EQ(e->args[1]->name, "b");
  const auto member = to_expr(*parse_formula("S2.X").formula);
  EXPECT_EQ(member->kind, model::ExprKind::Member);
  EXPECT_EQ(member->name, "S2");
  EXPECT_EQ(member->member, "X");
  const auto cmp = to_expr(*parse_formula("n >= 3").formula);
  EXPECT_EQ(cmp->kind, model::ExprKind::Ge);
  EXPECT_THROW(to_expr(*parse_formula("EF a").formula), std::invalid_argument);
}

TEST(Resolve, BindsNamesAndReportsUnknownOnes) {
  test::ToySystem ts(2, {"in1"}, {"S1", "S2"});
  auto ok = resolve(parse_formula("AG !(s1 & S2)").formula, ts, "--ctl");
  ASSERT_TRUE(ok.formula);
  EXPECT_EQ(atom_observables(*ok.formula), (std::vector<std::uint32_t>{0, 1}));
  auto bad = resolve(parse_formula("AG !(S1 & S9)").formula, ts, "--ctl");
  EXPECT_FALSE(bad.formula);
  ASSERT_EQ(bad.diagnostics.size(), 1u);
  EXPECT_EQ(bad.diagnostics[0].where.column, 11);
  EXPECT_NE(bad.diagnostics[0].message.find("unknown name 'S9'"), std::string::npos);
  auto input = resolve(parse_formula("EF in1").formula, ts, "--ctl");
  ASSERT_FALSE(input.formula);
  EXPECT_NE(input.diagnostics[0].message.find("is an input"), std::string::npos);
}

// Issue 49: the IEC 61131-3 operators beside & | !, in any case, and what errors accept.
TEST(ParserIec, KeywordOperatorsReadAsTheSymbols) {
  const std::pair<const char*, const char*> cases[] = {
      {"AG !(V2 AND NOT V4)", "AG !(V2 & !V4)"},
      {"AG (a or b xor c)", "AG (a | b xor c)"},
      {"AG (a <> b)", "AG (a != b)"},
      {"AG (level MOD 2 = 0)", "AG (level mod 2 = 0)"},
      {"AG (level + 1 <= limit * 2)", "AG (level + 1 <= limit * 2)"},
      {"AG (inst.x = Main.inst.y)", "AG (inst.x = Main.inst.y)"},
      {"EF (S.X & Chart.S.X)", "EF (S.X & Chart.S.X)"},
      {"AG ((a & b) = c)", "AG (a & b <-> c)"},
      {"AG (level -1 > 0)", "AG (level + -1 > 0)"},
  };
  for (const auto& [text, printed] : cases) {
    const auto r = parse_formula(text);
    ASSERT_TRUE(r.ok()) << text << ": " << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    EXPECT_EQ(to_string(r.formula), printed) << text;
  }
}

TEST(ParserIec, ErrorsSayWhatIsAccepted) {
  const auto r = parse_formula("AG !(V2 ++ V4)");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("operators accepted: ! NOT, & AND, | OR"),
            std::string::npos)
      << r.diagnostics[0].message;
  const auto unclosed = parse_formula("AG !(V2 & V4");
  ASSERT_FALSE(unclosed.ok());
  EXPECT_NE(unclosed.diagnostics[0].message.find("expected ')'"), std::string::npos);
  EXPECT_NE(unclosed.diagnostics[0].message.find("MOD"), std::string::npos);
  // The keywords are reserved, as in ST: no operand may bear their name.
  EXPECT_FALSE(parse_formula("AG and").ok());
  EXPECT_FALSE(parse_formula("AG (a & MOD)").ok());
  // A number is no formula; comparisons do not chain.
  EXPECT_FALSE(parse_formula("AG (level + 1)").ok());
  EXPECT_FALSE(parse_formula("AG (a < b < c)").ok());
}

}  // namespace
}  // namespace sfcv::logic

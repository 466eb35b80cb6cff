// The LTL syntax: X F G unary (like !), U R W binary (tighter than &, right associative), the
// CTL operators refused, errors located, nesting bounded, and the `ltl` form of spec files.

#include <gtest/gtest.h>

#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "logic/parser.hpp"
#include "model/nesting.hpp"

namespace sfcv::logic {
namespace {

std::string round_trip(const std::string& text) {
  auto r = parse_ltl(text);
  if (!r.ok()) return "error: " + r.diagnostics.front().str();
  return to_string(r.formula);
}

TEST(LtlParser, PrecedenceAndPrinting) {
  EXPECT_EQ(round_trip("G (a -> F b)"), "G (a -> F b)");
  EXPECT_EQ(round_trip("G F a"), "G F a");
  EXPECT_EQ(round_trip("a & b U c"), "a & (b U c)");
  EXPECT_EQ(round_trip("a U b U c"), "(a U (b U c))");
  EXPECT_EQ(round_trip("G a U b"), "(G a U b)");
  EXPECT_EQ(round_trip("!a R X b | c W d"), "(!a R X b) | (c W d)");
  auto f = parse_ltl("G a U b").formula;
  ASSERT_TRUE(f);
  EXPECT_EQ(f->op, Op::U);
  EXPECT_EQ(f->args[0]->op, Op::G);
  EXPECT_TRUE(is_ltl(*f));
  // What it prints parses back to the same formula.
  for (const char* text :
       {"G (a -> F b)", "a & b U c", "X X !(a W b)", "F G (x >= 3)", "G (rise(a) -> X b)"}) {
    const auto once = round_trip(text);
    EXPECT_EQ(round_trip(once), once) << text;
  }
}

TEST(LtlParser, AtomsAsInCtl) {
  auto f = parse_ltl("G (level >= 3 -> X prev(FILL.X))").formula;
  ASSERT_TRUE(f);
  const auto& imp = *f->args[0];
  EXPECT_EQ(imp.args[0]->op, Op::Compare);
  EXPECT_EQ(imp.args[1]->op, Op::X);
  EXPECT_EQ(imp.args[1]->args[0]->prev, 1u);
  // In CTL, G and F stay names (a variable may be called G).
  auto ctl = parse_formula("AG (G -> F)").formula;
  ASSERT_TRUE(ctl);
  EXPECT_FALSE(is_ltl(*ctl));
  EXPECT_EQ(ctl->args[0]->args[0]->op, Op::Atom);
}

TEST(LtlParser, ErrorsAreLocated) {
  auto r = parse_ltl("G (a ->\n  AF b)", "--ltl");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].where.line, 2);
  EXPECT_EQ(r.diagnostics[0].where.column, 3);
  EXPECT_NE(r.diagnostics[0].message.find("CTL operator 'AF'"), std::string::npos);
  r = parse_ltl("G (a U)");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].where.column, 7);
  r = parse_ltl("a U U b");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("keyword 'U'"), std::string::npos);
  r = parse_ltl("E[a U b]");
  EXPECT_FALSE(r.ok());
  r = parse_ltl("prev(F a)");
  EXPECT_FALSE(r.ok());
}

TEST(LtlParser, NestingIsBounded) {
  std::string deep;
  for (int k = 0; k <= model::kMaxNesting; ++k) deep += "G ";
  auto r = parse_ltl(deep + "a");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("nested deeper"), std::string::npos);
  std::string chain = "a";
  for (int k = 0; k <= model::kMaxNesting; ++k) chain += " U a";
  EXPECT_FALSE(parse_ltl(chain).ok());
  std::string shallow;
  for (int k = 0; k < 50; ++k) shallow += "X ";
  EXPECT_TRUE(parse_ltl(shallow + "a").ok());
}

TEST(LtlParser, SpecFileAndOption) {
  auto s = parse_spec("property p: AG a;\nltl q: G (a -> F b);\nltl r: AG a;\n", "f.spec");
  ASSERT_EQ(s.diagnostics.size(), 1u);
  EXPECT_EQ(s.diagnostics[0].where.line, 3);
  ASSERT_EQ(s.spec.properties.size(), 2u);
  EXPECT_FALSE(is_ltl(*s.spec.properties[0].formula));
  EXPECT_EQ(s.spec.properties[1].name, "q");
  EXPECT_TRUE(is_ltl(*s.spec.properties[1].formula));
  // A property name is unique across both forms.
  EXPECT_FALSE(parse_spec("property p: AG a; ltl p: G a;").ok());

  CheckInputs in;
  in.ltl = {"G F a", "G (a"};
  auto parsed = parse_check_inputs(in);
  ASSERT_EQ(parsed.spec.properties.size(), 1u);
  EXPECT_EQ(parsed.spec.properties[0].where.file, "--ltl");
  ASSERT_EQ(parsed.diagnostics.size(), 1u);
  EXPECT_NE(parsed.diagnostics[0].where.file.find("--ltl 'G (a'"), std::string::npos);
}

}  // namespace
}  // namespace sfcv::logic

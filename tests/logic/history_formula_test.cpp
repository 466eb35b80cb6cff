// prev(), rise() and fall() in the property language: parsing, printing, and errors.

#include <gtest/gtest.h>

#include "logic/formula.hpp"
#include "logic/parser.hpp"

namespace sfcv::logic {
namespace {

std::string printed(const std::string& text) {
  auto r = parse_formula(text);
  EXPECT_TRUE(r.formula) << (r.diagnostics.empty() ? "" : r.diagnostics.front().str());
  return r.formula ? to_string(r.formula) : "";
}

TEST(HistoryFormula, PrevDistributesOverConnectivesAndNests) {
  EXPECT_EQ(printed("AG prev(x)"), "AG prev(x)");
  EXPECT_EQ(printed("EF prev(a & !b)"), "EF (prev(a) & !prev(b))");
  EXPECT_EQ(printed("prev(prev(x)) | x"), "prev(prev(x)) | x");
  EXPECT_EQ(printed("prev(level) > 3"), "prev(level) > 3");
  EXPECT_EQ(printed("prev(level > 3)"), "prev(level) > 3");
  auto f = parse_formula("prev(prev(x))").formula;
  ASSERT_TRUE(f);
  EXPECT_EQ(f->op, Op::Atom);
  EXPECT_EQ(f->prev, 2u);
  EXPECT_TRUE(reads_previous(*f));
  EXPECT_FALSE(reads_previous(*parse_formula("AG x").formula));
}

TEST(HistoryFormula, EdgesExpandToPrev) {
  EXPECT_EQ(printed("AG (rise(start) -> AX V1)"), "AG (start & !prev(start) -> AX V1)");
  EXPECT_EQ(printed("EF fall(S1.X)"), "EF (!S1.X & prev(S1.X))");
  EXPECT_EQ(printed("rise(a | b)"), "(a | b) & !(prev(a) | prev(b))");
  // A variable called prev is still a name when no parenthesis follows.
  EXPECT_EQ(printed("prev & rise"), "prev & rise");
}

TEST(HistoryFormula, ErrorsAreLocated) {
  auto r = parse_formula("AG prev(EF x)", "--ctl");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_NE(r.diagnostics[0].message.find("prev() takes a propositional formula"),
            std::string::npos);
  EXPECT_EQ(r.diagnostics[0].where.column, 9);
  r = parse_formula("prev(a & b) > 3", "--ctl");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_NE(r.diagnostics[0].message.find("is no number for '>'"), std::string::npos);
  auto spec = parse_spec("assume rise(a);\nproperty p: AG rise(a) -> b;\n", "s.spec");
  ASSERT_EQ(spec.diagnostics.size(), 1u);
  EXPECT_EQ(spec.diagnostics[0].where.line, 1);
  EXPECT_NE(spec.diagnostics[0].message.find("not allowed in 'assume'"), std::string::npos);
  EXPECT_EQ(spec.spec.properties.size(), 1u);
}

}  // namespace
}  // namespace sfcv::logic

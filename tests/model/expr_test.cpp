#include "model/expr.hpp"

#include <gtest/gtest.h>

#include "model/chart.hpp"
#include "model/types.hpp"

namespace sfcv::model {
namespace {

TEST(Expr, PrintsWithMinimalParentheses) {
  auto a = make_name("a"), b = make_name("b"), c = make_name("c");
  EXPECT_EQ(to_st(make_nary(ExprKind::And, {make_nary(ExprKind::Or, {a, b}), c})),
            "(a OR b) AND c");
  EXPECT_EQ(to_st(make_nary(ExprKind::Or, {make_nary(ExprKind::And, {a, b}), c})), "a AND b OR c");
  EXPECT_EQ(to_st(make_binary(ExprKind::Sub, a, make_binary(ExprKind::Sub, b, c))), "a - (b - c)");
  EXPECT_EQ(to_st(make_unary(ExprKind::Not, make_member("S1", "X"))), "NOT S1.X");
  EXPECT_EQ(to_st(make_binary(ExprKind::Gt, make_member("Step0", "T"), make_time(6000))),
            "Step0.T > T#6s");
}

TEST(Expr, EqualityIgnoresCaseOfNamesAndLocations) {
  SourceLocation here{"f", 1, 2, {}};
  EXPECT_TRUE(equal(make_name("Valve", here), make_name("VALVE")));
  EXPECT_FALSE(equal(make_name("Valve"), make_name("Valves")));
  EXPECT_FALSE(equal(make_int(1), make_bool(true)));
}

TEST(Types, ElementaryRanges) {
  auto t = elementary_type("int");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->lo, -32768);
  EXPECT_EQ(t->hi, 32767);
  EXPECT_EQ(elementary_type("TON")->fb, StandardFb::TON);
  EXPECT_FALSE(elementary_type("REAL"));
}

TEST(Qualifier, ParsesAllStandardQualifiers) {
  for (const char* q : {"N", "R", "S", "P", "P0", "P1", "L", "D", "SD", "DS", "SL", "DL"}) {
    auto parsed = parse_qualifier(q);
    ASSERT_TRUE(parsed) << q;
    EXPECT_EQ(to_string(*parsed), q);
  }
  EXPECT_TRUE(parse_qualifier("sd"));
  EXPECT_FALSE(parse_qualifier("X"));
  EXPECT_TRUE(is_timed(Qualifier::SD));
  EXPECT_FALSE(is_timed(Qualifier::P1));
}

}  // namespace
}  // namespace sfcv::model

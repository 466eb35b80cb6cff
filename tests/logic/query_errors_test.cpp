// Parse, name and sort errors of the query language, with their columns.

#include <gtest/gtest.h>

#include "logic/query_test_support.hpp"

namespace sfcv::test {
namespace {

struct Located {
  std::uint32_t line = 0, column = 0;
  std::string message;
};

Located error_of(const std::string& q) {
  const auto ts = make_query_toy();
  logic::QueryLibrary lib;
  try {
    logic::compile_query(q, lib, ts);
  } catch (const logic::QueryError& e) {
    return {e.pos().line, e.pos().column, e.message()};
  }
  ADD_FAILURE() << "no error for: " << q;
  return {};
}

#define EXPECT_QUERY_ERROR(q, col, fragment)                                   \
  do {                                                                         \
    const auto err_ = error_of(q);                                             \
    EXPECT_EQ(err_.column, col) << q << " -> " << err_.message;                \
    EXPECT_NE(err_.message.find(fragment), std::string::npos) << err_.message; \
  } while (0)

TEST(QueryParse, SyntaxErrorsCarryTheirColumn) {
  EXPECT_QUERY_ERROR("Y - ", 5, "expected a set");
  EXPECT_QUERY_ERROR("Pred(Y0 T)", 9, "')' or ','");
  EXPECT_QUERY_ERROR("Y - Pred(Y0, T))", 16, "after the query");
  EXPECT_QUERY_ERROR("{1, }", 5, "expected a step");
  EXPECT_QUERY_ERROR("Y $ T", 3, "unexpected character '$'");
  EXPECT_QUERY_ERROR("let x = Y Y0", 11, "';'");
  EXPECT_QUERY_ERROR("{e in Steps Act(e) != {}}", 13, "'|'");
  EXPECT_QUERY_ERROR("#Y < 3 < 4", 8, "do not chain");
  EXPECT_QUERY_ERROR("Y - - T", 5, "followed by a number");
  EXPECT_QUERY_ERROR("12abc", 3, "after a number");
}

TEST(QueryParse, DeepNestingIsAnErrorNotACrash) {
  EXPECT_QUERY_ERROR(std::string(5000, '(') + "Y" + std::string(5000, ')'), 201,
                     "nested too deeply");
  EXPECT_QUERY_ERROR(std::string(5000, '!') + "Y", 201, "nested too deeply");
  EXPECT_QUERY_ERROR(std::string(5000, '#') + "Y", 201, "nested too deeply");
  // Reasonable nesting is fine.
  const auto ts = make_query_toy();
  logic::QueryLibrary lib;
  EXPECT_NO_THROW(logic::compile_query(std::string(50, '(') + "Y" + std::string(50, ')'), lib, ts));
}

// A let chain doubling at each line (and the same through definitions) is refused where the
// expansion passes its bound, in milliseconds, instead of growing exponentially.
TEST(QueryParse, ExponentialLetChainsAreRefusedAtTheirBound) {
  std::string q = "let a0 = Y;\n";
  for (int i = 1; i <= 40; ++i)
    q += "let a" + std::to_string(i) + " = a" + std::to_string(i - 1) + " + a" +
         std::to_string(i - 1) + ";\n";
  q += "a40";
  const auto e = error_of(q);
  EXPECT_NE(e.message.find("expands to more than"), std::string::npos) << e.message;
  EXPECT_GT(e.column, 0u);  // located (where the count ran out)

  const auto ts = make_query_toy();
  logic::QueryLibrary lib;
  std::string defs = "def d0() = Y;\n";
  for (int i = 1; i <= 40; ++i)
    defs += "def d" + std::to_string(i) + "() = d" + std::to_string(i - 1) + "() + d" +
            std::to_string(i - 1) + "();\n";
  lib.add_text(defs, "chain.sfq");
  try {
    logic::compile_query("d40()", lib, ts);
    ADD_FAILURE() << "no error for a doubling definition chain";
  } catch (const logic::QueryError& err) {
    EXPECT_NE(err.message().find("expands to more than"), std::string::npos) << err.message();
  }
  // Twelve doublings (4,096 uses) stay well within the bound.
  std::string small = "let a0 = Y;\n";
  for (int i = 1; i <= 12; ++i)
    small += "let a" + std::to_string(i) + " = a" + std::to_string(i - 1) + " + a" +
             std::to_string(i - 1) + ";\n";
  EXPECT_NO_THROW(logic::compile_query(small + "a12", lib, ts));
}

TEST(QueryParse, ErrorsOnLaterLinesCountLines) {
  const auto e = error_of("let a = Y;\n  a + T");
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.column, 5u);
  EXPECT_NE(e.message.find("same sort"), std::string::npos) << e.message;
}

TEST(QuerySorts, OperandsMustHaveTheSameSort) {
  EXPECT_QUERY_ERROR("Y + T", 3,
                     "the left one is a set of situations, the right one a set of "
                     "evolutions");
  EXPECT_QUERY_ERROR("Y0 * Steps", 4, "same sort");
  EXPECT_QUERY_ERROR("T - Y", 3, "same sort");
  EXPECT_QUERY_ERROR("Y = T", 3, "same sort");
  EXPECT_QUERY_ERROR("Int(T)", 5, "must be a set of situations");
  EXPECT_QUERY_ERROR("Amont(Y)", 7, "must be a set of evolutions");
  EXPECT_QUERY_ERROR("Pred(T, T)", 6, "must be a set of situations");
  EXPECT_QUERY_ERROR("Succ(Y0, Y0)", 10, "must be a set of evolutions");
  EXPECT_QUERY_ERROR("Act(Y0)", 5, "expected a set of steps");
  EXPECT_QUERY_ERROR("Y & Y0", 3, "for an intersection write '*'");
  EXPECT_QUERY_ERROR("Y | Y0", 3, "for a union write '+'");
  EXPECT_QUERY_ERROR("!Y", 1, "Y - A");
  EXPECT_QUERY_ERROR("#Y < Y", 4, "cannot compare a number with a set of situations");
  EXPECT_QUERY_ERROR("Y < Y0", 3, "compare sets with '='");
  EXPECT_QUERY_ERROR("(Y = {}) + Y", 10, "left operand is a test");
  EXPECT_QUERY_ERROR("{e | Act(e)}", 6, "must be a test");
}

TEST(QueryNames, UnknownAndMisusedNames) {
  EXPECT_QUERY_ERROR("Y - Z", 5, "unknown name 'Z'");
  EXPECT_QUERY_ERROR("Y - X1", 5, "is a step: write {X1}");
  EXPECT_QUERY_ERROR("O1", 1, "is an output, not a set: write Emis(O1)");
  EXPECT_QUERY_ERROR("a + Y", 1, "is an input, not a set: write Nec(a)");
  EXPECT_QUERY_ERROR("Act({X1, O1})", 10, "'O1' is not a step");
  EXPECT_QUERY_ERROR("Act({7})", 6, "no step numbered 7");
  EXPECT_QUERY_ERROR("Emis(O1 & a)", 11, "is an input");
  EXPECT_QUERY_ERROR("Emis(Q)", 6, "unknown name 'Q'");
  EXPECT_QUERY_ERROR("Nec(a + b)", 7, "set operator");
  EXPECT_QUERY_ERROR("Emis(Act({X1}))", 6, "is a set");
  EXPECT_QUERY_ERROR("Foo(Y)", 1, "unknown operator or definition 'Foo'");
  EXPECT_QUERY_ERROR("Pred(Y0)", 1, "takes 2 arguments");
  EXPECT_QUERY_ERROR("let T = Y; T", 1, "predefined");
  EXPECT_QUERY_ERROR("Emis(O1 < 3)", 9, "compares a Boolean with a number");
}

TEST(QueryParse, PrintsBackWithMinimalParentheses) {
  for (const std::string q :
       {"Y - Pred(Y0, T)", "Emis((O1 | X1) & (O2 | X2)) = {}", "Y - (Y0 - Act({1, 10}))",
        "#Y >= 3 & !(Y0 = {})", "{e in Steps | Act({e}) - Pred(Des({e}), T) != {}}",
        "let a = Y; a * Y0"}) {
    EXPECT_EQ(logic::to_string(*logic::parse_query(q)), q);
  }
}

}  // namespace
}  // namespace sfcv::test

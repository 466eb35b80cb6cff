// The shipped property library (share/sfcv/properties.sfq) and user definitions.

#include <gtest/gtest.h>

#include "logic/query_test_support.hpp"

namespace sfcv::test {
namespace {

using Edges = std::set<std::pair<std::uint32_t, std::uint32_t>>;
using States = std::set<std::uint32_t>;
using StepNames = std::set<std::string>;

class QueryLibraryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    f.library().add_file(std::string(SFCV_SOURCE_DIR) + "/share/sfcv/properties.sfq");
  }
  QueryFixture f{make_query_toy()};
};

TEST_F(QueryLibraryTest, ShippedDefinitions) {
  EXPECT_EQ(f.S("global_deadlock()"), (States{4}));
  EXPECT_EQ(f.S("global_deadlock"), (States{4}));  // no arguments: the parentheses are optional
  EXPECT_EQ(f.St("local_deadlock()"), (StepNames{"X1", "X2", "X3"}));
  EXPECT_EQ(f.S("no_return_to_initial()"), (States{3, 4}));
  EXPECT_EQ(f.S("no_return_to(Act({X3}))"), (States{4}));
  EXPECT_EQ(f.S("mutex(O1, O2)"), (States{3}));
  EXPECT_EQ(f.S("mutex(O1, X1)"), States{});
  EXPECT_EQ(f.S("pistons_move_together(X1, O1, X3, O2)"), (States{3}));
  EXPECT_EQ(f.S("precedence(O1, X1, O2)"), (States{1, 3}));
  EXPECT_EQ(f.S("precedence(O2, X1, O1)"), (States{3}));
  EXPECT_EQ(f.E("entries_into(Act({X3}))"), (Edges{{1, 2}, {1, 3}}));
  EXPECT_EQ(f.S("leads_to(Y - Amont(T))"), (States{0, 1, 2, 3, 4}));
  EXPECT_EQ(f.S("stored_start_and_stop({X2}, {X3})"), (States{3}));
  EXPECT_EQ(f.E("stored_twice(O2, {X3})"), Edges{});
  EXPECT_EQ(f.E("stored_twice(O1, {X3})"), (Edges{{1, 2}, {1, 3}}));
  EXPECT_EQ(f.St("unreachable_steps()"), StepNames{});
  EXPECT_EQ(f.E("not_guarded_by(a)"), (Edges{{1, 2}, {2, 0}, {3, 4}}));
  // An argument may itself be an expression.
  EXPECT_EQ(f.S("mutex(O1 | X1, !O2)"), (States{0, 1}));
  EXPECT_TRUE(f.B("mutex(O1, X1) = {}"));
}

TEST_F(QueryLibraryTest, UserDefinitionsCallEachOtherAndOverride) {
  f.library().add_text(
      "// faulty situations of the toy\n"
      "def both() = O1 & O2;\n"
      "def bad() = Emis(both());\n"
      "def into_bad() = entries_into(bad);\n"
      "def mutex(a, b) = Emis(a | b);  // replaces the shipped one\n",
      "user.sfq");
  EXPECT_EQ(f.S("bad()"), (States{3}));
  EXPECT_EQ(f.E("into_bad()"), (Edges{{1, 3}}));
  EXPECT_EQ(f.S("mutex(O1, O2)"), (States{1, 2, 3}));
  ASSERT_NE(f.library().find("both"), nullptr);
  EXPECT_EQ(f.library().find("both")->doc, "faulty situations of the toy\n");
}

TEST_F(QueryLibraryTest, ParametersAreLexicallyScoped) {
  // `a` inside the definition is its parameter, not the caller's let binding or the input a.
  f.library().add_text("def first(a, b) = a;", "user.sfq");
  EXPECT_EQ(f.S("let a = Y; first(Y0, a)"), (States{0}));
  EXPECT_EQ(f.S("let b = Y0; first(b, Y)"), (States{0}));
}

logic::QueryError library_error(const std::string& text) {
  logic::QueryLibrary lib;
  try {
    lib.add_text(text, "lib.sfq");
  } catch (const logic::QueryError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for: " << text;
  return logic::QueryError({}, "");
}

TEST(QueryLibraryErrors, DefinitionSyntax) {
  auto e = library_error("def f(a) = Y;\ndef f(b) = T;");
  EXPECT_EQ(e.pos().line, 2u);
  EXPECT_NE(e.message().find("already defined at lib.sfq:1:1"), std::string::npos) << e.what();
  e = library_error("def f(a, a) = Y;");
  EXPECT_EQ(e.pos().column, 10u);
  e = library_error("def f() = Y");
  EXPECT_NE(e.message().find("';' ending the definition of 'f'"), std::string::npos) << e.what();
  e = library_error("def Pred(a) = Y;");
  EXPECT_NE(e.message().find("predefined"), std::string::npos);
  e = library_error("let x = Y;");
  EXPECT_NE(e.message().find("expected 'def"), std::string::npos);
  EXPECT_EQ(std::string(e.what()).rfind("lib.sfq:1:1: ", 0), 0u) << e.what();
}

TEST(QueryLibraryErrors, ErrorsInsideADefinitionNameTheCallSite) {
  const auto ts = make_query_toy();
  logic::QueryLibrary lib;
  lib.add_text("def f(x) =\n  Y + x;\ndef loop(x) = loop(x);", "lib.sfq");
  try {
    logic::compile_query("f(T)", lib, ts);
    FAIL();
  } catch (const logic::QueryError& e) {
    EXPECT_EQ(e.pos().str(), "lib.sfq:2:5");
    EXPECT_NE(e.message().find("in 'f' used at query:1:1"), std::string::npos) << e.what();
  }
  try {
    logic::compile_query("Y - f()", lib, ts);
    FAIL();
  } catch (const logic::QueryError& e) {
    EXPECT_EQ(e.pos().str(), "query:1:5");
    EXPECT_NE(e.message().find("takes 1 argument(s), 0 given"), std::string::npos) << e.what();
  }
  EXPECT_THROW(logic::compile_query("loop(Y)", lib, ts), logic::QueryError);
  EXPECT_THROW(lib.add_file("/nonexistent/lib.sfq"), logic::QueryError);
}

}  // namespace
}  // namespace sfcv::test

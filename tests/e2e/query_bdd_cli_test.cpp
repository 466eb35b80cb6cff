// sfcv query --engine bdd: the symbolic evaluation prints exactly what the explicit one prints
// (same counts, same elements, same numbering, same JSON), and refuses what it cannot do.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

std::string quoted(const std::string& path) {
  return "'" + path + "'";
}
std::string plant() {
  return quoted(source_path("examples/chemical_plant/chemical_plant.st"));
}

const char* kQueries =
    " 'Y - Amont(T)' 'Y - Pred(Y0, T)' 'Tclear' 'Int(Emis(V2 & V4))' 'Nec(start & LIS1minus)'"
    " 'Succ(Y0, T - Nec(start))' '{e | Act({e}) * Emis(M) != {}}' '#Ext(Act(s12)) > 1'"
    " 'Emis(V1 & V3) = {}' 'let c = Act({s5, s12}); Ext(c) - Int(c)'"
    " --use 'mutex(V2, V4)' --use 'mutex(V1, V3)'";

TEST(QueryBddCli, PrintsWhatTheExplicitEnginePrints) {
  const auto x = run_sfcv("query " + plant() + kQueries + " --engine explicit");
  const auto b = run_sfcv("query " + plant() + kQueries + " --engine bdd");
  EXPECT_EQ(x.exit_code, 0) << x.err;
  EXPECT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(x.out, b.out);
  EXPECT_NE(b.out.find("(iec61131, complete)"), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("query: Tclear\n"), std::string::npos) << b.out;
  // The default stays explicit; auto keeps a small chart explicit and says so.
  EXPECT_EQ(run_sfcv("query " + plant() + kQueries).out, x.out);
  const auto a = run_sfcv("query " + plant() + kQueries + " --engine auto");
  EXPECT_EQ(a.out, x.out);
  EXPECT_NE(a.err.find("--engine auto: using the explicit engine"), std::string::npos) << a.err;
}

TEST(QueryBddCli, JsonAndAssertAgree) {
  const auto x = run_sfcv("query " + plant() + kQueries + " --json --assert --engine explicit");
  const auto b = run_sfcv("query " + plant() + kQueries + " --json --assert --engine bdd");
  EXPECT_EQ(x.exit_code, 1) << x.err;  // mutex(V2, V4) is violated (the paper's flaw)
  EXPECT_EQ(b.exit_code, 1) << b.err;
  const auto jx = nlohmann::json::parse(x.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(jx, jb);
  ASSERT_EQ(jb["queries"].size(), 12u);
  EXPECT_EQ(jb["queries"][10]["verdict"], "violated");
  EXPECT_EQ(jb["queries"][11]["verdict"], "holds");
  EXPECT_GT(jb["queries"][2]["count"].get<int>(), 0);
}

TEST(QueryBddCli, RangeErrorsAreAnomaliesInBothEngines) {
  const auto file = write_temp(R"(
PROGRAM Count
  VAR_INPUT a : BOOL; k : INT(-2..3); END_VAR
  VAR_OUTPUT n : INT(0..3); busy : BOOL; END_VAR
  INITIAL_STEP S1: END_STEP
  STEP S2: Inc(N); busy(N); END_STEP
  TRANSITION FROM S1 TO S2 := a AND k >= 0; END_TRANSITION
  TRANSITION FROM S2 TO S1 := NOT a OR k < -1; END_TRANSITION
  ACTION Inc: n := n + 1; END_ACTION
END_PROGRAM
)",
                               ".st");
  const std::string q = " 'Y' 'Nec(k >= 0)' 'Int(Emis(n >= 2 & busy))' --assert";
  const auto x = run_sfcv("query " + quoted(file) + q + " --engine explicit");
  const auto b = run_sfcv("query " + quoted(file) + q + " --engine bdd");
  EXPECT_EQ(x.exit_code, 3) << x.err;
  EXPECT_EQ(b.exit_code, 3) << b.err;
  EXPECT_EQ(x.out, b.out);
  EXPECT_EQ(x.err, b.err);
  EXPECT_NE(b.out.find("8 situations (2 distinct step sets)"), std::string::npos) << b.out;
  EXPECT_NE(b.err.find("out of the range"), std::string::npos) << b.err;
}

TEST(QueryBddCli, RefusesWhatItCannotDo) {
  // Grafcet: not encoded symbolically yet.
  auto r =
      run_sfcv("query " + quoted(source_path("examples/pistons/pistons.g7")) + " 'Y' --engine bdd");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("does not support the Grafcet semantics"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  // auto falls back to the explicit engine and says why.
  r = run_sfcv("query " + quoted(source_path("examples/pistons/pistons.g7")) +
               " '#Y' --engine auto");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("using the explicit engine"), std::string::npos) << r.err;
  r = run_sfcv("query " + plant() + " 'Y' --engine nosuch");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown --engine 'nosuch'"), std::string::npos) << r.err;
  // A limit gives unknown, never a partial answer.
  r = run_sfcv("query " + plant() + " 'Y - Amont(T)' --assert --engine bdd --max-states 5");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("--max-states"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("holds"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sfcv::test

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

/// A chart whose cycle reads `inputs` free Boolean inputs (their parity steers the steps) and
/// counts its cycles up to `top`: 2^inputs input valuations per situation for the explicit
/// engine, a few BDD operations per layer for the symbolic one.
std::string parity_counter(int inputs, int top) {
  std::string names, parity;
  for (int k = 0; k < inputs; ++k) {
    names += (k ? ", i" : "i") + std::to_string(k);
    parity += (k ? " XOR i" : "i") + std::to_string(k);
  }
  const auto bound = std::to_string(top);
  return write_temp("PROGRAM Parity\n  VAR_INPUT " + names +
                        " : BOOL; END_VAR\n  VAR x : BOOL; n : INT(0.." + bound +
                        "); END_VAR\n"
                        "  INITIAL_STEP s0: a(N); END_STEP\n  STEP s1: a(N); END_STEP\n"
                        "  TRANSITION FROM s0 TO s1 := x; END_TRANSITION\n"
                        "  TRANSITION FROM s1 TO s0 := NOT x; END_TRANSITION\n"
                        "  ACTION a: x := " +
                        parity + "; IF n < " + bound + " THEN n := n + 1; END_IF; END_ACTION\n" +
                        "END_PROGRAM\n",
                    ".st");
}

// Issue 15: where the explicit engine stalls, auto hands the query to the BDD engine, which
// prints what it prints alone: a situation wider than the probe's input valuations, and under
// --timeout a probe that used its share of the time (0.2 s a situation here, 601 situations).
TEST(QueryBddCli, AutoHandsAStalledExplicitEngineToTheBddEngine) {
  const std::string queries = " 'Emis(s1 & n = 300) = {}' 'Emis(n > 300) = {}' --assert";
  const auto wide = quoted(parity_counter(24, 300));
  const auto b = run_sfcv("query " + wide + queries + " --engine bdd");
  ASSERT_EQ(b.exit_code, 1) << b.out << b.err;
  auto a = run_sfcv("query " + wide + queries + " --engine auto");
  EXPECT_EQ(a.exit_code, 1) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.err.find("input valuations: switching to the bdd engine"), std::string::npos)
      << a.err;
  const auto slow = quoted(parity_counter(14, 300));
  a = run_sfcv("query " + slow + queries + " --engine auto --timeout 6");
  EXPECT_EQ(a.exit_code, 1) << a.err;
  EXPECT_EQ(a.out, run_sfcv("query " + slow + queries + " --engine bdd").out);
  EXPECT_NE(a.err.find("used its share of the time"), std::string::npos) << a.err;
  // The user's state bound still ends the run in the explicit engine: unknown, not a hand-over.
  a = run_sfcv("query " + slow + queries + " --engine auto --max-states 2");
  EXPECT_EQ(a.exit_code, 3) << a.out << a.err;
  EXPECT_EQ(a.out.find("holds"), std::string::npos) << a.out;
}

}  // namespace
}  // namespace sfcv::test

// sfcv query on the shipped examples and small inline grafcets.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

std::string pistons() {
  return "'" + source_path("examples/pistons/pistons.g7") + "'";
}

TEST(QueryCli, GlobalDeadlockOnThePistons) {
  const auto r = run_sfcv("query " + pistons() + " 'Y - Amont(T)'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(grafcet, complete)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("query: Y - Amont(T)\n  0 situations"), std::string::npos) << r.out;
}

TEST(QueryCli, AssertGivesVerdictsAndExitCodes) {
  auto r = run_sfcv("query " + pistons() + " 'Emis((I1 | O1) & (I2 | O2)) = {}' --assert");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  true\n  0 situations\n  holds"), std::string::npos) << r.out;

  // Free sensors let piston 1 be "in" and "out" at once: piston 2 may then start while I1 is
  // only emitted in a transient situation.
  r = run_sfcv("query " + pistons() + " --use 'precedence(O1, I1, O2)' --assert");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("VIOLATED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{11,20} O1"), std::string::npos) << r.out;

  // The worst verdict wins: one violation among holding properties exits 1.
  r = run_sfcv("query " + pistons() +
               " 'Y - Amont(T)' --use 'mutex(O1, O2)' "
               "--use 'precedence(O1, I1, O2)' --assert");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

TEST(QueryCli, AnIncompleteGraphNeverGivesAVerdict) {
  const auto r = run_sfcv("query " + pistons() + " 'Y - Amont(T)' --max-states 5 --assert");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("incomplete"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("unknown: the graph is incomplete"), std::string::npos) << r.out;
  // Without --assert the listing is still printed, and the exit code still says unknown.
  EXPECT_EQ(run_sfcv("query " + pistons() + " 'Y0' --max-states 5").exit_code, 3);
}

TEST(QueryCli, ErrorsAreLocatedAndExit2) {
  auto r = run_sfcv("query " + pistons() + " 'Y + T'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("query:1:3: the operands of '+' must have the same sort"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("  Y + T\n    ^"), std::string::npos) << r.err;
  r = run_sfcv("query " + pistons() + " 'Emis(O7)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("query:1:6: unknown name 'O7'"), std::string::npos) << r.err;
  r = run_sfcv("query " + pistons() + " --use 'nosuch(O1)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--use:1:1: unknown operator or definition 'nosuch'"), std::string::npos)
      << r.err;
  r = run_sfcv("query " + pistons());
  EXPECT_EQ(r.exit_code, 2);
  r = run_sfcv("query " + pistons() + " '#Y' --assert");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is a number"), std::string::npos) << r.err;
}

TEST(QueryCli, Json) {
  const auto r = run_sfcv("query " + pistons() + " 'Act({11}) * Y0' 'Y0 != {}' '#Y' " +
                          "'Int(Act({12, 20})) * Ext(Act({13}))' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["semantics"], "grafcet");
  EXPECT_GT(j["graph"]["situations"].get<int>(), 0);
  EXPECT_EQ(j["graph"]["complete"], true);
  ASSERT_EQ(j["queries"].size(), 4u);
  EXPECT_EQ(j["queries"][0]["sort"], "situations");
  EXPECT_EQ(j["queries"][0]["count"], 0);
  EXPECT_EQ(j["queries"][1]["sort"], "test");
  EXPECT_EQ(j["queries"][1]["value"], true);
  EXPECT_GT(j["queries"][1]["count"].get<int>(), 0);
  EXPECT_EQ(j["queries"][2]["value"], j["graph"]["situations"]);
  const auto& e = j["queries"][3];
  EXPECT_EQ(e["sort"], "evolutions");
  ASSERT_GT(e["count"].get<int>(), 0);
  for (const auto& ev : e["elements"]) {
    EXPECT_NE(ev["condition"].get<std::string>().find("in1"), std::string::npos) << ev;
    EXPECT_EQ(ev["fired"][0], "(3) X12 -> X13") << ev;
  }
}

TEST(QueryCli, UserLibrariesAndList) {
  const auto lib = write_temp(
      "// both pistons out\ndef both_out() = Emis(O1 & O2);\n"
      "def mutex(a, b) = Emis(a | b);\n",
      ".sfq");
  auto r = run_sfcv("query " + pistons() + " --library '" + lib +
                    "' --use both_out --use "
                    "'mutex(O1, O2)' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["queries"][0]["count"], 0);
  EXPECT_GT(j["queries"][1]["count"].get<int>(), 0);  // the user's mutex replaced the shipped one
  r = run_sfcv("query --list");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("mutex(a, b) = Emis(a & b);"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("global_deadlock() = Y - Pred(Amont(Tclear), T);"), std::string::npos)
      << r.out;
  const auto bad = write_temp("def f() = Y +;\n", ".sfq");
  r = run_sfcv("query " + pistons() + " Y --library '" + bad + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ":1:14:"), std::string::npos) << r.err;
}

TEST(QueryCli, InlineGrafcetWithADeadlockAndNec) {
  const auto g7 = write_temp(R"(
    project dead;
    input a, b;
    output V;
    grafcet G {
      step 1 initial; step 2; step 3;
      transition 1: 1 -> 2 when a & !b;
      transition 2: 2 -> 3 when b;
      action 2: V;
    }
  )",
                             ".g7");
  auto r = run_sfcv("query '" + g7 + "' --use global_deadlock --assert");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("4 situations (1 distinct step sets)"), std::string::npos) << r.out;
  // Step 3 with each of the 4 valuations of a, b. Input changes are evolutions: no node is
  // without successor, but every node with step 3 is dead.
  EXPECT_EQ(run_sfcv("query '" + g7 + "' 'Y - Amont(T) = {}' --assert").exit_code, 0);
  EXPECT_EQ(run_sfcv("query '" + g7 + "' 'global_deadlock = Act({3})' 'Act({3}) != {}' --assert")
                .exit_code,
            0);
  // Every evolution out of step 2 needs b; the one out of step 1 needs a and !b.
  r = run_sfcv("query '" + g7 +
               "' 'Int(Act({2})) * Ext(Act({3})) - Nec(b) = {}' "
               "'Int(Act({1})) * Ext(Act({2})) - Nec(a & !b) = {}' "
               "'Int(Act({1})) * Ext(Act({2})) * Nec(b) = {}' 'Emis(V) = Act({2})' --assert");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(QueryCli, PalletTransferCollision) {
  const auto flawed = source_path("examples/pallet_transfer/pallet_transfer.g7");
  const auto fixed = source_path("examples/pallet_transfer/pallet_transfer_fixed.g7");
  auto r = run_sfcv("query '" + flawed +
                    "' --use 'entries_into(Act({10, 25}))' "
                    "'Act({1, 10, 20, 25, 31, 40}) != {}' --assert --max-elements 2");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("VIOLATED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--> #"), std::string::npos) << r.out;
  r = run_sfcv("query '" + fixed +
               "' --use 'entries_into(Act({10, 25}))' 'Act({10, 25}) = {}' "
               "--assert");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace sfcv::test

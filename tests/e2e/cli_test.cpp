// End-to-end: the binary's subcommands, help and exit-code contract.

#include <nlohmann/json.hpp>
#include <regex>
#include <utility>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::write_temp;

TEST(Cli, HelpListsSubcommands) {
  const auto r = run_sfcv("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"check", "info", "lint", "simulate", "rsg", "query", "export"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub << " missing from --help:\n" << r.out;
  EXPECT_NE(r.out.find("Exit codes"), std::string::npos);
}

// The first line is unchanged; then the commit and the libraries (issue 48).
TEST(Cli, VersionPrintsNameProjectVersionCommitAndLibraries) {
  const auto r = run_sfcv("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("sfcv " SFCV_VERSION "\ncommit ", 0), 0u) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("\ncommit ([0-9a-f]{40}(-dirty)?|unknown)\n")))
      << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("\nBuDDy [0-9]+\\.[0-9]+"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("\nCaDiCaL [^\n]+\n$"))) << r.out;
}

TEST(Cli, MissingFileIsBadInput) {
  const auto r = run_sfcv("check /nonexistent/chart.xml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/chart.xml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot open the model"), std::string::npos) << r.err;
}

TEST(Cli, UnknownOptionIsBadUsage) {
  const auto r = run_sfcv("check --no-such-option x.xml");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(Cli, NoSubcommandIsBadUsage) {
  const auto r = run_sfcv("");
  EXPECT_EQ(r.exit_code, 2);
}

// Two transitions conflict on `a`: the standard priority keeps one, --priority none both. Every
// subcommand that builds the system must read the flag the same way (they share one option set).
TEST(Cli, SemanticsOptionsBuildTheSameSystemInEverySubcommand) {
  const auto chart = write_temp(R"(PROGRAM conflict
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; END_VAR
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  STEP S2 : q(N); END_STEP
  TRANSITION FROM S0 TO S1 := a; END_TRANSITION
  TRANSITION FROM S0 TO S2 := a; END_TRANSITION
  TRANSITION FROM S1 TO S0 := NOT a; END_TRANSITION
  TRANSITION FROM S2 TO S0 := NOT a; END_TRANSITION
END_PROGRAM
)",
                                ".st");
  for (const auto& [flags, states] : {std::pair<std::string, int>{"", 2}, {"--priority none", 3}}) {
    const auto rsg = run_sfcv("rsg " + chart + " " + flags + " --json");
    ASSERT_EQ(rsg.exit_code, 0) << rsg.err;
    EXPECT_EQ(nlohmann::json::parse(rsg.out)["states"].size(), static_cast<std::size_t>(states))
        << flags;
    const auto query = run_sfcv("query " + chart + " '#Y' " + flags + " --json");
    ASSERT_EQ(query.exit_code, 0) << query.err;
    EXPECT_EQ(nlohmann::json::parse(query.out)["queries"][0]["value"], states) << flags;
    const auto check =
        run_sfcv("check " + chart + " " + flags + " --checks reachable --json --quiet");
    EXPECT_EQ(nlohmann::json::parse(check.out)["states"], states) << flags;
  }
}

TEST(Cli, IecOptionsOnAGrafcetAreBadUsageNotIgnored) {
  const auto chart = sfcv::test::source_path("examples/pallet_transfer/pallet_transfer_fixed.g7");
  for (const char* sub : {"rsg", "query", "check"}) {
    const auto r = run_sfcv(std::string(sub) + " " + chart + " --priority none" +
                            (std::string(sub) == "query" ? " '#Y'" : ""));
    EXPECT_EQ(r.exit_code, 2) << sub;
    EXPECT_NE(r.err.find("apply to the IEC 61131-3 semantics only"), std::string::npos) << r.err;
  }
}

}  // namespace

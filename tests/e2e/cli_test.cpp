// End-to-end: the binary's subcommands, help and exit-code contract.

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;

TEST(Cli, HelpListsSubcommands) {
  const auto r = run_sfcv("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"check", "info", "lint", "simulate", "rsg", "query", "export"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub << " missing from --help:\n" << r.out;
  EXPECT_NE(r.out.find("Exit codes"), std::string::npos);
}

TEST(Cli, VersionPrintsName) {
  const auto r = run_sfcv("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("sfcv"), std::string::npos);
}

TEST(Cli, MissingFileIsBadInput) {
  const auto r = run_sfcv("check /nonexistent/chart.xml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/chart.xml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot open file"), std::string::npos) << r.err;
}

TEST(Cli, UnknownOptionIsBadUsage) {
  const auto r = run_sfcv("check --no-such-option x.xml");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(Cli, NoSubcommandIsBadUsage) {
  const auto r = run_sfcv("");
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace

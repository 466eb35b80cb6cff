// Requirement patterns end to end: --pattern and `pattern` statements in a spec file, the
// English sentence in text, JSON, JUnit and SARIF, vacuity, bounds in time, exit codes 0/1/2,
// and `sfcv patterns`.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kPlant =
    "'" + std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st'";

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

class PatternCli : public ::testing::TestWithParam<const char*> {};

TEST_P(PatternCli, ChemicalPlantVerdictsAndSentences) {
  const auto r = run_sfcv("check " + kPlant + " --engine " + GetParam() +
                          " --json --pattern 'absence(V1 & V3)' --pattern 'implies(V1 & V3, M)'"
                          " --pattern 'response(start, V1, within 1 cycle)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["properties"].size(), 3u);
  EXPECT_EQ(j["properties"][0]["name"], "absence(V1 & V3)");
  EXPECT_EQ(j["properties"][0]["description"], "V1 & V3 is never true.");
  EXPECT_EQ(j["properties"][0]["formula"], "AG !(V1 & V3)");
  EXPECT_EQ(j["properties"][0]["verdict"], "holds");
  EXPECT_EQ(j["properties"][1]["verdict"], "holds");
  EXPECT_EQ(j["properties"][1]["vacuous"], true);  // the antecedent V1 & V3 never occurs
  EXPECT_EQ(j["properties"][2]["verdict"], "violated");
  EXPECT_EQ(j["properties"][2]["description"],
            "Whenever start is true, V1 is true then or within the next cycle.");
}

INSTANTIATE_TEST_SUITE_P(Engines, PatternCli, ::testing::Values("explicit", "bdd"));

TEST(PatternCommand, TextJunitAndSarifCarryTheSentence) {
  const auto xml = write_temp("", ".xml");
  const auto sarif = write_temp("", ".sarif");
  const auto r = run_sfcv("check " + kPlant + " --pattern 'implies(V1 & V3, M)' --junit '" + xml +
                          "' --sarif '" + sarif + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  requirement: If V1 & V3 is true at the end of a cycle, M is true at "
                       "the end of the same cycle.\n  formula: AG (V1 & V3 -> M)\n  VACUOUS"),
            std::string::npos)
      << r.out;
  const auto junit = slurp(xml);
  // system-out: the id, where (the model: no file attribute in Jenkins' junit-10.xsd), the
  // deciding engine, the English sentence, the vacuity.
  EXPECT_NE(junit.find("\nIf V1 &amp; V3 is true at the end of a cycle, M is true at the "
                       "end of the same cycle.\nVACUOUS"),
            std::string::npos)
      << junit;
  EXPECT_NE(junit.find("where: " + std::string(SFCV_SOURCE_DIR)), std::string::npos) << junit;
  const auto log = nlohmann::json::parse(slurp(sarif));
  // The short description is the sentence; the full one and the help add the CTL formula.
  const auto& rule = log["runs"][0]["tool"]["driver"]["rules"][0];
  EXPECT_EQ(rule["shortDescription"]["text"],
            "If V1 & V3 is true at the end of a cycle, M is true at the end of the same cycle.");
  EXPECT_NE(rule["fullDescription"]["text"].get<std::string>().find("AG (V1 & V3 -> M)"),
            std::string::npos)
      << rule;
  EXPECT_NE(rule["help"]["text"].get<std::string>().find("--pattern 'implies(V1 & V3, M)'"),
            std::string::npos)
      << rule;
}

TEST(PatternCommand, SpecFilePatternsAndTheirErrors) {
  const auto spec = write_temp(
      "property no_overfill: AG !(V1 & V3);\n"
      "pattern starts: existence(s1, after start);\n",
      ".spec");
  auto r = run_sfcv("check " + kPlant + " --spec '" + spec + "' --json");
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["properties"].size(), 2u) << r.out;
  EXPECT_EQ(j["properties"][1]["name"], "starts");
  EXPECT_EQ(j["properties"][1]["description"], "From the first start on, s1 becomes true.");
  EXPECT_EQ(j["properties"][1]["where"], spec + ":2:1");
  const auto bad = write_temp("pattern p: absence(V1,\n  before V9);\n", ".spec");
  r = run_sfcv("check " + kPlant + " --spec '" + bad + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find(bad + ":2:10: error: unknown name 'V9'"), std::string::npos) << r.err;
  const auto arity = write_temp("pattern p: precedence(V1);\n", ".spec");
  r = run_sfcv("check " + kPlant + " --spec '" + arity + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(arity + ":1:12: error: pattern 'precedence' takes 2 arguments, found 1"),
            std::string::npos)
      << r.err;
}

TEST(PatternCommand, ExitCodes) {
  EXPECT_EQ(run_sfcv("check " + kPlant + " --pattern 'never(V1 & V3)'").exit_code, 0);
  EXPECT_EQ(run_sfcv("check " + kPlant + " --pattern 'never(V2 & V4)'").exit_code, 1);
  auto r = run_sfcv("check " + kPlant + " --pattern 'nevr(V1)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--pattern 'nevr(V1)':1:1: error: unknown pattern 'nevr'"),
            std::string::npos)
      << r.err;
  r = run_sfcv("check " + kPlant + " --pattern 'never(V1, V3)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(":1:11: error: pattern 'never' takes 1 argument, found 2"),
            std::string::npos)
      << r.err;
}

TEST(PatternCommand, BoundsInTimeNeedDiscreteTime) {
  auto r = run_sfcv("check " + kPlant + " --pattern 'response(s1, s2, within 1 s)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a bound in time needs a cycle time: use --time discrete"),
            std::string::npos)
      << r.err;
  r = run_sfcv("check " + kPlant +
               " --time discrete --cycle 100ms --json --pattern "
               "'response(s1, s2, within 1 s)'");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["properties"][0]["description"],
            "Whenever s1 is true, s2 is true then or within 1 s (the next 10 cycles of 100 ms).");
  EXPECT_EQ(j["properties"][0]["formula"].get<std::string>().find("AG (s1 -> s2 | EX TRUE & AX"),
            0u);
}

TEST(PatternCommand, ListingAndHelp) {
  const auto r = run_sfcv("patterns");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("  response(P, S[, scope | within N cycles | within T ms|s])\n"
                       "    whenever {P} is true, {S} is true then or later\n"
                       "    AG (P -> AF S)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("docs/properties.md"), std::string::npos);
  const auto help = run_sfcv("check --help");
  EXPECT_NE(help.out.find("--pattern"), std::string::npos);
  EXPECT_NE(help.out.find("docs/properties.md"), std::string::npos);
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// The shipped example spec says each verdict in a comment; sfcv must give it, on both engines.
TEST(PatternCommand, ShippedRequirementsSpecGivesTheVerdictsItStates) {
  const std::string spec =
      std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/requirements.spec";
  std::ifstream f(spec);
  std::map<std::string, std::string> stated;
  for (std::string line; std::getline(f, line);) {
    if (!line.starts_with("pattern ")) continue;
    const auto colon = line.find(':');
    std::string name = line.substr(8, colon - 8);
    name.erase(name.find_last_not_of(' ') + 1);
    stated[name] = line.find("-- holds") != std::string::npos ? "holds" : "violated";
  }
  ASSERT_GE(stated.size(), 8u);
  for (const char* engine : {"explicit", "bdd"}) {
    const auto r = run_sfcv("check " + kPlant + " --engine " + engine + " --spec '" + spec +
                            "' --json --quiet");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["properties"].size(), stated.size());
    for (const auto& p : j["properties"]) {
      EXPECT_EQ(p["verdict"], stated[p["name"].get<std::string>()]) << engine << " " << p["name"];
      EXPECT_FALSE(p["description"].get<std::string>().empty());
    }
  }
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// The shipped library share/sfcv/patterns.spec: `sfcv patterns --library` names it, every entry
// loads on the chemical plant and gets a definite verdict, the one its comment states.
TEST(PatternLibrary, EveryEntryGivesItsStatedVerdictOnThePlant) {
  auto where = run_sfcv("patterns --library");
  ASSERT_EQ(where.exit_code, 0) << where.err;
  const std::string path = where.out.substr(0, where.out.find('\n'));
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::map<std::string, std::string> stated;
  std::set<std::string> patterns_used;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("pattern ", 0) != 0) continue;
    const auto colon = line.find(':');
    const auto name = line.substr(8, colon - 8);
    const auto comment = line.find("-- ");
    ASSERT_NE(comment, std::string::npos) << line;
    stated[name] = line.substr(comment + 3, line.find_first_of(" (", comment + 3) - comment - 3);
    const auto body = line.find_first_not_of(' ', colon + 1);
    patterns_used.insert(line.substr(body, line.find('(', body) - body));
  }
  // Every pattern of the catalogue has an example.
  for (const char* p : {"always", "never", "implies", "next_cycle", "between_cycles",
                        "infinitely_often", "never_before", "reachable", "repeatable", "absence",
                        "universality", "existence", "precedence", "response"})
    EXPECT_TRUE(patterns_used.count(p)) << p;
  const auto r = run_sfcv("check '" + std::string(SFCV_SOURCE_DIR) +
                          "/examples/chemical_plant/chemical_plant.st' --spec '" + path +
                          "' --json --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto results = nlohmann::json::parse(r.out)["properties"];
  ASSERT_EQ(results.size(), stated.size());
  for (const auto& p : results) {
    const std::string name = p["name"];
    ASSERT_TRUE(stated.count(name)) << name;
    EXPECT_EQ(p["verdict"], stated[name]) << name;
  }
}

}  // namespace
}  // namespace sfcv::test

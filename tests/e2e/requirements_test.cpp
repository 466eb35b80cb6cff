// Requirement files (issue 49, docs/properties.md "Requirement files"): the PLCverif JSON and
// ESBMC-PLC YAML files shipped for the chemical plant give the verdicts their comments state,
// with id, English and justification in the reports; unknown ids and malformed files are
// located errors (exit 2); `sfcv patterns --json` describes the catalogue.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kDir = std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/";
const std::string kPlant = "'" + kDir + "chemical_plant.st'";

std::map<std::string, std::string> verdicts(const nlohmann::json& j) {
  std::map<std::string, std::string> out;
  for (const auto& p : j["properties"]) out[p["name"]] = p["verdict"];
  return out;
}

TEST(RequirementsFiles, PlcverifJsonForTheChemicalPlant) {
  const auto r = run_sfcv("check " + kPlant + " --json --requirements '" + kDir +
                          "requirements.plcverif.json'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::map<std::string, std::string> expected = {
      {"chemical-plant/1", "holds"}, {"chemical-plant/2", "violated"},
      {"chemical-plant/3", "holds"}, {"chemical-plant/4", "holds"},
      {"chemical-plant/5", "holds"}, {"chemical-plant/6", "holds"},
      {"chemical-plant/7", "holds"}, {"chemical-plant/8", "holds"}};
  EXPECT_EQ(verdicts(j), expected);
  EXPECT_EQ(j["properties"][4]["formula"], "AG AX (prev(s8.X) -> s10.X)");
  EXPECT_EQ(j["properties"][5]["formula"], "AX !E[!V4 U V5]");
  EXPECT_NE(j["properties"][0]["description"].get<std::string>().find(
                "Tank T1 is never filled and emptied at once."),
            std::string::npos);
}

TEST(RequirementsFiles, StartOfCycleAndEarlierCycleReadings) {
  // s8 -> s10 is guarded by TRUE: a cycle that starts in s8 ends in s10, never in s8 itself.
  const auto r = run_sfcv("check " + kPlant +
                          " --json --pattern 'statechange_duringcycle(s8, s10)'"
                          " --pattern 'implies(s8, s10)' --pattern 'leadsto(V5, V4)'"
                          " --pattern 'leadsto(V4, V5)' --pattern 'leadsto(V4, V4)'");
  const auto v = verdicts(nlohmann::json::parse(r.out));
  EXPECT_EQ(v.at("statechange_duringcycle(s8, s10)"), "holds");
  EXPECT_EQ(v.at("implies(s8, s10)"), "violated");
  EXPECT_EQ(v.at("leadsto(V5, V4)"), "holds");
  EXPECT_EQ(v.at("leadsto(V4, V5)"), "violated");
  EXPECT_EQ(v.at("leadsto(V4, V4)"), "violated");  // strictly earlier
}

TEST(RequirementsFiles, EsbmcYamlWithJustificationsInEveryReport) {
  const std::string dir = ::testing::TempDir();
  const auto r = run_sfcv("check " + kPlant + " --json --requirements '" + kDir +
                          "requirements.esbmc.yaml' --junit '" + dir + "req.xml' --sarif '" + dir +
                          "req.sarif' --html '" + dir + "req.html'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::map<std::string, std::string> expected = {
      {"P1", "holds"}, {"P2", "violated"}, {"P3", "holds"}, {"P4", "holds"}, {"P5", "holds"}};
  EXPECT_EQ(verdicts(j), expected);
  EXPECT_EQ(j["properties"][3]["justification"], "s8 -> s10 is guarded by TRUE: one scan");
  for (const char* file : {"req.xml", "req.sarif", "req.html"}) {
    std::ifstream in(dir + file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("guarded by TRUE: one scan"), std::string::npos) << file;
  }
  const auto text =
      run_sfcv("check " + kPlant + " --requirements '" + kDir + "requirements.esbmc.yaml'");
  EXPECT_NE(text.out.find("justification: s8 -> s10 is guarded by TRUE"), std::string::npos);
}

TEST(RequirementsFiles, UnknownIdsAndMalformedFilesAreLocatedErrors) {
  const std::string dir = ::testing::TempDir();
  const std::pair<const char*, const char*> cases[] = {
      {"bad_id.json",
       "[{\"property\": {\"job_req\": \"pattern\", \"pattern_id\": \"pattern-sometimes\","
       " \"pattern_params\": {\"1\": \"V1\"}}}]"},
      {"broken.json", "{\"property\": {\"job_req\": \n"},
      {"assertion.json", "{\"property\": {\"job_req\": \"assertion\"}}"},
      {"bad_kind.yaml", "properties:\n  - id: P1\n    kind: eventually\n    expression: V1\n"},
      {"no_justification.yaml",
       "properties:\n  - id: P1\n    kind: response\n    trigger: s8\n    response: s10\n"
       "    max_scans: 1\n"},
      {"broken.yaml", "properties:\n  - id: [P1\n"},
      {"bad_expression.yaml",
       "properties:\n  - id: P1\n    kind: invariant\n    expression: V1 &\n"},
  };
  for (const auto& [name, content] : cases) {
    std::ofstream(dir + name) << content;
    const auto r = run_sfcv("check " + kPlant + " --requirements '" + dir + name + "'");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.out << r.err;
    // file:line:col: error
    EXPECT_NE(r.err.find(std::string(name) + ":"), std::string::npos) << name << ": " << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << name;
  }
}

TEST(RequirementsFiles, PatternsJsonDescribesTheCatalogue) {
  const auto r = run_sfcv("patterns --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool found = false;
  for (const auto& p : j["patterns"]) {
    EXPECT_TRUE(p.contains("english") && p.contains("formula") && p.contains("parameters"));
    if (p["name"] == "leadsto") {
      found = true;
      EXPECT_EQ(p["parameters"], nlohmann::json::array({"A", "B"}));
      EXPECT_EQ(p["plcverif_pattern_ids"], nlohmann::json::array({"pattern-leadsto"}));
    }
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace sfcv::test

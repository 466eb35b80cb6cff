// Vacuity end to end: AG (a -> f) that holds says whether a is ever reachable (EF a), in
// text, JSON and JUnit, on both engines; the question's own result is not reported.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kPlant =
    "'" + std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st'";

class Vacuity : public ::testing::TestWithParam<const char*> {};

TEST_P(Vacuity, ChemicalPlant) {
  // V1 and V3 are never open together (AG !(V1 & V3) holds), so the first holds vacuously.
  const auto r = run_sfcv("check " + kPlant + " --engine " + GetParam() +
                          " --json --ctl 'AG (V1 & V3 -> M)' --ctl 'AG (V1 -> !V3)'"
                          " --ctl 'AG (V2 -> !V4)' --ctl 'AG (start -> EF V1)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["properties"].size(), 4u);  // the EF questions are not results of their own
  EXPECT_EQ(j["properties"][0]["verdict"], "holds");
  EXPECT_EQ(j["properties"][0]["vacuous"], true);
  EXPECT_NE(j["properties"][0]["vacuity"].get<std::string>().find("never true"), std::string::npos);
  EXPECT_EQ(j["properties"][1]["verdict"], "holds");
  EXPECT_EQ(j["properties"][1]["vacuous"], false);
  EXPECT_EQ(j["properties"][2]["verdict"], "violated");  // V2 & V4 overlap (the seed's finding)
  EXPECT_TRUE(j["properties"][2]["vacuous"].is_null());
  EXPECT_EQ(j["properties"][3]["verdict"], "holds");  // an input as the trigger
  EXPECT_EQ(j["properties"][3]["vacuous"], false);
}

INSTANTIATE_TEST_SUITE_P(Engines, Vacuity, ::testing::Values("explicit", "bdd"));

TEST(VacuityCommand, TextAndJunit) {
  const auto xml = write_temp("", ".xml");
  const auto r = run_sfcv("check " + kPlant +
                          " --ctl 'AG (V1 & V3 -> M)' --ctl 'AG (V1 -> !V3)' "
                          "--junit '" +
                          xml + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("VACUOUS: the antecedent V1 & V3 is never true in a reachable state"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("not vacuous: the antecedent V1 is reachable"), std::string::npos) << r.out;
  std::ifstream f(xml);
  const std::string junit((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // system-out: the id, where, the deciding engine, then the vacuity (issue 48).
  EXPECT_NE(junit.find("\nVACUOUS: the antecedent"), std::string::npos) << junit;
  EXPECT_NE(junit.find("tests=\"2\""), std::string::npos) << junit;
}

TEST(CoverageCommand, ChemicalPlantVisitsEverything) {
  auto r = run_sfcv("check " + kPlant + " --coverage --checks none --ctl 'AG TRUE' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["coverage"]["steps"], 13);
  EXPECT_EQ(j["coverage"]["steps_visited"], 13);
  EXPECT_EQ(j["coverage"]["transitions"], j["coverage"]["transitions_fired"]);
  EXPECT_GT(j["coverage"]["actions"].get<int>(), 0);
  EXPECT_TRUE(j["coverage"]["unvisited"].empty());
  // A chart with a step that is never reached: named in the text output.
  const auto st = write_temp(R"(PROGRAM P
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT y : BOOL; END_VAR
  INITIAL_STEP s0: END_STEP
  STEP s1: y(N); END_STEP
  TRANSITION FROM s0 TO s1 := a AND NOT a; END_TRANSITION
  TRANSITION FROM s1 TO s0 := TRUE; END_TRANSITION
END_PROGRAM
)",
                             ".st");
  r = run_sfcv("check '" + st + "' --coverage --checks none --ctl 'AG !y'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("coverage: 1/2 steps active, 0/2 transitions fired"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("never: step"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sfcv::test

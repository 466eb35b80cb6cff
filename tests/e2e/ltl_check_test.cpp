// LTL end to end on the seed's chemical plant: verdicts and exit codes, the lasso in text and
// JSON, fairness, spec files, refusals (other engines, CTL operators, exports) and limits; the
// BDD engine's LTL, and the two readings of deadlocks (--deadlock-paths) on a door that jams.

#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kPlant =
    "'" + std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st'";

TEST(LtlCheck, ResponseNeedsTheTankToReportFull) {
  // V1 fills T1 until LIS1plus: a run where the sensor never reports is a lasso.
  auto r = run_sfcv("check " + kPlant + " --ltl 'G (V1 -> F !V1)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("G (V1 -> F !V1)  violated"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("->"), std::string::npos) << r.out;  // the row where the loop starts
  EXPECT_NE(r.out.find("repeats rows"), std::string::npos) << r.out;
  // Only runs where LIS1plus holds infinitely often: then it holds.
  r = run_sfcv("check " + kPlant + " --ltl 'G (V1 -> F !V1)' --fair LIS1plus");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("check " + kPlant + " --ltl 'G (rise(V1) -> s2)' --ltl 'G !(V2 & V4)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("G (rise(V1) -> s2)  holds"), std::string::npos) << r.out;
}

TEST(LtlCheck, JsonHasTheLoopStart) {
  auto r = run_sfcv("check " + kPlant + " --ltl 'G F s9' --json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("\"loop_start\": 2"), std::string::npos) << r.out;
}

TEST(LtlCheck, SpecFileForm) {
  const auto spec = write_temp(
      "ltl fills: G (V1 -> F !V1);\nfair LIS1plus;\n"
      "property safe: AG !(V1 & V3);\n",
      ".spec");
  auto r = run_sfcv("check " + kPlant + " --spec '" + spec + "'");
  EXPECT_NE(r.out.find("fills"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.out.find("holds"), std::string::npos) << r.out;
}

TEST(LtlCheck, TheBddEngineChecksLtl) {
  auto r = run_sfcv("check " + kPlant + " --ltl 'G F s9' --engine bdd");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("counterexample"), std::string::npos) << r.out;
  r = run_sfcv("check " + kPlant + " --ltl 'G (rise(V1) -> s2)' --engine bdd");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("bdd engine"), std::string::npos) << r.out;
  // Only part of the states: unknown, not a proof.
  r = run_sfcv("check " + kPlant + " --ltl 'G (rise(V1) -> s2)' --engine bdd --max-states 5");
  EXPECT_EQ(r.exit_code, 3) << r.out;
}

// tests/data/door_jam.st under --assume '!Jammed': Jammed is reachable and has no successor.
// Stuttering, the door stays jammed forever (G !Jammed and AG !Jammed violated); dropping
// deadlocks as NuSMV does, no path passes through Jammed (both hold, and EF Jammed fails).
TEST(LtlCheck, DeadlockPathsStutterOrDrop) {
  const std::string door = "'" + std::string(SFCV_SOURCE_DIR) +
                           "/tests/data/door_jam.st' --assume '!Jammed' "
                           "--trace none --json";
  for (const std::string engine : {"explicit", "bdd"}) {
    SCOPED_TRACE(engine);
    const std::string props =
        " --ltl 'G !Jammed' --ltl 'G F Closed' --ctl 'EF Jammed' --engine " + engine;
    auto stutter = run_sfcv("check " + door + props);
    auto drop = run_sfcv("check " + door + props + " --deadlock-paths drop");
    EXPECT_EQ(stutter.exit_code, 1) << stutter.out << stutter.err;
    EXPECT_EQ(drop.exit_code, 1) << drop.out << drop.err;
    const auto s = nlohmann::json::parse(stutter.out)["properties"];
    const auto d = nlohmann::json::parse(drop.out)["properties"];
    ASSERT_EQ(s.size(), 3u);
    ASSERT_EQ(d.size(), 3u);
    std::map<std::string, std::string> sv, dv;
    for (const auto& r : s) sv[r["formula"]] = r["verdict"];
    for (const auto& r : d) dv[r["formula"]] = r["verdict"];
    EXPECT_EQ(sv["G !Jammed"], "violated");
    EXPECT_EQ(dv["G !Jammed"], "holds");
    EXPECT_EQ(sv["EF Jammed"], "holds");
    EXPECT_EQ(dv["EF Jammed"], "violated");
    // Opening forever (open_req held, no jam) is an infinite path in both readings.
    EXPECT_EQ(sv["G F Closed"], "violated");
    EXPECT_EQ(dv["G F Closed"], "violated");
  }
  // The default is the stutter reading; a bad value is a usage error.
  auto bad = run_sfcv("check " + door + " --ltl 'G !Jammed' --deadlock-paths never");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--deadlock-paths"), std::string::npos) << bad.err;
  bad = run_sfcv("check " + door + " --ctl 'AG !Jammed' --deadlock-paths drop --engine ic3");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("does not check it"), std::string::npos) << bad.err;
}

TEST(LtlCheck, RefusalsAndErrors) {
  auto r = run_sfcv("check " + kPlant + " --ltl 'G F s9' --engine ic3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("does not check LTL"), std::string::npos) << r.err;
  r = run_sfcv("check " + kPlant + " --ltl 'G (V1 -> AF !V1)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("1:10: error: CTL operator 'AF'"), std::string::npos) << r.err;
  r = run_sfcv("check " + kPlant + " --ltl 'G F nosuch'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nosuch"), std::string::npos) << r.err;
  r = run_sfcv("export --to nusmv " + kPlant + " --ltl 'G F s9'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  r = run_sfcv("export --to promela " + kPlant + " --ltl 'G (s9 -> X s1)'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  r = run_sfcv("export --to promela " + kPlant + " --ltl 'G F s9'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ltl sfcv_ltl_0 { [] <> sfcv_atom_0 }"), std::string::npos) << r.out;
}

TEST(LtlCheck, LimitsAnswerUnknown) {
  // A property that holds cannot be proved on part of the graph.
  auto r = run_sfcv("check " + kPlant + " --ltl 'G (rise(V1) -> s2)' --max-states 5");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  // A lasso among the states explored is still a counterexample.
  r = run_sfcv("check " + kPlant + " --ltl 'F G s9' --max-states 5");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  r = run_sfcv("check " + kPlant + " --ltl 'G F s9' --timeout 0.000001");
  EXPECT_EQ(r.exit_code, 3) << r.out;
}

}  // namespace
}  // namespace sfcv::test

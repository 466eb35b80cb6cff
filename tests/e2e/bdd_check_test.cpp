// sfcv check --engine bdd end to end: counterexamples of every shape replay in sfcv simulate,
// --reorder none/once/dynamic change no answer, --memory too small gives unknown (exit 3), the
// report counts states and edges as the explicit engine does, on our examples and on the shared
// corpus.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/generate.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kPlant =
    "'" + std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st'";

nlohmann::json check_json(const std::string& args, int* exit_code = nullptr) {
  const auto r = run_sfcv("check " + args + " --json --quiet");
  if (exit_code) *exit_code = r.exit_code;
  try {
    return nlohmann::json::parse(r.out);
  } catch (const std::exception&) {
    ADD_FAILURE() << "not JSON: " << r.out << r.err;
    return {};
  }
}

TEST(BddCheck, EveryCounterexampleReplaysInSimulate) {
  // A lasso (AF), a nested one (AG EF), an EX step, an until, and a witness (EG under fairness).
  for (const char* ctl : {"AF s8", "AG EF s9", "AG (s2 -> AX s2)", "A[!V2 U s8]", "EG !s8"}) {
    SCOPED_TRACE(ctl);
    const auto csv = write_temp("", ".csv");
    const auto r = run_sfcv("check " + kPlant + " --engine bdd --quiet --ctl '" + ctl +
                            "' --trace csv --trace-file '" + csv + "'");
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.out << r.err;
    const auto sim = run_sfcv("simulate " + kPlant + " --inputs '" + csv + "'");
    EXPECT_EQ(sim.exit_code, 0) << sim.out << sim.err;
    // The explicit engine gives the same verdict.
    const auto ex = run_sfcv("check " + kPlant + " --quiet --trace none --ctl '" + ctl + "'");
    EXPECT_EQ(ex.exit_code, r.exit_code);
  }
  const auto lasso = run_sfcv("check " + kPlant + " --engine bdd --ctl 'AF s8'");
  EXPECT_EQ(lasso.exit_code, 1);
  EXPECT_NE(lasso.out.find("counterexample"), std::string::npos) << lasso.out;
}

TEST(BddCheck, ReorderingChangesNoAnswer) {
  const std::string props =
      " --ctl 'AG !(V1 & V3)' --ctl 'AG !(V2 & V4)' --ctl 'AG EF s9' --ctl 'AF s8' "
      "--ctl 'EG !s8' --fair s1 --checks none";
  const auto plain = check_json(kPlant + " --engine bdd --reorder none" + props);
  ASSERT_TRUE(plain.contains("properties"));
  // The bare switch (older scripts) means dynamic, as the default does.
  for (const std::string mode : {"", " once", " dynamic"}) {
    SCOPED_TRACE("--reorder" + mode);
    const auto sifted = check_json(kPlant + " --engine bdd --reorder" + mode + props);
    ASSERT_TRUE(sifted.contains("properties"));
    EXPECT_EQ(plain["states"], sifted["states"]);
    EXPECT_EQ(plain["edges"], sifted["edges"]);
    ASSERT_EQ(plain["properties"].size(), sifted["properties"].size());
    for (std::size_t i = 0; i < plain["properties"].size(); ++i)
      EXPECT_EQ(plain["properties"][i]["verdict"], sifted["properties"][i]["verdict"]) << i;
  }
  EXPECT_EQ(run_sfcv("check " + kPlant + " --engine bdd --reorder sometimes" + props).exit_code, 2);
}

// 16 KB hold the first rings only (64 KB now hold the plant's 25 states: its images are
// simulated, without the relation).
TEST(BddCheck, TinyMemoryBudgetIsUnknown) {
  const auto r = run_sfcv("check " + kPlant +
                          " --engine bdd --memory 16K --ctl 'AG !(V1 & V3)' --checks reachable");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  // 16 KB is below what the process itself holds: the process-wide watchdog may stop it while
  // loading (the one-line answer on standard error) or the engine in its first rings (the
  // report); unknown either way, never a verdict.
  EXPECT_NE((r.out + r.err).find("unknown"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" holds"), std::string::npos) << r.out;
  EXPECT_NE((r.out + r.err).find("memory"), std::string::npos) << r.out;
  // A budget that fits answers.
  EXPECT_EQ(
      run_sfcv("check " + kPlant + " --engine bdd --memory 1G --ctl 'AG !(V1 & V3)'").exit_code, 0);
  EXPECT_EQ(
      run_sfcv("check " + kPlant + " --engine bdd --memory lots --ctl 'AG !(V1 & V3)'").exit_code,
      2);
}

TEST(BddCheck, ReportCountsStatesAndEdgesLikeExplicit) {
  const auto ex = check_json(kPlant + " --ctl 'AG !(V1 & V3)' --checks none");
  const auto bdd = check_json(kPlant + " --engine bdd --ctl 'AG !(V1 & V3)' --checks none");
  ASSERT_TRUE(ex.contains("states") && bdd.contains("states"));
  EXPECT_EQ(ex["states"], bdd["states"]);
  EXPECT_EQ(ex["edges"], bdd["edges"]);
  EXPECT_GT(bdd["edges"].get<std::uint64_t>(), bdd["states"].get<std::uint64_t>());
  const auto text = run_sfcv("check " + kPlant + " --engine bdd --ctl 'AG !(V1 & V3)'");
  EXPECT_NE(text.out.find(std::to_string(ex["states"].get<std::uint64_t>()) + " states, " +
                          std::to_string(ex["edges"].get<std::uint64_t>()) + " edges"),
            std::string::npos)
      << text.out;
}

// The IEC charts of the corpus that the semantics supports: the BDD engine counts their
// reachable states and edges, equal to the explicit engine's wherever that one finishes.
TEST(BddCheck, CorpusReachableStateCounts) {
  SFCV_REQUIRE_CORPUS(corpus);
  auto path = [&](const char* file) { return "'" + (corpus / file).string() + "'"; };
  struct Chart {
    const char* file;
    const char* options;
  };
  // 01: Beremiz's traffic light; 02: its counter chart (32769 rings; the whole program runs five
  // counters apart, far more states); 03/04: matiec's test chart,
  // which writes its input IX1; 07: CODESYS's pick-and-place unit, its three SFC function blocks
  // in one cycle; 13: a 22-step cycle; 15 with its input constrained.
  for (const Chart c :
       {Chart{"01_beremiz_traffic_light.xml", ""},
        Chart{"02_beremiz_first_steps.xml", " --pou CounterSFC"},
        Chart{"03_matiec_SFC_TEST_tc6v1.xml", ""}, Chart{"04_matiec_sfc_syntax.st", ""},
        Chart{"07_codesys_ppu_scenario3v1.xml", " --pou Stamp --pou Magazin --pou Crane"},
        Chart{"13_verifaps_loopunwinding1_left.sfc", ""},
        Chart{"15_verifaps_transition2_left.sfc", " --assume 'i >= 500 & i <= 600'"}}) {
    SCOPED_TRACE(c.file);
    const std::string args = path(c.file) + c.options + " --ctl TRUE --checks none --timeout 300";
    int code = -1;
    const auto ex = check_json(args, &code);
    ASSERT_EQ(code, 0) << ex.dump();
    const auto bdd = check_json(args + " --engine bdd", &code);
    ASSERT_EQ(code, 0) << bdd.dump();
    EXPECT_TRUE(bdd["complete"].get<bool>());
    EXPECT_GT(bdd["states"].get<std::uint64_t>(), 1u);
    EXPECT_EQ(ex["states"], bdd["states"]);
    EXPECT_EQ(ex["edges"], bdd["edges"]);
  }
  // 15 unconstrained: the explicit engine refuses to enumerate the INT input (unknown), the
  // BDD engine counts step A with each of the 65536 values of o := i, plus B1 (o = 1) and B2
  // (o = 2).
  int code = -1;
  const auto wide = check_json(
      path("15_verifaps_transition2_left.sfc") + " --engine bdd --ctl TRUE --checks none", &code);
  ASSERT_EQ(code, 0) << wide.dump();
  EXPECT_EQ(wide["states"].get<std::uint64_t>(), 65536u + 2u);
  EXPECT_EQ(run_sfcv("check " + path("15_verifaps_transition2_left.sfc") +
                     " --engine explicit --ctl TRUE --checks none --quiet")
                .exit_code,
            3);
  // --engine auto (the default) hands that case to the race, where only the BDD engine answers
  // a property that is not AG p or EF p.
  const auto chosen =
      check_json(path("15_verifaps_transition2_left.sfc") + " --ctl TRUE --checks none", &code);
  EXPECT_EQ(code, 0);
  EXPECT_EQ(chosen["engine"], "auto");
  EXPECT_EQ(chosen["properties"][0]["decided_by"], "bdd");
  EXPECT_EQ(chosen["states"].get<std::uint64_t>(), 65536u + 2u);
  // 09 (the xPPU, 19 SFC bodies) is refused by the semantics itself (exit 2, a located message),
  // by both engines alike: its function blocks read each other's instances
  // (`Stack.InitCompleted`). No count is better than a wrong one.
  for (const char* engine : {"explicit", "bdd"}) {
    const auto r =
        run_sfcv("check " + path("09_twincat_xppu_scenario1.xml") + " --engine " + engine +
                 " --pou MonostableCylinder --pou VacuumGripper --pou Crane --pou Stack"
                 " --pou PPU --ctl TRUE --checks none --quiet");
    EXPECT_EQ(r.exit_code, 2) << engine << r.out << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos);
  }
}

TEST(BddCheck, MaxStatesBoundsTheReachedStates) {
  // The bdd engine explores ring by ring; --max-states was read before each ring, so a run
  // stopped with up to a whole ring more (4,096 states past --max-states 1000). A ring that
  // would pass the bound is not kept: the states explored are at most the bound.
  const auto chart = generate("parallel 16", ".st");
  for (const char* bound : {"1000", "5000"}) {
    const auto r = run_sfcv("check '" + chart + "' --engine bdd --max-states " +
                            std::string(bound) + " --quiet --json");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j["states"].is_number()) << r.out.substr(0, 500);
    EXPECT_LE(j["states"].get<double>(), std::stod(bound)) << bound;
    EXPECT_GT(j["states"].get<double>(), 0);
    EXPECT_EQ(j["limit"], "states") << r.out.substr(0, 500);
  }
}

}  // namespace
}  // namespace sfcv::test

// Rockwell Studio 5000 .L5X through the binary: the demo chart (tests/support/l5x_text.hpp) and
// its IEC 61131-3 text twin give the same verdicts, on the explicit and BDD engines; what is
// not modelled is exit 2 naming the construct.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "support/l5x_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

TEST(L5xE2E, DemoChartAndItsIecTwinGiveTheSameVerdicts) {
  const auto native =
      write_temp(rockwell::l5x(rockwell::demo_tags(), rockwell::demo_sfc()), ".L5X");
  const auto twin = write_temp(rockwell::demo_twin(), ".st");
  // Read from the drawing: the selection legs exclude each other, the simultaneous legs run
  // together and the join waits for both; S2 is reachable (stop). In the situation where S1
  // has just become active its action has not run yet (a scan runs the actions of the steps
  // active at its start, then their transitions), so lamp may still be FALSE there; Merge is
  // reached before P1 ever set valve.
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG !(S1 & S2)", "holds"},
      {"AG (P1 <-> P2)", "holds"},
      {"AG !(P1 & Init)", "holds"},
      {"EF S2", "holds"},
      {"AG !S2", "violated"},
      {"AG (S1 -> lamp)", "violated"},
      {"AG (Merge -> valve)", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"}) {
    expect_ctl_verdicts_in_one_run(native, engine, verdicts);
    expect_ctl_verdicts_in_one_run(twin, engine, verdicts);
  }
  const auto r = run_sfcv("info " + native);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("rockwell-l5x 32.01"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("steps: 6, transitions: 6"), std::string::npos) << r.out;
}

TEST(L5xE2E, AStepTimerBitIsExitTwoNamingIt) {
  auto sfc = rockwell::demo_sfc();
  sfc.replace(sfc.find("NOT stop"), 8, "S1.DN");
  const auto file = write_temp(rockwell::l5x(rockwell::demo_tags(), sfc), ".L5X");
  const auto r = run_sfcv("check " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'S1.DN' (a step's DN is read in the conditions of the transitions leaving "
                       "it"),
            std::string::npos)
      << r.err;
}

// The two-step ladder sequence of tests/support/l5x_text.hpp, checked through the binary on
// every engine. The verdicts follow from Rockwell's rung rules, not from sfcv: S:FS sets X.0
// in the first scan; each step bit holds until its transition bit fires, so the two steps
// exclude each other; OTL(alarm) is never unlatched; motor is written by the Actions routine,
// which runs before Steps in the same scan, so it lags X.1 by one scan; T1 ends X.1.
TEST(L5xE2E, LadderSequenceVerdictsFollowFromTheRungRules) {
  const auto file = write_temp(
      rockwell::l5x_ladder(rockwell::ladder_tags(), rockwell::ladder_routines()), ".L5X");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG !(X_0 & X_1)", "holds"},
      {"AX AG !S_FS", "holds"},
      {"AG (alarm -> AG alarm)", "holds"},
      {"AG (motor -> X_1)", "violated"},
      {"AG (X_1 -> EF X_0)", "holds"},
      {"AG !alarm", "violated"},
      {"EF (X_1 & motor)", "holds"},
      {"AG (X_0 | X_1)", "violated"},  // the initial situation, before S:FS's first scan
  };
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
  const auto r = run_sfcv("info " + file);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(rockwell-l5x 32.01, IEC 61131-3, read in rockwell's dialect)"),
            std::string::npos)
      << r.out;
}

// ONS from its manual text: rung-condition-out is TRUE for one scan when rung-condition-in goes
// TRUE. So a pulse never lasts two scans, and it does come.
TEST(L5xE2E, OneShotPulsesForOneScan) {
  const auto file =
      write_temp(rockwell::l5x_ladder(
                     rockwell::alias("go", "Local:1:I.Data.0") + rockwell::bool_tag("mem", 0) +
                         rockwell::alias("pulse", "Local:1:O.Data.0"),
                     rockwell::rll_routine("Main", {"XIC(go)ONS(mem)OTE(pulse);"})),
                 ".L5X");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG (pulse -> AX !pulse)", "holds"},
      {"EF pulse", "holds"},
      {"AG !pulse", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
}

// Parts of a controller tag of a user type (tests/support/l5x_text.hpp's Cell_Data), with
// verdicts that follow from 1756-RM003's text: TON on an element of a TIMER array sets its .DN
// once the preset has elapsed with the rung TRUE; ADD adds when its rung is TRUE; LIM with a
// low limit above its high limit is TRUE outside the range between them (7..2: test >= 7 or
// test <= 2), and with equal limits only at that value.
TEST(L5xE2E, PartsOfAUserTypeTagFollowTheInstructionRules) {
  const auto file = write_temp(
      rockwell::l5x_ladder(
          rockwell::alias("go", "Local:1:I.Data.0") + rockwell::alias("q", "Local:1:O.Data.0") +
              rockwell::alias("q2", "Local:1:O.Data.1"),
          rockwell::rll_routine(
              "Main", {"XIC(go)TON(Cell1.TMR[3],?,?);", "XIC(Cell1.TMR[3].DN)OTE(Cell1.Flag);",
                       "XIC(Cell1.Flag)XIO(Cell1.BIT_Logic[1].0)ADD(Cell1.SP[0],1,Cell1.SP[0])"
                       "OTL(Cell1.BIT_Logic[1].0);",
                       "LIM(7,Cell1.SP[0],2)OTE(q);", "LIM(0,Cell1.SP[0],0)OTE(q2);"}),
          rockwell::cell_data_type(), rockwell::cell_tag("Cell1", 0, 7, 1000)),
      ".L5X");
  // SP[0] is written by ADD only, once (BIT_Logic[1].0 latches): it stays 0 or 1.
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG (Cell1_Flag -> go)", "holds"},
      {"EF Cell1_SP_0 = 1", "holds"},
      {"AG Cell1_SP_0 <= 1", "holds"},
      {"AX AG q", "holds"},
      {"AX AG (q2 <-> Cell1_SP_0 = 0)", "holds"},
      {"AG !Cell1_Flag", "violated"},
      {"AG q2", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
}

// A COUNTER from 1756-RM003's text: CTU counts a rising rung (it adds 1 when the rung is TRUE
// and .CU clear, then sets .CU; a FALSE rung clears .CU); .DN is .ACC >= .PRE where CTU runs;
// the prescan sets .CU, so a rung TRUE in the first scan does not count; RES clears .ACC and
// .CU, so a rung still TRUE counts again in the next scan (the "reset to 1" engineers meet).
TEST(L5xE2E, CounterFollowsTheInstructionRules) {
  const auto file = write_temp(
      rockwell::l5x_ladder(
          rockwell::counter_tag("C1", 3) + rockwell::alias("go", "Local:1:I.Data.0") +
              rockwell::alias("down", "Local:1:I.Data.1") +
              rockwell::alias("rst", "Local:1:I.Data.2") + rockwell::alias("q", "Local:1:O.Data.0"),
          rockwell::rll_routine(
              "Main", {"XIC(go)XIO(C1.DN)CTU(C1,?,?);", "XIC(down)GRT(C1.ACC,0)CTD(C1,?,?);",
                       "XIC(rst)RES(C1);", "XIC(C1.DN)OTE(q);"})),
      ".L5X");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AX C1_ACC = 0", "holds"},
      {"AG (C1_ACC >= 0 & C1_ACC <= 3)", "holds"},
      {"AG (q -> C1_ACC >= 3)", "holds"},
      {"EF q", "holds"},
      {"AG ((rst & go) -> AX ((go & !rst & !down) -> C1_ACC = 1))", "holds"},
      {"AG ((go & !rst & !down & C1_ACC = 1) -> AX ((go & !rst & !down) -> C1_ACC = 1))", "holds"},
      {"AG !q", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
}

// Integer arithmetic from 1756-RM003's text: DIV of integers truncates (-7 / 2 is -3), MOD is
// Source A - TRN(Source A / Source B) * Source B (-7 MOD 2 is -1), NEG negates; CPT computes its
// expression with * / MOD before + -.
TEST(L5xE2E, IntegerArithmeticFollowsTheInstructionRules) {
  const auto file = write_temp(
      rockwell::l5x_ladder(
          rockwell::dint_tag("d", 0) + rockwell::dint_tag("m", 0) + rockwell::dint_tag("e", 0) +
              rockwell::dint_tag("c", 0) + rockwell::alias("go", "Local:1:I.Data.0"),
          rockwell::rll_routine("Main", {"XIC(go)DIV(-7,2,d)MOD(-7,2,m);", "NEG(d,e);",
                                         "CPT(c,(d - 1) * 2 + ABS(m) MOD 2);"})),
      ".L5X");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG (go -> d = -3 & m = -1 & e = 3 & c = -7)", "holds"},
      {"AG (d = 0 | d = -3)", "holds"},
      {"AG !(d = -3 & m = -1)", "violated"},
  };
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
}

// A consumed tag's part (another controller writes it, nothing in the file does) is an input:
// its bit is TRUE in the tag's data, and still q can fall and rise at any time.
TEST(L5xE2E, ConsumedTagPartsAreInputs) {
  auto consumed = rockwell::cell_tag("Still", 0b10, 0, 100);
  const std::string base = "TagType=\"Base\"";
  consumed.replace(consumed.find(base), base.size(), "TagType=\"Consumed\"");
  const auto file = write_temp(
      rockwell::l5x_ladder(rockwell::alias("q", "Local:1:O.Data.0"),
                           rockwell::rll_routine("Main", {"XIC(Still.BIT_Logic[1].1)OTE(q);"}),
                           rockwell::cell_data_type(), consumed),
      ".L5X");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG EF q", "holds"}, {"AG EF !q", "holds"}, {"AX AG q", "violated"}};
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
}

// Indirect addressing (1756-RM003, "Index through arrays"): `Cell1.SP[n]` is the element n
// chooses when the instruction runs, read or written. n cycles 0, 1, 2; the elements hold 3, 5,
// 7 and the bits FALSE, TRUE, TRUE; CPT reads parts of the tag too.
TEST(L5xE2E, AnElementChosenByATagIsTheOneItsValueNames) {
  const auto file = write_temp(
      rockwell::l5x_ladder(
          rockwell::dint_tag("n", 0) + rockwell::dint_tag("m", 0) + rockwell::dint_tag("c", 0) +
              rockwell::alias("go", "Local:1:I.Data.0") + rockwell::alias("q", "Local:1:O.Data.0"),
          rockwell::rll_routine(
              "Main", {"MOV(3,Cell1.SP[0])MOV(5,Cell1.SP[1])MOV(7,Cell1.SP[2]);",
                       "OTU(Cell1.BIT_Logic[0].1)OTL(Cell1.BIT_Logic[1].1)OTL(Cell1.BIT_Logic[2].1)"
                       "OTU(Cell1.BIT_Logic[3].1);",
                       "XIC(go)ADD(n,1,n);", "GRT(n,2)CLR(n);", "MOV(Cell1.SP[n],m);",
                       "XIC(Cell1.BIT_Logic[n].1)OTE(q);", "CPT(c,Cell1.SP[n] + n);",
                       "XIC(go)ADD(n,10,Cell1.SP[n]);"}),
          rockwell::cell_data_type(), rockwell::cell_tag("Cell1", 0, 0, 100)),
      ".L5X");
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AX AG ((n = 0 -> m = 3 & !q) & (n = 1 -> m = 5 & q) & (n = 2 -> m = 7 & q))", "holds"},
      {"AX AG ((n = 0 -> c = 3) & (n = 1 -> c = 6) & (n = 2 -> c = 9))", "holds"},
      {"EF n = 2", "holds"},
      {"AG n <= 1", "violated"},
      // Written through the index: SP[n] := n + 10 with go, after the rung that reads it.
      {"AX AG ((go & n = 1) -> Cell1_SP_1 = 11 & Cell1_SP_0 = 3 & Cell1_SP_2 = 7)", "holds"},
      {"AX AG ((!go & n = 1) -> Cell1_SP_1 = 5)", "holds"},
  };
  for (const char* engine : {"explicit", "bdd"})
    expect_ctl_verdicts_in_one_run(file, engine, verdicts);
}

// SFCV_VENDOR_SAMPLES: a folder holding public vendor files, read in place, never copied.
std::optional<std::filesystem::path> vendor_sample(const std::string& name) {
  const char* root = std::getenv("SFCV_VENDOR_SAMPLES");
  if (!root || !*root) return std::nullopt;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(root, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
    if (it->path().filename() == name) return it->path();
  return std::nullopt;
}

// francisboudreau7/l5x_sfc tests/MainProgram.L5X, unmodified: a grafcet written in ladder (a
// main routine of JSRs to the routines Actions, Etapes, Transitions; step bits X.i in a DINT),
// its SFC routine called by no routine. It loads and is checked with the default options; the
// grafcet's steps exclude each other and its cycle returns to step 0.
TEST(L5xE2E, PublicLadderSampleLoadsAndIsChecked) {
  const auto sample = vendor_sample("MainProgram.L5X");
  if (!sample) GTEST_SKIP() << "SFCV_VENDOR_SAMPLES holds no MainProgram.L5X: test skipped";
  const auto r = run_sfcv("check --timeout 60 " + sample->string());
  // initial-return is violated: the state before the first scan (S:FS TRUE) never recurs.
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("routine 'SFC' (SFC) is not called from the main routine 'MainRoutine'"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("initial-return    violated"), std::string::npos) << r.out;
  expect_ctl_verdicts_in_one_run(sample->string(), "bdd",
                                 {{"AG !(X_0 & X_1)", "holds"},
                                  {"AG (A_plus -> !A_moins)", "holds"},
                                  {"EF X_19", "holds"},
                                  {"AG EF X_0", "holds"},
                                  {"AG !X_19", "violated"}});
}

// reh3376/acd-l5x-tool-lib docs/exports/Cooker_1_AutoLogic_Program.L5X, unmodified: a real
// plant's ladder program (2.2 MB) whose rungs address parts of controller tags of user types
// (`Cooker1.BIT_Logic[0].2`, `Cooker1.TMR_Logic[3].DN`). Those parts are read; it stays exit 2
// for what the model has no meaning for, each located: REAL parts, elements chosen by a tag,
// add-on instructions and their members, TIMER presets written by rungs.
TEST(L5xE2E, PublicPlantProgramIsRefusedOnlyAtWhatIsNotRead) {
  const auto sample = vendor_sample("Cooker_1_AutoLogic_Program.L5X");
  if (!sample)
    GTEST_SKIP() << "SFCV_VENDOR_SAMPLES holds no Cooker_1_AutoLogic_Program.L5X: test skipped";
  const auto r = run_sfcv("check --timeout 60 " + sample->string());
  EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 2000);
  EXPECT_EQ(r.err.find("unsupported: operand 'Cooker1.BIT_Logic["), std::string::npos);
  EXPECT_EQ(r.err.find("which is not a TIMER"), std::string::npos);
  // Elements chosen by a tag and read (`XIC(Cooker1.Startup_Step_Conf_Needed[Cooker1.Index])`).
  EXPECT_EQ(r.err.find("'Cooker1.Startup_Step_Conf_Needed[Cooker1.Index]'"), std::string::npos);
  for (const char* reason :
       {"(REAL) as an integer", "'Cooker1_Recipe.Step[0].Step_Ing_1_Actual' (REAL) as an integer",
        "unsupported: RLL instruction ANALOG_INPUT",
        "a TIMER's or COUNTER's preset is read from its tag's data",
        "RES on 'Cooker1.TMR_Logic[13]' (RES of a COUNTER, or of a TIMER that a TON runs, is read; "
        "no TON runs"})
    EXPECT_NE(r.err.find(reason), std::string::npos) << reason;
}

}  // namespace
}  // namespace sfcv::test

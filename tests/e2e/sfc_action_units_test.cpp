// SFC actions of function block instances called by name (issue 18, the TwinCAT idiom of the
// xPPU projects): a function block's SFC actions that its own SFC body (if any) does not name
// run each as its own chart, one cycle per call, called from ST (`cyl.ACT_Extend(SFCReset :=
// reset);`) or by a step's association (`STEP Run: cyl.ACT_Extend; END_STEP`); its `AT %I`
// variables are inputs of the plant (docs/semantics.md 1.3b). Every engine gives the same verdicts.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// The cylinder's SFC action: Idle -> Moving (unless reset) -> Ended (on its end sensor, a
// plant input `atEnd AT %IX1` of the instance). `out` and `done` follow Moving and Ended.
const std::string kCylinder =
    "FUNCTION_BLOCK Cylinder\n"
    "  VAR_INPUT SFCReset : BOOL; END_VAR\n"
    "  VAR_OUTPUT out : BOOL; done : BOOL; END_VAR\n"
    "  VAR atEnd AT %IX1 : BOOL; END_VAR\n"
    "  ACTION ACT_Extend:\n"
    "    INITIAL_STEP Idle: END_STEP\n"
    "    STEP Moving: out; END_STEP\n"
    "    STEP Ended: done; END_STEP\n"
    "    TRANSITION FROM Idle TO Moving := NOT SFCReset; END_TRANSITION\n"
    "    TRANSITION FROM Moving TO Ended := atEnd; END_TRANSITION\n"
    "  END_ACTION\n"
    "END_FUNCTION_BLOCK\n";

// A step calls the instance's SFC action while it is active.
const std::string kByAssociation = kCylinder +
                                   "PROGRAM Main\n"
                                   "  VAR_INPUT go : BOOL; END_VAR\n"
                                   "  VAR cyl : Cylinder; END_VAR\n"
                                   "  INITIAL_STEP Wait: END_STEP\n"
                                   "  STEP Run: cyl.ACT_Extend; END_STEP\n"
                                   "  TRANSITION FROM Wait TO Run := go; END_TRANSITION\n"
                                   "  TRANSITION FROM Run TO Wait := cyl.done; END_TRANSITION\n"
                                   "END_PROGRAM\n";

// ST calls it, passing the instance's SFCReset input.
const std::string kByCall = kCylinder +
                            "PROGRAM Cell\n"
                            "  VAR_INPUT go, reset : BOOL; END_VAR\n"
                            "  VAR cyl : Cylinder; END_VAR\n"
                            "  IF go OR reset THEN cyl.ACT_Extend(SFCReset := reset); END_IF;\n"
                            "END_PROGRAM\n";

/// The properties alone: the standard checks are not what these tests are about.
std::string check(const std::string& file, const std::string& engine, const std::string& props) {
  return check_command(file, engine, "--checks none " + props);
}

// The chart evolves only in the cycles where the step calls it, keeps its step when it is not
// called (Ended stays), and reaches Ended only through the plant's end sensor: a model that
// read `atEnd` as a constant, or never ran the action, would claim `AG !cyl.done`.
TEST(SfcActionUnits, AStepRunsTheInstancesChartOnlyWhileItsAssociationIsActive) {
  const auto file = write_temp(kByAssociation, ".st");
  for (const char* engine : {"explicit", "bdd", "ic3", "bmc"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check(file, engine, "--ctl 'AG !cyl.done'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    if (std::string(engine) == "bmc") continue;  // BMC cannot prove
    r = run_sfcv(check(file, engine,
                       "--ctl 'AG (cyl.ACT_Extend.Moving -> cyl.out)' "
                       "--ctl 'AG ((Wait & cyl.ACT_Extend.Idle) -> AX cyl.ACT_Extend.Idle)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("VACUOUS"), std::string::npos) << r.out;
  }
  for (const char* engine : {"explicit", "bdd"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv(
        check(file, engine, "--ctl 'AG (cyl.ACT_Extend.Ended -> AG cyl.ACT_Extend.Ended)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  }
}

// `cyl.ACT_Extend(SFCReset := reset)` assigns the input, then runs one cycle of the chart,
// which the flag resets to Idle: Ended can always be left, and only thanks to the reset.
TEST(SfcActionUnits, AnStCallPassesInputsAndSfcResetRestartsTheChart) {
  const auto file = write_temp(kByCall, ".st");
  for (const char* engine : {"explicit", "bdd"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check(file, engine,
                            "--ctl 'AG !cyl.done' "
                            "--ctl 'AG (cyl.ACT_Extend.Ended -> EF cyl.ACT_Extend.Idle)'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("AG !cyl.done"), std::string::npos);
    r = run_sfcv(
        check(file, engine, "--ctl 'AG (cyl.ACT_Extend.Ended -> EF cyl.ACT_Extend.Idle)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    r = run_sfcv(check(file, engine,
                       "--assume '!reset' "
                       "--ctl 'AG (cyl.ACT_Extend.Ended -> EF cyl.ACT_Extend.Idle)'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  }
}

// The counterexample of each engine replays in `sfcv simulate`, step for step.
// An SFC action run as a unit has its own copies of the actions its steps name, with their
// own stored flags: stored-actions and output-conflicts judge them there, under the unit's
// path. The cylinder's `Drive` is set at Moving; reset at Ended, it holds; without the reset,
// Drive stays stored into Ended, where Stop writes `out` too, and Moving sets it again.
TEST(SfcActionUnits, StoredActionsAndConflictsAreJudgedInsideTheUnit) {
  auto project = [](const std::string& ended) {
    return write_temp(
        "FUNCTION_BLOCK Cylinder\n  VAR_INPUT SFCReset : BOOL; END_VAR\n"
        "  VAR_OUTPUT out : BOOL; END_VAR\n  VAR atEnd AT %IX1 : BOOL; END_VAR\n"
        "  ACTION Drive: out := TRUE; END_ACTION\n  ACTION Stop: out := FALSE; END_ACTION\n"
        "  ACTION ACT_Extend:\n    INITIAL_STEP Idle: END_STEP\n"
        "    STEP Moving: Drive(S); END_STEP\n    STEP Ended: " +
            ended +
            " END_STEP\n"
            "    TRANSITION FROM Idle TO Moving := NOT SFCReset; END_TRANSITION\n"
            "    TRANSITION FROM Moving TO Ended := atEnd; END_TRANSITION\n"
            "    TRANSITION FROM Ended TO Idle := TRUE; END_TRANSITION\n"
            "  END_ACTION\nEND_FUNCTION_BLOCK\n" +
            "PROGRAM Main\n  VAR_INPUT go : BOOL; END_VAR\n  VAR cyl : Cylinder; END_VAR\n"
            "  INITIAL_STEP Wait: END_STEP\n  STEP Run: cyl.ACT_Extend; END_STEP\n"
            "  TRANSITION FROM Wait TO Run := go; END_TRANSITION\n"
            "  TRANSITION FROM Run TO Wait := NOT go; END_TRANSITION\nEND_PROGRAM\n",
        ".st");
  };
  const auto good = project("Drive(R); Stop(N);");
  const auto bad = project("Stop(N);");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check_command(good, engine, "--checks stored-actions,output-conflicts"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("stored actions are used correctly"), std::string::npos) << r.out;
    r = run_sfcv(check_command(bad, engine, "--checks stored-actions,output-conflicts"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("action Main.cyl.ACT_Extend.DRIVE is stored at step Moving"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("action Main.cyl.ACT_Extend.DRIVE is set again (S at Moving)"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("variable OUT of Main.cyl is written by"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("not checked"), std::string::npos) << r.out;
  }
}

TEST(SfcActionUnits, CounterexamplesReplayInSimulate) {
  for (const auto* text : {&kByAssociation, &kByCall}) {
    const auto file = write_temp(*text, ".st");
    for (const char* engine : {"explicit", "bdd", "bmc", "ic3"}) {
      SCOPED_TRACE(engine);
      const auto csv = write_temp("", ".csv");
      const auto r = run_sfcv("check " + file + " --engine " + engine +
                              " --checks none --quiet --ctl 'AG !cyl.done' --trace csv "
                              "--trace-file '" +
                              csv + "'");
      ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
      const auto sim = run_sfcv("simulate " + file + " --inputs '" + csv + "'");
      EXPECT_EQ(sim.exit_code, 0) << sim.out << sim.err;
      EXPECT_NE(sim.out.find("Ended"), std::string::npos) << sim.out;
    }
  }
}

// What cannot be called is refused with its place: an action the type does not have, inputs
// the type does not declare, an output binding.
TEST(SfcActionUnits, CallsOfMissingActionsAndInputsAreLocatedErrors) {
  auto text = kByAssociation;
  text.replace(text.find("cyl.ACT_Extend;"), 15, "cyl.ACT_Retract;");
  auto r = run_sfcv("check " + write_temp(text, ".st") + " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":17:13: error: step 'Run' names action 'cyl.ACT_Retract', but function "
                       "block Cylinder has no action 'ACT_Retract'"),
            std::string::npos)
      << r.err;
  text = kByCall;
  text.replace(text.find("SFCReset := reset"), 17, "Speed := 3");
  r = run_sfcv("check " + write_temp(text, ".st") + " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("error: function block Cylinder has no input 'Speed'"), std::string::npos)
      << r.err;
}

// TwinCAT PLC Control 3.5.6.1 (the VerifAPS `ppu.xml`): function blocks whose own body is SFC
// (here a one-step loop) still run their SFC actions that no step of that body names as units,
// called from another function block's step action (`crane.ACT_Init();`), from an action of
// one of the unit's steps (`ACT_MoveToStamp();`, the same instance) and from the body of the
// caller itself (`ACT_Lamp();`); the instance is a VAR_INPUT of its caller, as in the export.
const std::string kSfcBodyWithUnits = R"(FUNCTION_BLOCK Crane
  VAR_INPUT SFCReset : BOOL; END_VAR
  VAR_OUTPUT turning : BOOL; there : BOOL; END_VAR
  VAR atStamp AT %IX1 : BOOL; END_VAR
  INITIAL_STEP Init: END_STEP
  TRANSITION FROM Init TO Init := TRUE; END_TRANSITION
  ACTION ACT_Init:
    INITIAL_STEP Start: END_STEP
    STEP ToStamp: Go; END_STEP
    STEP Ready: END_STEP
    TRANSITION FROM Start TO ToStamp := NOT SFCReset; END_TRANSITION
    TRANSITION FROM ToStamp TO Ready := there; END_TRANSITION
  END_ACTION
  ACTION Go: ACT_MoveToStamp(); END_ACTION
  ACTION ACT_MoveToStamp:
    INITIAL_STEP Idle: END_STEP
    STEP Turning: turning; END_STEP
    STEP Arrived: there; END_STEP
    TRANSITION FROM Idle TO Turning := TRUE; END_TRANSITION
    TRANSITION FROM Turning TO Arrived := atStamp; END_TRANSITION
  END_ACTION
END_FUNCTION_BLOCK
FUNCTION_BLOCK Cell
  VAR_INPUT crane : Crane; go : BOOL; END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP Wait: END_STEP
  STEP Run: CallInit; END_STEP
  TRANSITION FROM Wait TO Run := go; END_TRANSITION
  TRANSITION FROM Run TO Wait := crane.there; END_TRANSITION
  ACTION CallInit: crane.ACT_Init(); ACT_Lamp(); END_ACTION
  ACTION ACT_Lamp:
    INITIAL_STEP Off: END_STEP
    STEP On: lamp; END_STEP
    TRANSITION FROM Off TO On := TRUE; END_TRANSITION
  END_ACTION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR cell : Cell; END_VAR
  cell(go := go);
END_PROGRAM
)";

// The crane reaches the stamp only through the chain of calls (Run -> ACT_Init at ToStamp ->
// Go -> ACT_MoveToStamp), its move chart stays at Idle in every cycle where ACT_Init is not at
// ToStamp, and keeps Arrived (history). A model that ran none of the calls would claim
// `AG !cell.crane.there`; one that ran the move chart every cycle would break the AX property.
TEST(SfcActionUnits, SfcActionsOfAnSfcBodiedBlockThatItsBodyDoesNotNameAreUnits) {
  const auto file = write_temp(kSfcBodyWithUnits, ".st");
  const std::string only_through_init =
      "--ctl 'AG ((cell.crane.ACT_MoveToStamp.Idle & !cell.crane.ACT_Init.ToStamp) -> "
      "AX cell.crane.ACT_MoveToStamp.Idle)' "
      "--ctl 'AG ((cell.Wait & cell.ACT_Lamp.Off) -> AX cell.ACT_Lamp.Off)'";
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check(file, engine, "--ctl 'AG !cell.crane.there' --ctl 'AG !cell.lamp'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_EQ(r.out.find("holds"), std::string::npos) << r.out;
    r = run_sfcv(check(file, engine, only_through_init));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("VACUOUS"), std::string::npos) << r.out;
  }
  for (const char* engine : {"explicit", "bdd"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv(check(file, engine,
                                  "--ctl 'AG (cell.crane.ACT_MoveToStamp.Arrived -> AG "
                                  "cell.crane.ACT_MoveToStamp.Arrived)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  // The shortest way to the stamp: go, ACT_Init leaves Start, the move chart leaves Idle, the
  // sensor; a call too many or too few per cycle changes the length.
  const auto r =
      run_sfcv("check " + file + " --engine explicit --checks none --ctl 'AG !cell.crane.there'");
  EXPECT_NE(r.out.find("counterexample (5 situations)"), std::string::npos) << r.out;
}

// An SFC action that a step of the block's own SFC body names is that step's nested chart
// (1.3); calling it by name as well, from ST or from a unit's step, would run one chart from two
// places: refused at the call, naming the step.
TEST(SfcActionUnits, ANestedChartOfTheBodyCalledByNameIsRefused) {
  const std::string feeder = R"(FUNCTION_BLOCK Feeder
  VAR_OUTPUT out : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Feed: ACT_Run; END_STEP
  TRANSITION FROM Idle TO Feed := TRUE; END_TRANSITION
  ACTION ACT_Run:
    INITIAL_STEP R0: out; END_STEP
  END_ACTION
)";
  auto r =
      run_sfcv("check " +
               write_temp(feeder + "END_FUNCTION_BLOCK\nPROGRAM Main\n  VAR f : Feeder; END_VAR\n"
                                   "  f();\n  f.ACT_Run();\nEND_PROGRAM\n",
                          ".st") +
               " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":13:3: error: call of action 'f.ACT_Run' of Feeder: step 'Feed' of the "
                       "SFC body of Feeder runs it as its nested chart"),
            std::string::npos)
      << r.err;
  r = run_sfcv("check " +
               write_temp(feeder +
                              "  ACTION ACT_Other:\n    INITIAL_STEP O0: ACT_Run; END_STEP\n"
                              "  END_ACTION\nEND_FUNCTION_BLOCK\nPROGRAM Main\n"
                              "  VAR f : Feeder; END_VAR\n  f();\n  f.ACT_Other();\nEND_PROGRAM\n",
                          ".st") +
               " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("error: step 'O0' of SFC action 'ACT_Other' names SFC action 'ACT_Run', "
                       "which step 'Feed' of the SFC body of Feeder runs as its nested chart"),
            std::string::npos)
      << r.err;
  // From inside the block: an ST action of the body calling `ACT_Run();`.
  auto inside = feeder +
                "  ACTION Kick: ACT_Run(); END_ACTION\nEND_FUNCTION_BLOCK\nPROGRAM Main\n"
                "  VAR f : Feeder; END_VAR\n  f();\nEND_PROGRAM\n";
  inside.replace(inside.find("INITIAL_STEP Idle: END_STEP"), 27,
                 "INITIAL_STEP Idle: Kick; END_STEP");
  r = run_sfcv("check " + write_temp(inside, ".st") + " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":9:16: error: call of action 'ACT_Run' of Feeder: step 'Feed' of the SFC "
                       "body of Feeder runs it as its nested chart"),
            std::string::npos)
      << r.err;
}

// A unit whose steps call, through another unit and an ST action, the unit itself would run
// forever within one scan: refused at the action, with the chain of calls.
TEST(SfcActionUnits, ACycleOfCallsIsRefused) {
  const auto file = write_temp(R"(FUNCTION_BLOCK Ping
  VAR_OUTPUT n : BOOL; END_VAR
  ACTION ACT_A:
    INITIAL_STEP A0: ACT_B; END_STEP
  END_ACTION
  ACTION ACT_B:
    INITIAL_STEP B0: Again; END_STEP
  END_ACTION
  ACTION Again: ACT_A(); END_ACTION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR p : Ping; END_VAR
  p.ACT_A();
END_PROGRAM
)",
                               ".st");
  const auto r = run_sfcv("check " + file + " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":3:3: error: 'Main.p.ACT_A' calls itself (Main.p.ACT_A -> "
                       "Main.p.ACT_B -> Main.p.ACT_A)"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace sfcv::test

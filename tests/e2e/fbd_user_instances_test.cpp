// FBD networks as programs: instances of the project's own function blocks as blocks (PLCopen
// `block` with an `instanceName` and the `typeName` of a FUNCTION_BLOCK POU: called once where
// the network first needs them, outputs read as members, EN guarding the call), standard
// functions such as SEL, and the data-flow order of assignments. Checked on every engine, and
// against the same program written in ST (and, on the corpus, against Beremiz's own ST, FBD and
// LD versions of one counter).

#include <gtest/gtest.h>

#include <string>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// Latch: q is set by `set`, cleared by `reset` (reset wins), and kept in between.
std::string latch_fb() {
  return "<pou name=\"Latch\" pouType=\"functionBlock\"><interface>" +
         plcopen_vars("inputVars", {"set", "reset"}) + plcopen_vars("outputVars", {"q"}) +
         "</interface><body>" +
         plcopen_st("IF set THEN q := TRUE; END_IF; IF reset THEN q := FALSE; END_IF;") +
         "</body></pou>\n";
}

std::string in_variable(int id, const std::string& name) {
  return "<inVariable localId=\"" + std::to_string(id) +
         "\"><position x=\"0\" y=\"0\"/><connectionPointOut/><expression>" + name +
         "</expression></inVariable>";
}

std::string wired(const std::string& pin, int from) {
  return "<variable formalParameter=\"" + pin + "\"><connectionPointIn><connection refLocalId=\"" +
         std::to_string(from) + "\"/></connectionPointIn></variable>";
}

/// Main in FBD: L1 : Latch(set := s1, reset := s2) drives `motor`; with `enable`, EN of L1 is
/// wired to input `en`; with `spare`, a second instance L2 whose output nobody reads latches
/// s2 (it still runs: its q is observable).
std::string fbd_main(bool enable, bool spare) {
  std::string vars =
      plcopen_vars("inputVars", {"s1", "s2", "en"}) + plcopen_vars("outputVars", {"motor"}) +
      "<localVars>" + "<variable name=\"L1\"><type><derived name=\"Latch\"/></type></variable>" +
      "<variable name=\"L2\"><type><derived name=\"Latch\"/></type></variable>" + "</localVars>";
  std::string fbd = in_variable(1, "s1") + in_variable(2, "s2") + in_variable(3, "en") +
                    "<block localId=\"4\" typeName=\"Latch\" instanceName=\"L1\"><position x=\"0\" "
                    "y=\"0\"/><inputVariables>" +
                    (enable ? wired("EN", 3) : "") + wired("set", 1) + wired("reset", 2) +
                    "</inputVariables><inOutVariables/><outputVariables><variable "
                    "formalParameter=\"q\"><connectionPointOut/></variable></outputVariables>"
                    "</block><outVariable localId=\"5\"><position x=\"0\" y=\"0\"/>"
                    "<connectionPointIn><connection refLocalId=\"4\" formalParameter=\"q\"/>"
                    "</connectionPointIn><expression>motor</expression></outVariable>";
  if (spare)
    fbd +=
        "<block localId=\"6\" typeName=\"Latch\" instanceName=\"L2\"><position x=\"0\" "
        "y=\"0\"/><inputVariables>" +
        wired("set", 2) +
        "</inputVariables><inOutVariables/><outputVariables><variable "
        "formalParameter=\"q\"><connectionPointOut/></variable></outputVariables></block>";
  return "<pou name=\"Main\" pouType=\"program\"><interface>" + vars + "</interface><body><FBD>" +
         fbd + "</FBD></body></pou>\n";
}

std::string st_main(bool enable) {
  return "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"s1", "s2", "en"}) + plcopen_vars("outputVars", {"motor"}) +
         "<localVars><variable name=\"L1\"><type><derived name=\"Latch\"/></type></variable>"
         "</localVars></interface><body>" +
         plcopen_st(enable ? "IF en THEN L1(set := s1, reset := s2); END_IF; motor := L1.q;"
                           : "L1(set := s1, reset := s2); motor := L1.q;") +
         "</body></pou>\n";
}

TEST(FbdUserInstances, AUserFunctionBlockBlockIsCalledAndItsOutputRead) {
  const auto file =
      write_temp(kPlcopenHeader + latch_fb() + fbd_main(false, false) + kPlcopenFooter, ".xml");
  // The latch keeps motor on after s1 falls (a model without the instance's memory would not
  // reach it), reset wins, and motor does come on.
  expect_on_every_engine(file, {{"--checks none --ctl 'EF (motor & !s1)'", 0},
                                {"--checks none --ctl 'AG (s2 -> !motor)'", 0},
                                {"--checks none --ctl 'AG !motor'", 1}});
}

TEST(FbdUserInstances, EnGuardsTheCallAndAnUnreadInstanceStillRuns) {
  const auto file =
      write_temp(kPlcopenHeader + latch_fb() + fbd_main(true, true) + kPlcopenFooter, ".xml");
  // EN FALSE: L1 is not called, so reset no longer wins (motor may stay on with s2).
  expect_on_every_engine(file, {{"--checks none --ctl 'AG (s2 -> !motor)'", 1},
                                {"--checks none --ctl 'AG (en & s2 -> !motor)'", 0},
                                {"--checks none --ctl 'AG !L2.q'", 1}});
}

TEST(FbdUserInstances, FbdAndStGiveTheSameStateSpace) {
  for (const bool enable : {false, true}) {
    SCOPED_TRACE(enable ? "with EN" : "without EN");
    const auto fbd =
        write_temp(kPlcopenHeader + latch_fb() + fbd_main(enable, false) + kPlcopenFooter, ".xml");
    const auto st =
        write_temp(kPlcopenHeader + latch_fb() + st_main(enable) + kPlcopenFooter, ".xml");
    const auto a = run_sfcv(check_command(fbd, "explicit", "--checks none --ctl 'AG !motor'"));
    const auto b = run_sfcv(check_command(st, "explicit", "--checks none --ctl 'AG !motor'"));
    ASSERT_EQ(a.exit_code, 1) << a.out << a.err;
    ASSERT_EQ(b.exit_code, 1) << b.out << b.err;
    EXPECT_EQ(a.out.substr(0, a.out.find('(')), b.out.substr(0, b.out.find('(')));
    EXPECT_NE(a.out.find(" states, "), std::string::npos) << a.out;
  }
}

// ENO of a user FB instance is EN when its POU never names ENO (nothing in it can clear it);
// an FB whose body names ENO is refused by name.
std::string eno_main(const std::string& type) {
  return "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"s1", "s2", "en"}) + plcopen_vars("outputVars", {"ok"}) +
         "<localVars><variable name=\"L1\"><type><derived name=\"" + type +
         "\"/></type></variable></localVars></interface><body><FBD>" + in_variable(1, "s1") +
         in_variable(2, "s2") + in_variable(3, "en") + "<block localId=\"4\" typeName=\"" + type +
         "\" instanceName=\"L1\"><position x=\"0\" y=\"0\"/><inputVariables>" + wired("EN", 3) +
         wired("set", 1) + wired("reset", 2) +
         "</inputVariables><inOutVariables/><outputVariables><variable formalParameter=\"ENO\">"
         "<connectionPointOut/></variable><variable formalParameter=\"q\"><connectionPointOut/>"
         "</variable></outputVariables></block><outVariable localId=\"5\"><position x=\"0\" "
         "y=\"0\"/><connectionPointIn><connection refLocalId=\"4\" formalParameter=\"ENO\"/>"
         "</connectionPointIn><expression>ok</expression></outVariable></FBD></body></pou>\n";
}

TEST(FbdUserInstances, EnoOfAnInstanceIsEnUnlessItsBlockNamesEno) {
  const auto quiet =
      write_temp(kPlcopenHeader + latch_fb() + eno_main("Latch") + kPlcopenFooter, ".xml");
  expect_on_every_engine(
      quiet, {{"--checks none --ctl 'AG (ok <-> en)'", 0}, {"--checks none --ctl 'AG ok'", 1}});
  const std::string clearer = "<pou name=\"Clearer\" pouType=\"functionBlock\"><interface>" +
                              plcopen_vars("inputVars", {"set", "reset"}) +
                              plcopen_vars("outputVars", {"q"}) + "</interface><body>" +
                              plcopen_st("q := set; ENO := NOT reset;") + "</body></pou>\n";
  const auto loud =
      write_temp(kPlcopenHeader + clearer + eno_main("Clearer") + kPlcopenFooter, ".xml");
  const auto r = run_sfcv(check_command(loud, "explicit", "--checks none --ctl 'AG ok'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("unsupported: ENO output of block Clearer (its body names ENO)"),
            std::string::npos)
      << r.err;
}

// Beremiz's first_steps (corpus 02) writes one counter in ST, FBD, LD and IL: `Cnt := SEL(Reset,
// Cnt + 1, ResetCounterValue); OUT := Cnt` (IL: LD Reset, JMPC ResetCnt, LD Cnt, ADD 1, JMP
// QuitFb, ResetCnt: LD ResetCounterValue, QuitFb: ST Cnt, ST Out). The FBD network assigns Cnt
// through an inOutVariable placed after the outVariable OUT in the document and reads it for OUT;
// before, SEL was refused, and assignments in document order made OUT lag one cycle (65,535 states
// instead of 32,768), and IL was refused. The four agree now, state for state.
TEST(FbdCorpus, BeremizCounterInStFbdLdAndIlAgree) {
  SFCV_REQUIRE_CORPUS(corpus);
  const std::string path = "'" + (corpus / "02_beremiz_first_steps.xml").string() + "'";
  for (const char* pou : {"CounterST", "CounterFBD", "CounterLD", "CounterIL"}) {
    SCOPED_TRACE(pou);
    // OUT = 18 takes a reset (OUT = 17) and one count: 3 situations; a lag of one cycle would
    // take 4.
    const auto r = run_sfcv("check " + path + " --pou " + pou +
                            " --engine explicit --checks none --ctl 'AG OUT <= 32767' "
                            "--ctl 'AG !(OUT = 18)'");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("32,768 states, 65,534 edges"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("counterexample (3 situations)"), std::string::npos) << r.out;
  }
}

// Data-flow order: OUT reads the variable `n` that an inOutVariable later in the document
// assigns: it reads the new value. Two variables reading each other without an execution
// order are refused by name.
std::string flow_main(bool cycle) {
  const std::string second_source = cycle ? "<connection refLocalId=\"3\"/>"  // m reads n
                                          : "<connection refLocalId=\"1\"/>";
  return "<pou name=\"Main\" pouType=\"program\"><interface>" + plcopen_vars("inputVars", {"go"}) +
         plcopen_vars("outputVars", {"OUT"}) + plcopen_vars("localVars", {"n", "m"}) +
         "</interface><body><FBD>" + in_variable(1, "go") +
         "<outVariable localId=\"2\"><position x=\"0\" y=\"0\"/><connectionPointIn>"
         "<connection refLocalId=\"3\"/></connectionPointIn><expression>OUT</expression>"
         "</outVariable>"
         "<inOutVariable localId=\"3\"><position x=\"0\" y=\"0\"/><connectionPointIn>"
         "<connection refLocalId=\"4\"/></connectionPointIn><connectionPointOut/>"
         "<expression>n</expression></inOutVariable>"
         "<inOutVariable localId=\"4\"><position x=\"0\" y=\"0\"/><connectionPointIn>" +
         second_source +
         "</connectionPointIn><connectionPointOut/><expression>m</expression></inOutVariable>"
         "</FBD></body></pou>\n";
}

TEST(FbdUserInstances, AssignmentsFollowTheDataFlowWithoutAnExecutionOrder) {
  const auto file = write_temp(kPlcopenHeader + flow_main(false) + kPlcopenFooter, ".xml");
  // m := go; n := m; OUT := n, all in one cycle: OUT is go of this cycle.
  expect_on_every_engine(
      file, {{"--checks none --ctl 'AG (OUT <-> go)'", 0}, {"--checks none --ctl 'AG !OUT'", 1}});
  const auto cyclic = write_temp(kPlcopenHeader + flow_main(true) + kPlcopenFooter, ".xml");
  const auto r = run_sfcv(check_command(cyclic, "explicit", "--checks none --ctl 'AG !OUT'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("read each other in a cycle and no execution order is given"),
            std::string::npos)
      << r.err;
}

// Beremiz SVGHMI programs declare their operator controls and lamps with the HMI types
// (corpus 01: `SwitchButton : HMI_BOOL`). The operator may set such a variable between any two
// cycles: a program's own HMI variable is an input of the plant of the base type, which the
// program's writes overwrite. Before, the variables were dropped ("unsupported type") and the
// body that uses them refused; an HMI type elsewhere (a VAR_OUTPUT) still is.
TEST(FbdUserInstances, BeremizHmiVariablesAreInputsTheOperatorSets) {
  auto program = [](const std::string& section) {
    return "<pou name=\"Main\" pouType=\"program\"><interface><" + section +
           "><variable name=\"Button\"><type><derived name=\"HMI_BOOL\"/></type></variable>"
           "<variable name=\"Lamp\"><type><derived name=\"HMI_BOOL\"/></type></variable></" +
           section + "></interface><body>" + plcopen_st("Lamp := Button;") + "</body></pou>\n";
  };
  const auto local = write_temp(kPlcopenHeader + program("localVars") + kPlcopenFooter, ".xml");
  // The button can be pressed (a model keeping it FALSE would claim AG !Lamp), and Lamp is
  // the program's value, not the HMI's.
  expect_on_every_engine(local, {{"--checks none --ctl 'AG !Lamp'", 1},
                                 {"--checks none --ctl 'AG (Lamp <-> Button)'", 0}});
  const auto out = write_temp(kPlcopenHeader + program("outputVars") + kPlcopenFooter, ".xml");
  const auto r = run_sfcv(check_command(out, "explicit", "--checks none --ctl 'AG !Lamp'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("unsupported type HMI_BOOL of variable 'Lamp'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sfcv::test

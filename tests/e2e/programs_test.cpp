// Programs that are not SFC: POUs with ST, FBD and LD bodies run as programs (a scan cycle
// without steps), several programs in one cycle, and the vendor idioms of real exports
// (CODESYS timer reset, CTU's RESET, TwinCAT timers without PT). The files are small ones
// written here in the vendors' export style.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// A PLCopen TC6 v2.01 document holding `pous`.
std::string plcopen(const std::string& pous) {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n"
         "<fileHeader companyName=\"t\" productName=\"t\" productVersion=\"1\" "
         "creationDateTime=\"2024-01-01T00:00:00\"/>\n<contentHeader name=\"demo\"/>\n"
         "<types><dataTypes/><pous>\n" +
         pous +
         "</pous></types>\n"
         "<instances><configurations/></instances>\n</project>\n";
}

std::string bool_vars(const char* section, std::initializer_list<const char*> names) {
  std::string s = std::string("<") + section + ">";
  for (const char* n : names)
    s += std::string("<variable name=\"") + n + "\"><type><BOOL/></type></variable>";
  return s + "</" + section + ">";
}

std::string st_pou(const std::string& name, const std::string& interface, const std::string& st,
                   const char* type = "program") {
  return "<pou name=\"" + name + "\" pouType=\"" + type + "\"><interface>" + interface +
         "</interface><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">" + st +
         "</xhtml></ST></body></pou>\n";
}

std::string motors(const std::string& st) {
  return plcopen(st_pou(
      "Motors", bool_vars("inputVars", {"start"}) + bool_vars("outputVars", {"M1", "M2"}), st));
}

// The regression of issue 18: an ST-bodied POU used to run as an empty program that "holds".
TEST(Programs, StBodyUnderPouIsCheckedNotEmpty) {
  const auto file = write_temp(motors("M1 := start; M2 := start;"), ".xml");
  auto r = run_sfcv("check " + file + " --pou Motors --ctl 'AG !(M1 & M2)' --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("violated"), std::string::npos) << r.out;
  // Without --pou: the one program runs.
  r = run_sfcv("check " + file + " --ctl 'AG !(M1 & M2)' --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  // And a property that holds holds.
  r = run_sfcv("check " + file + " --ctl 'AG (M1 <-> M2)' --ctl 'EF M1' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// M1 is evaluated first and wins: M2 never runs (`EF M2` is false), and never with M1.
TEST(Programs, InterlockedStBodyHolds) {
  const auto file = write_temp(motors("M1 := start AND NOT M2; M2 := start AND NOT M1;"), ".xml");
  const auto r = run_sfcv("check " + file + " --ctl 'AG !(M1 & M2)' --ctl 'EF M1' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(run_sfcv("check " + file + " --ctl 'EF M2' --trace none").exit_code, 1);
}

// An IL body is a program (docs/semantics.md 1.9.2); one with a loop (a backward jump) is
// refused by name and place (exit 2), never run as a no-op.
TEST(Programs, IlBodyIsModelledAndALoopIsRefusedWithItsLocation) {
  auto motors = [](const std::string& il) {
    return plcopen("<pou name=\"Motors\" pouType=\"program\"><interface>" +
                   bool_vars("outputVars", {"M1"}) +
                   "</interface><body><IL><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">" + il +
                   "</xhtml></IL></body></pou>\n");
  };
  const auto file = write_temp(motors("LD TRUE\nST M1"), ".xml");
  auto r = run_sfcv("check " + file + " --ctl 'AG !M1' --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto loop = write_temp(motors("top: LD M1\nSTN M1\nJMPCN top"), ".xml");
  r = run_sfcv("check " + loop + " --pou Motors --ctl 'AG !M1'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("IL body is not modelled"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(":8:1"), std::string::npos) << r.err;  // JMPCN, the body's third line
  EXPECT_NE(r.err.find("IL: backward jump to 'top' (a loop) is not modelled"), std::string::npos)
      << r.err;
  r = run_sfcv("check " + loop + " --ctl 'AG !M1'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--pou"), std::string::npos) << r.err;
}

// A pure IEC text file holding only an ST program: checked without --pou.
TEST(Programs, PureStTextProgram) {
  const auto file = write_temp(
      "PROGRAM p\n VAR_INPUT a : BOOL; END_VAR\n VAR_OUTPUT x, y : BOOL; END_VAR\n"
      " x := a; y := NOT a;\nEND_PROGRAM\n",
      ".st");
  auto r =
      run_sfcv("check " + file + " --ctl 'AG !(x & y)' --ctl 'EF x' --ctl 'EF y' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("check " + file + " --ctl 'AG !x' --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

// Two programs of one project run in one cycle in document order, sharing a global: the
// second sees what the first wrote in the same cycle.
TEST(Programs, SeveralProgramsRunInOneCycleInDocumentOrderOrTaskOrder) {
  const std::string a = st_pou(
      "A", bool_vars("inputVars", {"start"}) + bool_vars("globalVars", {"req"}), "req := start;");
  const std::string b =
      st_pou("B", bool_vars("externalVars", {"req"}) + bool_vars("outputVars", {"motor"}),
             "motor := req;");
  const auto ab = write_temp(plcopen(a + b), ".xml");
  auto r = run_sfcv("check " + ab + " --ctl 'AG (motor <-> req)' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // B before A: motor lags one cycle behind req.
  const auto ba = write_temp(plcopen(b + a), ".xml");
  r = run_sfcv("check " + ba + " --ctl 'AG (motor <-> req)' --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  // A configuration's task gives the order: B's instance first, then A's, whatever the
  // document order.
  std::string tasked = plcopen(a + b);
  const std::string task =
      "<configurations><configuration name=\"Cfg\"><resource name=\"Res\"><task name=\"T\" "
      "interval=\"T#10ms\" priority=\"1\"><pouInstance name=\"b1\" typeName=\"B\"/>"
      "<pouInstance name=\"a1\" typeName=\"A\"/></task></resource></configuration>"
      "</configurations>";
  tasked.replace(tasked.find("<configurations/>"), std::string("<configurations/>").size(), task);
  r = run_sfcv("check " + write_temp(tasked, ".xml") + " --ctl 'AG (motor <-> req)' --trace none");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

// An LD rung: contacts in series and parallel, a negated contact, set/reset coils and a
// rising-edge contact (Beremiz/CODESYS export style).
std::string ld_pou() {
  auto contact = [](int id, const char* var, int from, const char* extra = "") {
    return "<contact localId=\"" + std::to_string(id) + "\"" + extra +
           "><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"" +
           std::to_string(from) + "\"/></connectionPointIn><connectionPointOut/><variable>" + var +
           "</variable></contact>";
  };
  auto coil = [](int id, const char* var, int from, const char* extra = "") {
    return "<coil localId=\"" + std::to_string(id) + "\"" + extra +
           "><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"" +
           std::to_string(from) + "\"/></connectionPointIn><connectionPointOut/><variable>" + var +
           "</variable></coil>";
  };
  const std::string rail =
      "<leftPowerRail localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut "
      "formalParameter=\"\"/></leftPowerRail>";
  std::string ld = rail;
  // run := start AND NOT stop
  ld += contact(2, "start", 1) + contact(3, "stop", 2, " negated=\"true\"") + coil(4, "run", 3);
  // latched: S on a rising edge of start, R on stop
  ld += contact(5, "start", 1, " edge=\"rising\"") + coil(6, "latched", 5, " storage=\"set\"");
  ld += contact(7, "stop", 1) + coil(8, "latched", 7, " storage=\"reset\"");
  // pulse := rising edge of start (true one cycle)
  ld += contact(9, "start", 1, " edge=\"rising\"") + coil(10, "pulse", 9);
  return "<pou name=\"Rung\" pouType=\"program\"><interface>" +
         bool_vars("inputVars", {"start", "stop"}) +
         bool_vars("outputVars", {"run", "latched", "pulse"}) + "</interface><body><LD>" + ld +
         "</LD></body></pou>\n";
}

TEST(Programs, LadderRungIsPowerFlow) {
  const auto file = write_temp(plcopen(ld_pou()), ".xml");
  auto r = run_sfcv("check " + file +
                    " --trace none --ctl 'AG ((pulse & run) -> latched)'"
                    " --ctl 'EF latched' --ctl 'EF (latched & !run)' --ctl 'EF run'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // The edge contact passes power for one cycle only: start held does not keep pulse on.
  r = run_sfcv("check " + file + " --trace none --ctl 'AG (pulse -> AX !pulse)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("check " + file + " --trace none --ctl 'AG (run -> pulse)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  // Set before reset in rung order: a rising start with stop leaves the latch reset.
  r = run_sfcv("check " + file + " --trace none --ctl 'AG (pulse -> latched)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

// An edge contact that feeds two coils (the OpenPLC stairs light of ESBMC's LD benchmarks) is
// one element, evaluated once per cycle: both coils see the same one-cycle pulse. Before, the
// second coil made a second R_TRIG of the same name ("duplicate variable"); calling the one
// instance twice would leave the second coil without a pulse.
TEST(Programs, AnEdgeContactFeedingTwoCoilsIsOneElement) {
  auto element = [](const char* kind, int id, const char* var, int from, const char* extra) {
    return std::string("<") + kind + " localId=\"" + std::to_string(id) + "\"" + extra +
           "><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"" +
           std::to_string(from) + "\"/></connectionPointIn><connectionPointOut/><variable>" + var +
           "</variable></" + kind + ">";
  };
  const std::string ld =
      "<leftPowerRail localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut "
      "formalParameter=\"\"/></leftPowerRail>" +
      element("contact", 2, "start", 1, " edge=\"rising\"") +
      element("contact", 3, "enable", 2, "") + element("coil", 4, "pulse1", 2, "") +
      element("coil", 5, "pulse2", 3, "");
  const auto file = write_temp(plcopen("<pou name=\"Stairs\" pouType=\"program\"><interface>" +
                                       bool_vars("inputVars", {"start", "enable"}) +
                                       bool_vars("outputVars", {"pulse1", "pulse2"}) +
                                       "</interface><body><LD>" + ld + "</LD></body></pou>\n"),
                               ".xml");
  auto r = run_sfcv("check " + file +
                    " --trace none --ctl 'AG (pulse2 -> pulse1)' --ctl 'EF pulse2'"
                    " --ctl 'AG (pulse1 -> AX !pulse1)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("check " + file + " --trace none --ctl 'AG (pulse1 -> pulse2)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

// CODESYS: `T(IN := FALSE, PT := T#0MS)` resets a TON called elsewhere with PT := T#5S; a
// CTU's reset input is RESET. TwinCAT: a timer called without PT has PT = T#0s.
TEST(Programs, VendorTimerAndCounterIdioms) {
  const std::string interface =
      bool_vars("inputVars", {"go", "clear"}) +
      bool_vars("outputVars", {"done", "full", "at_once", "going", "cleared"}) +
      "<localVars><variable name=\"T\"><type><derived name=\"TON\"/></type></variable>"
      "<variable name=\"Z\"><type><derived name=\"TON\"/></type></variable>"
      "<variable name=\"C\"><type><derived name=\"CTU\"/></type></variable></localVars>";
  const std::string st =
      "IF clear THEN T(IN := FALSE, PT := T#0MS); ELSE T(IN := go, PT := T#5S); END_IF;\n"
      "done := T.Q;\nC(CU := go, RESET := clear, PV := 2);\nfull := C.Q;\n"
      "Z(IN := go);\nat_once := Z.Q;\ngoing := go;\ncleared := clear;\n";
  const auto file = write_temp(plcopen(st_pou("Codesys", interface, st)), ".xml");
  auto r =
      run_sfcv("check " + file +
               " --trace none --ctl 'AG (done -> going)' --ctl 'EF done'"
               " --ctl 'AG (cleared -> !full)' --ctl 'EF full' --ctl 'AG (at_once <-> going)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // Different PTs with IN not FALSE stay refused under discrete time.
  const std::string bad =
      "IF clear THEN T(IN := go, PT := T#1S); ELSE T(IN := go, PT := T#5S); END_IF; done := T.Q;";
  const auto bad_file = write_temp(plcopen(st_pou("Codesys", interface, bad)), ".xml");
  r = run_sfcv("check " + bad_file + " --time discrete --ctl 'EF done'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("different PT values"), std::string::npos) << r.err;
}

// An action of the POU called from its ST body runs at that point of the body.
TEST(Programs, ActionCalledFromSt) {
  const std::string pou =
      "<pou name=\"P\" pouType=\"program\"><interface>" + bool_vars("inputVars", {"a"}) +
      bool_vars("outputVars", {"x", "y"}) +
      "</interface><actions><action name=\"ACT_Copy\"><body><ST>"
      "<xhtml xmlns=\"http://www.w3.org/1999/xhtml\">x := a;</xhtml></ST></body></action></actions>"
      "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">ACT_Copy(); y := "
      "x;</xhtml></ST></body></pou>\n";
  const auto file = write_temp(plcopen(pou), ".xml");
  auto r = run_sfcv("check " + file + " --trace none --ctl 'AG (x <-> y)' --ctl 'EF x'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// TwinCAT FBs start SFC actions from ST (`ACT_Extend();`): one cycle of a chart per call is not
// modelled, and running such a POU is refused by name.
TEST(Programs, CallOfAnSfcActionIsRefused) {
  const std::string sfc =
      "<step localId=\"1\" name=\"S0\" "
      "initialStep=\"true\"><connectionPointIn/><connectionPointOut/></step>";
  const std::string pou = "<pou name=\"Cyl\" pouType=\"program\"><interface>" +
                          bool_vars("outputVars", {"x"}) +
                          "</interface><actions><action name=\"ACT_Extend\"><body><SFC>" + sfc +
                          "</SFC></body></action></actions>"
                          "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">ACT_Extend(); x "
                          ":= TRUE;</xhtml></ST></body></pou>\n";
  const auto file = write_temp(plcopen(pou), ".xml");
  const auto r = run_sfcv("check " + file + " --pou Cyl --ctl 'AG !x'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("call of action 'ACT_Extend'"), std::string::npos) << r.err;
}

// A program that keeps no state (TwinCAT sensor FBs whose outputs have types sfcv drops): one
// situation, not a crash.
TEST(Programs, ProgramWithoutStateHasOneSituation) {
  const auto file = write_temp(plcopen(st_pou("Probe", bool_vars("inputVars", {"a"}), "")), ".xml");
  const auto r = run_sfcv("check " + file + " --pou Probe --ctl 'AG TRUE' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 state,"), std::string::npos) << r.out;  // singular (issue 48)
}

}  // namespace
}  // namespace sfcv::test

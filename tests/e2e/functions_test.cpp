// User FUNCTIONs written in ST (issue 18): `sfcv check` on small IEC-text and PLCopen files
// written here whose programs call functions in bodies, actions and transition guards, with
// formal and positional arguments, a function calling a function and RETURN; what is not
// modelled (recursion, VAR_IN_OUT, a body in FBD) is refused with its location (exit 2).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// Permit is TRUE when the door is closed and the (capped) doubled level is below 8, i.e.
// level < 4: an open door RETURNs before the result is set, leaving its default FALSE.
const std::string kPumpText =
    "FUNCTION Cap : INT\n"
    "  VAR_INPUT x : INT; top : INT := 10; END_VAR\n"
    "  Cap := x;\n"
    "  IF x > top THEN Cap := top; END_IF;\n"
    "END_FUNCTION\n"
    "FUNCTION Permit : BOOL\n"
    "  VAR_INPUT level : INT; door : BOOL; END_VAR\n"
    "  VAR_TEMP doubled : INT; END_VAR\n"
    "  IF door THEN RETURN; END_IF;\n"
    "  doubled := Cap(x := level * 2);\n"
    "  Permit := doubled < 8;\n"
    "END_FUNCTION\n"
    "PROGRAM Main\n"
    "  VAR_INPUT level : INT(0..9); door : BOOL; END_VAR\n"
    "  VAR_OUTPUT pump, open, high : BOOL; END_VAR\n"
    "  pump := Permit(level, door);\n"
    "  open := door;\n"
    "  high := level >= 4;\n"
    "END_PROGRAM\n";

// The pump runs only with the door closed (RETURN) and a low level (Permit calls Cap); it does
// run (a model that lost the function's result would claim `AG !pump`).
TEST(FunctionsE2E, PropertiesHoldAndFailThroughAFunctionsResult) {
  const auto file = write_temp(kPumpText, ".st");
  for (const char* engine : {"explicit", "bdd", "ic3", "bmc"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check_command(file, engine, "--ctl 'AG !pump'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("violated"), std::string::npos) << r.out;
    if (std::string(engine) == "bmc") continue;  // BMC cannot prove
    r = run_sfcv(
        check_command(file, engine, "--ctl 'AG (pump -> !open)' --ctl 'AG (pump -> !high)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  }
}

// A function keeps nothing between calls: its VARs start from their initial values at every
// call (two calls in a cycle both give 6), and an unassigned result is its type's default.
TEST(FunctionsE2E, TemporariesStartFreshAtEveryCall) {
  const auto file = write_temp(
      "FUNCTION Next : INT\n  VAR n : INT := 5; END_VAR\n  n := n + 1;\n  Next := n;\n"
      "END_FUNCTION\n"
      "FUNCTION Never : BOOL\n  VAR_INPUT a : BOOL; END_VAR\n  IF a AND NOT a THEN Never := TRUE; "
      "END_IF;\nEND_FUNCTION\n"
      "PROGRAM Main\n  VAR_INPUT a : BOOL; END_VAR\n  VAR_OUTPUT y : INT; z : BOOL; END_VAR\n"
      "  y := Next() + Next();\n  z := Never(a);\nEND_PROGRAM\n",
      ".st");
  expect_on_every_engine(
      file, {{"--ctl 'AG (y = 0 | y = 12)' --ctl 'AG !z'", 0}, {"--ctl 'AG y = 0'", 1}});
}

// Recursion through a second function is refused at the call that closes the cycle.
TEST(FunctionsE2E, RecursionIsRefusedWithItsLocation) {
  const auto file = write_temp(
      "FUNCTION F : INT\n  VAR_INPUT x : INT; END_VAR\n  F := G(x) + 1;\nEND_FUNCTION\n"
      "FUNCTION G : INT\n  VAR_INPUT x : INT; END_VAR\n"
      "  IF x > 0 THEN G := F(x - 1); END_IF;\nEND_FUNCTION\n"
      "PROGRAM Main\n  VAR_INPUT a : BOOL; END_VAR\n  VAR_OUTPUT y : INT; END_VAR\n"
      "  y := F(BOOL_TO_INT(a));\nEND_PROGRAM\n",
      ".st");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    const auto r = run_sfcv(check_command(file, engine, "--ctl 'AG y >= 0'"));
    EXPECT_EQ(r.exit_code, 2) << engine << r.out << r.err;
    EXPECT_NE(r.err.find(":7:22: error: function 'F' calls itself (F -> G -> F): recursion"),
              std::string::npos)
        << r.err;
  }
  EXPECT_EQ(run_sfcv("lint " + file).exit_code, 2);
  // A chain of 40 functions, each calling the next, is deeper than the 32 calls modelled.
  std::string chain;
  for (int i = 0; i < 40; ++i)
    chain += "FUNCTION F" + std::to_string(i) + " : INT\n  VAR_INPUT x : INT; END_VAR\n  F" +
             std::to_string(i) +
             " := " + (i < 39 ? "F" + std::to_string(i + 1) + "(x) + 1" : std::string("x")) +
             ";\nEND_FUNCTION\n";
  const auto deep = write_temp(chain +
                                   "PROGRAM Main\n  VAR_INPUT a : BOOL; END_VAR\n"
                                   "  VAR_OUTPUT y : INT; END_VAR\n  y := F0(BOOL_TO_INT(a));\n"
                                   "END_PROGRAM\n",
                               ".st");
  const auto r = run_sfcv(check_command(deep, "explicit", "--ctl 'AG y >= 0'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("call of function 'F32' nested deeper than 32 function calls"),
            std::string::npos)
      << r.err;
}

// FB instances in a function, and calls that do not fit the declaration.
TEST(FunctionsE2E, UnmodelledFunctionsAndBadCallsAreLocatedErrors) {
  auto file = write_temp(
      "FUNCTION F : INT\n  VAR_INPUT x : INT; END_VAR\n  VAR_GLOBAL z : INT; END_VAR\n"
      "  VAR t : TON; END_VAR\n  F := x;\nEND_FUNCTION\n"
      "PROGRAM Main\n  VAR_INPUT a : BOOL; END_VAR\n  VAR_OUTPUT y : INT; END_VAR\n"
      "  y := F(BOOL_TO_INT(a));\nEND_PROGRAM\n",
      ".st");
  auto r = run_sfcv(check_command(file, "explicit", "--ctl 'AG y >= 0'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":3:14: error: VAR_GLOBAL 'z' of function F is not modelled"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(":4:7: error: function block instance 't' of function F"), std::string::npos)
      << r.err;
  file = write_temp(
      "FUNCTION F : INT\n  VAR_INPUT x : INT; END_VAR\n  F := x;\nEND_FUNCTION\n"
      "PROGRAM Main\n  VAR_OUTPUT y : INT; END_VAR\n"
      "  y := F(1, 2) + F(q := 1);\n  y := F(x := TRUE);\nEND_PROGRAM\n",
      ".st");
  r = run_sfcv(check_command(file, "explicit", "--ctl 'AG y >= 0'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":7:8: error: 'F(1, 2)': function F has 1 input(s), the call gives 2"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("function F has no input 'q'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(":8:15: error: 'F(x := TRUE)': input 'x' of function F has the wrong type"),
            std::string::npos)
      << r.err;
}

// ------------------------------------------------------------------------------- PLCopen XML

std::string function(const std::string& name, const std::string& result,
                     const std::string& interface, const std::string& body) {
  return "<pou name=\"" + name + "\" pouType=\"function\"><interface><returnType>" + result +
         "</returnType>" + interface + "</interface><body>" + body + "</body></pou>\n";
}

// Count2 counts its TRUE inputs; Both returns FALSE early unless x, else Count2(x, y) = 2.
std::string functions(const std::string& both_body =
                          plcopen_st("IF NOT x THEN RETURN; END_IF;\nBoth := Count2(x, y) = 2;")) {
  return function("Count2", "<INT/>", plcopen_vars("inputVars", {"a", "b"}),
                  plcopen_st("Count2 := BOOL_TO_INT(a) + BOOL_TO_INT(b);")) +
         function("Both", "<BOOL/>", plcopen_vars("inputVars", {"x", "y"}), both_body);
}

// A CODESYS-style program with an SFC body: Idle --guard--> Run --NOT s1--> Idle, the action
// ACT_Run (N on Run) setting `motor`, ACT_Idle (N on Idle) clearing it.
std::string main_sfc(const std::string& guard) {
  auto block = [](int id, int step, const char* action) {
    return "<actionBlock localId=\"" + std::to_string(id) +
           "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(step) +
           "\"/></connectionPointIn><action localId=\"" + std::to_string(id + 1) +
           "\" qualifier=\"N\"><reference name=\"" + action + "\"/></action></actionBlock>\n";
  };
  auto transition = [](int id, int from, const std::string& cond) {
    return "<transition localId=\"" + std::to_string(id) +
           "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
           "\"/></connectionPointIn><connectionPointOut/><condition><inline name=\"\">" +
           plcopen_st(cond) + "</inline></condition></transition>\n";
  };
  return "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"s1", "s2"}) + plcopen_vars("outputVars", {"motor"}) +
         "</interface><actions>"
         "<action name=\"ACT_Run\"><body>" +
         plcopen_st("motor := TRUE;") +
         "</body></action>"
         "<action name=\"ACT_Idle\"><body>" +
         plcopen_st("motor := FALSE;") +
         "</body></action></actions><body><SFC>\n"
         "<step localId=\"1\" name=\"Idle\" initialStep=\"true\"><connectionPointIn>"
         "<connection refLocalId=\"4\"/></connectionPointIn><connectionPointOut/></step>\n" +
         transition(3, 1, guard) +
         "<step localId=\"2\" name=\"Run\"><connectionPointIn><connection refLocalId=\"3\"/>"
         "</connectionPointIn><connectionPointOut/></step>\n" +
         transition(4, 2, "NOT s1") + block(10, 2, "ACT_Run") + block(12, 1, "ACT_Idle") +
         "</SFC></body></pou>\n";
}

// A transition guarded by a function's result: with y := s2 the chart reaches Run (only
// through the function: a model reading FALSE would claim `AG !Run`); with y := FALSE the
// count never reaches 2 and Run is unreachable.
TEST(FunctionsE2E, PlcopenFunctionGuardsATransition) {
  const auto reaches = write_temp(
      kPlcopenHeader + functions() + main_sfc("Both(x := s1, y := s2)") + kPlcopenFooter, ".xml");
  const auto never = write_temp(
      kPlcopenHeader + functions() + main_sfc("Both(y := FALSE, x := s1)") + kPlcopenFooter,
      ".xml");
  for (const char* engine : {"explicit", "bdd", "ic3", "bmc"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check_command(reaches, engine, "--ctl 'AG !Run'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    if (std::string(engine) == "bmc") continue;
    r = run_sfcv(check_command(never, engine, "--ctl 'AG !Run' --ctl 'AG !motor'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  }
}

// An FBD program calling a user function as a block (no instance name): the block's formal
// parameters are the call's, an unconnected input has its initial value, and a block whose
// result nobody reads is refused rather than dropped.
std::string fbd_main(const std::string& y_input, const std::string& motor_source) {
  return "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"s1", "s2"}) + plcopen_vars("outputVars", {"motor"}) +
         "</interface><body><FBD>"
         "<inVariable localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut/>"
         "<expression>s1</expression></inVariable>"
         "<inVariable localId=\"2\"><position x=\"0\" y=\"0\"/><connectionPointOut/>"
         "<expression>s2</expression></inVariable>"
         "<block localId=\"3\" typeName=\"Both\"><position x=\"0\" y=\"0\"/><inputVariables>"
         "<variable formalParameter=\"x\"><connectionPointIn><connection refLocalId=\"1\"/>"
         "</connectionPointIn></variable>"
         "<variable formalParameter=\"y\"><connectionPointIn>" +
         y_input +
         "</connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables>"
         "<variable formalParameter=\"Both\"><connectionPointOut/></variable></outputVariables>"
         "</block><outVariable localId=\"4\"><position x=\"0\" y=\"0\"/><connectionPointIn>" +
         motor_source + "</connectionPointIn><expression>motor</expression></outVariable>" +
         "</FBD></body></pou>\n";
}

TEST(FunctionsE2E, PlcopenFbdBlockCallsAFunction) {
  const std::string wired = "<connection refLocalId=\"2\"/>";
  const std::string result = "<connection refLocalId=\"3\" formalParameter=\"Both\"/>";
  const auto both =
      write_temp(kPlcopenHeader + functions() + fbd_main(wired, result) + kPlcopenFooter, ".xml");
  const auto open_y =
      write_temp(kPlcopenHeader + functions() + fbd_main("", result) + kPlcopenFooter, ".xml");
  expect_on_every_engine(both, {{"--ctl 'AG (motor -> s1 & s2)'", 0}, {"--ctl 'AG !motor'", 1}});
  expect_on_every_engine(open_y, {{"--ctl 'AG !motor'", 0}});  // y is FALSE: never 2
  const auto unused =
      write_temp(kPlcopenHeader + functions() + fbd_main(wired, "<connection refLocalId=\"1\"/>") +
                     kPlcopenFooter,
                 ".xml");
  // Its result read by nothing, Both still runs, as a statement (it could write globals).
  expect_on_every_engine(unused, {{"--ctl 'AG !motor'", 1}});
}

// Function bodies in FBD, LD and IL are read as statements, as programs' are (docs/semantics.md
// 1.9.2): Both := x AND y written in each gives the model of the ST body on every engine (Run
// is reached through Both(s1, s2), never through Both(s1, FALSE)). An edge contact in an LD
// function needs memory, which a function has not: refused where the function is called.
TEST(FunctionsE2E, PlcopenFunctionBodiesInFbdLdAndIlAreModelled) {
  const std::string in_vars =
      "<inVariable localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut/>"
      "<expression>x</expression></inVariable><inVariable localId=\"2\"><position x=\"0\" "
      "y=\"0\"/><connectionPointOut/><expression>y</expression></inVariable>";
  auto pin = [](const char* name, int from) {
    return std::string("<variable formalParameter=\"") + name +
           "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
           "\"/></connectionPointIn></variable>";
  };
  const std::string fbd =
      "<FBD>" + in_vars +
      "<block localId=\"3\" typeName=\"AND\"><position x=\"0\" y=\"0\"/><inputVariables>" +
      pin("IN1", 1) + pin("IN2", 2) +
      "</inputVariables><inOutVariables/><outputVariables><variable formalParameter=\"OUT\">"
      "<connectionPointOut/></variable></outputVariables></block><outVariable localId=\"4\">"
      "<position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"3\" "
      "formalParameter=\"OUT\"/></connectionPointIn><expression>Both</expression></outVariable>"
      "</FBD>";
  auto ld = [](const char* x_edge) {
    auto element = [](const std::string& kind, int id, int from, const std::string& var,
                      const std::string& extra) {
      return "<" + kind + " localId=\"" + std::to_string(id) + "\"" + extra +
             "><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"" +
             std::to_string(from) + "\"/></connectionPointIn><connectionPointOut/><variable>" +
             var + "</variable></" + kind + ">";
    };
    return "<LD><leftPowerRail localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut "
           "formalParameter=\"\"/></leftPowerRail>" +
           element("contact", 2, 1, "x", x_edge) + element("contact", 3, 2, "y", "") +
           element("coil", 4, 3, "Both", "") + "</LD>";
  };
  const std::string il =
      "<IL><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">LD x\nAND y\nST Both</xhtml></IL>";
  for (const auto& body : {plcopen_st("Both := x AND y;"), fbd, ld(""), il}) {
    SCOPED_TRACE(body);
    const auto reaches = write_temp(
        kPlcopenHeader + functions(body) + main_sfc("Both(s1, s2)") + kPlcopenFooter, ".xml");
    const auto never = write_temp(
        kPlcopenHeader + functions(body) + main_sfc("Both(s1, FALSE)") + kPlcopenFooter, ".xml");
    expect_on_every_engine(reaches, {{"--ctl 'AG !Run'", 1}, {"--ctl 'AG (Run -> s1)'", 0}});
    expect_on_every_engine(never, {{"--ctl 'AG !Run'", 0}});
  }
  const auto edge = write_temp(kPlcopenHeader + functions(ld(" edge=\"rising\"")) +
                                   main_sfc("Both(s1, s2)") + kPlcopenFooter,
                               ".xml");
  const auto r = run_sfcv(check_command(edge, "explicit", "--ctl 'AG !Run'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("of function Both: a function keeps no state between calls"),
            std::string::npos)
      << r.err;
}

// VAR_OUTPUTs of a function, bound with `=>` by the call that is the whole right side of an
// assignment (docs/semantics.md 1.9.1): the same model, on every engine, as the program with
// the function's code written out in place.
const std::string kSplit =
    "FUNCTION Split : BOOL\n"
    "  VAR_INPUT x : INT(0..7); END_VAR\n"
    "  VAR_OUTPUT lo : INT(0..3); hi : BOOL; END_VAR\n"
    "  lo := x MOD 4;\n"
    "  hi := x >= 4;\n"
    "  Split := x = 0;\n"
    "END_FUNCTION\n";

/// Each property line of a check's output, up to and with its verdict (the times dropped).
std::string verdict_lines(const std::string& out) {
  std::string kept;
  for (const char* v : {"holds", "violated"})
    for (auto at = out.find(v); at != std::string::npos; at = out.find(v, at + 1))
      kept += out.substr(out.rfind('\n', at) + 1, at - out.rfind('\n', at) - 1) + v + "\n";
  return kept;
}

/// `model` gives the `expected` verdict lines on the explicit, BDD and IC3 engines (exit 1).
void expect_verdicts_on_three_engines(const std::string& model, const std::string& props,
                                      const std::string& expected) {
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv(check_command(model, engine, props));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_EQ(verdict_lines(r.out), expected) << r.out;
  }
}

TEST(FunctionsE2E, OutputsBoundWithArrowsAgreeWithTheCodeInline) {
  const auto with_outputs = write_temp(kSplit +
                                           "PROGRAM Main\n"
                                           "  VAR_INPUT v : INT(0..7); END_VAR\n"
                                           "  VAR z : BOOL; l : INT(0..3); h : BOOL; END_VAR\n"
                                           "  z := Split(x := v, lo => l, hi => h);\n"
                                           "END_PROGRAM\n",
                                       ".st");
  const auto in_place = write_temp(
      "PROGRAM Main\n"
      "  VAR_INPUT v : INT(0..7); END_VAR\n"
      "  VAR z : BOOL; l : INT(0..3); h : BOOL; END_VAR\n"
      "  l := v MOD 4;\n  h := v >= 4;\n  z := v = 0;\n"
      "END_PROGRAM\n",
      ".st");
  const std::string props =
      "--ctl 'EF (l = 3 & h)' --ctl 'AG (z -> (l = 0 & !h))' --ctl 'AG (h -> l <= 2)'";
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto a = run_sfcv(check_command(with_outputs, engine, props));
    const auto b = run_sfcv(check_command(in_place, engine, props));
    EXPECT_EQ(a.exit_code, 1) << a.out << a.err;
    EXPECT_EQ(verdict_lines(a.out), verdict_lines(b.out)) << a.out << b.out;
    EXPECT_NE(verdict_lines(a.out).find("violated"), std::string::npos) << a.out;
  }
  // Printed back (IEC text, PLCopen) and reloaded, the bindings are still there.
  for (const char* to : {"iec", "plcopen"}) {
    const auto out = write_temp("", std::string(to) == "iec" ? ".st" : ".xml");
    ASSERT_EQ(run_sfcv("export " + with_outputs + " --to " + to + " -o " + out).exit_code, 0);
    const auto r = run_sfcv(check_command(out, "explicit", props));
    EXPECT_EQ(verdict_lines(r.out),
              verdict_lines(run_sfcv(check_command(in_place, "explicit", props)).out))
        << to << r.out << r.err;
  }
}

// `Split(x := v, lo => l, hi => h);` as a statement: the outputs are copied as in an
// assignment, the result is dropped; a call without outputs changes nothing.
TEST(FunctionsE2E, CalledAsAStatementItsOutputsAreCopiedAndItsResultDropped) {
  const auto as_statement = write_temp(kSplit +
                                           "PROGRAM Main\n"
                                           "  VAR_INPUT v : INT(0..7); END_VAR\n"
                                           "  VAR l : INT(0..3); h : BOOL; END_VAR\n"
                                           "  Split(x := v, lo => l, hi => h);\n"
                                           "  Split(x := 1);\n"
                                           "END_PROGRAM\n",
                                       ".st");
  const auto in_place = write_temp(
      "PROGRAM Main\n"
      "  VAR_INPUT v : INT(0..7); END_VAR\n"
      "  VAR l : INT(0..3); h : BOOL; END_VAR\n"
      "  l := v MOD 4;\n  h := v >= 4;\n"
      "END_PROGRAM\n",
      ".st");
  const std::string props =
      "--ctl 'EF (l = 3 & h)' --ctl 'AG (h -> l <= 2)' --ctl 'AG (l = 0 | l = 1 | l = 2 | l = 3)'";
  const auto expected = verdict_lines(run_sfcv(check_command(in_place, "explicit", props)).out);
  const auto bound = expected.find("AG (h -> l <= 2)");
  ASSERT_NE(bound, std::string::npos) << expected;
  EXPECT_EQ(expected.substr(expected.find_first_not_of(' ', bound + 16), 8), "violated")
      << expected;
  expect_verdicts_on_three_engines(as_statement, props, expected);
  // The state space is the same: the dropped results and the call without outputs add nothing.
  const auto a = run_sfcv(check_command(as_statement, "explicit", "--ctl 'AG TRUE'"));
  const auto b = run_sfcv(check_command(in_place, "explicit", "--ctl 'AG TRUE'"));
  EXPECT_EQ(a.out.substr(0, a.out.find(',')), b.out.substr(0, b.out.find(','))) << a.out << b.out;
  for (const char* to : {"iec", "plcopen"}) {
    const auto out = write_temp("", std::string(to) == "iec" ? ".st" : ".xml");
    ASSERT_EQ(run_sfcv("export " + as_statement + " --to " + to + " -o " + out).exit_code, 0);
    EXPECT_EQ(verdict_lines(run_sfcv(check_command(out, "explicit", props)).out), expected) << to;
  }
}

// A VAR_IN_OUT of a function is copied in and back around the body: the program agrees,
// state for state, with the same code written in place; every way the variable could be
// reached during the call otherwise is refused by name.
constexpr const char* kAdvance =
    "FUNCTION Advance : BOOL\n"
    "  VAR_INPUT limit : INT; END_VAR\n"
    "  VAR_IN_OUT n : INT(0..7); END_VAR\n"
    "  VAR_OUTPUT was : INT(0..7); END_VAR\n"
    "  VAR_EXTERNAL g : INT(0..7); END_VAR\n"
    "  was := n;\n"
    "  Advance := n < limit;\n"
    "  IF Advance THEN n := n + 1; END_IF;\n"
    "END_FUNCTION\n";

std::string advance_main(const std::string& vars, const std::string& body) {
  return std::string(kAdvance) +
         "PROGRAM Main\n  VAR_INPUT go : BOOL; END_VAR\n  VAR_EXTERNAL g : INT(0..7); END_VAR\n"
         "  VAR c, d, w : INT(0..7); more : BOOL; " +
         vars + "END_VAR\n" + body +
         "END_PROGRAM\n"
         "CONFIGURATION Cfg\n  VAR_GLOBAL g : INT(0..7); END_VAR\n"
         "  RESOURCE R ON PLC\n    TASK T(INTERVAL := T#10MS);\n"
         "    PROGRAM P WITH T : Main;\n  END_RESOURCE\nEND_CONFIGURATION\n";
}

TEST(FunctionsE2E, InOutOfAFunctionIsCopiedInAndBackAroundTheBody) {
  const auto by_reference =
      write_temp(advance_main("",
                              "  IF go THEN more := Advance(limit := 5, n := c); END_IF;\n"
                              "  Advance(limit := 3, n := d, was => w);\n"),
                 ".st");
  const auto in_place = write_temp(
      advance_main("",
                   "  IF go THEN more := c < 5; IF more THEN c := c + 1; END_IF; END_IF;\n"
                   "  w := d;\n  IF d < 3 THEN d := d + 1; END_IF;\n"),
      ".st");
  const std::string props =
      "--ctl 'AG c <= 5' --ctl 'AG c <= 4' --ctl 'AG d <= 3' --ctl 'AG w <= 2' "
      "--ctl 'EF (d = 3 & c = 5 & !more)' --ctl 'AG (more -> c >= 1)'";
  const auto reference = run_sfcv(check_command(in_place, "explicit", props));
  const auto expected = verdict_lines(reference.out);
  EXPECT_NE(expected.find("violated"), std::string::npos) << expected;
  expect_verdicts_on_three_engines(by_reference, props, expected);
  // The same reachable states: the function's fields return to their initial values.
  const auto all = run_sfcv(check_command(by_reference, "explicit", "--ctl 'AG TRUE'"));
  EXPECT_NE(all.out.find("17 states,"), std::string::npos) << all.out;
  EXPECT_NE(run_sfcv(check_command(in_place, "explicit", "--ctl 'AG TRUE'")).out.find("17 states,"),
            std::string::npos);
}

TEST(FunctionsE2E, InOutOfAFunctionRefusesEveryAlias) {
  auto error_of = [](const std::string& vars, const std::string& body) {
    const auto r = run_sfcv(
        check_command(write_temp(advance_main(vars, body), ".st"), "explicit", "--ctl 'AG TRUE'"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    return r.err;
  };
  const std::pair<const char*, const char*> cases[] = {
      {"  more := Advance(limit := 5);\n", "VAR_IN_OUT 'n' of function Advance is not bound"},
      {"  more := Advance(limit := 5, n := c + 1);\n", "bound to 'c + 1', which is no variable"},
      {"  more := NOT Advance(limit := 5, n := c);\n",
       "is bound only by a call that is the whole right side of an assignment or a statement"},
      {"  Advance(limit := 5, n := c, was => c);\n", "which an output of the call is bound to"},
      {"  Advance(limit := 5, n := g);\n", "a global variable that Advance names"},
      {"  Advance(limit := 5, n := go);\n", "of another type"},
  };
  for (const auto& [body, why] : cases) {
    SCOPED_TRACE(body);
    EXPECT_NE(error_of("", body).find(why), std::string::npos) << error_of("", body);
  }
  // A function that reads a program's variable by path could reach the bound variable.
  const auto by_path = run_sfcv(
      check_command(write_temp("FUNCTION Peek : BOOL\n  VAR_IN_OUT n : INT(0..7); END_VAR\n"
                               "  n := 1;\n  Peek := Main.c > 0;\nEND_FUNCTION\n"
                               "PROGRAM Main\n  VAR c : INT(0..7); p : BOOL; END_VAR\n"
                               "  p := Peek(n := c);\nEND_PROGRAM\n",
                               ".st"),
                    "explicit", "--ctl 'AG TRUE'"));
  EXPECT_EQ(by_path.exit_code, 2) << by_path.out << by_path.err;
  EXPECT_NE(by_path.err.find("Peek names variables of program Main"), std::string::npos)
      << by_path.err;
  // An INT function: its VAR_IN_OUT bound to the assignment's own target.
  const auto r = run_sfcv(check_command(
      write_temp("FUNCTION Inc : INT\n  VAR_IN_OUT n : INT(0..7); END_VAR\n"
                 "  IF n < 7 THEN n := n + 1; END_IF;\n  Inc := n;\nEND_FUNCTION\n"
                 "PROGRAM Main\n  VAR c : INT(0..7); END_VAR\n  c := Inc(n := c);\nEND_PROGRAM\n",
                 ".st"),
      "explicit", "--ctl 'AG TRUE'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("bound to 'c', which the assignment writes too"), std::string::npos)
      << r.err;
}

TEST(FunctionsE2E, FunctionOutputsAreWritesAndMisusesAreLocatedErrors) {
  auto error_of = [](const std::string& text) {
    const auto r = run_sfcv(check_command(write_temp(text, ".st"), "explicit", "--ctl 'EF h'"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    return r.err;
  };
  auto main = [](const std::string& body) {
    return kSplit +
           "PROGRAM Main\n  VAR_INPUT v : INT(0..7); END_VAR\n"
           "  VAR z : BOOL; l : INT(0..3); h : BOOL; END_VAR\n" +
           body + "END_PROGRAM\n";
  };
  EXPECT_NE(error_of(main("  z := Split(x := v, lo => l) OR TRUE;\n"))
                .find("the call must be the whole right side of the assignment"),
            std::string::npos);
  EXPECT_NE(error_of(main("  z := NOT Split(x := v, hi => h);\n"))
                .find("outputs are bound only by a call that is the whole right side"),
            std::string::npos);
  EXPECT_NE(
      error_of(main("  h := Split(x := v, hi => h);\n")).find("which the assignment writes too"),
      std::string::npos);
  EXPECT_NE(error_of(main("  z := Split(x := v, mid => l);\n"))
                .find("function Split has no VAR_OUTPUT 'mid'"),
            std::string::npos);
  EXPECT_NE(error_of(main("  Split(x := v, mid => l);\n"))
                .find(": error: 'Split(x := v)': function Split has no VAR_OUTPUT 'mid'"),
            std::string::npos);
  EXPECT_NE(error_of(main("  Split(y := v);\n")).find("function Split has no input 'y'"),
            std::string::npos);
  EXPECT_NE(error_of(main("  Split(v);\n")).find("positional arguments in the call of 'Split'"),
            std::string::npos);
  EXPECT_NE(error_of(main("  l := MAX(IN0 := v, lo => l);\n"))
                .find("only a call of a user FUNCTION binds outputs"),
            std::string::npos);
  // A duration that a function's output writes is no constant PT (docs/semantics.md 1.6).
  EXPECT_NE(
      error_of("FUNCTION Dur : BOOL\n  VAR_OUTPUT d : TIME; END_VAR\n  d := T#5S;\n"
               "  Dur := TRUE;\nEND_FUNCTION\n"
               "PROGRAM Main\n  VAR_INPUT go : BOOL; END_VAR\n  VAR_OUTPUT q : BOOL; END_VAR\n"
               "  VAR d : TIME := T#0MS; t : TON; ok : BOOL; END_VAR\n"
               "  ok := Dur(d => d);\n  t(IN := go, PT := d);\n  q := t.Q;\nEND_PROGRAM\n")
          .find("PT of 't' must be a constant"),
      std::string::npos);
}

}  // namespace
}  // namespace sfcv::test

// VAR_IN_OUT of user function block instances (issue 18, docs/semantics.md 1.3c): each call
// loads the parameter from the variable it binds and copies it back after the instance ran,
// which is the call by reference when nothing else reaches the variable during the call; every
// way something could (a global the block names, a program variable named by path, two
// parameters bound to one variable, the member read from outside, an action run from outside)
// is refused by name, never modelled as a copy that could differ from the reference.

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// Counts up to 5 in whatever variable the call binds, while `en`.
const std::string kInc = R"(FUNCTION_BLOCK Inc
  VAR_INPUT en : BOOL; END_VAR
  VAR_IN_OUT c : INT(0..5); END_VAR
  IF en AND c < 5 THEN c := c + 1; END_IF
END_FUNCTION_BLOCK
)";

const std::string kProperties =
    "--ctl 'EF a = 5' --ctl 'AG (a = 5 -> b = 5)' --ctl 'AG b <= 4' --ctl 'AG (a = 2 -> b >= 2)' "
    "--ctl 'EF (a = 0 & b = 5)'";

std::string check(const std::string& file, const std::string& engine) {
  return "check " + file + " --engine " + engine + " --checks none " + kProperties +
         " --trace none --timeout 60";
}

// `sfcv check`'s text without its closing provenance block (the "# " lines: version, command
// line, date, input digests), which names each run's own input file (issue 48).
std::string without_provenance(const std::string& out) {
  std::string kept;
  std::size_t at = 0;
  while (at < out.size()) {
    auto end = out.find('\n', at);
    end = end == std::string::npos ? out.size() : end + 1;
    if (out.compare(at, 2, "# ") != 0) kept.append(out, at, end - at);
    at = end;
  }
  return kept;
}

// The report without its timings.
std::string without_times(const std::string& out) {
  return std::regex_replace(without_provenance(out), std::regex("[0-9]+\\.[0-9]+s"), "");
}

// One instance called twice per cycle with two different variables: the same model, state for
// state and verdict for verdict, as the program with the block's code written out in place.
TEST(InOut, OneInstanceBindingTwoVariablesAgreesWithTheCodeInline) {
  const auto by_reference = write_temp(kInc + R"(PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR a : INT(0..5); b : INT(0..5); i : Inc; END_VAR
  i(en := go, c := a);
  i(en := TRUE, c := b);
END_PROGRAM
)",
                                       ".st");
  const auto inline_code = write_temp(R"(PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR a : INT(0..5); b : INT(0..5); END_VAR
  IF go AND a < 5 THEN a := a + 1; END_IF
  IF TRUE AND b < 5 THEN b := b + 1; END_IF
END_PROGRAM
)",
                                      ".st");
  const auto expected = run_sfcv(check(inline_code, "explicit"));
  ASSERT_EQ(expected.exit_code, 1) << expected.out << expected.err;
  EXPECT_NE(expected.out.find("21 states"), std::string::npos) << expected.out;
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv(check(by_reference, engine));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    const auto inline_r = run_sfcv(check(inline_code, engine));
    EXPECT_EQ(without_times(r.out), without_times(inline_r.out)) << r.out << inline_r.out;
  }
}

// The parameter copied back before the outputs: `q => x` after `io := x` leaves q in x, as the
// call by reference does (the block writes its parameter, then the output overwrites it).
TEST(InOut, AnOutputBoundToTheSameVariableIsCopiedLast) {
  const auto file = write_temp(R"(FUNCTION_BLOCK Both
  VAR_IN_OUT c : INT(0..5); END_VAR
  VAR_OUTPUT q : INT(0..5); END_VAR
  c := 4;
  q := 1;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR a : INT(0..5); i : Both; END_VAR
  i(c := a, q => a);
END_PROGRAM
)",
                               ".st");
  const auto r =
      run_sfcv("check " + file + " --checks none --ctl 'AG a <= 1' --ctl 'EF a = 1' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// A timer's PT bound to a VAR_IN_OUT is written by the call: never a constant (before, the
// write analyses did not see the copy back, and the initial T#0MS would be read as PT).
TEST(InOut, AVariableBoundToAnInOutIsWrittenByTheCall) {
  const auto file = write_temp(R"(FUNCTION_BLOCK Setter
  VAR_IN_OUT p : TIME; END_VAR
  p := T#5S;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; END_VAR
  VAR d : TIME := T#0MS; t : TON; s : Setter; END_VAR
  s(p := d);
  t(IN := go, PT := d);
  q := t.Q;
END_PROGRAM
)",
                               ".st");
  const auto r = run_sfcv("check " + file + " --checks none --ctl 'AG (go -> q)' --trace none");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("PT of 't' must be a constant"), std::string::npos) << r.err;
}

TEST(InOut, EveryPossibleAliasIsRefusedByName) {
  const std::string config = R"(CONFIGURATION Cfg
  VAR_GLOBAL g : INT(0..5); END_VAR
  RESOURCE Res ON PLC
    TASK Cyc(INTERVAL := T#10MS, PRIORITY := 1);
    PROGRAM P WITH Cyc : Main;
  END_RESOURCE
END_CONFIGURATION
)";
  const std::string inc_with_action = R"(FUNCTION_BLOCK Inc
  VAR_INPUT en : BOOL; END_VAR
  VAR_IN_OUT c : INT(0..5); END_VAR
  INITIAL_STEP S0: Bump; END_STEP
  ACTION Bump: IF en AND c < 5 THEN c := c + 1; END_IF END_ACTION
  ACTION Clear: c := 0; END_ACTION
END_FUNCTION_BLOCK
)";
  // `global`: Main declares the global g of `config`.
  auto main = [](const std::string& body, bool global = false) {
    return std::string("PROGRAM Main\n  VAR_INPUT go : BOOL; END_VAR\n") +
           (global ? "  VAR_EXTERNAL g : INT(0..5); END_VAR\n" : "") +
           "  VAR a : INT(0..5); i : Inc; END_VAR\n" + body + "END_PROGRAM\n";
  };
  struct Case {
    std::string text, error;
  };
  const std::vector<Case> cases = {
      {kInc + main("  i(en := go);\n"), "does not bind its VAR_IN_OUT 'c'"},
      {kInc + main("  i(en := go, c := a + 1);\n"), "which is no variable"},
      {kInc + main("  i(en := go, c := a);\n  a := i.c;\n"), "'i.c' is a VAR_IN_OUT of Inc"},
      {kInc + main("  i(en := go, c := i.c);\n"), "'i.c' is a VAR_IN_OUT of Inc"},
      {inc_with_action + main("  i(en := go, c := a);\n  i.Clear();\n"),
       "actions of such instances"},
      {R"(FUNCTION_BLOCK Inc
  VAR_IN_OUT c : INT(0..5); END_VAR
  VAR_EXTERNAL g : INT(0..5); END_VAR
  IF c < 5 THEN c := c + 1; END_IF
  g := 0;
END_FUNCTION_BLOCK
)" + main("  i(c := g);\n", true) +
           config,
       "a global variable that Inc names"},
      {R"(FUNCTION_BLOCK Inc
  VAR_IN_OUT c : INT(0..5); END_VAR
  IF c < 5 THEN c := c + 1; END_IF
  Main.a := 0;
END_FUNCTION_BLOCK
)" + main("  i(c := a);\n"),
       "Inc names variables of program Main"},
      {R"(FUNCTION_BLOCK Inc
  VAR_IN_OUT c : INT(0..5); d : INT(0..5); END_VAR
  c := 1;
  d := 0;
END_FUNCTION_BLOCK
)" + main("  i(c := a, d := a);\n"),
       "which another VAR_IN_OUT of the call binds"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const auto file = write_temp(c.text, ".st");
    const auto r = run_sfcv("check " + file + " --checks none --ctl 'EF a = 5' --trace none");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(c.error), std::string::npos) << r.err;
    // lint names the same reason.
    const auto lint = run_sfcv("lint " + file);
    EXPECT_NE((lint.out + lint.err).find(c.error), std::string::npos) << lint.out << lint.err;
  }
  // A global that the block does not name may be bound: nothing else reaches it in the call.
  const auto file = write_temp(kInc + main("  i(en := go, c := g);\n", true) + config, ".st");
  const auto r = run_sfcv("check " + file + " --checks none --ctl 'EF g = 5' --trace none");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// An FBD block of a user function block with a VAR_IN_OUT pin (PLCopen `inOutVariables`, as
// Beremiz and CODESYS export it): the variable wired to the pin is bound, and the pin's output
// side reads that variable after the call. Same model as the ST call `i(up := go, c := a);
// b := a;` on every engine; a pin wired to an expression or left open is a located error.
std::string inc_fbd(const std::string& c_source, const std::string& b_source,
                    const std::string& a_expression = "a") {
  const auto local = [](const std::string& id, const std::string& name) {
    return "<inVariable localId=\"" + id +
           "\"><position x=\"0\" y=\"0\"/><connectionPointOut/>"
           "<expression>" +
           name + "</expression></inVariable>";
  };
  return kPlcopenHeader + "<pou name=\"Inc\" pouType=\"functionBlock\"><interface>" +
         plcopen_vars("inputVars", {"up"}) + plcopen_vars("inOutVars", {"c"}, "<INT/>") +
         "</interface><body>" + plcopen_st("IF up AND c &lt; 5 THEN c := c + 1; END_IF;") +
         "</body></pou>\n"
         "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"go"}) + plcopen_vars("localVars", {"a", "b"}, "<INT/>") +
         plcopen_vars("localVars", {"i"}, "<derived name=\"Inc\"/>") + "</interface><body><FBD>" +
         local("1", "go") + local("2", a_expression) +
         "<block localId=\"3\" typeName=\"Inc\" instanceName=\"i\"><position x=\"0\" y=\"0\"/>"
         "<inputVariables><variable formalParameter=\"up\"><connectionPointIn>"
         "<connection refLocalId=\"1\"/></connectionPointIn></variable></inputVariables>"
         "<inOutVariables><variable formalParameter=\"c\"><connectionPointIn>" +
         c_source +
         "</connectionPointIn><connectionPointOut/></variable></inOutVariables>"
         "<outputVariables/></block>"
         "<outVariable localId=\"4\"><position x=\"0\" y=\"0\"/><connectionPointIn>" +
         b_source + "</connectionPointIn><expression>b</expression></outVariable>" +
         "</FBD></body></pou>\n" + kPlcopenFooter;
}

// The FBD file and its ST twin give the same report (some property violated) on every engine.
void expect_same_reports(const std::string& fbd, const std::string& st, const std::string& props) {
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto a = run_sfcv("check " + fbd + " --engine " + engine + " --checks none " + props +
                            " --trace none");
    const auto b = run_sfcv("check " + st + " --engine " + engine + " --checks none " + props +
                            " --trace none");
    EXPECT_EQ(a.exit_code, 1) << a.out << a.err;
    EXPECT_EQ(without_times(a.out), without_times(b.out)) << a.out << b.out;
  }
}

TEST(InOut, FbdBlockPinBindsTheWiredVariable) {
  const std::string pin_out = "<connection refLocalId=\"3\" formalParameter=\"c\"/>";
  const auto fbd = write_temp(inc_fbd("<connection refLocalId=\"2\"/>", pin_out), ".xml");
  const auto st = write_temp(R"(FUNCTION_BLOCK Inc
  VAR_INPUT up : BOOL; END_VAR
  VAR_IN_OUT c : INT; END_VAR
  IF up AND c < 5 THEN c := c + 1; END_IF;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR a : INT; b : INT; i : Inc; END_VAR
  i(up := go, c := a);
  b := a;
END_PROGRAM
)",
                             ".st");
  const std::string props =
      "--ctl 'EF b = 5' --ctl 'AG (a = 5 -> b = 5)' --ctl 'AG b <= 4' --ctl 'AG (b = 2 -> a = 2)'";
  const auto expected =
      run_sfcv("check " + st + " --engine explicit --checks none " + props + " --trace none");
  ASSERT_EQ(expected.exit_code, 1) << expected.out << expected.err;
  EXPECT_NE(expected.out.find("11 states"), std::string::npos) << expected.out;
  expect_same_reports(fbd, st, props);
  // Left open, or wired to an expression: refused where the pin is.
  auto error_of = [&](const std::string& source, const std::string& a_expression) {
    const auto file = write_temp(inc_fbd(source, pin_out, a_expression), ".xml");
    const auto r = run_sfcv("check " + file + " --engine explicit --checks none --ctl 'AG TRUE'");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    return r.err;
  };
  EXPECT_NE(error_of("", "a").find("in/out parameter c of block Inc is not connected"),
            std::string::npos);
  EXPECT_NE(error_of("<connection refLocalId=\"2\"/>", "a + 1")
                .find("in/out parameter c of block Inc is wired to 'a + 1', which is no variable"),
            std::string::npos);
}

// An FBD block of a user FUNCTION with a VAR_IN_OUT pin, its result read by nothing: the
// function runs as the statement `Bump(up := go, c := a);`, and the pin's output side reads a
// after it, as in ST (docs/semantics.md 1.9.1). Reading the result as well is refused.
std::string bump_fbd(bool read_result) {
  const auto local = [](const std::string& id, const std::string& name) {
    return "<inVariable localId=\"" + id +
           "\"><position x=\"0\" y=\"0\"/><connectionPointOut/><expression>" + name +
           "</expression></inVariable>";
  };
  const auto out = [](const std::string& id, const std::string& source, const std::string& var) {
    return "<outVariable localId=\"" + id + "\"><position x=\"0\" y=\"0\"/><connectionPointIn>" +
           source + "</connectionPointIn><expression>" + var + "</expression></outVariable>";
  };
  return kPlcopenHeader +
         "<pou name=\"Bump\" pouType=\"function\"><interface><returnType><BOOL/></returnType>" +
         plcopen_vars("inputVars", {"up"}) + plcopen_vars("inOutVars", {"c"}, "<INT/>") +
         "</interface><body>" +
         plcopen_st("IF up AND c &lt; 5 THEN c := c + 1; END_IF; Bump := c = 5;") +
         "</body></pou>\n<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"go"}) + plcopen_vars("localVars", {"a", "b"}, "<INT/>") +
         plcopen_vars("localVars", {"full"}) + "</interface><body><FBD>" + local("1", "go") +
         local("2", "a") +
         "<block localId=\"3\" typeName=\"Bump\"><position x=\"0\" y=\"0\"/>"
         "<inputVariables><variable formalParameter=\"up\"><connectionPointIn>"
         "<connection refLocalId=\"1\"/></connectionPointIn></variable></inputVariables>"
         "<inOutVariables><variable formalParameter=\"c\"><connectionPointIn>"
         "<connection refLocalId=\"2\"/></connectionPointIn><connectionPointOut/></variable>"
         "</inOutVariables><outputVariables><variable formalParameter=\"Bump\">"
         "<connectionPointOut/></variable></outputVariables></block>" +
         out("4", "<connection refLocalId=\"3\" formalParameter=\"c\"/>", "b") +
         (read_result ? out("5", "<connection refLocalId=\"3\" formalParameter=\"Bump\"/>", "full")
                      : "") +
         "</FBD></body></pou>\n" + kPlcopenFooter;
}

TEST(InOut, FbdFunctionBlockWithAnInOutPinRunsAsAStatement) {
  const auto fbd = write_temp(bump_fbd(false), ".xml");
  const auto st = write_temp(R"(FUNCTION Bump : BOOL
  VAR_INPUT up : BOOL; END_VAR
  VAR_IN_OUT c : INT; END_VAR
  IF up AND c < 5 THEN c := c + 1; END_IF; Bump := c = 5;
END_FUNCTION
PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR a : INT; b : INT; full : BOOL; END_VAR
  Bump(up := go, c := a);
  b := a;
END_PROGRAM
)",
                             ".st");
  const std::string props = "--ctl 'EF b = 5' --ctl 'AG (a = 5 -> b = 5)' --ctl 'AG b <= 4'";
  expect_same_reports(fbd, st, props);
  const auto both =
      run_sfcv("check " + write_temp(bump_fbd(true), ".xml") + " --checks none --ctl 'AG TRUE'");
  EXPECT_EQ(both.exit_code, 2) << both.out << both.err;
  EXPECT_NE(both.err.find("unsupported: function Bump with both its result and an in/out "
                          "parameter read"),
            std::string::npos)
      << both.err;
}

}  // namespace
}  // namespace sfcv::test

// User data types (issue 18): enumerations, STRUCTs and ARRAYs, lowered by the readers to one
// variable per element (docs/semantics.md 1.8). Every engine gives the same verdicts; initial
// values, CASE labels written as enumerators, variable indices (an index out of bounds is a
// range error) and the PLCopen <dataTypes> of CODESYS/TwinCAT exports are each pinned.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kTypes =
    "TYPE\n"
    "  E_State : (Idle, Filling := 5, Draining) := Idle;\n"
    "  Valve : STRUCT\n"
    "    open : BOOL;\n"
    "    count : INT(0..3) := 1;\n"
    "  END_STRUCT;\n"
    "END_TYPE\n";

// A tank: Idle -> Filling (on go) -> Draining (once levels[3]) -> Idle. In Filling, the level
// chosen by the input k is set; valves[2] follows levels[3]. `err` is valves[2] open in Idle.
const std::string kTank = kTypes +
                          "PROGRAM Tank\n"
                          "VAR_INPUT go : BOOL; k : INT(0..3); END_VAR\n"
                          "VAR\n"
                          "  state : E_State;\n"
                          "  v : Valve;\n"
                          "  levels : ARRAY[0..3] OF BOOL := [TRUE, 3(FALSE)];\n"
                          "  valves : ARRAY[1..2] OF Valve;\n"
                          "  err : BOOL;\n"
                          "END_VAR\n"
                          "CASE state OF\n"
                          "  Idle: IF go THEN state := E_State#Filling; END_IF;\n"
                          "  Filling: levels[k] := TRUE; v.open := TRUE;\n"
                          "    valves[2].open := levels[3];\n"
                          "    IF levels[3] THEN state := Draining; END_IF;\n"
                          "  E_State.Draining: v.open := FALSE; state := Idle;\n"
                          "END_CASE;\n"
                          "err := valves[2].open AND state = Idle;\n"
                          "END_PROGRAM\n";

std::string check(const std::string& file, const std::string& engine, const std::string& what) {
  return "check " + file + " --engine " + engine + " " + what + " --timeout 60";
}

// Holds only if the enumerators have their declared values (Idle 0, Filling 5, Draining 6),
// the array initialiser and the structure's field default are read, and the fields of the two
// valves are distinct variables. Violated only if an indexed write reaches levels[3] and the
// element valves[2].open.
TEST(DataTypes, EnumerationsStructuresAndArraysAgreeOnEveryEngine) {
  const auto file = write_temp(kTank, ".st");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv(check(file, engine,
                            "--checks none --ctl 'AG (state = 0 | state = 5 | state = 6)' "
                            "--ctl 'AG levels[0]' --ctl 'AG (v.count = 1 & valves[1].count = 1)' "
                            "--ctl 'AG !valves[1].open'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    r = run_sfcv(check(file, engine, "--checks none --ctl 'AG !valves[2].open'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    r = run_sfcv(check(file, engine, "--checks none --ctl 'AG !err'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    // Shortest: go, then k = 3 in Filling sets levels[3] and valves[2].open in the same cycle.
    EXPECT_NE(r.out.find("counterexample (4 situations)"), std::string::npos) << r.out;
  }
  // The range of an enumeration variable is its enumerators': Filling is 5, never 1.
  auto r = run_sfcv(check(file, "explicit", "--checks none --ctl 'EF state = 5'"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // Properties may name the enumerators; an unknown one is a located error.
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    r = run_sfcv(check(file, engine,
                       "--checks none --ctl 'AG (state = Idle | state = Filling | "
                       "state = Draining)' --ctl 'AG (state != Filling | !valves[1].open)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    r = run_sfcv(check(file, engine, "--checks none --ctl 'AG (state = Draining -> !v.open)'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    // The trace names the enumerators too.
    EXPECT_NE(r.out.find("state=Draining"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("state=6"), std::string::npos) << r.out;
  }
  r = run_sfcv(check(file, "explicit", "--checks none --ctl 'AG state != Blue'"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(":1:4: error: 'Blue' is no enumerator of 'state' (E_State)"),
            std::string::npos)
      << r.err;
  // CODESYS's ARRAY OF ARRAY: m[1][2] and m[1,2] are one element.
  const auto matrix = write_temp(
      "PROGRAM P\nVAR_INPUT go : BOOL; END_VAR\n"
      "VAR m : ARRAY[1..2] OF ARRAY[1..2] OF BOOL; END_VAR\n"
      "IF go THEN m[1][2] := TRUE; END_IF;\nm[2,1] := m[1,2];\nEND_PROGRAM\n",
      ".st");
  r = run_sfcv(
      check(matrix, "explicit", "--checks none --ctl 'AG (m[2,1] -> m[1,2])' --ctl 'AG !m[1,1]'"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv(check(matrix, "explicit", "--checks none --ctl 'AG !m[2,1]'"));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

// `a[k]` with k outside the bounds stops the cycle with a range error (instability), read and
// written alike; inside them, no range error.
TEST(DataTypes, AVariableIndexOutOfBoundsIsARangeError) {
  const std::string head =
      "PROGRAM P\nVAR_INPUT k : INT(0..3); END_VAR\nVAR a : ARRAY[1..3] OF INT; x : INT; END_VAR\n";
  const std::string read = write_temp(head + "x := a[k];\nEND_PROGRAM\n", ".st");
  const std::string write = write_temp(head + "a[k] := 2;\nEND_PROGRAM\n", ".st");
  const std::string inside = write_temp(
      "PROGRAM P\nVAR_INPUT k : INT(1..3); END_VAR\nVAR a : ARRAY[1..3] OF INT; END_VAR\n"
      "a[k] := a[k] + 1;\nIF a[k] > 2 THEN a[k] := 0; END_IF;\nEND_PROGRAM\n",
      ".st");
  for (const char* engine : {"explicit", "bdd"}) {
    SCOPED_TRACE(engine);
    // The array is a table of constants here (nothing writes it in `read`): --unwritten keep
    // (docs/semantics.md 1.8; free, its INT elements would be enumerated).
    for (const auto& file : {read, write}) {
      const auto r = run_sfcv(check(file, engine, "--checks instability --unwritten keep"));
      EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    }
    const auto r = run_sfcv(check(inside, engine, "--checks instability"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  // Each element counts on its own: a[1] reaches 2 while a[2] stays 0.
  const auto r =
      run_sfcv(check(inside, "explicit", "--checks none --ctl 'EF (a[1] = 2 & a[2] = 0)'"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// STRINGs are compared and assigned: each literal is a code, and each STRING input may also be
// a string no literal spells, so two inputs can differ from every literal and from each other.
TEST(DataTypes, StringsAreComparedAndAssigned) {
  const auto file = write_temp(
      "PROGRAM P\n"
      "VAR_INPUT cmd : STRING; other : STRING(20); END_VAR\n"
      "VAR mode : STRING := 'idle'; last : STRING; run, same, odd : BOOL; END_VAR\n"
      "IF cmd = 'start' THEN mode := 'running'; ELSIF cmd = 'stop' THEN mode := 'idle'; END_IF;\n"
      "last := cmd;\n"
      "same := last = other;\n"
      "odd := last <> other AND last <> 'start' AND last <> 'stop' AND other <> 'start'\n"
      "  AND other <> 'stop' AND last <> '' AND other <> '' AND last <> 'idle'\n"
      "  AND other <> 'idle' AND last <> 'running' AND other <> 'running';\n"
      "run := mode <> 'idle';\n"
      "END_PROGRAM\n",
      ".st");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    // Literals in sorted order: '' 0, 'idle' 1, 'running' 2, 'start' 3, 'stop' 4.
    auto r = run_sfcv(check(file, engine,
                            "--checks none --ctl 'AG (mode = 1 | mode = 2)' "
                            "--ctl 'AG (run <-> mode = 2)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    for (const char* reached : {"run", "same", "odd"}) {
      r = run_sfcv(check(file, engine, std::string("--checks none --ctl 'AG !") + reached + "'"));
      EXPECT_EQ(r.exit_code, 1) << reached << r.out << r.err;
    }
  }
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"i := s;", ":3:1: error: assignment of a STRING to 'i'"},
           {"s := 1;", ":3:1: error: assignment of a value that is no STRING to 's', a STRING"},
           {"b := s < 'a';", ":3:6: error: unsupported: 's < 'a'' uses a STRING"},
           {"b := s = 1;", ":3:8: error: comparison of a STRING with a value that is not one"}}) {
    const auto bad = write_temp(
        "PROGRAM P\nVAR s : STRING; i : INT; b : BOOL; END_VAR\n" + text + "\nEND_PROGRAM\n",
        ".st");
    const auto r = run_sfcv("check " + bad + " --checks none");
    EXPECT_EQ(r.exit_code, 2) << text << r.out << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
}

// A CODESYS/TwinCAT-like export: <dataTypes> with an enumeration and a structure, an <array>
// variable with an <arrayValue>, a <structValue> initial value.
const std::string kPlcopen = R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="test" productName="test" productVersion="1" creationDateTime="2026-12-03T00:00:00"/>
  <contentHeader name="types"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types>
    <dataTypes>
      <dataType name="E_Mode">
        <baseType><enum><values><value name="Off"/><value name="Auto" value="3"/><value name="Manual"/></values></enum></baseType>
      </dataType>
      <dataType name="Axis">
        <baseType><struct>
          <variable name="pos"><type><INT/></type><initialValue><simpleValue value="2"/></initialValue></variable>
          <variable name="busy"><type><BOOL/></type></variable>
        </struct></baseType>
      </dataType>
    </dataTypes>
    <pous>
      <pou name="Main" pouType="program">
        <interface>
          <inputVars><variable name="sel"><type><INT/></type></variable></inputVars>
          <localVars>
            <variable name="mode"><type><derived name="E_Mode"/></type><initialValue><simpleValue value="E_Mode.Manual"/></initialValue></variable>
            <variable name="ax"><type><derived name="Axis"/></type><initialValue><structValue><value member="busy"><simpleValue value="TRUE"/></value></structValue></initialValue></variable>
            <variable name="tab"><type><array><dimension lower="1" upper="3"/><baseType><INT/></baseType></array></type>
              <initialValue><arrayValue><value repetitionValue="2"><simpleValue value="7"/></value><value><simpleValue value="9"/></value></arrayValue></initialValue></variable>
          </localVars>
        </interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">IF mode = Manual AND sel &gt;= 1 AND sel &lt;= 3 THEN ax.pos := tab[sel]; END_IF;</xhtml></ST></body>
      </pou>
    </pous>
  </types>
  <instances><configurations/></instances>
</project>
)";

TEST(DataTypes, PlcopenDataTypesAndStructuredInitialValues) {
  const auto file = write_temp(kPlcopen, ".xml");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    // mode starts Manual (4), ax.busy TRUE, tab = [7, 7, 9]: pos takes 2, 7 or 9 only. The test
    // is about initial values, which nothing writes: --unwritten keep (docs/semantics.md 1.8).
    auto r = run_sfcv(check(file, engine,
                            "--checks none --unwritten keep --ctl 'AG (mode = 4 & ax.busy)' "
                            "--ctl 'AG (ax.pos = 2 | ax.pos = 7 | ax.pos = 9)'"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    r = run_sfcv(check(file, engine, "--checks none --unwritten keep --ctl 'AG ax.pos != 9'"));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  }
}

// Each mistake is an error at its place (exit 2), never a model with a gap.
TEST(DataTypes, MistakesAreLocatedErrors) {
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {"PROGRAM P\nVAR a : ARRAY[1..3] OF BOOL; END_VAR\na[4] := TRUE;\nEND_PROGRAM\n",
       ":3:1: error: 'a[4]' is no element of a declared array or structure"},
      {"PROGRAM P\nVAR a : ARRAY[1..3] OF BOOL; x : BOOL; END_VAR\nx := a[0];\nEND_PROGRAM\n",
       ":3:6: error: 'a[0]' is no element"},
      {"PROGRAM P\nVAR_INPUT i : INT; END_VAR\nVAR a : ARRAY[1..3] OF BOOL; x : BOOL; END_VAR\n"
       "x := a[i, i];\nEND_PROGRAM\n",
       ":4:6: error: array 'a' has 1 dimension(s), indexed with 2"},
      {"PROGRAM P\nVAR a : ARRAY[1..300000] OF BOOL; END_VAR\nEND_PROGRAM\n",
       ":2:5: error: array 'a' has more than 100000 elements"},
      {"TYPE S : STRUCT x : BOOL; END_STRUCT; END_TYPE\nPROGRAM P\nVAR s : S := (y := TRUE); "
       "END_VAR\nEND_PROGRAM\n",
       "error: 'y' is no field of S"},
      {"TYPE S : STRUCT next : S; END_STRUCT; END_TYPE\nPROGRAM P\nVAR s : S; END_VAR\n"
       "END_PROGRAM\n",
       "contains itself"},
      {"TYPE A : (Red, Green); B : (Green, Red); END_TYPE\nPROGRAM P\nVAR x : A; END_VAR\n"
       "x := Red;\nEND_PROGRAM\n",
       ":4:6: error: enumerator 'Red' has different values in several types: write Type#Red"},
      {"TYPE A : (Red, Green); END_TYPE\nPROGRAM P\nVAR x : A; END_VAR\n"
       "CASE x OF Blue: x := Red; END_CASE;\nEND_PROGRAM\n",
       "error: CASE label 'Blue' is no enumerator"},
      // FB call arguments and output bindings follow the rule of assignments.
      {"FUNCTION_BLOCK F\nVAR_INPUT n : INT; END_VAR\nVAR_OUTPUT s : STRING; END_VAR\n"
       "END_FUNCTION_BLOCK\nPROGRAM P\nVAR f : F; END_VAR\nf(n := 'x');\nEND_PROGRAM\n",
       ":7:8: error: assignment of a STRING to 'f.n'"},
      {"FUNCTION_BLOCK F\nVAR_INPUT t : STRING; END_VAR\nEND_FUNCTION_BLOCK\n"
       "PROGRAM P\nVAR f : F; k : INT; END_VAR\nf(t := k);\nEND_PROGRAM\n",
       "error: assignment of a value that is no STRING to 'f.t', a STRING"},
      {"FUNCTION_BLOCK F\nVAR_OUTPUT s : STRING; END_VAR\nEND_FUNCTION_BLOCK\n"
       "PROGRAM P\nVAR f : F; k : INT; END_VAR\nf(s => k);\nEND_PROGRAM\n",
       "error: assignment of a STRING to 'k'"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const auto file = write_temp(c.text, ".st");
    const auto r = run_sfcv("check " + file + " --checks none");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  // Printing cannot give the declarations back: a clear refusal, not a different program.
  const auto r = run_sfcv("export --to iec " + write_temp(kTank, ".st"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("user data types"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sfcv::test

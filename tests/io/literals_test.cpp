// Numeric literals in every reader (issue 53 item 5, docs/semantics.md 1.7): one past the range
// of the type is a located error, the limits themselves are accepted, and the most negative
// value is a literal. One small inline file per reader.

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "io/load.hpp"
#include "model/chart.hpp"
#include "support/plcopen_text.hpp"

namespace sfcv::io {
namespace {

constexpr auto kMin = std::numeric_limits<std::int64_t>::min();
constexpr auto kMax = std::numeric_limits<std::int64_t>::max();

/// Every error of `r`, one per line, as "line:column: message" (with the element path when
/// the reader gives one).
std::string errors_of(const LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Error) s += d.str() + "\n";
  return s;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ---------------------------------------------------------------------------- IEC text, ST

LoadResult iec(const std::string& vars, const std::string& condition = "TRUE",
               const std::string& action = "") {
  return load_iec_text("PROGRAM p\n  VAR a : BOOL; " + vars +
                           " END_VAR\n"
                           "  INITIAL_STEP s0: " +
                           action +
                           " END_STEP\n  STEP s1: END_STEP\n"
                           "  ACTION act: a := TRUE; END_ACTION\n"
                           "  TRANSITION FROM s0 TO s1 := " +
                           condition +
                           "; END_TRANSITION\n"
                           "  TRANSITION FROM s1 TO s0 := NOT a; END_TRANSITION\nEND_PROGRAM\n",
                       "lit.st");
}

TEST(LiteralsIecText, LimitsOfEachTypeAreAccepted) {
  const auto r =
      iec("i : INT := -32768; j : INT := 32767; k : INT := INT#-32768; u : UINT := 65535; "
          "l : LINT := -9223372036854775808; m : LINT := 9223372036854775807; "
          "t : TIME := T#24d20h31m23s647ms;",
          "l < -9223372036854775807 AND m = 9223372036854775807 AND k = INT#-32768 AND "
          "m > LINT#-9223372036854775808",
          "act(L, T#24d20h31m23s647ms);");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& p = r.project->pous.at(0);
  EXPECT_EQ(p.find_variable("i")->initial, -32768);
  EXPECT_EQ(p.find_variable("l")->initial, kMin);
  EXPECT_EQ(p.find_variable("m")->initial, kMax);
  EXPECT_EQ(p.find_variable("t")->initial, 2147483647);
  EXPECT_EQ(p.associations.at(0).duration_ms, 2147483647);
}

TEST(LiteralsIecText, OnePastTheRangeIsALocatedError) {
  EXPECT_EQ(errors_of(iec("n : INT := 40000;")),
            "lit.st:2:28: error: initial value 40000 is outside INT (-32768..32767)\n");
  EXPECT_EQ(errors_of(iec("n : LINT;", "n = 9223372036854775808")),
            "lit.st:6:35: error: integer literal 9223372036854775808 is outside LINT "
            "(-9223372036854775808..9223372036854775807)\n");
  EXPECT_EQ(errors_of(iec("n : LINT;", "n = -9223372036854775809")),
            "lit.st:6:36: error: integer literal 9223372036854775809 is outside LINT "
            "(-9223372036854775808..9223372036854775807)\n");
  EXPECT_EQ(errors_of(iec("n : INT;", "n = INT#32768")),
            "lit.st:6:35: error: INT#32768 is outside INT (-32768..32767)\n");
  EXPECT_EQ(errors_of(iec("", "TRUE", "act(L, T#9223372036854775807ms);")),
            "lit.st:3:27: error: TIME literal T#9223372036854775807ms is outside TIME "
            "(T#0ms..T#24d20h31m23s647ms)\n");
  EXPECT_EQ(errors_of(iec("t : TIME := T#24d20h31m23s648ms;")),
            "lit.st:2:29: error: TIME literal T#24d20h31m23s648ms is outside TIME "
            "(T#0ms..T#24d20h31m23s647ms)\n");
}

// -------------------------------------------------------------------------------- PLCopen XML

std::string xml(const std::string& vars, const std::string& duration,
                const std::string& priority = "") {
  return test::kPlcopenHeader +
         "<pou name=\"P\" pouType=\"program\"><interface>"
         "<inputVars><variable name=\"a\"><type><BOOL/></type></variable></inputVars>"
         "<outputVars><variable name=\"y\"><type><BOOL/></type></variable></outputVars>" +
         vars +
         "</interface><body><SFC>\n"
         "<step localId=\"1\" name=\"S0\" initialStep=\"true\"><connectionPointOut/></step>\n"
         "<actionBlock localId=\"20\"><connectionPointIn><connection refLocalId=\"1\"/>"
         "</connectionPointIn><action localId=\"0\" qualifier=\"L\" duration=\"" +
         duration +
         "\"><reference name=\"y\"/></action></actionBlock>\n"
         "<transition localId=\"2\"" +
         (priority.empty() ? "" : " priority=\"" + priority + "\"") +
         "><connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn>"
         "<connectionPointOut/><condition><inline name=\"\">" +
         test::plcopen_st("a") +
         "</inline></condition></transition>\n"
         "<step localId=\"3\" name=\"S1\"><connectionPointIn><connection refLocalId=\"2\"/>"
         "</connectionPointIn><connectionPointOut/></step>\n"
         "<transition localId=\"4\"><connectionPointIn><connection refLocalId=\"3\"/>"
         "</connectionPointIn><connectionPointOut/><condition><inline name=\"\">" +
         test::plcopen_st("NOT a") +
         "</inline></condition></transition>\n"
         "<jumpStep localId=\"5\" targetName=\"S0\"><connectionPointIn><connection "
         "refLocalId=\"4\"/></connectionPointIn></jumpStep>\n"
         "</SFC></body></pou>\n" +
         test::kPlcopenFooter;
}

std::string local(const std::string& name, const std::string& type, const std::string& value) {
  return "<localVars><variable name=\"" + name + "\"><type><" + type +
         "/></type><initialValue><simpleValue value=\"" + value +
         "\"/></initialValue></variable></localVars>";
}

// The issue's case: the duration wrapped around to -1 ms and `EF y` flipped to violated.
TEST(LiteralsPlcopenXml, ADurationPastTimesRangeIsALocatedErrorNotMinusOneMillisecond) {
  const auto r = load_plcopen_xml(xml("", "T#9223372036854775807ms"), "lit.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(errors_of(r),
            "lit.xml:8:95 (/project/types/pous/pou[@name='P']/body/SFC/"
            "actionBlock[@localId='20']/action[@localId='0']): error: cannot read the duration "
            "'T#9223372036854775807ms': TIME literal T#9223372036854775807ms is outside TIME "
            "(T#0ms..T#24d20h31m23s647ms)\n");
  const auto big = load_plcopen_xml(xml("", "T#24d20h31m23s647ms"), "lit.xml");
  ASSERT_TRUE(big.ok()) << errors_of(big);
  EXPECT_EQ(big.project->pous.at(0).associations.at(0).duration_ms, 2147483647);
  const auto negative = load_plcopen_xml(xml("", "T#-1s"), "lit.xml");
  EXPECT_TRUE(has(errors_of(negative), "negative duration 'T#-1s'")) << errors_of(negative);
}

TEST(LiteralsPlcopenXml, InitialValuesAtTheLimitsAndOnePast) {
  const auto r = load_plcopen_xml(xml(local("i", "INT", "-32768") + local("j", "INT", "INT#32767") +
                                          local("l", "LINT", "-9223372036854775808") +
                                          local("m", "LINT", "16#7FFF_FFFF_FFFF_FFFF") +
                                          local("t", "TIME", "T#24d20h31m23s647ms"),
                                      "T#2s"),
                                  "lit.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& p = r.project->pous.at(0);
  EXPECT_EQ(p.find_variable("i")->initial, -32768);
  EXPECT_EQ(p.find_variable("j")->initial, 32767);
  EXPECT_EQ(p.find_variable("l")->initial, kMin);
  EXPECT_EQ(p.find_variable("m")->initial, kMax);
  EXPECT_EQ(p.find_variable("t")->initial, 2147483647);

  const auto past = [](const std::string& type, const std::string& value) {
    return errors_of(load_plcopen_xml(xml(local("n", type, value), "T#2s"), "lit.xml"));
  };
  EXPECT_TRUE(has(past("INT", "40000"),
                  "error: initial value 40000 of variable 'n' is outside INT (-32768..32767)"))
      << past("INT", "40000");
  EXPECT_TRUE(has(past("LINT", "9223372036854775808"),
                  "integer literal 9223372036854775808 is outside LINT"));
  EXPECT_TRUE(has(past("INT", "INT#40000"), "INT#40000 is outside INT (-32768..32767)"));
  EXPECT_TRUE(has(past("TIME", "T#9223372036854775807ms"),
                  "TIME literal T#9223372036854775807ms is outside TIME"));
  EXPECT_TRUE(has(past("TIME", "T#-1s"), "initial value T#-1s of variable 'n' is outside TIME"));
  // Located at the variable's <initialValue>.
  EXPECT_TRUE(has(past("INT", "40000"), "/interface/localVars/variable[@name='n']/initialValue"))
      << past("INT", "40000");
}

TEST(LiteralsPlcopenXml, PrioritiesOutsideTheirRangeAreErrorsNotTruncated) {
  // 2^32 + 1 was cast to int: priority 1.
  const auto r = load_plcopen_xml(xml("", "T#2s", "4294967297"), "lit.xml");
  EXPECT_TRUE(has(errors_of(r), "priority 4294967297 is outside 0..1000000")) << errors_of(r);
  EXPECT_TRUE(has(errors_of(load_plcopen_xml(xml("", "T#2s", "-1"), "lit.xml")),
                  "priority -1 is outside 0..1000000"));
  const auto ok = load_plcopen_xml(xml("", "T#2s", "1000000"), "lit.xml");
  ASSERT_TRUE(ok.ok()) << errors_of(ok);
  EXPECT_EQ(ok.project->pous.at(0).charts.at(0).transitions.at(0).priority, 1000000);
}

TEST(LiteralsPlcopenXml, AnStLiteralInABodyIsLocatedInItsElement) {
  std::string doc = xml("", "T#2s");
  doc.replace(doc.find(test::plcopen_st("a")), test::plcopen_st("a").size(),
              test::plcopen_st("a AND 9223372036854775808 > 0"));
  const auto r = load_plcopen_xml(doc, "lit.xml");
  EXPECT_TRUE(has(errors_of(r), "integer literal 9223372036854775808 is outside LINT"))
      << errors_of(r);
  EXPECT_TRUE(has(errors_of(r), "transition[@localId='2']")) << errors_of(r);
}

TEST(LiteralsPlcopenXml, EnumeratorValuesThatCannotBeReadAreErrors) {
  std::string doc = xml("", "T#2s");
  doc.replace(doc.find("<dataTypes/>"), 12,
              "<dataTypes><dataType name=\"E\"><baseType><enum><values>"
              "<value name=\"A\" value=\"99999999999999999999\"/><value name=\"B\"/>"
              "</values></enum></baseType></dataType></dataTypes>");
  const auto r = load_plcopen_xml(doc, "lit.xml");
  EXPECT_TRUE(has(errors_of(r),
                  "value of enumerator 'A': integer literal 99999999999999999999 "
                  "is outside LINT"))
      << errors_of(r);
}

// -------------------------------------------------------------------------------------- .g7

std::string g7_error(const std::string& doc) {
  return errors_of(load_g7(doc, "lit.g7"));
}

TEST(LiteralsG7, LimitsAreAcceptedAndOnePastIsALocatedError) {
  const auto r = load_g7(
      "internal n : -9223372036854775808..9223372036854775807 := -9223372036854775808;\n"
      "internal m : -9223372036854775808..9223372036854775807 := 9223372036854775807;\n"
      "grafcet G { step 1 initial; step 2;\n"
      "  transition 1 -> 2 when 2147483647ms/X1 & n < -9223372036854775807; }\n",
      "lit.g7");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& p = r.project->pous.at(0);
  EXPECT_EQ(p.find_variable("n")->initial, kMin);
  EXPECT_EQ(p.find_variable("m")->initial, kMax);
  EXPECT_EQ(p.find_variable("n")->type.lo, kMin);

  EXPECT_EQ(g7_error("internal n : 0..9223372036854775808;\ngrafcet G { step 1 initial; }\n"),
            "lit.g7:1:17: error: integer literal 9223372036854775808 is outside LINT "
            "(-9223372036854775808..9223372036854775807)\n");
  EXPECT_EQ(g7_error("internal n : 0..9 := 10;\ngrafcet G { step 1 initial; }\n"),
            "lit.g7:1:22: error: initial value 10 is outside INT(0..9)\n");
  EXPECT_EQ(g7_error("grafcet G { step 1 initial; step 2;\n"
                     "  transition 1 -> 2 when 9223372036854775807ms/X1; }\n"),
            "lit.g7:2:26: error: duration TIME literal '9223372036854775807ms' is outside TIME "
            "(T#0ms..T#24d20h31m23s647ms)\n");
  EXPECT_EQ(g7_error("grafcet G { step 1 initial; step 2;\n"
                     "  transition 1 -> 2 when 2147484s/X1; }\n"),
            "lit.g7:2:26: error: duration TIME literal '2147484s' is outside TIME "
            "(T#0ms..T#24d20h31m23s647ms)\n");
}

// ----------------------------------------------------------------------------- AGRAFE XMI

std::string agrafe(const std::string& transition_attributes, const std::string& term) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<grafcet:Grafcet xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:grafcet="http://www.example.org/grafcet" xmlns:terms="http://www.example.org/terms">
  <variableDeclarationContainer>
    <variableDeclarations name="k" variableDeclarationType="input"><sort xsi:type="terms:Integer" id="1"/></variableDeclarations>
  </variableDeclarationContainer>
  <partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <steps xsi:type="grafcet:Step" id="2"/>
    <arcs source="//@partialGrafcets.0/@steps.0" target="//@partialGrafcets.0/@transitions.0"/>
    <arcs source="//@partialGrafcets.0/@transitions.0" target="//@partialGrafcets.0/@steps.1"/>
    <transitions id="1" )" +
         transition_attributes +
         R"(><term xsi:type="terms:LessThan"><subterm xsi:type="terms:Variable" variableDeclaration="//@variableDeclarationContainer/@variableDeclarations.0"/><subterm xsi:type="terms:IntegerConstant" )" +
         term + R"(/></term></transitions>
  </partialGrafcets>
</grafcet:Grafcet>
)";
}

TEST(LiteralsAgrafe, IntegerConstantsAndDelaysThroughTheCheckedConversion) {
  const auto ok = load_agrafe_xmi(agrafe("timeConditionType=\"timeDelayed\" delayTime=\"2147483\"",
                                         "value=\"-9223372036854775808\""),
                                  "lit.grafcet");
  ASSERT_TRUE(ok.ok()) << errors_of(ok);
  const auto& g = ok.project->pous.at(0).charts.at(0).transitions.at(0).guard;
  ASSERT_EQ(g->kind, model::ExprKind::Delay);
  EXPECT_EQ(g->value, 2147483000);
  EXPECT_EQ(g->args.at(0)->args.at(1)->value, kMin);

  const auto value = [](const std::string& attributes, const std::string& term) {
    return errors_of(load_agrafe_xmi(agrafe(attributes, term), "lit.grafcet"));
  };
  // as_llong() read "abc" as 0 and saturated past 64 bits.
  EXPECT_TRUE(has(value("", "value=\"9223372036854775808\""),
                  "IntegerConstant: integer literal 9223372036854775808 is outside LINT"));
  EXPECT_TRUE(has(value("", "value=\"abc\""), "IntegerConstant: 'abc' is not an integer literal"));
  // delayTime * 1000 wrapped around.
  EXPECT_TRUE(has(
      value("timeConditionType=\"timeDelayed\" delayTime=\"9223372036854775807\"", "value=\"1\""),
      "TIME literal delayTime 9223372036854775807 is outside TIME"));
  EXPECT_TRUE(has(value("timeConditionType=\"timeDelayed\" delayTime=\"2147484\"", "value=\"1\""),
                  "is outside TIME"));
  // An unknown unit was read as seconds.
  EXPECT_TRUE(has(
      value("timeConditionType=\"timeDelayed\" delayTime=\"2\" unit=\"fortnight\"", "value=\"1\""),
      "unknown time unit 'fortnight'"));
  const std::string located = value("", "value=\"9223372036854775808\"");
  EXPECT_TRUE(has(located, "lit.grafcet:")) << located;
}

// ---------------------------------------------------------------------------------------- IL

TEST(LiteralsIl, AnOperandPastItsRangeIsLocatedInTheBody) {
  const std::string doc = test::kPlcopenHeader +
                          "<pou name=\"Main\" pouType=\"program\"><interface>" +
                          test::plcopen_vars("localVars", {"n"}, "<LINT/>") +
                          "</interface><body><IL><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">"
                          "LD n\nADD 9223372036854775808\nST n\n</xhtml></IL></body></pou>\n" +
                          test::kPlcopenFooter;
  // An IL body that cannot be read is not modelled, and running it is refused (exit 2, as
  // tests/e2e/il_test.cpp checks); the reason is located at the operand.
  const auto r = load_plcopen_xml(doc, "lit.xml");
  std::string all;
  for (const auto& d : r.diagnostics) all += d.str() + "\n";
  EXPECT_TRUE(has(all,
                  "lit.xml:7:5 (/project/types/pous/pou[@name='Main']/body/IL): note: "
                  "integer literal 9223372036854775808 is outside LINT"))
      << all;
  EXPECT_TRUE(has(all, "its IL body is not modelled")) << all;
  std::string limit = doc;
  limit.replace(limit.find("ADD 9223372036854775808"), 23, "ADD -9223372036854775808");
  const auto ok = load_plcopen_xml(limit, "lit.xml");
  ASSERT_TRUE(ok.ok()) << errors_of(ok);
  EXPECT_TRUE(ok.diagnostics.empty()) << ok.diagnostics.front().str();
}

}  // namespace
}  // namespace sfcv::io

// The PLCopen TC6 XML writer: write -> load -> the same model, per feature with small inline
// documents, what it refuses, and the print / re-load round trip of every corpus file.

#include "io/plcopen_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <pugixml.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "grafcet_compare.hpp"
#include "io/g7_writer.hpp"
#include "io/iec_text_writer.hpp"
#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/errors.hpp"
#include "model/names.hpp"
#include "round_trip.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::io {
namespace {

using test::diagnostics_text;
using test::plcopen_round_trip;

model::Project load_text(std::string_view text) {
  auto r = load_iec_text(text, "t.sfc");
  EXPECT_TRUE(r.ok()) << diagnostics_text(r.diagnostics);
  return r.project ? *r.project : model::Project{};
}

model::Project load_xml(std::string_view text) {
  auto r = load_plcopen_xml(text, "t.xml");
  EXPECT_TRUE(r.ok()) << diagnostics_text(r.diagnostics);
  return r.project ? *r.project : model::Project{};
}

// A TC6 v2.01 document holding `pous`.
std::string document(const std::string& pous) {
  return "<?xml version=\"1.0\"?><project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" "
         "xmlns:xhtml=\"http://www.w3.org/1999/xhtml\"><types><pous>" +
         pous + "</pous></types></project>";
}

std::string st(const std::string& text) {
  return "<ST><xhtml:p><![CDATA[" + text + "]]></xhtml:p></ST>";
}

// A two-step chart S0 -a-> S1 -NOT a-> S0, as the importer's tests write it.
std::string two_steps(const std::string& extra = "") {
  return R"(<step localId="1" name="S0" initialStep="true"><connectionPointOut/></step>
    <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
      <condition><inline name=""><ST><xhtml:p>a</xhtml:p></ST></inline></condition></transition>
    <step localId="3" name="S1"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></step>
    <transition localId="4"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
      <condition><inline name=""><ST><xhtml:p>NOT a</xhtml:p></ST></inline></condition></transition>
    <jumpStep localId="5" targetName="S0"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></jumpStep>)" +
         extra;
}

const char* const kVarA =
    "<localVars><variable name=\"a\"><type><BOOL/></type></variable>"
    "<variable name=\"x\"><type><BOOL/></type></variable></localVars>";

// ------------------------------------------------------------------------------------ features

// Every feature of the textual form: VAR sections, addresses, initial values, subranges, FB
// instances, named transitions with priorities, selection and simultaneous branches, loops,
// qualifiers with durations (literal and variable) and indicators, ST and nested SFC actions.
const char* const kTextFeatures = R"(
FUNCTION_BLOCK Press
  VAR_INPUT start, stop : BOOL; level : INT(0..10) := 3; small : UINT(2..7); END_VAR
  VAR_OUTPUT motor AT %QX0.1 : BOOL := TRUE; lamp : BOOL; END_VAR
  VAR_IN_OUT shared : DINT; END_VAR
  VAR delta_1 : TIME := T#1s500ms; t1 : TON; n : INT := -2; b : BYTE := 255; END_VAR
  VAR_EXTERNAL g : BOOL; END_VAR

  INITIAL_STEP Idle: Reset(P); lamp; END_STEP
  TRANSITION go (PRIORITY := 2) FROM Idle TO (Run, Watch) := start AND NOT stop; END_TRANSITION
  TRANSITION FROM Idle TO Fault := level > 9; END_TRANSITION
  TRANSITION quick (PRIORITY := 0) FROM Idle TO Idle := stop AND start; END_TRANSITION
  STEP Run: motor(N); Beep(L, T#2s); Beep(D, delta_1, lamp); Count(S); Count(R); Beep(SD, T#1s); END_STEP
  STEP Watch: Sub(N); Beep(DS, T#3s); Beep(SL, T#4s); Beep(P0); Beep(P1); END_STEP
  STEP Fault: END_STEP
  TRANSITION FROM (Run, Watch) TO Idle := Run.T > T#1m30s OR stop; END_TRANSITION
  TRANSITION done FROM Fault TO Idle := NOT start; END_TRANSITION
  TRANSITION FROM Run TO Fault := n >= 3; END_TRANSITION

  ACTION Reset: n := 0; t1(IN := FALSE, PT := T#5s); END_ACTION
  ACTION Beep: IF n < 5 THEN lamp := TRUE; ELSIF n = 6 THEN lamp := g; ELSE lamp := FALSE; END_IF; END_ACTION
  ACTION Count: CASE n OF 0: n := 1; 1..4: n := n + 1; ELSE n := 0; END_CASE; END_ACTION
  ACTION Sub:
    INITIAL_STEP S0: Blink(N); END_STEP
    TRANSITION FROM S0 TO S1 := t1.Q; END_TRANSITION
    STEP S1: END_STEP
    TRANSITION FROM S1 TO S0 := TRUE; END_TRANSITION
  END_ACTION
  ACTION Blink: lamp := NOT lamp; END_ACTION
END_FUNCTION_BLOCK

PROGRAM Main
  VAR x, y : BOOL; END_VAR
  INITIAL_STEP A: END_STEP
  STEP B: END_STEP
  TRANSITION FROM A TO B := x; END_TRANSITION
  TRANSITION FROM B TO A := y; END_TRANSITION
END_PROGRAM
)";

TEST(PlcopenWriter, EveryFeatureOfTheTextualFormRoundTrips) {
  const auto p = load_text(kTextFeatures);
  const std::string xml = plcopen_round_trip(p);
  for (const char* expected : {"pouType=\"functionBlock\"",
                               "pouType=\"program\"",
                               "<inOutVars>",
                               "<externalVars>",
                               "address=\"%QX0.1\"",
                               "<subrangeSigned>",
                               "<subrangeUnsigned>",
                               "<derived name=\"TON\"",
                               "<simpleValue value=\"T#1500ms\"",
                               "<BYTE",
                               "<simultaneousDivergence",
                               "<simultaneousConvergence",
                               "<selectionDivergence",
                               "<selectionConvergence",
                               "<jumpStep",
                               "priority=\"2\"",
                               "priority=\"0\"",
                               "<inline name=\"go\"",
                               "qualifier=\"D\" duration=\"delta_1\" indicator=\"lamp\"",
                               "duration=\"T#2s\"",
                               "<action name=\"Sub\">"})
    EXPECT_NE(xml.find(expected), std::string::npos) << expected << "\n" << xml;
}

TEST(PlcopenWriter, TransitionNamesArePrintedAsInlineConditionNames) {
  const auto p = load_text(kTextFeatures);
  const auto again = load_xml(write_plcopen_xml(p));
  const auto& chart = again.pous.at(0).charts.at(0);
  std::set<std::string> names;
  for (const auto& t : chart.transitions) names.insert(t.name);
  EXPECT_EQ(names, (std::set<std::string>{"", "go", "quick", "done"}));
}

TEST(PlcopenWriter, DocumentOrderOfTransitionsIsKept) {
  // Three transitions leave A; only document order tells which is tried first.
  const auto p = load_text(R"(
PROGRAM o
  VAR x, y : BOOL; END_VAR
  INITIAL_STEP A: END_STEP
  STEP B: END_STEP
  STEP C: END_STEP
  TRANSITION FROM A TO C := y; END_TRANSITION
  TRANSITION FROM A TO B := x; END_TRANSITION
  TRANSITION FROM A TO A := x AND y; END_TRANSITION
  TRANSITION FROM (B, C) TO A := TRUE; END_TRANSITION
  TRANSITION FROM B TO (B, C) := y; END_TRANSITION
END_PROGRAM
)");
  plcopen_round_trip(p);
  auto swapped = p;
  std::swap(swapped.pous[0].charts[0].transitions[0].order,
            swapped.pous[0].charts[0].transitions[1].order);
  const auto again = load_xml(write_plcopen_xml(swapped));
  EXPECT_FALSE(model::first_difference(swapped, again).has_value());
  EXPECT_TRUE(model::first_difference(p, again).has_value());
}

TEST(PlcopenWriter, FunctionAndStPousWithoutModelledBodies) {
  // Corpus 02: a FUNCTION and ST/FBD POUs whose bodies sfcv does not model, beside an SFC FB.
  const auto p = load_xml(
      document("<pou name=\"Avg\" pouType=\"function\"><interface><inputVars><variable "
               "name=\"n\"><type><INT/></type>"
               "</variable></inputVars></interface><body>" +
               st("Avg := n;") +
               "</body></pou>"
               "<pou name=\"Fbd\" pouType=\"program\"><interface/><body><FBD/></body></pou>"
               "<pou name=\"P\" pouType=\"functionBlock\"><interface>" +
               kVarA + "</interface><body><SFC>" + two_steps() + "</SFC></body></pou>"));
  ASSERT_EQ(p.pous.size(), 3u);
  EXPECT_EQ(p.pous[0].kind, model::PouKind::Function);
  // Without a returnType, calling the function is refused (the reason is kept).
  EXPECT_TRUE(p.pous[0].body_unsupported);
  EXPECT_NE(p.pous[0].unsupported_reason.find("its result type (none) is not modelled"),
            std::string::npos)
      << p.pous[0].unsupported_reason;
  const std::string xml = plcopen_round_trip(p);
  EXPECT_NE(xml.find("pouType=\"function\""), std::string::npos) << xml;
}

TEST(PlcopenWriter, FunctionsKeepTheirResultType) {
  // A FUNCTION's result is the variable named like it, read from and written as returnType;
  // a formal call keeps its parameter names.
  const auto p = load_text(
      "FUNCTION Cap : INT(0..10)\n  VAR_INPUT x : INT; END_VAR\n  Cap := x;\nEND_FUNCTION\n"
      "PROGRAM Main\n  VAR y : INT; END_VAR\n  y := Cap(x := 3);\nEND_PROGRAM\n");
  const std::string xml = plcopen_round_trip(p);
  EXPECT_NE(xml.find("<returnType>"), std::string::npos) << xml;
  EXPECT_EQ(xml.find("<variable name=\"Cap\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("y := Cap(x := 3);"), std::string::npos) << xml;
  const auto again = load_xml(xml);
  const auto* result = again.pous.at(0).find_variable("Cap");
  ASSERT_NE(result, nullptr);
  EXPECT_EQ(result->direction, model::VarDirection::Output);
  EXPECT_EQ(result->type, model::Type::integer("INT(0..10)", 0, 10));
}

TEST(PlcopenWriter, StBodyOfAnSfcPouIsASecondBody) {
  // Corpus 01: FBs of condition networks become calls in the POU body, beside the chart.
  auto p = load_xml(document(
      "<pou name=\"P\" pouType=\"functionBlock\"><interface>" + std::string(kVarA) +
      "<localVars><variable name=\"t\"><type><derived name=\"TON\"/></type></variable></localVars>"
      "</interface><body><SFC>" +
      two_steps() + "</SFC></body></pou>"));
  auto& pou = p.pous.at(0);
  ASSERT_TRUE(pou.body.empty());
  pou.body.push_back(
      model::make_fb_call("t", {{"IN", model::make_name("a")}, {"PT", model::make_time(2000)}}));
  pou.body.push_back(model::make_assign("x", model::make_member("t", "Q")));
  const std::string xml = plcopen_round_trip(p);
  EXPECT_NE(xml.find("t(IN := a, PT := T#2s);"), std::string::npos) << xml;
  // The importer reads an ST body beside an SFC body.
  const auto again = load_xml(xml);
  EXPECT_EQ(again.pous.at(0).body.size(), 2u);
}

TEST(PlcopenWriter, MacroStepsKeepTheirBodies) {
  const std::string sfc = R"(<step localId="1" name="S0" initialStep="true"/>
    <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
      <condition><inline name=""><ST><xhtml:p>a</xhtml:p></ST></inline></condition></transition>
    <macroStep localId="3" name="M"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><body><SFC>
      <step localId="1" name="M_in" initialStep="true"/>
      <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
        <condition><inline name=""><ST><xhtml:p>x</xhtml:p></ST></inline></condition></transition>
      <step localId="3" name="M_out"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></step>
    </SFC></body></macroStep>
    <transition localId="4"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
      <condition><inline name=""><ST><xhtml:p>NOT a</xhtml:p></ST></inline></condition></transition>
    <jumpStep localId="5" targetName="S0"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></jumpStep>)";
  const auto p =
      load_xml(document("<pou name=\"P\" pouType=\"program\"><interface>" + std::string(kVarA) +
                        "</interface><body><SFC>" + sfc + "</SFC></body></pou>"));
  ASSERT_EQ(p.pous.at(0).charts.size(), 2u);
  const std::string xml = plcopen_round_trip(p);
  EXPECT_NE(xml.find("<macroStep"), std::string::npos) << xml;
}

TEST(PlcopenWriter, UnmodelledActionBodiesKeepTheirText) {
  const auto p = load_xml(document(
      "<pou name=\"P\" pouType=\"program\"><interface>" + std::string(kVarA) +
      "</interface><actions>"
      "<action name=\"Loop\"><body>" +
      st("x := p^;") +
      "</body></action>"
      "<action name=\"Il\"><body><IL><xhtml:p><![CDATA[top: LD a\nST x\nJMPC top]]></xhtml:p></IL>"
      "</body></action>"
      "</actions><body><SFC>" +
      two_steps(
          R"(<actionBlock localId="9"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
        <action localId="10" qualifier="N"><reference name="Loop"/></action><action localId="11"><reference name="Il"/></action></actionBlock>)") +
      "</SFC></body></pou>"));
  const auto* loop = p.pous.at(0).find_action("Loop");
  ASSERT_TRUE(loop && loop->body_unsupported);
  EXPECT_EQ(loop->unsupported_language, "ST");
  const std::string xml = plcopen_round_trip(p);
  const auto again = load_plcopen_xml(xml, "again.xml");
  ASSERT_TRUE(again.project);
  const auto* loop2 = again.project->pous.at(0).find_action("Loop");
  const auto* il2 = again.project->pous.at(0).find_action("Il");
  ASSERT_TRUE(loop2 && il2);
  EXPECT_TRUE(loop2->body_unsupported);
  // The text comes back as written (an xhtml paragraph ends in a line break).
  EXPECT_EQ(loop2->unsupported_text, loop->unsupported_text);
  EXPECT_TRUE(il2->body_unsupported);
  EXPECT_EQ(il2->unsupported_language, "IL");
  // IEC text cannot carry such a body: refused, not printed as an empty action.
  EXPECT_THROW(write_iec_text(p), sfcv::UnsupportedConstruct);
}

TEST(PlcopenWriter, DottedActionNamesBooleanActionsAndCodesysStepActions) {
  // Corpus 09: `Motor.ACT_TurnClockwise` (an instance's action) and CODESYS entry/exit actions.
  const std::string attrs =
      "<addData><data name=\"http://www.3s-software.com/plcopenxml/sfc/element\" "
      "handleUnknown=\"implementation\">"
      "<attributes><attribute guid=\"a6b08bd8-b696-47e3-9cbf-7408b61c9ff8\">S1_entry</attribute>"
      "<attribute "
      "guid=\"a2621e18-7de3-4ea6-ae6d-89e9e0b7befd\">S1_exit</attribute></attributes></data></"
      "addData>";
  std::string sfc = two_steps(
      R"(<actionBlock localId="9"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
        <action localId="10" qualifier="S"><reference name="Motor.ACT_TurnClockwise"/></action>
        <action localId="11" qualifier="N"><reference name="x"/></action></actionBlock>)");
  const std::string s1 = "<step localId=\"3\" name=\"S1\">";
  sfc.insert(sfc.find(s1) + s1.size(), attrs);
  const auto p = load_xml(document("<pou name=\"P\" pouType=\"functionBlock\"><interface>" +
                                   std::string(kVarA) +
                                   "</interface><actions>"
                                   "<action name=\"S1_entry\"><body>" +
                                   st("x := TRUE;") +
                                   "</body></action>"
                                   "<action name=\"S1_exit\"><body>" +
                                   st("x := FALSE;") +
                                   "</body></action></actions>"
                                   "<body><SFC>" +
                                   sfc + "</SFC></body></pou>"));
  const auto& pou = p.pous.at(0);
  ASSERT_EQ(pou.associations.size(), 4u);
  EXPECT_EQ(pou.associations[0].action, "Motor.ACT_TurnClockwise");
  ASSERT_NE(pou.find_action("x"), nullptr);
  EXPECT_EQ(pou.find_action("x")->kind, model::ActionBodyKind::Variable);
  const std::string xml = plcopen_round_trip(p);
  EXPECT_NE(xml.find("<reference name=\"Motor.ACT_TurnClockwise\""), std::string::npos) << xml;
  // The entry and exit actions go back where CODESYS writes them (not as IEC action blocks,
  // which CODESYS's dialect would give a final call, docs/semantics.md 1.4a).
  EXPECT_EQ(xml.find("qualifier=\"P1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("guid=\"a6b08bd8-b696-47e3-9cbf-7408b61c9ff8\">S1_entry<"), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("guid=\"a2621e18-7de3-4ea6-ae6d-89e9e0b7befd\">S1_exit<"), std::string::npos)
      << xml;
  const auto again = io::load_plcopen_xml(xml, "again.xml");
  ASSERT_TRUE(again.ok());
  for (const auto& as : again.project->pous.at(0).associations)
    EXPECT_EQ(as.step_action, as.action == "S1_entry" || as.action == "S1_exit") << as.action;
}

TEST(PlcopenWriter, OutputIsAWellFormedTc6Document) {
  const auto p = load_text(kTextFeatures);
  const std::string xml = write_plcopen_xml(p);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str()));
  const auto root = doc.document_element();
  EXPECT_STREQ(root.name(), "project");
  EXPECT_STREQ(root.attribute("xmlns").value(), "http://www.plcopen.org/xml/tc6_0201");
  EXPECT_TRUE(root.child("fileHeader").attribute("creationDateTime"));
  EXPECT_TRUE(root.child("contentHeader").child("coordinateInfo").child("sfc").child("scaling"));
  EXPECT_TRUE(root.child("instances").child("configurations"));
  // Within each SFC body: unique localIds, a position first in every element, and every
  // connection naming an element of the same body.
  for (const auto& x : doc.select_nodes("//SFC")) {
    std::set<std::string> ids;
    for (auto e : x.node().children()) {
      EXPECT_TRUE(ids.insert(e.attribute("localId").value()).second) << e.name();
      EXPECT_STREQ(e.first_child().name(), "position") << e.name();
    }
    for (auto e : x.node().children())
      for (auto c : e.child("connectionPointIn").children("connection"))
        EXPECT_TRUE(ids.count(c.attribute("refLocalId").value())) << e.name();
  }
  for (const auto& a : doc.select_nodes("//actionBlock/action")) {
    EXPECT_TRUE(a.node().attribute("localId"));
    EXPECT_STREQ(a.node().first_child().name(), "relPosition");
  }
}

// ------------------------------------------------------------------------------------- refusals

std::string refusal(const model::Project& p) {
  try {
    write_plcopen_xml(p);
  } catch (const sfcv::UnsupportedConstruct& e) {
    return e.what();
  }
  return "(written)";
}

TEST(PlcopenWriter, RefusesWhatTheImporterWouldNotReadBack) {
  const auto base = load_text(R"(
PROGRAM r
  VAR x : BOOL; END_VAR
  INITIAL_STEP A: Act(N); END_STEP
  STEP B: END_STEP
  TRANSITION FROM A TO B := x; END_TRANSITION
  TRANSITION FROM B TO A := NOT x; END_TRANSITION
  ACTION Act: x := TRUE; END_ACTION
END_PROGRAM
)");
  auto expect = [&](auto change, const std::string& message) {
    auto p = base;
    change(p.pous[0]);
    EXPECT_NE(refusal(p).find(message), std::string::npos) << refusal(p);
  };
  EXPECT_EQ(refusal(base), "(written)");
  expect([](model::Pou& u) { u.charts[0].transitions[0].targets = {"Nowhere"}; },
         "names step 'Nowhere', which the chart does not declare");
  expect([](model::Pou& u) { u.charts[0].transitions[0].sources.clear(); },
         "transition without source or target steps");
  expect(
      [](model::Pou& u) {
        u.charts[0].transitions[0].guard =
            model::make_unary(model::ExprKind::Rising, model::make_name("x"));
      },
      "rising edge in a transition condition");
  expect([](model::Pou& u) { u.charts[0].transitions[0].priority = -1; },
         "negative transition priority");
  expect([](model::Pou& u) { u.associations[0].qualifier = model::Qualifier::L; },
         "timed qualifier L of action 'Act' without a duration");
  expect([](model::Pou& u) { u.associations[0].condition = model::make_name("x"); },
         "assignment condition of action 'Act'");
  expect([](model::Pou& u) { u.associations[0].step = "Ghost"; },
         "association of action 'Act' to step 'Ghost'");
  expect([](model::Pou& u) { u.stored_actions.emplace_back(); }, "Grafcet stored actions");
  expect([](model::Pou& u) { u.forcing_orders.emplace_back(); }, "Grafcet forcing orders");
  expect([](model::Pou& u) { u.charts[0].steps[1].kind = model::StepKind::Enclosing; },
         "Grafcet enclosing step 'B'");
  expect(
      [](model::Pou& u) {
        u.actions[0].body_unsupported = true;
        u.actions[0].body.clear();
      },
      "action 'Act', whose graphical body sfcv does not model");
  expect(
      [](model::Pou& u) {
        u.body_unsupported = true;
        u.unsupported_language = "FBD";
        u.unsupported_text = "not xml <";
      },
      "the FBD body of POU 'r', which sfcv does not model");
  // A POU whose only body is ST is a program (issue 18): written, and read back the same.
  auto st_only = base;
  st_only.pous[0].charts.clear();
  st_only.pous[0].associations.clear();
  st_only.pous[0].body.push_back(model::make_assign("x", model::make_bool(true)));
  plcopen_round_trip(st_only);
  auto grafcet = base;
  grafcet.dialect = model::Dialect::Grafcet;
  EXPECT_NE(refusal(grafcet).find("a Grafcet (IEC 60848) project"), std::string::npos);
}

TEST(PlcopenWriter, CompareSeesAnUnmodelledActionBody) {
  const auto p = load_text(R"(
PROGRAM c
  VAR x : BOOL; END_VAR
  INITIAL_STEP A: Act(N); END_STEP
  TRANSITION FROM A TO A := x; END_TRANSITION
  ACTION Act: END_ACTION
END_PROGRAM
)");
  auto q = p;
  q.pous[0].actions[0].body_unsupported = true;
  const auto diff = model::first_difference(p, q);
  ASSERT_TRUE(diff.has_value());
  EXPECT_EQ(*diff, "POU 'c': action 'Act': body modelled in only one");
}

// ---------------------------------------------------------------------------------- the corpus

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The files the MANIFEST lists ("NN_name | repository ...").
std::vector<std::string> manifest_files(const std::filesystem::path& corpus) {
  std::vector<std::string> files;
  std::istringstream in(slurp(corpus / "MANIFEST.txt"));
  const std::regex entry(R"(^(\d\d_[^ |]+) \|)");
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, entry)) files.push_back(m[1]);
  return files;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// An IEC model: printed in its natural form (IEC text or PLCopen XML) and, whatever its source,
// through the PLCopen writer too.
void iec_round_trips(const model::Project& p, bool text, const std::string& what) {
  SCOPED_TRACE(what);
  if (text) test::iec_round_trip(p);
  plcopen_round_trip(p);
}

TEST(RoundTripCorpus, EveryManifestFilePrintsAndReloadsToTheSameModel) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto files = manifest_files(corpus);
  ASSERT_GE(files.size(), 15u);
  int checked = 0;
  for (const auto& f : files) {
    SCOPED_TRACE(f);
    const auto path = corpus / f;
    ASSERT_TRUE(std::filesystem::exists(path));
    if (ends_with(f, ".tmpl")) {
      // 05: a template; the placeholder is replaced by identifiers that are qualifier names.
      const std::string tmpl = slurp(path);
      for (const std::string id : {"N", "S", "D", "L", "P", "SD"}) {
        std::string text = tmpl;
        for (auto at = text.find("XXXX"); at != std::string::npos; at = text.find("XXXX", at))
          text.replace(at, 4, id);
        const auto r = load_iec_text(text, "05_" + id + ".st");
        ASSERT_TRUE(r.ok()) << id << "\n" << diagnostics_text(r.diagnostics);
        iec_round_trips(*r.project, true, "05 with " + id);
      }
      ++checked;
      continue;
    }
    const auto r = load_file(path.string());
    ASSERT_TRUE(r.ok()) << diagnostics_text(r.diagnostics);
    const auto& p = *r.project;
    if (ends_with(f, ".grafcet")) {
      const std::string g7 = write_g7(p);
      const auto again = load_g7(g7, "printed.g7");
      ASSERT_TRUE(again.ok()) << diagnostics_text(again.diagnostics) << g7;
      const auto diff = model::first_difference(p, *again.project);
      EXPECT_FALSE(diff.has_value()) << *diff;
      EXPECT_EQ(test::grafcet_difference(p, *again.project), "");
      EXPECT_THROW(write_plcopen_xml(p), sfcv::UnsupportedConstruct);
    } else if (f.rfind("14_", 0) == 0) {
      // The ill-formed file keeps its defects for validation: IEC text says them again; a
      // PLCopen graph cannot wire a transition to an undeclared step, and the writer says so.
      test::iec_round_trip(p);
      EXPECT_NE(refusal(p).find("names step 'I1a', which the chart does not declare"),
                std::string::npos)
          << refusal(p);
    } else {
      ASSERT_TRUE(ends_with(f, ".xml") || ends_with(f, ".st") || ends_with(f, ".sfc")) << f;
      iec_round_trips(p, !ends_with(f, ".xml"), f);
    }
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(files.size()));
}

}  // namespace
}  // namespace sfcv::io

// The PLCopen TC6 XML importer: small inline documents per feature, and the shared corpus.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/load.hpp"
#include "io/plcopen_writer.hpp"
#include "model/chart.hpp"
#include "model/compare.hpp"
#include "model/names.hpp"
#include "model/validate.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::io {
namespace {

using model::Severity;

const char* const kNs201 = "http://www.plcopen.org/xml/tc6_0201";
const char* const kNs200 = "http://www.plcopen.org/xml/tc6_0200";
const char* const kNs10 = "http://www.plcopen.org/xml/tc6.xsd";

// A project with one POU `P` (program) holding `interface`, `extra` (actions, transitions) and
// an SFC body `sfc`.
[[maybe_unused]] std::string project(const std::string& sfc, const std::string& interface = "",
                                     const std::string& extra = "", const char* ns = kNs201) {
  return std::string("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<project xmlns=\"") + ns +
         "\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n"
         "<fileHeader companyName=\"t\" productName=\"t\" productVersion=\"1\" "
         "creationDateTime=\"2024-01-01T00:00:00\"/>\n"
         "<contentHeader name=\"demo\"/>\n<types><dataTypes/><pous>\n"
         "<pou name=\"P\" pouType=\"program\">\n<interface>" +
         interface + "</interface>\n" + extra + "\n<body><SFC>\n" + sfc +
         "\n</SFC></body>\n</pou>\n</pous></types>\n</project>\n";
}

[[maybe_unused]] std::string step(int id, const std::string& name, int from = -1,
                                  bool initial = false) {
  std::string s = "<step localId=\"" + std::to_string(id) + "\" name=\"" + name + "\"" +
                  (initial ? " initialStep=\"true\"" : "") + ">";
  if (from >= 0)
    s += "<connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn>";
  return s + "<connectionPointOut/></step>\n";
}

[[maybe_unused]] std::string inline_st(const std::string& text) {
  return "<condition><inline name=\"\"><ST><xhtml:p><![CDATA[" + text +
         "]]></xhtml:p></ST></inline></condition>";
}

[[maybe_unused]] std::string transition(int id, int from, const std::string& condition) {
  return "<transition localId=\"" + std::to_string(id) +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn><connectionPointOut/>" + condition + "</transition>\n";
}

[[maybe_unused]] std::string jump(int id, int from, const std::string& target) {
  return "<jumpStep localId=\"" + std::to_string(id) + "\" targetName=\"" + target +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn></jumpStep>\n";
}

std::string errors_of(const LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics)
    if (d.severity == Severity::Error) s += d.str() + "\n";
  return s;
}

[[maybe_unused]] bool has_message(const LoadResult& r, Severity sev, const std::string& part) {
  return std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [&](const auto& d) {
    return d.severity == sev && d.message.find(part) != std::string::npos;
  });
}

[[maybe_unused]] const model::Diagnostic* find_message(const LoadResult& r, Severity sev,
                                                       const std::string& part) {
  for (const auto& d : r.diagnostics)
    if (d.severity == sev && d.message.find(part) != std::string::npos) return &d;
  return nullptr;
}

[[maybe_unused]] std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

[[maybe_unused]] const model::Chart& chart0(const LoadResult& r) {
  return r.project->pous.at(0).charts.at(0);
}

// A two-step loop S0 -> S1 -> S0 whose first condition is `cond1`.
std::string two_steps(const std::string& cond1 = inline_st("a"),
                      const std::string& extra_sfc = "") {
  return step(1, "S0", -1, true) + transition(2, 1, cond1) + step(3, "S1", 2) +
         transition(4, 3, inline_st("NOT a")) + jump(5, 4, "S0") + extra_sfc;
}

const std::string kVarA =
    "<inputVars><variable name=\"a\"><type><BOOL/></type></variable>"
    "<variable name=\"b\"><type><BOOL/></type></variable></inputVars>";

model::ExprPtr guard0(const LoadResult& r) {
  return chart0(r).transitions.at(0).guard;
}

// `sfcv info` says what wrote the file: the fileHeader's fields as written (TC6: the product
// and version of the tool), a version that repeats the product standing for both.
TEST(PlcopenXml, TheFileHeaderSaysWhatWroteTheFile) {
  const std::string header = "companyName=\"t\" productName=\"t\" productVersion=\"1\"";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"companyName=\"\" productName=\"CODESYS\" productVersion=\"CODESYS V3.5 SP4 Patch 4\"",
       "plcopen-xml from CODESYS V3.5 SP4 Patch 4"},
      {"companyName=\"Beckhoff Automation GmbH\" productName=\"TwinCAT PLC Control\" "
       "productVersion=\"3.5.8.40\"",
       "plcopen-xml from Beckhoff Automation GmbH TwinCAT PLC Control 3.5.8.40"},
      {"companyName=\"\" productName=\"\" productVersion=\"\"", "plcopen-xml"},
  };
  for (const auto& [attributes, format] : cases) {
    auto text = project(two_steps(), kVarA);
    text.replace(text.find(header), header.size(), attributes);
    const auto r = load_plcopen_xml(text, "h.xml");
    ASSERT_TRUE(r.ok()) << errors_of(r);
    EXPECT_EQ(r.project->source_format, format);
  }
}

// ------------------------------------------------------------------------------ namespaces, BOM

TEST(PlcopenXml, ReadsTheThreeNamespaces) {
  for (const char* ns : {kNs10, kNs200, kNs201}) {
    const auto r = load_plcopen_xml(project(two_steps(), kVarA, "", ns), "ns.xml");
    ASSERT_TRUE(r.ok()) << ns << "\n" << errors_of(r);
    EXPECT_FALSE(has_message(r, Severity::Warning, "namespace")) << ns;
    const auto& c = chart0(r);
    ASSERT_EQ(c.steps.size(), 2u);
    EXPECT_EQ(c.steps[0].name, "S0");
    EXPECT_TRUE(c.steps[0].initial);
    EXPECT_FALSE(c.steps[1].initial);
    ASSERT_EQ(c.transitions.size(), 2u);
    EXPECT_EQ(c.transitions[1].targets, std::vector<std::string>{"S0"});
    EXPECT_EQ(r.project->source_format, "plcopen-xml from t t 1");  // the fileHeader's fields
    EXPECT_EQ(r.project->name, "demo");
  }
}

TEST(PlcopenXml, UnknownNamespaceIsAWarning) {
  const auto r = load_plcopen_xml(project(two_steps(), kVarA, "", "urn:other"), "ns.xml");
  EXPECT_TRUE(r.ok()) << errors_of(r);
  EXPECT_TRUE(has_message(r, Severity::Warning, "unknown namespace 'urn:other'"));
}

TEST(PlcopenXml, PrefixedElementsAreMatchedByLocalName) {
  std::string doc = project(two_steps(), kVarA);
  // Put every PLCopen element in the "p:" prefix.
  std::string out;
  for (std::size_t i = 0; i < doc.size(); ++i) {
    out += doc[i];
    if (doc[i] == '<' && i + 1 < doc.size() &&
        (std::isalpha(static_cast<unsigned char>(doc[i + 1]))) &&
        doc.compare(i + 1, 6, "xhtml:") != 0)
      out += "p:";
    if (doc[i] == '<' && i + 2 < doc.size() && doc[i + 1] == '/' &&
        doc.compare(i + 2, 6, "xhtml:") != 0) {
      out += "/p:";
      ++i;
    }
  }
  const auto pos = out.find("xmlns=");
  out.replace(pos, 6, "xmlns:p=");
  const auto r = load_plcopen_xml(out, "prefixed.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r) << out;
  EXPECT_EQ(model::count_steps(*r.project), 2u);
  EXPECT_EQ(model::count_transitions(*r.project), 2u);
}

TEST(PlcopenXml, Utf8BomIsAccepted) {
  const auto r = load_plcopen_xml("\xEF\xBB\xBF" + project(two_steps(), kVarA), "bom.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::count_steps(*r.project), 2u);
}

TEST(PlcopenXml, BomDoesNotShiftLineNumbers) {
  const std::string doc = project(two_steps(inline_st("a AND AND b")), kVarA);
  for (const std::string prefix : {"", "\xEF\xBB\xBF"}) {
    const auto r = load_plcopen_xml(prefix + doc, "bom.xml");
    ASSERT_FALSE(r.ok());
    const auto* d = find_message(r, Severity::Error, "");
    ASSERT_NE(d, nullptr);
    // The condition is on the line of transition 2.
    const auto line =
        1 + std::count(doc.begin(), doc.begin() + static_cast<long>(doc.find("a AND AND b")), '\n');
    EXPECT_EQ(d->where.line, line) << d->str();
    EXPECT_EQ(d->where.file, "bom.xml");
  }
}

// ------------------------------------------------------------------------------ condition forms

TEST(PlcopenXml, InlineConditionInXhtmlParagraph) {
  const auto r = load_plcopen_xml(project(two_steps(inline_st("a AND NOT b")), kVarA), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "a AND NOT b");
}

TEST(PlcopenXml, NameOfAnInlineConditionNamesTheTransition) {
  const auto named =
      "<condition><inline name=\"T_go\"><ST><xhtml:p>a</xhtml:p></ST></inline></condition>";
  const auto r = load_plcopen_xml(project(two_steps(named), kVarA), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(chart0(r).transitions.at(0).name, "T_go");
  EXPECT_EQ(chart0(r).transitions.at(1).name, "");  // inline name="" (Beremiz): no name
}

TEST(PlcopenXml, StBodyBesideAnSfcBodyIsThePouBody) {
  const std::string doc = project(
      two_steps(),
      kVarA + "<localVars><variable name=\"x\"><type><BOOL/></type></variable></localVars>");
  std::string with_st = doc;
  with_st.insert(with_st.find("</pou>"),
                 "<body><ST><xhtml:p><![CDATA[x := a AND b;]]></xhtml:p></ST></body>");
  const auto r = load_plcopen_xml(with_st, "st.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  ASSERT_EQ(r.project->pous.at(0).body.size(), 1u);
  EXPECT_EQ(model::to_st(r.project->pous.at(0).body), "x := a AND b;\n");
  EXPECT_FALSE(has_message(r, Severity::Note, "not modelled"));
  // One that does not parse is marked unmodelled (running the POU is refused), with a warning.
  std::string bad = doc;
  bad.insert(bad.find("</pou>"),
             "<body><ST><xhtml:p><![CDATA[x := a ** 2;]]></xhtml:p></ST></body>");
  const auto b = load_plcopen_xml(bad, "st.xml");
  ASSERT_TRUE(b.ok()) << errors_of(b);
  EXPECT_TRUE(b.project->pous.at(0).body.empty());
  EXPECT_TRUE(b.project->pous.at(0).body_unsupported);
  EXPECT_EQ(b.project->pous.at(0).unsupported_text.rfind("x := a ** 2;", 0), 0u);
  EXPECT_TRUE(has_message(b, Severity::Warning, "its ST body is not modelled"));
}

TEST(PlcopenXml, InlineConditionAsRawText) {
  const auto cond = "<condition><inline name=\"\"><ST>a OR b</ST></inline></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond), kVarA, "", kNs10), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "a OR b");
}

TEST(PlcopenXml, InlineConditionInXhtmlElement) {
  const auto cond =
      "<condition><inline><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">a &amp; "
      "b</xhtml></ST></inline></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond), kVarA, "", kNs200), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "a AND b");
}

TEST(PlcopenXml, NestedMemberChainsInConditionsAreKeptAsMembers) {
  // TwinCAT (corpus 09): `Table.AtStack.DI_SwitchTrue` reads a member of a member of an FB.
  const auto extra =
      "<inVariable localId=\"9\"><connectionPointOut/><expression>"
      "Table.AtStack.DI_SwitchTrue AND NOT a.b.c.d AND x.y AND S0.T &lt; "
      "T#1.5s</expression></inVariable>";
  const auto cond =
      "<condition><connectionPointIn><connection "
      "refLocalId=\"9\"/></connectionPointIn></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond, extra), kVarA, "", kNs200), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto g = guard0(r);
  ASSERT_EQ(g->kind, model::ExprKind::And);
  ASSERT_EQ(g->args.size(), 4u);
  EXPECT_EQ(g->args[0]->kind, model::ExprKind::Member);
  EXPECT_EQ(g->args[0]->name, "Table.AtStack");
  EXPECT_EQ(g->args[0]->member, "DI_SwitchTrue");
  EXPECT_EQ(g->args[1]->args[0]->name, "a.b.c");
  EXPECT_EQ(g->args[1]->args[0]->member, "d");
  EXPECT_EQ(g->args[2]->name, "x");
  EXPECT_EQ(g->args[3]->args[1]->value, 1500);
}

TEST(PlcopenXml, NegatedCondition) {
  const auto cond = "<condition negated=\"true\"><inline><ST>a</ST></inline></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond), kVarA), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "NOT a");
}

TEST(PlcopenXml, ReferenceToAnStTransition) {
  const auto transitions =
      "<transitions><transition name=\"GO\"><body><ST><xhtml:p><![CDATA[a AND "
      "b]]></xhtml:p></ST></body></transition>"
      "<transition name=\"GO2\"><body><ST><xhtml:p><![CDATA[GO2 := a OR "
      "b;]]></xhtml:p></ST></body></transition></transitions>";
  const std::string sfc =
      step(1, "S0", -1, true) +
      transition(2, 1, "<condition><reference name=\"GO\"/></condition>") + step(3, "S1", 2) +
      transition(4, 3, "<condition><reference name=\"go2\"/></condition>") + jump(5, 4, "S0");
  const auto r = load_plcopen_xml(project(sfc, kVarA, transitions), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(chart0(r).transitions[0].guard), "a AND b");
  EXPECT_EQ(model::to_st(chart0(r).transitions[1].guard), "a OR b");
}

TEST(PlcopenXml, ReferenceToAnFbdTransition) {
  // Corpus 01's STOP: NOT block between an inVariable and the outVariable named STOP.
  const auto transitions = R"(<transitions><transition name="STOP"><body><FBD>
    <block localId="42" typeName="NOT"><inputVariables><variable formalParameter="IN">
      <connectionPointIn><connection refLocalId="43"/></connectionPointIn></variable></inputVariables>
      <inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    <inVariable localId="43" negated="false"><connectionPointOut/><expression>a</expression></inVariable>
    <outVariable localId="44"><connectionPointIn><connection refLocalId="42" formalParameter="OUT"/></connectionPointIn>
      <expression>STOP</expression></outVariable></FBD></body></transition></transitions>)";
  const auto r = load_plcopen_xml(
      project(two_steps("<condition><reference name=\"STOP\"/></condition>"), kVarA, transitions),
      "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "NOT a");
}

TEST(PlcopenXml, ReferenceToAnLdTransition) {
  const auto transitions = R"(<transitions><transition name="T1"><body><LD>
    <leftPowerRail localId="1"><connectionPointOut/></leftPowerRail>
    <contact localId="2" negated="true"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>a</variable></contact>
    <coil localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>T1</variable></coil>
    </LD></body></transition></transitions>)";
  const auto r = load_plcopen_xml(
      project(two_steps("<condition><reference name=\"T1\"/></condition>"), kVarA, transitions),
      "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "NOT a");
}

TEST(PlcopenXml, ReferenceToAnUndeclaredTransitionIsAnError) {
  const auto r = load_plcopen_xml(
      project(two_steps("<condition><reference name=\"NOPE\"/></condition>"), kVarA), "c.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "'NOPE'"));
}

TEST(PlcopenXml, ConditionWiredToAnInVariable) {
  const auto extra =
      "<inVariable localId=\"9\"><connectionPointOut/><expression>S0.T &gt; "
      "T#6s</expression></inVariable>";
  const auto cond =
      "<condition><connectionPointIn><connection "
      "refLocalId=\"9\"/></connectionPointIn></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond, extra), kVarA, "", kNs200), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto g = guard0(r);
  ASSERT_EQ(g->kind, model::ExprKind::Gt);
  EXPECT_EQ(g->args[0]->kind, model::ExprKind::Member);
  EXPECT_EQ(g->args[1]->kind, model::ExprKind::TimeConst);
  EXPECT_EQ(g->args[1]->value, 6000);
}

TEST(PlcopenXml, ConditionWiredToFbdLogicWithNegatedPins) {
  const auto extra = R"(
    <inVariable localId="10"><connectionPointOut/><expression>a</expression></inVariable>
    <inVariable localId="11" negated="true"><connectionPointOut/><expression>b</expression></inVariable>
    <block localId="12" typeName="AND"><inputVariables>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></variable>
      <variable formalParameter="IN2" negated="true"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    <block localId="13" typeName="OR"><inputVariables>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="12" formalParameter="OUT"/></connectionPointIn></variable>
      <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT" negated="true"><connectionPointOut/></variable></outputVariables></block>
    <block localId="14" typeName="GE"><inputVariables>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="15"/></connectionPointIn></variable>
      <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="16"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    <inVariable localId="15"><connectionPointOut/><expression>n</expression></inVariable>
    <inVariable localId="16"><connectionPointOut/><expression>3</expression></inVariable>)";
  const auto vars = std::string(kVarA) +
                    "<localVars><variable name=\"n\"><type><INT/></type></variable></localVars>";
  const std::string sfc = step(1, "S0", -1, true) +
                          transition(2, 1,
                                     "<condition><connectionPointIn><connection refLocalId=\"13\" "
                                     "formalParameter=\"OUT\"/></connectionPointIn></condition>") +
                          step(3, "S1", 2) +
                          transition(4, 3,
                                     "<condition><connectionPointIn><connection "
                                     "refLocalId=\"14\"/></connectionPointIn></condition>") +
                          jump(5, 4, "S0") + extra;
  const auto r = load_plcopen_xml(project(sfc, vars), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  // AND(a, NOT(NOT b)) OR a, negated at the output.
  EXPECT_EQ(model::to_st(chart0(r).transitions[0].guard), "NOT (a AND NOT NOT b OR a)");
  EXPECT_EQ(model::to_st(chart0(r).transitions[1].guard), "n >= 3");
  EXPECT_TRUE(r.project->pous[0].body.empty());
}

TEST(PlcopenXml, ConditionWiredToLdContactsInSeriesAndParallel) {
  // rail -> a -> NOT b  (series), in parallel with rail -> c  => (a AND NOT b) OR c
  const auto extra = R"(
    <leftPowerRail localId="20"><connectionPointOut formalParameter=""/></leftPowerRail>
    <contact localId="21"><connectionPointIn><connection refLocalId="20"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact>
    <contact localId="22" negated="true"><connectionPointIn><connection refLocalId="21"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact>
    <contact localId="23"><connectionPointIn><connection refLocalId="20"/></connectionPointIn><connectionPointOut/><variable>c</variable></contact>
    <contact localId="24"><connectionPointIn><connection refLocalId="22"/><connection refLocalId="23"/></connectionPointIn><connectionPointOut/><variable>d</variable></contact>)";
  const auto vars = std::string(kVarA) +
                    "<localVars><variable name=\"c\"><type><BOOL/></type></variable><variable "
                    "name=\"d\"><type><BOOL/></type></variable></localVars>";
  const auto cond =
      "<condition><connectionPointIn><connection "
      "refLocalId=\"24\"/></connectionPointIn></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond, extra), vars), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "(a AND NOT b OR c) AND d");
}

TEST(PlcopenXml, FunctionBlockInAConditionNetworkBecomesACallInThePouBody) {
  // GREEN's condition in corpus 01: OR(TON3.Q, WARN) where TON3.IN = SR0.Q1 and SR0.R = TON3.Q.
  const auto extra = R"(
    <block localId="32" typeName="TON" instanceName="TON3"><inputVariables>
      <variable formalParameter="IN"><connectionPointIn><connection refLocalId="44" formalParameter="Q1"/></connectionPointIn></variable>
      <variable formalParameter="PT"><connectionPointIn><connection refLocalId="34"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables>
      <variable formalParameter="Q"><connectionPointOut/></variable><variable formalParameter="ET"><connectionPointOut/></variable>
    </outputVariables></block>
    <inVariable localId="33"><connectionPointOut/><expression>a</expression></inVariable>
    <inVariable localId="34"><connectionPointOut/><expression>T#2s</expression></inVariable>
    <block localId="35" typeName="OR"><inputVariables>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="32" formalParameter="Q"/></connectionPointIn></variable>
      <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="36"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    <inVariable localId="36"><connectionPointOut/><expression>b</expression></inVariable>
    <block localId="44" typeName="SR" instanceName="SR0"><inputVariables>
      <variable formalParameter="S1"><connectionPointIn><connection refLocalId="33"/></connectionPointIn></variable>
      <variable formalParameter="R"><connectionPointIn><connection refLocalId="32" formalParameter="Q"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q1"><connectionPointOut/></variable></outputVariables></block>)";
  const auto vars =
      std::string(kVarA) +
      "<localVars><variable name=\"TON3\"><type><derived name=\"TON\"/></type></variable>"
      "<variable name=\"SR0\"><type><derived name=\"SR\"/></type></variable></localVars>";
  const auto cond =
      "<condition><connectionPointIn><connection refLocalId=\"35\" "
      "formalParameter=\"OUT\"/></connectionPointIn></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond, extra), vars), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "TON3.Q OR b");
  const auto& pou = r.project->pous[0];
  // SR0 is called first (TON3 needs SR0.Q1); SR0 reads TON3.Q of the previous call.
  EXPECT_EQ(model::to_st(pou.body),
            "SR0(S1 := a, R := TON3.Q);\nTON3(IN := SR0.Q1, PT := T#2s);\n");
  EXPECT_TRUE(
      has_message(r, Severity::Warning, "(SR0, TON3) are modelled as calls in the POU body"));
  ASSERT_NE(pou.find_variable("TON3"), nullptr);
  EXPECT_EQ(pou.find_variable("TON3")->type.fb, model::StandardFb::TON);
}

TEST(PlcopenXml, UnsupportedBlockInAConditionIsAPreciseError) {
  const auto extra = R"(
    <block localId="12" typeName="SQRT"><inputVariables>
      <variable formalParameter="IN"><connectionPointIn><connection refLocalId="13"/></connectionPointIn></variable>
    </inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    <inVariable localId="13"><connectionPointOut/><expression>a</expression></inVariable>)";
  const auto cond =
      "<condition><connectionPointIn><connection "
      "refLocalId=\"12\"/></connectionPointIn></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond, extra), kVarA), "c.xml");
  EXPECT_FALSE(r.ok());
  const auto* d = find_message(r, Severity::Error, "unsupported: function SQRT");
  ASSERT_NE(d, nullptr) << errors_of(r);
  EXPECT_EQ(d->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/block[@localId='12']");
}

TEST(PlcopenXml, ConditionThroughConnectorAndContinuation) {
  const auto extra = R"(
    <inVariable localId="10"><connectionPointOut/><expression>a</expression></inVariable>
    <connector localId="11" name="wire"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></connector>
    <continuation localId="12" name="WIRE"><connectionPointOut/></continuation>)";
  const auto cond =
      "<condition><connectionPointIn><connection "
      "refLocalId=\"12\"/></connectionPointIn></condition>";
  const auto r = load_plcopen_xml(project(two_steps(cond, extra), kVarA), "c.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(guard0(r)), "a");
}

// ----------------------------------------------------------------------- divergence, convergence

TEST(PlcopenXml, SelectionDivergenceAndConvergence) {
  const std::string sfc =
      step(1, "A", -1, true) +
      R"(<selectionDivergence localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
         <connectionPointOut/><connectionPointOut/></selectionDivergence>)" +
      transition(3, 2, inline_st("a")) + transition(4, 2, inline_st("b")) + step(5, "B", 3) +
      step(6, "C", 4) + transition(7, 5, inline_st("a")) + transition(8, 6, inline_st("b")) +
      R"(<selectionConvergence localId="9"><connectionPointIn><connection refLocalId="7"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="8"/></connectionPointIn><connectionPointOut/></selectionConvergence>)" +
      jump(10, 9, "A");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "sel.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& t = chart0(r).transitions;
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].sources, std::vector<std::string>{"A"});
  EXPECT_EQ(t[0].targets, std::vector<std::string>{"B"});
  EXPECT_EQ(t[1].sources, std::vector<std::string>{"A"});
  EXPECT_EQ(t[1].targets, std::vector<std::string>{"C"});
  EXPECT_EQ(t[2].targets, std::vector<std::string>{"A"});
  EXPECT_EQ(t[3].sources, std::vector<std::string>{"C"});
  EXPECT_EQ(t[3].targets, std::vector<std::string>{"A"});
  for (int i = 0; i < 4; ++i) EXPECT_EQ(t[static_cast<std::size_t>(i)].order, i);
}

TEST(PlcopenXml, SimultaneousDivergenceAndConvergence) {
  const std::string sfc =
      step(1, "A", -1, true) + transition(2, 1, inline_st("a")) +
      R"(<simultaneousDivergence localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn>
         <connectionPointOut/><connectionPointOut/><connectionPointOut/></simultaneousDivergence>)" +
      step(4, "B1", 3) + step(5, "B2", 3) + step(6, "B3", 3) +
      R"(<simultaneousConvergence localId="7"><connectionPointIn><connection refLocalId="4"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="5"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="6"/></connectionPointIn><connectionPointOut/></simultaneousConvergence>)" +
      transition(8, 7, inline_st("b")) + jump(9, 8, "A");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "par.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& t = chart0(r).transitions;
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].targets, (std::vector<std::string>{"B1", "B2", "B3"}));
  EXPECT_EQ(t[1].sources, (std::vector<std::string>{"B1", "B2", "B3"}));
  EXPECT_EQ(t[1].targets, std::vector<std::string>{"A"});
}

// TwinCAT 3 (corpus 11): alternative branches that end in a step meet in a selection
// convergence, and the transition after it leaves whichever of those steps is active; a branch
// that ends in a jump is still wired into the convergence, though control leaves it by the jump.
TEST(PlcopenXml, TransitionAfterASelectionConvergenceLeavesEachBranchStep) {
  const std::string sfc =
      step(1, "A", -1, true) +
      R"(<selectionDivergence localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
         <connectionPointOut/><connectionPointOut/><connectionPointOut/></selectionDivergence>)" +
      transition(3, 2, inline_st("a")) + transition(4, 2, inline_st("b")) +
      transition(5, 2, inline_st("NOT a AND NOT b")) + step(6, "B", 3) + step(7, "C", 4) +
      jump(8, 5, "A") +
      R"(<selectionConvergence localId="9"><connectionPointIn><connection refLocalId="6"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="7"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="8"/></connectionPointIn><connectionPointOut/></selectionConvergence>)" +
      transition(10, 9, inline_st("a AND b")) + step(11, "D", 10) +
      transition(12, 11, inline_st("TRUE")) + jump(13, 12, "A");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "twincat.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& t = chart0(r).transitions;
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[2].sources, std::vector<std::string>{"A"});
  EXPECT_EQ(t[2].targets, std::vector<std::string>{"A"});
  EXPECT_EQ(t[3].sources, std::vector<std::string>{"B"});
  EXPECT_EQ(t[3].targets, std::vector<std::string>{"D"});
  EXPECT_EQ(t[4].sources, std::vector<std::string>{"C"});
  EXPECT_EQ(t[4].targets, std::vector<std::string>{"D"});
  EXPECT_EQ(model::to_st(t[3].guard), model::to_st(t[4].guard));
  EXPECT_EQ(t[5].sources, std::vector<std::string>{"D"});
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(t[i].order, static_cast<int>(i));
}

// A simultaneous convergence joins its branches; a selection convergence on one of them
// multiplies the joined source sets.
TEST(PlcopenXml, SimultaneousConvergenceOfASelectionConvergenceJoinsEachAlternative) {
  const std::string sfc =
      step(1, "A", -1, true) + transition(2, 1, inline_st("a")) +
      R"(<simultaneousDivergence localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn>
         <connectionPointOut/><connectionPointOut/></simultaneousDivergence>)" +
      step(4, "P", 3) + step(5, "Q", 3) +
      R"(<selectionDivergence localId="6"><connectionPointIn><connection refLocalId="5"/></connectionPointIn>
         <connectionPointOut/><connectionPointOut/></selectionDivergence>)" +
      transition(7, 6, inline_st("a")) + transition(8, 6, inline_st("b")) + step(9, "Q1", 7) +
      step(10, "Q2", 8) +
      R"(<selectionConvergence localId="11"><connectionPointIn><connection refLocalId="9"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="10"/></connectionPointIn><connectionPointOut/></selectionConvergence>)" +
      R"(<simultaneousConvergence localId="12"><connectionPointIn><connection refLocalId="4"/></connectionPointIn>
         <connectionPointIn><connection refLocalId="11"/></connectionPointIn><connectionPointOut/></simultaneousConvergence>)" +
      transition(13, 12, inline_st("b")) + jump(14, 13, "A");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "join.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& t = chart0(r).transitions;
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[3].sources, (std::vector<std::string>{"P", "Q1"}));
  EXPECT_EQ(t[4].sources, (std::vector<std::string>{"P", "Q2"}));
  EXPECT_EQ(t[4].targets, std::vector<std::string>{"A"});
}

// A jump ends its branch: a transition wired directly after one has no source step.
TEST(PlcopenXml, TransitionAfterAJumpIsAnError) {
  const std::string sfc = step(1, "S0", -1, true) + transition(2, 1, inline_st("a")) +
                          jump(3, 2, "S0") + transition(4, 3, inline_st("b")) + step(5, "S1", 4);
  const auto r = load_plcopen_xml(project(sfc, kVarA), "afterjump.xml");
  EXPECT_FALSE(r.ok());
  // Issue 45: named in the chart's words (the jump's target), not as "follows jumpStep".
  EXPECT_TRUE(has_message(r, Severity::Error,
                          "transition (localId 4) directly follows the jump to 'S0' (localId 3)"))
      << errors_of(r);
}

// ------------------------------------------- jumps ending parallel branches (issue 45, xPPU)

const std::string kVarsAbcd =
    "<inputVars><variable name=\"a\"><type><BOOL/></type></variable>"
    "<variable name=\"b\"><type><BOOL/></type></variable>"
    "<variable name=\"c\"><type><BOOL/></type></variable>"
    "<variable name=\"d\"><type><BOOL/></type></variable></inputVars>";

std::string sim_div(int id, int from) {
  return "<simultaneousDivergence localId=\"" + std::to_string(id) +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn><connectionPointOut/><connectionPointOut/>"
         "</simultaneousDivergence>\n";
}

std::string convergence(const std::string& kind, int id, std::vector<int> from) {
  std::string s = "<" + kind + " localId=\"" + std::to_string(id) + "\">";
  for (int f : from)
    s += "<connectionPointIn><connection refLocalId=\"" + std::to_string(f) +
         "\"/></connectionPointIn>";
  return s + "<connectionPointOut/></" + kind + ">\n";
}

std::string count_errors(const model::Diagnostics& ds) {
  std::string s;
  for (const auto& d : ds)
    if (d.severity == Severity::Error) s += d.str() + "\n";
  return s;
}

// As TwinCAT writes xPPU 15-23: branch 2 of a parallel sequence ends in a jump out of it, and
// the jump is still wired into the simultaneous convergence. CODESYS: "a parallel branch ends
// with a double line or with a jump"; the convergence waits for the other branch only.
TEST(PlcopenXml, JumpEndingAParallelBranchLeavesTheConvergenceToTheOtherBranches) {
  const std::string sfc = step(1, "Init", -1, true) + transition(2, 1, inline_st("a")) +
                          sim_div(3, 2) + step(4, "Sort", 3) + step(5, "Recv", 3) +
                          transition(6, 5, inline_st("b")) + jump(7, 6, "Init") +
                          convergence("simultaneousConvergence", 8, {4, 7}) +
                          transition(9, 8, inline_st("c")) + step(10, "Reduce", 9) +
                          transition(11, 10, inline_st("d")) + jump(12, 11, "Init");
  const auto r = load_plcopen_xml(project(sfc, kVarsAbcd), "xppu.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& c = chart0(r);
  ASSERT_EQ(c.transitions.size(), 4u);
  EXPECT_EQ(c.transitions[0].targets, (std::vector<std::string>{"Sort", "Recv"}));
  EXPECT_EQ(c.transitions[1].sources, std::vector<std::string>{"Recv"});
  EXPECT_EQ(c.transitions[1].targets, std::vector<std::string>{"Init"});
  EXPECT_EQ(c.transitions[2].sources, std::vector<std::string>{"Sort"});  // not Recv
  EXPECT_EQ(c.transitions[2].targets, std::vector<std::string>{"Reduce"});
  const auto* w =
      find_message(r, Severity::Warning, "a parallel branch ends in the jump to 'Init'");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/jumpStep[@localId='7']");
  EXPECT_TRUE(c.parallel_branch_jump.known());
  // The "unsafe" structure is the vendor's idiom here, not an error of validate().
  EXPECT_EQ(count_errors(model::validate(*r.project)), "");
}

// In any nesting: an alternative inside a parallel branch, one way out by a jump (wired into
// a selection convergence that feeds the simultaneous convergence), the other to the join.
TEST(PlcopenXml, JumpInsideAnAlternativeOfAParallelBranch) {
  const std::string sfc =
      step(1, "Init", -1, true) + transition(2, 1, inline_st("a")) + sim_div(3, 2) +
      step(4, "P", 3) + step(5, "Q", 3) +
      R"(<selectionDivergence localId="20"><connectionPointIn><connection refLocalId="5"/></connectionPointIn>
         <connectionPointOut/><connectionPointOut/></selectionDivergence>)" +
      transition(21, 20, inline_st("b")) + jump(22, 21, "Init") +
      transition(23, 20, inline_st("c")) + step(24, "Q2", 23) +
      convergence("selectionConvergence", 25, {22, 24}) +
      convergence("simultaneousConvergence", 26, {4, 25}) + transition(27, 26, inline_st("d")) +
      jump(28, 27, "Init");
  const auto r = load_plcopen_xml(project(sfc, kVarsAbcd), "nested.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& t = chart0(r).transitions;
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[1].sources, std::vector<std::string>{"Q"});
  EXPECT_EQ(t[1].targets, std::vector<std::string>{"Init"});
  EXPECT_EQ(t[3].sources, (std::vector<std::string>{"P", "Q2"}));
  // The jump leaves the parallel branch as in the test above: the same warning, at the jump.
  const auto* w =
      find_message(r, Severity::Warning, "a parallel branch ends in the jump to 'Init'");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/jumpStep[@localId='22']");
  EXPECT_TRUE(chart0(r).parallel_branch_jump.known());
  EXPECT_EQ(count_errors(model::validate(*r.project)), "");
}

// A genuine defect: every branch into the convergence ends in a jump, so nothing precedes its
// transition; the error says so in the chart's terms.
TEST(PlcopenXml, ConvergenceWhoseEveryBranchJumpsIsAnError) {
  const std::string sfc = step(1, "Init", -1, true) + transition(2, 1, inline_st("a")) +
                          sim_div(3, 2) + step(4, "P", 3) + step(5, "Q", 3) +
                          transition(6, 4, inline_st("b")) + jump(7, 6, "Init") +
                          transition(8, 5, inline_st("c")) + jump(9, 8, "Init") +
                          convergence("simultaneousConvergence", 10, {7, 9}) +
                          transition(11, 10, inline_st("d")) + jump(12, 11, "Init");
  const auto r = load_plcopen_xml(project(sfc, kVarsAbcd), "alljump.xml");
  EXPECT_FALSE(r.ok());
  const auto* d = find_message(r, Severity::Error,
                               "transition (localId 11) has no source step: every branch into "
                               "simultaneousConvergence (localId 10) ends in a jump");
  ASSERT_NE(d, nullptr) << errors_of(r);
  EXPECT_EQ(d->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/transition[@localId='11']");
}

// TC6 v1.0 (Beremiz 2008): the condition holds its connection without a connectionPointIn.
TEST(PlcopenXml, Tc6V10ConditionWithABareConnection) {
  const std::string sfc =
      step(1, "S0", -1, true) +
      R"(<inVariable localId="7"><connectionPointOut/><expression>a AND NOT b</expression></inVariable>
         <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
         <condition><connection refLocalId="7"/></condition></transition>)" +
      step(3, "S1", 2) + transition(4, 3, inline_st("b")) + jump(5, 4, "S0");
  const auto r = load_plcopen_xml(project(sfc, kVarA, "", kNs10), "tc6v10.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(chart0(r).transitions[0].guard), "a AND NOT b");
}

// AGRAFE's generated ST (issue 45): the program assigns the variables of a global list that
// the project keeps in its own addData (`globalVars name="Global_GrafcetVars"`).
TEST(PlcopenXml, BodiesAssignTheGlobalListOfTheProjectAddData) {
  const std::string text = std::string(R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns=")") + kNs201 +
                           R"(" xmlns:xhtml="http://www.w3.org/1999/xhtml">
<fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
<contentHeader name="g"/>
<types><dataTypes/><pous>
<pou name="G1" pouType="program"><interface><inputVars><variable name="go"><type><BOOL/></type></variable></inputVars></interface>
<body><ST><xhtml:p><![CDATA[IF go THEN actStep_1 := TRUE; Step_1 := NOT Step_1; END_IF;]]></xhtml:p></ST></body></pou>
</pous></types>
<instances><configurations/></instances>
<addData><data name="http://www.3s-software.com/plcopenxml/globalvars" handleUnknown="implementation">
<globalVars name="Global_GrafcetVars">
<variable name="actStep_1"><type><BOOL/></type><initialValue><simpleValue value="false"/></initialValue></variable>
<variable name="Step_1"><type><BOOL/></type></variable>
</globalVars></data></addData>
</project>
)";
  const auto r = load_plcopen_xml(text, "agrafe_st.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* g1 = r.project->find_pou("G1");
  ASSERT_NE(g1, nullptr);
  EXPECT_FALSE(g1->body_unsupported) << g1->unsupported_reason;
  EXPECT_EQ(g1->body.size(), 1u);
  // The list stays a POU of its own, after the POUs, as before.
  ASSERT_EQ(r.project->pous.size(), 2u);
  EXPECT_EQ(r.project->pous[1].name, "Global_GrafcetVars");
  EXPECT_EQ(r.project->pous[1].variables.size(), 2u);
}

TEST(PlcopenXml, PriorityAttribute) {
  const std::string sfc =
      step(1, "S0", -1, true) +
      R"(<transition localId="2" priority="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>)" +
      inline_st("a") + "</transition>" + step(3, "S1", 2) + transition(4, 3, inline_st("b")) +
      jump(5, 4, "S0");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "prio.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(chart0(r).transitions[0].priority, 2);
  EXPECT_FALSE(chart0(r).transitions[1].priority.has_value());
}

TEST(PlcopenXml, JumpToAnUnknownStepIsAnError) {
  const std::string sfc =
      step(1, "S0", -1, true) + transition(2, 1, inline_st("a")) + jump(3, 2, "NOWHERE");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "jump.xml");
  EXPECT_FALSE(r.ok());
  const auto* d = find_message(r, Severity::Error, "jump to unknown step 'NOWHERE'");
  ASSERT_NE(d, nullptr) << errors_of(r);
  EXPECT_EQ(d->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/jumpStep[@localId='3']");
}

TEST(PlcopenXml, MacroStepWithABodyBecomesAMacroStepAndAChart) {
  const std::string sfc =
      step(1, "S0", -1, true) + transition(2, 1, inline_st("a")) +
      R"(<macroStep localId="3" name="M"><connectionPointIn><connection refLocalId="2"/></connectionPointIn>
         <connectionPointOut/><body><SFC>)" +
      step(1, "M_in", -1, true) + transition(2, 1, inline_st("b")) + step(3, "M_out", 2) +
      "</SFC></body></macroStep>" + transition(4, 3, inline_st("NOT a")) + jump(5, 4, "S0");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "macro.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  ASSERT_EQ(pou.charts.size(), 2u);
  const auto* m = pou.charts[0].find_step("M");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->kind, model::StepKind::MacroStep);
  EXPECT_EQ(m->expansion, "M");
  EXPECT_EQ(pou.charts[1].name, "M");
  EXPECT_EQ(pou.charts[1].steps.size(), 2u);
  EXPECT_EQ(pou.charts[0].transitions.size(), 2u);
}

TEST(PlcopenXml, MacroStepWithoutABodyIsUnsupported) {
  const std::string sfc =
      step(1, "S0", -1, true) + transition(2, 1, inline_st("a")) +
      R"(<macroStep localId="3" name="M"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></macroStep>)";
  const auto r = load_plcopen_xml(project(sfc, kVarA), "macro.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "unsupported: macroStep 'M' has no SFC body"));
}

// ----------------------------------------------------------------------------------- actions

std::string action_block(int id, int step_id, const std::string& actions) {
  return "<actionBlock localId=\"" + std::to_string(id) +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(step_id) +
         "\"/></connectionPointIn>" + actions + "</actionBlock>\n";
}

const std::string kOutputs =
    "<outputVars><variable name=\"x\"><type><BOOL/></type></variable>"
    "<variable name=\"y\"><type><BOOL/></type></variable>"
    "<variable name=\"n\"><type><INT/></type></variable></outputVars>"
    "<localVars><variable name=\"delay\"><type><TIME/></type><initialValue><simpleValue "
    "value=\"T#3s\"/></initialValue></variable></localVars>";

TEST(PlcopenXml, ActionBlockQualifiersDurationsAndIndicators) {
  const auto blocks =
      action_block(20, 1,
                   R"(<action localId="0"><reference name="x"/></action>
         <action localId="0" qualifier="S"><reference name="y"/></action>
         <action localId="0" qualifier="D" duration="T#2s"><reference name="ACT"/></action>
         <action localId="0" qualifier="L" duration="delay" indicator="y"><reference name="ACT"/></action>)") +
      action_block(21, 3, R"(<action qualifier="R"><reference name="y"/></action>)");
  const auto actions =
      "<actions><action name=\"ACT\"><body><ST><xhtml:p><![CDATA[n := n + "
      "1;]]></xhtml:p></ST></body></action></actions>";
  const auto r = load_plcopen_xml(
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs, actions),
      "act.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  ASSERT_EQ(pou.associations.size(), 5u);
  const auto& as = pou.associations;
  EXPECT_EQ(as[0].qualifier, model::Qualifier::N);
  EXPECT_EQ(as[0].step, "S0");
  EXPECT_EQ(as[0].chart, "P");
  EXPECT_EQ(as[0].action, "x");
  EXPECT_EQ(as[1].qualifier, model::Qualifier::S);
  EXPECT_EQ(as[2].qualifier, model::Qualifier::D);
  EXPECT_EQ(as[2].duration_ms, 2000);
  EXPECT_EQ(as[3].qualifier, model::Qualifier::L);
  EXPECT_FALSE(as[3].duration_ms.has_value());
  EXPECT_EQ(as[3].duration_variable, "delay");
  EXPECT_EQ(as[3].indicator, "y");
  EXPECT_EQ(as[4].qualifier, model::Qualifier::R);
  EXPECT_EQ(as[4].step, "S1");
  // ACT has an ST body; x and y are Boolean-variable actions.
  const auto* act = pou.find_action("ACT");
  ASSERT_NE(act, nullptr);
  EXPECT_EQ(act->kind, model::ActionBodyKind::Statements);
  EXPECT_EQ(model::to_st(act->body), "n := n + 1;\n");
  ASSERT_NE(pou.find_action("x"), nullptr);
  EXPECT_EQ(pou.find_action("x")->kind, model::ActionBodyKind::Variable);
  EXPECT_EQ(pou.find_action("x")->variable, "x");
  EXPECT_EQ(pou.find_variable("delay")->initial, 3000);
}

TEST(PlcopenXml, TimedQualifierWithoutDurationAndUnknownQualifierAreErrors) {
  const auto blocks =
      action_block(20, 1,
                   R"(<action localId="0" qualifier="D"><reference name="x"/></action>
         <action localId="0" qualifier="Q"><reference name="x"/></action>)");
  const auto r = load_plcopen_xml(
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs), "act.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "qualifier D needs a duration"));
  const auto* d = find_message(r, Severity::Error, "unknown action qualifier 'Q'");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/actionBlock[@localId='20']/"
            "action[@localId='0'][2]");
}

TEST(PlcopenXml, InlineActionBodiesBecomeNamedActions) {
  const auto blocks = action_block(
      20, 3,
      R"(<action localId="0" qualifier="P"><inline><ST><xhtml:p><![CDATA[x := TRUE;]]></xhtml:p></ST></inline></action>
         <action localId="0"><inline><ST><xhtml:p><![CDATA[IF a THEN n := 1; ELSE n := 2; END_IF;]]></xhtml:p></ST></inline></action>)");
  const auto r = load_plcopen_xml(
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs), "act.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  const auto* a1 = pou.find_action("INLINE1");
  const auto* a2 = pou.find_action("INLINE2");
  ASSERT_NE(a1, nullptr);
  ASSERT_NE(a2, nullptr);
  EXPECT_EQ(model::to_st(a1->body), "x := TRUE;\n");
  EXPECT_EQ(a2->body.size(), 1u);
  EXPECT_EQ(a2->body[0]->kind, model::StmtKind::If);
  ASSERT_EQ(pou.associations.size(), 2u);
  EXPECT_EQ(pou.associations[0].action, "INLINE1");
  EXPECT_EQ(pou.associations[0].qualifier, model::Qualifier::P);
  EXPECT_EQ(pou.associations[1].qualifier, model::Qualifier::N);
}

TEST(PlcopenXml, InlineActionNamesAvoidDeclaredNames) {
  const auto blocks =
      action_block(20, 1, R"(<action><inline><ST>x := TRUE;</ST></inline></action>)") +
      action_block(21, 3, R"(<action><inline><ST>y := TRUE;</ST></inline></action>)");
  const auto actions =
      "<actions><action name=\"INLINE1\"><body><ST>n := 1;</ST></body></action></actions>";
  const auto r = load_plcopen_xml(
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs, actions),
      "act.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  EXPECT_EQ(model::to_st(pou.find_action("INLINE1")->body), "n := 1;\n");
  ASSERT_NE(pou.find_action("INLINE1_2"), nullptr);
  EXPECT_EQ(model::to_st(pou.find_action("INLINE1_2")->body), "x := TRUE;\n");
  ASSERT_NE(pou.find_action("INLINE2"), nullptr);
  EXPECT_EQ(model::to_st(pou.find_action("INLINE2")->body), "y := TRUE;\n");
}

TEST(PlcopenXml, UnparsableActionBodyIsKeptAsUnsupportedWithAWarning) {
  const auto blocks = action_block(
      20, 3,
      R"(<action localId="0"><inline><ST><xhtml:p><![CDATA[n := p^;]]></xhtml:p></ST></inline></action>)");
  const auto actions =
      "<actions><action name=\"IL_ACT\"><body><IL><xhtml:p><![CDATA[top: LD a\nST "
      "x\nJMPC top]]></xhtml:p></IL></body></action></actions>";
  const auto r = load_plcopen_xml(
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs, actions),
      "act.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);  // loads: the semantics refuses the actions instead
  const auto& pou = r.project->pous[0];
  const auto* inl = pou.find_action("INLINE1");
  ASSERT_NE(inl, nullptr);
  EXPECT_TRUE(inl->body_unsupported);
  EXPECT_TRUE(inl->body.empty());
  const auto* w = find_message(r, Severity::Warning, "action 'INLINE1': body not modelled");
  ASSERT_NE(w, nullptr);
  EXPECT_NE(w->where.element_path.find("actionBlock[@localId='20']/action[@localId='0']/inline/ST"),
            std::string::npos)
      << w->where.element_path;
  EXPECT_TRUE(has_message(r, Severity::Note, "unsupported"));
  const auto* il = pou.find_action("IL_ACT");
  ASSERT_NE(il, nullptr);
  EXPECT_TRUE(il->body_unsupported);
  EXPECT_TRUE(has_message(r, Severity::Warning,
                          "action 'IL_ACT': body not modelled (IL: backward jump to 'top' (a "
                          "loop) is not modelled)"));
}

TEST(PlcopenXml, LdActionBodyBecomesStatements) {
  // Corpus 01's BLINK_ORANGE_LIGHT, reduced: a TON whose output sets x through an R_TRIG.
  const auto actions = R"(<actions><action name="BLINK"><body><LD>
    <leftPowerRail localId="1"><connectionPointOut/></leftPowerRail>
    <contact localId="2" negated="true"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>x</variable></contact>
    <block localId="3" typeName="TON" instanceName="T1"><inputVariables>
      <variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
      <variable formalParameter="PT"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>
    <inVariable localId="4"><connectionPointOut/><expression>T#500ms</expression></inVariable>
    <coil localId="5" storage="set"><connectionPointIn><connection refLocalId="3" formalParameter="Q"/></connectionPointIn><variable>x</variable></coil>
    <coil localId="6"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>y</variable></coil>
    <rightPowerRail localId="7"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
    </LD></body></action></actions>)";
  const auto vars = std::string(kVarA) + kOutputs +
                    "<localVars><variable name=\"T1\"><type><derived "
                    "name=\"TON\"/></type></variable></localVars>";
  const auto blocks = action_block(20, 3, R"(<action><reference name="BLINK"/></action>)");
  const auto r =
      load_plcopen_xml(project(two_steps(inline_st("a"), blocks), vars, actions), "ld.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* act = r.project->pous[0].find_action("BLINK");
  ASSERT_NE(act, nullptr);
  EXPECT_FALSE(act->body_unsupported);
  EXPECT_EQ(model::to_st(act->body),
            "T1(IN := NOT x, PT := T#500ms);\nIF T1.Q THEN\n  x := TRUE;\nEND_IF;\ny := NOT x;\n");
}

// EN of a standard FB instance in FBD/LD: the instance is called only while EN is TRUE (its
// outputs keep their values otherwise), and its ENO is EN. A function's EN stays refused.
TEST(PlcopenXml, EnAndEnoOfStandardFunctionBlockInstances) {
  const auto actions = R"(<actions><action name="COUNT"><body><LD>
    <leftPowerRail localId="1"><connectionPointOut/></leftPowerRail>
    <contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>x</variable></contact>
    <contact localId="8"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>a</variable></contact>
    <block localId="3" typeName="CTU" instanceName="C1"><inputVariables>
      <variable formalParameter="EN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
      <variable formalParameter="CU"><connectionPointIn><connection refLocalId="8"/></connectionPointIn></variable>
      <variable formalParameter="R"><connectionPointIn><connection refLocalId="9"/></connectionPointIn></variable>
      <variable formalParameter="PV"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>
    <inVariable localId="4"><connectionPointOut/><expression>3</expression></inVariable>
    <inVariable localId="9"><connectionPointOut/><expression>FALSE</expression></inVariable>
    <coil localId="5"><connectionPointIn><connection refLocalId="3" formalParameter="ENO"/></connectionPointIn><variable>y</variable></coil>
    <coil localId="6"><connectionPointIn><connection refLocalId="3" formalParameter="Q"/></connectionPointIn><variable>z</variable></coil>
    <rightPowerRail localId="7"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
    </LD></body></action></actions>)";
  const auto vars = std::string(kVarA) + kOutputs +
                    "<localVars><variable name=\"C1\"><type><derived "
                    "name=\"CTU\"/></type></variable><variable name=\"z\"><type><BOOL/></type>"
                    "</variable></localVars>";
  const auto blocks = action_block(20, 3, R"(<action><reference name="COUNT"/></action>)");
  const auto r =
      load_plcopen_xml(project(two_steps(inline_st("a"), blocks), vars, actions), "en.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* act = r.project->pous[0].find_action("COUNT");
  ASSERT_NE(act, nullptr);
  ASSERT_FALSE(act->body_unsupported) << act->unsupported_reason;
  EXPECT_EQ(model::to_st(act->body),
            "IF x THEN\n  C1(CU := a, R := FALSE, PV := 3);\nEND_IF;\ny := x;\nz := C1.Q;\n");

  // An edge on EN would call the instance on a rising edge only: not modelled, so refused.
  std::string edged = actions;
  edged.replace(edged.find(R"(formalParameter="EN")"), 20, R"(formalParameter="EN" edge="rising")");
  const auto e =
      load_plcopen_xml(project(two_steps(inline_st("a"), blocks), vars, edged), "en.xml");
  const auto* refused = e.ok() ? e.project->pous[0].find_action("COUNT") : nullptr;
  ASSERT_NE(refused, nullptr) << errors_of(e);
  EXPECT_TRUE(refused->body_unsupported);
  EXPECT_NE(refused->unsupported_reason.find("rising edge input of block CTU"), std::string::npos)
      << refused->unsupported_reason;
}

// A function with EN runs only while EN is TRUE; its result is defined only then, so EN is
// modelled where the result is assigned straight to a variable, which otherwise keeps its value.
TEST(PlcopenXml, EnOfAFunctionGuardsTheAssignmentOfItsResult) {
  const auto body = [](const std::string& sink) {
    return R"(<actions><action name="SUM"><body><FBD>
    <inVariable localId="1"><connectionPointOut/><expression>a</expression></inVariable>
    <inVariable localId="2"><connectionPointOut/><expression>n</expression></inVariable>
    <inVariable localId="3"><connectionPointOut/><expression>1</expression></inVariable>
    <block localId="4" typeName="ADD"><inputVariables>
      <variable formalParameter="EN" negated="true"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
      <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    )" + sink +
           "</FBD></body></action></actions>";
  };
  const auto blocks = action_block(20, 3, R"(<action><reference name="SUM"/></action>)");
  const auto load = [&](const std::string& sink) {
    return load_plcopen_xml(
        project(two_steps(inline_st("a"), blocks), kVarA + kOutputs, body(sink)), "en.xml");
  };
  // ENO of a standard function is EN (an error inside it is a range error, not ENO FALSE).
  const auto r = load(
      R"(<outVariable localId="5"><connectionPointIn><connection refLocalId="4" formalParameter="OUT"/></connectionPointIn><expression>n</expression></outVariable>
    <outVariable localId="9"><connectionPointIn><connection refLocalId="4" formalParameter="ENO"/></connectionPointIn><expression>y</expression></outVariable>)");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* act = r.project->pous[0].find_action("SUM");
  ASSERT_NE(act, nullptr);
  ASSERT_FALSE(act->body_unsupported) << act->unsupported_reason;
  EXPECT_EQ(model::to_st(act->body), "IF NOT a THEN\n  n := n + 1;\nEND_IF;\ny := NOT a;\n");

  // Read by another block, the result would be undefined while EN is FALSE: refused by name.
  const auto e =
      load(R"(<inVariable localId="6"><connectionPointOut/><expression>5</expression></inVariable>
    <block localId="7" typeName="GT"><inputVariables>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="4" formalParameter="OUT"/></connectionPointIn></variable>
      <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></variable>
    </inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
    <outVariable localId="8"><connectionPointIn><connection refLocalId="7" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>)");
  const auto* refused = e.ok() ? e.project->pous[0].find_action("SUM") : nullptr;
  ASSERT_NE(refused, nullptr) << errors_of(e);
  EXPECT_TRUE(refused->body_unsupported);
  EXPECT_NE(refused->unsupported_reason.find(
                "EN input of block ADD whose result is not assigned straight to a variable"),
            std::string::npos)
      << refused->unsupported_reason;
}

TEST(PlcopenXml, ActionWithAnSfcBodyIsANestedChart) {
  const auto actions =
      std::string("<actions><action name=\"SUB\"><body><SFC>") + step(0, "Init", -1, true) +
      "<inVariable localId=\"4\"><connectionPointOut/><expression>FALSE</expression></inVariable>" +
      transition(5, 0,
                 "<condition><connectionPointIn><connection "
                 "refLocalId=\"4\"/></connectionPointIn></condition>") +
      jump(6, 5, "Init") +
      action_block(7, 0, "<action qualifier=\"N\"><reference name=\"x\"/></action>") +
      "</SFC></body></action></actions>";
  const auto blocks =
      action_block(20, 3, R"(<action qualifier="S" duration=""><reference name="SUB"/></action>)");
  const auto r = load_plcopen_xml(
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs, actions, kNs200),
      "nested.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  ASSERT_EQ(pou.charts.size(), 2u);
  EXPECT_EQ(pou.charts[0].name, "P");
  EXPECT_EQ(pou.charts[0].parent_action, "");
  EXPECT_EQ(pou.charts[1].name, "SUB");
  EXPECT_EQ(pou.charts[1].parent_action, "SUB");
  EXPECT_EQ(pou.charts[1].steps.size(), 1u);
  ASSERT_EQ(pou.charts[1].transitions.size(), 1u);
  EXPECT_EQ(pou.charts[1].transitions[0].targets, std::vector<std::string>{"Init"});
  const auto* sub = pou.find_action("SUB");
  ASSERT_NE(sub, nullptr);
  EXPECT_EQ(sub->kind, model::ActionBodyKind::Chart);
  EXPECT_EQ(sub->chart, 1);
  // The nested chart's own association names its chart.
  EXPECT_TRUE(std::any_of(pou.associations.begin(), pou.associations.end(), [](const auto& as) {
    return as.chart == "SUB" && as.step == "Init" && as.action == "x";
  }));
}

// ---------------------------------------------------------------------------- CODESYS, TwinCAT

std::string codesys_step(int id, const std::string& name, int from, bool initial,
                         const std::string& attributes) {
  std::string s = "<step localId=\"" + std::to_string(id) + "\" name=\"" + name + "\"" +
                  (initial ? " initialStep=\"true\"" : "") + ">";
  s += from >= 0 ? "<connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
                       "\"/></connectionPointIn>"
                 : "<connectionPointIn/>";
  return s +
         "<connectionPointOut formalParameter=\"sfc\"/><addData><data "
         "name=\"http://www.3s-software.com/plcopenxml/sfc/element\" "
         "handleUnknown=\"implementation\"><attributes xmlns=\"\">" +
         attributes + "</attributes></data></addData></step>\n";
}

TEST(PlcopenXml, CodesysEntryActiveAndExitActions) {
  const std::string attrs =
      "<attribute guid=\"38391c6d-6d4a-42f8-8ee7-9f45e5adafa8\">Run</attribute>"
      "<attribute guid=\"a6b08bd8-b696-47e3-9cbf-7408b61c9ff8\">Run_entry</attribute>"
      "<attribute guid=\"700a583f-b4d4-43e4-8c14-629c7cd3bec8\">Run_active</attribute>"
      "<attribute guid=\"a2621e18-7de3-4ea6-ae6d-89e9e0b7befd\">Run_exit</attribute>";
  const std::string sfc =
      codesys_step(0, "Init", -1, true, "") +
      "<inVariable localId=\"1\"><connectionPointOut/><expression>a</expression></inVariable>" +
      transition(2, 0,
                 "<condition><connectionPointIn><connection "
                 "refLocalId=\"1\"/></connectionPointIn></condition>") +
      codesys_step(3, "Run", 2, false, attrs) +
      "<inVariable localId=\"4\"><connectionPointOut/><expression>NOT a</expression></inVariable>" +
      transition(5, 3,
                 "<condition><connectionPointIn><connection "
                 "refLocalId=\"4\"/></connectionPointIn></condition>") +
      jump(6, 5, "Init");
  std::string actions = "<actions>";
  for (const char* n : {"Run_entry", "Run_active", "Run_exit"})
    actions += std::string("<action name=\"") + n +
               "\"><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">x := NOT "
               "x;</xhtml></ST></body></action>";
  actions += "</actions>";
  const auto r =
      load_plcopen_xml(project(sfc, std::string(kVarA) + kOutputs, actions, kNs200), "codesys.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& as = r.project->pous[0].associations;
  ASSERT_EQ(as.size(), 3u);
  EXPECT_EQ(as[0].action, "Run_entry");
  EXPECT_EQ(as[0].qualifier, model::Qualifier::P1);
  EXPECT_EQ(as[1].action, "Run_active");
  EXPECT_EQ(as[1].qualifier, model::Qualifier::N);
  EXPECT_EQ(as[2].action, "Run_exit");
  EXPECT_EQ(as[2].qualifier, model::Qualifier::P0);
  for (const auto& a : as) EXPECT_EQ(a.step, "Run");
}

// CODESYS and TwinCAT run each IEC action once more in the cycle after it becomes inactive
// (CODESYS SFC help, "Processing order"; Beckhoff's TwinCAT 3 help): a file they wrote is in
// their dialect (docs/semantics.md 1.4a), which the semantics reads from the fileHeader, or,
// in sfcv's own export of such a model, from sfcv's addData.
TEST(PlcopenXml, AVendorsFileSaysWhoseDialectItIsIn) {
  const auto blocks = action_block(20, 3,
                                   R"(<action localId="0"><reference name="ACT"/></action>
         <action localId="0" qualifier="S"><reference name="y"/></action>)");
  const auto actions =
      "<actions><action name=\"ACT\"><body><ST><xhtml:p><![CDATA[n := n + "
      "1;]]></xhtml:p></ST></body></action></actions>";
  const auto text =
      project(two_steps(inline_st("a"), blocks), std::string(kVarA) + kOutputs, actions);
  const std::string header = "companyName=\"t\" productName=\"t\" productVersion=\"1\"";
  auto codesys = text;
  codesys.replace(codesys.find(header), header.size(),
                  "companyName=\"\" productName=\"CODESYS\" productVersion=\"CODESYS V3.5 "
                  "SP14\"");
  const auto r = load_plcopen_xml(codesys, "codesys.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::vendor_of(*r.project), "codesys");
  EXPECT_TRUE(r.project->vendor.empty());  // the fileHeader says it
  // sfcv's export says it in its addData; read back, the model is in the same dialect.
  const auto exported = io::write_plcopen_xml(*r.project);
  EXPECT_NE(exported.find("<data name=\"urn:sfcv:dialect\""), std::string::npos) << exported;
  const auto again = load_plcopen_xml(exported, "again.xml");
  ASSERT_TRUE(again.ok()) << errors_of(again);
  EXPECT_EQ(again.project->vendor, "codesys");
  EXPECT_EQ(model::vendor_of(*again.project), "codesys");
  // The same chart from another tool: plain IEC 61131-3, and no such addData.
  const auto other = load_plcopen_xml(text, "other.xml");
  ASSERT_TRUE(other.ok()) << errors_of(other);
  EXPECT_EQ(model::vendor_of(*other.project), "");
  EXPECT_EQ(io::write_plcopen_xml(*other.project).find("urn:sfcv:dialect"), std::string::npos);
}

TEST(PlcopenXml, PousUnderAddDataAreRead) {
  // TwinCAT: types/pous is empty, the POUs live in project/addData/.../data[@name=".../pou"].
  std::string doc = project(two_steps(), kVarA, "", kNs200);
  const auto pous_begin = doc.find("<pous>") + 6, pous_end = doc.find("</pous>");
  const std::string pou = doc.substr(pous_begin, pous_end - pous_begin);
  doc.erase(pous_begin, pous_end - pous_begin);
  const std::string add_data =
      "<addData><data name=\"http://www.3s-software.com/plcopenxml/application\" "
      "handleUnknown=\"implementation\">"
      "<resource name=\"R\"><addData><data name=\"http://www.3s-software.com/plcopenxml/pou\" "
      "handleUnknown=\"implementation\">" +
      pou + "</data></addData></resource></data></addData>";
  doc.insert(doc.find("</project>"), add_data);
  const auto r = load_plcopen_xml(doc, "twincat.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  ASSERT_EQ(r.project->pous.size(), 1u);
  EXPECT_EQ(r.project->pous[0].name, "P");
  EXPECT_EQ(model::count_steps(*r.project), 2u);
  EXPECT_EQ(chart0(r).transitions[0].where.element_path,
            "/project/addData/data[@name='http://www.3s-software.com/plcopenxml/application']/"
            "resource[@name='R']"
            "/addData/data[@name='http://www.3s-software.com/plcopenxml/pou']/pou[@name='P']/body/"
            "SFC/transition[@localId='2']");
}

TEST(PlcopenXml, StBodyCallingSfcActionsIsRead) {
  // TwinCAT: an FB with an ST body and an action written in SFC, started from the ST body.
  std::string doc = std::string("<?xml version=\"1.0\"?><project xmlns=\"") + kNs200 +
                    "\"><types><pous>"
                    "<pou name=\"Cyl\" pouType=\"functionBlock\"><interface>" +
                    kVarA +
                    "</interface>"
                    "<actions><action name=\"ACT_Extend\"><body><SFC>" +
                    two_steps() +
                    "</SFC></body></action></actions>"
                    "<body><ST><xhtml "
                    "xmlns=\"http://www.w3.org/1999/xhtml\">ACT_Extend();</xhtml></ST></body></pou>"
                    "</pous></types></project>";
  const auto r = load_plcopen_xml(doc, "tc.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(r.project->pous[0].charts.size(), 1u);
  EXPECT_EQ(r.project->pous[0].charts[0].parent_action, "ACT_Extend");
  // The body is read (a call of the POU's action); the semantics refuses calling an SFC action
  // (Programs.CallOfAnSfcActionIsRefused).
  EXPECT_FALSE(r.project->pous[0].body_unsupported);
  ASSERT_EQ(r.project->pous[0].body.size(), 1u);
  EXPECT_EQ(r.project->pous[0].body[0]->target, "ACT_Extend");
}

TEST(PlcopenXml, InstanceActionReferencesAreKeptAsNames) {
  const auto blocks = action_block(
      20, 3, R"(<action qualifier="N"><reference name="Motor.ACT_TurnClockwise"/></action>)");
  const auto r = load_plcopen_xml(project(two_steps(inline_st("a"), blocks), kVarA), "inst.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  ASSERT_EQ(r.project->pous[0].associations.size(), 1u);
  EXPECT_EQ(r.project->pous[0].associations[0].action, "Motor.ACT_TurnClockwise");
}

// ----------------------------------------------------------------------------------- variables

TEST(PlcopenXml, VariablesDirectionsTypesAndInitialValues) {
  const auto vars = R"(
    <inputVars><variable name="i1" address="%IX0.1"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable></inputVars>
    <outputVars><variable name="o1"><type><INT/></type><initialValue><simpleValue value="16#10"/></initialValue></variable></outputVars>
    <inOutVars><variable name="io"><type><UINT/></type></variable></inOutVars>
    <localVars><variable name="t"><type><TIME/></type><initialValue><simpleValue value="T#1m30s"/></initialValue></variable>
      <variable name="r"><type><subrangeSigned><range lower="0" upper="10"/><baseType><INT/></baseType></subrangeSigned></type><initialValue><simpleValue value="5"/></initialValue></variable>
      <variable name="f"><type><REAL/></type></variable>
      <variable name="s"><type><wstring/></type></variable>
      <variable name="str"><type><string length="20"/></type></variable>
      <variable name="u"><type><derived name="MyFb"/></type></variable>
      <variable name="tp"><type><derived name="TP"/></type></variable>
      <variable name="a"><type><BOOL/></type></variable></localVars>
    <externalVars><variable name="e"><type><DINT/></type></variable></externalVars>)";
  const auto r = load_plcopen_xml(project(two_steps(), vars), "vars.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  const auto* i1 = pou.find_variable("i1");
  ASSERT_NE(i1, nullptr);
  EXPECT_EQ(i1->direction, model::VarDirection::Input);
  EXPECT_EQ(i1->initial, 1);
  EXPECT_EQ(i1->address, "%IX0.1");
  EXPECT_EQ(pou.find_variable("o1")->direction, model::VarDirection::Output);
  EXPECT_EQ(pou.find_variable("o1")->initial, 16);
  EXPECT_EQ(pou.find_variable("io")->direction, model::VarDirection::InOut);
  EXPECT_EQ(pou.find_variable("io")->type.hi, 65535);
  EXPECT_EQ(pou.find_variable("t")->initial, 90000);
  EXPECT_EQ(pou.find_variable("t")->type.kind, model::TypeKind::Time);
  EXPECT_EQ(pou.find_variable("r")->type.lo, 0);
  EXPECT_EQ(pou.find_variable("r")->type.hi, 10);
  EXPECT_EQ(pou.find_variable("r")->initial, 5);
  EXPECT_EQ(pou.find_variable("tp")->type.fb, model::StandardFb::TP);
  EXPECT_EQ(pou.find_variable("e")->direction, model::VarDirection::External);
  // STRING is modelled (its range is set when the project's types are lowered, 1.7a).
  ASSERT_NE(pou.find_variable("str"), nullptr);
  EXPECT_TRUE(pou.find_variable("str")->type.is_string());
  for (const char* ignored : {"f", "s", "u"}) {
    EXPECT_EQ(pou.find_variable(ignored), nullptr) << ignored;
    EXPECT_TRUE(has_message(r, Severity::Warning,
                            std::string("of variable '") + ignored + "': variable ignored"));
  }
  EXPECT_TRUE(has_message(r, Severity::Warning, "unsupported type REAL of variable 'f'"));
  EXPECT_TRUE(has_message(r, Severity::Warning, "unsupported type MyFb of variable 'u'"));
}

TEST(PlcopenXml, UnreadableInitialValueIsAnError) {
  const auto vars =
      R"(<localVars><variable name="a"><type><BOOL/></type><initialValue><simpleValue value="MAYBE"/></initialValue></variable>
    <variable name="n"><type><SINT/></type><initialValue><simpleValue value="300"/></initialValue></variable></localVars>)";
  const auto r = load_plcopen_xml(project(two_steps(), vars), "vars.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error,
                          "cannot read the initial value 'MAYBE' of variable 'a' (BOOL)"));
  EXPECT_TRUE(has_message(r, Severity::Error,
                          "initial value 300 of variable 'n' is outside SINT (-128..127)"));
}

// ------------------------------------------------------------------------------ malformed input

TEST(PlcopenXml, UnknownRefLocalIdIsLocated) {
  const std::string sfc =
      step(1, "S0", -1, true) + transition(2, 99, inline_st("a")) + step(3, "S1", 2);
  const auto r = load_plcopen_xml(project(sfc, kVarA), "bad.xml");
  EXPECT_FALSE(r.ok());
  const auto* d = find_message(r, Severity::Error, "unknown localId '99'");
  ASSERT_NE(d, nullptr) << errors_of(r);
  EXPECT_EQ(d->where.file, "bad.xml");
  EXPECT_EQ(d->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/transition[@localId='2']/"
            "connectionPointIn/connection");
  EXPECT_GT(d->where.line, 0);
  EXPECT_NE(d->str().find("bad.xml:"), std::string::npos);
}

TEST(PlcopenXml, DanglingTransitionIsAnError) {
  const std::string sfc = step(1, "S0", -1, true) + transition(2, 1, inline_st("a"));
  const auto r = load_plcopen_xml(project(sfc, kVarA), "bad.xml");
  EXPECT_FALSE(r.ok());
  const auto* d = find_message(r, Severity::Error, "dangling transition (localId 2)");
  ASSERT_NE(d, nullptr) << errors_of(r);
  EXPECT_EQ(d->where.element_path,
            "/project/types/pous/pou[@name='P']/body/SFC/transition[@localId='2']");
}

TEST(PlcopenXml, TransitionWithoutSourceIsAnError) {
  const std::string sfc = step(1, "S0", -1, true) + "<transition localId=\"2\">" + inline_st("a") +
                          "</transition>" + step(3, "S1", 2);
  const auto r = load_plcopen_xml(project(sfc, kVarA), "bad.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "transition (localId 2) has no source step"));
}

TEST(PlcopenXml, TwoTransitionsInSequenceAreAnError) {
  const std::string sfc = step(1, "S0", -1, true) + transition(2, 1, inline_st("a")) +
                          transition(3, 2, inline_st("b")) + step(4, "S1", 3);
  const auto r = load_plcopen_xml(project(sfc, kVarA), "bad.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "follows transition (localId 2)"));
}

TEST(PlcopenXml, DuplicateLocalIdIsAnError) {
  const std::string sfc = step(1, "S0", -1, true) + step(1, "S1");
  const auto r = load_plcopen_xml(project(sfc, kVarA), "bad.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "duplicate localId '1'"));
}

TEST(PlcopenXml, MissingInitialStepStillLoads) {
  // Validation (sfcv lint) reports it; the importer keeps the chart as written.
  const std::string sfc = step(1, "S0") + transition(2, 1, inline_st("a")) + step(3, "S1", 2);
  const auto r = load_plcopen_xml(project(sfc, kVarA), "noinit.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_FALSE(chart0(r).steps[0].initial);
  EXPECT_FALSE(chart0(r).steps[1].initial);
}

TEST(PlcopenXml, BadConditionTextIsALocatedError) {
  const auto r = load_plcopen_xml(project(two_steps(inline_st("a AND (b")), kVarA), "bad.xml");
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  const auto* d = find_message(r, Severity::Error, "");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->where.element_path.find("transition[@localId='2']/condition/inline/ST"),
            std::string::npos)
      << d->where.element_path;
}

TEST(PlcopenXml, MalformedXmlIsAnErrorWithLineAndColumn) {
  const auto r =
      load_plcopen_xml("<?xml version=\"1.0\"?>\n<project>\n  <types>\n</project>\n", "broken.xml");
  EXPECT_FALSE(r.project.has_value());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  const auto& d = r.diagnostics[0];
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_NE(d.message.find("XML parse error"), std::string::npos);
  EXPECT_EQ(d.where.file, "broken.xml");
  EXPECT_EQ(d.where.line, 4);
  EXPECT_GT(d.where.column, 0);
}

TEST(PlcopenXml, RootOtherThanProjectIsAnError) {
  const auto r = load_plcopen_xml("<?xml version=\"1.0\"?>\n<html/>\n", "other.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_message(r, Severity::Error, "root element is <html>"));
}

TEST(PlcopenXml, LoadFileDetectsPlcopenXml) {
  const auto path = sfcv::test::write_temp(project(two_steps(), kVarA), ".xml");
  const auto r = load_file(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::count_steps(*r.project), 2u);
}

// ------------------------------------------------------------------- POU bodies (issue 18)

// Beremiz leaves transitions wired to nothing in its files; its code generator ignores them.
TEST(PlcopenXml, StrayTransitionIsAWarningAndIgnored) {
  const std::string stray = "<transition localId=\"9\"><connectionPointIn/><connectionPointOut/>" +
                            inline_st("b") + "</transition>\n";
  const auto r = load_plcopen_xml(project(two_steps(inline_st("a"), stray), kVarA), "stray.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_TRUE(has_message(r, Severity::Warning, "connected to nothing: ignored"));
  EXPECT_EQ(chart0(r).transitions.size(), 2u);
}

std::string body_project(const std::string& body, const std::string& interface = kVarA) {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<project xmlns=\"" + std::string(kNs201) +
         "\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n<contentHeader name=\"demo\"/>\n"
         "<types><dataTypes/><pous>\n<pou name=\"P\" pouType=\"program\">\n<interface>" +
         interface +
         "<outputVars><variable "
         "name=\"x\"><type><BOOL/></type></variable></outputVars></interface>\n"
         "<body>" +
         body + "</body>\n</pou>\n</pous></types>\n</project>\n";
}

TEST(PlcopenXml, StBodyOfAPouWithoutSfcIsItsProgram) {
  const auto r =
      load_plcopen_xml(body_project("<ST><xhtml:p>x := a AND NOT b;</xhtml:p></ST>"), "st.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous.at(0);
  EXPECT_FALSE(pou.has_sfc());
  EXPECT_FALSE(pou.body_unsupported);
  ASSERT_EQ(pou.body.size(), 1u);
  EXPECT_EQ(model::to_st(pou.body), "x := a AND NOT b;\n");
}

TEST(PlcopenXml, LdEdgeContactBecomesAnRTrigInstance) {
  const std::string ld =
      "<LD><leftPowerRail localId=\"1\"><connectionPointOut/></leftPowerRail>"
      "<contact localId=\"2\" edge=\"rising\"><connectionPointIn><connection "
      "refLocalId=\"1\"/></connectionPointIn>"
      "<variable>a</variable></contact>"
      "<contact localId=\"3\" negated=\"true\"><connectionPointIn><connection "
      "refLocalId=\"2\"/></connectionPointIn>"
      "<variable>b</variable></contact>"
      "<coil localId=\"4\"><connectionPointIn><connection refLocalId=\"3\"/></connectionPointIn>"
      "<variable>x</variable></coil></LD>";
  const auto r = load_plcopen_xml(body_project(ld), "ld.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous.at(0);
  const auto* edge = pou.find_variable("SFCV_EDGE_BODY_2");
  ASSERT_NE(edge, nullptr);
  EXPECT_EQ(edge->type.fb, model::StandardFb::R_TRIG);
  EXPECT_EQ(model::to_st(pou.body),
            "SFCV_EDGE_BODY_2(CLK := a);\nx := SFCV_EDGE_BODY_2.Q AND NOT b;\n");
}

// An IL body with a loop, and an ST body calling an instance of a user function block (its
// variable was dropped), load but are marked: running the POU is refused, never an empty
// program.
TEST(PlcopenXml, BodiesThatCannotBeModelledAreMarked) {
  auto r = load_plcopen_xml(body_project("<IL><xhtml:p>top: LD a\nST x\nJMPC top</xhtml:p></IL>"),
                            "il.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_TRUE(r.project->pous.at(0).body_unsupported);
  EXPECT_EQ(r.project->pous.at(0).unsupported_language, "IL");
  EXPECT_TRUE(has_message(r, Severity::Warning, "its IL body is not modelled"));
  const std::string user_fb = kVarA + std::string(
                                          "<localVars><variable name=\"m\"><type><derived "
                                          "name=\"Motor\"/></type></variable></localVars>");
  r = load_plcopen_xml(body_project("<ST><xhtml:p>m(go := a); x := a;</xhtml:p></ST>", user_fb),
                       "fb.xml");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_TRUE(r.project->pous.at(0).body_unsupported);
  EXPECT_TRUE(r.project->pous.at(0).body.empty());
  EXPECT_NE(r.project->pous.at(0).unsupported_reason.find("'m'"), std::string::npos)
      << r.project->pous.at(0).unsupported_reason;
}

// --------------------------------------------------------------------------------- the corpus

[[maybe_unused]] std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct CorpusCase {
  const char* file;
  std::size_t steps;
  std::size_t transitions;
};

class PlcopenCorpus : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(PlcopenCorpus, LoadsWithManifestCounts) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto& c = GetParam();
  const auto path = corpus / c.file;
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const auto r = load_file(path.string());
  ASSERT_TRUE(r.project.has_value()) << errors_of(r);
  EXPECT_EQ(errors_of(r), "");
  EXPECT_EQ(model::count_steps(*r.project), c.steps);
  EXPECT_EQ(model::count_transitions(*r.project), c.transitions);
}

// 06: PLC_PRG has 6 steps and 5 transitions, its action sub_sfc1 1 step and 1 transition
// (counted in the file: 7 <step>, 6 <transition>).
INSTANTIATE_TEST_SUITE_P(Manifest, PlcopenCorpus,
                         ::testing::Values(CorpusCase{"01_beremiz_traffic_light.xml", 6, 11},
                                           CorpusCase{"02_beremiz_first_steps.xml", 3, 4},
                                           CorpusCase{"03_matiec_SFC_TEST_tc6v1.xml", 12, 13},
                                           CorpusCase{"06_codesys_nested_sfc_action.xml", 7, 6},
                                           CorpusCase{"07_codesys_ppu_scenario3v1.xml", 55, 58},
                                           CorpusCase{"09_twincat_xppu_scenario1.xml", 95, 104}),
                         [](const auto& param_info) {
                           return "file" + std::string(param_info.param.file).substr(0, 2);
                         });

// 03 (XML) and 04 (its textual twin) give the same model, except for the initial values the
// two files really declare differently (03: QX1 FALSE, QX2 TRUE; 04: QX1 := 1, QX2 := 0).
TEST(PlcopenCorpusTwin, MatiecXmlAndTextGiveTheSameModel) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto xml = load_file((corpus / "03_matiec_SFC_TEST_tc6v1.xml").string());
  const auto text = load_file((corpus / "04_matiec_sfc_syntax.st").string());
  ASSERT_TRUE(xml.ok()) << errors_of(xml);
  ASSERT_TRUE(text.ok()) << errors_of(text);
  auto a = *xml.project;
  const auto diff = model::first_difference(a, *text.project);
  ASSERT_TRUE(diff.has_value());
  EXPECT_NE(diff->find("variable 'QX1': initial value differs"), std::string::npos) << *diff;
  const auto* qx1 = text.project->pous[0].find_variable("QX1");
  const auto* qx2 = text.project->pous[0].find_variable("QX2");
  ASSERT_TRUE(qx1 && qx2);
  EXPECT_EQ(a.pous[0].find_variable("QX1")->initial, 0);
  EXPECT_EQ(a.pous[0].find_variable("QX2")->initial, 1);
  for (auto& v : a.pous[0].variables) {
    if (model::iequals(v.name, "QX1")) v.initial = qx1->initial;
    if (model::iequals(v.name, "QX2")) v.initial = qx2->initial;
  }
  const auto rest = model::first_difference(a, *text.project);
  EXPECT_FALSE(rest.has_value()) << *rest;
}

}  // namespace
}  // namespace sfcv::io

// The AGRAFE XMI (.grafcet) importer: each meta-model feature on a small inline document,
// errors with element paths, the corpus files 22-26 and their .g7 round trip.

#include <gtest/gtest.h>

#include <string>

#include "io/g7_writer.hpp"
#include "io/grafcet_compare.hpp"
#include "io/load.hpp"
#include "model/validate.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::io {
namespace {

using model::ExprKind;

std::string messages(const LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += d.str() + "\n";
  return s;
}

/// A document with the given variable declarations and partial grafcets.
std::string doc(const std::string& variables, const std::string& grafcets) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<grafcet:Grafcet xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:grafcet="http://www.example.org/grafcet" xmlns:terms="http://www.example.org/terms">
  <variableDeclarationContainer>
)" + variables +
         R"(
  </variableDeclarationContainer>
)" + grafcets +
         "\n</grafcet:Grafcet>\n";
}

std::string var(const std::string& name, const std::string& type, const std::string& sort,
                const std::string& extra = "") {
  return "    <variableDeclarations name=\"" + name + "\"" +
         (type.empty() ? "" : " variableDeclarationType=\"" + type + "\"") + extra +
         "><sort xsi:type=\"terms:" + sort + "\" id=\"1\"/></variableDeclarations>\n";
}

std::string vref(int i) {
  return "variableDeclaration=\"//@variableDeclarationContainer/@variableDeclarations." +
         std::to_string(i) + "\"";
}

LoadResult load(const std::string& text) {
  return load_agrafe_xmi(text, "t.grafcet");
}

const std::string kTwoSteps = R"(
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <steps xsi:type="grafcet:Step" id="2"/>
    <arcs source="//@partialGrafcets.0/@steps.0" target="//@partialGrafcets.0/@transitions.0"/>
    <arcs source="//@partialGrafcets.0/@transitions.0" target="//@partialGrafcets.0/@steps.1"/>)";

/// The guard of transition 0 of a two-step grafcet whose term is `term`.
model::ExprPtr guard(const std::string& variables, const std::string& term) {
  const auto r = load(doc(
      variables, "<partialGrafcets xsi:type=\"grafcet:PartialGrafcet\" name=\"G\">" + kTwoSteps +
                     "<transitions id=\"1\">" + term + "</transitions></partialGrafcets>"));
  EXPECT_TRUE(r.ok()) << messages(r);
  if (!r.ok()) return nullptr;
  return r.project->pous[0].charts[0].transitions[0].guard;
}

TEST(AgrafeXmi, VariablesDirectionsAndSorts) {
  const auto r =
      load(doc(var("a", "", "Bool") + var("V", "output", "Bool") + var("k", "internal", "Integer") +
                   var("n", "input", "Integer"),
               "<partialGrafcets xsi:type=\"grafcet:PartialGrafcet\" name=\"G\">"
               "<steps xsi:type=\"grafcet:Step\" id=\"1\" initial=\"true\"/></partialGrafcets>"));
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.project->dialect, model::Dialect::Grafcet);
  EXPECT_EQ(r.project->source_format, "agrafe-xmi");
  EXPECT_EQ(r.project->name, "t");
  const auto& v = r.project->pous[0].variables;
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0].direction, model::VarDirection::Input);  // the meta-model's default
  EXPECT_EQ(v[0].type.kind, model::TypeKind::Bool);
  EXPECT_EQ(v[1].direction, model::VarDirection::Output);
  EXPECT_EQ(v[2].direction, model::VarDirection::Local);
  EXPECT_EQ(v[2].type.kind, model::TypeKind::Int);
  // Issue 45: an internal (or output) integer takes INT's range, as AGRAFE's generated code
  // declares it; an input keeps 0..255 (enumerated value by value when computed with).
  EXPECT_EQ(v[2].type.lo, -32768);
  EXPECT_EQ(v[2].type.hi, 32767);
  EXPECT_EQ(v[3].type.lo, 0);
  EXPECT_EQ(v[3].type.hi, 255);
  int notes = 0;
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Note) {
      ++notes;
      EXPECT_NE(d.message.find(notes == 1 ? "-32768..32767" : "0..255"), std::string::npos)
          << d.message;
      EXPECT_FALSE(d.where.element_path.empty());
    }
  EXPECT_EQ(notes, 2);
  EXPECT_EQ(v[2].where.element_path, "//@variableDeclarationContainer/@variableDeclarations.2");
  EXPECT_EQ(v[2].where.line, 6);
}

TEST(AgrafeXmi, TermsBecomeExpressions) {
  const std::string vars = var("a", "", "Bool") + var("b", "", "Bool") + var("n", "", "Integer");
  auto g =
      guard(vars, R"(<term xsi:type="terms:And"><subterm xsi:type="terms:Variable" )" + vref(0) +
                      R"(/><subterm xsi:type="terms:Not"><subterm xsi:type="terms:Variable" )" +
                      vref(1) + "/></subterm></term>");
  ASSERT_TRUE(g);
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args[0]->name, "a");
  EXPECT_EQ(g->args[1]->kind, ExprKind::Not);
  g = guard(
      vars,
      R"(<term xsi:type="terms:Or"><subterm xsi:type="terms:RisingEdge"><subterm xsi:type="terms:Variable" )" +
          vref(0) +
          R"(/></subterm><subterm xsi:type="terms:FallingEdge"><subterm xsi:type="terms:Variable" )" +
          vref(1) + "/></subterm></term>");
  ASSERT_EQ(g->kind, ExprKind::Or);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Rising);
  EXPECT_EQ(g->args[1]->kind, ExprKind::Falling);
  for (const auto& [type, kind] : std::vector<std::pair<std::string, ExprKind>>{
           {"LessThan", ExprKind::Lt}, {"GreaterThan", ExprKind::Gt}, {"Equality", ExprKind::Eq}}) {
    g = guard(vars,
              "<term xsi:type=\"terms:" + type +
                  "\"><subterm xsi:type=\"terms:Addition\"><subterm xsi:type=\"terms:Variable\" " +
                  vref(2) +
                  "/><subterm xsi:type=\"terms:IntegerConstant\" value=\"2\"/></subterm>"
                  "<subterm xsi:type=\"terms:IntegerConstant\" value=\"7\"/></term>");
    ASSERT_TRUE(g);
    EXPECT_EQ(g->kind, kind);
    EXPECT_EQ(g->args[0]->kind, ExprKind::Add);
    EXPECT_EQ(g->args[0]->args[1]->value, 2);
    EXPECT_EQ(g->args[1]->value, 7);
  }
  g = guard(vars, R"(<term xsi:type="terms:BooleanConstant" value="true"/>)");
  EXPECT_EQ(g->kind, ExprKind::BoolConst);
  EXPECT_EQ(g->value, 1);
  g = guard(vars, R"(<term xsi:type="terms:BooleanConstant"/>)");  // EMF leaves out false
  EXPECT_EQ(g->value, 0);
  g = guard(vars, "");  // no term: always true
  EXPECT_EQ(g->kind, ExprKind::BoolConst);
  EXPECT_EQ(g->value, 1);
}

TEST(AgrafeXmi, StepVariablesAndDelayNamedVariables) {
  const std::string vars = var("X2", "step", "Bool", " step=\"//@partialGrafcets.0/@steps.1\"") +
                           var("2s/X2", "internal", "Bool") +
                           var("500ms/X1/1s", "internal", "Bool");
  const auto r = load(doc(
      vars, "<partialGrafcets xsi:type=\"grafcet:PartialGrafcet\" name=\"G\">" + kTwoSteps +
                "<transitions id=\"1\"><term xsi:type=\"terms:And\"><subterm "
                "xsi:type=\"terms:Variable\" " +
                vref(0) + "/><subterm xsi:type=\"terms:Variable\" " + vref(1) +
                "/></term></transitions><transitions id=\"2\"><term xsi:type=\"terms:Variable\" " +
                vref(2) + "/></transitions></partialGrafcets>"));
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_TRUE(r.project->pous[0].variables.empty());
  const auto& g = r.project->pous[0].charts[0].transitions[0].guard;
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Name);
  EXPECT_EQ(g->args[0]->name, "X2");
  ASSERT_EQ(g->args[1]->kind, ExprKind::Delay);
  EXPECT_EQ(g->args[1]->value, 2000);
  EXPECT_EQ(g->args[1]->value2, 0);
  EXPECT_EQ(g->args[1]->args[0]->name, "X2");
  const auto& d = r.project->pous[0].charts[0].transitions[1].guard;
  ASSERT_EQ(d->kind, ExprKind::Delay);
  EXPECT_EQ(d->value, 500);
  EXPECT_EQ(d->value2, 1000);
  int warnings = 0;
  for (const auto& diag : r.diagnostics) warnings += diag.severity == model::Severity::Warning;
  EXPECT_EQ(warnings, 2);
}

TEST(AgrafeXmi, TimeConditionsBecomeDelays) {
  const std::string vars = var("a", "", "Bool") + var("V", "output", "Bool");
  const auto r = load(doc(
      vars,
      R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">)" + kTwoSteps +
          R"(<transitions id="1" timeConditionType="timeDelayed" delayTime="3"><term xsi:type="terms:Variable" )" +
          vref(0) + R"(/></transitions>
    <transitions id="2" timeConditionType="timeDependent" delayTime="200" resetTime="50" unit="ms"><term xsi:type="terms:Variable" )" +
          vref(0) + R"(/></transitions>
    <actionTypes xsi:type="grafcet:ContinuousAction" id="1" timeConditionType="timeDelayed" delayTime="2"><variable )" +
          vref(1) + R"(/></actionTypes>
    <actionLinks step="//@partialGrafcets.0/@steps.1" actionType="//@partialGrafcets.0/@actionTypes.0"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = r.project->pous[0];
  const auto& g1 = p.charts[0].transitions[0].guard;
  ASSERT_EQ(g1->kind, ExprKind::Delay);
  EXPECT_EQ(g1->value, 3000);
  EXPECT_EQ(g1->value2, 0);
  EXPECT_EQ(g1->args[0]->name, "a");
  const auto& g2 = p.charts[0].transitions[1].guard;
  ASSERT_EQ(g2->kind, ExprKind::Delay);
  EXPECT_EQ(g2->value, 200);
  EXPECT_EQ(g2->value2, 50);
  const auto& c = p.associations.at(0).condition;
  ASSERT_TRUE(c);
  ASSERT_EQ(c->kind, ExprKind::Delay);  // 2s/X2: the action is delayed after its step's activation
  EXPECT_EQ(c->value, 2000);
  EXPECT_EQ(c->args[0]->name, "X2");

  const auto bad = load(doc(
      vars,
      R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">)" + kTwoSteps +
          R"(<transitions id="1" timeConditionType="timeLimited" delayTime="3"/></partialGrafcets>)"));
  EXPECT_FALSE(bad.project.has_value());
  ASSERT_FALSE(bad.diagnostics.empty());
  EXPECT_EQ(bad.diagnostics.back().message,
            "unsupported time condition 'timeLimited' (time-limited actions)");
  EXPECT_EQ(bad.diagnostics.back().where.element_path, "//@partialGrafcets.0/@transitions.0");
}

TEST(AgrafeXmi, SynchronizationsAreAndDivergencesAndConvergences) {
  const auto r = load(doc("", R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <steps xsi:type="grafcet:Step" id="2"/>
    <steps xsi:type="grafcet:Step" id="3"/>
    <transitions id="1"/>
    <transitions id="2"/>
    <synchronizations/>
    <synchronizations/>
    <arcs source="//@partialGrafcets.0/@steps.0" target="//@partialGrafcets.0/@transitions.0"/>
    <arcs source="//@partialGrafcets.0/@transitions.0" target="//@partialGrafcets.0/@synchronizations.0"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.0" target="//@partialGrafcets.0/@steps.2"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.0" target="//@partialGrafcets.0/@steps.1"/>
    <arcs source="//@partialGrafcets.0/@steps.1" target="//@partialGrafcets.0/@synchronizations.1"/>
    <arcs source="//@partialGrafcets.0/@steps.2" target="//@partialGrafcets.0/@synchronizations.1"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.1" target="//@partialGrafcets.0/@transitions.1"/>
    <arcs source="//@partialGrafcets.0/@transitions.1" target="//@partialGrafcets.0/@steps.0"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& t = r.project->pous[0].charts[0].transitions;
  EXPECT_EQ(t[0].sources, std::vector<std::string>{"1"});
  EXPECT_EQ(t[0].targets, (std::vector<std::string>{"2", "3"}));  // in step order
  EXPECT_EQ(t[1].sources, (std::vector<std::string>{"2", "3"}));
  EXPECT_EQ(t[1].targets, std::vector<std::string>{"1"});
}

TEST(AgrafeXmi, ActionsStoredContinuousAndForcing) {
  const std::string vars =
      var("a", "", "Bool") + var("V", "output", "Bool") + var("k", "internal", "Integer");
  const auto r = load(doc(
      vars,
      R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G1">
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <steps xsi:type="grafcet:EnclosingStep" id="2" partialGrafcets="//@partialGrafcets.1"/>
    <actionTypes xsi:type="grafcet:ContinuousAction" id="1"><variable )" +
          vref(1) + R"(/><term xsi:type="terms:Variable" )" + vref(0) + R"(/></actionTypes>
    <actionTypes xsi:type="grafcet:StoredAction" id="2"><variable )" +
          vref(2) +
          R"(/><value xsi:type="terms:IntegerConstant" value="4"/></actionTypes>
    <actionTypes xsi:type="grafcet:StoredAction" id="3" storedActionType="deactivation"><variable )" +
          vref(1) +
          R"(/><value xsi:type="terms:BooleanConstant"/></actionTypes>
    <actionTypes xsi:type="grafcet:StoredAction" id="4" storedActionType="event"><variable )" +
          vref(2) + R"(/><value xsi:type="terms:Addition"><subterm xsi:type="terms:Variable" )" +
          vref(2) +
          R"(/><subterm xsi:type="terms:IntegerConstant" value="1"/></value><term xsi:type="terms:RisingEdge"><subterm xsi:type="terms:Variable" )" +
          vref(0) + R"(/></term></actionTypes>
    <actionTypes xsi:type="grafcet:ForcingOrder" id="5" partialGrafcet="//@partialGrafcets.1" forcingOrderType="explicitSituation" forcedSteps="//@partialGrafcets.1/@steps.1"/>
    <actionTypes xsi:type="grafcet:ForcingOrder" id="6" partialGrafcet="//@partialGrafcets.1" forcingOrderType="initialSituation"/>
    <actionTypes xsi:type="grafcet:ForcingOrder" id="7" partialGrafcet="//@partialGrafcets.1" forcingOrderType="emptySituation"/>
    <actionTypes xsi:type="grafcet:ForcingOrder" id="8" partialGrafcet="//@partialGrafcets.1" forcedSteps="//@partialGrafcets.1/@steps.0"/>
    <actionLinks step="//@partialGrafcets.0/@steps.1" actionType="//@partialGrafcets.0/@actionTypes.0"/>
    <actionLinks step="//@partialGrafcets.0/@steps.1" actionType="//@partialGrafcets.0/@actionTypes.1"/>
    <actionLinks step="//@partialGrafcets.0/@steps.1" actionType="//@partialGrafcets.0/@actionTypes.2"/>
    <actionLinks step="//@partialGrafcets.0/@steps.0" actionType="//@partialGrafcets.0/@actionTypes.3"/>
    <actionLinks step="//@partialGrafcets.0/@steps.0" actionType="//@partialGrafcets.0/@actionTypes.4"/>
    <actionLinks step="//@partialGrafcets.0/@steps.0" actionType="//@partialGrafcets.0/@actionTypes.5"/>
    <actionLinks step="//@partialGrafcets.0/@steps.0" actionType="//@partialGrafcets.0/@actionTypes.6"/>
    <actionLinks step="//@partialGrafcets.0/@steps.1" actionType="//@partialGrafcets.0/@actionTypes.7"/>
  </partialGrafcets>
  <partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G2" enclosingStep="//@partialGrafcets.0/@steps.1">
    <steps xsi:type="grafcet:Step" id="21" activationLink="true"/>
    <steps xsi:type="grafcet:Step" id="22"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = r.project->pous[0];
  EXPECT_EQ(p.charts[0].steps[1].kind, model::StepKind::Enclosing);
  EXPECT_EQ(p.charts[0].steps[1].enclosed, std::vector<std::string>{"G2"});
  EXPECT_TRUE(p.charts[1].steps[0].activation_link);
  ASSERT_EQ(p.associations.size(), 1u);
  EXPECT_EQ(p.associations[0].step, "2");
  EXPECT_EQ(p.associations[0].action, "V");
  ASSERT_TRUE(p.associations[0].condition);
  EXPECT_EQ(p.associations[0].condition->name, "a");
  ASSERT_EQ(p.stored_actions.size(), 3u);
  EXPECT_EQ(p.stored_actions[0].when, model::StoredWhen::Activation);
  EXPECT_EQ(p.stored_actions[0].value->value, 4);
  EXPECT_EQ(p.stored_actions[1].when, model::StoredWhen::Deactivation);
  EXPECT_EQ(p.stored_actions[1].value->kind, ExprKind::BoolConst);
  EXPECT_EQ(p.stored_actions[2].when, model::StoredWhen::Event);
  EXPECT_EQ(p.stored_actions[2].event->kind, ExprKind::Rising);
  EXPECT_EQ(p.stored_actions[2].value->kind, ExprKind::Add);
  ASSERT_EQ(p.forcing_orders.size(), 4u);
  EXPECT_EQ(p.forcing_orders[0].kind, model::ForcingKind::Situation);
  EXPECT_EQ(p.forcing_orders[0].target, "G2");
  EXPECT_EQ(p.forcing_orders[0].situation, std::vector<std::string>{"22"});
  EXPECT_EQ(p.forcing_orders[1].kind, model::ForcingKind::Initial);
  EXPECT_EQ(p.forcing_orders[2].kind, model::ForcingKind::Empty);
  // No forcingOrderType: the meta-model's default, currentSituation, with a warning that the
  // listed steps are ignored.
  EXPECT_EQ(p.forcing_orders[3].kind, model::ForcingKind::Current);
  EXPECT_EQ(p.forcing_orders[3].step, "2");
  bool warned = false;
  for (const auto& d : r.diagnostics)
    warned = warned || (d.severity == model::Severity::Warning &&
                        d.message.find("ignored") != std::string::npos);
  EXPECT_TRUE(warned) << messages(r);
}

TEST(AgrafeXmi, AssignedVariablesWithoutDeclarationTypeAreNotInputs) {
  const std::string vars = var("done", "", "Bool") + var("lamp", "", "Bool");
  const auto r =
      load(doc(vars, R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <actionTypes xsi:type="grafcet:StoredAction" id="1"><variable )" +
                         vref(0) +
                         R"(/><value xsi:type="terms:BooleanConstant" value="true"/></actionTypes>
    <actionTypes xsi:type="grafcet:ContinuousAction" id="2"><variable )" +
                         vref(1) + R"(/></actionTypes>
    <actionLinks step="//@partialGrafcets.0/@steps.0" actionType="//@partialGrafcets.0/@actionTypes.0"/>
    <actionLinks step="//@partialGrafcets.0/@steps.0" actionType="//@partialGrafcets.0/@actionTypes.1"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.project->pous[0].variables[0].direction, model::VarDirection::Local);
  EXPECT_EQ(r.project->pous[0].variables[1].direction, model::VarDirection::Output);
  int warnings = 0;
  for (const auto& d : r.diagnostics) warnings += d.severity == model::Severity::Warning;
  EXPECT_EQ(warnings, 2);
}

TEST(AgrafeXmi, MacroStepsWithExpansion) {
  const auto r = load(doc("", R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <transitions id="1"/>
    <macrosteps id="2" expansion="//@partialGrafcets.1"/>
    <arcs source="//@partialGrafcets.0/@steps.0" target="//@partialGrafcets.0/@transitions.0"/>
    <arcs source="//@partialGrafcets.0/@transitions.0" target="//@partialGrafcets.0/@macrosteps"/>
  </partialGrafcets>
  <partialGrafcets xsi:type="grafcet:MacrostepExpansion" name="M2">
    <transitions id="5"/>
    <entryStep id="20"/>
    <exitStep id="29"/>
    <arcs source="//@partialGrafcets.1/@entryStep" target="//@partialGrafcets.1/@transitions.0"/>
    <arcs source="//@partialGrafcets.1/@transitions.0" target="//@partialGrafcets.1/@exitStep"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = r.project->pous[0];
  ASSERT_EQ(p.charts[0].steps.size(), 2u);
  EXPECT_EQ(p.charts[0].steps[1].kind, model::StepKind::MacroStep);
  EXPECT_EQ(p.charts[0].steps[1].expansion, "M2");
  EXPECT_EQ(p.charts[0].transitions[0].targets, std::vector<std::string>{"2"});
  EXPECT_EQ(p.charts[1].macro_entry, "20");
  EXPECT_EQ(p.charts[1].macro_exit, "29");
  EXPECT_EQ(p.charts[1].transitions[0].sources, std::vector<std::string>{"20"});
  EXPECT_EQ(p.charts[1].transitions[0].targets, std::vector<std::string>{"29"});
  // The .g7 form keeps all of it.
  const auto again = load_g7(write_g7(*r.project), "t.g7");
  ASSERT_TRUE(again.ok()) << messages(again);
  EXPECT_EQ(test::grafcet_difference(*r.project, *again.project), "");
}

std::string first_error(const std::string& text) {
  const auto r = load(text);
  EXPECT_FALSE(r.project.has_value());
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Error) return d.where.str() + ": " + d.message;
  return "no error";
}

TEST(AgrafeXmiErrors, NameTheElement) {
  EXPECT_EQ(first_error(doc("",
                            "<partialGrafcets name=\"G\"><steps id=\"1\"/><transitions id=\"1\"/>"
                            "<arcs source=\"//@partialGrafcets.0/@steps.4\" "
                            "target=\"//@partialGrafcets.0/@transitions.0\"/>"
                            "</partialGrafcets>")),
            "t.grafcet:6:63 (//@partialGrafcets.0/@arcs.0): reference "
            "'//@partialGrafcets.0/@steps.4' leads to no element");
  // An index past 64 bits made std::stoul throw (an internal error, exit 4).
  EXPECT_EQ(first_error(doc("",
                            "<partialGrafcets name=\"G\"><steps id=\"1\"/><transitions id=\"1\"/>"
                            "<arcs source=\"//@partialGrafcets.0/@steps.99999999999999999999999\" "
                            "target=\"//@partialGrafcets.0/@transitions.0\"/>"
                            "</partialGrafcets>")),
            "t.grafcet:6:63 (//@partialGrafcets.0/@arcs.0): reference "
            "'//@partialGrafcets.0/@steps.99999999999999999999999' leads to no element");
  EXPECT_EQ(
      first_error(doc("",
                      "<partialGrafcets name=\"G\"><steps id=\"1\"/><transitions id=\"1\">"
                      "<term xsi:type=\"terms:Multiplication\"/></transitions></partialGrafcets>")),
      "t.grafcet:6:62 (//@partialGrafcets.0/@transitions.0/@term): unsupported term type "
      "'Multiplication'");
  EXPECT_EQ(
      first_error(doc(
          "", "<partialGrafcets name=\"G\"><steps id=\"1\"/><steps id=\"1\"/></partialGrafcets>")),
      "t.grafcet:6:42 (//@partialGrafcets.0/@steps.1): step id '1' is used twice in partial "
      "grafcet 'G'");
  EXPECT_EQ(first_error(doc(var("a", "input", "Bool"),
                            "<partialGrafcets name=\"G\"><steps id=\"1\"/><actionTypes "
                            "xsi:type=\"grafcet:StoredAction\" id=\"1\">"
                            "<variable " +
                                vref(0) +
                                "/><value xsi:type=\"terms:BooleanConstant\"/></actionTypes>"
                                "<actionLinks step=\"//@partialGrafcets.0/@steps.0\" "
                                "actionType=\"//@partialGrafcets.0/@actionTypes.0\"/>"
                                "</partialGrafcets>")),
            "t.grafcet:7:94 (//@partialGrafcets.0/@actionTypes.0/@variable): an action assigns the "
            "input 'a'");
  EXPECT_EQ(
      first_error("<grafcet:Grafcet xmlns:grafcet=\"x\">\n  <partialGrafcets>\n</grafcet:Grafcet>"),
      "t.grafcet:3:3: XML error: Start-end tags mismatch");
  EXPECT_EQ(first_error(doc("", "<partialGrafcets name=\"G\"><steps id=\"\"/></partialGrafcets>")),
            "t.grafcet:6:27 (//@partialGrafcets.0/@steps.0): step without an id");
  EXPECT_EQ(
      first_error(doc("", "<partialGrafcets name=\"G\"><steps id=\"a&#10;b\"/></partialGrafcets>")),
      "t.grafcet:6:27 (//@partialGrafcets.0/@steps.0): step id contains a control character");
  EXPECT_EQ(first_error("<project/>"),
            "t.grafcet:1:1 (/): not an AGRAFE grafcet: the root element is <project>, expected "
            "<grafcet:Grafcet>");
}

// ---------------------------------------------------- AGRAFE's own test inputs (issue 45)

std::size_t count_warnings(const LoadResult& r, const std::string& part) {
  std::size_t n = 0;
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Warning && d.message.find(part) != std::string::npos) ++n;
  return n;
}

TEST(AgrafeXmiIdioms, ActionLinkWithoutAnActionIsIgnoredWithAWarning) {
  // As conflictingActions7/9/10 write it: a second link of step 2 names no actionType.
  const auto r =
      load(doc(var("V", "output", "Bool"),
               "<partialGrafcets xsi:type=\"grafcet:PartialGrafcet\" name=\"G\">" + kTwoSteps +
                   "<transitions id=\"1\"/>"
                   "<actionTypes xsi:type=\"grafcet:ContinuousAction\" id=\"1\"><variable " +
                   vref(0) +
                   "/></actionTypes>"
                   "<actionLinks step=\"//@partialGrafcets.0/@steps.1\" "
                   "actionType=\"//@partialGrafcets.0/@actionTypes.0\"/>"
                   "<actionLinks step=\"//@partialGrafcets.0/@steps.1\"/></partialGrafcets>"));
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(count_warnings(r, "action link without an action: ignored"), 1u) << messages(r);
  ASSERT_EQ(r.project->pous[0].associations.size(), 1u);
  EXPECT_EQ(r.project->pous[0].associations[0].step, "2");
  // A link without a step is still an error: it cannot be placed.
  EXPECT_FALSE(load(doc("",
                        "<partialGrafcets name=\"G\"><steps id=\"1\"/>"
                        "<actionLinks/></partialGrafcets>"))
                   .ok());
}

TEST(AgrafeXmiIdioms, TransitionIdUsedTwiceNamesTheCopyApart) {
  // As conflictingActions9 writes it: from the AND divergence after 1, step 3 -(b)-> 4 and step
  // 2 -(a)-> 5, both transitions with id "3". Arcs name transitions by position, so they are
  // two transitions; the second gets its own name (validate refused the duplicate name).
  const auto r = load(doc(var("a", "", "Bool") + var("b", "", "Bool"),
                          R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G1">
    <steps id="1" initial="true"/><steps id="2"/><steps id="3"/><steps id="4"/><steps id="5"/>
    <transitions id="1"/>
    <transitions id="3"><term xsi:type="terms:Variable" )" +
                              vref(1) + R"(/></transitions>
    <transitions id="3"><term xsi:type="terms:Variable" )" +
                              vref(0) + R"(/></transitions>
    <synchronizations/>
    <arcs source="//@partialGrafcets.0/@steps.0" target="//@partialGrafcets.0/@transitions.0"/>
    <arcs source="//@partialGrafcets.0/@transitions.0" target="//@partialGrafcets.0/@synchronizations.0"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.0" target="//@partialGrafcets.0/@steps.1"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.0" target="//@partialGrafcets.0/@steps.2"/>
    <arcs source="//@partialGrafcets.0/@steps.2" target="//@partialGrafcets.0/@transitions.1"/>
    <arcs source="//@partialGrafcets.0/@transitions.1" target="//@partialGrafcets.0/@steps.3"/>
    <arcs source="//@partialGrafcets.0/@steps.1" target="//@partialGrafcets.0/@transitions.2"/>
    <arcs source="//@partialGrafcets.0/@transitions.2" target="//@partialGrafcets.0/@steps.4"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(count_warnings(r,
                           "transition id '3' is used twice in partial grafcet 'G1': this one "
                           "is named '3_2'"),
            1u)
      << messages(r);
  const auto& c = r.project->pous[0].charts[0];
  ASSERT_EQ(c.transitions.size(), 3u);
  EXPECT_EQ(c.transitions[1].name, "3");
  EXPECT_EQ(c.transitions[1].sources, std::vector<std::string>{"3"});
  EXPECT_EQ(c.transitions[1].targets, std::vector<std::string>{"4"});
  EXPECT_EQ(model::to_st(c.transitions[1].guard), "b");
  EXPECT_EQ(c.transitions[2].name, "3_2");
  EXPECT_EQ(c.transitions[2].sources, std::vector<std::string>{"2"});
  EXPECT_EQ(c.transitions[2].targets, std::vector<std::string>{"5"});
  EXPECT_EQ(model::to_st(c.transitions[2].guard), "a");
  for (const auto& d : model::validate(*r.project))
    EXPECT_NE(d.severity, model::Severity::Error) << d.str();
}

TEST(AgrafeXmiIdioms, SynchronizationFromStepsToAStepIsAnAlwaysTrueTransition) {
  // As stepReachability4 writes it: steps 1 and 2 -> bar -> step 3, no transition.
  const auto r = load(doc("", R"(<partialGrafcets xsi:type="grafcet:PartialGrafcet" name="G">
    <steps xsi:type="grafcet:Step" id="1" initial="true"/>
    <steps xsi:type="grafcet:Step" id="2"/>
    <steps xsi:type="grafcet:Step" id="3"/>
    <synchronizations/>
    <arcs source="//@partialGrafcets.0/@steps.0" target="//@partialGrafcets.0/@synchronizations.0"/>
    <arcs source="//@partialGrafcets.0/@steps.1" target="//@partialGrafcets.0/@synchronizations.0"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.0" target="//@partialGrafcets.0/@steps.2"/>
  </partialGrafcets>)"));
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(count_warnings(r, "with no transition: read as transition 'sync1'"), 1u) << messages(r);
  const auto& c = r.project->pous[0].charts[0];
  ASSERT_EQ(c.transitions.size(), 1u);
  EXPECT_EQ(c.transitions[0].sources, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(c.transitions[0].targets, std::vector<std::string>{"3"});
  ASSERT_TRUE(c.transitions[0].guard);
  EXPECT_EQ(model::to_st(c.transitions[0].guard), "TRUE");
  // Transitions to transitions through a bar still mean nothing.
  EXPECT_FALSE(load(doc("", R"(<partialGrafcets name="G"><steps id="1"/>
    <transitions id="1"/><transitions id="2"/><synchronizations/>
    <arcs source="//@partialGrafcets.0/@transitions.0" target="//@partialGrafcets.0/@synchronizations.0"/>
    <arcs source="//@partialGrafcets.0/@synchronizations.0" target="//@partialGrafcets.0/@transitions.1"/>
  </partialGrafcets>)"))
                   .ok());
}

// ------------------------------------------------------------------------------------ corpus

struct CorpusCase {
  const char* file;
  std::size_t steps, transitions;
};

TEST(AgrafeXmiCorpus, LoadsWithManifestCountsAndRoundTripsThroughG7) {
  SFCV_REQUIRE_CORPUS(corpus);
  for (const CorpusCase& c : {CorpusCase{"22_agrafe_quality_control_plant.grafcet", 64, 69},
                              CorpusCase{"24_agrafe_exclusive_selection.grafcet", 11, 16},
                              CorpusCase{"25_agrafe_hierarchical_conflict1.grafcet", 7, 5},
                              CorpusCase{"26_agrafe_step_reachability3.grafcet", 5, 3}}) {
    const auto path = (corpus / c.file).string();
    const auto r = load_file(path);
    ASSERT_TRUE(r.ok()) << c.file << "\n" << messages(r);
    EXPECT_EQ(model::count_steps(*r.project), c.steps) << c.file;
    EXPECT_EQ(model::count_transitions(*r.project), c.transitions) << c.file;
    const std::string printed = write_g7(*r.project);
    const auto again = load_g7(printed, "converted.g7");
    ASSERT_TRUE(again.ok()) << c.file << "\n" << messages(again) << printed;
    EXPECT_EQ(test::grafcet_difference(*r.project, *again.project), "") << c.file;
  }
}

TEST(AgrafeXmiCorpus, QualityControlPlantStructure) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto r = load_file((corpus / "22_agrafe_quality_control_plant.grafcet").string());
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = r.project->pous[0];
  ASSERT_EQ(p.charts.size(), 8u);
  EXPECT_EQ(p.charts[0].name, "GlobalGrafcet");
  int enclosing = 0, linked = 0;
  for (const auto& c : p.charts)
    for (const auto& s : c.steps) {
      enclosing += s.kind == model::StepKind::Enclosing;
      linked += s.activation_link;
    }
  EXPECT_EQ(enclosing, 8);
  EXPECT_EQ(linked, 7);
  EXPECT_EQ(p.associations.size(), 16u);
  EXPECT_EQ(p.stored_actions.size(), 46u);
  // Step 3 of GlobalGrafcet encloses G0, whose steps 11..16 enclose G1, G2, G3, G5, G6, G7.
  EXPECT_EQ(p.charts[0].steps[2].enclosed, std::vector<std::string>{"G0"});
  EXPECT_TRUE(p.charts[0].steps[3].enclosed.empty());  // EnclosingStep 4 encloses nothing
  EXPECT_EQ(p.charts[1].steps[1].enclosed, std::vector<std::string>{"G1"});
  // G0's transition 10 is an AND divergence to steps 11..16.
  EXPECT_EQ(p.charts[1].transitions[0].targets,
            (std::vector<std::string>{"11", "12", "13", "14", "15", "16"}));
  // Transition 17 waits on the AND convergence of 17..22 with a rising edge.
  const auto& t17 = p.charts[1].transitions[7];
  EXPECT_EQ(t17.name, "17");
  EXPECT_EQ(t17.sources, (std::vector<std::string>{"17", "18", "19", "20", "21", "22"}));
  EXPECT_EQ(t17.guard->kind, ExprKind::Rising);
  // The internal variable named "2s/X202" is read as a delay on step 202.
  bool delay = false;
  for (const auto& c : p.charts)
    for (const auto& t : c.transitions)
      for (const auto& a : t.guard->args)
        delay =
            delay || (a->kind == ExprKind::Delay && a->value == 2000 && a->args[0]->name == "X202");
  EXPECT_TRUE(delay);
  EXPECT_FALSE(p.find_variable("2s/X202"));
}

TEST(AgrafeXmiCorpus, HierarchicalConflictAndReachabilityDetails) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto r25 = load_file((corpus / "25_agrafe_hierarchical_conflict1.grafcet").string());
  ASSERT_TRUE(r25.ok()) << messages(r25);
  const auto& p = r25.project->pous[0];
  const auto& g1 = p.charts[0];
  EXPECT_EQ(g1.transitions[3].name, "4");
  EXPECT_EQ(g1.transitions[3].sources, std::vector<std::string>{"1"});
  EXPECT_EQ(g1.transitions[3].targets, (std::vector<std::string>{"2", "6"}));
  EXPECT_EQ(g1.transitions[2].sources, (std::vector<std::string>{"3", "6"}));
  EXPECT_TRUE(g1.transitions[2].targets.empty());  // a sink transition in the file
  EXPECT_EQ(g1.steps[4].enclosed, std::vector<std::string>{"G2"});
  ASSERT_EQ(p.forcing_orders.size(), 1u);
  EXPECT_EQ(p.forcing_orders[0].step, "5");
  EXPECT_EQ(p.forcing_orders[0].target, "G2");
  EXPECT_EQ(p.forcing_orders[0].kind, model::ForcingKind::Current);

  const auto r26 = load_file((corpus / "26_agrafe_step_reachability3.grafcet").string());
  ASSERT_TRUE(r26.ok()) << messages(r26);
  const auto& q = r26.project->pous[0];
  EXPECT_EQ(q.charts[0].name, "G0");
  EXPECT_TRUE(q.charts[0].steps[0].initial);
  EXPECT_TRUE(q.charts[0].steps[3].initial);
  EXPECT_EQ(model::to_st(q.charts[0].transitions[1].guard), "k < 1");
  ASSERT_EQ(q.stored_actions.size(), 1u);
  EXPECT_EQ(q.stored_actions[0].step, "5");
  EXPECT_EQ(q.stored_actions[0].variable, "k");
  EXPECT_EQ(q.stored_actions[0].value->value, 1);
}

}  // namespace
}  // namespace sfcv::io

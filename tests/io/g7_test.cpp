// The native Grafcet text format (.g7): every feature on a small inline document, errors with
// their exact place, and print/re-load round trips.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "io/g7_writer.hpp"
#include "io/grafcet_compare.hpp"
#include "io/load.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::io {
namespace {

using model::ExprKind;

LoadResult load(const std::string& text) {
  return load_g7(text, "t.g7");
}

std::string messages(const LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += d.str() + "\n";
  return s;
}

const model::Pou& pou_of(const LoadResult& r) {
  return r.project->pous.at(0);
}

/// The guard of the only transition of the only chart of `doc`.
model::ExprPtr guard(const std::string& decls, const std::string& receptivity) {
  const auto r = load(decls + "\ngrafcet G { step 1 initial; step 2; transition 1 -> 2 when " +
                      receptivity + "; }\n");
  EXPECT_TRUE(r.ok()) << messages(r);
  if (!r.ok()) return nullptr;
  return pou_of(r).charts.at(0).transitions.at(0).guard;
}

/// The first error of `doc`, as "line:col: message".
std::string first_error(const std::string& doc) {
  const auto r = load(doc);
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Error)
      return std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + ": " + d.message;
  return "no error";
}

/// Loads, prints, re-loads and compares; returns the printed text.
std::string round_trip(const std::string& doc) {
  const auto first = load(doc);
  EXPECT_TRUE(first.ok()) << messages(first);
  if (!first.ok()) return {};
  const std::string printed = write_g7(*first.project);
  const auto second = load_g7(printed, "t.g7");
  EXPECT_TRUE(second.ok()) << messages(second) << printed;
  if (!second.ok()) return printed;
  EXPECT_EQ(test::grafcet_difference(*first.project, *second.project), "") << printed;
  // Printing is a fixed point.
  EXPECT_EQ(write_g7(*second.project), printed);
  return printed;
}

// ------------------------------------------------------------------------------- features

TEST(G7, DeclarationsGiveDirectionsTypesAndInitialValues) {
  const auto r = load(R"(
    project press;   # a comment
    input a, b;
    input n : 0..10;
    output V1;       // another comment
    internal k : -5..255 := 3;
    internal flag := true;
    grafcet G { step 1 initial; }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.project->name, "press");
  EXPECT_EQ(r.project->dialect, model::Dialect::Grafcet);
  EXPECT_EQ(r.project->source_format, "g7");
  const auto& p = pou_of(r);
  EXPECT_EQ(p.name, "press");
  EXPECT_EQ(p.kind, model::PouKind::Program);
  ASSERT_EQ(p.variables.size(), 6u);
  EXPECT_EQ(p.variables[0].name, "a");
  EXPECT_EQ(p.variables[0].direction, model::VarDirection::Input);
  EXPECT_EQ(p.variables[0].type.kind, model::TypeKind::Bool);
  EXPECT_EQ(p.variables[2].type.kind, model::TypeKind::Int);
  EXPECT_EQ(p.variables[2].type.lo, 0);
  EXPECT_EQ(p.variables[2].type.hi, 10);
  EXPECT_EQ(p.variables[3].direction, model::VarDirection::Output);
  EXPECT_EQ(p.variables[4].direction, model::VarDirection::Local);
  EXPECT_EQ(p.variables[4].type.lo, -5);
  EXPECT_EQ(p.variables[4].initial, 3);
  EXPECT_EQ(p.variables[5].initial, 1);
  EXPECT_EQ(p.variables[4].where.line, 6);
}

TEST(G7, ProjectNameDefaultsToTheFileStem) {
  const auto r = load_g7("grafcet G { step 1 initial; }", "/tmp/dir/pistons.g7");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.project->name, "pistons");
}

TEST(G7, StepsTransitionsAndDivergences) {
  const auto r = load(R"(
    input a, b;
    grafcet G1 {
      step 1 initial;
      step 2, 3, 4;
      transition 1: 1 -> {2, 3} when a;
      transition {2, 3} -> 4 when b;
      transition t3: 4 -> 1;
    }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& c = pou_of(r).charts.at(0);
  EXPECT_EQ(c.name, "G1");
  ASSERT_EQ(c.steps.size(), 4u);
  EXPECT_TRUE(c.steps[0].initial);
  EXPECT_FALSE(c.steps[1].initial);
  ASSERT_EQ(c.transitions.size(), 3u);
  EXPECT_EQ(c.transitions[0].name, "1");
  EXPECT_EQ(c.transitions[0].sources, std::vector<std::string>{"1"});
  EXPECT_EQ(c.transitions[0].targets, (std::vector<std::string>{"2", "3"}));
  EXPECT_EQ(c.transitions[1].name, "");
  EXPECT_EQ(c.transitions[1].sources, (std::vector<std::string>{"2", "3"}));
  EXPECT_EQ(c.transitions[1].order, 1);
  EXPECT_EQ(c.transitions[2].name, "t3");
  ASSERT_TRUE(c.transitions[2].guard);
  EXPECT_EQ(c.transitions[2].guard->kind, ExprKind::BoolConst);
  EXPECT_EQ(c.transitions[2].guard->value, 1);
  EXPECT_EQ(c.transitions[0].where.line, 6);
  EXPECT_EQ(c.transitions[0].where.column, 7);
}

TEST(G7, SourceAndSinkTransitionsAreNoted) {
  const auto r = load(
      "input a;\ngrafcet G { step 1 initial; transition {} -> 1 when RE a;\n"
      "transition 1 -> {} when FE a; }");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& c = pou_of(r).charts.at(0);
  EXPECT_TRUE(c.transitions[0].sources.empty());
  EXPECT_TRUE(c.transitions[1].targets.empty());
  int notes = 0;
  for (const auto& d : r.diagnostics) notes += d.severity == model::Severity::Note;
  EXPECT_EQ(notes, 2);
}

TEST(G7, ReceptivityOperatorsAndPrecedence) {
  const std::string decls = "input a, b, c; input n : 0..10;";
  auto g = guard(decls, "a & !b | c");
  ASSERT_TRUE(g);
  ASSERT_EQ(g->kind, ExprKind::Or);
  EXPECT_EQ(g->args[0]->kind, ExprKind::And);
  EXPECT_EQ(g->args[0]->args[1]->kind, ExprKind::Not);
  g = guard(decls, "a & (b | c)");
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args[1]->kind, ExprKind::Or);
  g = guard(decls, "a & b & c");
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args.size(), 3u);
  g = guard(decls, "n >= 3 & a");
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Ge);
  g = guard(decls, "n + 1 = 4");
  ASSERT_EQ(g->kind, ExprKind::Eq);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Add);
  for (const auto& [text, kind] :
       std::vector<std::pair<std::string, ExprKind>>{{"n < 2", ExprKind::Lt},
                                                     {"n <= 2", ExprKind::Le},
                                                     {"n > 2", ExprKind::Gt},
                                                     {"n <> 2", ExprKind::Ne},
                                                     {"n != 2", ExprKind::Ne},
                                                     {"n == 2", ExprKind::Eq}})
    EXPECT_EQ(guard(decls, text)->kind, kind) << text;
}

TEST(G7, EdgesInAsciiAndUtf8) {
  const std::string decls = "input a, b;";
  auto g = guard(decls, "RE a & FE b");
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Rising);
  EXPECT_EQ(g->args[1]->kind, ExprKind::Falling);
  auto u = guard(decls,
                 "\xE2\x86\x91"
                 "a & \xE2\x86\x93"
                 "b");  // ↑a & ↓b
  EXPECT_TRUE(model::equal(g, u));
  g = guard(decls, "RE (a & b)");
  ASSERT_EQ(g->kind, ExprKind::Rising);
  EXPECT_EQ(g->args[0]->kind, ExprKind::And);
}

TEST(G7, ConstantsOneAndZeroAreTrueAndFalse) {
  for (const auto& [text, value] : std::vector<std::pair<std::string, int>>{
           {"1", 1}, {"0", 0}, {"true", 1}, {"false", 0}, {"TRUE", 1}}) {
    const auto g = guard("", text);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->kind, ExprKind::BoolConst) << text;
    EXPECT_EQ(g->value, value) << text;
  }
  const auto g = guard("input a;", "a & 1");
  EXPECT_EQ(g->args[1]->kind, ExprKind::BoolConst);
}

TEST(G7, StepVariablesStayNamesXi) {
  const auto r = load(
      "grafcet G { step 1 initial; step 12; transition 1 -> 12 when !X12; }\n"
      "grafcet H { step 5 initial; transition 5 -> 5 when X1 & x12; }");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& g = pou_of(r).charts[0].transitions[0].guard;
  ASSERT_EQ(g->kind, ExprKind::Not);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Name);
  EXPECT_EQ(g->args[0]->name, "X12");
}

TEST(G7, Delays) {
  auto g = guard("", "2s/X1/0s");
  ASSERT_EQ(g->kind, ExprKind::Delay);
  EXPECT_EQ(g->value, 2000);
  EXPECT_EQ(g->value2, 0);
  EXPECT_EQ(g->args[0]->name, "X1");
  g = guard("input a;", "500ms/a/1min & a");
  ASSERT_EQ(g->kind, ExprKind::And);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Delay);
  EXPECT_EQ(g->args[0]->value, 500);
  EXPECT_EQ(g->args[0]->value2, 60000);
  g = guard("input a, b;", "3s/(a | b)");
  ASSERT_EQ(g->kind, ExprKind::Delay);
  EXPECT_EQ(g->value2, 0);
  EXPECT_EQ(g->args[0]->kind, ExprKind::Or);
}

TEST(G7, ContinuousActionsWithAssignmentConditions) {
  const auto r = load(R"(
    input stop; output V1, V2;
    grafcet G {
      step 1 initial; step 3;
      action 3: V1 if !stop;
      action 3: V2;
      action 1: V1;
    }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = pou_of(r);
  ASSERT_EQ(p.associations.size(), 3u);
  EXPECT_EQ(p.associations[0].chart, "G");
  EXPECT_EQ(p.associations[0].step, "3");
  EXPECT_EQ(p.associations[0].action, "V1");
  EXPECT_EQ(p.associations[0].qualifier, model::Qualifier::N);
  ASSERT_TRUE(p.associations[0].condition);
  EXPECT_EQ(p.associations[0].condition->kind, ExprKind::Not);
  EXPECT_FALSE(p.associations[1].condition);
  ASSERT_EQ(p.actions.size(), 2u);  // one Boolean-variable action per variable
  EXPECT_EQ(p.actions[0].kind, model::ActionBodyKind::Variable);
  EXPECT_EQ(p.actions[0].variable, "V1");
}

TEST(G7, StoredActionsOnActivationDeactivationAndEvent) {
  const auto r = load(R"(
    input b; output V2; internal k : 0..10; internal count : 0..100;
    grafcet G {
      step 1 initial; step 3;
      action 3 on_enter: k := 1;
      action 3 on_exit: V2 := 0;
      action 3 on RE b: count := count + 1;
      action 1 on_enter: V2 := true;
    }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& s = pou_of(r).stored_actions;
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].when, model::StoredWhen::Activation);
  EXPECT_EQ(s[0].variable, "k");
  EXPECT_EQ(s[0].value->kind, ExprKind::IntConst);
  EXPECT_EQ(s[1].when, model::StoredWhen::Deactivation);
  EXPECT_EQ(s[1].value->kind, ExprKind::BoolConst);  // Boolean variable: 0 is false
  EXPECT_EQ(s[1].value->value, 0);
  EXPECT_EQ(s[2].when, model::StoredWhen::Event);
  ASSERT_TRUE(s[2].event);
  EXPECT_EQ(s[2].event->kind, ExprKind::Rising);
  EXPECT_EQ(s[2].value->kind, ExprKind::Add);
  EXPECT_EQ(s[3].value->kind, ExprKind::BoolConst);
  EXPECT_EQ(s[3].value->value, 1);
}

TEST(G7, ForcingOrders) {
  const auto r = load(R"(
    grafcet G1 {
      step 1 initial; step 2; step 3; step 4;
      action 1: G7{5, 6};
      action 2: G7{*};
      action 3: G7{INIT};
      action 4: G7{};
    }
    grafcet G7 { step 5 initial; step 6; }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& f = pou_of(r).forcing_orders;
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0].chart, "G1");
  EXPECT_EQ(f[0].step, "1");
  EXPECT_EQ(f[0].target, "G7");
  EXPECT_EQ(f[0].kind, model::ForcingKind::Situation);
  EXPECT_EQ(f[0].situation, (std::vector<std::string>{"5", "6"}));
  EXPECT_EQ(f[1].kind, model::ForcingKind::Current);
  EXPECT_EQ(f[2].kind, model::ForcingKind::Initial);
  EXPECT_EQ(f[3].kind, model::ForcingKind::Empty);
  EXPECT_TRUE(f[3].situation.empty());
}

TEST(G7, MacroStepsAndTheirExpansion) {
  const auto r = load(R"(
    input a, b;
    grafcet G { step 1 initial; step M2 macro EM2; step 3;
                transition 1 -> M2 when a; transition M2 -> 3 when b; }
    grafcet EM2 { step E2 entry; step 21; step S2 exit;
                  transition E2 -> 21; transition 21 -> S2 when a; }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = pou_of(r);
  EXPECT_EQ(p.charts[0].steps[1].kind, model::StepKind::MacroStep);
  EXPECT_EQ(p.charts[0].steps[1].expansion, "EM2");
  EXPECT_EQ(p.charts[1].macro_entry, "E2");
  EXPECT_EQ(p.charts[1].macro_exit, "S2");
}

TEST(G7, EnclosingStepsAndActivationLinks) {
  const auto r = load(R"(
    grafcet G1 { step 1 initial; step 6 encloses {G2, G3}; step 7 encloses G2; step 8 encloses {}; }
    grafcet G2 { step 21 linked; step 22; transition 21 -> 22; }
    grafcet G3 { step 31 initial linked; }
  )");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = pou_of(r);
  EXPECT_EQ(p.charts[0].steps[1].kind, model::StepKind::Enclosing);
  EXPECT_EQ(p.charts[0].steps[1].enclosed, (std::vector<std::string>{"G2", "G3"}));
  EXPECT_EQ(p.charts[0].steps[2].enclosed, std::vector<std::string>{"G2"});
  EXPECT_EQ(p.charts[0].steps[3].kind, model::StepKind::Enclosing);
  EXPECT_TRUE(p.charts[0].steps[3].enclosed.empty());
  EXPECT_TRUE(p.charts[1].steps[0].activation_link);
  EXPECT_FALSE(p.charts[1].steps[1].activation_link);
  EXPECT_TRUE(p.charts[2].steps[0].initial);
  EXPECT_TRUE(p.charts[2].steps[0].activation_link);
}

TEST(G7, QuotedNamesAndReservedWords) {
  const auto r = load(
      "input \"RE\", \"my var\";\n"
      "grafcet \"main line\" { step \"1a\" initial; transition \"1a\" -> \"1a\" "
      "when \"RE\" & RE \"my var\"; }");
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& c = pou_of(r).charts[0];
  EXPECT_EQ(c.name, "main line");
  EXPECT_EQ(c.steps[0].name, "1a");
  EXPECT_EQ(c.transitions[0].guard->args[0]->name, "RE");
  EXPECT_EQ(c.transitions[0].guard->args[1]->kind, ExprKind::Rising);
}

// ----------------------------------------------------------------------------------- errors

TEST(G7Errors, LocatedAtLineAndColumn) {
  EXPECT_EQ(first_error("input a;\ngrafcet G {\n  step 1 initial;\n  transition 1 -> 2 when a;\n}"),
            "4:19: undeclared step '2' in grafcet 'G'");
  EXPECT_EQ(
      first_error("input a;\ngrafcet G { step 1 initial;\n  transition 1 -> 1 when a & bb; }"),
      "3:30: unknown name 'bb' (not a declared variable nor a step variable X<step>)");
  EXPECT_EQ(first_error("input a\ngrafcet G { step 1 initial; }"),
            "2:1: expected ';', found 'grafcet'");
  EXPECT_EQ(first_error("input a;\ngrafcet G { step 1 initial; action 1 on_enter: a := 1; }"),
            "2:48: the input 'a' cannot be assigned by an action");
  EXPECT_EQ(first_error("grafcet G { step 1 initial;\n step 1; }"),
            "2:7: step '1' is declared twice in grafcet 'G'");
  EXPECT_EQ(first_error("input a; input a;"), "1:16: variable 'a' is declared twice");
  EXPECT_EQ(first_error("internal k : 5..1;"), "1:14: empty integer range 5..1");
  EXPECT_EQ(first_error("grafcet G { step 1 initial; transition 1 -> 1 when 2; }"),
            "1:52: the integer 2 is not a condition");
  EXPECT_EQ(first_error("input a;\ngrafcet G { step 1 initial; transition 1 -> 1 when a $ a; }"),
            "2:54: unexpected character '$'");
  EXPECT_EQ(first_error("grafcet G { step 1 initial; transition 1 -> 1 when RE; }"),
            "1:54: expected an expression, found ';'");
  EXPECT_EQ(first_error("grafcet G { step 1; action 1: H{1}; }"),
            "1:31: undeclared partial grafcet 'H'");
  EXPECT_EQ(first_error("grafcet G { step 1; action 1: G{9}; }"),
            "1:33: forced step '9' is not a step of grafcet 'G'");
  EXPECT_EQ(first_error("internal k : 0..3;\ngrafcet G { step 1; action 1: k; }"),
            "2:31: the continuous action 'k' needs a Boolean variable");
  EXPECT_EQ(first_error("grafcet G { step 1 initial;"), "1:28: missing '}' closing grafcet 'G'");
  EXPECT_EQ(first_error("input n : 0..3;\ngrafcet G { step 1; transition 1 -> 1 when n < 1 < 2; }"),
            "2:50: comparisons do not chain: add parentheses");
  EXPECT_EQ(first_error("grafcet G { step 1; transition 1 -> 1 when 2x; }"),
            "1:44: invalid number '2x' (durations end in ms, s, min or h; quote names that start "
            "with a digit)");
  EXPECT_EQ(first_error("grafcet G { step M macro E; } grafcet E { step 1; }"),
            "1:18: the expansion 'E' of macro-step 'M' needs an entry step and an exit step");
  EXPECT_EQ(first_error("step 1;"),
            "1:1: expected 'project', 'input', 'output', 'internal' or 'grafcet', found 'step'");
}

TEST(G7Errors, AmbiguousStepVariable) {
  EXPECT_EQ(first_error("grafcet G { step 1 initial; transition 1 -> 1 when X1; }\n"
                        "grafcet H { step 1 initial; }"),
            "1:52: step variable 'X1' is ambiguous: several partial grafcets have a step '1'");
  // A declared variable named X1 is the variable.
  const auto r = load(
      "input X1;\ngrafcet G { step 1 initial; transition 1 -> 1 when X1; }\n"
      "grafcet H { step 1 initial; }");
  EXPECT_TRUE(r.ok()) << messages(r);
}

TEST(G7, TheDocumentationExampleLoads) {
  std::ifstream in(test::source_path("docs/formats.md"));
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string md = ss.str();
  const auto section = md.find("### A complete example");
  ASSERT_NE(section, std::string::npos);
  const auto begin = md.find("```\n", section) + 4;
  const auto end = md.find("```", begin);
  const auto r = load(md.substr(begin, end - begin));
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& p = pou_of(r);
  EXPECT_EQ(p.charts.size(), 2u);
  EXPECT_EQ(p.forcing_orders.size(), 1u);
  EXPECT_EQ(p.stored_actions.size(), 1u);
  ASSERT_TRUE(p.associations.at(1).condition);
  round_trip(md.substr(begin, end - begin));
}

TEST(G7Errors, SeveralErrorsAreAllReportedAndNoModelIsReturned) {
  const auto r = load(
      "input a;\ngrafcet G {\n step 1 initial;\n transition 1 -> 2 when a;\n"
      " transition 1 -> 1 when zz;\n bogus;\n}");
  EXPECT_FALSE(r.project.has_value());
  int errors = 0;
  for (const auto& d : r.diagnostics) {
    errors += d.severity == model::Severity::Error;
    EXPECT_EQ(d.where.file, "t.g7");
  }
  EXPECT_EQ(errors, 3) << messages(r);
}

// ------------------------------------------------------------------------------- round trip

TEST(G7RoundTrip, EveryFeature) {
  const std::string printed = round_trip(R"(
    project all_features;
    input a, b, stop; input n : 0..10;
    output V1, V2 := true;
    internal k : 0..255 := 0;
    grafcet G1 {
      step 1 initial; step 2, 3; step 4 encloses {G2, G3}; step M5 macro EM5; step 6;
      transition 1: 1 -> {2, 3} when RE a & !(b | n > 3);
      transition 2: {2, 3} -> 4 when 2s/X2/500ms | FE stop;
      transition 3: 4 -> M5 when (a & b) & n + 1 = 4;
      transition 4: M5 -> 6 when a & (b & stop);
      transition 6 -> 1 when X22 ^ a;
      transition {} -> 6 when RE b;
      transition 6 -> {} when n - (n - 1) <> -1;
      action 2: V1 if !stop & a;
      action 3: V1;
      action 2 on_enter: k := k + 1;
      action 3 on_exit: V2 := 0;
      action 6 on RE a | FE b: k := (k + 2) * 3 - 1;
      action 1: G2{INIT};
      action 6: G2{21, 22};
      action 6: G3{*};
      action 1: G3{};
    }
    grafcet G2 { step 21 initial linked; step 22; transition 21 -> 22 when -n < -(3); }
    grafcet G3 { step 31 linked; }
    grafcet EM5 { step E5 entry; step S5 exit; transition E5 -> S5 when true; }
  )");
  EXPECT_NE(printed.find("transition 1: 1 -> {2, 3} when RE a & !(b | n > 3);"), std::string::npos)
      << printed;
  EXPECT_NE(printed.find("step 4 encloses {G2, G3};"), std::string::npos) << printed;
  EXPECT_NE(printed.find("2s/X2/500ms"), std::string::npos) << printed;
  EXPECT_NE(printed.find("when (a & b) & n + 1 = 4;"), std::string::npos) << printed;
  EXPECT_NE(printed.find("when a & (b & stop);"), std::string::npos) << printed;
}

TEST(G7RoundTrip, QuotedNames) {
  round_trip(
      "input \"RE\", \"my var\"; internal \"3x\" : 0..3;\n"
      "grafcet \"main line\" { step \"1a\" initial; step \"true\";\n"
      " transition \"1a\" -> \"true\" when \"RE\" & RE \"my var\" & \"3x\" = 2; }");
}

TEST(G7RoundTrip, StepsNamedLikeKeywords) {
  const std::string printed = round_trip(
      "grafcet G { step initial initial; step INIT, when, on_enter;\n"
      " transition when: initial -> when when X_when_ | Xwhen;\n"
      " transition {when, INIT} -> on_enter; action initial: G{INIT}; action when: G{\"INIT\"}; }\n"
      "input X_when_;");
  EXPECT_NE(printed.find("action when: G{\"INIT\"};"), std::string::npos) << printed;
  EXPECT_NE(printed.find("action initial: G{INIT};"), std::string::npos) << printed;
}

TEST(G7Errors, DuplicatePartialGrafcetKeepsLaterErrorsPrecise) {
  const auto r = load("grafcet G { step 1; }\ngrafcet G { step 1;\n transition 1 -> 9; }");
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].message, "partial grafcet 'G' is declared twice");
  EXPECT_EQ(r.diagnostics[0].where.line, 2);
  EXPECT_EQ(r.diagnostics[1].where.line, 3);
  EXPECT_EQ(r.diagnostics[1].where.column, 18);
}

TEST(G7RoundTrip, SmallSequence) {
  const std::string printed = round_trip(
      "input a;\noutput V;\ngrafcet G { step 0 initial; step 1; transition 0 -> 1 when a;\n"
      " transition 1 -> 0 when !a; action 1: V; }");
  EXPECT_EQ(printed,
            "# Grafcet (IEC 60848) in the sfcv native format, see docs/formats.md\n"
            "project t;\n\n"
            "input a;\n"
            "output V;\n\n"
            "grafcet G {\n"
            "  step 0 initial;\n"
            "  step 1;\n"
            "  transition 0 -> 1 when a;\n"
            "  transition 1 -> 0 when !a;\n"
            "  action 1: V;\n"
            "}\n");
}

TEST(G7RoundTrip, ExamplesShippedWithSfcv) {
  for (const char* path :
       {"examples/pistons/pistons.g7", "examples/pallet_transfer/pallet_transfer.g7",
        "examples/pallet_transfer/pallet_transfer_fixed.g7"}) {
    const auto r = load_file(test::source_path(path));
    ASSERT_TRUE(r.ok()) << path << "\n" << messages(r);
    const std::string printed = write_g7(*r.project);
    const auto again = load_g7(printed, path);
    ASSERT_TRUE(again.ok()) << messages(again) << printed;
    EXPECT_EQ(test::grafcet_difference(*r.project, *again.project), "") << path;
  }
}

TEST(G7Examples, PalletTransferFixDiffersOnlyInTransition15) {
  const auto flawed = load_file(test::source_path("examples/pallet_transfer/pallet_transfer.g7"));
  const auto fixed =
      load_file(test::source_path("examples/pallet_transfer/pallet_transfer_fixed.g7"));
  ASSERT_TRUE(flawed.ok() && fixed.ok()) << messages(flawed) << messages(fixed);
  const auto& p = flawed.project->pous[0];
  ASSERT_EQ(p.charts.size(), 4u);
  std::vector<std::string> initial;
  std::size_t steps = 0;
  for (const auto& c : p.charts)
    for (const auto& s : c.steps) {
      ++steps;
      if (s.initial) initial.push_back(s.name);
    }
  EXPECT_EQ(steps, 24u);  // "the grafcet has only 24 steps"
  EXPECT_EQ(initial, (std::vector<std::string>{"1", "20", "30", "40"}));
  EXPECT_EQ(model::count_transitions(*flawed.project), 25u);
  // Same model once transition 15 gets the fixed receptivity (and the project its name).
  model::Project patched = *flawed.project;
  patched.name = fixed.project->name;
  patched.pous[0].name = fixed.project->pous[0].name;
  auto& t15 = patched.pous[0].charts[1].transitions[4];
  ASSERT_EQ(t15.name, "15");
  EXPECT_EQ(model::to_st(t15.guard), "NOT X10");
  t15.guard = fixed.project->pous[0].charts[1].transitions[4].guard;
  EXPECT_EQ(model::to_st(t15.guard), "NOT X10 AND NOT X9");
  EXPECT_EQ(test::grafcet_difference(patched, *fixed.project), "");
}

TEST(G7Writer, RefusesWhatTheFormatCannotExpress) {
  auto r = load("output V;\ngrafcet G { step 1 initial; action 1: V; }");
  ASSERT_TRUE(r.ok());
  model::Project p = *r.project;
  p.pous[0].associations[0].qualifier = model::Qualifier::S;
  EXPECT_THROW(write_g7(p), G7WriteError);
  p = *r.project;
  p.pous[0].variables[0].type = model::Type::time();
  EXPECT_THROW(write_g7(p), G7WriteError);
  p = *r.project;
  p.pous.push_back(p.pous[0]);
  EXPECT_THROW(write_g7(p), G7WriteError);
  p = *r.project;
  p.pous[0].charts[0].parent_action = "A";
  EXPECT_THROW(write_g7(p), G7WriteError);
}

}  // namespace
}  // namespace sfcv::io

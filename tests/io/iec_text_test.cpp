#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/iec_text_writer.hpp"
#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/errors.hpp"
#include "model/names.hpp"
#include "round_trip.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::io {
namespace {

std::string all(const model::Diagnostics& d) {
  std::string s;
  for (const auto& x : d) s += x.str() + "\n";
  return s;
}

model::Project load_ok(std::string_view text, const std::string& file = "t.sfc") {
  auto r = load_iec_text(text, file);
  EXPECT_TRUE(r.ok()) << all(r.diagnostics);
  if (!r.project) return {};
  return *r.project;
}

// The errors of a text that must fail, one "line:col: message" per line.
std::string errors(std::string_view text) {
  auto r = load_iec_text(text, "bad.sfc");
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.project.has_value());
  std::string s;
  for (const auto& d : r.diagnostics) {
    if (d.severity != model::Severity::Error) continue;
    EXPECT_EQ(d.where.file, "bad.sfc");
    s += std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + ": " + d.message +
         "\n";
  }
  return s;
}

// Prints, re-loads and compares; returns the printed text.
std::string round_trip(const model::Project& p) {
  return test::iec_round_trip(p);
}

const char* const kFeatures = R"((* all features of the textual form *)
FUNCTION_BLOCK Press
  VAR_INPUT start, stop : BOOL; level : INT(0..10) := 3; END_VAR
  VAR_OUTPUT motor AT %QX0.1 : BOOL := TRUE; lamp : BOOL; END_VAR
  VAR delta_1 : TIME := T#1s; t1 : TON; n : INT := -2; END_VAR

  INITIAL_STEP Idle:
    Reset(P); lamp;
  END_STEP

  TRANSITION go (PRIORITY := 2) FROM Idle TO (Run, Watch)
    := start AND NOT stop;
  END_TRANSITION

  TRANSITION FROM Idle TO Fault := level > 9; END_TRANSITION

  STEP Run:
    motor(N);
    Beep(L, T#2s);
    Beep(D, delta_1, lamp, motor);
    Count(S);
  END_STEP

  STEP Watch: Sub(N); END_STEP
  STEP Fault: END_STEP

  TRANSITION FROM (Run, Watch) TO Idle := Run.T > T#1m30s OR stop; END_TRANSITION
  TRANSITION done FROM Fault TO Idle :
    done := NOT start;
  END_TRANSITION

  ACTION Reset: n := 0; t1(IN := FALSE, PT := T#5s); END_ACTION
  ACTION Beep:
    IF n < 5 THEN lamp := TRUE; ELSE lamp := FALSE; END_IF;
  END_ACTION
  ACTION Count:
    CASE n OF 0: n := 1; 1..4: n := n + 1; ELSE n := 0; END_CASE;
  END_ACTION
  ACTION Sub:
    INITIAL_STEP S0: Blink(N); END_STEP
    TRANSITION FROM S0 TO S1 := t1.Q; END_TRANSITION
    STEP S1: END_STEP
    TRANSITION FROM S1 TO S0 := TRUE; END_TRANSITION
  END_ACTION
  ACTION Blink: lamp := NOT lamp; END_ACTION
END_FUNCTION_BLOCK

FUNCTION Helper : BOOL
  VAR_INPUT x : BOOL; END_VAR
  Helper := x;
END_FUNCTION

PROGRAM Main
  VAR t : TON; done : BOOL; END_VAR
  t(IN := NOT done, PT := T#1s);
  done := t.Q;
END_PROGRAM

CONFIGURATION Conf
  RESOURCE Res ON PLC
    TASK Cyclic(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM Inst WITH Cyclic : Main;
  END_RESOURCE
END_CONFIGURATION
)";

TEST(IecText, LoadsEveryFeature) {
  auto r = load_iec_text(kFeatures, "f.sfc");
  ASSERT_TRUE(r.ok()) << all(r.diagnostics);
  const auto& p = *r.project;
  EXPECT_EQ(p.source_format, "iec-text");
  ASSERT_EQ(p.pous.size(), 3u);  // CONFIGURATION is skipped ...
  int notes = 0;
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Note) ++notes;
  EXPECT_EQ(notes, 1);  // ... with a note
  // A FUNCTION's result is the output variable named like it.
  const auto& helper = p.pous[1];
  EXPECT_EQ(helper.kind, model::PouKind::Function);
  ASSERT_NE(helper.find_variable("Helper"), nullptr);
  EXPECT_EQ(helper.find_variable("Helper")->direction, model::VarDirection::Output);
  EXPECT_EQ(helper.find_variable("Helper")->type.kind, model::TypeKind::Bool);
  const auto& fb = p.pous[0];
  EXPECT_EQ(fb.kind, model::PouKind::FunctionBlock);
  EXPECT_EQ(fb.name, "Press");
  ASSERT_EQ(fb.variables.size(), 8u);
  EXPECT_EQ(fb.find_variable("level")->type, model::Type::integer("INT(0..10)", 0, 10));
  EXPECT_EQ(fb.find_variable("motor")->address, "%QX0.1");
  EXPECT_EQ(fb.find_variable("motor")->direction, model::VarDirection::Output);
  EXPECT_EQ(fb.find_variable("delta_1")->initial, 1000);
  EXPECT_EQ(fb.find_variable("n")->initial, -2);

  ASSERT_EQ(fb.charts.size(), 2u);
  const auto& top = fb.charts[0];
  EXPECT_EQ(top.name, "Press");
  EXPECT_TRUE(top.parent_action.empty());
  ASSERT_EQ(top.steps.size(), 4u);
  EXPECT_TRUE(top.steps[0].initial);
  EXPECT_EQ(top.steps[0].name, "Idle");
  EXPECT_EQ(top.steps[0].where.line, 7);
  EXPECT_EQ(top.steps[0].where.column, 3);
  EXPECT_FALSE(top.steps[1].initial);
  ASSERT_EQ(top.transitions.size(), 4u);
  const auto& go = top.transitions[0];
  EXPECT_EQ(go.name, "go");
  EXPECT_EQ(go.priority, 2);
  EXPECT_EQ(go.order, 0);
  EXPECT_EQ(go.sources, std::vector<std::string>{"Idle"});
  EXPECT_EQ(go.targets, (std::vector<std::string>{"Run", "Watch"}));
  EXPECT_EQ(model::to_st(go.guard), "start AND NOT stop");
  EXPECT_FALSE(top.transitions[1].priority.has_value());
  EXPECT_EQ(top.transitions[1].order, 1);
  EXPECT_EQ(top.transitions[2].sources, (std::vector<std::string>{"Run", "Watch"}));
  EXPECT_EQ(model::to_st(top.transitions[2].guard), "Run.T > T#90s OR stop");
  EXPECT_EQ(top.transitions[3].name, "done");
  EXPECT_EQ(model::to_st(top.transitions[3].guard), "NOT start");

  // Associations, in document order.
  ASSERT_EQ(fb.associations.size(), 8u);
  const auto& a = fb.associations;
  EXPECT_EQ(a[0].step, "Idle");
  EXPECT_EQ(a[0].chart, "Press");
  EXPECT_EQ(a[0].qualifier, model::Qualifier::P);
  EXPECT_EQ(a[1].action, "lamp");  // no qualifier: N
  EXPECT_EQ(a[1].qualifier, model::Qualifier::N);
  EXPECT_EQ(a[3].qualifier, model::Qualifier::L);
  EXPECT_EQ(a[3].duration_ms, 2000);
  EXPECT_EQ(a[4].qualifier, model::Qualifier::D);
  EXPECT_FALSE(a[4].duration_ms.has_value());
  EXPECT_EQ(a[4].duration_variable, "delta_1");
  EXPECT_EQ(a[4].indicator, "lamp");  // the first of the indicators
  EXPECT_EQ(a[5].qualifier, model::Qualifier::S);
  EXPECT_EQ(a[7].chart, "Sub");
  EXPECT_EQ(a[7].step, "S0");

  // Actions: declared ones, then the Boolean-variable actions named by steps.
  const auto* reset = fb.find_action("Reset");
  ASSERT_NE(reset, nullptr);
  EXPECT_EQ(reset->kind, model::ActionBodyKind::Statements);
  ASSERT_EQ(reset->body.size(), 2u);
  EXPECT_EQ(reset->body[1]->kind, model::StmtKind::FbCall);
  EXPECT_EQ(fb.find_action("Beep")->body[0]->kind, model::StmtKind::If);
  EXPECT_EQ(fb.find_action("Count")->body[0]->kind, model::StmtKind::Case);
  const auto* sub = fb.find_action("Sub");
  ASSERT_NE(sub, nullptr);
  EXPECT_EQ(sub->kind, model::ActionBodyKind::Chart);
  ASSERT_EQ(sub->chart, 1);
  EXPECT_EQ(fb.charts[1].parent_action, "Sub");
  EXPECT_EQ(fb.charts[1].steps.size(), 2u);
  EXPECT_EQ(fb.charts[1].transitions.size(), 2u);
  EXPECT_EQ(fb.charts[1].transitions[1].order, 1);
  for (const char* v : {"lamp", "motor"}) {
    const auto* x = fb.find_action(v);
    ASSERT_NE(x, nullptr) << v;
    EXPECT_EQ(x->kind, model::ActionBodyKind::Variable);
    EXPECT_EQ(x->variable, v);
  }
  EXPECT_EQ(fb.actions.size(), 7u);

  const auto& main = p.pous[2];
  EXPECT_EQ(main.kind, model::PouKind::Program);
  EXPECT_FALSE(main.has_sfc());
  ASSERT_EQ(main.body.size(), 2u);
  EXPECT_EQ(main.body[0]->kind, model::StmtKind::FbCall);
}

TEST(IecText, PrintsAndReloadsEveryFeature) {
  const auto p = load_ok(kFeatures);
  const std::string text = round_trip(p);
  EXPECT_NE(text.find("TRANSITION go (PRIORITY := 2) FROM Idle TO (Run, Watch)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("Beep(D, delta_1, lamp);"), std::string::npos) << text;
  EXPECT_NE(text.find("level : INT(0..10) := 3;"), std::string::npos) << text;
  EXPECT_NE(text.find("motor AT %QX0.1 : BOOL := TRUE;"), std::string::npos) << text;
  EXPECT_NE(text.find("FUNCTION Helper : BOOL\n  VAR_INPUT\n    x : BOOL;\n  END_VAR\n"),
            std::string::npos)
      << text;
}

TEST(IecText, QualifierNamesAreLegalStepAndActionNames) {
  const auto p = load_ok(R"(
PROGRAM q
  VAR x : BOOL; END_VAR
  INITIAL_STEP N: S(S); D(D, T#1s); END_STEP
  STEP S: N(N); L(L, T#2s); P(); SD; END_STEP
  TRANSITION N (PRIORITY := 1) FROM N TO S := x; END_TRANSITION
  TRANSITION FROM S TO N := NOT x; END_TRANSITION
  ACTION S: x := TRUE; END_ACTION
  ACTION D: x := FALSE; END_ACTION
  ACTION N: ; END_ACTION
  ACTION L: ; END_ACTION
  ACTION P: ; END_ACTION
  ACTION SD: ; END_ACTION
END_PROGRAM
)");
  ASSERT_EQ(p.pous.size(), 1u);
  const auto& pou = p.pous[0];
  ASSERT_EQ(pou.charts[0].steps.size(), 2u);
  EXPECT_EQ(pou.charts[0].steps[0].name, "N");
  EXPECT_EQ(pou.charts[0].transitions[0].name, "N");
  ASSERT_EQ(pou.associations.size(), 6u);
  EXPECT_EQ(pou.associations[0].action, "S");
  EXPECT_EQ(pou.associations[0].qualifier, model::Qualifier::S);
  EXPECT_EQ(pou.associations[1].action, "D");
  EXPECT_EQ(pou.associations[1].qualifier, model::Qualifier::D);
  EXPECT_EQ(pou.associations[4].action, "P");
  EXPECT_EQ(pou.associations[4].qualifier, model::Qualifier::N);
  EXPECT_EQ(pou.associations[5].action, "SD");
  round_trip(p);
}

TEST(IecText, KeepsWhatValidationMustReport) {
  // Duplicate steps, undeclared targets, undeclared actions and a second initial step are
  // semantic matters: loading keeps them as written.
  const auto p = load_ok(R"(
PROGRAM v
  VAR x : BOOL; END_VAR
  TRANSITION FROM A TO Later := x; END_TRANSITION
  INITIAL_STEP A: Ghost(N); END_STEP
  STEP A: END_STEP
  STEP Later: END_STEP
  TRANSITION FROM Later TO Nowhere := TRUE; END_TRANSITION
  INITIAL_STEP B: END_STEP
  TRANSITION FROM B TO B := x; END_TRANSITION
END_PROGRAM
)");
  const auto& pou = p.pous[0];
  ASSERT_EQ(pou.charts.size(), 1u);  // several sequences, one chart
  ASSERT_EQ(pou.charts[0].steps.size(), 4u);
  EXPECT_EQ(pou.charts[0].steps[1].name, "A");
  EXPECT_EQ(pou.charts[0].transitions[1].targets[0], "Nowhere");
  EXPECT_EQ(pou.associations.size(), 1u);
  EXPECT_EQ(pou.associations[0].action, "Ghost");
  EXPECT_TRUE(pou.actions.empty());
  round_trip(p);
}

TEST(IecText, SyntaxErrorsAreLocated) {
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a:\n    act(X);\n  END_STEP\nEND_PROGRAM\n"),
            "3:9: expected an action qualifier (N, R, S, P, P0, P1, L, D, SD, DS, SL, DL), found "
            "'X'\n");
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: act(L); END_STEP\nEND_PROGRAM\n"),
            "2:23: qualifier L needs a duration\n");
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: act(N, T#1s); END_STEP\nEND_PROGRAM\n"),
            "2:26: qualifier N takes no duration\n");
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: act(D, 5); END_STEP\nEND_PROGRAM\n"),
            "2:26: expected a TIME literal or a TIME variable as duration, found '5'\n");
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: END_STEP\n  TRANSITION FROM a TO a x; "
                   "END_TRANSITION\nEND_PROGRAM\n"),
            "3:26: expected ':=' and the transition condition, found 'x'\n");
  EXPECT_EQ(errors("PROGRAM p\n  TRANSITION FROM a := x; END_TRANSITION\nEND_PROGRAM\n"),
            "2:21: expected TO, found ':='\n");
  EXPECT_EQ(errors("PROGRAM p\n  TRANSITION FROM a TO b := x AND; END_TRANSITION\nEND_PROGRAM\n"),
            "2:34: expected an expression, found ';'\n");
  EXPECT_EQ(errors("PROGRAM p\n  ACTION a:\n    JMP lbl;\n  END_ACTION\nEND_PROGRAM\n"),
            "3:5: unsupported: JMP statement\n");
  EXPECT_EQ(
      errors("PROGRAM p\n  VAR r : REAL; END_VAR\n  INITIAL_STEP a: END_STEP\nEND_PROGRAM\n"),
      "2:11: unsupported type REAL "
      "(sfcv models BOOL, integers, TIME, STRING, enumerations, arrays, structures and FBs)\n");
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: END_STEP\n"),
            "3:1: expected END_PROGRAM, found end of text\n");
  EXPECT_EQ(
      errors("PROGRAM p\n  TRANSITION FROM a TO b : x := TRUE; END_TRANSITION\nEND_PROGRAM\n"),
      "2:26: unsupported: transition body other than '<transition name> := <condition>;'\n");
  // A function's outputs bound in a transition body would be writes of a condition.
  EXPECT_EQ(errors("PROGRAM p\n  TRANSITION t1 FROM a TO b : t1 := F(x := 1, q => z); "
                   "END_TRANSITION\nEND_PROGRAM\n"),
            "2:29: unsupported: transition body other than '<transition name> := <condition>;'\n");
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: END_STEP\n  € \nEND_PROGRAM\n"),
            "3:3: unexpected character '\\xE2'\n");
  // Lexical errors are all reported, without the parse errors they would cause.
  EXPECT_EQ(errors("PROGRAM p\n  INITIAL_STEP a: ? END_STEP\n  TRANSITION FROM a TO a := T#1; "
                   "END_TRANSITION\nEND_PROGRAM\n"),
            "2:19: unexpected character '?'\n3:29: TIME literal: missing unit (d, h, m, s, ms)\n");
  EXPECT_EQ(
      errors("STEP a: END_STEP"),
      "1:1: expected PROGRAM, FUNCTION_BLOCK, FUNCTION, CONFIGURATION or TYPE, found 'STEP'\n");
  EXPECT_EQ(errors(""), "0:0: no PROGRAM, FUNCTION_BLOCK or FUNCTION in the file\n");
  EXPECT_EQ(errors("PROGRAM p\n  ACTION a: x := T#1s2; END_ACTION\nEND_PROGRAM\n"),
            "2:18: TIME literal: missing unit (d, h, m, s, ms)\n");
}

TEST(IecText, RecoversToReportSeveralErrors) {
  EXPECT_EQ(
      errors(R"(PROGRAM p
  INITIAL_STEP a: act(Q); END_STEP
  STEP b: END_STEP
  TRANSITION FROM a TO b := ; END_TRANSITION
  ACTION act: x := 1 END_ACTION
END_PROGRAM
FUNCTION_BLOCK ok
  INITIAL_STEP s: END_STEP
  TRANSITION FROM s TO s := TRUE END_TRANSITION
END_FUNCTION_BLOCK
)"),
      "2:23: expected an action qualifier (N, R, S, P, P0, P1, L, D, SD, DS, SL, DL), found 'Q'\n"
      "4:29: expected an expression, found ';'\n"
      "5:22: expected ';' after the assignment, found 'END_ACTION'\n");
}

TEST(IecText, WriterRejectsWhatIecTextCannotSay) {
  auto p = load_ok(
      "PROGRAM p\n VAR x : BOOL; END_VAR\n INITIAL_STEP a: END_STEP\n"
      " TRANSITION FROM a TO a := x; END_TRANSITION\nEND_PROGRAM\n");
  auto expect_throw = [](const model::Project& q, const std::string& what) {
    try {
      write_iec_text(q);
      ADD_FAILURE() << "no exception for " << what;
    } catch (const sfcv::UnsupportedConstruct& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  {
    auto q = p;
    model::StoredAction s;
    s.chart = "p";
    s.step = "a";
    s.variable = "x";
    s.value = model::make_int(1);
    q.pous[0].stored_actions.push_back(s);
    expect_throw(q, "stored actions");
  }
  {
    auto q = p;
    q.pous[0].forcing_orders.push_back(model::ForcingOrder{});
    expect_throw(q, "forcing orders");
  }
  {
    auto q = p;
    q.pous[0].charts[0].steps[0].kind = model::StepKind::MacroStep;
    expect_throw(q, "macro-step");
  }
  {
    auto q = p;
    q.pous[0].charts[0].transitions[0].guard =
        model::make_unary(model::ExprKind::Rising, model::make_name("x"));
    expect_throw(q, "rising edge");
  }
  {
    auto q = p;
    model::ActionAssociation a;
    a.chart = "p";
    a.step = "a";
    a.action = "x";
    a.qualifier = model::Qualifier::L;
    q.pous[0].associations.push_back(a);
    expect_throw(q, "without a duration");
    q.pous[0].associations[0].step = "zz";
    q.pous[0].associations[0].qualifier = model::Qualifier::N;
    expect_throw(q, "does not exist");
  }
  {
    auto q = p;
    q.pous[0].charts[0].steps[0].name = "has space";
    expect_throw(q, "not an IEC identifier");
  }
  {
    auto q = p;
    q.dialect = model::Dialect::Grafcet;
    expect_throw(q, "Grafcet");
  }
  {
    // Printing an empty action would run a no-op where the semantics must refuse.
    auto q = p;
    model::Action a;
    a.name = "Opaque";
    a.body_unsupported = true;
    q.pous[0].actions.push_back(a);
    expect_throw(q, "action 'Opaque', whose body sfcv does not model");
  }
  {
    // A Boolean action is printed as the association naming its variable: it needs one.
    auto q = p;
    model::Action a;
    a.name = "x";
    a.kind = model::ActionBodyKind::Variable;
    a.variable = "x";
    q.pous[0].actions.push_back(a);
    expect_throw(q, "action 'x' standing for variable 'x'");
  }
}

TEST(Compare, FindsStructuralDifferences) {
  const char* base = R"(
PROGRAM p
  VAR x, y : BOOL; END_VAR
  INITIAL_STEP a: act(N); END_STEP
  STEP b: END_STEP
  TRANSITION FROM a TO b := x; END_TRANSITION
  TRANSITION FROM a TO a := y; END_TRANSITION
  TRANSITION FROM b TO a := TRUE; END_TRANSITION
  ACTION act: x := NOT x; END_ACTION
END_PROGRAM
)";
  const auto p = load_ok(base);
  EXPECT_FALSE(model::first_difference(p, p).has_value());
  // Step order, letter case and the order of independent transitions do not matter.
  const auto reordered = load_ok(R"(
PROGRAM P
  VAR y, X : BOOL; END_VAR
  TRANSITION FROM B TO A := TRUE; END_TRANSITION
  STEP b: END_STEP
  TRANSITION FROM a TO b := x; END_TRANSITION
  INITIAL_STEP a: act(N); END_STEP
  TRANSITION FROM a TO a := y; END_TRANSITION
  ACTION act: x := NOT x; END_ACTION
END_PROGRAM
)");
  EXPECT_EQ(model::first_difference(p, reordered), std::nullopt);
  auto differs = [&](auto change, const std::string& expected) {
    auto q = p;
    change(q.pous[0]);
    const auto d = model::first_difference(p, q);
    ASSERT_TRUE(d.has_value()) << expected;
    EXPECT_EQ(*d, expected);
  };
  differs([](model::Pou& u) { u.charts[0].transitions[0].guard = model::make_name("y"); },
          "POU 'p': body: transition FROM a TO b := x only in the first");
  differs([](model::Pou& u) { u.charts[0].steps[1].initial = true; },
          "POU 'p': body: step B only in the first");
  differs([](model::Pou& u) { u.associations[0].qualifier = model::Qualifier::S; },
          "POU 'p': step A (body): association act(N) against act(S)");
  differs(
      [](model::Pou& u) {
        std::swap(u.charts[0].transitions[0].order, u.charts[0].transitions[1].order);
      },
      "POU 'p': body: order of transition FROM a TO b := x and transition FROM a TO a := y");
  differs([](model::Pou& u) { u.variables[1].initial = 1; },
          "POU 'p': variable 'y': initial value differs");
  differs([](model::Pou& u) { u.charts[0].transitions[2].priority = 1; },
          "POU 'p': body: transition FROM b TO a := TRUE only in the first");
  differs([](model::Pou& u) { u.actions[0].body.clear(); }, "POU 'p': action 'act': body differs");
}

// ------------------------------------------------------------------------------------- corpus

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(IecTextCorpus, LoadsWithManifestCountsAndRoundTrips) {
  SFCV_REQUIRE_CORPUS(corpus);
  struct Case {
    const char* file;
    std::size_t steps, transitions;
  } cases[] = {{"04_matiec_sfc_syntax.st", 12, 13},
               {"13_verifaps_loopunwinding1_left.sfc", 22, 22},
               {"15_verifaps_transition2_left.sfc", 3, 2}};
  for (const auto& c : cases) {
    auto r = load_file((corpus / c.file).string());
    ASSERT_TRUE(r.ok()) << c.file << "\n" << all(r.diagnostics);
    EXPECT_EQ(model::count_steps(*r.project), c.steps) << c.file;
    EXPECT_EQ(model::count_transitions(*r.project), c.transitions) << c.file;
    round_trip(*r.project);
  }
}

TEST(IecTextCorpus, File04IsTheChartOf03) {
  SFCV_REQUIRE_CORPUS(corpus);
  auto r = load_file((corpus / "04_matiec_sfc_syntax.st").string());
  ASSERT_TRUE(r.ok()) << all(r.diagnostics);
  const auto& pou = r.project->pous.at(0);
  EXPECT_EQ(pou.name, "MAIN_TEST");
  EXPECT_EQ(pou.variables.size(), 6u);
  EXPECT_EQ(pou.find_variable("QX1")->address, "%QX1");
  EXPECT_EQ(pou.find_variable("QX1")->initial, 1);
  const auto& chart = pou.charts.at(0);
  int from_step2 = 0;
  for (const auto& t : chart.transitions)
    if (t.sources == std::vector<std::string>{"STEP2"}) ++from_step2;
  EXPECT_EQ(from_step2, 4);  // the 4-way selection divergence
  EXPECT_EQ(chart.transitions[4].targets, (std::vector<std::string>{"D1", "D2", "D3"}));
  EXPECT_EQ(chart.transitions[6].sources, (std::vector<std::string>{"E1", "E2", "E3"}));
  EXPECT_EQ(pou.find_action("INLINE1")->body.size(), 2u);
  EXPECT_EQ(pou.associations.size(), 11u);
}

TEST(IecTextCorpus, TemplateLoadsWithQualifierNamesAsIdentifiers) {
  SFCV_REQUIRE_CORPUS(corpus);
  const std::string tmpl = slurp(corpus / "05_matiec_identifier_in_sfc.st.tmpl");
  ASSERT_NE(tmpl.find("XXXX"), std::string::npos);
  for (const std::string id : {"N", "S", "D", "L", "P", "SD"}) {
    std::string text = tmpl;
    for (auto at = text.find("XXXX"); at != std::string::npos; at = text.find("XXXX", at))
      text.replace(at, 4, id);
    auto r = load_iec_text(text, "05_" + id + ".st");
    ASSERT_TRUE(r.ok()) << id << "\n" << all(r.diagnostics);
    const auto& p = *r.project;
    EXPECT_EQ(p.pous.size(), 16u) << id;
    EXPECT_EQ(model::count_steps(p), 35u) << id;
    EXPECT_EQ(model::count_transitions(p), 27u) << id;
    const auto& bar01 = *p.find_pou("bar01");
    EXPECT_EQ(bar01.charts[0].steps[0].name, id);
    EXPECT_TRUE(bar01.charts[0].steps[0].initial);
    EXPECT_EQ(bar01.charts[0].transitions[6].name, "transition_id3");
    EXPECT_EQ(bar01.charts[0].transitions[6].priority, 3);
    EXPECT_EQ(p.find_pou("bar03")->charts[0].transitions[0].name, id);
    EXPECT_EQ(p.find_pou("bar03")->charts[0].transitions[0].priority, 3);
    const auto& bar31 = *p.find_pou("bar31");
    ASSERT_EQ(bar31.associations.size(), 1u);
    EXPECT_EQ(bar31.associations[0].action, id);
    EXPECT_EQ(bar31.associations[0].qualifier, model::Qualifier::L);
    EXPECT_EQ(bar31.associations[0].duration_variable, "delta_1");
    EXPECT_EQ(bar31.associations[0].indicator, "IX1");
    EXPECT_EQ(p.find_pou("bar25")->associations[0].duration_ms, 1000);
    EXPECT_EQ(p.find_pou("bar20")->associations[0].qualifier, model::Qualifier::N);
    EXPECT_EQ(p.find_pou("bar32")->associations.size(), 9u);
    round_trip(p);
  }
}

TEST(IecTextCorpus, IllFormedFileLoadsWithItsDefectsKept) {
  SFCV_REQUIRE_CORPUS(corpus);
  auto r = load_file((corpus / "14_verifaps_delay1_right_illformed.sfc").string());
  ASSERT_TRUE(r.ok()) << all(r.diagnostics);
  const auto& chart = r.project->pous.at(0).charts.at(0);
  int i1 = 0;
  for (const auto& s : chart.steps)
    if (s.name == "I1") ++i1;
  EXPECT_EQ(i1, 2);  // the duplicate step is kept for validation to report
  EXPECT_EQ(chart.steps.size(), 5u);
  EXPECT_EQ(chart.transitions.size(), 5u);
  EXPECT_EQ(chart.transitions[0].targets[0], "I1a");
  round_trip(*r.project);
}

}  // namespace
}  // namespace sfcv::io

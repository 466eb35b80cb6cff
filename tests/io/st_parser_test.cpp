#include "io/st_parser.hpp"

#include <gtest/gtest.h>

#include "model/names.hpp"

namespace sfcv::io {
namespace {

using model::ExprKind;

model::SourceLocation file_start(int line = 1, int col = 1) {
  model::SourceLocation s;
  s.file = "f.st";
  s.line = line;
  s.column = col;
  return s;
}

model::ExprPtr expr(std::string_view text) {
  model::Diagnostics d;
  auto e = parse_st_expression(text, file_start(), d);
  EXPECT_TRUE(d.empty()) << (d.empty() ? "" : d[0].str());
  return e;
}

std::string printed(std::string_view text) {
  auto e = expr(text);
  return e ? model::to_st(e) : "<null>";
}

// The first diagnostic of a text that must fail, as "line:col: message".
std::string expr_error(std::string_view text) {
  model::Diagnostics d;
  auto e = parse_st_expression(text, file_start(), d);
  EXPECT_EQ(e, nullptr);
  if (d.empty()) return "<no error>";
  return std::to_string(d[0].where.line) + ":" + std::to_string(d[0].where.column) + ": " +
         d[0].message;
}

std::string stmt_error(std::string_view text) {
  model::Diagnostics d;
  auto body = parse_st_statements(text, file_start(), d);
  EXPECT_TRUE(body.empty());
  if (d.empty()) return "<no error>";
  return std::to_string(d[0].where.line) + ":" + std::to_string(d[0].where.column) + ": " +
         d[0].message;
}

TEST(StExpression, PrecedenceFollowsIec) {
  auto e = expr("a OR b XOR c AND d");
  ASSERT_EQ(e->kind, ExprKind::Or);
  EXPECT_EQ(e->args[1]->kind, ExprKind::Xor);
  EXPECT_EQ(e->args[1]->args[1]->kind, ExprKind::And);
  // Comparisons bind tighter than AND; NOT tighter than comparisons.
  auto c = expr("x = 1 AND NOT y < 2");
  ASSERT_EQ(c->kind, ExprKind::And);
  EXPECT_EQ(c->args[0]->kind, ExprKind::Eq);
  ASSERT_EQ(c->args[1]->kind, ExprKind::Lt);
  EXPECT_EQ(c->args[1]->args[0]->kind, ExprKind::Not);
  // = binds looser than <.
  auto q = expr("a < b = c");
  ASSERT_EQ(q->kind, ExprKind::Eq);
  EXPECT_EQ(q->args[0]->kind, ExprKind::Lt);
  // Arithmetic.
  auto m = expr("1 + 2 * 3 MOD 4 - -x");
  ASSERT_EQ(m->kind, ExprKind::Sub);
  EXPECT_EQ(m->args[1]->kind, ExprKind::Neg);
  ASSERT_EQ(m->args[0]->kind, ExprKind::Add);
  EXPECT_EQ(m->args[0]->args[1]->kind, ExprKind::Mod);
  EXPECT_EQ(m->args[0]->args[1]->args[0]->kind, ExprKind::Mul);
  EXPECT_EQ(printed("(a - b) - c"), "a - b - c");
  EXPECT_EQ(printed("a - (b - c)"), "a - (b - c)");
  EXPECT_EQ(printed("a & b"), "a AND b");
}

TEST(StExpression, AssociativeOperatorsAreFlat) {
  auto e = expr("a AND b AND (c AND d)");
  ASSERT_EQ(e->kind, ExprKind::And);
  EXPECT_EQ(e->args.size(), 4u);
  EXPECT_TRUE(model::equal(expr("(a OR b) OR c"), expr("a OR b OR c")));
  EXPECT_FALSE(model::equal(expr("(a OR b) AND c"), expr("a OR b AND c")));
}

// A chain is one node located at its last operator, however long (issue 52: a node rebuilt at
// each operator copied the operands so far, and a 100,000-term AND took 110 s of CPU to parse).
TEST(StExpression, ALongChainIsOneNodeAtItsLastOperator) {
  std::string text = "a";
  for (int i = 1; i < 100000; ++i) text += i % 3 == 0 ? " AND (b AND c)" : " AND a";
  const auto e = expr(text);
  ASSERT_EQ(e->kind, ExprKind::And);
  EXPECT_EQ(e->args.size(), 100000u + 33333u);
  EXPECT_EQ(e->height, 2u);
  EXPECT_EQ(e->where.column,
            static_cast<int>(text.rfind(" AND (")) + 2);  // the last term is (b AND c)
  const auto x = expr("a XOR b XOR (c XOR d) OR e OR f");
  ASSERT_EQ(x->kind, ExprKind::Or);
  ASSERT_EQ(x->args.size(), 3u);
  EXPECT_EQ(x->args[0]->kind, ExprKind::Xor);
  EXPECT_EQ(x->args[0]->args.size(), 4u);
}

TEST(StExpression, Literals) {
  EXPECT_EQ(expr("16#FF")->value, 255);
  EXPECT_EQ(expr("2#1010")->value, 10);
  EXPECT_EQ(expr("8#17")->value, 15);
  EXPECT_EQ(expr("1_000")->value, 1000);
  EXPECT_EQ(expr("INT#5")->value, 5);
  EXPECT_EQ(expr("UINT#16#10")->value, 16);
  auto neg = expr("INT#-5");
  ASSERT_EQ(neg->kind, ExprKind::Neg);
  EXPECT_EQ(neg->args[0]->value, 5);
  EXPECT_EQ(expr("TRUE")->kind, ExprKind::BoolConst);
  EXPECT_EQ(expr("false")->value, 0);
  EXPECT_EQ(expr("BOOL#1")->value, 1);
  struct {
    const char* text;
    std::int64_t ms;
  } times[] = {{"T#2s", 2000},         {"TIME#1m30s", 90000},    {"t#100ms", 100},
               {"T#1.5s", 1500},       {"T#1h2m3s4ms", 3723004}, {"T#1h_30m", 5400000},
               {"LTIME#1d", 86400000}, {"T#0.5m", 30000},        {"T#2000us", 2}};
  for (const auto& t : times) {
    auto e = expr(t.text);
    ASSERT_NE(e, nullptr) << t.text;
    EXPECT_EQ(e->kind, ExprKind::TimeConst) << t.text;
    EXPECT_EQ(e->value, t.ms) << t.text;
  }
}

TEST(StExpression, NamesAndMembers) {
  auto e = expr("Step1.X AND fb.Q AND Step1.T > T#6s");
  ASSERT_EQ(e->kind, ExprKind::And);
  ASSERT_EQ(e->args[0]->kind, ExprKind::Member);
  EXPECT_EQ(e->args[0]->name, "Step1");
  EXPECT_EQ(e->args[0]->member, "X");
  EXPECT_EQ(e->args[1]->member, "Q");
  EXPECT_EQ(e->args[2]->kind, ExprKind::Gt);
  EXPECT_EQ(e->args[2]->args[1]->value, 6000);
  // Comments and pragmas are skipped; a trailing ';' is tolerated.
  EXPECT_EQ(printed("a (* one (* nested *) *) OR // line\n b {pragma};"), "a OR b");
}

TEST(StExpression, RoundTripsThroughThePrinter) {
  const char* texts[] = {"a AND NOT (b OR c)",  "x + 1 > y * (2 - z)", "NOT NOT a",
                         "(a = b) = c",         "S1.T >= T#1500ms",    "a XOR b XOR c",
                         "-(a + 3) MOD 4 <> 0", "a OR b AND c OR d"};
  for (const char* t : texts) {
    auto e = expr(t);
    ASSERT_NE(e, nullptr) << t;
    EXPECT_TRUE(model::equal(e, expr(model::to_st(e)))) << t << " -> " << model::to_st(e);
  }
}

// A REAL literal parses to a literal of an unmodelled type (refused by the validator where it
// is used; a write nothing reads may be left out: UnmodelledTypes.* in tests/e2e).
TEST(StExpression, RealLiteralsParseAsUnmodelledConstants) {
  const auto e = expr("x > 1.5E3 * 2");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->args[1]->args[0]->kind, model::ExprKind::UnmodelledConst);
  EXPECT_EQ(e->args[1]->args[0]->name, "1.5E3");
  EXPECT_EQ(printed("x > 1.5E3 * 2"), "x > 1.5E3 * 2");
}

TEST(StExpression, ErrorsAreLocated) {
  EXPECT_EQ(expr_error("a AND"), "1:6: expected an expression, found end of text");
  EXPECT_EQ(expr_error("a AND\n  (b OR )"), "2:9: expected an expression, found ')'");
  EXPECT_EQ(expr_error("x > y[i][j]"), "1:9: unsupported: a second non-constant index in 'y'");
  EXPECT_EQ(expr_error("s = \"abc\""), "1:5: unsupported: WSTRING literal \"abc\"");
  EXPECT_EQ(expr_error("s = 'a$Qb'"), "1:5: malformed '$' escape in the string 'a$Qb'");
  EXPECT_EQ(expr_error("p^"), "1:2: unsupported: pointer dereference of 'p'");
  EXPECT_EQ(expr_error("a ** 2"), "1:3: unsupported: operator '**'");
  EXPECT_EQ(expr_error("a b"), "1:3: expected end of text, found 'b'");
  EXPECT_EQ(expr_error("T#5"), "1:1: TIME literal: missing unit (d, h, m, s, ms)");
  EXPECT_EQ(expr_error("T#1us"), "1:1: unsupported: TIME literal finer than a millisecond");
  EXPECT_EQ(expr_error("a (* open"), "1:3: unterminated comment '(*'");
  EXPECT_EQ(expr_error("a ? b"), "1:3: unexpected character '?'");
  EXPECT_EQ(expr_error("99999999999999999999"),
            "1:1: integer literal 99999999999999999999 is outside LINT "
            "(-9223372036854775808..9223372036854775807)");
  EXPECT_EQ(expr_error("%IX1.0 AND a"),
            "1:1: unsupported: direct address %IX1.0 in an expression (declare a variable AT it)");
  EXPECT_EQ(expr_error(""), "1:1: expected an expression, found end of text");
}

TEST(StExpression, AbsurdNestingIsAnErrorNotACrash) {
  const std::string deep = std::string(100000, '(') + "a" + std::string(100000, ')');
  EXPECT_EQ(expr_error(deep), "1:201: nesting deeper than 200 levels");
  std::string nots;
  for (int i = 0; i < 50000; ++i) nots += "NOT ";
  EXPECT_EQ(expr_error(nots + "a"), "1:801: nesting deeper than 200 levels");
  std::string ifs;
  for (int i = 0; i < 50000; ++i) ifs += "IF a THEN ";
  EXPECT_EQ(stmt_error(ifs), "1:1994: nesting deeper than 200 levels");
  // Moderate nesting is fine.
  EXPECT_NE(expr(std::string(150, '(') + "a" + std::string(150, ')')), nullptr);
}

TEST(StExpression, LocationsAreOffsetByTheStart) {
  model::Diagnostics d;
  // Text starting at line 10, column 7 of a file: column shifts on its first line only.
  EXPECT_EQ(parse_st_expression("a AND", file_start(10, 7), d), nullptr);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].where.str(), "f.st:10:12");
  d.clear();
  EXPECT_EQ(parse_st_expression("a AND\n b +", file_start(10, 7), d), nullptr);
  EXPECT_EQ(d[0].where.str(), "f.st:11:5");
  // An XML element: the path is kept, line/column are relative to the text.
  model::SourceLocation xml;
  xml.file = "p.xml";
  xml.element_path = "/project/types/pous/pou[@name='P']/transition[@localId='4']";
  d.clear();
  EXPECT_EQ(parse_st_expression("\n  x >", xml, d), nullptr);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].where.element_path, xml.element_path);
  EXPECT_EQ(d[0].where.line, 2);
  EXPECT_EQ(d[0].where.column, 6);
}

TEST(StStatements, AssignmentsIfCaseAndCalls) {
  model::Diagnostics d;
  auto body = parse_st_statements(R"(
    x := a AND b; ;
    IF n > 3 THEN y := 1; ELSIF n = 2 THEN y := 2; ELSE y := 3; END_IF;
    CASE n OF
      1: y := 10;
      2, 3: y := 20; z := TRUE;
      4..6, -1: ;
    ELSE
      y := 0;
    END_CASE
    t1(IN := x, PT := T#1s);
    r();
  )",
                                  file_start(), d);
  ASSERT_TRUE(d.empty()) << d[0].str();
  ASSERT_EQ(body.size(), 5u);
  EXPECT_EQ(body[0]->kind, model::StmtKind::Assign);
  EXPECT_EQ(body[0]->target, "x");
  EXPECT_EQ(body[0]->where.line, 2);
  EXPECT_EQ(body[0]->where.column, 5);
  const auto& ifs = *body[1];
  ASSERT_EQ(ifs.kind, model::StmtKind::If);
  EXPECT_EQ(ifs.conditions.size(), 2u);
  EXPECT_EQ(ifs.bodies.size(), 2u);
  EXPECT_EQ(ifs.else_body.size(), 1u);
  const auto& cs = *body[2];
  ASSERT_EQ(cs.kind, model::StmtKind::Case);
  ASSERT_EQ(cs.labels.size(), 3u);
  EXPECT_EQ(cs.labels[1], (std::vector<model::CaseLabel>{{2, 2, {}, {}}, {3, 3, {}, {}}}));
  EXPECT_EQ(cs.labels[2], (std::vector<model::CaseLabel>{{4, 6, {}, {}}, {-1, -1, {}, {}}}));
  EXPECT_EQ(cs.bodies[1].size(), 2u);
  EXPECT_TRUE(cs.bodies[2].empty());
  EXPECT_EQ(cs.else_body.size(), 1u);
  ASSERT_EQ(body[3]->kind, model::StmtKind::FbCall);
  EXPECT_EQ(body[3]->target, "t1");
  ASSERT_EQ(body[3]->arguments.size(), 2u);
  EXPECT_EQ(body[3]->arguments[1].first, "PT");
  EXPECT_EQ(body[3]->arguments[1].second->value, 1000);
  EXPECT_TRUE(body[4]->arguments.empty());
  // Printing and re-reading gives the same statements.
  d.clear();
  auto again = parse_st_statements(model::to_st(body), file_start(), d);
  EXPECT_TRUE(d.empty());
  EXPECT_TRUE(model::equal(body, again)) << model::to_st(body);
}

TEST(StStatements, LoopsAndJumps) {
  model::Diagnostics d;
  const auto body = parse_st_statements(R"(
    FOR i := 1 TO n BY 2 DO
      IF i = 3 THEN CONTINUE; END_IF;
      x := x + i;
      IF x > 10 THEN EXIT; END_IF;
    END_FOR;
    WHILE x > 0 DO x := x - 1; END_WHILE;
    REPEAT x := x + 1; UNTIL x >= 3 END_REPEAT;
    RETURN;
  )",
                                        file_start(), d);
  ASSERT_TRUE(d.empty()) << d[0].str();
  ASSERT_EQ(body.size(), 4u);
  EXPECT_EQ(body[0]->kind, model::StmtKind::For);
  EXPECT_EQ(body[0]->target, "i");
  EXPECT_EQ(model::to_st(body[0]->limit), "n");
  EXPECT_EQ(model::to_st(body[0]->step), "2");
  EXPECT_EQ(body[0]->bodies.at(0).size(), 3u);
  EXPECT_EQ(body[1]->kind, model::StmtKind::While);
  EXPECT_EQ(body[2]->kind, model::StmtKind::Repeat);
  EXPECT_EQ(model::to_st(body[2]->conditions.at(0)), "x >= 3");
  EXPECT_EQ(body[3]->kind, model::StmtKind::Return);
  EXPECT_EQ(body[0]->where.line, 2);
  // Printing and re-reading gives the same statements.
  const auto again = parse_st_statements(model::to_st(body), file_start(), d);
  ASSERT_TRUE(d.empty());
  EXPECT_TRUE(model::equal(body, again)) << model::to_st(body) << model::to_st(again);
  EXPECT_EQ(stmt_error("FOR i = 1 TO 3 DO END_FOR;"),
            "1:7: expected ':=' after the FOR control variable, found '='");
  EXPECT_EQ(stmt_error("WHILE a DO x := 1;"), "1:19: expected END_WHILE, found end of text");
}

TEST(StExpression, FunctionCalls) {
  EXPECT_EQ(printed("MAX(a, b + 1) > LIMIT(0, x, 10)"), "MAX(a, b + 1) > LIMIT(0, x, 10)");
  EXPECT_EQ(printed("INT_TO_BOOL(w.3)"), "INT_TO_BOOL(w.3)");
  const auto e = expr("SEL(g, 1, 2)");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->kind, ExprKind::Call);
  EXPECT_EQ(e->name, "SEL");
  EXPECT_EQ(e->args.size(), 3u);
  EXPECT_TRUE(model::equal(expr("max(a,b)"), expr("MAX(a, b)")));
  // A formal call keeps its parameter names (IEC 61131-3 2.5.1.1), in the order written.
  const auto formal = expr("Clamp(hi := 10, x := a + 1)");
  ASSERT_TRUE(formal);
  EXPECT_EQ(formal->arg_names, (std::vector<std::string>{"hi", "x"}));
  EXPECT_EQ(printed("Clamp(hi := 10, x := a + 1)"), "Clamp(hi := 10, x := a + 1)");
  EXPECT_FALSE(model::equal(formal, expr("Clamp(x := 10, hi := a + 1)")));
  EXPECT_FALSE(model::equal(formal, expr("Clamp(10, a + 1)")));
  EXPECT_FALSE(model::equal(expr("MAX(a, b)"), expr("MIN(a, b)")));
}

TEST(StStatements, UnsupportedConstructsAreNamed) {
  EXPECT_EQ(stmt_error("x := MAX(EN := a, 2);"),
            "1:19: the call of function 'MAX' mixes formal ('name := value') and positional "
            "arguments");
  EXPECT_EQ(stmt_error("x := F(a, q => b);"),
            "1:6: the call of function 'F' mixes formal ('name := value') and positional "
            "arguments");
  EXPECT_EQ(stmt_error("x := 1 + F(a := 1, q => b);"),
            "1:20: unsupported: output argument 'q =>' in the call of function 'F' (outputs are "
            "bound only by a call that is the whole right side of an assignment: y := F(..., q "
            "=> z);)");
  EXPECT_EQ(stmt_error("x := F(a := 1, q => b) + 1;"),
            "1:24: output arguments '=>' in the call of function 'F': the call must be the whole "
            "right side of the assignment");
  EXPECT_EQ(stmt_error("x := F(a := G(q => c), q => b);"),
            "1:15: unsupported: output argument 'q =>' in the call of function 'G' (outputs are "
            "bound only by a call that is the whole right side of an assignment: y := G(..., q "
            "=> z);)");
  EXPECT_EQ(stmt_error("t1(a, b);"),
            "1:4: unsupported: positional arguments in the call of 't1' (write IN := value)");
  EXPECT_EQ(stmt_error("a[i, 1][k] := 1;"), "1:8: unsupported: a second non-constant index in 'a'");
  EXPECT_EQ(stmt_error("x := 1\ny := 2;"), "2:1: expected ';' after the assignment, found 'y'");
  EXPECT_EQ(stmt_error("IF a THEN x := 1;"), "1:18: expected END_IF, found end of text");
  {
    // An enumerator as a CASE label parses; lowering the data types resolves it (an unknown
    // one is an error there: DataTypes.MistakesAreLocatedErrors).
    model::Diagnostics d;
    const auto body = parse_st_statements("CASE n OF A, E.B..C: x := 1; END_CASE", file_start(), d);
    ASSERT_TRUE(d.empty() && body.size() == 1);
    ASSERT_EQ(body[0]->labels.at(0).size(), 2u);
    EXPECT_EQ(body[0]->labels[0][0].lo_name, "A");
    EXPECT_EQ(body[0]->labels[0][1].lo_name, "E.B");
    EXPECT_EQ(body[0]->labels[0][1].hi_name, "C");
  }
  EXPECT_EQ(stmt_error("JMP done;"), "1:1: unsupported: JMP statement");
  EXPECT_EQ(stmt_error("done: x := 1;"),
            "1:1: unsupported: label 'done' (jump labels; CASE labels must be integer literals)");
  EXPECT_EQ(stmt_error("x = 1;"), "1:3: expected ':=' or '(' after 'x', found '='");
  EXPECT_EQ(stmt_error("x := 1; END_IF"), "1:9: expected a statement, found 'END_IF'");
}

TEST(StStatements, LastStatementMayOmitItsSemicolon) {
  model::Diagnostics d;
  // IL operator names are ordinary identifiers in ST.
  EXPECT_EQ(parse_st_statements("JMP := LD AND ST;", file_start(), d).size(), 1u);
  EXPECT_TRUE(d.empty());
  auto body = parse_st_statements("x := 1; y := x", file_start(), d);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(body.size(), 2u);
}

TEST(StVarSections, DeclarationsTypesAndInitialValues) {
  model::Diagnostics d;
  auto vars = parse_var_sections(R"(
    VAR_INPUT a, b : BOOL := TRUE; x AT %IX1 : BOOL; END_VAR
    VAR_OUTPUT q : INT; END_VAR
    VAR CONSTANT n : INT(0..10) := 3; m : int := -4; END_VAR
    VAR RETAIN t : TIME := T#1s; t1 : TON; u : UDINT; END_VAR
    VAR_IN_OUT io : BOOL; END_VAR
    VAR_GLOBAL g : BOOL := 1; END_VAR
    VAR_EXTERNAL e : BOOL; END_VAR
    VAR_TEMP tmp : BOOL; END_VAR
  )",
                                 file_start(), d);
  ASSERT_TRUE(d.empty()) << d[0].str();
  ASSERT_EQ(vars.size(), 13u);
  EXPECT_EQ(vars[0].name, "a");
  EXPECT_EQ(vars[1].name, "b");
  EXPECT_EQ(vars[1].direction, model::VarDirection::Input);
  EXPECT_EQ(vars[1].initial, 1);
  EXPECT_EQ(vars[2].address, "%IX1");
  EXPECT_FALSE(vars[2].initial.has_value());
  EXPECT_EQ(vars[3].direction, model::VarDirection::Output);
  EXPECT_EQ(vars[3].type, *model::elementary_type("INT"));
  EXPECT_EQ(vars[4].type, model::Type::integer("INT(0..10)", 0, 10));
  EXPECT_EQ(vars[4].initial, 3);
  EXPECT_EQ(vars[4].direction, model::VarDirection::Local);
  EXPECT_EQ(vars[5].initial, -4);
  EXPECT_EQ(vars[6].type.kind, model::TypeKind::Time);
  EXPECT_EQ(vars[6].initial, 1000);
  EXPECT_EQ(vars[7].type.kind, model::TypeKind::FunctionBlock);
  EXPECT_EQ(vars[7].type.fb, model::StandardFb::TON);
  EXPECT_EQ(vars[8].type.hi, 4294967295LL);
  EXPECT_EQ(vars[9].direction, model::VarDirection::InOut);
  EXPECT_EQ(vars[10].direction, model::VarDirection::Global);
  EXPECT_EQ(vars[11].direction, model::VarDirection::External);
  EXPECT_EQ(vars[12].direction, model::VarDirection::Local);
  EXPECT_EQ(vars[12].where.line, 9);
  EXPECT_EQ(vars[12].where.column, 14);
}

TEST(StVarSections, UnsupportedAndMalformedDeclarations) {
  auto err = [](std::string_view text) {
    model::Diagnostics d;
    parse_var_sections(text, file_start(), d);
    if (d.empty()) return std::string("<no error>");
    return std::to_string(d[0].where.line) + ":" + std::to_string(d[0].where.column) + ": " +
           d[0].message;
  };
  EXPECT_EQ(err("VAR r : REAL; END_VAR"),
            "1:9: unsupported type REAL "
            "(sfcv models BOOL, integers, TIME, STRING, enumerations, arrays, structures and FBs)");
  // Any other type name is an instance of a user function block (resolved by the semantics).
  EXPECT_EQ(err("VAR\n  s : MyType; END_VAR"), "<no error>");
  EXPECT_EQ(err("VAR a : ARRAY[1..2] OF BOOL; END_VAR"), "<no error>");
  EXPECT_EQ(err("VAR a : ARRAY[2..1] OF BOOL; END_VAR"), "1:9: array bounds [2..1] are empty");
  EXPECT_EQ(err("VAR p : POINTER TO INT; END_VAR"),
            "1:9: unsupported type POINTER "
            "(sfcv models BOOL, integers, TIME, STRING, enumerations, arrays, structures and FBs)");
  EXPECT_EQ(err("VAR b : BOOL := T#1s; END_VAR"), "1:17: initial value does not match type BOOL");
  EXPECT_EQ(err("VAR n : INT(0..10) := 11; END_VAR"),
            "1:23: initial value 11 is outside INT(0..10)");
  EXPECT_EQ(err("VAR n : SINT(0..300); END_VAR"), "1:9: subrange 0..300 is empty or outside SINT");
  EXPECT_EQ(err("VAR n : INT := a + 1; END_VAR"),
            "1:16: unsupported: initial value that is not a literal");
  EXPECT_EQ(err("VAR t : TON := (PT := T#1s); END_VAR"),
            "1:16: unsupported: initial values of function block instances");
  EXPECT_EQ(err("VAR a : BOOL END_VAR"),
            "1:14: expected ';' after the declaration, found 'END_VAR'");
  EXPECT_EQ(err("VAR a : BOOL;"), "1:14: expected END_VAR, found end of text");
  EXPECT_EQ(err("VAR_ACCESS a : BOOL; END_VAR"), "1:1: unsupported: VAR_ACCESS section");
  EXPECT_EQ(err("VAR a, b AT %IX1 : BOOL; END_VAR"), "1:8: AT can locate only one variable");
}

}  // namespace
}  // namespace sfcv::io

namespace sfcv::io {
namespace {

// Issue 18: members of user FB instances (nested), member targets and `=>` outputs parse;
// whether the names exist is the compiler's question (tests/e2e/instances_test.cpp).
TEST(StStatements, InstanceMembersAndOutputBindings) {
  EXPECT_EQ(printed("a.b.c AND d.q"), "a.b.c AND d.q");
  model::Diagnostics d;
  auto body =
      parse_st_statements("t1(IN := a, Q => b);\nt1.IN := a;\nx.y.z := t1.Q;", file_start(), d);
  ASSERT_TRUE(d.empty()) << d[0].message;
  ASSERT_EQ(body.size(), 3u);
  ASSERT_EQ(body[0]->outputs.size(), 1u);
  EXPECT_EQ(body[0]->outputs[0].first, "Q");
  EXPECT_EQ(body[0]->outputs[0].second, "b");
  EXPECT_EQ(body[1]->target, "t1.IN");
  EXPECT_EQ(body[2]->target, "x.y.z");
}

// `y := F(x := a, q => b.c);`: the assignment carries the function's output bindings, and
// prints back as written.
TEST(StStatements, FunctionOutputsBoundByTheAssignment) {
  model::Diagnostics d;
  const std::string text = "y := F(x := a, q => b.c, r => e);\nz := G(q => w);\n";
  auto body = parse_st_statements(text, file_start(), d);
  ASSERT_TRUE(d.empty()) << d[0].message;
  ASSERT_EQ(body.size(), 2u);
  EXPECT_EQ(body[0]->kind, model::StmtKind::Assign);
  EXPECT_EQ(body[0]->outputs,
            (std::vector<std::pair<std::string, std::string>>{{"q", "b.c"}, {"r", "e"}}));
  EXPECT_EQ(body[0]->value->args.size(), 1u);
  EXPECT_EQ(model::to_st(body), text);
}

}  // namespace
}  // namespace sfcv::io

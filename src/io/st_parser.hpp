#pragma once
// Structured Text parsing shared by the importers: expressions (guards), statement lists (action
// bodies) and VAR sections. Errors come back as located diagnostics; nothing is printed.
//
// Supported: OR XOR AND/& NOT, = <> < <= > >=, + - * / MOD, unary -, parentheses, TRUE/FALSE,
// integer literals (16#FF, 2#1010, 1_000, INT#5), TIME literals (T#1m30s -> ms), names and
// `a.b` members, function calls `f(a, b)`; `x := e;`, IF/ELSIF/ELSE, CASE, FOR/WHILE/REPEAT,
// EXIT/CONTINUE/RETURN, FB calls `inst(IN := x);`, `;`.
// Anything else (REAL, strings, arrays ...) is an error
// "unsupported: <construct>" at its place.

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/st_lexer.hpp"
#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "model/errors.hpp"
#include "model/expr.hpp"
#include "model/source_location.hpp"
#include "model/statement.hpp"

namespace sfcv::io {

/// Parses `text` as one ST expression. `start` is the location of text[0]: a file position
/// (line/column inside the text are added to it) or an XML element (its element_path is carried
/// into every diagnostic, with line/column relative to the text). Returns null on error.
model::ExprPtr parse_st_expression(std::string_view text, const model::SourceLocation& start,
                                   model::Diagnostics& diags);

/// Parses `text` as an ST statement list (an action body). On error, the diagnostics say why and
/// the result is empty.
model::StmtList parse_st_statements(std::string_view text, const model::SourceLocation& start,
                                    model::Diagnostics& diags);

/// Parses a sequence of VAR ... END_VAR sections (VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT,
/// VAR_GLOBAL, VAR_EXTERNAL, VAR_TEMP as Local; CONSTANT/RETAIN tolerated).
std::vector<model::Variable> parse_var_sections(std::string_view text,
                                                const model::SourceLocation& start,
                                                model::Diagnostics& diags);

namespace st {

/// Thrown by Parser on the first syntax error of a construct; importers catch it, record it and
/// resynchronise.
struct ParseError : InputError {
  ParseError(model::SourceLocation w, const std::string& m) : InputError(m), where(std::move(w)) {}
  model::SourceLocation where;
};

/// Recursive-descent parser over a token vector, used directly by the textual SFC importer.
class Parser {
 public:
  /// Past `budget`'s deadline (when given), consuming a token throws LimitReached.
  Parser(std::vector<Token> tokens, Locator locator, const model::Budget* budget = nullptr);

  // ---- token access
  const Token& peek(std::size_t k = 0) const;
  const Token& next();
  bool at(TokenKind kind, std::size_t k = 0) const { return peek(k).kind == kind; }
  /// The token k ahead is the identifier `word` (case-insensitive).
  bool at_word(std::string_view word, std::size_t k = 0) const;
  bool accept(TokenKind kind);
  bool accept_word(std::string_view word);
  const Token& expect(TokenKind kind, std::string_view what);
  void expect_word(std::string_view word);
  /// An identifier that is not a reserved ST keyword; `what` names it in the error message.
  std::string identifier(std::string_view what);
  std::size_t position() const { return pos_; }
  void seek(std::size_t pos) { pos_ = pos; }

  model::SourceLocation where(const Token& t) const { return locator_.at(t); }
  [[noreturn]] void fail(const Token& t, const std::string& message) const;
  [[noreturn]] void fail_unexpected(std::string_view expected) const;
  /// The value of the Integer token `t`, negated when `negated` (a unary minus before it):
  /// through model::signed_literal, so 2^63 is accepted only as LINT's smallest value.
  std::int64_t integer_value(const Token& t, bool negated) const;

  // ---- grammar
  model::ExprPtr expression();
  /// Statements up to the first token that cannot start one (END_..., ELSE, a CASE label, end).
  model::StmtList statements();
  bool at_var_section() const;
  /// One VAR... END_VAR section; appends its variables.
  void var_section(std::vector<model::Variable>& out);
  /// `a, b : T [:= init];` ... up to the word `end` (not consumed).
  void declarations(model::VarDirection direction, std::string_view end,
                    std::vector<model::Variable>& out);
  /// A type name: BOOL, an integer type or subrange, TIME, a (standard or user) FB type, a
  /// user type's name; with `dimensions`, also ARRAY[..] OF a type (its bounds appended there).
  model::Type var_type(std::vector<model::ArrayDimension>* dimensions = nullptr);
  /// An initial value: an expression, `[a, b, n(c)]` (an array: Call "[") or `(x := a, ...)`
  /// (a structure: formal Call "(").
  model::ExprPtr initialiser();
  /// `TYPE name : ...; ... END_TYPE`: appends the declared types.
  void type_declarations(std::vector<model::DataType>& out);

 private:
  model::ExprPtr or_expr();
  model::ExprPtr xor_expr();
  model::ExprPtr and_expr();
  model::ExprPtr eq_expr();
  model::ExprPtr cmp_expr();
  model::ExprPtr add_expr();
  model::ExprPtr mul_expr();
  model::ExprPtr unary_expr();
  model::ExprPtr primary();
  model::StmtPtr statement();
  model::StmtPtr if_statement();
  model::StmtPtr case_statement();
  model::StmtPtr fb_call(const Token& name);
  model::StmtPtr for_statement();
  /// WHILE ... END_WHILE and REPEAT ... END_REPEAT.
  model::StmtPtr while_statement();
  /// A function call in an expression, `name(` next: positional arguments.
  model::ExprPtr call(const Token& name);
  std::int64_t case_bound();
  /// The characters of a STRING literal token, its '$' escapes decoded.
  std::string string_characters(const Token& t) const;
  /// A CASE label's bound: an integer literal into `value`, or an enumerator into `name`.
  void case_label_bound(std::int64_t& value, std::string& name);
  /// `[i, j]` after a name: constant indices join `path` (`a[1,2]`); others become its one
  /// "[*]", with `indices` receiving them.
  void subscript(std::string& path, std::vector<model::ExprPtr>& indices);
  void end_statement(std::string_view what);
  /// The variable after `=>` (`y`, `a.b`).
  std::string bound_variable();

  /// Bounds recursion so that absurd nesting is an error, not a stack overflow.
  void enter(const Token& t);
  model::ExprPtr bounded(model::ExprPtr e, const Token& op);
  void leave() { --depth_; }

  std::vector<Token> tokens_;
  Locator locator_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  int in_case_ = 0;  ///< inside CASE bodies, `name:` starts the next label
  /// The token of the function call that is the whole right side of the assignment being
  /// parsed: only that call may bind outputs, into `call_outputs_` (`y := F(x, q => z);`).
  std::size_t outputs_call_at_ = static_cast<std::size_t>(-1);
  std::vector<std::pair<std::string, std::string>> call_outputs_;
  model::BudgetPoll poll_;
};

/// True for words ST reserves (AND, IF, END_IF, ...) which cannot name a variable.
bool is_reserved(std::string_view word);

}  // namespace st
}  // namespace sfcv::io

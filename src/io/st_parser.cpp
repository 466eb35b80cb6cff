#include "io/st_parser.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <functional>
#include <limits>
#include <optional>

#include "model/literal.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/types.hpp"

namespace sfcv::io {
namespace st {

namespace {

using model::ExprKind;
using model::ExprPtr;

constexpr std::array<std::string_view, 47> kReserved{
    "AND",          "OR",           "XOR",
    "NOT",          "MOD",          "TRUE",
    "FALSE",        "IF",           "THEN",
    "ELSIF",        "ELSE",         "END_IF",
    "CASE",         "OF",           "END_CASE",
    "FOR",          "TO",           "BY",
    "DO",           "END_FOR",      "WHILE",
    "END_WHILE",    "REPEAT",       "UNTIL",
    "END_REPEAT",   "RETURN",       "EXIT",
    "CONTINUE",     "VAR",          "VAR_INPUT",
    "VAR_OUTPUT",   "VAR_IN_OUT",   "VAR_GLOBAL",
    "VAR_EXTERNAL", "VAR_TEMP",     "END_VAR",
    "AT",           "END_STEP",     "END_TRANSITION",
    "END_ACTION",   "END_PROGRAM",  "END_FUNCTION_BLOCK",
    "END_FUNCTION", "INITIAL_STEP", "ARRAY",
    "POINTER",      "REF_TO"};

std::string upper(std::string_view s) {
  return model::to_upper(s);
}

// The operands of an associative operator's chain, flattened, so that `a AND b AND c` and
// `(a AND b) AND c` give one model and printing then re-parsing is the identity.
void append_flat(std::vector<ExprPtr>& args, ExprKind kind, ExprPtr e) {
  if (e->kind == kind)
    args.insert(args.end(), e->args.begin(), e->args.end());
  else
    args.push_back(std::move(e));
}

}  // namespace

bool is_reserved(std::string_view word) {
  for (auto r : kReserved)
    if (model::iequals(r, word)) return true;
  return false;
}

Parser::Parser(std::vector<Token> tokens, Locator locator, const model::Budget* budget)
    : tokens_(std::move(tokens)), locator_(std::move(locator)), poll_(budget, 4096) {
  if (tokens_.empty() || tokens_.back().kind != TokenKind::End) tokens_.push_back(Token{});
}

const Token& Parser::peek(std::size_t k) const {
  return tokens_[std::min(pos_ + k, tokens_.size() - 1)];
}

const Token& Parser::next() {
  poll_.tick_or_throw("reading the model");
  const Token& t = peek();
  if (pos_ < tokens_.size() - 1) ++pos_;
  return t;
}

bool Parser::at_word(std::string_view word, std::size_t k) const {
  const Token& t = peek(k);
  return t.kind == TokenKind::Identifier && model::iequals(t.text, word);
}

bool Parser::accept(TokenKind kind) {
  if (!at(kind)) return false;
  next();
  return true;
}

bool Parser::accept_word(std::string_view word) {
  if (!at_word(word)) return false;
  next();
  return true;
}

const Token& Parser::expect(TokenKind kind, std::string_view what) {
  if (!at(kind)) fail_unexpected(what);
  return next();
}

void Parser::expect_word(std::string_view word) {
  if (!at_word(word)) fail_unexpected(word);
  next();
}

std::string Parser::identifier(std::string_view what) {
  const Token& t = peek();
  if (t.kind != TokenKind::Identifier || is_reserved(t.text)) fail_unexpected(what);
  return next().text;
}

void Parser::fail(const Token& t, const std::string& message) const {
  throw ParseError(where(t), message);
}

void Parser::fail_unexpected(std::string_view expected) const {
  const Token& t = peek();
  if (t.kind == TokenKind::Unsupported) fail(t, "unsupported: literal " + t.text);
  fail(t, "expected " + std::string(expected) + ", found " + describe(t));
}

// ------------------------------------------------------------------------------ expressions

ExprPtr Parser::expression() {
  return or_expr();
}

// A chain `a OR b OR c` is one node, its operands collected first and the node made once (a
// node rebuilt at each operator copied the operands so far: a 100,000-term AND took 110 s of
// CPU). The node is located at the last operator.
ExprPtr Parser::or_expr() {
  ExprPtr first = xor_expr();
  if (!at_word("OR")) return first;
  std::vector<ExprPtr> args;
  append_flat(args, ExprKind::Or, std::move(first));
  const Token* op = nullptr;
  while (at_word("OR")) {
    op = &next();
    append_flat(args, ExprKind::Or, xor_expr());
  }
  return model::make_nary(ExprKind::Or, std::move(args), where(*op));
}

ExprPtr Parser::xor_expr() {
  ExprPtr first = and_expr();
  if (!at_word("XOR")) return first;
  std::vector<ExprPtr> args;
  append_flat(args, ExprKind::Xor, std::move(first));
  const Token* op = nullptr;
  while (at_word("XOR")) {
    op = &next();
    append_flat(args, ExprKind::Xor, and_expr());
  }
  return model::make_nary(ExprKind::Xor, std::move(args), where(*op));
}

ExprPtr Parser::and_expr() {
  ExprPtr first = eq_expr();
  auto at_and = [this] { return at_word("AND") || at(TokenKind::Ampersand); };
  if (!at_and()) return first;
  std::vector<ExprPtr> args;
  append_flat(args, ExprKind::And, std::move(first));
  std::uint32_t height = 0;  // of the operands so far: the node is one level above them
  for (const auto& a : args) height = std::max(height, a->height);
  const Token* op = nullptr;
  while (at_and()) {
    op = &next();
    const auto before = args.size();
    append_flat(args, ExprKind::And, eq_expr());
    for (auto i = before; i < args.size(); ++i) height = std::max(height, args[i]->height);
    if (height + 1 > static_cast<std::uint32_t>(model::kMaxNesting))
      fail(*op, "expression nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
  }
  return model::make_nary(ExprKind::And, std::move(args), where(*op));
}

ExprPtr Parser::eq_expr() {
  ExprPtr e = cmp_expr();
  while (at(TokenKind::Eq) || at(TokenKind::Ne)) {
    const Token& op = next();
    const auto kind = op.kind == TokenKind::Eq ? ExprKind::Eq : ExprKind::Ne;
    e = bounded(model::make_binary(kind, e, cmp_expr(), where(op)), op);
  }
  return e;
}

ExprPtr Parser::cmp_expr() {
  ExprPtr e = add_expr();
  for (;;) {
    ExprKind kind;
    if (at(TokenKind::Lt))
      kind = ExprKind::Lt;
    else if (at(TokenKind::Le))
      kind = ExprKind::Le;
    else if (at(TokenKind::Gt))
      kind = ExprKind::Gt;
    else if (at(TokenKind::Ge))
      kind = ExprKind::Ge;
    else
      return e;
    const Token& op = next();
    e = bounded(model::make_binary(kind, e, add_expr(), where(op)), op);
  }
}

ExprPtr Parser::add_expr() {
  ExprPtr e = mul_expr();
  while (at(TokenKind::Plus) || at(TokenKind::Minus)) {
    const Token& op = next();
    const auto kind = op.kind == TokenKind::Plus ? ExprKind::Add : ExprKind::Sub;
    e = bounded(model::make_binary(kind, e, mul_expr(), where(op)), op);
  }
  return e;
}

ExprPtr Parser::mul_expr() {
  ExprPtr e = unary_expr();
  for (;;) {
    ExprKind kind;
    if (at(TokenKind::Star))
      kind = ExprKind::Mul;
    else if (at(TokenKind::Slash))
      kind = ExprKind::Div;
    else if (at_word("MOD"))
      kind = ExprKind::Mod;
    else
      return e;
    const Token& op = next();
    e = bounded(model::make_binary(kind, e, unary_expr(), where(op)), op);
  }
}

void Parser::enter(const Token& t) {
  if (++depth_ > model::kMaxNesting) {
    --depth_;
    fail(t, "nesting deeper than " + std::to_string(model::kMaxNesting) + " levels");
  }
}

// A chain `a + b + c ...` is built by a loop, not by recursion: bound the tree's height too.
ExprPtr Parser::bounded(ExprPtr e, const Token& op) {
  if (e->height > static_cast<std::uint32_t>(model::kMaxNesting))
    fail(op, "expression nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
  return e;
}

namespace {
// Leaves a nesting level on every exit path of a recursive rule.
struct DepthGuard {
  explicit DepthGuard(std::function<void()> on_exit) : leave(std::move(on_exit)) {}
  ~DepthGuard() { leave(); }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;
  std::function<void()> leave;
};
}  // namespace

std::int64_t Parser::integer_value(const Token& t, bool negated) const {
  const std::uint64_t magnitude = t.negation_only ? model::kMaxLiteralMagnitude
                                  : t.value < 0   ? 0 - static_cast<std::uint64_t>(t.value)
                                                  : static_cast<std::uint64_t>(t.value);
  const bool negative = negated != (t.value < 0 && !t.negation_only);
  const auto v = model::signed_literal(negative, magnitude, negated ? "-" + t.text : t.text);
  if (!v) fail(t, v.error);
  return *v;
}

ExprPtr Parser::unary_expr() {
  enter(peek());
  DepthGuard guard([this] { leave(); });
  if (at(TokenKind::Minus) && at(TokenKind::Integer, 1) && peek(1).negation_only) {
    // -9223372036854775808: LINT's smallest value is a literal (its magnitude is not).
    const Token& op = next();
    return model::make_int(integer_value(next(), true), where(op));
  }
  if (at(TokenKind::Minus)) {
    const Token& op = next();
    return model::make_unary(ExprKind::Neg, unary_expr(), where(op));
  }
  if (at(TokenKind::Plus)) {
    next();
    return unary_expr();
  }
  if (at_word("NOT")) {
    const Token& op = next();
    // NOT is also the standard function NOT(IN := x) (IEC 61131-3 2.5.1.5.1), formal call.
    if (at(TokenKind::LParen) && at_word("IN", 1) && at(TokenKind::Assign, 2)) {
      next();
      next();
      next();
      ExprPtr operand = expression();
      expect(TokenKind::RParen, "')' after the argument of NOT");
      return model::make_unary(ExprKind::Not, std::move(operand), where(op));
    }
    return model::make_unary(ExprKind::Not, unary_expr(), where(op));
  }
  ExprPtr e = primary();
  if (at(TokenKind::Power)) fail(peek(), "unsupported: operator '**'");
  return e;
}

std::string Parser::string_characters(const Token& t) const {
  // IEC 61131-3 6.3.3: '$' escapes: $$ $' $L $N $P $R $T and two hex digits.
  std::string out;
  const std::string& w = t.text;
  for (std::size_t i = 1; i + 1 < w.size(); ++i) {
    if (w[i] != '$') {
      out += w[i];
      continue;
    }
    const char e = i + 2 < w.size()
                       ? static_cast<char>(std::toupper(static_cast<unsigned char>(w[i + 1])))
                       : '\0';
    if (e == '$' || e == '\'' || e == '"')
      out += e;
    else if (e == 'L' || e == 'N')
      out += '\n';
    else if (e == 'P')
      out += '\f';
    else if (e == 'R')
      out += '\r';
    else if (e == 'T')
      out += '\t';
    else if (std::isxdigit(static_cast<unsigned char>(e)) && i + 3 < w.size() &&
             std::isxdigit(static_cast<unsigned char>(w[i + 2]))) {
      out += static_cast<char>(std::stoi(w.substr(i + 1, 2), nullptr, 16));
      ++i;
    } else {
      fail(t, "malformed '$' escape in the string " + w);
    }
    ++i;
  }
  return out;
}

ExprPtr Parser::primary() {
  const Token& t = peek();
  const auto loc = where(t);
  switch (t.kind) {
    case TokenKind::Integer:
    case TokenKind::Time: {
      next();
      const bool time = t.kind == TokenKind::Time;
      if (!time && t.negation_only) integer_value(t, false);  // out of range: fails
      // LINT#-9223372036854775808 has no positive magnitude to negate.
      if (t.value == std::numeric_limits<std::int64_t>::min()) return model::make_int(t.value, loc);
      const std::int64_t v = t.value < 0 ? -t.value : t.value;
      ExprPtr lit = time ? model::make_time(v, loc) : model::make_int(v, loc);
      // INT#-5 is Neg(5), like -5, so that printing and re-reading give the same model.
      return t.value < 0 ? model::make_unary(ExprKind::Neg, lit, loc) : lit;
    }
    case TokenKind::Bool:
      next();
      return model::make_bool(t.value != 0, loc);
    case TokenKind::LParen: {
      next();
      ExprPtr e = expression();
      expect(TokenKind::RParen, "')'");
      return e;
    }
    case TokenKind::Unsupported:  // refused where it is used (model::UnmodelledConst)
      next();
      return model::make_unmodelled_literal(t.text, loc);
    case TokenKind::String: {
      next();
      if (t.text.front() == '"') fail(t, "unsupported: WSTRING literal " + t.text);
      return model::make_string(string_characters(t), loc);
    }
    case TokenKind::DirectAddress:
      fail(t, "unsupported: direct address " + t.text +
                  " in an expression (declare a variable AT it)");
    case TokenKind::Identifier:
      break;
    default:
      fail_unexpected("an expression");
  }
  if (at_word("TRUE") || at_word("FALSE")) {
    next();
    return model::make_bool(model::iequals(t.text, "TRUE"), loc);
  }
  if (is_reserved(t.text)) fail_unexpected("an expression");
  next();
  if (at(TokenKind::LParen)) return call(t);
  if (at(TokenKind::Caret)) fail(peek(), "unsupported: pointer dereference of '" + t.text + "'");
  if (!at(TokenKind::Dot) && !at(TokenKind::LBracket)) return model::make_name(t.text, loc);
  std::string path = t.text;
  std::vector<ExprPtr> indices;
  for (;;) {
    if (at(TokenKind::LBracket)) {
      subscript(path, indices);
      continue;
    }
    if (!accept(TokenKind::Dot)) break;
    // Bit access `w.3`: the member is the bit number.
    if (at(TokenKind::Integer) && peek().value >= 0 && peek().value < 64 && indices.empty()) {
      const Token& bit = next();
      return model::make_member(path, std::to_string(bit.value), loc);
    }
    if (!at(TokenKind::Identifier)) fail_unexpected("a member name after '.'");
    const Token& member = next();
    if (at(TokenKind::LParen))
      fail(member, "unsupported: call of method '" + path + "." + member.text + "'");
    path += "." + member.text;
  }
  if (!indices.empty()) return model::make_index(path, std::move(indices), loc);
  // `a.b.c` (a member of a nested instance, or an element `s.x`): name "a.b", member "c".
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return model::make_name(path, loc);
  return model::make_member(path.substr(0, dot), path.substr(dot + 1), loc);
}

void Parser::subscript(std::string& path, std::vector<ExprPtr>& indices) {
  const Token& open = next();  // '['
  std::vector<ExprPtr> k;
  do k.push_back(expression());
  while (accept(TokenKind::Comma));
  expect(TokenKind::RBracket, "']' after the index");
  // Constant indices are part of the element's name (`a[2]`); others are chosen by the model.
  std::string constant = "[";
  bool all_constant = true;
  for (std::size_t i = 0; i < k.size(); ++i) {
    const auto& e = k[i];
    std::optional<std::int64_t> v;
    if (e->kind == ExprKind::IntConst) v = e->value;
    if (e->kind == ExprKind::Neg && e->args[0]->kind == ExprKind::IntConst) v = -e->args[0]->value;
    if (!v)
      all_constant = false;
    else
      constant += (i ? "," : "") + std::to_string(*v);
  }
  if (all_constant) {
    // `a[1][2]` (CODESYS's ARRAY OF ARRAY) is `a[1,2]`: one array of both dimensions.
    if (!path.empty() && path.back() == ']' && !path.ends_with("[*]")) {
      path.back() = ',';
      path += constant.substr(1) + "]";
    } else {
      path += constant + "]";
    }
    return;
  }
  if (!indices.empty())
    fail(open,
         "unsupported: a second non-constant index in '" + path.substr(0, path.find('[')) + "'");
  path += "[*]";
  indices = std::move(k);
}

// ------------------------------------------------------------------------------- statements

model::StmtList Parser::statements() {
  model::StmtList out;
  for (;;) {
    if (accept(TokenKind::Semicolon)) continue;  // empty statement
    if (!at(TokenKind::Identifier)) return out;
    const std::string w = upper(peek().text);
    if (w.rfind("END_", 0) == 0 || w == "ELSE" || w == "ELSIF" || w == "STEP" ||
        w == "INITIAL_STEP" || w == "TRANSITION" || w == "ACTION" || w == "UNTIL")
      return out;
    // `Idle:`, `A, B:`, `E.Idle:`: the next CASE label, an enumerator.
    const auto label_end = [&](std::size_t k) {
      return at(TokenKind::Colon, k) || at(TokenKind::Comma, k) || at(TokenKind::DotDot, k);
    };
    if (in_case_ > 0 &&
        (label_end(1) || (at(TokenKind::Dot, 1) && at(TokenKind::Identifier, 2) && label_end(3))))
      return out;
    out.push_back(statement());
  }
}

void Parser::end_statement(std::string_view what) {
  if (accept(TokenKind::Semicolon)) return;
  // The last statement of a text may omit its ';' (seen in exported XML bodies).
  if (at(TokenKind::End)) return;
  fail_unexpected("';' after " + std::string(what));
}

model::StmtPtr Parser::statement() {
  const Token& t = peek();
  enter(t);
  DepthGuard guard([this] { leave(); });
  if (at_word("FOR")) return for_statement();
  if (at_word("WHILE") || at_word("REPEAT")) return while_statement();
  if (at_word("EXIT") || at_word("CONTINUE") || at_word("RETURN")) {
    next();
    auto s = std::make_shared<model::Stmt>();
    s->kind = model::iequals(t.text, "EXIT")       ? model::StmtKind::Exit
              : model::iequals(t.text, "CONTINUE") ? model::StmtKind::Continue
                                                   : model::StmtKind::Return;
    s->where = where(t);
    end_statement(upper(t.text));
    return s;
  }
  // JMP is an IL operator, so a legal name; `JMP label;` is the CODESYS ST jump.
  if (at_word("JMP") && at(TokenKind::Identifier, 1) && at(TokenKind::Semicolon, 2))
    fail(t, "unsupported: JMP statement");
  if (at_word("IF")) return if_statement();
  if (at_word("CASE")) return case_statement();
  if (is_reserved(t.text)) fail_unexpected("a statement");
  next();
  if (at(TokenKind::LParen)) return fb_call(t);
  if (at(TokenKind::Dot) || at(TokenKind::LBracket) || at(TokenKind::Assign)) {
    // `x := v`, `inst.x := v` (a member of an instance, possibly nested: `a.b.x`), `a[i].y := v`.
    std::string target = t.text;
    std::vector<ExprPtr> indices;
    for (;;) {
      if (at(TokenKind::LBracket)) {
        subscript(target, indices);
        continue;
      }
      if (!accept(TokenKind::Dot)) break;
      if (!at(TokenKind::Identifier)) fail_unexpected("a member name after '.'");
      target += "." + next().text;
    }
    if (at(TokenKind::LParen)) {
      // `inst.ACT();` (TwinCAT): a call of an action of a function block instance.
      if (!indices.empty())
        fail(peek(), "unsupported: a call of an instance chosen by a variable index");
      Token call = t;
      call.text = target;
      return fb_call(call);
    }
    expect(TokenKind::Assign, "':='");
    outputs_call_at_ = position();
    call_outputs_.clear();
    ExprPtr value = expression();
    outputs_call_at_ = static_cast<std::size_t>(-1);
    end_statement("the assignment");
    auto assign = model::make_assign(target, value, where(t));
    if (indices.empty() && call_outputs_.empty()) return assign;
    auto s = std::make_shared<model::Stmt>(*assign);
    s->target_indices = std::move(indices);
    s->outputs = std::move(call_outputs_);
    return s;
  }
  if (at(TokenKind::Colon))
    fail(t,
         "unsupported: label '" + t.text + "' (jump labels; CASE labels must be integer literals)");
  if (at(TokenKind::Arrow)) fail(peek(), "unsupported: output assignment '=>'");
  fail_unexpected("':=' or '(' after '" + t.text + "'");
}

std::string Parser::bound_variable() {
  if (!at(TokenKind::Identifier)) fail_unexpected("a variable after '=>'");
  std::string var = next().text;
  while (accept(TokenKind::Dot)) {
    if (!at(TokenKind::Identifier)) fail_unexpected("a member name after '.'");
    var += "." + next().text;
  }
  return var;
}

model::StmtPtr Parser::fb_call(const Token& name) {
  expect(TokenKind::LParen, "'('");
  std::vector<std::pair<std::string, ExprPtr>> args;
  std::vector<std::pair<std::string, std::string>> outputs;
  if (!at(TokenKind::RParen)) {
    do {
      if (at_word("NOT") && at(TokenKind::Identifier, 1) && at(TokenKind::Arrow, 2))
        fail(peek(), "unsupported: output assignment '=>' in the call of '" + name.text + "'");
      if (!(at(TokenKind::Identifier) && (at(TokenKind::Assign, 1) || at(TokenKind::Arrow, 1)))) {
        if (at(TokenKind::RParen)) fail_unexpected("an input name");
        fail(peek(), "unsupported: positional arguments in the call of '" + name.text +
                         "' (write IN := value)");
      }
      const Token& input = next();
      if (accept(TokenKind::Arrow)) {  // `Q => y`: y receives the output after the call
        outputs.emplace_back(input.text, bound_variable());
        continue;
      }
      next();
      args.emplace_back(input.text, expression());
    } while (accept(TokenKind::Comma));
  }
  expect(TokenKind::RParen, "',' or ')'");
  end_statement("the call of '" + name.text + "'");
  auto call = model::make_fb_call(name.text, std::move(args), where(name));
  if (!outputs.empty()) {
    auto s = std::make_shared<model::Stmt>(*call);
    s->outputs = std::move(outputs);
    return s;
  }
  return call;
}

model::StmtPtr Parser::if_statement() {
  const Token& kw = next();  // IF
  auto s = std::make_shared<model::Stmt>();
  s->kind = model::StmtKind::If;
  s->where = where(kw);
  do {
    s->conditions.push_back(expression());
    expect_word("THEN");
    s->bodies.push_back(statements());
  } while (accept_word("ELSIF"));
  if (accept_word("ELSE")) s->else_body = statements();
  expect_word("END_IF");
  accept(TokenKind::Semicolon);
  return s;
}

model::ExprPtr Parser::call(const Token& name) {
  // Outputs only where the call is the whole right side: `y := F(x, q => z);`.
  const bool may_bind_outputs = position() == outputs_call_at_ + 1;
  expect(TokenKind::LParen, "'('");
  std::vector<ExprPtr> args;
  // IEC 61131-3 2.5.1.1: a call is formal (every argument `name := value`) or positional.
  std::vector<std::string> names;
  std::vector<std::pair<std::string, std::string>> outputs;
  if (!at(TokenKind::RParen)) {
    do {
      const bool formal = at(TokenKind::Identifier) && at(TokenKind::Assign, 1);
      if (at(TokenKind::Identifier) && at(TokenKind::Arrow, 1)) {
        if (!may_bind_outputs)
          fail(peek(), "unsupported: output argument '" + peek().text +
                           " =>' in the call of function '" + name.text +
                           "' (outputs are bound only by a call that is the whole right side of "
                           "an assignment: y := " +
                           name.text + "(..., " + peek().text + " => z);)");
        const Token& output = next();
        next();  // =>
        outputs.emplace_back(output.text, bound_variable());
        continue;
      }
      if ((!args.empty() && formal != !names.empty()) || (!formal && !outputs.empty()))
        fail(peek(), "the call of function '" + name.text +
                         "' mixes formal ('name := value') and positional arguments");
      if (formal) {
        names.push_back(next().text);
        next();  // :=
      }
      args.push_back(expression());
    } while (accept(TokenKind::Comma));
  }
  expect(TokenKind::RParen, "',' or ')'");
  if (!outputs.empty()) {
    if (!args.empty() && names.empty())
      fail(name, "the call of function '" + name.text +
                     "' mixes formal ('name := value') and positional arguments");
    call_outputs_ = std::move(outputs);
    // The right side must end here: `y := F(q => z) + 1` would copy z in the middle of it.
    if (!at(TokenKind::Semicolon))
      fail(peek(), "output arguments '=>' in the call of function '" + name.text +
                       "': the call must be the whole right side of the assignment");
  }
  if (!names.empty())
    return model::make_formal_call(name.text, std::move(names), std::move(args), where(name));
  return model::make_call(name.text, std::move(args), where(name));
}

model::StmtPtr Parser::for_statement() {
  const Token& kw = next();  // FOR
  auto s = std::make_shared<model::Stmt>();
  s->kind = model::StmtKind::For;
  s->where = where(kw);
  s->target = identifier("the FOR loop's control variable");
  expect(TokenKind::Assign, "':=' after the FOR control variable");
  s->value = expression();
  expect_word("TO");
  s->limit = expression();
  if (accept_word("BY")) s->step = expression();
  expect_word("DO");
  s->bodies.push_back(statements());
  expect_word("END_FOR");
  accept(TokenKind::Semicolon);
  return s;
}

model::StmtPtr Parser::while_statement() {
  const Token& kw = next();  // WHILE or REPEAT
  auto s = std::make_shared<model::Stmt>();
  s->where = where(kw);
  if (model::iequals(kw.text, "WHILE")) {
    s->kind = model::StmtKind::While;
    s->conditions.push_back(expression());
    expect_word("DO");
    s->bodies.push_back(statements());
    expect_word("END_WHILE");
  } else {
    s->kind = model::StmtKind::Repeat;
    s->bodies.push_back(statements());
    expect_word("UNTIL");
    s->conditions.push_back(expression());
    expect_word("END_REPEAT");
  }
  accept(TokenKind::Semicolon);
  return s;
}

std::int64_t Parser::case_bound() {
  const bool negative = accept(TokenKind::Minus);
  const Token& t = peek();
  if (t.kind != TokenKind::Integer) fail_unexpected("an integer literal");
  next();
  return integer_value(t, negative);
}

void Parser::case_label_bound(std::int64_t& value, std::string& name) {
  if (at(TokenKind::Identifier) && !is_reserved(peek().text)) {
    // An enumerator (`Idle`, `E_State#Idle`, `E_State.Idle`), resolved when types are lowered.
    name = next().text;
    if (accept(TokenKind::Dot)) name += "." + identifier("an enumerator after '.'");
    return;
  }
  value = case_bound();
}

model::StmtPtr Parser::case_statement() {
  const Token& kw = next();  // CASE
  auto s = std::make_shared<model::Stmt>();
  s->kind = model::StmtKind::Case;
  s->where = where(kw);
  s->value = expression();
  expect_word("OF");
  ++in_case_;
  DepthGuard in_case([this] { --in_case_; });
  while (at(TokenKind::Integer) || at(TokenKind::Minus) ||
         (at(TokenKind::Identifier) && !is_reserved(peek().text))) {
    std::vector<model::CaseLabel> labels;
    do {
      model::CaseLabel l;
      case_label_bound(l.lo, l.lo_name);
      l.hi = l.lo;
      l.hi_name = l.lo_name;
      if (accept(TokenKind::DotDot)) {
        l.hi_name.clear();
        case_label_bound(l.hi, l.hi_name);
      }
      labels.push_back(l);
    } while (accept(TokenKind::Comma));
    expect(TokenKind::Colon, "':' after the CASE labels");
    s->labels.push_back(std::move(labels));
    s->bodies.push_back(statements());
  }
  if (accept_word("ELSE")) s->else_body = statements();
  expect_word("END_CASE");
  accept(TokenKind::Semicolon);
  return s;
}

// ------------------------------------------------------------------------------ VAR sections

namespace {
struct SectionKind {
  std::string_view word;
  model::VarDirection direction;
};
constexpr std::array<SectionKind, 7> kSections{{
    {"VAR", model::VarDirection::Local},
    {"VAR_INPUT", model::VarDirection::Input},
    {"VAR_OUTPUT", model::VarDirection::Output},
    {"VAR_IN_OUT", model::VarDirection::InOut},
    {"VAR_GLOBAL", model::VarDirection::Global},
    {"VAR_EXTERNAL", model::VarDirection::External},
    {"VAR_TEMP", model::VarDirection::Local},
}};
}  // namespace

bool Parser::at_var_section() const {
  if (!at(TokenKind::Identifier)) return false;
  for (const auto& s : kSections)
    if (at_word(s.word)) return true;
  return at_word("VAR_ACCESS") || at_word("VAR_CONFIG");
}

model::Type Parser::var_type(std::vector<model::ArrayDimension>* dimensions) {
  const Token& t = peek();
  if (t.kind != TokenKind::Identifier) fail_unexpected("a type name");
  const std::string name = upper(t.text);
  if (name == "ARRAY" && dimensions) {
    // ARRAY [lo..hi, ...] OF T; ARRAY[..] OF ARRAY[..] OF T is one array of both dimensions.
    next();
    expect(TokenKind::LBracket, "'[' after ARRAY");
    do {
      model::ArrayDimension d;
      d.lo = case_bound();
      expect(TokenKind::DotDot, "'..' in the array bounds");
      d.hi = case_bound();
      if (d.lo > d.hi)
        fail(t,
             "array bounds [" + std::to_string(d.lo) + ".." + std::to_string(d.hi) + "] are empty");
      dimensions->push_back(d);
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RBracket, "']' after the array bounds");
    expect_word("OF");
    return var_type(dimensions);
  }
  if (name == "STRING") {
    // STRING, STRING(80), STRING[80]: the length does not matter to = and <> (1.7a).
    next();
    if (at(TokenKind::LParen) || at(TokenKind::LBracket)) {
      const bool paren = at(TokenKind::LParen);
      next();
      expect(TokenKind::Integer, "the string's length");
      expect(paren ? TokenKind::RParen : TokenKind::RBracket, paren ? "')'" : "']'");
    }
    return model::Type::string();
  }
  if (name == "ARRAY" || name == "POINTER" || name == "REF_TO" || name == "STRUCT" ||
      name == "WSTRING" || name == "REAL" || name == "LREAL")
    fail(t, "unsupported type " + name +
                " (sfcv models BOOL, integers, TIME, STRING, enumerations, arrays, structures and "
                "FBs)");
  next();
  auto type = model::elementary_type(name);
  if (!type && !at(TokenKind::LParen)) {
    // Any other name is a user type (TYPE ... END_TYPE) or a user function block: lowering
    // resolves the types (model::lower_data_types), the semantics the function blocks, and
    // each refuses, with this location, a name that is neither.
    model::Type fb;
    fb.kind = model::TypeKind::FunctionBlock;
    fb.fb = model::StandardFb::None;
    fb.name = t.text;
    return fb;
  }
  if (!type)
    fail(t,
         "unsupported type '" + t.text + "' (sfcv models BOOL, integers, TIME and standard FBs)");
  if (at(TokenKind::LParen)) {
    if (type->kind != model::TypeKind::Int) fail(peek(), "a subrange needs an integer base type");
    next();
    const std::int64_t lo = case_bound();
    expect(TokenKind::DotDot, "'..' in the subrange");
    const std::int64_t hi = case_bound();
    expect(TokenKind::RParen, "')' after the subrange");
    if (lo > hi || lo < type->lo || hi > type->hi)
      fail(t, "subrange " + std::to_string(lo) + ".." + std::to_string(hi) +
                  " is empty or outside " + name);
    type = model::Type::integer(name + "(" + std::to_string(lo) + ".." + std::to_string(hi) + ")",
                                lo, hi);
  }
  return *type;
}

model::ExprPtr Parser::initialiser() {
  const Token& t = peek();
  enter(t);
  DepthGuard guard([this] { leave(); });
  if (accept(TokenKind::LBracket)) {
    // `[1, 2, 3(0)]`: one argument per element, repetitions expanded.
    std::vector<ExprPtr> elements;
    do {
      if (at(TokenKind::Integer) && at(TokenKind::LParen, 1)) {
        const Token& count = next();
        next();
        ExprPtr e = at(TokenKind::RParen) ? nullptr : initialiser();
        expect(TokenKind::RParen, "')' after the repeated value");
        if (count.value < 0 || count.negation_only)
          fail(count, "repetition count " + count.text + " is negative");
        if (count.value > 100000 - static_cast<std::int64_t>(elements.size()))
          fail(count, "array initialiser with more than 100000 elements");
        if (!e) fail(count, "unsupported: a repetition without a value");
        for (std::int64_t i = 0; i < count.value; ++i) elements.push_back(e);
        continue;
      }
      elements.push_back(initialiser());
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RBracket, "']' after the array initialiser");
    return model::make_call("[", std::move(elements), where(t));
  }
  if (at(TokenKind::LParen) && at(TokenKind::Identifier, 1) && at(TokenKind::Assign, 2)) {
    // `(x := 1, y := Red)`: a structure.
    next();
    std::vector<std::string> names;
    std::vector<ExprPtr> values;
    do {
      names.push_back(identifier("a field name"));
      expect(TokenKind::Assign, "':='");
      values.push_back(initialiser());
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RParen, "')' after the structure initialiser");
    return model::make_formal_call("(", std::move(names), std::move(values), where(t));
  }
  return expression();
}

void Parser::var_section(std::vector<model::Variable>& out) {
  const Token& kw = next();
  std::optional<model::VarDirection> direction;
  for (const auto& s : kSections)
    if (model::iequals(s.word, kw.text)) direction = s.direction;
  if (!direction) fail(kw, "unsupported: " + upper(kw.text) + " section");
  bool constant = false;
  for (;;) {
    if (accept_word("CONSTANT"))
      constant = true;
    else if (!accept_word("RETAIN") && !accept_word("NON_RETAIN") && !accept_word("PERSISTENT"))
      break;
  }
  const auto first = out.size();
  declarations(*direction, "END_VAR", out);
  for (auto i = first; i < out.size(); ++i) out[i].constant = constant;
  next();  // END_VAR
}

void Parser::declarations(model::VarDirection direction, std::string_view end,
                          std::vector<model::Variable>& out) {
  while (!at_word(end)) {
    if (at(TokenKind::End)) fail_unexpected(end);
    std::vector<const Token*> names;
    do {
      const Token& n = peek();
      identifier("a variable name or END_VAR");
      names.push_back(&n);
    } while (accept(TokenKind::Comma));
    std::string address;
    if (accept_word("AT")) {
      if (names.size() > 1) fail(*names[1], "AT can locate only one variable");
      address = expect(TokenKind::DirectAddress, "a direct address such as %IX1").text;
    }
    expect(TokenKind::Colon, "':' and a type");
    std::vector<model::ArrayDimension> dimensions;
    model::Type type = var_type(&dimensions);
    std::optional<std::int64_t> initial;
    ExprPtr declared_initial;
    const bool user_type =
        type.kind == model::TypeKind::FunctionBlock && type.fb == model::StandardFb::None;
    const bool has_initial = accept(TokenKind::Assign);
    if (has_initial && (user_type || !dimensions.empty() || type.is_string())) {
      declared_initial = initialiser();  // checked when the types are lowered
    } else if (has_initial) {
      const Token& init_tok = peek();
      if (type.kind == model::TypeKind::FunctionBlock)
        fail(init_tok, "unsupported: initial values of function block instances");
      ExprPtr e = expression();
      bool negative = false;
      if (e->kind == ExprKind::Neg) {
        negative = true;
        e = e->args[0];
      }
      const auto k = e->kind;
      const bool fits =
          (type.kind == model::TypeKind::Bool &&
           (k == ExprKind::BoolConst || (k == ExprKind::IntConst && !negative && e->value <= 1))) ||
          (type.kind == model::TypeKind::Int && k == ExprKind::IntConst) ||
          (type.kind == model::TypeKind::Time && k == ExprKind::TimeConst && !negative);
      if (k != ExprKind::BoolConst && k != ExprKind::IntConst && k != ExprKind::TimeConst)
        fail(init_tok, "unsupported: initial value that is not a literal");
      if (!fits) fail(init_tok, "initial value does not match type " + type.name);
      if (negative && e->value == std::numeric_limits<std::int64_t>::min())
        fail(init_tok, "initial value is outside " + model::range_text(type));
      const std::int64_t v = negative ? -e->value : e->value;
      if (const auto why = model::range_error(v, type, "initial value " + std::to_string(v));
          type.kind == model::TypeKind::Int && !why.empty())
        fail(init_tok, why);
      initial = v;
    }
    if (at(TokenKind::Identifier) && (at_word("R_EDGE") || at_word("F_EDGE")))
      fail(peek(), "unsupported: " + upper(peek().text) + " declarations");
    expect(TokenKind::Semicolon, "';' after the declaration");
    for (const Token* n : names) {
      model::Variable v;
      v.name = n->text;
      v.direction = direction;
      v.type = type;
      v.initial = initial;
      v.declared_initial = declared_initial;
      v.dimensions = dimensions;
      v.address = address;
      v.where = where(*n);
      out.push_back(std::move(v));
    }
  }
}

void Parser::type_declarations(std::vector<model::DataType>& out) {
  expect_word("TYPE");
  while (!at_word("END_TYPE")) {
    if (at(TokenKind::End)) fail_unexpected("END_TYPE");
    model::DataType t;
    const Token& name = peek();
    t.name = identifier("a type name or END_TYPE");
    t.where = where(name);
    expect(TokenKind::Colon, "':' after the type name");
    if (accept_word("STRUCT")) {
      t.kind = model::DataTypeKind::Structure;
      declarations(model::VarDirection::Local, "END_STRUCT", t.fields);
      next();  // END_STRUCT
      if (t.fields.empty()) fail(name, "structure '" + t.name + "' has no field");
    } else if (at(TokenKind::LParen)) {
      // (A, B := 5, C): values count on from the previous one, from 0.
      t.kind = model::DataTypeKind::Enumeration;
      next();
      std::int64_t value = 0;
      bool past_lint = false;  // the previous enumerator was LINT's largest value
      do {
        const Token& at_name = peek();
        const std::string e = identifier("an enumerator");
        if (accept(TokenKind::Assign)) {
          const bool negative = accept(TokenKind::Minus);
          const Token& v = expect(TokenKind::Integer, "an integer value of the enumerator");
          value = integer_value(v, negative);
        } else if (past_lint) {
          fail(at_name, "enumerator '" + e + "' would be past the range of LINT");
        }
        t.enumerators.emplace_back(e, value);
        past_lint = value == std::numeric_limits<std::int64_t>::max();
        if (!past_lint) ++value;
      } while (accept(TokenKind::Comma));
      expect(TokenKind::RParen, "')' after the enumerators");
      // `(A, B) := B`: the default of the type's variables, first enumerator otherwise.
      if (accept(TokenKind::Assign)) {
        const std::string d = identifier("the enumerator the type starts with");
        auto it = std::find_if(t.enumerators.begin(), t.enumerators.end(),
                               [&](const auto& en) { return model::iequals(en.first, d); });
        if (it == t.enumerators.end()) fail(name, "'" + d + "' is no enumerator of " + t.name);
        std::rotate(t.enumerators.begin(), it, it + 1);
      }
    } else {
      // An alias: `T : INT(0..5)`, `T : ARRAY[1..3] OF INT := [..]`, `T : Other`.
      t.kind = model::DataTypeKind::Alias;
      model::Variable v;
      v.where = t.where;
      v.type = var_type(&v.dimensions);
      if (accept(TokenKind::Assign)) v.declared_initial = initialiser();
      t.fields.push_back(std::move(v));
    }
    expect(TokenKind::Semicolon, "';' after the type declaration");
    out.push_back(std::move(t));
  }
  next();  // END_TYPE
}

}  // namespace st

// --------------------------------------------------------------------------- free functions

namespace {
template <typename F>
void run(std::string_view text, const model::SourceLocation& start, model::Diagnostics& diags,
         F&& body) {
  st::Locator locator(start);
  model::Diagnostics lexical;
  auto tokens = st::tokenize(text, locator, lexical);
  if (!lexical.empty()) {
    diags.insert(diags.end(), lexical.begin(), lexical.end());
    return;
  }
  st::Parser parser(std::move(tokens), locator);
  try {
    body(parser);
    if (!parser.at(st::TokenKind::End)) parser.fail_unexpected("end of text");
  } catch (const st::ParseError& e) {
    diags.push_back({model::Severity::Error, e.where, e.what()});
  }
}
}  // namespace

model::ExprPtr parse_st_expression(std::string_view text, const model::SourceLocation& start,
                                   model::Diagnostics& diags) {
  model::ExprPtr result;
  bool ok = false;
  const auto before = diags.size();
  run(text, start, diags, [&](st::Parser& p) {
    if (p.at(st::TokenKind::End)) p.fail_unexpected("an expression");
    result = p.expression();
    p.accept(st::TokenKind::Semicolon);  // some exporters end conditions with ';'
    ok = true;
  });
  if (!ok || diags.size() != before) return nullptr;
  return result;
}

model::StmtList parse_st_statements(std::string_view text, const model::SourceLocation& start,
                                    model::Diagnostics& diags) {
  model::StmtList result;
  run(text, start, diags, [&](st::Parser& p) {
    result = p.statements();
    if (!p.at(st::TokenKind::End)) {
      result.clear();
      p.fail_unexpected("a statement");
    }
  });
  return result;
}

std::vector<model::Variable> parse_var_sections(std::string_view text,
                                                const model::SourceLocation& start,
                                                model::Diagnostics& diags) {
  std::vector<model::Variable> result;
  run(text, start, diags, [&](st::Parser& p) {
    while (p.at_var_section()) p.var_section(result);
  });
  return result;
}

}  // namespace sfcv::io

#include "logic/parser.hpp"

#include <cctype>
#include <limits>
#include <stdexcept>
#include <vector>

#include "logic/formula.hpp"
#include "logic/pattern.hpp"
#include "model/errors.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::logic {

namespace {

enum class Tok {
  Ident,
  Int,
  Not,
  And,
  Or,
  Implies,
  Iff,
  LParen,
  RParen,
  LBracket,
  RBracket,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  Semi,
  Colon,
  Plus,
  Minus,
  Star,
  Slash,
  End,
  Bad,
};

struct Token {
  Tok kind = Tok::End;
  std::string text;
  std::int64_t value = 0;
  int line = 1, column = 1;
  std::size_t offset = 0;  ///< into the text: a `pattern` statement is read from its text
};

std::vector<Token> lex(std::string_view s) {
  std::vector<Token> out;
  int line = 1, col = 1;
  std::size_t i = 0;
  auto advance = [&](std::size_t n) {
    for (std::size_t k = 0; k < n && i < s.size(); ++k, ++i) {
      if (s[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
  };
  while (i < s.size()) {
    const char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      advance(1);
      continue;
    }
    if ((c == '-' && i + 1 < s.size() && s[i + 1] == '-') ||
        (c == '/' && i + 1 < s.size() && s[i + 1] == '/')) {
      while (i < s.size() && s[i] != '\n') advance(1);
      continue;
    }
    Token t;
    t.line = line;
    t.column = col;
    t.offset = i;
    auto sym = [&](Tok k, std::size_t n) {
      t.kind = k;
      t.text = std::string(s.substr(i, n));
      advance(n);
    };
    const auto rest = s.substr(i);
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t n = 0;
      for (;;) {
        while (n < rest.size() && (std::isalnum(static_cast<unsigned char>(rest[n])) ||
                                   rest[n] == '_' || rest[n] == '.'))
          ++n;
        // An array element `a[2]`, `m[1,-2].x`: constant indices are part of its name.
        if (n >= rest.size() || rest[n] != '[') break;
        std::size_t close = n + 1;
        while (close < rest.size() && (std::isdigit(static_cast<unsigned char>(rest[close])) ||
                                       rest[close] == ',' || rest[close] == '-'))
          ++close;
        if (close == n + 1 || close >= rest.size() || rest[close] != ']') break;
        n = close + 1;
      }
      sym(Tok::Ident, n);
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '-' && rest.size() > 1 && std::isdigit(static_cast<unsigned char>(rest[1])))) {
      std::size_t n = 1;
      while (n < rest.size() && std::isdigit(static_cast<unsigned char>(rest[n]))) ++n;
      // The one checked conversion (model/literal.hpp): -9223372036854775808 is a literal.
      const auto v = model::integer_literal(rest.substr(0, n));
      t.value = v.value.value_or(0);
      sym(v ? Tok::Int : Tok::Bad, n);
    } else if (rest.starts_with("<->")) {
      sym(Tok::Iff, 3);
    } else if (rest.starts_with("->")) {
      sym(Tok::Implies, 2);
    } else if (rest.starts_with("!=") || rest.starts_with("<>")) {
      sym(Tok::Ne, 2);
    } else if (rest.starts_with("<=")) {
      sym(Tok::Le, 2);
    } else if (rest.starts_with(">=")) {
      sym(Tok::Ge, 2);
    } else if (rest.starts_with("==")) {
      sym(Tok::Eq, 2);
    } else {
      switch (c) {
        case '!':
          sym(Tok::Not, 1);
          break;
        case '&':
          sym(Tok::And, 1);
          break;
        case '|':
          sym(Tok::Or, 1);
          break;
        case '(':
          sym(Tok::LParen, 1);
          break;
        case ')':
          sym(Tok::RParen, 1);
          break;
        case '[':
          sym(Tok::LBracket, 1);
          break;
        case ']':
          sym(Tok::RBracket, 1);
          break;
        case '=':
          sym(Tok::Eq, 1);
          break;
        case '<':
          sym(Tok::Lt, 1);
          break;
        case '>':
          sym(Tok::Gt, 1);
          break;
        case ';':
          sym(Tok::Semi, 1);
          break;
        case ':':
          sym(Tok::Colon, 1);
          break;
        case '+':
          sym(Tok::Plus, 1);
          break;
        case '-':
          sym(Tok::Minus, 1);
          break;
        case '*':
          sym(Tok::Star, 1);
          break;
        case '/':
          sym(Tok::Slash, 1);
          break;
        default:
          sym(Tok::Bad, 1);
          break;
      }
    }
    out.push_back(std::move(t));
  }
  Token end;
  end.kind = Tok::End;
  end.line = line;
  end.column = col;
  end.offset = s.size();
  out.push_back(end);
  return out;
}

struct SyntaxError : InputError {
  SyntaxError(const Token& t, const std::string& m)
      : InputError(m), line(t.line), column(t.column) {}
  int line, column;
};

std::string describe(const Token& t) {
  if (t.kind == Tok::End) return "end of input";
  return "'" + t.text + "'";
}

bool is_temporal_keyword(const std::string& s, Op& op) {
  static const std::pair<const char*, Op> table[] = {{"EX", Op::EX}, {"AX", Op::AX},
                                                     {"EF", Op::EF}, {"AF", Op::AF},
                                                     {"EG", Op::EG}, {"AG", Op::AG}};
  for (const auto& [k, o] : table)
    if (s == k) {
      op = o;
      return true;
    }
  return false;
}

// The first temporal operator in f, or null.
const Formula* first_temporal(const Formula& f) {
  if (is_temporal(f.op)) return &f;
  for (const auto& a : f.args)
    if (const auto* t = first_temporal(*a)) return t;
  return nullptr;
}

class Parser {
 public:
  /// `ltl`: the linear operators X F G U R W are keywords and the CTL ones are refused.
  explicit Parser(const std::vector<Token>& toks, std::size_t pos = 0, bool ltl = false)
      : t_(toks), pos_(pos), ltl_(ltl) {}

  FormulaPtr formula() { return iff(); }
  const Token& peek(std::size_t k = 0) const { return t_[std::min(pos_ + k, t_.size() - 1)]; }
  const Token& next() { return t_[pos_ < t_.size() - 1 ? pos_++ : pos_]; }
  std::size_t pos() const { return pos_; }
  void expect(Tok k, const char* what) {
    if (peek().kind != k)
      throw SyntaxError(peek(), std::string("expected ") + what + ", found " + describe(peek()));
    next();
  }

 private:
  // Recursion (parentheses, unary and temporal operators, `->`) and the height of chains built
  // by loops (`a & b & c ...`) are both bounded by model::kMaxNesting.
  void enter(const model::NestingLevel& level, const Token& t) const {
    if (level.too_deep())
      throw SyntaxError(
          t, "formula nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
  }
  FormulaPtr bounded(FormulaPtr f, const Token& op) const {
    if (f->height > static_cast<std::uint32_t>(model::kMaxNesting))
      throw SyntaxError(
          op, "formula nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
    return f;
  }
  FormulaPtr iff() {
    auto lhs = implies();
    while (peek().kind == Tok::Iff) {
      const auto& op = next();
      auto rhs = implies();
      lhs = bounded(make_op(Op::Iff, {boolean(lhs), boolean(rhs)}, op.line, op.column), op);
    }
    return lhs;
  }
  FormulaPtr implies() {
    const model::NestingLevel level(depth_);
    enter(level, peek());
    auto lhs = disjunction();
    if (peek().kind == Tok::Implies) {
      const auto& op = next();
      auto rhs = implies();
      return bounded(make_op(Op::Implies, {boolean(lhs), boolean(rhs)}, op.line, op.column), op);
    }
    return lhs;
  }
  // The IEC 61131-3 operators are keywords in every case (`AND`, `and`): reserved words of ST,
  // so no variable can bear them.
  static bool keyword(const Token& t, const char* k) {
    return t.kind == Tok::Ident && model::iequals(t.text, k);
  }
  static bool is_xor(const Token& t) { return keyword(t, "xor"); }
  static bool is_iec_keyword(const Token& t) {
    return keyword(t, "AND") || keyword(t, "OR") || keyword(t, "XOR") || keyword(t, "NOT") ||
           keyword(t, "MOD");
  }
  FormulaPtr disjunction() {
    auto lhs = conjunction();
    while (peek().kind == Tok::Or || is_xor(peek()) || keyword(peek(), "OR")) {
      const auto& op = next();
      auto rhs = conjunction();
      lhs = bounded(
          make_op(is_xor(op) ? Op::Xor : Op::Or, {boolean(lhs), boolean(rhs)}, op.line, op.column),
          op);
    }
    return lhs;
  }
  FormulaPtr conjunction() {
    auto lhs = until();
    while (peek().kind == Tok::And || keyword(peek(), "AND")) {
      const auto& op = next();
      auto rhs = until();
      lhs = bounded(make_op(Op::And, {boolean(lhs), boolean(rhs)}, op.line, op.column), op);
    }
    return lhs;
  }
  // LTL's binary operators bind tighter than & and weaker than the unary ones (as in Spot):
  // `a & b U c` is `a & (b U c)`, `G a U b` is `(G a) U b`; right associative.
  static bool ltl_binary(const Token& t, Op& op) {
    if (t.kind != Tok::Ident) return false;
    if (t.text == "U")
      op = Op::U;
    else if (t.text == "R")
      op = Op::R;
    else if (t.text == "W")
      op = Op::W;
    else
      return false;
    return true;
  }
  static bool ltl_unary(const Token& t, Op& op) {
    if (t.kind != Tok::Ident) return false;
    if (t.text == "X")
      op = Op::X;
    else if (t.text == "F")
      op = Op::F;
    else if (t.text == "G")
      op = Op::G;
    else
      return false;
    return true;
  }
  FormulaPtr until() {
    if (!ltl_) return unary();
    const model::NestingLevel level(depth_);
    enter(level, peek());
    auto lhs = unary();
    Op op;
    if (ltl_binary(peek(), op)) {
      const auto& t = next();
      auto rhs = until();
      return bounded(make_op(op, {boolean(lhs), boolean(rhs)}, t.line, t.column), t);
    }
    return lhs;
  }
  FormulaPtr unary() {
    const Token& t = peek();
    const model::NestingLevel level(depth_);
    enter(level, t);
    if (t.kind == Tok::Not || keyword(t, "NOT")) {
      next();
      return make_op(Op::Not, {boolean(unary())}, t.line, t.column);
    }
    Op op;
    if (ltl_ && ltl_unary(t, op)) {
      next();
      return make_op(op, {boolean(unary())}, t.line, t.column);
    }
    if (t.kind == Tok::Ident && is_temporal_keyword(t.text, op)) {
      if (ltl_)
        throw SyntaxError(t, "CTL operator " + describe(t) + " in an LTL formula (write " +
                                 t.text.substr(1) + "; every LTL path is universal)");
      next();
      return make_op(op, {boolean(unary())}, t.line, t.column);
    }
    return comparison();
  }

 public:
  /// `f` used as a truth value: a term (a number) is an error located at it.
  static FormulaPtr boolean(FormulaPtr f) {
    if (!is_term(f->op)) return f;
    const Token at{Tok::Ident, "", 0, f->line, f->column};
    if (f->op == Op::Number)
      throw SyntaxError(at,
                        "an integer is not a formula; compare it with a variable, e.g. "
                        "'level >= " +
                            to_string(*f) + "'");
    throw SyntaxError(at, "'" + to_string(*f) + "' is a number, not a formula; compare it, e.g. '" +
                              to_string(*f) + " > 0'");
  }

 private:
  /// A number the lexer could not read (Tok::Bad): the checked conversion says why.
  static void bad_number(const Token& t) {
    if (!t.text.empty() &&
        (std::isdigit(static_cast<unsigned char>(t.text[0])) || t.text[0] == '-'))
      throw SyntaxError(t, model::integer_literal(t.text).error);
  }

  static bool is_cmp(Tok k) {
    return k == Tok::Eq || k == Tok::Ne || k == Tok::Lt || k == Tok::Le || k == Tok::Gt ||
           k == Tok::Ge;
  }
  static CompareOp cmp_of(Tok k) {
    switch (k) {
      case Tok::Eq:
        return CompareOp::Eq;
      case Tok::Ne:
        return CompareOp::Ne;
      case Tok::Lt:
        return CompareOp::Lt;
      case Tok::Le:
        return CompareOp::Le;
      case Tok::Gt:
        return CompareOp::Gt;
      default:
        return CompareOp::Ge;
    }
  }
  static CompareOp flip(CompareOp c) {
    switch (c) {
      case CompareOp::Lt:
        return CompareOp::Gt;
      case CompareOp::Le:
        return CompareOp::Ge;
      case CompareOp::Gt:
        return CompareOp::Lt;
      case CompareOp::Ge:
        return CompareOp::Le;
      default:
        return c;
    }
  }
  static FormulaPtr number(std::int64_t v, int line, int column, std::string name = {}) {
    auto f = std::make_shared<Formula>();
    f->op = Op::Number;
    f->value = v;
    f->value_name = std::move(name);
    f->line = line;
    f->column = column;
    return f;
  }
  // An integer literal or TRUE/FALSE as a constant operand of a comparison.
  static bool literal(const Formula& f, std::int64_t& v) {
    if (f.op == Op::Number && f.value_name.empty()) {
      v = f.value;
      return true;
    }
    if (f.op == Op::True || f.op == Op::False) {
      v = f.op == Op::True ? 1 : 0;
      return true;
    }
    return false;
  }
  /// `f` as an operand of arithmetic or of a comparison of values: a name is its value, TRUE
  /// and FALSE are 1 and 0; a formula (`a & b`) is no number.
  static FormulaPtr term(const FormulaPtr& f, const Token& op) {
    if (is_term(f->op)) return f;
    if (f->op == Op::Atom) {
      auto v = std::make_shared<Formula>(*f);
      v->op = Op::Value;
      return v;
    }
    if (f->op == Op::True || f->op == Op::False)
      return number(f->op == Op::True ? 1 : 0, f->line, f->column,
                    f->op == Op::True ? "TRUE" : "FALSE");
    throw SyntaxError(op, "the formula '" + to_string(*f) + "' is no number for " + describe(op) +
                              ": only = and <> compare truth values");
  }
  // lhs cmp rhs: a name with a constant keeps the Compare atom every engine and export reads;
  // `name = other` is an enumerator or a variable (resolve() decides); two truth values are
  // <-> or xor; anything else is a Relation of two terms.
  FormulaPtr relation(const FormulaPtr& lhs, const Token& op, const FormulaPtr& rhs) {
    const auto c = cmp_of(op.kind);
    std::int64_t v = 0;
    auto named = [](const FormulaPtr& atom, CompareOp cmp, std::int64_t value) {
      auto f = std::make_shared<Formula>(
          *make_compare(atom->name, cmp, value, atom->line, atom->column));
      f->prev = atom->prev;
      return f;
    };
    if (lhs->op == Op::Atom && literal(*rhs, v)) return named(lhs, c, v);
    if (rhs->op == Op::Atom && literal(*lhs, v)) return named(rhs, flip(c), v);
    if (lhs->op == Op::Atom && rhs->op == Op::Atom && rhs->prev == 0) {
      auto f = named(lhs, c, 0);
      f->value_name = rhs->name;
      return f;
    }
    const bool truth_l = !is_term(lhs->op) && lhs->op != Op::Atom;
    const bool truth_r = !is_term(rhs->op) && rhs->op != Op::Atom;
    if ((truth_l || truth_r) && (c == CompareOp::Eq || c == CompareOp::Ne) &&
        !(lhs->op == Op::Number || rhs->op == Op::Number))
      return make_op(c == CompareOp::Eq ? Op::Iff : Op::Xor, {boolean(lhs), boolean(rhs)}, op.line,
                     op.column);
    auto r = make_op(Op::Relation, {term(lhs, op), term(rhs, op)}, lhs->line, lhs->column);
    auto out = std::make_shared<Formula>(*r);
    out->cmp = c;
    return out;
  }
  FormulaPtr comparison() {
    auto lhs = sum();
    if (!is_cmp(peek().kind)) return lhs;
    const Token op = next();
    auto rhs = sum();
    if (is_cmp(peek().kind))
      throw SyntaxError(peek(), "comparisons do not chain: write '(a < b) & (b < c)'");
    return relation(lhs, op, rhs);
  }
  FormulaPtr arithmetic(Op op, const Token& t, const FormulaPtr& a, const FormulaPtr& b) {
    return bounded(make_op(op, {term(a, t), term(b, t)}, t.line, t.column), t);
  }
  FormulaPtr sum() {
    auto lhs = product();
    for (;;) {
      const Token t = peek();
      if (t.kind == Tok::Plus || t.kind == Tok::Minus) {
        next();
        lhs = arithmetic(t.kind == Tok::Plus ? Op::Add : Op::Sub, t, lhs, product());
      } else if (t.kind == Tok::Int && t.text.starts_with("-")) {
        // `a -1`: the lexer read a negative literal; it is a subtraction here.
        next();
        lhs = arithmetic(Op::Add, t, lhs, number(t.value, t.line, t.column));
      } else {
        return lhs;
      }
    }
  }
  FormulaPtr product() {
    auto lhs = factor();
    for (;;) {
      const Token t = peek();
      Op op;
      if (t.kind == Tok::Star)
        op = Op::Mul;
      else if (t.kind == Tok::Slash)
        op = Op::Div;
      else if (keyword(t, "MOD"))
        op = Op::Mod;
      else
        return lhs;
      next();
      lhs = arithmetic(op, t, lhs, factor());
    }
  }
  FormulaPtr factor() {
    const Token t = peek();
    if (t.kind != Tok::Minus) return primary();
    const model::NestingLevel level(depth_);
    enter(level, t);
    next();
    auto operand = factor();
    if (operand->op == Op::Number && operand->value_name.empty() &&
        operand->value != std::numeric_limits<std::int64_t>::min())
      return number(-operand->value, t.line, t.column);
    return make_op(Op::Neg, {term(operand, t)}, t.line, t.column);
  }
  FormulaPtr primary() {
    const Token t = peek();
    if (t.kind == Tok::LParen) {
      next();
      auto f = iff();
      expect_closing(Tok::RParen, "')'");
      return f;
    }
    if (!ltl_ && t.kind == Tok::Ident && (t.text == "E" || t.text == "A") &&
        peek(1).kind == Tok::LBracket) {
      next();
      next();
      auto lhs = iff();
      if (!(peek().kind == Tok::Ident && peek().text == "U"))
        throw SyntaxError(peek(),
                          "expected 'U' in " + t.text + "[ p U q ], found " + describe(peek()));
      next();
      auto rhs = iff();
      expect_closing(Tok::RBracket, "']'");
      return make_op(t.text == "E" ? Op::EU : Op::AU, {boolean(lhs), boolean(rhs)}, t.line,
                     t.column);
    }
    if (t.kind == Tok::Int) {
      next();
      return number(t.value, t.line, t.column);
    }
    if (t.kind == Tok::Ident &&
        (model::iequals(t.text, "TRUE") || model::iequals(t.text, "FALSE"))) {
      next();
      return make_const(model::iequals(t.text, "TRUE"), t.line, t.column);
    }
    if (t.kind == Tok::Ident && peek(1).kind == Tok::LParen &&
        (t.text == "prev" || t.text == "rise" || t.text == "fall"))
      return history_term(t);
    if (t.kind == Tok::Ident) {
      Op op;
      if (is_temporal_keyword(t.text, op) || is_iec_keyword(t) || t.text == "U" ||
          (ltl_ && (ltl_unary(t, op) || ltl_binary(t, op))))
        throw SyntaxError(t, "expected an operand, found keyword " + describe(t));
      next();
      return make_atom(t.text, t.line, t.column);
    }
    if (t.kind == Tok::Bad) bad_number(t);
    if (t.kind == Tok::Bad)
      throw SyntaxError(t, "unexpected character " + describe(t) + "; " + accepted());
    throw SyntaxError(t, "expected a formula, found " + describe(t) + "; " + accepted());
  }

  // prev(p), rise(p), fall(p) of a propositional p (prev also of a term: `prev(level) > 3`).
  FormulaPtr history_term(const Token& t) {
    next();
    next();
    auto inner = iff();
    expect_closing(Tok::RParen, "')'");
    if (const auto* temporal = first_temporal(*inner))
      throw SyntaxError(Token{Tok::Ident, "", 0, temporal->line, temporal->column},
                        t.text + "() takes a propositional formula, not a temporal operator");
    if (t.text == "rise") return make_rise(boolean(inner), t.line, t.column);
    if (t.text == "fall") return make_fall(boolean(inner), t.line, t.column);
    return shifted_back(inner);
  }

 public:
  /// What the language accepts, for error messages.
  std::string accepted() const {
    return ltl_ ? "operators accepted: ! NOT, & AND, | OR, xor XOR, ->, <->, X F G, U R W, "
                  "= <> != < <= > >=, + - * / MOD, prev() rise() fall()"
                : "operators accepted: ! NOT, & AND, | OR, xor XOR, ->, <->, EX AX EF AF EG AG, "
                  "E[p U q] A[p U q], = <> != < <= > >=, + - * / MOD, prev() rise() fall()";
  }
  void expect_closing(Tok k, const char* what) {
    if (peek().kind != k)
      throw SyntaxError(peek(), std::string("expected ") + what + ", found " + describe(peek()) +
                                    "; " + accepted());
    next();
  }

 private:
  const std::vector<Token>& t_;
  std::size_t pos_;
  bool ltl_ = false;
  int depth_ = 0;
};

model::Diagnostic error_at(const std::string& file, int line, int column, std::string message) {
  model::Diagnostic d;
  d.severity = model::Severity::Error;
  d.where.file = file;
  d.where.line = line;
  d.where.column = column;
  d.message = std::move(message);
  return d;
}

}  // namespace

namespace {
ParsedFormula parse_one(std::string_view text, std::string source, bool ltl) {
  ParsedFormula out;
  const auto toks = lex(text);
  Parser p(toks, 0, ltl);
  try {
    auto f = p.formula();
    if (p.peek().kind == Tok::Semi && p.peek(1).kind == Tok::End) p.next();
    if (p.peek().kind != Tok::End)
      throw SyntaxError(p.peek(),
                        "unexpected " + describe(p.peek()) + " after the formula; " + p.accepted());
    out.formula = Parser::boolean(std::move(f));
  } catch (const SyntaxError& e) {
    out.diagnostics.push_back(error_at(source, e.line, e.column, e.what()));
  }
  return out;
}
}  // namespace

ParsedFormula parse_formula(std::string_view text, std::string source) {
  return parse_one(text, std::move(source), false);
}

ParsedFormula parse_ltl(std::string_view text, std::string source) {
  return parse_one(text, std::move(source), true);
}

ParsedFormula parse_propositional(std::string_view text, std::string source) {
  auto r = parse_formula(text, source);
  if (r.formula) {
    if (const auto* t = first_temporal(*r.formula)) {
      r.diagnostics.push_back(error_at(source, t->line, t->column,
                                       "temporal operator not allowed here: an assumption or "
                                       "fairness constraint is a propositional formula"));
      r.formula.reset();
    }
  }
  return r;
}

ParsedSpec parse_spec(std::string_view text, std::string file, const PatternOptions& patterns) {
  ParsedSpec out;
  const auto toks = lex(text);
  std::size_t pos = 0;
  while (toks[pos].kind != Tok::End) {
    const Token head = toks[pos];
    const bool ltl_entry = head.kind == Tok::Ident && model::iequals(head.text, "ltl");
    Parser p(toks, pos, ltl_entry);
    bool consumed = false;
    try {
      NamedFormula nf;
      nf.where.file = file;
      nf.where.line = head.line;
      nf.where.column = head.column;
      enum { Property, Assume, Fair } kind;
      if (head.kind == Tok::Ident && (model::iequals(head.text, "property") || ltl_entry)) {
        kind = Property;
        p.next();
        const Token name = p.peek();
        if (name.kind != Tok::Ident)
          throw SyntaxError(name, "expected a property name, found " + describe(name));
        p.next();
        nf.name = name.text;
        p.expect(Tok::Colon, "':' after the property name");
      } else if (head.kind == Tok::Ident && model::iequals(head.text, "pattern")) {
        // pattern name: response(a, b, within 5 cycles);  -- read by logic/pattern.hpp
        p.next();
        const Token name = p.peek();
        if (name.kind != Tok::Ident)
          throw SyntaxError(name, "expected a pattern name, found " + describe(name));
        p.next();
        p.expect(Tok::Colon, "':' after the property name");
        const Token body = p.peek();
        std::size_t end = p.pos();
        while (toks[end].kind != Tok::Semi && toks[end].kind != Tok::End) ++end;
        if (toks[end].kind == Tok::End)
          throw SyntaxError(toks[end], "expected ';' at the end of the statement");
        pos = end + 1;
        consumed = true;
        auto r = parse_pattern(text.substr(body.offset, toks[end].offset - body.offset), file,
                               patterns, body.line, body.column);
        out.diagnostics.insert(out.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
        for (const auto& other : out.spec.properties)
          if (model::iequals(other.name, name.text))
            throw SyntaxError(head, "property '" + name.text +
                                        "' is defined twice (first at line " +
                                        std::to_string(other.where.line) + ")");
        if (r.ok()) {
          nf.name = name.text;
          nf.formula = r.formula;
          nf.description = r.english;
          out.spec.properties.push_back(std::move(nf));
        }
        continue;
      } else if (head.kind == Tok::Ident && model::iequals(head.text, "assume")) {
        kind = Assume;
        p.next();
      } else if (head.kind == Tok::Ident && model::iequals(head.text, "fair")) {
        kind = Fair;
        p.next();
      } else {
        throw SyntaxError(
            head,
            "expected 'property', 'ltl', 'pattern', 'assume' or 'fair', found " + describe(head));
      }
      nf.formula = Parser::boolean(p.formula());
      p.expect(Tok::Semi, "';' at the end of the statement");
      pos = p.pos();
      consumed = true;
      if (kind != Property) {
        if (const auto* t = first_temporal(*nf.formula))
          throw SyntaxError(Token{Tok::Ident, "", 0, t->line, t->column},
                            "temporal operator not allowed in '" + head.text +
                                "': it takes a propositional formula");
      }
      if (kind == Assume && reads_previous(*nf.formula))
        throw SyntaxError(head,
                          "prev(), rise() and fall() are not allowed in 'assume': an "
                          "assumption constrains one cycle's inputs and state");
      if (kind == Property) {
        for (const auto& other : out.spec.properties)
          if (model::iequals(other.name, nf.name))
            throw SyntaxError(head, "property '" + nf.name + "' is defined twice (first at line " +
                                        std::to_string(other.where.line) + ")");
        out.spec.properties.push_back(std::move(nf));
      } else if (kind == Assume) {
        out.spec.assumptions.push_back(std::move(nf));
      } else {
        out.spec.fairness.push_back(std::move(nf));
      }
    } catch (const SyntaxError& e) {
      out.diagnostics.push_back(error_at(file, e.line, e.column, e.what()));
      // Recover at the next statement.
      if (consumed) continue;
      pos = std::max(pos, p.pos());
      while (toks[pos].kind != Tok::End && toks[pos].kind != Tok::Semi) ++pos;
      if (toks[pos].kind == Tok::Semi) ++pos;
    }
  }
  return out;
}

}  // namespace sfcv::logic

// Recursive-descent parser of the query language. Precedence, loosest first:
//   let x = e; e   |   &   !   = != < <= > >=   + -   *   #   primary
// so that `A + B = {}` is a test on a union and `V1 & n > 3` a conjunction with a comparison.

#include <algorithm>
#include <cctype>
#include <limits>

#include "logic/query_ast.hpp"
#include "model/literal.hpp"
#include "model/nesting.hpp"

namespace sfcv::logic {

std::string QueryPos::str() const {
  return (source ? *source : std::string("query")) + ":" + std::to_string(line) + ":" +
         std::to_string(column);
}

// The query language's own lexer and parser, named apart from the formula parser's.
namespace query_syntax {
namespace {

enum class Tok {
  Ident,
  Int,
  LParen,
  RParen,
  LBrace,
  RBrace,
  Comma,
  Semi,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  Plus,
  Minus,
  Star,
  Amp,
  Bar,
  Bang,
  Hash,
  End,
};

struct Token {
  Tok kind = Tok::End;
  std::string text;
  std::int64_t value = 0;
  /// Int: 2^63, LINT's smallest value once negated (value holds it); out of range otherwise.
  bool negation_only = false;
  QueryPos pos;
  std::string doc;  ///< `//` comment lines right before this token
};

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::End:
      return "end of input";
    case Tok::Ident:
      return "'" + t.text + "'";
    case Tok::Int:
      return "'" + t.text + "'";
    default:
      return "'" + t.text + "'";
  }
}

class Lexer {
 public:
  Lexer(std::string_view text, std::shared_ptr<const std::string> source)
      : text_(text), source_(std::move(source)) {}

  Token next() {
    std::string doc;
    for (;;) {
      while (i_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[i_]))) advance();
      if (i_ + 1 < text_.size() && text_[i_] == '/' && text_[i_ + 1] == '/') {
        advance(2);
        const auto start = i_;
        while (i_ < text_.size() && text_[i_] != '\n') advance();
        std::string line(text_.substr(start, i_ - start));
        const auto b = line.find_first_not_of(' ');
        doc += (b == std::string::npos ? std::string() : line.substr(b)) + "\n";
        continue;
      }
      break;
    }
    Token t;
    t.pos = here();
    t.doc = std::move(doc);
    if (i_ >= text_.size()) return t;
    const char c = text_[i_];
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const auto start = i_;
      for (;;) {
        while (i_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[i_])) ||
                                     text_[i_] == '_' || text_[i_] == '.'))
          advance();
        // An array element `a[2]`: constant indices are part of its name.
        if (i_ >= text_.size() || text_[i_] != '[') break;
        std::size_t close = i_ + 1;
        while (close < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[close])) ||
                                        text_[close] == ',' || text_[close] == '-'))
          ++close;
        if (close == i_ + 1 || close >= text_.size() || text_[close] != ']') break;
        while (i_ <= close) advance();
      }
      t.kind = Tok::Ident;
      t.text = std::string(text_.substr(start, i_ - start));
      return t;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) {
      const auto start = i_;
      while (i_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i_]))) advance();
      t.kind = Tok::Int;
      t.text = std::string(text_.substr(start, i_ - start));
      // The one checked conversion (model/literal.hpp).
      const auto magnitude = model::literal_magnitude(t.text, 10, t.text);
      if (!magnitude) throw QueryError(t.pos, magnitude.error);
      t.negation_only = *magnitude == model::kMaxLiteralMagnitude;
      t.value = t.negation_only ? std::numeric_limits<std::int64_t>::min()
                                : static_cast<std::int64_t>(*magnitude);
      if (i_ < text_.size() &&
          (std::isalpha(static_cast<unsigned char>(text_[i_])) || text_[i_] == '_'))
        throw QueryError(here(), "unexpected '" + std::string(1, text_[i_]) + "' after a number");
      return t;
    }
    auto two = [&](char second) { return i_ + 1 < text_.size() && text_[i_ + 1] == second; };
    auto sym = [&](Tok k, std::size_t n) {
      t.kind = k;
      t.text = std::string(text_.substr(i_, n));
      advance(n);
      return t;
    };
    switch (c) {
      case '(':
        return sym(Tok::LParen, 1);
      case ')':
        return sym(Tok::RParen, 1);
      case '{':
        return sym(Tok::LBrace, 1);
      case '}':
        return sym(Tok::RBrace, 1);
      case ',':
        return sym(Tok::Comma, 1);
      case ';':
        return sym(Tok::Semi, 1);
      case '+':
        return sym(Tok::Plus, 1);
      case '-':
        return sym(Tok::Minus, 1);
      case '*':
        return sym(Tok::Star, 1);
      case '&':
        return two('&') ? sym(Tok::Amp, 2) : sym(Tok::Amp, 1);
      case '|':
        return two('|') ? sym(Tok::Bar, 2) : sym(Tok::Bar, 1);
      case '#':
        return sym(Tok::Hash, 1);
      case '=':
        return two('=') ? sym(Tok::Eq, 2) : sym(Tok::Eq, 1);
      case '!':
        return two('=') ? sym(Tok::Ne, 2) : sym(Tok::Bang, 1);
      case '<':
        if (two('>')) return sym(Tok::Ne, 2);
        return two('=') ? sym(Tok::Le, 2) : sym(Tok::Lt, 1);
      case '>':
        return two('=') ? sym(Tok::Ge, 2) : sym(Tok::Gt, 1);
      default:
        break;
    }
    throw QueryError(t.pos, "unexpected character '" + std::string(1, c) + "'");
  }

 private:
  QueryPos here() const { return QueryPos{source_, line_, col_}; }
  void advance(std::size_t n = 1) {
    for (std::size_t k = 0; k < n && i_ < text_.size(); ++k, ++i_) {
      if (text_[i_] == '\n') {
        ++line_;
        col_ = 1;
      } else {
        ++col_;
      }
    }
  }

  std::string_view text_;
  std::shared_ptr<const std::string> source_;
  std::size_t i_ = 0;
  std::uint32_t line_ = 1, col_ = 1;
};

NodePtr make(NodeKind k, QueryPos pos, std::vector<NodePtr> args = {}, std::string name = {},
             std::int64_t value = 0) {
  auto n = std::make_shared<Node>();
  n->kind = k;
  n->pos = std::move(pos);
  n->args = std::move(args);
  n->name = std::move(name);
  n->value = value;
  for (const auto& a : n->args) n->height = std::max(n->height, a->height + 1);
  // Chains (`a | b | c ...`) are built by loops: bound the tree's height as the recursion is.
  if (n->height > static_cast<std::uint32_t>(model::kMaxNesting))
    throw QueryError(n->pos, "expression nested too deeply");
  return n;
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& source_name)
      : lex_(text, std::make_shared<const std::string>(source_name)) {
    tok_ = lex_.next();
  }

  NodePtr query() {
    auto e = expr();
    if (tok_.kind != Tok::End)
      throw QueryError(tok_.pos, "unexpected " + describe(tok_) + " after the query");
    return e;
  }

  std::vector<Definition> library() {
    std::vector<Definition> defs;
    while (tok_.kind != Tok::End) {
      if (tok_.kind != Tok::Ident || tok_.text != "def")
        throw QueryError(tok_.pos,
                         "expected 'def name(params) = query;' but found " + describe(tok_));
      Definition d;
      d.doc = tok_.doc;
      d.pos = tok_.pos;
      take();
      d.name = ident("a definition name").text;
      expect(Tok::LParen, "'('");
      if (tok_.kind != Tok::RParen) {
        for (;;) {
          const auto p = ident("a parameter name");
          for (const auto& q : d.params)
            if (q == p.text) throw QueryError(p.pos, "parameter '" + p.text + "' repeated");
          d.params.push_back(p.text);
          if (tok_.kind != Tok::Comma) break;
          take();
        }
      }
      expect(Tok::RParen, "')'");
      expect(Tok::Eq, "'='");
      d.body = expr();
      expect(Tok::Semi, "';' ending the definition of '" + d.name + "'");
      defs.push_back(std::move(d));
    }
    return defs;
  }

 private:
  Token take() {
    Token t = std::move(tok_);
    tok_ = lex_.next();
    return t;
  }
  Token expect(Tok k, const std::string& what) {
    if (tok_.kind != k)
      throw QueryError(tok_.pos, "expected " + what + " but found " + describe(tok_));
    return take();
  }
  Token ident(const std::string& what) {
    if (tok_.kind != Tok::Ident || is_keyword(tok_.text))
      throw QueryError(tok_.pos, "expected " + what + " but found " + describe(tok_));
    return take();
  }
  static bool is_keyword(const std::string& s) { return s == "let" || s == "def" || s == "in"; }

  NodePtr expr() {
    // Bound the recursion so that a pathological text is an error, not a stack overflow.
    struct Depth {
      int& d;
      explicit Depth(int& depth) : d(depth) { ++d; }
      ~Depth() { --d; }
    } guard(depth_);
    if (depth_ > model::kMaxNesting) throw QueryError(tok_.pos, "expression nested too deeply");
    if (tok_.kind == Tok::Ident && tok_.text == "let") {
      const auto pos = take().pos;
      const auto name = ident("a name after 'let'");
      expect(Tok::Eq, "'=' after 'let " + name.text + "'");
      auto value = expr();
      expect(Tok::Semi, "';' ending 'let " + name.text + " = ...'");
      auto body = expr();
      return make(NodeKind::Let, pos, {std::move(value), std::move(body)}, name.text);
    }
    return disjunction();
  }

  NodePtr disjunction() {
    auto lhs = conjunction();
    while (tok_.kind == Tok::Bar) {
      const auto pos = take().pos;
      lhs = make(NodeKind::Or, pos, {lhs, conjunction()});
    }
    return lhs;
  }
  NodePtr conjunction() {
    auto lhs = negation();
    while (tok_.kind == Tok::Amp) {
      const auto pos = take().pos;
      lhs = make(NodeKind::And, pos, {lhs, negation()});
    }
    return lhs;
  }
  NodePtr negation() {
    if (tok_.kind == Tok::Bang) {
      const auto pos = take().pos;
      return make(NodeKind::Not, pos, {expr_level(&Parser::negation)});
    }
    return comparison();
  }
  NodePtr comparison() {
    auto lhs = sum();
    NodeKind k;
    switch (tok_.kind) {
      case Tok::Eq:
        k = NodeKind::Eq;
        break;
      case Tok::Ne:
        k = NodeKind::Ne;
        break;
      case Tok::Lt:
        k = NodeKind::Lt;
        break;
      case Tok::Le:
        k = NodeKind::Le;
        break;
      case Tok::Gt:
        k = NodeKind::Gt;
        break;
      case Tok::Ge:
        k = NodeKind::Ge;
        break;
      default:
        return lhs;
    }
    const auto pos = take().pos;
    auto rhs = sum();
    switch (tok_.kind) {
      case Tok::Eq:
      case Tok::Ne:
      case Tok::Lt:
      case Tok::Le:
      case Tok::Gt:
      case Tok::Ge:
        throw QueryError(tok_.pos, "comparisons do not chain: add parentheses");
      default:
        break;
    }
    return make(k, pos, {lhs, rhs});
  }
  NodePtr sum() {
    auto lhs = product();
    while (tok_.kind == Tok::Plus || tok_.kind == Tok::Minus) {
      const auto k = tok_.kind == Tok::Plus ? NodeKind::Union : NodeKind::Diff;
      const auto pos = take().pos;
      lhs = make(k, pos, {lhs, product()});
    }
    return lhs;
  }
  NodePtr product() {
    auto lhs = prefix();
    while (tok_.kind == Tok::Star) {
      const auto pos = take().pos;
      lhs = make(NodeKind::Inter, pos, {lhs, prefix()});
    }
    return lhs;
  }
  NodePtr prefix() {
    if (tok_.kind == Tok::Hash) {
      const auto pos = take().pos;
      return make(NodeKind::Count, pos, {expr_level(&Parser::prefix)});
    }
    return primary();
  }

  static std::int64_t int_value(const Token& t, bool negated) {
    const std::uint64_t magnitude =
        t.negation_only ? model::kMaxLiteralMagnitude : static_cast<std::uint64_t>(t.value);
    const auto v = model::signed_literal(negated, magnitude, (negated ? "-" : "") + t.text);
    if (!v) throw QueryError(t.pos, v.error);
    return *v;
  }

  NodePtr primary() {
    switch (tok_.kind) {
      case Tok::Int: {
        auto t = take();
        return make(NodeKind::Integer, t.pos, {}, t.text, int_value(t, false));
      }
      case Tok::Minus: {
        // A negative literal (comparisons inside Nec/Emis): `n > -1`.
        auto m = take();
        if (tok_.kind != Tok::Int)
          throw QueryError(m.pos,
                           "'-' here must be followed by a number (set difference needs a "
                           "left operand)");
        auto t = take();
        return make(NodeKind::Integer, m.pos, {}, "-" + t.text, int_value(t, true));
      }
      case Tok::LParen: {
        take();
        auto e = expr();
        expect(Tok::RParen, "')'");
        return e;
      }
      case Tok::LBrace:
        return braces();
      case Tok::Ident: {
        if (tok_.text == "let") return expr();
        auto t = ident("a name");
        if (tok_.kind != Tok::LParen) return make(NodeKind::Name, t.pos, {}, t.text);
        take();
        std::vector<NodePtr> args;
        if (tok_.kind != Tok::RParen) {
          for (;;) {
            args.push_back(expr());
            if (tok_.kind != Tok::Comma) break;
            take();
          }
        }
        expect(Tok::RParen, "')' or ',' in the arguments of '" + t.text + "'");
        return make(NodeKind::Call, t.pos, std::move(args), t.text);
      }
      default:
        throw QueryError(tok_.pos, "expected a set, a name or '(' but found " + describe(tok_));
    }
  }

  // {}   {1, 10, X3}   { e in Steps | test }   { e | test }
  NodePtr braces() {
    const auto open = take().pos;
    if (tok_.kind == Tok::RBrace) {
      take();
      return make(NodeKind::EmptySet, open);
    }
    std::vector<NodePtr> elems;
    for (;;) {
      if (tok_.kind == Tok::Int) {
        auto t = take();
        elems.push_back(make(NodeKind::Integer, t.pos, {}, t.text, int_value(t, false)));
      } else if (tok_.kind == Tok::Ident && !is_keyword(tok_.text)) {
        auto t = take();
        if (elems.empty() &&
            (tok_.kind == Tok::Bar || (tok_.kind == Tok::Ident && tok_.text == "in"))) {
          NodePtr domain;
          if (tok_.kind == Tok::Ident) {
            take();
            domain = sum();
          } else {
            domain = make(NodeKind::Name, t.pos, {}, "Steps");
          }
          expect(Tok::Bar, "'|' after the domain of '{" + t.text + " in ...'");
          auto body = expr();
          expect(Tok::RBrace, "'}' closing the set of steps");
          return make(NodeKind::SetBuilder, t.pos, {domain, body}, t.text);
        }
        elems.push_back(make(NodeKind::Name, t.pos, {}, t.text));
      } else {
        throw QueryError(tok_.pos,
                         "expected a step (a number or a name) but found " + describe(tok_));
      }
      if (tok_.kind != Tok::Comma) break;
      take();
    }
    expect(Tok::RBrace, "'}' or ',' in the set of steps");
    return make(NodeKind::StepList, open, std::move(elems));
  }

  /// A nested call of `level` that counts towards the nesting bound (prefix operators).
  NodePtr expr_level(NodePtr (Parser::*level)()) {
    if (++depth_ > model::kMaxNesting) throw QueryError(tok_.pos, "expression nested too deeply");
    auto n = (this->*level)();
    --depth_;
    return n;
  }

  Lexer lex_;
  Token tok_;
  int depth_ = 0;
};

int precedence(NodeKind k) {
  switch (k) {
    case NodeKind::Let:
      return 0;
    case NodeKind::Or:
      return 1;
    case NodeKind::And:
      return 2;
    case NodeKind::Not:
      return 3;
    case NodeKind::Eq:
    case NodeKind::Ne:
    case NodeKind::Lt:
    case NodeKind::Le:
    case NodeKind::Gt:
    case NodeKind::Ge:
      return 4;
    case NodeKind::Union:
    case NodeKind::Diff:
      return 5;
    case NodeKind::Inter:
      return 6;
    case NodeKind::Count:
      return 7;
    default:
      return 8;
  }
}

const char* op_text(NodeKind k) {
  switch (k) {
    case NodeKind::Or:
      return " | ";
    case NodeKind::And:
      return " & ";
    case NodeKind::Eq:
      return " = ";
    case NodeKind::Ne:
      return " != ";
    case NodeKind::Lt:
      return " < ";
    case NodeKind::Le:
      return " <= ";
    case NodeKind::Gt:
      return " > ";
    case NodeKind::Ge:
      return " >= ";
    case NodeKind::Union:
      return " + ";
    case NodeKind::Diff:
      return " - ";
    case NodeKind::Inter:
      return " * ";
    default:
      return " ? ";
  }
}

std::string print(const Node& n, int context) {
  const int p = precedence(n.kind);
  std::string s;
  switch (n.kind) {
    case NodeKind::Name:
      return n.name;
    case NodeKind::Integer:
      return std::to_string(n.value);
    case NodeKind::EmptySet:
      return "{}";
    case NodeKind::StepList:
      s = "{";
      for (std::size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + print(*n.args[i], 0);
      return s + "}";
    case NodeKind::SetBuilder:
      return "{" + n.name + " in " + print(*n.args[0], 5) + " | " + print(*n.args[1], 0) + "}";
    case NodeKind::Call:
      s = n.name + "(";
      for (std::size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + print(*n.args[i], 0);
      return s + ")";
    case NodeKind::Let:
      s = "let " + n.name + " = " + print(*n.args[0], 0) + "; " + print(*n.args[1], 0);
      break;
    // Parenthesise a negated comparison, although `!` binds looser, for the reader.
    case NodeKind::Not:
      s = "!" + print(*n.args[0], 5);
      break;
    case NodeKind::Count:
      s = "#" + print(*n.args[0], p);
      break;
    default:
      // Left-associative: the right operand needs parentheses at equal precedence.
      s = print(*n.args[0], p) + op_text(n.kind) + print(*n.args[1], p + 1);
      break;
  }
  return p < context ? "(" + s + ")" : s;
}

}  // namespace
}  // namespace query_syntax

std::string to_string(const Node& n) {
  return query_syntax::print(n, 0);
}

NodePtr parse_query(std::string_view text, const std::string& source_name) {
  return query_syntax::Parser(text, source_name).query();
}

std::vector<Definition> parse_library(std::string_view text, const std::string& source_name) {
  return query_syntax::Parser(text, source_name).library();
}

}  // namespace sfcv::logic

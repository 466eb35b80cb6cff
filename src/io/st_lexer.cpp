#include "io/st_lexer.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <string>

#include "model/literal.hpp"
#include "model/names.hpp"

namespace sfcv::io::st {

model::SourceLocation Locator::at(int line, int column) const {
  model::SourceLocation loc = start_;
  if (start_.line > 0) {
    loc.line = start_.line + line - 1;
    loc.column = line == 1 ? std::max(start_.column, 1) + column - 1 : column;
  } else {
    loc.line = line;
    loc.column = column;
  }
  return loc;
}

std::string describe(const Token& t) {
  if (t.kind == TokenKind::End) return "end of text";
  return "'" + t.text + "'";
}

namespace {

bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

bool is_integer_type(const std::string& upper) {
  static const char* const names[] = {"SINT",  "INT",   "DINT", "LINT", "USINT", "UINT",
                                      "UDINT", "ULINT", "BYTE", "WORD", "DWORD", "LWORD"};
  for (const char* n : names)
    if (upper == n) return true;
  return false;
}

class Lexer {
 public:
  Lexer(std::string_view text, const Locator& locator, model::Diagnostics& diags,
        const model::Budget* budget)
      : s_(text), loc_(locator), diags_(diags), poll_(budget, 4096) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    // A UTF-8 byte order mark is not text.
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    for (;;) {
      poll_.tick_or_throw("reading the model");
      skip_blanks_and_comments();
      Token t;
      t.line = line_;
      t.column = col_;
      t.offset = pos_;
      if (pos_ >= s_.size()) {
        out.push_back(t);
        return out;
      }
      if (lex_one(t)) {
        t.text = std::string(s_.substr(t.offset, pos_ - t.offset));
        out.push_back(std::move(t));
      }
    }
  }

 private:
  char peek(std::size_t k = 0) const { return pos_ + k < s_.size() ? s_[pos_ + k] : '\0'; }

  void advance(std::size_t n = 1) {
    for (std::size_t i = 0; i < n && pos_ < s_.size(); ++i) {
      if (s_[pos_] == '\n') {
        ++line_;
        col_ = 1;
      } else if ((static_cast<unsigned char>(s_[pos_]) & 0xC0) != 0x80) {
        ++col_;  // count code points, not UTF-8 continuation bytes
      }
      ++pos_;
    }
  }

  void error(int line, int col, std::string msg) {
    diags_.push_back({model::Severity::Error, loc_.at(line, col), std::move(msg)});
  }

  void skip_blanks_and_comments() {
    for (;;) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '(' && peek(1) == '*') {
        const int l = line_, k = col_;
        advance(2);
        int depth = 1;
        while (pos_ < s_.size() && depth > 0) {
          if (peek() == '(' && peek(1) == '*') {
            ++depth;
            advance(2);
          } else if (peek() == '*' && peek(1) == ')') {
            --depth;
            advance(2);
          } else {
            advance();
          }
        }
        if (depth > 0) error(l, k, "unterminated comment '(*'");
      } else if (c == '/' && peek(1) == '*') {
        const int l = line_, k = col_;
        advance(2);
        while (pos_ < s_.size() && !(peek() == '*' && peek(1) == '/')) advance();
        if (pos_ >= s_.size()) error(l, k, "unterminated comment '/*'");
        advance(2);
      } else if (c == '/' && peek(1) == '/') {
        while (pos_ < s_.size() && peek() != '\n') advance();
      } else if (c == '{') {
        // Pragmas ({attribute ...}, {#include ...}) carry no semantics for sfcv.
        const int l = line_, k = col_;
        while (pos_ < s_.size() && peek() != '}') advance();
        if (pos_ >= s_.size()) error(l, k, "unterminated pragma '{'");
        advance();
      } else {
        return;
      }
    }
  }

  // The extent of digits of `base` and '_' separators (checked by model::literal_magnitude).
  std::string_view scan_digits(int base) {
    const std::size_t b = pos_;
    while (digit_value(peek()) < base || peek() == '_') advance();
    return s_.substr(b, pos_ - b);
  }

  // An integer literal with an optional base prefix (16#FF); at a digit. Its magnitude may be
  // 2^63 (the parser accepts it only after a unary minus: LINT's smallest value).
  bool lex_integer(Token& t) {
    const std::size_t b = pos_;
    std::string_view digits = scan_digits(10);
    int base = 10;
    if (peek() == '#' && (digits == "2" || digits == "8" || digits == "16")) {
      base = digits == "2" ? 2 : digits == "8" ? 8 : 16;
      advance();
      digits = scan_digits(base);
      if (digits.empty()) {
        error(t.line, t.column, "malformed base-" + std::to_string(base) + " integer literal");
        return false;
      }
    }
    if (base == 10 && peek() == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))) {
      // REAL literal: 1.5, 1.0E3.
      advance();
      while (std::isdigit(static_cast<unsigned char>(peek())) || peek() == '_') advance();
      if ((peek() == 'e' || peek() == 'E') &&
          (std::isdigit(static_cast<unsigned char>(peek(1))) || peek(1) == '-' || peek(1) == '+')) {
        advance(2);
        while (std::isdigit(static_cast<unsigned char>(peek()))) advance();
      }
      t.kind = TokenKind::Unsupported;
      return true;
    }
    const auto magnitude = model::literal_magnitude(digits, base, s_.substr(b, pos_ - b));
    if (!magnitude) {
      error(t.line, t.column, magnitude.error);
      return false;
    }
    t.kind = TokenKind::Integer;
    t.negation_only = *magnitude == model::kMaxLiteralMagnitude;
    t.value = t.negation_only ? std::numeric_limits<std::int64_t>::min()
                              : static_cast<std::int64_t>(*magnitude);
    return true;
  }

  // A duration after T# / TIME#: [-] { number [. fraction] unit } with '_' separators, read by
  // model::duration_body (the one conversion of durations, docs/semantics.md 1.7).
  bool lex_duration(Token& t) {
    if (peek() == '-' || peek() == '+') advance();
    while (is_ident_char(peek()) ||
           (peek() == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))))
      advance();
    const std::string_view written = s_.substr(t.offset, pos_ - t.offset);
    const auto body = written.substr(written.find('#') + 1);
    const auto ms = model::duration_body(body, written);
    if (!ms) {
      error(t.line, t.column, ms.error);
      return false;
    }
    t.kind = TokenKind::Time;
    t.value = *ms;
    return true;
  }

  // `TYPE#literal`: at the '#' after the identifier `prefix`.
  bool lex_typed_literal(Token& t, const std::string& prefix) {
    advance();  // '#'
    const std::string p = model::to_upper(prefix);
    if (p == "T" || p == "TIME" || p == "LT" || p == "LTIME") return lex_duration(t);
    if (is_integer_type(p)) {
      const bool negative = peek() == '-';
      if (negative || peek() == '+') advance();
      if (!std::isdigit(static_cast<unsigned char>(peek()))) {
        error(t.line, t.column, "malformed " + p + " literal");
        return false;
      }
      if (!lex_integer(t)) return false;
      if (t.kind != TokenKind::Integer) return true;
      // The type is written: its range applies (INT#40000 is an error naming INT's range).
      const std::string_view written = s_.substr(t.offset, pos_ - t.offset);
      const auto magnitude =
          t.negation_only ? model::kMaxLiteralMagnitude : static_cast<std::uint64_t>(t.value);
      const auto v = model::signed_literal(negative, magnitude, written);
      std::string why = v ? model::range_error(*v, *model::elementary_type(p), written) : v.error;
      if (!why.empty()) {
        error(t.line, t.column, why);
        return false;
      }
      // A negative value is kept in the token: the parser builds Neg(literal), as for `-5`.
      t.value = *v;
      t.negation_only = false;
      return true;
    }
    if (p == "BOOL") {
      if (peek() == '0' || peek() == '1') {
        t.kind = TokenKind::Bool;
        t.value = peek() - '0';
        advance();
        return true;
      }
      std::string word;
      while (is_ident_char(peek())) {
        word += peek();
        advance();
      }
      if (model::iequals(word, "TRUE") || model::iequals(word, "FALSE")) {
        t.kind = TokenKind::Bool;
        t.value = model::iequals(word, "TRUE") ? 1 : 0;
        return true;
      }
      error(t.line, t.column, "malformed BOOL literal");
      return false;
    }
    // `Color#Red`: an enumerator qualified by its type, a name the model resolves.
    static const std::set<std::string> kLiteralTypes{
        "REAL",  "LREAL", "DATE", "D",      "TOD",     "TIME_OF_DAY", "DT",   "DATE_AND_TIME",
        "LDATE", "LTOD",  "LDT",  "STRING", "WSTRING", "CHAR",        "WCHAR"};
    if (!kLiteralTypes.count(p) && is_ident_start(peek())) {
      std::size_t end = pos_;
      while (end < s_.size() && is_ident_char(s_[end])) ++end;
      if (end == s_.size() || (s_[end] != '.' && s_[end] != '#' && s_[end] != '\'')) {
        while (pos_ < end) advance();
        t.kind = TokenKind::Identifier;
        return true;
      }
    }
    // REAL#1.5, DATE#..., TOD#..., STRING#'...': outside the model.
    while (is_ident_char(peek()) || peek() == '.' || peek() == ':' || peek() == '-' ||
           peek() == '#')
      advance();
    t.kind = TokenKind::Unsupported;
    return true;
  }

  bool lex_one(Token& t) {
    const char c = peek();
    if (is_ident_start(c)) {
      std::string word;
      while (is_ident_char(peek())) {
        word += peek();
        advance();
      }
      if (peek() == '#') return lex_typed_literal(t, word);
      t.kind = TokenKind::Identifier;
      return true;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) return lex_integer(t);
    if (c == '\'' || c == '"') {
      advance();
      while (pos_ < s_.size() && peek() != c && peek() != '\n') {
        if (peek() == '$') advance();
        advance();
      }
      if (peek() != c) {
        error(t.line, t.column, "unterminated string literal");
        return false;
      }
      advance();
      t.kind = TokenKind::String;
      return true;
    }
    if (c == '%') {
      advance();
      while (is_ident_char(peek()) || peek() == '.' || peek() == '*') advance();
      t.kind = TokenKind::DirectAddress;
      return true;
    }
    auto two = [&](char a, char b) { return c == a && peek(1) == b; };
    struct Op {
      char a, b;
      TokenKind kind;
    };
    static constexpr Op twos[] = {{':', '=', TokenKind::Assign}, {'=', '>', TokenKind::Arrow},
                                  {'<', '>', TokenKind::Ne},     {'<', '=', TokenKind::Le},
                                  {'>', '=', TokenKind::Ge},     {'.', '.', TokenKind::DotDot},
                                  {'*', '*', TokenKind::Power}};
    for (const auto& op : twos)
      if (two(op.a, op.b)) {
        t.kind = op.kind;
        advance(2);
        return true;
      }
    static constexpr std::pair<char, TokenKind> ones[] = {
        {':', TokenKind::Colon},    {';', TokenKind::Semicolon}, {',', TokenKind::Comma},
        {'(', TokenKind::LParen},   {')', TokenKind::RParen},    {'.', TokenKind::Dot},
        {'[', TokenKind::LBracket}, {']', TokenKind::RBracket},  {'^', TokenKind::Caret},
        {'=', TokenKind::Eq},       {'<', TokenKind::Lt},        {'>', TokenKind::Gt},
        {'+', TokenKind::Plus},     {'-', TokenKind::Minus},     {'*', TokenKind::Star},
        {'/', TokenKind::Slash},    {'&', TokenKind::Ampersand}, {'#', TokenKind::Hash}};
    for (const auto& [ch, kind] : ones)
      if (c == ch) {
        t.kind = kind;
        advance();
        return true;
      }
    std::string shown(1, c);
    if (static_cast<unsigned char>(c) >= 0x80 || !std::isprint(static_cast<unsigned char>(c))) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X",
                    static_cast<unsigned>(static_cast<unsigned char>(c)));
      shown = buf;
    }
    error(t.line, t.column, "unexpected character '" + shown + "'");
    advance();
    // Skip the rest of a UTF-8 sequence.
    while (pos_ < s_.size() && (static_cast<unsigned char>(peek()) & 0xC0) == 0x80) advance();
    return false;
  }

  std::string_view s_;
  const Locator& loc_;
  model::Diagnostics& diags_;
  model::BudgetPoll poll_;
  std::size_t pos_ = 0;
  int line_ = 1, col_ = 1;
};

}  // namespace

std::vector<Token> tokenize(std::string_view text, const Locator& locator,
                            model::Diagnostics& diags, const model::Budget* budget) {
  return Lexer(text, locator, diags, budget).run();
}

}  // namespace sfcv::io::st

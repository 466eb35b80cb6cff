#include "io/st_lexer.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <string>

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

// Exact arithmetic for durations (a day in ns times a large count overflows 64 bits).
__extension__ using Int128 = __int128;

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

  // Reads digits of `base` with '_' separators into `value`; false on overflow or no digit.
  bool read_digits(int base, std::int64_t& value, bool& overflow) {
    bool any = false;
    value = 0;
    while (digit_value(peek()) < base || (peek() == '_' && any)) {
      if (peek() != '_') {
        const int d = digit_value(peek());
        if (value > (std::numeric_limits<std::int64_t>::max() - d) / base)
          overflow = true;
        else
          value = value * base + d;
        any = true;
      }
      advance();
    }
    return any;
  }

  // An integer literal with an optional base prefix (16#FF); at a digit.
  bool lex_integer(Token& t) {
    std::int64_t v = 0;
    bool overflow = false;
    read_digits(10, v, overflow);
    if (peek() == '#' && (v == 2 || v == 8 || v == 16) && !overflow) {
      const int base = static_cast<int>(v);
      advance();
      if (!read_digits(base, v, overflow)) {
        error(t.line, t.column, "malformed base-" + std::to_string(base) + " integer literal");
        return false;
      }
    }
    if (peek() == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))) {
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
    if (overflow) {
      error(t.line, t.column, "integer literal too large");
      return false;
    }
    t.kind = TokenKind::Integer;
    t.value = v;
    return true;
  }

  // A duration after T# / TIME#: [-] { number [. fraction] unit } with '_' separators.
  bool lex_duration(Token& t) {
    bool negative = false;
    if (peek() == '-') {
      negative = true;
      advance();
    } else if (peek() == '+') {
      advance();
    }
    // Accumulate nanoseconds exactly; a literal finer than 1 ms is rejected below.
    Int128 total_ns = 0;
    bool any = false;
    while (std::isdigit(static_cast<unsigned char>(peek()))) {
      Int128 whole = 0;
      while (std::isdigit(static_cast<unsigned char>(peek())) || peek() == '_') {
        if (peek() != '_') whole = whole * 10 + (peek() - '0');
        if (whole > static_cast<Int128>(1) << 80) break;
        advance();
      }
      Int128 frac = 0, frac_scale = 1;
      if (peek() == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))) {
        advance();
        while (std::isdigit(static_cast<unsigned char>(peek()))) {
          if (frac_scale < 1000000000000LL) {
            frac = frac * 10 + (peek() - '0');
            frac_scale *= 10;
          }
          advance();
        }
      }
      std::string unit;
      while (std::isalpha(static_cast<unsigned char>(peek()))) {
        unit += static_cast<char>(std::tolower(static_cast<unsigned char>(peek())));
        advance();
      }
      Int128 scale = 0;
      if (unit == "d")
        scale = 86400LL * 1000000000LL;
      else if (unit == "h")
        scale = 3600LL * 1000000000LL;
      else if (unit == "m")
        scale = 60LL * 1000000000LL;
      else if (unit == "s")
        scale = 1000000000LL;
      else if (unit == "ms")
        scale = 1000000LL;
      else if (unit == "us")
        scale = 1000LL;
      else if (unit == "ns")
        scale = 1;
      else {
        error(t.line, t.column,
              unit.empty() ? "TIME literal: missing unit (d, h, m, s, ms)"
                           : "TIME literal: unknown unit '" + unit + "'");
        return false;
      }
      total_ns += whole * scale + frac * scale / frac_scale;
      if ((frac * scale) % frac_scale != 0) {
        error(t.line, t.column, "TIME literal finer than a nanosecond");
        return false;
      }
      any = true;
      if (total_ns > static_cast<Int128>(1) << 100) {
        error(t.line, t.column, "TIME literal too large");
        return false;
      }
      if (peek() == '_') advance();
    }
    if (!any) {
      error(t.line, t.column, "malformed TIME literal");
      return false;
    }
    if (total_ns % 1000000 != 0) {
      error(t.line, t.column, "unsupported: TIME literal finer than a millisecond");
      return false;
    }
    const Int128 ms = total_ns / 1000000;
    if (ms > std::numeric_limits<std::int32_t>::max()) {
      error(t.line, t.column, "TIME literal too large");
      return false;
    }
    t.kind = TokenKind::Time;
    t.value = static_cast<std::int64_t>(negative ? -ms : ms);
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
      if (t.kind == TokenKind::Integer && negative) {
        // Kept as a token with a leading '-': the parser builds Neg(literal), as for `-5`.
        t.value = -t.value;
      }
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

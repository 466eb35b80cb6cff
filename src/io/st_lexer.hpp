#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Tokens of IEC 61131-3 Structured Text and textual SFC. Keywords are not distinguished here:
// SFC lets qualifier names (N, S, D, L ...) be step and action names, so the parsers decide
// from context whether an identifier is a keyword.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "model/budget.hpp"
#include "model/diagnostic.hpp"
#include "model/source_location.hpp"

namespace sfcv::io::st {

enum class TokenKind {
  Identifier,     ///< text as written
  Integer,        ///< value (16#FF, 2#1010, 1_000, INT#5)
  Time,           ///< value in ms (T#1m30s, TIME#100ms)
  Bool,           ///< value 0/1 from BOOL#TRUE, BOOL#0 (plain TRUE/FALSE are identifiers)
  DirectAddress,  ///< %IX1, %QW3.2: text
  Unsupported,    ///< a literal sfcv does not model (REAL, dates): text names it
  String,         ///< a character string literal: text is it as written, quotes included
  Assign,         ///< :=
  Arrow,          ///< =>
  Colon,
  Semicolon,
  Comma,
  LParen,
  RParen,
  Dot,
  DotDot,
  LBracket,
  RBracket,
  Caret,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  Plus,
  Minus,
  Star,
  Slash,
  Power,
  Ampersand,
  Hash,
  End,  ///< end of text
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;        ///< as written (identifier, literal, operator)
  std::int64_t value = 0;  ///< Integer, Time, Bool
  /// Integer: the literal is 2^63, LINT's smallest value once negated (value holds it); any
  /// use but after a unary minus is out of range.
  bool negation_only = false;
  int line = 1, column = 1;  ///< 1-based, relative to the lexed text
  std::size_t offset = 0;    ///< byte offset in the lexed text
};

/// Maps positions inside a piece of text to locations in its container: a file (the text's first
/// character is at `start.line:start.column`) or an XML element (element_path is kept and
/// line/column stay relative to the text).
class Locator {
 public:
  explicit Locator(model::SourceLocation start) : start_(std::move(start)) {}
  model::SourceLocation at(int line, int column) const;
  model::SourceLocation at(const Token& t) const { return at(t.line, t.column); }

 private:
  model::SourceLocation start_;
};

/// Splits `text` into tokens (the last one is End). Comments `(* *)` (nested), `/* */`, `//`
/// and pragmas `{ }` are skipped. Lexical errors are appended to `diags`; the offending
/// characters are skipped. Past `budget`'s deadline (when given) throws LimitReached.
std::vector<Token> tokenize(std::string_view text, const Locator& locator,
                            model::Diagnostics& diags, const model::Budget* budget = nullptr);

/// Human-readable form of a token for messages: "'THEN'", "end of text".
std::string describe(const Token& t);

}  // namespace sfcv::io::st

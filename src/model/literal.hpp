#pragma once
// The one checked conversion of numeric literals (issue 53, docs/semantics.md 1.7). Every reader
// (IEC text, ST and IL bodies, PLCopen XML attributes, .g7, AGRAFE XMI) and the command line turn
// digits and durations into values here, so that a literal past the range of its type is an
// error the reader locates, never a value that wrapped around: `T#9223372036854775807ms` once
// became -1 ms in PLCopen XML and turned `EF y` from holds into violated.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "model/types.hpp"

namespace sfcv::model {

/// A converted literal, or why the text is not one: a message without a place (each reader
/// adds the place as it does for its other errors).
template <class T>
struct Converted {
  std::optional<T> value;
  std::string error;  ///< set when there is no value
  explicit operator bool() const { return value.has_value(); }
  const T& operator*() const { return *value; }
};

/// 2^63: the magnitude of LINT's smallest value, the largest a literal may have before its sign.
inline constexpr std::uint64_t kMaxLiteralMagnitude = std::uint64_t{1} << 63;
/// TIME's largest value in milliseconds (T#24d20h31m23s647ms), as model::Type::time().
inline constexpr std::int64_t kMaxTimeMs = 2147483647;

/// Digits of `base` (2, 8, 10 or 16) with single '_' between digits, as IEC 61131-3 writes them:
/// their value, at most 2^63. `written` is the literal as the message shows it.
Converted<std::uint64_t> literal_magnitude(std::string_view digits, int base,
                                           std::string_view written);

/// A sign and a magnitude: the value, or an error past LINT's range (-2^63 .. 2^63-1).
Converted<std::int64_t> signed_literal(bool negative, std::uint64_t magnitude,
                                       std::string_view written);

/// An integer literal as attributes and options write it: [+|-] [TYPE#] [+|-] [2#|8#|16#]
/// digits, e.g. `42`, `-3`, `16#FF`, `INT#-5`, `1_000`. With TYPE an IEC integer type the value
/// is checked against that type's range (`INT#40000` is an error naming INT and its range).
Converted<std::int64_t> integer_literal(std::string_view text);

/// "INT (-32768..32767)"; TIME: "TIME (T#0ms..T#24d20h31m23s647ms)".
std::string range_text(const Type& t);

/// Empty when `v` is in the range of `t` (an integer or TIME type); otherwise
/// "<written> is outside INT (-32768..32767)".
std::string range_error(std::int64_t v, const Type& t, std::string_view written);

/// Milliseconds as an IEC duration: 90000 -> "T#1m30s", 0 -> "T#0ms".
std::string time_text(std::int64_t ms);

/// The components of a duration added up exactly (nanoseconds, saturated far past TIME's
/// range) and given in the model's unit, milliseconds, within TIME's range.
class DurationLiteral {
 public:
  explicit DurationLiteral(std::string_view written) : written_(written) {}
  /// One component: `whole` digits ('_' between digits), `fraction` digits (may be empty) and
  /// its unit in nanoseconds. false when it cannot be added (error() says why).
  bool add(std::string_view whole, std::string_view fraction, std::int64_t unit_ns);
  /// The sum in ms, negated when `negative`: an error finer than a millisecond (sfcv's time
  /// unit) or past TIME's range.
  Converted<std::int64_t> milliseconds(bool negative) const;
  const std::string& error() const { return error_; }

 private:
  std::string written_;
  std::uint64_t ns_ = 0;
  bool too_large_ = false;
  std::string error_;
};

/// An IEC 61131-3 duration unit (d, h, m, s, ms, us, ns; any case) in nanoseconds.
std::optional<std::int64_t> iec_duration_unit_ns(std::string_view unit);

/// What follows `T#` in a TIME literal: [+|-] components `number[.fraction]unit`, optionally
/// separated by '_' (`1h_30m`, `1.5s`, `-250ms`). `written` is the whole literal.
Converted<std::int64_t> duration_body(std::string_view body, std::string_view written);

/// A TIME literal: `T#`, `TIME#`, `LT#` or `LTIME#` (any case) and a duration body. No value
/// and an empty error when the text does not start with such a prefix (a variable name).
Converted<std::int64_t> time_literal(std::string_view text);

}  // namespace sfcv::model

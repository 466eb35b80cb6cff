#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Lexical rules of the native Grafcet format (.g7) shared by its reader and its writer, so that
// what the writer prints is what the reader reads.

#include <cstdint>
#include <string>
#include <string_view>

namespace sfcv::io::g7 {

/// Words that cannot be bare variable names inside expressions (case-insensitive).
bool is_reserved_in_expression(std::string_view word);

/// True when `name` can be written bare: an identifier ([A-Za-z_][A-Za-z0-9_]*) or a
/// non-negative decimal number (step and transition names are usually numbers).
bool is_plain_name(std::string_view name);

/// `name` bare when plain, else in double quotes with `"` and `\` escaped. `in_expression`
/// also quotes the reserved words and numbers (a number in an expression is a constant).
std::string quote_name(std::string_view name, bool in_expression);

/// Milliseconds as a .g7 duration: "2s", "1500ms", "0s".
std::string duration(std::int64_t ms);

/// The default range of an integer variable whose source gives no bounds (AGRAFE Integer).
inline constexpr std::int64_t kDefaultIntLo = 0;
inline constexpr std::int64_t kDefaultIntHi = 255;

/// The type name the .g7 reader gives a bounded integer: "INT(lo..hi)".
std::string range_type_name(std::int64_t lo, std::int64_t hi);

}  // namespace sfcv::io::g7

#pragma once
// Data types the model supports: BOOL, bounded integers (IEC ranges or a declared subrange),
// TIME (milliseconds), and instances of the standard function blocks.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sfcv::model {

enum class TypeKind { Bool, Int, Time, FunctionBlock };

/// The standard function blocks the semantics implements.
enum class StandardFb { None, R_TRIG, F_TRIG, SR, RS, TON, TOF, TP, CTU, CTD };

struct Type {
  TypeKind kind = TypeKind::Bool;
  std::string name = "BOOL";         ///< as written: "INT", "UINT", "TIME", "TON", "INT(0..10)"
  std::int64_t lo = 0;               ///< Int: smallest value
  std::int64_t hi = 1;               ///< Int: largest value
  StandardFb fb = StandardFb::None;  ///< FunctionBlock: which one
  /// Int of an enumeration: its enumerators and their values (properties may name them).
  std::vector<std::pair<std::string, std::int64_t>> enumerators;

  static Type boolean();
  static Type time();
  static Type integer(std::string name, std::int64_t lo, std::int64_t hi);
  static Type function_block(StandardFb fb);
  /// STRING, as read: model::lower_data_types gives it the range of the project's string
  /// codes (docs/semantics.md 1.7a).
  static Type string();
  bool is_string() const { return kind == TypeKind::Int && name == "STRING"; }

  bool operator==(const Type&) const = default;
};

/// The IEC 61131-3 elementary type named `name` (case-insensitive: BOOL, SINT, INT, DINT, LINT,
/// USINT, UINT, UDINT, ULINT, BYTE, WORD, DWORD, TIME) or a standard FB (TON, ...); nullopt if
/// unknown.
std::optional<Type> elementary_type(std::string_view name);

StandardFb standard_fb(std::string_view name);
std::string_view to_string(StandardFb fb);

}  // namespace sfcv::model

#include "model/types.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <utility>

namespace sfcv::model {

namespace {
std::string upper(std::string_view s) {
  std::string r(s);
  for (auto& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}
}  // namespace

Type Type::boolean() {
  return Type{};
}

Type Type::time() {
  Type t;
  t.kind = TypeKind::Time;
  t.name = "TIME";
  t.lo = 0;
  t.hi = std::numeric_limits<std::int32_t>::max();
  return t;
}

Type Type::integer(std::string name, std::int64_t lo, std::int64_t hi) {
  Type t;
  t.kind = TypeKind::Int;
  t.name = std::move(name);
  t.lo = lo;
  t.hi = hi;
  return t;
}

Type Type::function_block(StandardFb fb) {
  Type t;
  t.kind = TypeKind::FunctionBlock;
  t.name = std::string(to_string(fb));
  t.lo = t.hi = 0;
  t.fb = fb;
  return t;
}

Type Type::string() {
  return integer("STRING", 0, 0);
}

std::optional<Type> elementary_type(std::string_view name) {
  const std::string n = upper(name);
  if (n == "BOOL") return Type::boolean();
  if (n == "TIME") return Type::time();
  struct Range {
    const char* name;
    std::int64_t lo, hi;
  };
  static constexpr std::array<Range, 12> ranges{{
      {"SINT", -128, 127},
      {"INT", -32768, 32767},
      {"DINT", std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()},
      {"LINT", std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()},
      {"USINT", 0, 255},
      {"UINT", 0, 65535},
      {"UDINT", 0, 4294967295LL},
      {"ULINT", 0, std::numeric_limits<std::int64_t>::max()},
      {"BYTE", 0, 255},
      {"WORD", 0, 65535},
      {"DWORD", 0, 4294967295LL},
      {"LWORD", 0, std::numeric_limits<std::int64_t>::max()},
  }};
  for (const auto& r : ranges)
    if (n == r.name) return Type::integer(r.name, r.lo, r.hi);
  if (auto fb = standard_fb(n); fb != StandardFb::None) return Type::function_block(fb);
  return std::nullopt;
}

StandardFb standard_fb(std::string_view name) {
  const std::string n = upper(name);
  static constexpr std::array<std::pair<const char*, StandardFb>, 9> fbs{{
      {"R_TRIG", StandardFb::R_TRIG},
      {"F_TRIG", StandardFb::F_TRIG},
      {"SR", StandardFb::SR},
      {"RS", StandardFb::RS},
      {"TON", StandardFb::TON},
      {"TOF", StandardFb::TOF},
      {"TP", StandardFb::TP},
      {"CTU", StandardFb::CTU},
      {"CTD", StandardFb::CTD},
  }};
  for (const auto& [k, v] : fbs)
    if (n == k) return v;
  return StandardFb::None;
}

std::string_view to_string(StandardFb fb) {
  switch (fb) {
    case StandardFb::R_TRIG:
      return "R_TRIG";
    case StandardFb::F_TRIG:
      return "F_TRIG";
    case StandardFb::SR:
      return "SR";
    case StandardFb::RS:
      return "RS";
    case StandardFb::TON:
      return "TON";
    case StandardFb::TOF:
      return "TOF";
    case StandardFb::TP:
      return "TP";
    case StandardFb::CTU:
      return "CTU";
    case StandardFb::CTD:
      return "CTD";
    case StandardFb::None:
      break;
  }
  return "";
}

}  // namespace sfcv::model

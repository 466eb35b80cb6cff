#include "model/literal.hpp"

#include <cctype>
#include <limits>

#include "model/names.hpp"

namespace sfcv::model {

namespace {

// Sums of durations are kept in ns below this cap; anything at or above it is far past TIME's
// range (2^31 ms is about 2^51 ns), so saturating there loses nothing.
constexpr std::uint64_t kDurationCapNs = std::uint64_t{1} << 62;

int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

bool starts_with_ci(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && iequals(s.substr(0, prefix.size()), prefix);
}

std::string lint_range_error(std::string_view written) {
  return "integer literal " + std::string(written) + " is outside " +
         range_text(*elementary_type("LINT"));
}

// Digits with single '_' separators: false on anything else (empty, a leading, trailing or
// doubled '_', a digit not of `base`). `each` gets each digit's value.
template <class Each>
bool for_each_digit(std::string_view digits, int base, Each each) {
  if (digits.empty() || digits.front() == '_' || digits.back() == '_') return false;
  char previous = '0';
  for (char c : digits) {
    if (c == '_') {
      if (previous == '_') return false;
    } else {
      const int d = digit_value(c);
      if (d >= base) return false;
      each(d);
    }
    previous = c;
  }
  return true;
}

}  // namespace

Converted<std::uint64_t> literal_magnitude(std::string_view digits, int base,
                                           std::string_view written) {
  std::uint64_t v = 0;
  bool too_large = false;
  const auto b = static_cast<std::uint64_t>(base);
  const bool ok = for_each_digit(digits, base, [&](int d) {
    if (too_large || v > (kMaxLiteralMagnitude - static_cast<std::uint64_t>(d)) / b)
      too_large = true;
    else
      v = v * b + static_cast<std::uint64_t>(d);
  });
  if (!ok) return {std::nullopt, "malformed integer literal '" + std::string(written) + "'"};
  if (too_large) return {std::nullopt, lint_range_error(written)};
  return {v, {}};
}

Converted<std::int64_t> signed_literal(bool negative, std::uint64_t magnitude,
                                       std::string_view written) {
  if (magnitude > kMaxLiteralMagnitude || (!negative && magnitude == kMaxLiteralMagnitude))
    return {std::nullopt, lint_range_error(written)};
  if (magnitude == kMaxLiteralMagnitude) return {std::numeric_limits<std::int64_t>::min(), {}};
  const auto v = static_cast<std::int64_t>(magnitude);
  return {negative ? -v : v, {}};
}

Converted<std::int64_t> integer_literal(std::string_view text) {
  const std::string_view written = text;
  const auto not_integer = [&] {
    return Converted<std::int64_t>{std::nullopt,
                                   "'" + std::string(written) + "' is not an integer literal"};
  };
  bool negative = false;
  const auto sign = [&] {
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
      negative = negative != (text.front() == '-');
      text.remove_prefix(1);
      return true;
    }
    return false;
  };
  const bool signed_outside = sign();
  // A type prefix such as INT# or UDINT# (letters before '#'): its range applies.
  std::optional<Type> type;
  if (const auto hash = text.find('#'); hash != std::string_view::npos && hash > 0 &&
                                        std::isalpha(static_cast<unsigned char>(text.front()))) {
    const auto prefix = text.substr(0, hash);
    for (char c : prefix)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return not_integer();
    type = elementary_type(prefix);
    // An unknown prefix (a vendor's or user's integer type) is read without a range.
    if (type && type->kind != TypeKind::Int) return not_integer();
    text.remove_prefix(hash + 1);
    if (sign() && signed_outside) return not_integer();
  }
  int base = 10;
  if (const auto hash = text.find('#'); hash != std::string_view::npos) {
    const auto b = text.substr(0, hash);
    if (b == "2")
      base = 2;
    else if (b == "8")
      base = 8;
    else if (b == "16")
      base = 16;
    else
      return not_integer();
    text.remove_prefix(hash + 1);
  }
  if (text.empty() || digit_value(text.front()) >= base) return not_integer();
  const auto magnitude = literal_magnitude(text, base, written);
  if (!magnitude) return {std::nullopt, magnitude.error};
  auto value = signed_literal(negative, *magnitude, written);
  if (value && type) {
    if (auto e = range_error(*value, *type, written); !e.empty()) return {std::nullopt, e};
  }
  return value;
}

std::string time_text(std::int64_t ms) {
  if (ms == 0) return "T#0ms";
  std::string s = ms < 0 ? "T#-" : "T#";
  // The magnitude of the most negative value does not fit: go through unsigned.
  std::uint64_t m = ms < 0 ? 0 - static_cast<std::uint64_t>(ms) : static_cast<std::uint64_t>(ms);
  const std::pair<const char*, std::uint64_t> units[] = {
      {"d", 86400000}, {"h", 3600000}, {"m", 60000}, {"s", 1000}, {"ms", 1}};
  for (const auto& [unit, size] : units) {
    if (m >= size) {
      s += std::to_string(m / size) + unit;
      m %= size;
    }
  }
  return s;
}

std::string range_text(const Type& t) {
  if (t.kind == TypeKind::Time)
    return t.name + " (" + time_text(t.lo) + ".." + time_text(t.hi) + ")";
  // A subrange's name already shows its range: INT(0..10).
  if (t.name.find('(') != std::string::npos) return t.name;
  return t.name + " (" + std::to_string(t.lo) + ".." + std::to_string(t.hi) + ")";
}

std::string range_error(std::int64_t v, const Type& t, std::string_view written) {
  if (t.kind != TypeKind::Int && t.kind != TypeKind::Time) return {};
  if (v >= t.lo && v <= t.hi) return {};
  return std::string(written) + " is outside " + range_text(t);
}

bool DurationLiteral::add(std::string_view whole, std::string_view fraction, std::int64_t unit_ns) {
  std::uint64_t w = 0;
  const auto unit = static_cast<std::uint64_t>(unit_ns);
  bool ok = for_each_digit(whole, 10, [&](int d) {
    w = w > kDurationCapNs / 10 ? kDurationCapNs : w * 10 + static_cast<std::uint64_t>(d);
  });
  for (char c : fraction)
    if (!std::isdigit(static_cast<unsigned char>(c))) ok = false;
  if (!ok) {
    error_ = "malformed TIME literal";
    return false;
  }
  if (w >= kDurationCapNs / unit)
    too_large_ = true;
  else
    ns_ += w * unit;
  // The fraction F/10^k of the unit, exactly: trailing zeros add nothing, and more than 20
  // significant digits can never make whole nanoseconds (a day is 2^16 * 3^3 * 5^11 ns).
  while (!fraction.empty() && fraction.back() == '0') fraction.remove_suffix(1);
  if (fraction.size() > 20) {
    error_ = "TIME literal finer than a nanosecond";
    return false;
  }
  __extension__ using Int128 = unsigned __int128;
  Int128 f = 0, scale = 1;
  for (char c : fraction) {
    f = f * 10 + static_cast<unsigned>(c - '0');
    scale *= 10;
  }
  const Int128 part = f * unit;
  if (part % scale != 0) {
    error_ = "TIME literal finer than a nanosecond";
    return false;
  }
  ns_ += static_cast<std::uint64_t>(part / scale);  // below one unit: at most a day
  if (ns_ >= kDurationCapNs) too_large_ = true;
  return true;
}

Converted<std::int64_t> DurationLiteral::milliseconds(bool negative) const {
  const auto too_large = [&] {
    return Converted<std::int64_t>{
        std::nullopt, "TIME literal " + written_ + " is outside " + range_text(Type::time())};
  };
  if (too_large_) return too_large();
  if (ns_ % 1000000 != 0)
    return {std::nullopt, "unsupported: TIME literal finer than a millisecond"};
  const auto ms = static_cast<std::int64_t>(ns_ / 1000000);
  // T#-5s is the negation of T#5s: its magnitude is in TIME's range, as the parsers read it.
  if (ms > kMaxTimeMs) return too_large();
  return {negative ? -ms : ms, {}};
}

std::optional<std::int64_t> iec_duration_unit_ns(std::string_view unit) {
  const std::string u = to_upper(unit);
  if (u == "D") return 86400LL * 1000000000LL;
  if (u == "H") return 3600LL * 1000000000LL;
  if (u == "M") return 60LL * 1000000000LL;
  if (u == "S") return 1000000000LL;
  if (u == "MS") return 1000000LL;
  if (u == "US") return 1000LL;
  if (u == "NS") return 1LL;
  return std::nullopt;
}

Converted<std::int64_t> duration_body(std::string_view body, std::string_view written) {
  const auto fail = [](std::string why) { return Converted<std::int64_t>{std::nullopt, why}; };
  bool negative = false;
  if (!body.empty() && (body.front() == '-' || body.front() == '+')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  DurationLiteral d(written);
  bool any = false;
  std::size_t i = 0;
  while (i < body.size()) {
    if (!std::isdigit(static_cast<unsigned char>(body[i]))) return fail("malformed TIME literal");
    const std::size_t w = i;
    while (i < body.size() && (std::isdigit(static_cast<unsigned char>(body[i])) || body[i] == '_'))
      ++i;
    const std::string_view whole = body.substr(w, i - w);
    std::string_view fraction;
    if (i < body.size() && body[i] == '.') {
      const std::size_t f = ++i;
      while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i;
      fraction = body.substr(f, i - f);
      if (fraction.empty()) return fail("malformed TIME literal");
    }
    const std::size_t u = i;
    while (i < body.size() && std::isalpha(static_cast<unsigned char>(body[i]))) ++i;
    const std::string_view unit = body.substr(u, i - u);
    const auto unit_ns = iec_duration_unit_ns(unit);
    if (!unit_ns)
      return fail(unit.empty() ? "TIME literal: missing unit (d, h, m, s, ms)"
                               : "TIME literal: unknown unit '" + std::string(unit) + "'");
    if (!d.add(whole, fraction, *unit_ns)) return fail(d.error());
    any = true;
    if (i < body.size() && body[i] == '_') ++i;
  }
  if (!any) return fail("malformed TIME literal");
  return d.milliseconds(negative);
}

Converted<std::int64_t> time_literal(std::string_view text) {
  for (std::string_view prefix : {"TIME#", "LTIME#", "LT#", "T#"})
    if (starts_with_ci(text, prefix)) return duration_body(text.substr(prefix.size()), text);
  return {std::nullopt, {}};
}

}  // namespace sfcv::model

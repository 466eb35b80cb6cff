#include "io/g7_lexicon.hpp"

#include <array>
#include <cctype>

#include "model/names.hpp"

namespace sfcv::io::g7 {

bool is_reserved_in_expression(std::string_view word) {
  static constexpr std::array<std::string_view, 6> kWords{"RE",    "FE",  "TRUE",
                                                          "FALSE", "MOD", "INIT"};
  for (auto w : kWords)
    if (model::iequals(w, word)) return true;
  return false;
}

bool is_plain_name(std::string_view name) {
  if (name.empty()) return false;
  const auto c0 = static_cast<unsigned char>(name[0]);
  if (std::isdigit(c0)) {
    for (char c : name)
      if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
  }
  if (!std::isalpha(c0) && c0 != '_') return false;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (!std::isalnum(u) && u != '_') return false;
  }
  return true;
}

std::string quote_name(std::string_view name, bool in_expression) {
  const bool bare = is_plain_name(name) &&
                    !(in_expression && (std::isdigit(static_cast<unsigned char>(name[0])) ||
                                        is_reserved_in_expression(name)));
  if (bare) return std::string(name);
  std::string s = "\"";
  for (char c : name) {
    if (c == '"' || c == '\\') s += '\\';
    s += c;
  }
  return s + "\"";
}

std::string duration(std::int64_t ms) {
  if (ms % 1000 == 0) return std::to_string(ms / 1000) + "s";
  return std::to_string(ms) + "ms";
}

std::string range_type_name(std::int64_t lo, std::int64_t hi) {
  return "INT(" + std::to_string(lo) + ".." + std::to_string(hi) + ")";
}

}  // namespace sfcv::io::g7

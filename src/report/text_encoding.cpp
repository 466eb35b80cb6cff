#include "report/text_encoding.hpp"

#include <cstdint>
#include <utility>

namespace sfcv::report {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

/// The length of the well-formed UTF-8 sequence at s[i] (1 to 4), 0 when s[i] starts none
/// (Unicode 15, table 3-7); `code` is its code point.
std::size_t sequence_at(std::string_view s, std::size_t i, std::uint32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) {
    code = b0;
    return 1;
  }
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;  // no overlong form
    if (b0 == 0xED) hi = 0x9F;  // no surrogate
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;  // no overlong form
    if (b0 == 0xF4) hi = 0x8F;  // at most U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  code = b0 & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
  for (std::size_t k = 1; k < n; ++k) code = (code << 6) | (byte(i + k) & 0x3F);
  return n;
}

/// `s` with each invalid byte, and each character `keep` refuses, replaced by U+FFFD.
template <class Keep>
std::string replaced(std::string_view s, Keep keep) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    std::uint32_t code = 0;
    const auto n = sequence_at(s, i, code);
    if (n == 0 || !keep(code)) {
      out += kReplacement;
      i += n == 0 ? 1 : n;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  return out;
}

bool xml_char(std::uint32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c != 0xFFFE && c != 0xFFFF);
}

}  // namespace

bool is_valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    std::uint32_t code = 0;
    const auto n = sequence_at(s, i, code);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string valid_utf8(std::string_view s) {
  if (is_valid_utf8(s)) return std::string(s);
  return replaced(s, [](std::uint32_t) { return true; });
}

std::string xml_text(std::string_view s) {
  return replaced(s, xml_char);
}

namespace {

template <class Json>
void walk(Json& j) {
  if (j.is_string()) {
    auto& text = j.template get_ref<std::string&>();
    if (!is_valid_utf8(text)) text = valid_utf8(text);
  } else if (j.is_array()) {
    for (auto& x : j) walk(x);
  } else if (j.is_object()) {
    bool bad_key = false;
    for (auto it = j.begin(); it != j.end(); ++it) {
      bad_key = bad_key || !is_valid_utf8(it.key());
      walk(it.value());
    }
    if (!bad_key) return;
    Json out = Json::object();
    for (auto it = j.begin(); it != j.end(); ++it)
      out[valid_utf8(it.key())] = std::move(it.value());
    j = std::move(out);
  }
}

}  // namespace

void make_valid_utf8(nlohmann::json& j) {
  walk(j);
}
void make_valid_utf8(nlohmann::ordered_json& j) {
  walk(j);
}

}  // namespace sfcv::report

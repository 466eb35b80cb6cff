#include "report/numbers.hpp"

#include <algorithm>

namespace sfcv::report {

std::string count_text(std::string_view decimal) {
  if (decimal.empty() ||
      !std::all_of(decimal.begin(), decimal.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::string(decimal);
  while (decimal.size() > 1 && decimal.front() == '0') decimal.remove_prefix(1);
  if (decimal.size() <= 4) return std::string(decimal);  // 1024, not 1,024: short enough
  if (decimal.size() <= 12) {
    std::string out;
    for (std::size_t i = 0; i < decimal.size(); ++i) {
      if (i > 0 && (decimal.size() - i) % 3 == 0) out += ',';
      out += decimal[i];
    }
    return out;
  }
  // Rounded to two significant digits, by hand: the count may not fit in any machine number.
  int first = decimal[0] - '0', second = decimal[1] - '0';
  std::size_t exponent = decimal.size() - 1;
  if (decimal[2] >= '5' && ++second == 10) {
    second = 0;
    if (++first == 10) {
      first = 1;
      ++exponent;
    }
  }
  return std::to_string(first) + "." + std::to_string(second) + "\u00b710^" +
         std::to_string(exponent);
}

std::string count_text(std::uint64_t n) {
  return count_text(std::to_string(n));
}

std::string counted(std::string_view decimal, std::string_view singular, std::string_view plural) {
  const bool one = decimal == "1";
  std::string word(one ? singular : plural);
  if (!one && plural.empty()) word = std::string(singular) + "s";
  return count_text(decimal) + " " + word;
}

std::string counted(std::uint64_t n, std::string_view singular, std::string_view plural) {
  return counted(std::to_string(n), singular, plural);
}

}  // namespace sfcv::report

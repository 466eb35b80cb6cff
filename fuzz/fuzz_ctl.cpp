// libFuzzer harness: the CTL formula and spec-file parsers, and printing what they parse.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "logic/formula.hpp"
#include "logic/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto f = sfcv::logic::parse_formula(text);
    if (f.formula) (void)sfcv::logic::to_string(*f.formula);
    const auto s = sfcv::logic::parse_spec(text);
    for (const auto& p : s.spec.properties) (void)sfcv::logic::to_string(*p.formula);
  } catch (const std::exception&) {
  }
  return 0;
}

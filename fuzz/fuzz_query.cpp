// libFuzzer harness: the query parser and printer, and the query library parser.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "logic/query_ast.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto q = sfcv::logic::parse_query(text);
    if (q) (void)sfcv::logic::to_string(*q);
  } catch (const std::exception&) {
  }
  try {
    (void)sfcv::logic::parse_library(text, "fuzz");
  } catch (const std::exception&) {
  }
  return 0;
}

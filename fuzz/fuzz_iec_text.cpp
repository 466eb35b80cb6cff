// libFuzzer harness: io::load_iec_text, then validation and the semantics' compilation.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sfcv::fuzz::load_validate_build(&sfcv::io::load_iec_text, data, size);
  return 0;
}

// libFuzzer harness: io::load_l5x (SFC routines, ladder rungs and their JSRs), then validation
// and the semantics' compilation.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sfcv::fuzz::load_validate_build(&sfcv::io::load_l5x, data, size);
  return 0;
}

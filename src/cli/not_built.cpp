#include "cli/not_built.hpp"

#include <iostream>

#include "cli/exit_code.hpp"

namespace sfcv::cli {
int not_built_yet(const std::string& what) {
  std::cerr << "sfcv: " << what << " is not built yet\n";
  return kBadInput;
}
}  // namespace sfcv::cli

#pragma once
#include <string>

namespace sfcv::cli {
/// A subcommand that is not built yet says so and exits 2.
int not_built_yet(const std::string& what);
}  // namespace sfcv::cli

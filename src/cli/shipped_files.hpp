#pragma once
// The files sfcv ships in share/sfcv (the query library, the patterns library).

#include <string>

namespace sfcv::cli {

/// share/sfcv/`name`: <prefix>/share/sfcv next to an installed binary, else the source tree;
/// empty when neither has it.
std::string shipped_file(const std::string& name);

}  // namespace sfcv::cli

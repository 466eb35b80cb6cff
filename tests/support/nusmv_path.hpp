#pragma once
// The NuSMV the optional NuSMV tests run: $SFCV_NUSMV when set (a NuSMV built by hand, outside
// the repository: NuSMV is not packaged in Debian), else a NuSMV on PATH (what
// `--engine nusmv` finds). Without one those tests skip, visibly.

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "engine/external/nusmv_runner.hpp"

namespace sfcv::test {

inline std::optional<std::string> nusmv_for_tests() {
  if (const char* p = std::getenv("SFCV_NUSMV"); p && *p) {
    if (std::filesystem::exists(p)) return std::filesystem::absolute(p).string();
    return std::nullopt;
  }
  return engine::find_nusmv();
}

}  // namespace sfcv::test

#define REQUIRE_NUSMV(var)                                                               \
  const auto var = sfcv::test::nusmv_for_tests();                                        \
  if (!var)                                                                              \
  GTEST_SKIP() << "no NuSMV: set SFCV_NUSMV to a NuSMV 2.6 binary or put NuSMV on PATH " \
                  "(docs/exports.md)"

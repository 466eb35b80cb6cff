#include "cli/shipped_files.hpp"

#include <filesystem>

namespace sfcv::cli {

std::string shipped_file(const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "sfcv" / name;
    if (fs::exists(installed, ec)) return installed.string();
  }
  const fs::path source = fs::path(SFCV_SHARE_DIR) / name;
  if (!std::string(SFCV_SHARE_DIR).empty() && fs::exists(source, ec)) return source.string();
  return {};
}

}  // namespace sfcv::cli

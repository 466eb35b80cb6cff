#pragma once
// Test helpers: running the sfcv binary, reaching the shared corpus, writing temp files.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace sfcv::test {

struct RunResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `sfcv <args>` (args are passed to /bin/sh as written) and captures both streams.
inline RunResult run_sfcv(const std::string& args, const std::string& stdin_text = "") {
  namespace fs = std::filesystem;
  static int counter = 0;
  const auto dir = fs::temp_directory_path() /
                   ("sfcv-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::create_directories(dir);
  const auto out = dir / "out", err = dir / "err", in = dir / "in";
  { std::ofstream(in) << stdin_text; }
  const std::string cmd = std::string("'") + SFCV_BINARY + "' " + args + " <'" + in.string() +
                          "' >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  auto slurp = [](const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove_all(dir);
  return r;
}

/// The shared corpus folder, from SFCV_CORPUS; nullopt when unset.
inline std::optional<std::filesystem::path> corpus_dir() {
  const char* v = std::getenv("SFCV_CORPUS");
  if (!v || !*v) return std::nullopt;
  return std::filesystem::path(v);
}

/// Skips the current test, visibly, when the corpus is not available.
#define SFCV_REQUIRE_CORPUS(var)                                                 \
  const auto var##_opt = ::sfcv::test::corpus_dir();                             \
  if (!var##_opt) GTEST_SKIP() << "SFCV_CORPUS is not set: corpus test skipped"; \
  const std::filesystem::path var = *var##_opt

/// A file under the source tree (examples/, tests/data/).
inline std::string source_path(const std::string& relative) {
  return std::string(SFCV_SOURCE_DIR) + "/" + relative;
}

/// Writes `text` to a fresh temporary file with the given suffix and returns its path.
inline std::string write_temp(const std::string& text, const std::string& suffix) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const auto p = fs::temp_directory_path() / ("sfcv-input-" + std::to_string(::getpid()) + "-" +
                                              std::to_string(counter++) + suffix);
  std::ofstream(p) << text;
  return p.string();
}

}  // namespace sfcv::test

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
#include <utility>
#include <vector>

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

/// Writes `text` to a fresh temporary file with the given suffix and returns its path. The file
/// is removed when the test program exits (a CI run wrote some 17,000 of them to /tmp).
inline std::string write_temp(const std::string& text, const std::string& suffix) {
  namespace fs = std::filesystem;
  struct Written {
    std::vector<fs::path> paths;
    ~Written() {
      std::error_code ignored;
      for (const auto& p : paths) fs::remove(p, ignored);
    }
  };
  static Written written;
  static int counter = 0;
  const auto p = fs::temp_directory_path() / ("sfcv-input-" + std::to_string(::getpid()) + "-" +
                                              std::to_string(counter++) + suffix);
  std::ofstream(p) << text;
  written.paths.push_back(p);
  return p.string();
}

/// The whole content of the file at `path` ("" when it cannot be read).
inline std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

/// The arguments of `sfcv check FILE --engine ENGINE OPTIONS` without traces, within a minute
/// (the engine-by-engine tests of a small chart).
inline std::string check_command(const std::string& file, const std::string& engine,
                                 const std::string& options) {
  return "check " + file + " --engine " + engine + " " + options + " --trace none --timeout 60";
}

/// One verdict of `sfcv check`: its options and the exit code expected (0 holds, 1 violated).
struct Verdict {
  std::string options;
  int exit_code;
};

/// Each verdict, on the explicit, BDD and IC3 engines alike (check_command's arguments).
inline void expect_on_every_engine(const std::string& file, const std::vector<Verdict>& verdicts) {
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    for (const auto& v : verdicts) {
      const auto r = run_sfcv(check_command(file, engine, v.options));
      EXPECT_EQ(r.exit_code, v.exit_code) << v.options << "\n" << r.out << r.err;
    }
  }
}

/// Each CTL property with its verdict word ("holds", "violated"), read from its own line of one
/// `sfcv check` run of `file` on `engine` (one run for all: the vendor-format tests compare a
/// native file with its twin and stay fast under sanitizers). Some verdict is violated: exit 1.
inline void expect_ctl_verdicts_in_one_run(
    const std::string& file, const std::string& engine,
    const std::vector<std::pair<std::string, const char*>>& verdicts) {
  SCOPED_TRACE(file + " " + engine);
  std::string options = "--checks none";
  for (const auto& [ctl, verdict] : verdicts) options += " --ctl '" + ctl + "'";
  const auto r = run_sfcv(check_command(file, engine, options));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  for (const auto& [ctl, verdict] : verdicts) {
    const auto at = r.out.find(ctl + " ");
    ASSERT_NE(at, std::string::npos) << ctl << "\n" << r.out;
    const auto line = r.out.substr(at, r.out.find('\n', at) - at);
    EXPECT_NE(line.find(verdict), std::string::npos) << line;
  }
}

/// IEC 61131-3 text of a chain of `n` steps s0..s{n-1} in one loop, each crossed on input `go`
/// (the long charts of the size and time-limit tests; 1,000,000 steps are 80 MB).
inline std::string iec_chain_text(int n) {
  std::string st = "PROGRAM p\nVAR_INPUT go : BOOL; END_VAR\nINITIAL_STEP s0 : END_STEP\n";
  st.reserve(static_cast<std::size_t>(n) * 80);
  for (int i = 1; i < n; ++i) st += "STEP s" + std::to_string(i) + " : END_STEP\n";
  for (int i = 0; i < n; ++i)
    st += "TRANSITION FROM s" + std::to_string(i) + " TO s" + std::to_string((i + 1) % n) +
          " := go; END_TRANSITION\n";
  return st + "END_PROGRAM\n";
}

/// The same chain as a `.g7` grafcet (steps 0..n-1, transitions named 0..n-1).
inline std::string g7_chain_text(int n) {
  std::string g7 = "project chain;\ninput go;\noutput o;\ngrafcet g {\n  step 0 initial;\n";
  for (int i = 1; i < n; ++i) g7 += "  step " + std::to_string(i) + ";\n";
  for (int i = 0; i < n; ++i)
    g7 += "  transition " + std::to_string(i) + ": " + std::to_string(i) + " -> " +
          std::to_string((i + 1) % n) + " when go;\n";
  return g7 + "}\n";
}

}  // namespace sfcv::test

#pragma once
// An sfcv run measured in CPU seconds of the child (getrusage), which a loaded machine does
// not inflate as it does wall time: the measure for "ends within its budget" tests; and one
// measured in peak resident memory, for "stays within --memory".

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {

// The bounds are for an optimised build; under AddressSanitizer every instruction costs
// several (the ci-asan preset measured 8 to 14 CPU s where the release build stays under 6).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr double kSlowdown = 4;
#else
inline constexpr double kSlowdown = 1;
#endif

inline double children_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

struct CpuRun {
  RunResult run;
  double cpu = 0;
};

inline CpuRun cpu_run(const std::string& args) {
  const double before = children_cpu_seconds();
  CpuRun r;
  r.run = run_sfcv(args);
  r.cpu = children_cpu_seconds() - before;
  return r;
}

struct MemoryRun {
  int exit_code = -1;
  std::string out;
  std::uint64_t peak_kib = 0;  ///< the child's peak resident memory (ru_maxrss)
};

/// Runs `sfcv <args>` as its own child (the shell execs sfcv), so that wait4 gives the peak
/// resident memory of that one run, not of the largest child the test process ever had.
inline MemoryRun memory_run(const std::string& args) {
  namespace fs = std::filesystem;
  const auto out = fs::temp_directory_path() /
                   ("sfcv-mem-" + std::to_string(::getpid()) + "-" + std::to_string(::rand()));
  const std::string cmd = std::string("exec '") + SFCV_BINARY + "' " + args + " >'" + out.string() +
                          "' 2>/dev/null </dev/null";
  MemoryRun r;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid > 0 && ::wait4(pid, &status, 0, &usage) == pid) {
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.peak_kib = static_cast<std::uint64_t>(usage.ru_maxrss);
  }
  std::ifstream f(out);
  std::stringstream ss;
  ss << f.rdbuf();
  r.out = ss.str();
  fs::remove(out);
  return r;
}

}  // namespace sfcv::test

#pragma once
// An sfcv run measured in CPU seconds of the child (getrusage), which a loaded machine does
// not inflate as it does wall time: the measure for "ends within its budget" tests.

#include <sys/resource.h>

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

}  // namespace sfcv::test

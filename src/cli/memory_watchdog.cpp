#include "cli/memory_watchdog.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace sfcv::cli {

namespace {

// Under AddressSanitizer the quarantine of freed blocks and the shadow pages are resident
// memory the program did not ask for; the budget is for what sfcv itself holds.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kSanitizerFactor = 4;
#else
constexpr std::uint64_t kSanitizerFactor = 1;
#endif

}  // namespace

std::uint64_t resident_memory_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long size = 0, resident = 0;
  const int read = std::fscanf(f, "%llu %llu", &size, &resident);
  std::fclose(f);
  if (read != 2) return 0;
  const long page = ::sysconf(_SC_PAGESIZE);
  return static_cast<std::uint64_t>(resident) * static_cast<std::uint64_t>(page > 0 ? page : 4096);
}

MemoryWatchdog::MemoryWatchdog(std::uint64_t max_bytes, std::shared_ptr<std::atomic<bool>> cancel) {
  if (max_bytes == 0 || !cancel || resident_memory_bytes() == 0) return;
  const std::uint64_t limit = max_bytes * kSanitizerFactor;
  thread_ = std::jthread([this, limit, cancel = std::move(cancel)](std::stop_token stop) {
    while (!stop.stop_requested()) {
      if (const auto now = resident_memory_bytes(); now > limit) {
        seen_.store(now);
        tripped_.store(true);
        cancel->store(true);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
}

MemoryWatchdog::~MemoryWatchdog() = default;  // the jthread asks its loop to stop and joins

}  // namespace sfcv::cli

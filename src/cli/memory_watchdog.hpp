#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// --memory for the whole process. Each engine counts its own structures (states, BDD nodes,
// the circuit), but not what it shares with others: under --engine auto three racers each held
// their own share and `--memory 100M` peaked at 134-178 MB. The watchdog reads the resident
// memory of the process (/proc/self/statm) every 10 ms and, past the budget, raises the run's
// cancel flag: the engines stop as at their deadline, and the report says the memory limit
// left the rest unknown (docs/reliability.md).

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>

namespace sfcv::cli {

/// The resident memory of this process in bytes (0 when it cannot be read).
std::uint64_t resident_memory_bytes();

class MemoryWatchdog {
 public:
  /// Watches until destroyed; does nothing when `max_bytes` is 0.
  MemoryWatchdog(std::uint64_t max_bytes, std::shared_ptr<std::atomic<bool>> cancel);
  ~MemoryWatchdog();
  MemoryWatchdog(const MemoryWatchdog&) = delete;
  MemoryWatchdog& operator=(const MemoryWatchdog&) = delete;

  /// Whether the process went past the budget (and the run was cancelled).
  bool tripped() const { return tripped_.load(); }
  /// The resident memory that tripped it.
  std::uint64_t seen_bytes() const { return seen_.load(); }

 private:
  std::atomic<bool> tripped_{false};
  std::atomic<std::uint64_t> seen_{0};
  std::jthread thread_;
};

}  // namespace sfcv::cli

#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// The progress of a long run on standard error, for every phase: the library reports through
// model::Budget::progress; a ticker thread prints what was last reported, so that a phase that
// reports nothing (loading, building) still shows its name and time. Nothing before ~2 s; then
// a refreshing line (\r) on a terminal, or one line every ~10 s elsewhere (CI logs).

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "model/budget.hpp"

namespace sfcv::cli {

class ProgressLine {
 public:
  /// `enabled` false (--quiet): prints nothing, ever.
  explicit ProgressLine(bool enabled);
  ~ProgressLine();  ///< stops the ticker; clears a refreshing line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Starts a phase ("load", "build", "explore", ...): its counters start from 0.
  void phase(const char* name);
  /// The callback for model::Budget::progress.
  std::function<void(const model::Progress&)> callback();
  /// Clears a refreshing line before other output goes to standard error.
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  void tick();
  std::string render() const;  ///< under mutex_

  bool enabled_;
  bool terminal_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point phase_start_ = start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool line_shown_ = false;  ///< a refreshing line is on the terminal
  model::Progress last_;
  std::string phase_ = "start";
  std::thread ticker_;
};

}  // namespace sfcv::cli

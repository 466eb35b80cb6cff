#pragma once
// Public within sfcv_cli for its tests (tests/cli/progress_line_test.cpp).
// The progress of a long run on standard error, for every phase: the library reports through
// model::Budget::progress; a ticker thread prints what was last reported, so that a phase that
// reports nothing (loading, building) still shows its name and time. Nothing before ~2 s; then
// a refreshing line (\r) on a terminal, never wider than the terminal (a wider line wraps and
// scrolls), or one line every ~10 s elsewhere (CI logs). Under --engine auto each engine of
// the race (bdd, ic3, bmc) has its part of the line: its phase, depth or frame, and how long it
// has been on its current step when that is long (a slow BDD image must not look frozen).

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "model/budget.hpp"

namespace sfcv::cli {

/// The columns of the terminal on `fd` (ioctl TIOCGWINSZ); else $COLUMNS; else 80.
int terminal_width(int fd);

/// Where and how often the line is printed (tests use a pseudo-terminal and short delays).
struct ProgressOutput {
  std::FILE* stream = stderr;
  bool terminal = false;  ///< a refreshing line; else one line per interval
  int fd = 2;             ///< asked for its width at each refresh (a terminal may be resized)
  std::chrono::milliseconds quiet_start{2000};    ///< short runs print nothing
  std::chrono::milliseconds refresh{500};         ///< on a terminal
  std::chrono::milliseconds log_interval{10000};  ///< off a terminal
  static ProgressOutput standard_error();
};

class ProgressLine {
 public:
  /// `enabled` false (--quiet): prints nothing, ever.
  explicit ProgressLine(bool enabled, ProgressOutput output = ProgressOutput::standard_error());
  ~ProgressLine();  ///< stops the ticker; clears a refreshing line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Starts a phase ("load", "build", "explore", ...): its counters start from 0.
  void phase(const char* name);
  /// The callback for model::Budget::progress.
  std::function<void(const model::Progress&)> callback();
  /// Clears a refreshing line before other output goes to standard error.
  void clear();
  /// The line as it would be printed now, cut to `width` columns less one (tests).
  std::string line(int width);

 private:
  using Clock = std::chrono::steady_clock;
  /// One engine of --engine auto's race: what it last reported, and since when.
  struct Racer {
    model::Progress last;
    std::string phase;
    Clock::time_point since;
    bool finished = false;
  };
  void tick();
  std::string render(int width) const;  ///< under mutex_
  std::string racer_text(const std::string& name, const Racer& r) const;

  bool enabled_;
  ProgressOutput output_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point phase_start_ = start_;
  Clock::time_point last_report_ = start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::size_t shown_ = 0;  ///< columns of the refreshing line on the terminal (0: none)
  model::Progress last_;
  std::string phase_ = "start";
  std::map<std::string, Racer> racers_;
  std::thread ticker_;
};

}  // namespace sfcv::cli

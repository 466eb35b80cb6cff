#include "cli/progress_line.hpp"

#include <unistd.h>

#include <cstdio>

namespace sfcv::cli {

namespace {

constexpr std::chrono::milliseconds kQuietStart{2000};  ///< short runs print nothing
constexpr std::chrono::milliseconds kTerminalRefresh{500};
constexpr std::chrono::milliseconds kLogInterval{10000};  ///< off a terminal

}  // namespace

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), terminal_(::isatty(2) != 0) {
  if (enabled_) ticker_ = std::thread([this] { tick(); });
}

ProgressLine::~ProgressLine() {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  ticker_.join();
  clear();
}

void ProgressLine::phase(const char* name) {
  std::lock_guard<std::mutex> lock(mutex_);
  phase_ = name;
  phase_start_ = Clock::now();
  last_ = model::Progress{};
}

std::function<void(const model::Progress&)> ProgressLine::callback() {
  if (!enabled_) return {};
  return [this](const model::Progress& p) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (p.phase && *p.phase && phase_ != p.phase) {
      phase_ = p.phase;
      phase_start_ = Clock::now();
    }
    last_ = p;
  };
}

void ProgressLine::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (line_shown_) {
    std::fprintf(stderr, "\r%*s\r", 100, "");
    std::fflush(stderr);
    line_shown_ = false;
  }
}

std::string ProgressLine::render() const {
  const double total = std::chrono::duration<double>(Clock::now() - start_).count();
  const double in_phase = std::chrono::duration<double>(Clock::now() - phase_start_).count();
  char buf[256];
  int n = std::snprintf(buf, sizeof buf, "sfcv: %s: %.0f s", phase_.c_str(), total);
  auto add = [&](const char* fmt, auto... args) {
    if (n >= 0 && n < static_cast<int>(sizeof buf))
      n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), fmt, args...);
  };
  if (last_.states) {
    add(", %llu states", static_cast<unsigned long long>(last_.states));
    if (last_.edges) add(", %llu edges", static_cast<unsigned long long>(last_.edges));
    add(", depth %u", last_.depth);
    const double seconds = last_.seconds > 0 ? last_.seconds : in_phase;
    if (seconds > 0.1 && last_.total == 0) add(", %.0f states/s", last_.states / seconds);
  }
  if (last_.total)
    add(", %llu/%llu done", static_cast<unsigned long long>(last_.done),
        static_cast<unsigned long long>(last_.total));
  return buf;
}

void ProgressLine::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_for(lock, kQuietStart, [this] { return stop_; })) return;
  for (;;) {
    const std::string line = render();
    if (terminal_) {
      std::fprintf(stderr, "\r%-99s", line.c_str());
      line_shown_ = true;
    } else {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
    std::fflush(stderr);
    if (wake_.wait_for(lock, terminal_ ? kTerminalRefresh : kLogInterval, [this] { return stop_; }))
      return;
  }
}

}  // namespace sfcv::cli

#include "cli/progress_line.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "report/numbers.hpp"

namespace sfcv::cli {

namespace {

/// A step of one engine that has lasted this long shows its time: it is working, not frozen.
constexpr std::chrono::seconds kSlowStep{3};

/// A count on the line: grouped digits, or 3.5e13 past a trillion (ASCII: one byte per column).
std::string count(std::uint64_t n) {
  if (n < 1000000000000ULL) return report::count_text(n);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", static_cast<double>(n));
  return buf;
}

}  // namespace

int terminal_width(int fd) {
  struct winsize size {};
  if (::ioctl(fd, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  if (const char* columns = std::getenv("COLUMNS")) {
    const int n = std::atoi(columns);
    if (n > 0) return n;
  }
  return 80;
}

ProgressOutput ProgressOutput::standard_error() {
  ProgressOutput o;
  o.terminal = ::isatty(2) != 0;
  return o;
}

ProgressLine::ProgressLine(bool enabled, ProgressOutput output)
    : enabled_(enabled), output_(output) {
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
  last_report_ = phase_start_;
  last_ = model::Progress{};
  racers_.clear();  // a race belongs to the phase that ran it
}

std::function<void(const model::Progress&)> ProgressLine::callback() {
  if (!enabled_) return {};
  return [this](const model::Progress& p) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = Clock::now();
    if (p.engine && *p.engine) {
      auto& r = racers_[p.engine];
      const std::string phase = p.phase ? p.phase : "";
      if (phase == "done") {
        r.finished = true;
        return;
      }
      // A new depth, frame or count is progress: the "on this step for N s" restarts.
      if (r.phase != phase || r.last.depth != p.depth || r.last.done != p.done ||
          r.since == Clock::time_point{})
        r.since = now;
      r.phase = phase;
      r.last = p;
      return;
    }
    if (p.phase && *p.phase && phase_ != p.phase) {
      phase_ = p.phase;
      phase_start_ = now;
    }
    if (p.depth != last_.depth || p.done != last_.done || p.states != last_.states)
      last_report_ = now;
    last_ = p;
  };
}

void ProgressLine::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (shown_ > 0) {
    std::fprintf(output_.stream, "\r%*s\r", static_cast<int>(shown_), "");
    std::fflush(output_.stream);
    shown_ = 0;
  }
}

std::string ProgressLine::line(int width) {
  std::lock_guard<std::mutex> lock(mutex_);
  return render(width);
}

std::string ProgressLine::racer_text(const std::string& name, const Racer& r) const {
  if (r.finished) return name + " done";
  std::string text = name;
  const auto& p = r.last;
  // Words per engine: IC3 opens frames, BMC and k-induction unroll depths, the BDD engine
  // computes images ring by ring, then runs the checks.
  if (r.phase == "ic3")
    text += " frame " + std::to_string(p.depth);
  else if (r.phase == "bmc" || r.phase == "k-induction")
    text += (name == r.phase ? "" : " " + r.phase) + " depth " + std::to_string(p.depth);
  else if (p.total > 0)
    text += " checks " + std::to_string(p.done) + "/" + std::to_string(p.total);
  else if (r.phase.rfind("explore", 0) == 0)
    text += " depth " + std::to_string(p.depth) + (p.states ? ", " + count(p.states) + " st" : "");
  else if (!r.phase.empty())
    text += " " + r.phase;
  const auto on_step = Clock::now() - r.since;
  if (on_step >= kSlowStep)
    text += " (" +
            std::to_string(std::chrono::duration_cast<std::chrono::seconds>(on_step).count()) +
            " s)";
  return text;
}

std::string ProgressLine::render(int width) const {
  const auto now = Clock::now();
  const double total = std::chrono::duration<double>(now - start_).count();
  const double in_phase = std::chrono::duration<double>(now - phase_start_).count();
  char seconds_text[32];
  std::snprintf(seconds_text, sizeof seconds_text, "%.0f s", total);
  std::string text;
  if (!racers_.empty()) {
    // The race: one part per engine; "done" only for an engine that has finished.
    text = "sfcv: race: " + std::string(seconds_text);
    for (const auto& [name, r] : racers_) text += " | " + racer_text(name, r);
  } else {
    text = "sfcv: " + phase_ + ": " + seconds_text;
    if (last_.states) {
      text += ", " + count(last_.states) + " states";
      if (last_.edges) text += ", " + count(last_.edges) + " edges";
      text += ", depth " + std::to_string(last_.depth);
      const double seconds = last_.seconds > 0 ? last_.seconds : in_phase;
      if (seconds > 0.1 && last_.total == 0)
        text += ", " + count(static_cast<std::uint64_t>(last_.states / seconds)) + " states/s";
    }
    if (last_.total)
      text += ", " + std::to_string(last_.done) + "/" + std::to_string(last_.total) + " checks";
    const auto quiet = now - last_report_;
    if (quiet >= kSlowStep && (last_.states || last_.total))
      text += " (" +
              std::to_string(std::chrono::duration_cast<std::chrono::seconds>(quiet).count()) +
              " s on this step)";
  }
  // The last column is left free: a line that fills it wraps on some terminals.
  const auto limit = static_cast<std::size_t>(width > 1 ? width - 1 : 1);
  if (text.size() > limit)
    text = text.substr(0, limit > 3 ? limit - 3 : limit) + (limit > 3 ? "..." : "");
  return text;
}

void ProgressLine::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_for(lock, output_.quiet_start, [this] { return stop_; })) return;
  for (;;) {
    if (output_.terminal) {
      const std::string text = render(terminal_width(output_.fd));
      // Blanks over what is left of a longer previous line, never past it.
      const int pad = shown_ > text.size() ? static_cast<int>(shown_ - text.size()) : 0;
      std::fprintf(output_.stream, "\r%s%*s", text.c_str(), pad, "");
      if (pad > 0) std::fprintf(output_.stream, "\r%s", text.c_str());
      shown_ = std::max(text.size(), std::size_t{1});
    } else {
      std::fprintf(output_.stream, "%s\n", render(1 << 20).c_str());
    }
    std::fflush(output_.stream);
    if (wake_.wait_for(lock, output_.terminal ? output_.refresh : output_.log_interval,
                       [this] { return stop_; }))
      return;
  }
}

}  // namespace sfcv::cli

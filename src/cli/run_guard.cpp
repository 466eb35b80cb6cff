#include "cli/run_guard.hpp"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>

#include "cli/exit_code.hpp"
#include "cli/interrupt.hpp"
#include "engine/portfolio/portfolio_model_checker.hpp"

namespace sfcv::cli {

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr double kSanitizerSlowdown = 4;
#else
constexpr double kSanitizerSlowdown = 1;
#endif

using Clock = model::Budget::Clock;

/// CPU seconds used by this process, every thread together.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) / 1e9;
}

std::string held_text(std::uint64_t bytes) {
  return "memory limit reached (the process held " + std::to_string(bytes >> 20) + " MiB)";
}

}  // namespace

double backstop_grace_seconds(double timeout_seconds) {
  return (2.0 + 0.1 * timeout_seconds) * kSanitizerSlowdown;
}

double race_grace_seconds(double timeout_seconds) {
  return (0.5 + 0.02 * timeout_seconds) * kSanitizerSlowdown;
}

int end_here_if_racers_left_behind(int code) {
  if (engine::abandoned_racers() == 0) return code;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);  // _Exit does not flush C streams
  std::_Exit(code);
}

void rethrow_unless_racers_left_behind(std::exception_ptr error, std::ostream* json_out) {
  if (engine::abandoned_racers() == 0) std::rethrow_exception(error);
  end_here_if_racers_left_behind(
      run_with_exit_codes([&]() -> int { std::rethrow_exception(error); }, std::cerr, json_out));
  std::abort();  // not reached: a racer was left behind, so the call above ends the process
}

RunGuard::RunGuard(const LimitOptions& options, std::shared_ptr<std::atomic<bool>> cancel)
    : budget_(make_budget(options)) {
  budget_.cancel = cancel ? std::move(cancel) : std::make_shared<std::atomic<bool>>(false);
  watchdog_ = std::make_unique<MemoryWatchdog>(budget_.max_memory_bytes, budget_.cancel);
  if (!budget_.deadline && budget_.max_memory_bytes == 0) return;
  // The backstop: the phases read the clock and the cancel flag, and a run normally ends
  // within a second of its limit with what it has. One that does not (a phase that never
  // polls) is ended here, so that no input keeps sfcv past its limits.
  const double timeout =
      budget_.deadline ? std::chrono::duration<double>(*budget_.deadline - Clock::now()).count()
                       : 0.0;
  const auto grace = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(backstop_grace_seconds(timeout)));
  const auto deadline = budget_.deadline;
  const MemoryWatchdog* watchdog = watchdog_.get();
  // Past --memory the watchdog cancels the run, which then stops and prints what it has; a
  // phase that goes on allocating without reading the cancel flag is ended at 10 % over.
  const auto ceiling = static_cast<std::uint64_t>(static_cast<double>(budget_.max_memory_bytes) *
                                                  1.1 * kSanitizerSlowdown);
  // Past the deadline the grace is counted in CPU seconds of the process, as the limits are
  // measured: on a loaded machine a phase that does stop (a BuDDy reordering pass, a solver
  // freeing a deep unrolling) takes longer in wall time, and ending it there lost the report
  // of every verdict already decided (corpus 02 at load 25). A run that uses no CPU and does
  // not end (blocked) is ended at ten times the grace in wall time.
  const double grace_cpu = backstop_grace_seconds(timeout);
  backstop_ = std::jthread([deadline, grace, grace_cpu, watchdog, ceiling](std::stop_token stop) {
    std::optional<Clock::time_point> tripped_at;
    std::optional<double> cpu_at_deadline;
    while (!stop.stop_requested()) {
      const auto now = Clock::now();
      if (ceiling > 0)
        if (const auto held = resident_memory_bytes(); held > ceiling)
          end_process_now((held_text(held) + ", 10 % over the budget").c_str());
      if (deadline && now > *deadline) {
        if (!cpu_at_deadline) cpu_at_deadline = process_cpu_seconds();
        if (process_cpu_seconds() - *cpu_at_deadline > grace_cpu || now > *deadline + 10 * grace)
          end_process_now("time limit reached and the run did not stop by itself");
      }
      if (watchdog->tripped() && !tripped_at) tripped_at = now;
      if (tripped_at && now > *tripped_at + grace)
        end_process_now(
            (held_text(watchdog->seen_bytes()) + " and the run did not stop by itself").c_str());
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
}

RunGuard::~RunGuard() {
  // The backstop first: it reads the watchdog.
  if (backstop_.joinable()) {
    backstop_.request_stop();
    backstop_.join();
  }
}

std::string RunGuard::memory_text() const {
  return held_text(watchdog_->seen_bytes());
}

LimitReached RunGuard::reason(const LimitReached& e) const {
  if (watchdog_->tripped() && !interrupted()) {
    // The phases word a cancel "cancelled while loading the model": keep where it stopped.
    const std::string what = e.what();
    const auto at = what.find(" while ");
    return LimitReached(Limit::Memory, memory_text() + (at == std::string::npos ? " (" + what + ")"
                                                                                : what.substr(at)));
  }
  if (interrupted())
    return LimitReached(e.which(), std::string(interrupt_signal_name()) + ": " + e.what());
  return e;
}

void RunGuard::check(const char* while_doing) const {
  try {
    budget_.check_time(while_doing);
  } catch (const LimitReached& e) {
    throw reason(e);
  }
}

int report_limit(const LimitReached& e) {
  std::cerr << "sfcv: " << e.what() << "; verdict unknown\n";
  return kUnknown;
}

int run_limited(const LimitOptions& options, const std::function<int(const RunGuard&)>& body,
                std::shared_ptr<std::atomic<bool>> cancel) {
  const RunGuard guard(options, std::move(cancel));
  try {
    return body(guard);
  } catch (const LimitReached& e) {
    throw guard.reason(e);
  }
}

}  // namespace sfcv::cli

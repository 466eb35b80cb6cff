#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// The limits of one run, the same for every subcommand (docs/reliability.md, "Limits in every
// subcommand"): --timeout, --memory and --max-states (cli/run_limits.hpp) become one
// model::Budget whose deadline starts when the guard is made; the memory watchdog cancels that
// budget past --memory, so every phase that reads the clock stops there as well; and a
// backstop ends the process with exit 3 when a phase that does not read the clock (a parse, a
// library call, a renderer) runs well past the deadline or the memory budget.

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <thread>

#include "cli/memory_watchdog.hpp"
#include "cli/run_limits.hpp"
#include "model/budget.hpp"

namespace sfcv::cli {

class RunGuard {
 public:
  /// `cancel`: the flag the budget shares (check and equiv pass interrupt_flag(), so that a
  /// signal stops the run too); null: a flag of its own, raised only by the watchdog.
  explicit RunGuard(const LimitOptions& options,
                    std::shared_ptr<std::atomic<bool>> cancel = nullptr);
  ~RunGuard();
  RunGuard(const RunGuard&) = delete;
  RunGuard& operator=(const RunGuard&) = delete;

  const model::Budget& budget() const { return budget_; }
  const MemoryWatchdog& watchdog() const { return *watchdog_; }
  /// "memory limit reached (the process held N MiB)" once the watchdog has tripped.
  std::string memory_text() const;
  /// The limit that stopped the run, as a LimitReached: `e` itself, or the memory limit when
  /// the watchdog cancelled the run (the phases word a cancel as a time limit).
  LimitReached reason(const LimitReached& e) const;
  /// Throws reason(...) when the run is past its deadline or its memory; `while_doing` names
  /// the phase ("writing the export").
  void check(const char* while_doing) const;

 private:
  model::Budget budget_;
  std::unique_ptr<MemoryWatchdog> watchdog_;
  std::jthread backstop_;
};

/// Every subcommand's body runs here: `body` under the guard made from `options`; a limit
/// reached in any phase leaves as a LimitReached naming it (exit 3 through
/// run_with_exit_codes, after the body printed what it had).
int run_limited(const LimitOptions& options, const std::function<int(const RunGuard&)>& body,
                std::shared_ptr<std::atomic<bool>> cancel = nullptr);

/// For a subcommand that printed what it had (a JSON document among it): the limit's line on
/// standard error, as run_with_exit_codes words it, and exit 3.
int report_limit(const LimitReached& e);

/// How long past its deadline (or past --memory) a run may go before the backstop ends it:
/// 2 s + 10 % of the timeout (4x under AddressSanitizer, whose runs are several times slower),
/// in CPU seconds of the process past the deadline (ten times that in wall time).
double backstop_grace_seconds(double timeout_seconds);

/// How long past its deadline `--engine auto` waits for a racer that has not stopped before it
/// reports without it (engine::PortfolioOptions::abandon_after): 0.5 s + 2 % of the timeout,
/// well inside the backstop's grace, so that the report is out before the backstop would end
/// the process without one.
double race_grace_seconds(double timeout_seconds);

/// When the engines left a racer behind (engine::abandoned_racers()), it still reads the
/// system this run built: the process ends here with `code`, its report already printed, before
/// the system is freed. Otherwise returns `code`.
int end_here_if_racers_left_behind(int code);

/// For an error after the engines ran: rethrows `error` when no racer was left behind; else
/// prints it as run_with_exit_codes does (also as JSON on `json_out` when given) and ends the
/// process here with its exit code (end_here_if_racers_left_behind).
[[noreturn]] void rethrow_unless_racers_left_behind(std::exception_ptr error,
                                                    std::ostream* json_out);

}  // namespace sfcv::cli

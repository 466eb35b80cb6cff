#pragma once
// One budget for a whole run (--timeout, --memory, --max-states): a plain value passed down
// through the options of every phase, so that loading, building, exploring, the checks after
// exploration and the engine switch of --engine auto all share one deadline. The library reads
// no global state; it polls expired() every so many iterations and reports progress through
// the callback, which the CLI renders.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "model/errors.hpp"

namespace sfcv::model {

/// Where a long run is, for a progress line. Counters that a phase does not have stay 0.
struct Progress {
  std::uint64_t states = 0;
  std::uint64_t edges = 0;
  std::uint32_t depth = 0;
  double seconds = 0;       ///< since the phase started
  const char* phase = "";   ///< "explore", "checks", "build", ...
  std::uint64_t done = 0;   ///< checks (or items) done in this phase
  std::uint64_t total = 0;  ///< out of; 0 = not counted
  /// The engine reporting, when several race (--engine auto: "bdd", "ic3", "bmc"); "" alone.
  /// Phase "done": that engine has finished.
  const char* engine = "";
};

struct Budget {
  using Clock = std::chrono::steady_clock;

  std::optional<Clock::time_point> deadline;  ///< none: no time limit
  std::uint64_t max_states = 0;               ///< 0 = unlimited
  std::uint64_t max_memory_bytes = 0;         ///< 0 = unlimited
  /// Input valuations the explicit engine may enumerate for the successors of one state (0 =
  /// unlimited): a state past it stays unexpanded, Limit::Valuations. Set only by the probe of
  /// --engine auto (engine/auto_policy.hpp), which then hands the rest to the symbolic engines.
  std::uint64_t max_valuations = 0;
  std::function<void(const Progress&)> progress;  ///< may be empty
  /// Raised by another thread to stop the run (the portfolio of --engine auto cancels the
  /// engines that lost): every engine reads it where it reads the deadline, so a cancelled run
  /// ends as one past its deadline would, with unknown answers. Shared by copies; may be null.
  std::shared_ptr<std::atomic<bool>> cancel;

  /// A budget whose deadline is `seconds` from now (0 or less: no deadline).
  static Budget with_timeout(double seconds) {
    Budget b;
    b.set_timeout(seconds);
    return b;
  }
  void set_timeout(double seconds) {
    if (seconds > 0)
      deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(seconds));
    else
      deadline.reset();
  }

  bool has_deadline() const { return deadline.has_value(); }
  bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
  /// Past the deadline, or cancelled.
  bool expired() const { return cancelled() || (deadline && Clock::now() > *deadline); }
  /// Seconds until the deadline (at least a millisecond while one is set); 0 = no deadline.
  double seconds_left() const {
    if (!deadline) return 0;
    const double left = std::chrono::duration<double>(*deadline - Clock::now()).count();
    return left > 0.001 ? left : 0.001;
  }
  /// Throws LimitReached(Time) once the deadline has passed; `while_doing` completes
  /// "time limit reached while ...".
  void check_time(const char* while_doing) const {
    if (cancelled()) throw LimitReached(Limit::Time, std::string("cancelled while ") + while_doing);
    if (expired())
      throw LimitReached(Limit::Time, std::string("time limit reached while ") + while_doing);
  }
  void report(const Progress& p) const {
    if (progress) progress(p);
  }
};

/// Polls a budget's clock every `every` calls of tick() (reading the clock costs ~20 ns; loops
/// of cheap iterations should not pay it each time).
class BudgetPoll {
 public:
  explicit BudgetPoll(const Budget& budget, std::uint32_t every = 256)
      : budget_(&budget), every_(every) {}
  /// No budget (null): tick() never expires, so a pass that may run without a budget (a
  /// loader called from a test or a tool) polls the same way.
  explicit BudgetPoll(const Budget* budget, std::uint32_t every = 256)
      : budget_(budget), every_(every) {}
  /// True once the deadline has passed (checked every `every` calls).
  bool tick() {
    if (!budget_ || ++count_ < every_) return false;
    count_ = 0;
    return budget_->expired();
  }
  void tick_or_throw(const char* while_doing) {
    if (tick()) budget_->check_time(while_doing);
  }

 private:
  const Budget* budget_;
  std::uint32_t every_;
  std::uint32_t count_ = 0;
};

}  // namespace sfcv::model

#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// SIGINT and SIGTERM (docs/reliability.md, "Interruption"). The handler only raises an atomic
// flag or ends the process; it never runs library code:
// - inside an InterruptScope (sfcv check), the first signal raises the flag that the run's
//   budget reads as its cancel flag (model::Budget::cancel), so the engines stop as at their
//   deadline and the normal reporting path prints and writes what was decided;
// - otherwise (other subcommands, or a second signal), the process ends at once with exit 3
//   after removing the temporary file being written (output_file.hpp), so no half-written file
//   is left behind and no target is truncated.

#include <atomic>
#include <memory>

namespace sfcv::cli {

/// Installs the handlers (once per process; a signal ignored at start stays ignored).
void install_interrupt_handlers();

/// The flag the first signal raises inside an InterruptScope, shaped for model::Budget::cancel.
std::shared_ptr<std::atomic<bool>> interrupt_flag();

/// Whether a signal was received inside an InterruptScope.
bool interrupted();
/// "SIGINT" or "SIGTERM" once interrupted(), else "".
const char* interrupt_signal_name();

/// While alive, the first SIGINT/SIGTERM stops the run through interrupt_flag() instead of
/// ending the process.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

/// The temporary file being written, removed by the handler when a signal ends the process.
/// `path` must stay valid and unchanged until release_temporary_file(); mkstemp may fill in its
/// XXXXXX after the call (the handler reads it only when it runs).
void guard_temporary_file(char* path);
/// Ends the process at once with exit 3 (cli/run_guard.hpp's backstop): removes the temporary
/// file being written, kills the outside tool running (engine/external), says `why` on
/// standard error.
[[noreturn]] void end_process_now(const char* why);
void release_temporary_file();

}  // namespace sfcv::cli

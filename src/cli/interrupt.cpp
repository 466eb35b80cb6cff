#include "cli/interrupt.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>

#include "cli/exit_code.hpp"
#include "engine/external/external_tool.hpp"

namespace sfcv::cli {

namespace {

// Everything the handler touches is lock-free and async-signal-safe to read or store.
std::atomic<bool> g_flag{false};
std::atomic<int> g_signal{0};
std::atomic<int> g_scopes{0};
std::atomic<char*> g_temporary{nullptr};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free &&
              std::atomic<char*>::is_always_lock_free);

void say(const char* text) {
  // The result is ignored: nothing can be done about a failing standard error here.
  [[maybe_unused]] const auto written = ::write(2, text, std::strlen(text));
}

void on_signal(int sig) {
  int expected = 0;
  if (g_scopes.load() > 0 && g_signal.compare_exchange_strong(expected, sig)) {
    g_flag.store(true);
    say(sig == SIGINT ? "\nsfcv: SIGINT: stopping; the answers decided so far follow (again to "
                        "quit at once)\n"
                      : "\nsfcv: SIGTERM: stopping; the answers decided so far follow\n");
    return;
  }
  if (char* temporary = g_temporary.load()) ::unlink(temporary);
  engine::kill_running_tools();
  say(sig == SIGINT ? "\nsfcv: SIGINT: stopped; verdict unknown\n"
                    : "\nsfcv: SIGTERM: stopped; verdict unknown\n");
  ::_exit(kUnknown);
}

}  // namespace

void install_interrupt_handlers() {
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and writes in progress go on
    ::sigaction(sig, &action, nullptr);
  }
}

std::shared_ptr<std::atomic<bool>> interrupt_flag() {
  // Aliasing constructor: a shared_ptr to the static flag that owns nothing.
  return std::shared_ptr<std::atomic<bool>>(std::shared_ptr<void>(), &g_flag);
}

bool interrupted() {
  // The signal, not the flag: the memory watchdog raises the flag too (memory_watchdog.hpp).
  return g_signal.load() != 0;
}

const char* interrupt_signal_name() {
  switch (g_signal.load()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "";
  }
}

InterruptScope::InterruptScope() {
  g_scopes.fetch_add(1);
}

InterruptScope::~InterruptScope() {
  g_scopes.fetch_sub(1);
}

void guard_temporary_file(char* path) {
  g_temporary.store(path);
}

void end_process_now(const char* why) {
  if (char* temporary = g_temporary.load()) ::unlink(temporary);
  engine::kill_running_tools();
  say("sfcv: ");
  say(why);
  say("; stopped; verdict unknown\n");
  ::_exit(kUnknown);
}

void release_temporary_file() {
  g_temporary.store(nullptr);
}

}  // namespace sfcv::cli

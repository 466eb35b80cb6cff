#include "engine/external/external_tool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <thread>

namespace sfcv::engine {

namespace {

// The process groups of the tools running now (several engines may run one each under
// --engine auto); 0 = a free slot. Lock-free, so that a signal handler may read them.
constexpr std::size_t kToolSlots = 16;
std::atomic<pid_t> g_tool_groups[kToolSlots];
static_assert(std::atomic<pid_t>::is_always_lock_free);

std::size_t register_tool(pid_t group) {
  for (std::size_t i = 0; i < kToolSlots; ++i) {
    pid_t expected = 0;
    if (g_tool_groups[i].compare_exchange_strong(expected, group)) return i;
  }
  return kToolSlots;  // all taken: the tool still dies at its timeout and with sfcv
}

void release_tool(std::size_t slot) {
  if (slot < kToolSlots) g_tool_groups[slot].store(0);
}

}  // namespace

void kill_running_tools() noexcept {
  for (auto& group : g_tool_groups)
    if (const pid_t g = group.load(); g > 0) ::kill(-g, SIGKILL);
}

std::optional<std::string> find_on_path(const std::vector<std::string>& names) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  for (const auto& name : names) {
    std::string dirs = path;
    std::size_t start = 0;
    while (start <= dirs.size()) {
      const auto end = dirs.find(':', start);
      const std::string dir =
          dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
      if (!dir.empty()) {
        const auto candidate = std::filesystem::path(dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
      }
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  return std::nullopt;
}

ToolRun run_tool(const std::vector<std::string>& argv, const std::string& working_dir,
                 double timeout_seconds, const std::atomic<bool>* cancel) {
  if (argv.empty()) throw std::invalid_argument("run_tool: empty command");
  const auto log = std::filesystem::path(working_dir) / ".tool-output";
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("run_tool: fork failed");
  if (pid == 0) {
    if (::chdir(working_dir.c_str()) != 0) ::_exit(127);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) ::_exit(127);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) ::dup2(null_in, 0);
    ::setpgid(0, 0);
    // The tool dies with sfcv: killed sfcv once left graphviz's dot running for minutes. (Its
    // own process group keeps it out of a terminal's Ctrl-C, which sfcv handles itself.)
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  // The parent sets the group too, so that a kill right after fork reaches it.
  ::setpgid(pid, pid);
  const std::size_t slot = register_tool(pid);
  ToolRun run;
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if ((timeout_seconds > 0 && elapsed > timeout_seconds) ||
        (cancel && cancel->load(std::memory_order_relaxed))) {
      ::kill(-pid, SIGKILL);
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      run.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // The group may outlive its leader (a shell script's children): it ends with the tool.
  ::kill(-pid, SIGKILL);
  release_tool(slot);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (FILE* f = std::fopen(log.c_str(), "rb")) {
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) run.output.append(buf, n);
    std::fclose(f);
  }
  return run;
}

TempDir::TempDir() {
  std::string tmpl = (std::filesystem::temp_directory_path() / "sfcv-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary directory");
  path_ = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace sfcv::engine

#pragma once
// Running an outside checker (ABC, Spin, NuSMV) as a child process, with a time limit.

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace sfcv::engine {

/// Absolute path of the first of `names` found on PATH, or nullopt.
std::optional<std::string> find_on_path(const std::vector<std::string>& names);

struct ToolRun {
  int exit_code = -1;
  bool timed_out = false;
  std::string output;  ///< standard output and standard error, interleaved
};

/// Runs `argv` in `working_dir` (argv[0] an absolute path) in a process group of its own,
/// killing the group after `timeout_seconds` (0 = no limit) or once `cancel` (the run's
/// model::Budget::cancel, may be null) is raised.
ToolRun run_tool(const std::vector<std::string>& argv, const std::string& working_dir,
                 double timeout_seconds, const std::atomic<bool>* cancel = nullptr);

/// Kills the process group of every tool running now (async-signal-safe: the CLI calls it
/// from its signal handler and from its backstop before it ends the process).
void kill_running_tools() noexcept;

/// A fresh private directory under the system's temporary directory, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace sfcv::engine

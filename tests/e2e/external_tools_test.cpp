// External tools die with sfcv: a killed sfcv once left graphviz's `dot` laying out a
// 20,000-step chart for minutes. A stand-in `dot` first on PATH records its pid and sleeps;
// sfcv is killed with SIGKILL while it waits, and the stand-in must be gone.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>

#include "support/sfcv_test.hpp"

namespace {

namespace fs = std::filesystem;

bool alive(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_field, comm, state;
  if (!(stat >> pid_field >> comm >> state)) return false;
  return state != "Z" && state != "X";  // a zombie has exited already
}

TEST(ExternalTools, AKilledSfcvTakesItsGraphvizChildWithIt) {
  const fs::path dir = fs::temp_directory_path() / ("sfcv-fake-dot-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path pid_file = dir / "dot.pid";
  {
    std::ofstream dot(dir / "dot");
    dot << "#!/bin/sh\necho $$ > '" << pid_file.string() << "'\nexec sleep 600\n";
  }
  fs::permissions(dir / "dot", fs::perms::owner_all);
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const std::string html = (dir / "r.html").string();
  const std::string path = dir.string() + ":" + std::getenv("PATH");

  const pid_t sfcv = fork();
  ASSERT_GE(sfcv, 0);
  if (sfcv == 0) {
    setenv("PATH", path.c_str(), 1);
    execl(SFCV_BINARY, SFCV_BINARY, "check", chart.c_str(), "--checks", "reachable", "--html",
          html.c_str(), "--quiet", static_cast<char*>(nullptr));
    _exit(127);
  }
  pid_t dot = 0;
  for (int i = 0; i < 600 && dot == 0; ++i) {  // up to 60 s on a loaded machine
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::ifstream f(pid_file);
    if (!(f >> dot)) dot = 0;
  }
  kill(sfcv, SIGKILL);
  int status = 0;
  waitpid(sfcv, &status, 0);
  ASSERT_GT(dot, 0) << "the stand-in dot never started";
  bool gone = false;
  for (int i = 0; i < 50 && !gone; ++i) {
    gone = !alive(dot);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!gone) kill(dot, SIGKILL);
  EXPECT_TRUE(gone) << "dot (pid " << dot << ") outlived the killed sfcv";
  fs::remove_all(dir);
}

/// A stand-in tool named `name` in a fresh directory: a shell that records its pid, starts a
/// `sleep` child (a grandchild of sfcv, outside PR_SET_PDEATHSIG's reach) and waits for it.
struct SlowTool {
  fs::path dir;
  fs::path shell_pid, sleep_pid;
  std::string path;  ///< PATH with the stand-in first
  explicit SlowTool(const std::string& name) {
    dir = fs::temp_directory_path() /
          ("sfcv-slow-" + name + "-" + std::to_string(getpid()) + "-" + std::to_string(rand()));
    fs::create_directories(dir);
    shell_pid = dir / "shell.pid";
    sleep_pid = dir / "sleep.pid";
    {
      std::ofstream tool(dir / name);
      tool << "#!/bin/sh\necho $$ > '" << shell_pid.string() << "'\nsleep 600 &\necho $! > '"
           << sleep_pid.string() << "'\nwait\n";
    }
    fs::permissions(dir / name, fs::perms::owner_all);
    path = dir.string() + ":" + std::getenv("PATH");
  }
  ~SlowTool() {
    for (const auto& f : {shell_pid, sleep_pid}) {
      std::ifstream in(f);
      pid_t pid = 0;
      if (in >> pid && pid > 0 && alive(pid)) kill(pid, SIGKILL);
    }
    fs::remove_all(dir);
  }
  bool started() const { return fs::exists(sleep_pid) && fs::file_size(sleep_pid) > 0; }
  /// Whether the shell and its sleep are both gone (waiting up to 2 s for the kernel).
  bool gone() const {
    for (int i = 0; i < 20; ++i) {
      bool any = false;
      for (const auto& f : {shell_pid, sleep_pid}) {
        std::ifstream in(f);
        pid_t pid = 0;
        if (in >> pid && pid > 0) any = any || alive(pid);
      }
      if (!any) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }
};

/// `sfcv <args>` with PATH set to `path`; its exit code and wall time.
std::pair<int, double> run_with_path(const std::string& path, const std::string& args) {
  const auto start = std::chrono::steady_clock::now();
  const std::string cmd = "PATH='" + path + "' '" + std::string(SFCV_BINARY) + "' " + args +
                          " >/dev/null 2>&1 </dev/null";
  const int status = std::system(cmd.c_str());
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, wall};
}

TEST(ExternalTools, GraphvizIsKilledWithItsChildrenAtTheRunsDeadline) {
  // The HTML report's layouts run under what is left of --timeout (plus half a second): the
  // stand-in dot would sleep 600 s; its process group (the shell and its sleep) is killed.
  const SlowTool dot("dot");
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const std::string html = (dot.dir / "r.html").string();
  const auto [code, wall] =
      run_with_path(dot.path, "check '" + chart +
                                  "' --checks reachable --timeout 2 --quiet --html '" + html + "'");
  EXPECT_TRUE(dot.started()) << "the stand-in dot never started";
  EXPECT_TRUE(code == 0 || code == 3) << code;
  EXPECT_LT(wall, 2 + 1 + 0.1 + 5) << "the run went past its deadline";  // 5 s: a loaded CI
  EXPECT_TRUE(dot.gone()) << "dot or its child outlived the run's deadline";
  EXPECT_TRUE(fs::exists(html));
}

TEST(ExternalTools, NusmvIsKilledWithItsChildrenAtTheRunsDeadline) {
  const SlowTool nusmv("NuSMV");
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const auto [code, wall] =
      run_with_path(nusmv.path, "check '" + chart +
                                    "' --engine nusmv --checks none --ctl 'EF TRUE' "
                                    "--timeout 2 --quiet");
  EXPECT_TRUE(nusmv.started()) << "the stand-in NuSMV never started";
  EXPECT_EQ(code, 3) << "NuSMV's time limit leaves the property unknown";
  EXPECT_LT(wall, 2 + 1 + 0.1 + 5);
  EXPECT_TRUE(nusmv.gone()) << "NuSMV or its child outlived the run's deadline";
}

}  // namespace

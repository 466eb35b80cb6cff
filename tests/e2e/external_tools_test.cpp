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

}  // namespace

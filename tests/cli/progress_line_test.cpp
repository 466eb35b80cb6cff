// The progress line on a terminal (issue 48): never wider than the terminal, whose width is
// asked of the terminal itself; each engine of --engine auto's race shown with its own
// progress, "done" only for an engine that has finished; a long step shows its time.

#include "cli/progress_line.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace sfcv::cli {
namespace {

/// A pseudo-terminal of `columns` columns: the program writes to `slave`, the test reads `master`.
struct Pty {
  int master = -1, slave = -1;
  explicit Pty(unsigned short columns) {
    struct winsize size {};
    size.ws_col = columns;
    size.ws_row = 24;
    if (::openpty(&master, &slave, nullptr, nullptr, &size) != 0) master = slave = -1;
  }
  ~Pty() {
    if (master >= 0) ::close(master);
    if (slave >= 0) ::close(slave);
  }
  std::string read_all() const {
    std::string out;
    ::fcntl(master, F_SETFL, O_NONBLOCK);
    char buf[4096];
    for (;;) {
      const auto n = ::read(master, buf, sizeof buf);
      if (n <= 0) break;
      out.append(buf, static_cast<std::size_t>(n));
    }
    return out;
  }
};

model::Progress racer(const char* engine, const char* phase, std::uint32_t depth,
                      std::uint64_t states = 0) {
  model::Progress p;
  p.engine = engine;
  p.phase = phase;
  p.depth = depth;
  p.states = states;
  return p;
}

TEST(ProgressLine, TheWidthIsAskedOfTheTerminal) {
  const Pty pty(80);
  ASSERT_GE(pty.slave, 0) << "no pseudo-terminal";
  EXPECT_EQ(terminal_width(pty.slave), 80);
  const Pty narrow(52);
  EXPECT_EQ(terminal_width(narrow.slave), 52);
  // Not a terminal: $COLUMNS, else 80.
  const int null = ::open("/dev/null", O_WRONLY);
  ::setenv("COLUMNS", "123", 1);
  EXPECT_EQ(terminal_width(null), 123);
  ::unsetenv("COLUMNS");
  EXPECT_EQ(terminal_width(null), 80);
  ::close(null);
}

TEST(ProgressLine, OnAnEightyColumnTerminalNoLineWrapsOrScrolls) {
  const Pty pty(80);
  ASSERT_GE(pty.slave, 0) << "no pseudo-terminal";
  std::FILE* out = ::fdopen(::dup(pty.slave), "w");
  ASSERT_NE(out, nullptr);
  {
    ProgressOutput o;
    o.stream = out;
    o.terminal = true;
    o.fd = pty.slave;
    o.quiet_start = std::chrono::milliseconds(0);
    o.refresh = std::chrono::milliseconds(20);
    ProgressLine line(true, o);
    line.phase("explore");
    const auto report = line.callback();
    // Long enough to pass 80 columns: huge counts, then three racers.
    model::Progress p;
    p.phase = "explore (bdd)";
    p.states = 35184372088832ULL;
    p.edges = 98765432109876ULL;
    p.depth = 12345;
    report(p);
    std::this_thread::sleep_for(std::chrono::milliseconds(80));
    report(racer("bdd", "explore (bdd)", 31, 12036255745ULL));
    report(racer("ic3", "ic3", 7));
    report(racer("bmc", "bmc", 41));
    std::this_thread::sleep_for(std::chrono::milliseconds(80));
  }
  std::fclose(out);
  const auto text = pty.read_all();
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.find('\n'), std::string::npos) << "a refreshing line never starts a new line";
  // Every refresh starts at column 0 and stays within 79 columns.
  std::size_t from = 0, refreshes = 0;
  while (from < text.size()) {
    auto to = text.find('\r', from);
    if (to == std::string::npos) to = text.size();
    EXPECT_LE(to - from, 79u) << "[" << text.substr(from, to - from) << "]";
    from = to + 1;
    ++refreshes;
  }
  EXPECT_GT(refreshes, 2u);
  EXPECT_NE(text.find("race:"), std::string::npos) << text;
}

TEST(ProgressLine, EachRacerShowsItsOwnProgressAndOnlyFinishedOnesSayDone) {
  ProgressOutput o;
  o.stream = stderr;
  o.quiet_start = std::chrono::hours(1);  // prints nothing: the test reads line()
  ProgressLine line(true, o);
  line.phase("explore");
  const auto report = line.callback();
  report(racer("bdd", "explore (bdd)", 12, 163594241));
  report(racer("ic3", "ic3", 7));
  report(racer("bmc", "bmc", 41));
  auto text = line.line(200);
  EXPECT_NE(text.find("bdd depth 12, 163,594,241 st"), std::string::npos) << text;
  EXPECT_NE(text.find("ic3 frame 7"), std::string::npos) << text;
  EXPECT_NE(text.find("bmc depth 41"), std::string::npos) << text;
  EXPECT_EQ(text.find("done"), std::string::npos) << text;
  // The BDD engine has run all its checks, IC3 still works: not "10/10 done" for the run.
  model::Progress checks = racer("bdd", "standard checks", 0);
  checks.done = 10;
  checks.total = 10;
  report(checks);
  model::Progress finished = racer("bdd", "done", 0);
  report(finished);
  text = line.line(200);
  EXPECT_NE(text.find("bdd done"), std::string::npos) << text;
  EXPECT_NE(text.find("ic3 frame 7"), std::string::npos) << text;
  EXPECT_EQ(text.find("ic3 done"), std::string::npos) << text;
  // Cut to the width, the last column left free.
  EXPECT_LE(line.line(40).size(), 39u);
}

TEST(ProgressLine, HugeCountsAreReadable) {
  ProgressOutput o;
  o.quiet_start = std::chrono::hours(1);
  ProgressLine line(true, o);
  line.phase("explore");
  model::Progress p;
  p.phase = "explore (bdd)";
  p.states = 35184372088832ULL;
  p.depth = 0;
  line.callback()(p);
  const auto text = line.line(200);
  EXPECT_NE(text.find("3.5e+13 states"), std::string::npos) << text;
  EXPECT_EQ(text.find("35184372088832"), std::string::npos) << text;
}

}  // namespace
}  // namespace sfcv::cli

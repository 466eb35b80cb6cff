// Output files and interruption (issue 53, item 7; docs/reliability.md, "Output files" and
// "Interruption"): every output path is checked before the run (exit 2 at once, the file and
// the option named), files are replaced atomically (no half file, an old report intact when the
// run fails before writing), write errors are exit 2 naming the file, and SIGINT/SIGTERM during
// `sfcv check` prints and writes the answers decided so far, the rest unknown ("interrupted").

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/sfcv_test.hpp"

namespace {

namespace fs = std::filesystem;
using sfcv::test::run_sfcv;
using sfcv::test::source_path;
using sfcv::test::write_temp;

const std::string kPistons = "'" + source_path("examples/pistons/pistons.g7") + "'";
const std::string kPlant = "'" + source_path("examples/chemical_plant/chemical_plant.st") + "'";
const std::string kPlantTrace =
    "'" + source_path("examples/chemical_plant/v2_v4_overlap.csv") + "'";

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

/// A fresh empty directory, removed with the test.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("sfcv-out-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  /// The names of the files in it (a temporary file left behind shows here).
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(path_)) out.push_back(e.path().filename());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  fs::path path_;
};

/// A chart whose explicit exploration takes minutes (2^26 + 1 states) while its file loads in
/// milliseconds: a run that reaches the exploration is easy to tell from one refused at once.
const std::string& large_chart() {
  static const std::string path = [] {
    const std::string p = write_temp("", ".st");
    const std::string cmd = std::string("'") + SFCV_GEN + "' parallel 26 --selector -o '" + p + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return p;
  }();
  return path;
}

struct Timed {
  sfcv::test::RunResult run;
  double seconds = 0;
};

Timed timed_run(const std::string& args) {
  const auto t0 = std::chrono::steady_clock::now();
  Timed t;
  t.run = run_sfcv(args);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

TEST(OutputFiles, MissingDirectoryIsRefusedBeforeTheRunForEveryOutputOption) {
  // Before: `--junit /nonexistent/dir/r.xml` ran the whole check (15 s on a large model), then
  // exited 2 with nothing on standard output, hiding a violation.
  const std::string big = "'" + large_chart() + "'";
  const std::string missing = "/nonexistent-sfcv-dir/sub/out.file";
  TempDir dir;
  const std::string result_json = dir / "result.json";
  const auto saved = run_sfcv("check " + kPistons + " --json --quiet");
  ASSERT_EQ(saved.exit_code, 0) << saved.err;
  std::ofstream(result_json) << saved.out;
  struct Case {
    std::string command, option;
  };
  const std::vector<Case> cases = {
      {"check " + big + " --engine explicit --ctl 'AG !(A0 & B0)'", "--junit"},
      {"check " + big + " --engine explicit --ctl 'AG !(A0 & B0)'", "--sarif"},
      {"check " + big + " --engine explicit --ctl 'AG !(A0 & B0)'", "--html"},
      {"check " + big + " --engine explicit --ctl 'AG !(A0 & B0)'", "--trace-file"},
      {"check " + big + " --engine ic3 --ctl 'AG !(A0 & B0)'", "--certificate"},
      {"export " + kPlant + " --to nusmv", "-o"},
      {"rsg " + big, "--dot"},
      {"rsg " + big, "--dot-states"},
      {"simulate " + kPlant + " --inputs " + kPlantTrace, "--vcd"},
      {"query " + big + " Y0", "--html"},
      {"report '" + result_json + "'", "--html"},
  };
  for (const auto& c : cases) {
    const auto t = timed_run(c.command + " " + c.option + " " + missing);
    SCOPED_TRACE(c.command + " " + c.option);
    EXPECT_EQ(t.run.exit_code, 2) << t.run.out << t.run.err;
    EXPECT_NE(t.run.err.find(c.option + " " + missing), std::string::npos) << t.run.err;
    EXPECT_NE(t.run.err.find("does not exist"), std::string::npos) << t.run.err;
    EXPECT_LT(t.seconds, 5.0);  // the exploration of the large chart takes minutes
  }
}

TEST(OutputFiles, DirectoryAndSharedPathsAreRefusedBeforeTheRun) {
  TempDir dir;
  const std::string big = "'" + large_chart() + "'";
  auto t = timed_run("check " + big + " --engine explicit --ctl 'AG !(A0 & B0)' --junit '" +
                     dir.path().string() + "'");
  EXPECT_EQ(t.run.exit_code, 2) << t.run.err;
  EXPECT_NE(t.run.err.find("--junit " + dir.path().string() + ": is a directory"),
            std::string::npos)
      << t.run.err;
  EXPECT_LT(t.seconds, 5.0);
  // Two reports into one file: one would silently replace the other.
  t = timed_run("check " + big + " --engine explicit --ctl 'AG !(A0 & B0)' --junit '" +
                (dir / "r") + "' --sarif '" + (dir / "r") + "'");
  EXPECT_EQ(t.run.exit_code, 2) << t.run.err;
  EXPECT_NE(t.run.err.find("--sarif " + (dir / "r") + ": is also the file of --junit"),
            std::string::npos)
      << t.run.err;
  EXPECT_LT(t.seconds, 5.0);
  // Relative paths naming one new file in the working directory.
  const auto same = run_sfcv("check " + kPistons + " --junit r.xml --sarif ./r.xml");
  EXPECT_EQ(same.exit_code, 2) << same.err;
  EXPECT_NE(same.err.find("--sarif ./r.xml: is also the file of --junit"), std::string::npos)
      << same.err;
  EXPECT_FALSE(fs::exists("r.xml"));
  // A missing directory in the middle of the path, and a file used as a directory.
  std::ofstream(dir / "plain") << "x";
  const auto r = run_sfcv("export " + kPlant + " --to nusmv -o '" + (dir / "plain/m.smv") + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is not a directory"), std::string::npos) << r.err;
  EXPECT_EQ(dir.names(), std::vector<std::string>{"plain"});
}

TEST(OutputFiles, WriteErrorsAreExitTwoNamingTheFile) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  // Before: `export -o /dev/full` exited 0 with nothing written.
  auto r = run_sfcv("export " + kPlant + " --to nusmv -o /dev/full");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("-o /dev/full"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left"), std::string::npos) << r.err;
  // A report that cannot be written: the verdicts are still printed, then exit 2.
  r = run_sfcv("check " + kPlant + " --checks none --ctl 'AG !(V2 & V4)' --junit /dev/full");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.out.find("violated"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("--junit /dev/full"), std::string::npos) << r.err;
  // Standard output itself (run_sfcv redirects it: this runs the shell directly).
  TempDir dir;
  const std::string err = dir / "err";
  for (const std::string& command :
       {"check " + kPlant + " --checks none --ctl 'AG !(V2 & V4)'",
        "export " + kPlant + " --to nusmv", "rsg " + kPistons, "info " + kPistons}) {
    const std::string shell =
        std::string("'") + SFCV_BINARY + "' " + command + " >/dev/full 2>'" + err + "'";
    const int status = std::system(shell.c_str());
    EXPECT_TRUE(WIFEXITED(status)) << command;
    EXPECT_EQ(WEXITSTATUS(status), 2) << command << "\n" << slurp(err);
    EXPECT_NE(slurp(err).find("cannot write standard output"), std::string::npos) << slurp(err);
  }
}

TEST(OutputFiles, SpecialFilesAreWrittenDirectly) {
  // Standard output by name or as "-": the export is the output, nothing renamed over /dev.
  const auto plain = run_sfcv("export " + kPlant + " --to nusmv");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  for (const std::string target : {"-", "/dev/stdout"}) {
    const auto r = run_sfcv("export " + kPlant + " --to nusmv -o " + target);
    EXPECT_EQ(r.exit_code, 0) << target << "\n" << r.err;
    EXPECT_EQ(r.out, plain.out) << target;
  }
  // A FIFO: read while sfcv writes it.
  TempDir dir;
  const std::string fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string read_back;
  std::thread reader([&] { read_back = slurp(fifo); });
  const auto r = run_sfcv("export " + kPlant + " --to nusmv -o '" + fifo + "'");
  reader.join();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_back, plain.out);
  EXPECT_EQ(run_sfcv("export " + kPlant + " --to nusmv -o /dev/null").exit_code, 0);
}

TEST(OutputFiles, ReportsAreReplacedWholeAndKeptWhenTheRunFailsFirst) {
  TempDir dir;
  const std::string junit = dir / "r.xml", sarif = dir / "r.sarif", exported = dir / "m.smv";
  std::ofstream(junit) << "OLD";
  std::ofstream(sarif) << "OLD";
  std::ofstream(exported) << "OLD";
  ::chmod(sarif.c_str(), 0640);
  // A run that fails before writing (a property naming nothing): the old files are intact,
  // not truncated as an early open would have left them.
  auto r = run_sfcv("check " + kPlant + " --ctl 'AG !nosuchstep' --junit '" + junit +
                    "' --sarif '" + sarif + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(slurp(junit), "OLD");
  EXPECT_EQ(slurp(sarif), "OLD");
  r = run_sfcv("export " + kPlant + " --to nusmv --ctl 'AG !nosuchstep' -o '" + exported + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(slurp(exported), "OLD");
  // A run that succeeds replaces them whole, keeps their mode, leaves no temporary file.
  r = run_sfcv("check " + kPlant + " --checks none --ctl 'AG !(V2 & V4)' --junit '" + junit +
               "' --sarif '" + sarif + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_file(junit.c_str())) << slurp(junit);
  EXPECT_TRUE(nlohmann::json::accept(slurp(sarif)));
  struct stat st {};
  ASSERT_EQ(::stat(sarif.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_EQ(run_sfcv("export " + kPlant + " --to nusmv -o '" + exported + "'").exit_code, 0);
  EXPECT_NE(slurp(exported).find("MODULE main"), std::string::npos);
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"m.smv", "r.sarif", "r.xml"}));
}

TEST(OutputFiles, AnEngineStoppedByALimitStillReportsEveryQuestion) {
  // 199 nested enclosing steps: building the SAT engines' circuit takes minutes, so --timeout 2
  // stops IC3 before it has a report. Before, the run ended with "time limit reached while
  // building the circuit" on standard error, no verdict printed and no report written.
  std::string text = "project nest;\ninput a;\noutput o;\n";
  for (int i = 0; i < 199; ++i) {
    text += "grafcet G" + std::to_string(i) + " {\n";
    text += i == 0 ? "  step 1 initial;\n" : "  step 1 linked;\n";
    text += i + 1 < 199 ? "  step 2 encloses G" + std::to_string(i + 1) + ";\n" : "  step 2;\n";
    text += "  transition t1: 1 -> 2 when a;\n  transition t2: 2 -> 1 when !a;\n}\n";
  }
  const auto nest = write_temp(text, ".g7");
  TempDir dir;
  const std::string junit = dir / "r.xml";
  const auto t =
      timed_run("check " + nest + " --engine ic3 --timeout 2 --checks reachable " +
                "--ctl 'AG !(G0.X1 & G0.X2)' --json --trace none --junit '" + junit + "'");
  EXPECT_EQ(t.run.exit_code, 3) << t.run.out << t.run.err;
  EXPECT_LT(t.seconds, 15.0);
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(t.run.out)) << t.run.out << t.run.err;
  EXPECT_EQ(j.at("limit"), "time");
  ASSERT_EQ(j.at("properties").size(), 2u) << j.dump(2);
  for (const auto& p : j["properties"]) {
    EXPECT_EQ(p.at("verdict"), "unknown") << p.dump();
    EXPECT_NE(p.dump().find("time limit reached"), std::string::npos) << p.dump();
  }
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(junit.c_str())) << slurp(junit);
  EXPECT_EQ(doc.select_nodes("//testcase/error").size(), 2u) << slurp(junit);
}

/// `sfcv <args>` started in the background with its streams in files of `dir`.
class Background {
 public:
  Background(const std::string& args, const TempDir& dir)
      : out_(dir / "stdout"), err_(dir / "stderr") {
    const std::string cmd = std::string("exec '") + SFCV_BINARY + "' " + args + " >'" + out_ +
                            "' 2>'" + err_ + "' </dev/null";
    pid_ = ::fork();
    if (pid_ == 0) {
      ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
  }
  /// Waits until standard error shows `text` (a progress line), at most `seconds`.
  bool wait_for_err(const std::string& text, double seconds) const {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
      if (slurp(err_).find(text) != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }
  void signal(int sig) const { ::kill(pid_, sig); }
  /// The exit code (128 + the signal when killed by one), waiting at most `seconds`.
  int wait(double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (::waitpid(pid_, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > until) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  std::string out() const { return slurp(out_); }
  std::string err() const { return slurp(err_); }

 private:
  std::string out_, err_;
  pid_t pid_ = -1;
};

class Interrupt : public ::testing::TestWithParam<int> {};

TEST_P(Interrupt, CheckPrintsAndWritesWhatWasDecided) {
  // Before: Ctrl-C printed nothing at all, though checks were decided.
  // AG !B0 is violated two cycles in; AG !(A0 & B0) holds but needs all 2^26 + 1 states.
  const int sig = GetParam();
  TempDir dir;
  const std::string junit = dir / "r.xml", sarif = dir / "r.sarif", html = dir / "r.html";
  Background run("check '" + large_chart() +
                     "' --engine explicit --checks none --ctl 'AG !B0' --ctl 'AG !(A0 & B0)' "
                     "--json --trace none --junit '" +
                     junit + "' --sarif '" + sarif + "' --html '" + html + "'",
                 dir);
  // The progress line (after ~2 s) shows the exploration under way.
  ASSERT_TRUE(run.wait_for_err("explore", 60)) << run.err();
  run.signal(sig);
  const int code = run.wait(60);
  // The documented code: the worst decided verdict (here violated, 1); else 3 (unknown).
  EXPECT_EQ(code, 1) << run.out() << run.err();
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(run.out())) << run.out() << run.err();
  EXPECT_EQ(j.at("limit"), "interrupted") << j.dump(2);
  ASSERT_EQ(j.at("properties").size(), 2u);
  EXPECT_EQ(j["properties"][0]["verdict"], "violated");
  EXPECT_EQ(j["properties"][1]["verdict"], "unknown");
  const std::string sig_name = sig == SIGINT ? "SIGINT" : "SIGTERM";
  EXPECT_NE(j["properties"][1].dump().find("interrupted by " + sig_name), std::string::npos)
      << j["properties"][1].dump();
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(junit.c_str())) << slurp(junit);
  EXPECT_EQ(doc.select_nodes("//testcase/failure").size(), 1u) << slurp(junit);
  EXPECT_EQ(doc.select_nodes("//testcase/error").size(), 1u) << slurp(junit);
  EXPECT_TRUE(nlohmann::json::accept(slurp(sarif)));
  EXPECT_NE(slurp(html).find("</html>"), std::string::npos);
  EXPECT_EQ(dir.names(),
            (std::vector<std::string>{"r.html", "r.sarif", "r.xml", "stderr", "stdout"}));
}

TEST_P(Interrupt, CheckWithNothingDecidedIsUnknown) {
  const int sig = GetParam();
  TempDir dir;
  const std::string junit = dir / "r.xml";
  Background run("check '" + large_chart() +
                     "' --engine explicit --checks none --ctl 'AG !(A0 & B0)' --junit '" + junit +
                     "'",
                 dir);
  ASSERT_TRUE(run.wait_for_err("explore", 60)) << run.err();
  run.signal(sig);
  EXPECT_EQ(run.wait(60), 3) << run.out() << run.err();
  EXPECT_NE(run.out().find("unknown"), std::string::npos) << run.out();
  EXPECT_NE(run.out().find("interrupted"), std::string::npos) << run.out();
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(junit.c_str())) << slurp(junit);
  EXPECT_EQ(doc.select_nodes("//testcase/error").size(), 1u) << slurp(junit);
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"r.xml", "stderr", "stdout"}));
}

TEST_P(Interrupt, OtherSubcommandsStopWithExitThreeAndNoFile) {
  // rsg explores the same chart; its --dot file is written after the exploration, so the
  // signal finds no file at all, and the old one stays whole.
  const int sig = GetParam();
  TempDir dir;
  const std::string dot = dir / "g.dot";
  std::ofstream(dot) << "OLD";
  Background run("rsg '" + large_chart() + "' --dot '" + dot + "'", dir);
  ASSERT_TRUE(run.wait_for_err("explore", 60)) << run.err();
  run.signal(sig);
  EXPECT_EQ(run.wait(60), 3) << run.out() << run.err();
  EXPECT_EQ(slurp(dot), "OLD");
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"g.dot", "stderr", "stdout"}));
}

INSTANTIATE_TEST_SUITE_P(Signals, Interrupt, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& param_info) {
                           return std::string(param_info.param == SIGINT ? "SIGINT" : "SIGTERM");
                         });

}  // namespace

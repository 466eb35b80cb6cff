// sfcv against ABC on the real programs of the shared corpus: which steps are ever active.
// `sfcv export --to aiger --checks reachable` makes one bad state per step ("the step is
// active"); ABC's `pdr -a` reaches some (each "Output k was asserted") and proves the others
// never active. sfcv's own answer (`check --checks reachable`, engine auto) must agree:
// a step ABC reaches is never among sfcv's "never active", and where both decide every step
// the two sets are the same. Engine-against-engine tests inside sfcv share the reading of the
// chart and the export; ABC reads only the exported circuit, so a name that changes what the
// export means (two latches of one name, an output cached by name: both once did, on every
// xPPU scenario) shows here as a disagreement, or as a file ABC refuses.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

bool have_abc() {
  return std::system("command -v berkeley-abc >/dev/null 2>&1") == 0;
}

std::string run_abc(const std::string& script) {
  std::string out;
  if (FILE* p = ::popen(("berkeley-abc -c '" + script + "' 2>&1").c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  return out;
}

// The step of each bad output, from the ASCII export's symbol table (`b3 unreachable_P.S3`).
std::vector<std::string> bad_steps(const std::string& aag) {
  std::vector<std::string> steps;
  std::istringstream in(aag);
  const std::string prefix = "unreachable_";
  for (std::string line; std::getline(in, line);) {
    if (line == "c") break;
    if (line.size() < 3 || line[0] != 'b') continue;
    const auto space = line.find(' ');
    if (space == std::string::npos || line.compare(space + 1, prefix.size(), prefix) != 0) continue;
    steps.push_back(line.substr(space + 1 + prefix.size()));
  }
  return steps;
}

// "step P.S3 (file:5:1) is never active" -> "P.S3".
std::string finding_step(const std::string& finding) {
  static const std::regex re(R"(^step (.+?)( \(.*\))? is never active)");
  std::smatch m;
  return std::regex_search(finding, m, re) ? m[1].str() : std::string();
}

struct Case {
  const char* file;
  const char* args;
};

TEST(AbcCorpus, StepsEverActiveAgreeWithAbc) {
  SFCV_REQUIRE_CORPUS(corpus);
  if (!have_abc()) GTEST_SKIP() << "berkeley-abc not installed";
  const std::vector<Case> cases = {
      {"01_beremiz_traffic_light.xml", ""},
      {"03_matiec_SFC_TEST_tc6v1.xml", ""},
      {"04_matiec_sfc_syntax.st", ""},
      {"13_verifaps_loopunwinding1_left.sfc", ""},
      {"15_verifaps_transition2_left.sfc", ""},
      {"07_codesys_ppu_scenario3v1.xml", "--pou Stamp"},
      {"07_codesys_ppu_scenario3v1.xml", "--pou Magazin"},
      {"07_codesys_ppu_scenario3v1.xml", "--pou Crane"},
      {"12_codesys_ppu_scenario10.xml", "--pou Conveyor"},
      // With the sensors frozen most steps are never active (52 of 55, 111 of 116): ABC must
      // prove each of them so and reach the others.
      {"07_codesys_ppu_scenario3v1.xml", "--unwritten keep"},
      {"12_codesys_ppu_scenario10.xml", "--unwritten keep"},
      // The TwinCAT xPPU, whose instances' Boolean actions bear their variables' names: ABC
      // reaches most steps in the time, none of which sfcv may call never active.
      {"09_twincat_xppu_scenario1.xml", ""},
  };
  std::size_t compared_whole = 0, reached = 0;
  for (const auto& c : cases) {
    const std::string file = (corpus / c.file).string();
    SCOPED_TRACE(std::string(c.file) + " " + c.args);
    const std::string model = "'" + file + "' " + c.args;
    const auto aag = run_sfcv("export " + model + " --to aag --checks reachable -q");
    ASSERT_EQ(aag.exit_code, 0) << aag.err;
    const auto steps = bad_steps(aag.out);
    ASSERT_FALSE(steps.empty());
    const auto aig = write_temp("", ".aig");
    ASSERT_EQ(run_sfcv("export " + model + " --to aiger --checks reachable -q -o '" + aig + "'")
                  .exit_code,
              0);
    const auto abc = run_abc("read_aiger " + aig + "; fold; pdr -a -T 15");
    std::filesystem::remove(aig);
    ASSERT_EQ(abc.find("Repeated"), std::string::npos) << abc;
    ASSERT_NE(abc.find("Properties:"), std::string::npos) << abc;
    std::set<std::string> abc_reached;
    static const std::regex asserted(R"(Output\s+(\d+) was asserted)");
    for (auto it = std::sregex_iterator(abc.begin(), abc.end(), asserted);
         it != std::sregex_iterator(); ++it) {
      const auto k = std::stoul((*it)[1].str());
      ASSERT_LT(k, steps.size()) << abc;
      abc_reached.insert(steps[k]);
    }
    const bool abc_whole = abc.find("Undecided = 0.") != std::string::npos;

    const auto check =
        run_sfcv("check " + model + " --checks reachable --all --json -q --timeout 15");
    ASSERT_TRUE(check.exit_code == 0 || check.exit_code == 1 || check.exit_code == 3) << check.err;
    const auto report = nlohmann::json::parse(check.out);
    const auto& result = report.at("properties").at(0);
    std::set<std::string> never_active;
    for (const auto& f : result.at("findings"))
      never_active.insert(finding_step(f.get<std::string>()));
    ASSERT_EQ(never_active.size(), result.at("findings_total").get<std::size_t>());
    for (const auto& s : abc_reached)
      EXPECT_FALSE(never_active.count(s)) << "ABC reaches " << s << ", sfcv says never active";
    reached += abc_reached.size();
    const auto verdict = result.at("verdict").get<std::string>();
    if (abc_whole && (verdict == "holds" || verdict == "violated")) {
      std::set<std::string> abc_never;
      for (const auto& s : steps)
        if (!abc_reached.count(s)) abc_never.insert(s);
      EXPECT_EQ(abc_never, never_active);
      ++compared_whole;
    }
  }
  // The comparison must have had something to compare.
  EXPECT_GE(compared_whole, 10u);
  EXPECT_GE(reached, 100u);
}

}  // namespace
}  // namespace sfcv::test

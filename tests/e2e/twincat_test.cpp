// TwinCAT 3 native files through the binary: the demo .TcPOU chart and its PLCopen twin
// (tests/support/twincat_text.hpp) give the same verdicts, on every engine; the public
// MrFrakt/Fraktal press demo (SFC chart and its ST twin), when SFCV_FRAKTAL names a checkout of
// it, is refused by name -- it is object-oriented -- and its chart alone reads as drawn.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "support/sfcv_test.hpp"
#include "support/twincat_text.hpp"

namespace sfcv::test {
namespace {

TEST(TwinCatE2E, DemoChartAndItsPlcopenTwinGiveTheSameVerdicts) {
  const auto native = write_temp(tc::demo_tcpou(tc::vendor_guids()), ".TcPOU");
  const auto twin = write_temp(tc::demo_plcopen(), ".xml");
  // Read from the chart: the alternative legs exclude each other, the parallel legs run
  // together, the join waits for both; P2 is reachable; and in the situation where S1 has just
  // become active its main action has not yet set m1 (the counterexample: Init -> S1, m1=0).
  // One run per engine and file (the test stays fast under sanitizers): each verdict is read
  // from its line of the report.
  const std::vector<std::pair<std::string, const char*>> verdicts = {
      {"AG !(S1 & S2)", "holds"},     {"EF (P1b & P2)", "holds"},
      {"AG (P1 -> !Merge)", "holds"}, {"AG ((P1 | P1b) <-> P2)", "holds"},
      {"AG !P2", "violated"},         {"AG (S1 -> m1)", "violated"},
  };
  for (const char* engine : {"explicit", "bdd", "ic3"})
    expect_ctl_verdicts_in_one_run(native, engine, verdicts);
  expect_ctl_verdicts_in_one_run(twin, "explicit",
                                 verdicts);  // the engines' agreement is the native file's, above
  const auto r = run_sfcv("info " + native);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("twincat 3.1.4024.12"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("steps: 7, transitions: 7"), std::string::npos) << r.out;
}

TEST(TwinCatE2E, UnreadVendorFormatIsExitTwoNamingIt) {
  const auto file = write_temp("<?xml version=\"1.0\"?><ExportFile/>", ".export");
  const auto r = run_sfcv("check " + file);
  EXPECT_EQ(r.exit_code, 2);
  // CODESYS exports are read now (tests/e2e/codesys_export_test.cpp): an empty one is a
  // located error of their reader.
  EXPECT_NE(r.err.find("CODESYS export without objects"), std::string::npos) << r.err;
}

// ---------------------------------------------------------------- the public Fraktal sample

std::optional<std::filesystem::path> find_under(const std::filesystem::path& root,
                                                const std::string& name) {
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(root, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
    if (it->path().filename() == name) return it->path();
  return std::nullopt;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// SFCV_FRAKTAL: a checkout of github.com/MrFrakt/Fraktal (MIT), read in place, never copied.
TEST(TwinCatE2E, FraktalPressDemoSfcAndItsStTwin) {
  const char* root = std::getenv("SFCV_FRAKTAL");
  if (!root || !*root) GTEST_SKIP() << "SFCV_FRAKTAL is not set: Fraktal sample test skipped";
  const auto sfc = find_under(root, "FB_SFC_PressDemoAuto.TcPOU");
  const auto st = find_under(root, "FB_PressDemoAuto.TcPOU");
  ASSERT_TRUE(sfc && st) << "FB_SFC_PressDemoAuto.TcPOU / FB_PressDemoAuto.TcPOU not under "
                         << root;
  // Both extend FB_SequenceBase and call its methods: sfcv does not model object-oriented
  // function blocks, so neither is checked -- a refusal naming the construct, never a verdict.
  for (const auto& file : {*sfc, *st}) {
    const auto r = run_sfcv("check " + file.string());
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("unsupported: EXTENDS (object-oriented function blocks)"),
              std::string::npos)
        << r.err;
  }
  // The chart itself reads as drawn (19 steps, 20 transitions, 3 branches): with the
  // declaration, methods and step bodies replaced by plain ones, it loads with no error.
  std::string text = slurp(*sfc);
  const auto a = text.find("<Declaration><![CDATA[");
  const auto b = text.find("]]></Declaration>");
  ASSERT_TRUE(a != std::string::npos && b != std::string::npos);
  text.replace(a + 22, b - a - 22,
               "FUNCTION_BLOCK FB_SFC_PressDemoAuto\nVAR\n _retVal : INT;\n"
               " _conRetVal : ARRAY[1..2] OF INT;\nEND_VAR");
  text = std::regex_replace(text, std::regex(R"(<Method [\s\S]*?</Method>)"), "");
  text = std::regex_replace(
      text,
      std::regex(
          R"((<Action Name="[^"]*" Id="[^"]*">\s*<Implementation>\s*<ST><!\[CDATA\[)[\s\S]*?(\]\]></ST>))"),
      "$1_retVal := 1;$2");
  text = std::regex_replace(text, std::regex(R"(E_StepResult\.[A-Z0-9_]+)"), "1");
  const auto file = write_temp(text, ".TcPOU");
  const auto r = run_sfcv("info " + file);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("steps: 19, transitions: 20"), std::string::npos) << r.out << r.err;
}

}  // namespace
}  // namespace sfcv::test

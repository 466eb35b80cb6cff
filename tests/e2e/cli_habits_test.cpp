// End-to-end: the command line meets a user's habits (issue 48, "The command line"): "did you
// mean" for subcommands, options, names and --pou; files of the wrong kind named by their
// content; durations with units; each subcommand's exit codes in its own help.

#include <filesystem>
#include <string>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::source_path;
using sfcv::test::write_temp;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string kTwoPrograms = R"(PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Boin: lamp(N); END_STEP
  TRANSITION FROM Idle TO Boin := go; END_TRANSITION
  TRANSITION FROM Boin TO Idle := NOT go; END_TRANSITION
END_PROGRAM
PROGRAM Crane
  VAR_INPUT up : BOOL; END_VAR
  INITIAL_STEP Rest: END_STEP
  STEP Lift: END_STEP
  TRANSITION FROM Rest TO Lift := up; END_TRANSITION
  TRANSITION FROM Lift TO Rest := NOT up; END_TRANSITION
END_PROGRAM
)";

TEST(CliHabits, MisspelledSubcommandGetsTheClosestOne) {
  const auto r = run_sfcv("chek x.st");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "unknown subcommand 'chek': did you mean 'check'?")) << r.err;
  const auto far = run_sfcv("frobnicate x.st");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_TRUE(has(far.err, "unknown subcommand 'frobnicate' (the subcommands: check")) << far.err;
}

TEST(CliHabits, MisspelledOptionGetsTheClosestOne) {
  const auto r = run_sfcv("check x.st --clt 'AG x'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "unknown option '--clt' of sfcv check: did you mean '--ctl'?")) << r.err;
  const auto eq = run_sfcv("rsg x.st --max-node=3");
  EXPECT_TRUE(has(eq.err, "did you mean '--max-nodes'?")) << eq.err;
}

TEST(CliHabits, MisspelledNameInAPropertyGetsTheClosestObservable) {
  const auto chart = write_temp(kTwoPrograms, ".st");
  const auto r = run_sfcv("check " + chart + " --pou Main --ctl 'AG !Boing' --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "unknown name 'Boing' (did you mean 'Main.Boin'?)")) << r.err;
}

TEST(CliHabits, ANameOfAPouLeftOutOfTheRunSaysSo) {
  const auto chart = write_temp(kTwoPrograms, ".st");
  const auto r = run_sfcv("check " + chart + " --pou Main --ctl 'AG !Lift' --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "'Lift' is a step of POU 'Crane', which this run leaves out")) << r.err;
  EXPECT_TRUE(has(r.err, "--pou Crane")) << r.err;
}

TEST(CliHabits, MisspelledPouIsBadUsageWithASuggestion) {
  const auto chart = write_temp(kTwoPrograms, ".st");
  const auto r = run_sfcv("check " + chart + " --pou Cran --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "no POU named 'Cran': did you mean 'Crane'?")) << r.err;
  EXPECT_TRUE(has(r.err, "bad --pou")) << r.err;
  EXPECT_FALSE(has(r.err, "semantics cannot model")) << r.err;
}

TEST(CliHabits, LintSuggestsTheClosestNameOfAnUnknownOne) {
  const auto chart = write_temp(R"(PROGRAM P
  VAR_INPUT Boin : BOOL; END_VAR
  INITIAL_STEP S0: END_STEP
  STEP S1: END_STEP
  TRANSITION FROM S0 TO S1 := Boing; END_TRANSITION
  TRANSITION FROM S1 TO S0 := NOT Boin; END_TRANSITION
END_PROGRAM
)",
                                ".st");
  const auto r = run_sfcv("lint " + chart);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.out, "unknown name 'Boing'")) << r.out;
  EXPECT_TRUE(has(r.out, "did you mean 'Boin'?")) << r.out;
}

TEST(CliHabits, FilesOfTheWrongKindAreNamedByTheirContent) {
  struct Case {
    std::string text, suffix, kind;
  };
  const Case cases[] = {
      {R"({"$schema": "https://json.schemastore.org/sarif-2.1.0.json", "version": "2.1.0", "runs": []})",
       ".st", "this is a SARIF log, not a model"},
      {"{\n  \"model\": \"a.st\",\n  \"results\": []\n}\n", ".xml",
       "this is a JSON result of 'sfcv check --json'"},
      {"$date today $end\n$timescale 1ms $end\n$scope module top $end\n", ".st",
       "this is a VCD waveform, not a model"},
      {"<!DOCTYPE html>\n<html><body></body></html>\n", ".xml",
       "this is an HTML page, not a model"},
      {"<?xml version=\"1.0\"?>\n<testsuites name=\"sfcv\"></testsuites>\n", ".xml",
       "this is a JUnit XML report, not a model"},
  };
  for (const auto& c : cases) {
    const auto file = write_temp(c.text, c.suffix);
    for (const char* sub : {"info", "check", "lint"}) {
      const auto r = run_sfcv(std::string(sub) + " " + file);
      EXPECT_EQ(r.exit_code, 2) << sub << " " << c.kind;
      EXPECT_TRUE(has(r.err, c.kind)) << sub << ": " << r.err;
      EXPECT_FALSE(has(r.err, "lexer")) << r.err;
    }
  }
  // An IEC pragma starts with a brace too: still a model.
  const auto pragma = write_temp(
      "{attribute 'qualified_only'}\nPROGRAM P\n  VAR_INPUT a : BOOL; END_VAR\n"
      "  INITIAL_STEP S0: END_STEP\n  STEP S1: END_STEP\n"
      "  TRANSITION FROM S0 TO S1 := a; END_TRANSITION\n"
      "  TRANSITION FROM S1 TO S0 := NOT a; END_TRANSITION\nEND_PROGRAM\n",
      ".st");
  const auto r = run_sfcv("info " + pragma);
  EXPECT_FALSE(has(r.err, "not a model")) << r.err;
}

TEST(CliHabits, TimeoutTakesUnitsLikeCycleAndMemory) {
  const auto chart = source_path("examples/chemical_plant/chemical_plant.st");
  for (const char* t : {"10s", "2m", "1h", "500ms", "30"}) {
    const auto r = run_sfcv("check " + chart + " --checks reachable --quiet --timeout " + t);
    EXPECT_EQ(r.exit_code, 0) << t << ": " << r.err;
  }
  for (const char* t : {"10x", "0s", "-1m", "s"}) {
    const auto r = run_sfcv("check " + chart + " --checks reachable --quiet --timeout " + t);
    EXPECT_EQ(r.exit_code, 2) << t;
    EXPECT_TRUE(has(r.err, "bad --timeout")) << r.err;
  }
}

TEST(CliHabits, DashIsStandardOutputForEveryReport) {
  const auto chart = source_path("examples/chemical_plant/chemical_plant.st");
  // sfcv runs in the test's working directory: a file named "-" would appear there.
  std::filesystem::remove("-");
  const auto j = run_sfcv("check " + chart + " --checks reachable --quiet --trace none --junit -");
  EXPECT_EQ(j.exit_code, 0) << j.err;
  EXPECT_TRUE(has(j.out, "<testsuites")) << j.out;
  EXPECT_FALSE(std::filesystem::exists("-"));
}

TEST(CliHabits, EachSubcommandsHelpSaysWhatItsExitCodesMean) {
  struct Case {
    const char* sub;
    const char* meaning;
  };
  for (const auto& c :
       {Case{"info", "0 the model was read"}, Case{"lint", "0 no error"},
        Case{"export", "0 the model was written"}, Case{"report", "0 the report was written"},
        Case{"rsg", "1 it has an anomaly"}, Case{"query", "every query was answered"}}) {
    const auto r = run_sfcv(std::string(c.sub) + " --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_TRUE(has(r.out, c.meaning)) << c.sub << ":\n" << r.out;
    EXPECT_FALSE(has(r.out, "some property is violated")) << c.sub;
  }
  const auto check = run_sfcv("check --help");
  EXPECT_TRUE(has(check.out, "some property is violated")) << check.out;
  // --ltl is decided by the bdd engine too.
  EXPECT_TRUE(has(check.out, "engines explicit, bdd")) << check.out;
}

}  // namespace

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::write_temp;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Nothing can move: the only condition reads a variable that no POU writes, held at its initial
// value by --unwritten keep (corpus 07's situation, in small).
const std::string kStuck = R"(PROGRAM P
  VAR start : BOOL; END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP S0: END_STEP
  STEP S1: lamp(N); END_STEP
  TRANSITION FROM S0 TO S1 := start; END_TRANSITION
  TRANSITION FROM S1 TO S0 := NOT start; END_TRANSITION
END_PROGRAM
)";

TEST(CliDiagnosis, AChartThatNeverMovesIsDiagnosed) {
  const auto chart = write_temp(kStuck, ".st");
  const auto r = run_sfcv("check " + chart + " --unwritten keep --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(contains(r.out,
                       "diagnosis: the chart never moves: every one of its 2 transitions "
                       "is dead and only 1 state is reachable"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "why: no input ever changes")) << r.out;
  EXPECT_TRUE(contains(r.out, "what to do:")) << r.out;
  // Free, `start` is an input: the chart moves and nothing is diagnosed.
  const auto free = run_sfcv("check " + chart + " --quiet");
  EXPECT_FALSE(contains(free.out, "diagnosis:")) << free.out;
}

TEST(CliDiagnosis, Corpus07WithHeldSensorsIsDiagnosed) {
  const auto corpus = sfcv::test::corpus_dir();
  if (!corpus) GTEST_SKIP() << "SFCV_CORPUS not set";
  const auto r = run_sfcv("check '" + (*corpus / "07_codesys_ppu_scenario3v1.xml").string() +
                          "' --unwritten keep --engine explicit --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(contains(r.out, "diagnosis: the chart never moves")) << r.out;
  // Findings are short: no XML element path without --verbose.
  EXPECT_FALSE(contains(r.out, "/project/types")) << r.out.substr(0, 2000);
  const auto v =
      run_sfcv("--verbose check '" + (*corpus / "07_codesys_ppu_scenario3v1.xml").string() +
               "' --unwritten keep --engine explicit --quiet --checks reachable");
  EXPECT_TRUE(contains(v.out, "(/project/types/pous/pou[@name='Magazin']"))
      << v.out.substr(0, 2000);
}

TEST(CliNumbers, OneSituationIsSingularAndAnEarlyStopIsNotComplete) {
  const auto chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  // A violation in the initial situation: a counterexample of one situation.
  const auto r = run_sfcv("check " + chart + " --ctl 'AG !s9' --quiet");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.out, "counterexample (1 situation):")) << r.out;
  // Invariants alone stop at their violations: the counts are not the system's.
  const auto j = run_sfcv("check " + chart + " --ctl 'AG !s9' --json --quiet --engine explicit");
  EXPECT_TRUE(contains(j.out, "\"complete\": false")) << j.out.substr(0, 600);
  EXPECT_TRUE(contains(j.out, "\"stopped_early\": true")) << j.out.substr(0, 600);
  const auto t = run_sfcv("check " + chart + " --ctl 'AG !s9' --quiet --engine explicit");
  EXPECT_TRUE(contains(t.out, "stopped early")) << t.out;
}

TEST(CliNotes, FewNotesInShortTheRestCountedAndAllUnderVerbose) {
  // Corpus 01 printed 8 long notes before every output.
  const auto corpus = sfcv::test::corpus_dir();
  if (!corpus) GTEST_SKIP() << "SFCV_CORPUS not set";
  const auto file = "'" + (*corpus / "01_beremiz_traffic_light.xml").string() + "'";
  const auto r = run_sfcv("info " + file);
  std::size_t notes = 0;
  for (std::size_t from = 0; from < r.err.size();) {
    auto to = r.err.find('\n', from);
    if (to == std::string::npos) to = r.err.size();
    const auto line = r.err.substr(from, to - from);
    if (contains(line, ": note: ")) {
      ++notes;
      EXPECT_LE(line.size(), 200u) << line;
    }
    from = to + 1;
  }
  EXPECT_EQ(notes, 3u) << r.err;
  EXPECT_TRUE(contains(r.err, "more notes (--verbose prints every note in full")) << r.err;
  EXPECT_FALSE(contains(r.err, "(/project")) << r.err;
  const auto v = run_sfcv("--verbose info " + file);
  EXPECT_GT(v.err.size(), r.err.size());
  EXPECT_FALSE(contains(v.err, "more notes")) << v.err;
}

}  // namespace

// sfcv equiv OLD NEW (issue 50, docs/equivalence.md): two programs read the same inputs each
// cycle; they are equivalent when every compared output is equal at the end of every cycle,
// from the initial situations. The charts are written here: a filler, its refactored copy
// (steps renamed, the valve's action moved from N to S/R on other steps, a guard's operands
// swapped), a planted one-guard change, and an ST twin.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const char* kHeader =
    "  VAR_INPUT\n    start : BOOL;\n    full : BOOL;\n    stop : BOOL;\n  END_VAR\n";

std::string old_filler() {
  return std::string("PROGRAM Filler\n") + kHeader +
         "  VAR_OUTPUT\n    valve : BOOL;\n    lamp : BOOL;\n  END_VAR\n"
         "  INITIAL_STEP Idle: lamp(N); END_STEP\n"
         "  STEP Fill: valve(N); END_STEP\n"
         "  STEP Done: END_STEP\n"
         "  TRANSITION FROM Idle TO Fill := start AND NOT stop; END_TRANSITION\n"
         "  TRANSITION FROM Fill TO Done := full; END_TRANSITION\n"
         "  TRANSITION FROM Fill TO Idle := stop; END_TRANSITION\n"
         "  TRANSITION FROM Done TO Idle := NOT full; END_TRANSITION\n"
         "END_PROGRAM\n";
}

/// Steps renamed, the valve set on entering Filling and reset in the two other steps instead
/// of N on Filling, the first guard's operands swapped. `fill_to_full` is the guard of
/// Filling -> Full (the planted change edits it).
std::string refactored_filler(const std::string& fill_to_full = "full") {
  return std::string("PROGRAM Filler\n") + kHeader +
         "  VAR_OUTPUT\n    valve : BOOL;\n    lamp : BOOL;\n  END_VAR\n"
         "  INITIAL_STEP Waiting: lamp(N); valve(R); END_STEP\n"
         "  STEP Filling: valve(S); END_STEP\n"
         "  STEP Full: valve(R); END_STEP\n"
         "  TRANSITION FROM Waiting TO Filling := NOT stop AND start; END_TRANSITION\n"
         "  TRANSITION FROM Filling TO Full := " +
         fill_to_full +
         "; END_TRANSITION\n"
         "  TRANSITION FROM Filling TO Waiting := stop; END_TRANSITION\n"
         "  TRANSITION FROM Full TO Waiting := NOT full; END_TRANSITION\n"
         "END_PROGRAM\n";
}

/// The same machine as a CASE over a state variable; `lamp_init` its lamp's declaration.
std::string st_twin(const std::string& lamp_init = " := TRUE", const std::string& extra = "") {
  return std::string("PROGRAM Filler\n") + kHeader +
         "  VAR_OUTPUT\n    valve : BOOL;\n    lamp : BOOL" + lamp_init +
         ";\n  END_VAR\n  VAR\n    state : INT(0..2);\n    late : BOOL;\n  END_VAR\n"
         "  CASE state OF\n"
         "    0: IF start AND NOT stop THEN state := 1; END_IF;\n"
         "    1: IF full THEN state := 2; ELSIF stop THEN state := 0; END_IF;\n"
         "    2: IF NOT full THEN state := 0; END_IF;\n"
         "  END_CASE;\n" +
         (extra.empty() ? "  valve := state = 1;\n" : extra) +
         "  lamp := state = 0;\n"
         "END_PROGRAM\n";
}

int rows_of_trace(const std::string& out) {
  // The table's rows are "  <cycle>  ...": count them.
  int rows = 0;
  std::size_t at = 0;
  while ((at = out.find("\n  ", at)) != std::string::npos) {
    at += 3;
    if (at < out.size() && std::isdigit(static_cast<unsigned char>(out[at]))) ++rows;
  }
  return rows;
}

TEST(Equiv, RefactoredChartIsEquivalentOnEveryEngine) {
  const auto a = write_temp(old_filler(), ".st");
  const auto b = write_temp(refactored_filler(), ".st");
  for (const char* engine : {"explicit", "bdd", "kind", "ic3", "auto"}) {
    const auto r = run_sfcv(std::string("-q equiv ") + a + " " + b + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 0) << engine << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find(": equivalent"), std::string::npos) << engine << r.out;
    EXPECT_NE(r.out.find("compared (2): valve, lamp"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("shared inputs (3): full, start, stop"), std::string::npos) << r.out;
  }
  // BMC proves nothing: no difference within the bound is "unknown", never "equivalent".
  const auto r = run_sfcv("-q equiv " + a + " " + b + " --engine bmc --depth 12");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
}

// The planted change: Filling -> Full also on `stop` (before: stop went back to Waiting). The
// shortest run that tells them apart: start (both fill), then stop: OLD is back in Idle with its
// lamp on, NEW is in Full with the lamp off. Two cycles, on every engine.
TEST(Equiv, OneGuardChangeIsFoundWithTheShortestTrace) {
  const auto a = write_temp(old_filler(), ".st");
  const auto b = write_temp(refactored_filler("full OR stop"), ".st");
  for (const char* engine : {"explicit", "bdd", "bmc", "kind", "ic3"}) {
    const auto r = run_sfcv(std::string("-q equiv ") + a + " " + b + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << engine << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("all: differ after 2 cycle(s)"), std::string::npos) << engine << r.out;
    EXPECT_NE(r.out.find("first difference: lamp"), std::string::npos) << engine << r.out;
    EXPECT_EQ(rows_of_trace(r.out), 3) << engine << r.out;  // cycles 0, 1, 2
  }
  // JSON: the trace side by side, the difference in the last cycle only.
  const auto r = run_sfcv("-q equiv " + a + " " + b + " --engine explicit --json");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["verdict"], "differ");
  const auto& trace = j["results"][0]["trace"];
  EXPECT_EQ(trace["length"], 2);
  const auto& last = trace["cycles"][2];
  EXPECT_EQ(last["old"]["signals"]["lamp"], 1);
  EXPECT_EQ(last["new"]["signals"]["lamp"], 0);
  EXPECT_EQ(last["old"]["steps"][0], "Filler.Idle");
  EXPECT_EQ(last["new"]["steps"][0], "Filler.Full");
  EXPECT_TRUE(last["inputs"].contains("stop"));
  EXPECT_EQ(trace["cycles"][1]["differs"].size(), 0u);
}

TEST(Equiv, SfcAndItsStTwinAreEquivalent) {
  const auto a = write_temp(old_filler(), ".st");
  const auto b = write_temp(st_twin(), ".st");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    const auto r = run_sfcv(std::string("-q equiv ") + a + " " + b + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 0) << engine << "\n" << r.out << r.err;
  }
  // The twin whose lamp starts FALSE differs before any cycle: the initial step's N action
  // has the chart's lamp on in the initial situation.
  const auto c = write_temp(st_twin(""), ".st");
  const auto r = run_sfcv("-q equiv " + a + " " + c + " --engine explicit");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("differ after 0 cycle(s)"), std::string::npos) << r.out;
}

// --within N: at the end of every cycle NEW's value equals OLD's at one of the last N+1 cycles.
// A twin whose valve follows one cycle late differs without it and passes with --within 1.
TEST(Equiv, WithinAllowsTheNewOutputToLag) {
  const auto a = write_temp(old_filler(), ".st");
  const auto b = write_temp(st_twin(" := TRUE", "  valve := late;\n  late := state = 1;\n"), ".st");
  auto r = run_sfcv("-q equiv " + a + " " + b + " --engine explicit --outputs valve");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("differ after 1 cycle(s)"), std::string::npos) << r.out;
  for (const char* engine : {"explicit", "ic3"}) {
    r = run_sfcv(std::string("-q equiv ") + a + " " + b + " --within 1 --engine " + engine);
    EXPECT_EQ(r.exit_code, 0) << engine << r.out << r.err;
  }
}

// --changed: each output its own verdict and trace; --ignore leaves one out; --map pairs names.
TEST(Equiv, ChangedListsEachOutputIgnoreAndMap) {
  const auto a = write_temp(old_filler(), ".st");
  // NEW's lamp never changes from TRUE: lamp differs, valve does not (same chart otherwise).
  std::string lamp_stuck = old_filler();
  lamp_stuck.replace(lamp_stuck.find("lamp(N)"), 7, "lamp(S)");
  const auto b = write_temp(lamp_stuck, ".st");
  auto r = run_sfcv("-q equiv " + a + " " + b + " --changed --engine explicit --json");
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][0]["signal"], "valve");
  EXPECT_EQ(j["results"][0]["verdict"], "equivalent");
  EXPECT_EQ(j["results"][1]["signal"], "lamp");
  EXPECT_EQ(j["results"][1]["verdict"], "differ");
  EXPECT_EQ(j["results"][1]["trace"]["length"], 1);
  r = run_sfcv("-q equiv " + a + " " + b + " --ignore lamp --engine explicit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // NEW renames the input stop to halt and the output lamp to ready.
  std::string renamed = refactored_filler();
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"stop", "halt"}, {"lamp", "ready"}})
    for (std::size_t at; (at = renamed.find(from)) != std::string::npos;)
      renamed.replace(at, from.size(), to);
  const auto c = write_temp(renamed, ".st");
  r = run_sfcv("-q equiv " + a + " " + c + " --engine explicit");
  // `stop` and `halt` are then two inputs, each read by one side: they differ, and notes say so.
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("OLD's input stop is not an input of NEW"), std::string::npos) << r.out;
  r = run_sfcv("-q equiv " + a + " " + c + " --map stop=halt --map lamp=ready --engine explicit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("lamp=ready"), std::string::npos) << r.out;
}

TEST(Equiv, BadInputsAreRefused) {
  const auto a = write_temp(old_filler(), ".st");
  // An input of another type on the two sides is named.
  std::string int_start = old_filler();
  int_start.replace(int_start.find("start : BOOL"), 12, "start : INT");
  int_start.replace(int_start.find("start AND"), 5, "start > 2");
  const auto b = write_temp(int_start, ".st");
  auto r = run_sfcv("-q equiv " + a + " " + b);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("the input 'start' is BOOL in OLD and INT in NEW"), std::string::npos)
      << r.err;
  // An input of NEW named like an output of OLD would read OLD's output in the product.
  const auto reads_lamp = write_temp(
      "PROGRAM Panel\n  VAR_INPUT lamp : BOOL; END_VAR\n  VAR_OUTPUT valve : BOOL; END_VAR\n"
      "  valve := lamp;\nEND_PROGRAM\n",
      ".st");
  r = run_sfcv("-q equiv " + a + " " + reads_lamp);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("'lamp' is an input of NEW but an output of OLD's Filler"),
            std::string::npos)
      << r.err;
  // A Grafcet side: refused with the reason, never a verdict.
  const auto g = write_temp(g7_chain_text(2), ".g7");
  r = run_sfcv("-q equiv " + g + " " + a);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  // Nothing to compare.
  r = run_sfcv("-q equiv " + a + " " + a + " --ignore valve --ignore lamp");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("nothing to compare"), std::string::npos) << r.err;
}

TEST(Equiv, TraceFileInVcdShowsBothSides) {
  const auto a = write_temp(old_filler(), ".st");
  const auto b = write_temp(refactored_filler("full OR stop"), ".st");
  const auto vcd = write_temp("", ".vcd");
  const auto r =
      run_sfcv("-q equiv " + a + " " + b + " --engine explicit --trace vcd --trace-file " + vcd);
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  std::ifstream in(vcd);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Old_Filler_lamp"), std::string::npos) << text;
  EXPECT_NE(text.find("New_Filler_lamp"), std::string::npos) << text;
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// Function block types: one both sides declare identically is shared (each instance keeps its
// own state); one that differs runs as NEW's own `New_<type>`, and so does an unchanged type
// that holds an instance of the changed one (else NEW would run OLD's inner block).
std::string latch_program(const std::string& latch_body) {
  return "FUNCTION_BLOCK Latch\n  VAR_INPUT set, reset : BOOL; END_VAR\n"
         "  VAR_OUTPUT q : BOOL; END_VAR\n  " +
         latch_body +
         "\nEND_FUNCTION_BLOCK\n"
         "FUNCTION_BLOCK Holder\n  VAR_INPUT s, r : BOOL; END_VAR\n"
         "  VAR_OUTPUT q : BOOL; END_VAR\n  VAR l : Latch; END_VAR\n"
         "  l(set := s, reset := r, q => q);\nEND_FUNCTION_BLOCK\n"
         "PROGRAM Main\n  VAR_INPUT a, b : BOOL; END_VAR\n"
         "  VAR_OUTPUT lamp : BOOL; END_VAR\n  VAR h : Holder; END_VAR\n"
         "  h(s := a, r := b, q => lamp);\nEND_PROGRAM\n";
}

TEST(Equiv, ChangedFunctionBlockTypesRunAsNewsOwn) {
  // Set wins over reset in OLD; reset wins in NEW: they differ when both come at once.
  const auto a = write_temp(
      latch_program("IF set THEN q := TRUE; ELSIF reset THEN q := FALSE; END_IF;"), ".st");
  const auto same = write_temp(
      latch_program("IF set THEN q := TRUE; ELSIF reset THEN q := FALSE; END_IF;"), ".st");
  const auto b = write_temp(
      latch_program("IF reset THEN q := FALSE; ELSIF set THEN q := TRUE; END_IF;"), ".st");
  auto r = run_sfcv("-q equiv " + a + " " + same + " --engine explicit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("note: NEW's"), std::string::npos) << r.out;
  for (const char* engine : {"explicit", "ic3"}) {
    r = run_sfcv(std::string("-q equiv ") + a + " " + b + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("differ after 1 cycle(s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("NEW's Latch differs from OLD's: it runs as New_Latch"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("NEW's Holder differs from OLD's: it runs as New_Holder"),
              std::string::npos)
        << r.out;
  }
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// docs/equivalence.md, timers: under abstract time each side's timer expires when it likes, so
// even a program and its copy "differ" (the note says why); in discrete time they do not.
TEST(Equiv, TimersCompareInDiscreteTime) {
  const auto a = write_temp(
      "PROGRAM Blink\n  VAR_INPUT go : BOOL; END_VAR\n  VAR_OUTPUT out : BOOL; END_VAR\n"
      "  VAR t : TON; END_VAR\n  t(IN := go, PT := T#30ms);\n  out := t.Q;\nEND_PROGRAM\n",
      ".st");
  auto r = run_sfcv("-q equiv " + a + " " + a + " --engine explicit");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("run on abstract time"), std::string::npos) << r.out;
  r = run_sfcv("-q equiv " + a + " " + a + " --engine explicit --time discrete --cycle 10ms");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("abstract time"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// A compared output that one side never writes is that side's free value (any value in each
// cycle, its declared value before the first): the difference shows in the initial situation,
// with both values in the trace.
TEST(Equiv, AnOutputOneSideNeverWritesIsItsFreeValue) {
  std::string silent = old_filler();
  silent.replace(silent.find("lamp(N);"), 8, "");
  // Read but never written: free (docs/semantics.md 1.8).
  silent.replace(silent.find("start AND NOT stop"), 18, "start AND NOT stop AND NOT lamp");
  const auto a = write_temp(silent, ".st");
  const auto b = write_temp(old_filler(), ".st");
  for (const char* engine : {"explicit", "bmc"}) {
    const auto r = run_sfcv(std::string("-q equiv ") + a + " " + b +
                            " --outputs lamp --depth 3 --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("OLD never writes the compared lamp"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("differ after 0 cycle(s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0/1 *"), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace sfcv::test

namespace sfcv::test {
namespace {

// Integer outputs of different ranges: NEW's value outside OLD's range is a difference (the
// observer keeps each side's value in that side's type), never a range error that would end
// the run and hide it.
TEST(Equiv, IntegerOutputsOfDifferentRangesCompareByValue) {
  const auto program = [](const std::string& type) {
    return "PROGRAM Count\n  VAR_INPUT up : BOOL; END_VAR\n  VAR_OUTPUT n : " + type +
           "; END_VAR\n  IF up AND n < 12 THEN n := n + 1; END_IF;\nEND_PROGRAM\n";
  };
  const auto a = write_temp(program("INT(0..12)"), ".st");
  const auto b = write_temp(program("INT(0..20)"), ".st");
  auto r = run_sfcv("-q equiv " + a + " " + b + " --engine explicit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto c = write_temp(
      "PROGRAM Count\n  VAR_INPUT up : BOOL; END_VAR\n  VAR_OUTPUT n : INT(0..20); END_VAR\n"
      "  IF up AND n < 13 THEN n := n + 1; END_IF;\nEND_PROGRAM\n",
      ".st");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    r = run_sfcv(std::string("-q equiv ") + a + " " + c + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("differ after 13 cycle(s)"), std::string::npos) << engine << r.out;
    EXPECT_NE(r.out.find("12/13 *"), std::string::npos) << engine << r.out;
  }
}

}  // namespace
}  // namespace sfcv::test

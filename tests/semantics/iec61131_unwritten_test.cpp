// Variables that the run reads and no POU of it writes (docs/semantics.md 1.8, issue 53): by
// default inputs, free each cycle; `UnwrittenMode::Keep` holds them at their initial values.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/load.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

struct Built {
  std::unique_ptr<model::Project> project;
  semantics::TransitionSystemPtr system;
  model::Diagnostics diags;
};

Built build(const std::string& text, semantics::UnwrittenMode mode = semantics::UnwrittenMode::Free,
            std::vector<std::string> pous = {}) {
  Built b;
  auto loaded = io::load_iec_text(text, "unwritten.st");
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) return b;
  b.project = std::make_unique<model::Project>(std::move(*loaded.project));
  semantics::Iec61131Options o;
  o.unwritten = mode;
  o.pous = std::move(pous);
  b.system = semantics::make_iec61131_system(*b.project, o, b.diags);
  for (const auto& d : b.diags) EXPECT_NE(d.severity, model::Severity::Error) << d.str();
  return b;
}

bool has_input(const semantics::TransitionSystem& ts, const std::string& name) {
  return std::any_of(ts.inputs().begin(), ts.inputs().end(),
                     [&](const auto& in) { return in.name == name; });
}

std::vector<std::string> unwritten_names(const semantics::TransitionSystem& ts) {
  std::vector<std::string> out;
  for (const auto& u : semantics::unwritten_variables(ts)) out.push_back(u.name);
  return out;
}

std::string notes(const model::Diagnostics& diags) {
  std::string s;
  for (const auto& d : diags)
    if (d.severity == model::Severity::Note) s += d.message + "\n";
  return s;
}

// A crane lowers while its sensor `down` is FALSE and stops when it is TRUE; `down` is a plain
// VAR that nothing writes (a CODESYS export without its I/O mapping).
const char* kCrane = R"(PROGRAM Main
  VAR_INPUT start : BOOL; END_VAR
  VAR down : BOOL; lower : BOOL; END_VAR
  INITIAL_STEP Idle : END_STEP
  STEP Lowering : Lower(N); END_STEP
  STEP Done : END_STEP
  TRANSITION FROM Idle TO Lowering := start; END_TRANSITION
  TRANSITION FROM Lowering TO Done := down; END_TRANSITION
  TRANSITION FROM Done TO Idle := NOT down; END_TRANSITION
  ACTION Lower : lower := NOT down; END_ACTION
END_PROGRAM
)";

TEST(Unwritten, AReadVariableNothingWritesIsAFreeInputByDefault) {
  auto b = build(kCrane);
  ASSERT_TRUE(b.system);
  const auto& ts = *b.system;
  EXPECT_TRUE(has_input(ts, "down"));
  EXPECT_FALSE(semantics::find_observable(ts, "down"));  // no longer a state variable
  EXPECT_EQ(unwritten_names(ts), std::vector<std::string>{"down"});
  const auto u = semantics::unwritten_variables(ts).front();
  EXPECT_TRUE(u.free);
  EXPECT_EQ(u.read_in, "Main");
  EXPECT_GT(u.read_at.line, 0);
  EXPECT_EQ(u.declared.line, 3);
  // `lower` is written (by Lower), `start` is a VAR_INPUT: neither is listed.
  const auto text = notes(b.diags);
  EXPECT_NE(text.find("1 variable that no POU of the run writes is read as an input (free each "
                      "cycle): down (read in Main, line "),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("--unwritten keep holds it at its initial value"), std::string::npos);
  // The machine moves through the sensor: Lowering is left when `down` rises.
  Runner r(ts);
  ASSERT_TRUE(r.cycle({{"start", 1}}));
  EXPECT_EQ(r["Lowering"], 1);
  ASSERT_TRUE(r.cycle({{"down", 0}}));
  EXPECT_EQ(r["lower"], 1);
  ASSERT_TRUE(r.cycle({{"down", 1}}));
  EXPECT_EQ(r["Done"], 1);
  ASSERT_TRUE(r.cycle({{"down", 0}}));
  EXPECT_EQ(r["Idle"], 1);
}

TEST(Unwritten, KeepHoldsThemAtTheirInitialValues) {
  auto b = build(kCrane, semantics::UnwrittenMode::Keep);
  ASSERT_TRUE(b.system);
  const auto& ts = *b.system;
  EXPECT_FALSE(has_input(ts, "down"));
  ASSERT_TRUE(semantics::find_observable(ts, "down"));
  const auto list = semantics::unwritten_variables(ts);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_FALSE(list.front().free);
  EXPECT_NE(notes(b.diags).find("held at its initial value (--unwritten keep)"), std::string::npos)
      << notes(b.diags);
  Runner r(ts);
  ASSERT_TRUE(r.cycle({{"start", 1}}));
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["Lowering"], 1);  // frozen sensor: never leaves Lowering
  EXPECT_EQ(r["down"], 0);
}

TEST(Unwritten, ConstantsWrittenVariablesAndLocatedOutputsAreNotFree) {
  auto b = build(R"(PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR CONSTANT limit : INT := 3; enabled : BOOL := TRUE; END_VAR
  VAR n : INT; seen : BOOL; lamp AT %QX0.0 : BOOL; twice : BOOL; END_VAR
  IF go AND enabled AND n < limit THEN n := n + 1; END_IF;
  twice := seen AND lamp;
END_PROGRAM
PROGRAM Other
  VAR x : BOOL; END_VAR
  Main.seen := x;
END_PROGRAM
)");
  ASSERT_TRUE(b.system);
  const auto& ts = *b.system;
  // `seen` is written by Other (another POU of the run); `x`, read by Other and written by
  // nobody, is free; CONSTANTs and the %Q output keep their values.
  EXPECT_EQ(unwritten_names(ts), std::vector<std::string>{"x"});
  EXPECT_TRUE(semantics::find_observable(ts, "limit"));
  EXPECT_TRUE(semantics::find_observable(ts, "enabled"));
  EXPECT_TRUE(semantics::find_observable(ts, "lamp"));
  EXPECT_TRUE(semantics::find_observable(ts, "seen"));
}

TEST(Unwritten, AWriteInAPouOutsideTheRunDoesNotCount) {
  const char* text = R"(PROGRAM Main
  VAR_GLOBAL alarm : BOOL; END_VAR
  VAR pump : BOOL; END_VAR
  pump := NOT alarm;
END_PROGRAM
PROGRAM Watch
  VAR_INPUT hot : BOOL; END_VAR
  VAR_EXTERNAL alarm : BOOL; END_VAR
  alarm := hot;
END_PROGRAM
)";
  auto whole = build(text);
  ASSERT_TRUE(whole.system);
  EXPECT_TRUE(unwritten_names(*whole.system).empty());
  auto alone = build(text, semantics::UnwrittenMode::Free, {"Main"});
  ASSERT_TRUE(alone.system);
  EXPECT_EQ(unwritten_names(*alone.system), std::vector<std::string>{"alarm"});
  EXPECT_TRUE(has_input(*alone.system, "alarm"));
}

TEST(Unwritten, LocatedInputsStayInputsAndAreNotListed) {
  auto b = build(R"(PROGRAM Main
  VAR b1 AT %IX0.1 : BOOL; q : BOOL; END_VAR
  q := b1;
END_PROGRAM
)");
  ASSERT_TRUE(b.system);
  EXPECT_TRUE(has_input(*b.system, "b1"));
  EXPECT_TRUE(unwritten_names(*b.system).empty());
  EXPECT_EQ(notes(b.diags).find("no POU of the run writes"), std::string::npos);
}

// Each instance's copy of a function block variable that the type never writes and no caller
// sets is an input of its own; an integer one is split by the comparisons that read it.
TEST(Unwritten, InstanceVariablesGlobalsAndIntegersAreFreeEach) {
  auto b = build(R"(FUNCTION_BLOCK Tank
  VAR_INPUT fill : BOOL; END_VAR
  VAR_OUTPUT full : BOOL; END_VAR
  VAR level : INT; END_VAR
  full := fill AND level > 90;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_GLOBAL stop : BOOL; END_VAR
  VAR a : Tank; b : Tank; alarm : BOOL; END_VAR
  a(fill := NOT stop);
  b(fill := TRUE);
  alarm := a.full AND b.full;
END_PROGRAM
)");
  ASSERT_TRUE(b.system);
  const auto& ts = *b.system;
  auto names = unwritten_names(ts);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"Main.a.level", "Main.b.level", "stop"}));
  EXPECT_TRUE(has_input(ts, "Main.a.level"));
  EXPECT_TRUE(has_input(ts, "Main.b.level"));
  EXPECT_TRUE(has_input(ts, "stop"));
  Runner r(ts);
  ASSERT_TRUE(r.cycle({{"Main.a.level", 95}, {"Main.b.level", 95}}));
  EXPECT_EQ(r["alarm"], 1);
  ASSERT_TRUE(r.cycle({{"Main.a.level", 95}, {"Main.b.level", 95}, {"stop", 1}}));
  EXPECT_EQ(r["alarm"], 0);
  ASSERT_TRUE(r.cycle({{"Main.a.level", 95}, {"Main.b.level", 10}}));
  EXPECT_EQ(r["alarm"], 0);
}

// An SFC flag that nothing sets stays FALSE: free, a reset at any cycle would hide every
// deadlock of the chart (docs/semantics.md 1.8).
TEST(Unwritten, AnSfcFlagNothingSetsStaysFalse) {
  auto b = build(R"(PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR SFCReset : BOOL; END_VAR
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
  TRANSITION FROM S1 TO S0 := FALSE; END_TRANSITION
END_PROGRAM
)");
  ASSERT_TRUE(b.system);
  EXPECT_TRUE(unwritten_names(*b.system).empty());
  EXPECT_FALSE(has_input(*b.system, "SFCReset"));
  Runner r(*b.system);
  ASSERT_TRUE(r.cycle({{"go", 1}}));
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["S1"], 1);  // never reset
}

// A duration read from a variable stays its initial value (sfcv needs constant durations).
TEST(Unwritten, ADurationVariableKeepsItsValue) {
  auto b = build(R"(PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR delay : TIME := T#2s; t : TON; done : BOOL; END_VAR
  t(IN := go, PT := delay);
  done := t.Q;
END_PROGRAM
)");
  ASSERT_TRUE(b.system);
  EXPECT_TRUE(unwritten_names(*b.system).empty());
  EXPECT_FALSE(has_input(*b.system, "delay"));
}

}  // namespace
}  // namespace sfcv::test

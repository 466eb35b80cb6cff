// Idioms of the real TwinCAT exports (VerifAPS xPPU 15-23, issue 45): NOT on integers and a
// timer's PT and ET read by the program (docs/semantics.md 1.6 and 1.9.1). Small self-written
// programs that mimic the exports, never the public files.

#include "io/load.hpp"
#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

struct Built {
  semantics::TransitionSystemPtr ts;
  std::string diagnostics;
};

Built build_text(const std::string& text, semantics::Iec61131Options options = {}) {
  auto loaded = io::load_iec_text(text, "idioms.st");
  EXPECT_TRUE(loaded.ok());
  Built b;
  if (!loaded.ok()) return b;
  model::Diagnostics diags;
  b.ts = semantics::make_iec61131_system(*loaded.project, options, diags);
  for (const auto& d : diags) b.diagnostics += d.str() + "\n";
  return b;
}

// IEC 61131-3 (bitwise Boolean functions): NOT is the bit-by-bit complement of its operand;
// CODESYS and TwinCAT apply it to the integer types too, at the type's width in two's
// complement: NOT INT#5 = -6 (16#0005 -> 16#FFFA), NOT INT#-32768 = 32767, NOT SINT#127 =
// -128, NOT UINT#0 = 65535, NOT USINT#1 = 254. (The BYTE/WORD/DWORD case is unchanged.)
TEST(IntegerNot, IsTheBitwiseComplementAtTheTypesWidth) {
  const auto b = build_text(R"(
FUNCTION Zero : UINT
  VAR_INPUT v : BOOL; END_VAR
  Zero := 0;
END_FUNCTION
PROGRAM Main
  VAR_OUTPUT a, b, c : INT; s : SINT; d : DINT; u : UINT; y : USINT; w : WORD; END_VAR
  VAR five, low : INT; top : SINT; big : DINT; one : USINT; v : WORD; END_VAR
  five := 5; low := -32768; top := 127; big := 100000; one := 1; v := 16#0005;
  a := NOT five;
  b := NOT low;
  c := NOT (five + 1);
  s := NOT top;
  d := NOT big;
  u := NOT Zero(TRUE);
  y := NOT one;
  w := NOT v;
END_PROGRAM
)");
  ASSERT_TRUE(b.ts) << b.diagnostics;
  Runner r(*b.ts);
  ASSERT_TRUE(r.cycle()) << r.error;
  EXPECT_EQ(r["a"], -6);
  EXPECT_EQ(r["b"], 32767);
  EXPECT_EQ(r["c"], -7);
  EXPECT_EQ(r["s"], -128);
  EXPECT_EQ(r["d"], -100001);
  EXPECT_EQ(r["u"], 65535);
  EXPECT_EQ(r["y"], 254);
  EXPECT_EQ(r["w"], 0xFFFA);
}

// `NOT x >= k` is `(NOT x) >= k` (NOT binds tighter than a comparison): xPPU 15 writes
// `NOT UltrasonicSensor.AI_UltraSonic >= 15200`. Read so, with a warning that names the
// reading; an operand whose width sfcv cannot tell (an unsigned subrange) is refused.
TEST(IntegerNot, BindsTighterThanAComparisonAndSaysSo) {
  const auto b = build_text(R"(
FUNCTION_BLOCK Sensor
  VAR_INPUT AI : INT; END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_OUTPUT far : BOOL; END_VAR
  VAR us : Sensor; END_VAR
  us(AI := 0);
  far := NOT us.AI >= 15200;
END_PROGRAM
)");
  ASSERT_TRUE(b.ts) << b.diagnostics;
  EXPECT_NE(b.diagnostics.find("warning: 'NOT us.AI >= 15200' compares the bitwise complement of "
                               "us.AI"),
            std::string::npos)
      << b.diagnostics;
  EXPECT_NE(b.diagnostics.find("write NOT (us.AI >= 15200)"), std::string::npos);
  Runner r(*b.ts);
  ASSERT_TRUE(r.cycle()) << r.error;
  EXPECT_EQ(r["far"], 0);  // NOT 0 = -1, below 15200 (NOT (0 >= 15200) would be TRUE)

  const auto refused = build_text(R"(
PROGRAM Main
  VAR_OUTPUT x : INT; END_VAR
  VAR p : UINT(0..100); END_VAR
  x := NOT p;
END_PROGRAM
)");
  EXPECT_FALSE(refused.ts);
  EXPECT_NE(refused.diagnostics.find("'NOT p': bitwise NOT needs an operand whose type"),
            std::string::npos)
      << refused.diagnostics;
}

// A timer's PT is the PT of its last call (an input of the instance keeps its value between
// calls, T#0s before any): here T#0s, then T#20ms, then T#0s from CODESYS's reset idiom
// `t(IN := FALSE, PT := T#0MS)`. Both time modes.
TEST(TimerReads, PtIsThePtOfTheLastCall) {
  const char* text = R"(
PROGRAM Main
  VAR_INPUT go, call : BOOL; END_VAR
  VAR_OUTPUT pt : TIME; END_VAR
  VAR t : TON; END_VAR
  pt := t.PT;
  IF call THEN
    IF go THEN t(IN := TRUE, PT := T#20ms); ELSE t(IN := FALSE, PT := T#0ms); END_IF;
  END_IF;
END_PROGRAM
)";
  for (const auto& options : {semantics::Iec61131Options{}, discrete(10)}) {
    const auto b = build_text(text, options);
    ASSERT_TRUE(b.ts) << b.diagnostics;
    Runner r(*b.ts);
    std::string seen;
    const std::pair<int, int> in[] = {{0, 0}, {1, 1}, {0, 0}, {0, 1}, {0, 0}};
    for (const auto& [go, call] : in) {
      ASSERT_TRUE(r.cycle({{"go", go}, {"call", call}})) << r.error;
      seen += std::to_string(r["pt"]) + " ";
    }
    EXPECT_EQ(seen, "0 0 20 20 0 ");  // read before the call of the cycle
  }
}

// Abstract time, TwinCAT's blinking lamp (xPPU 19-23): ET is 0 while the timer holds no time,
// PT once it expired, and while it runs any value below PT, chosen by the pseudo-input
// `et:Main.Timer` (0..PT-1): both lamp colours are possible while it runs.
TEST(TimerReads, AbstractEtIsZeroIdleBelowPtRunningAndPtExpired) {
  const auto b = build_text(R"(
PROGRAM Main
  VAR_OUTPUT green : BOOL; et : TIME; END_VAR
  VAR Timer : TON; t : TIME := T#1s500ms; END_VAR
  Timer(IN := NOT Timer.Q, PT := t);
  et := Timer.ET;
  green := Timer.ET < Timer.PT / 2;
END_PROGRAM
)");
  ASSERT_TRUE(b.ts) << b.diagnostics;
  const auto et = input_index(*b.ts, "et:Main.Timer");
  EXPECT_EQ(b.ts->inputs()[et].type.lo, 0);
  EXPECT_EQ(b.ts->inputs()[et].type.hi, 1499);
  Runner r(*b.ts);
  ASSERT_TRUE(r.cycle({{"et:Main.Timer", 1400}})) << r.error;  // started: running
  EXPECT_EQ(r["et"], 1400);
  EXPECT_EQ(r["green"], 0);
  ASSERT_TRUE(r.cycle({{"et:Main.Timer", 100}})) << r.error;
  EXPECT_EQ(r["et"], 100);
  EXPECT_EQ(r["green"], 1);
  ASSERT_TRUE(r.cycle({{"timeout:Main.Timer", 1}})) << r.error;  // expires: ET = PT
  EXPECT_EQ(r["et"], 1500);
  EXPECT_EQ(r["green"], 0);
  ASSERT_TRUE(r.cycle({{"et:Main.Timer", 700}})) << r.error;  // IN = NOT Q = FALSE: idle
  EXPECT_EQ(r["et"], 0);
  EXPECT_EQ(r["green"], 1);
}

// The same lamp in discrete time (10 ms cycle, PT = T#40ms): ET = 0, 10, 20, 30, 40, then the
// expired timer is called with IN = FALSE (ET = 0) and restarts; green while ET < 20 ms.
TEST(TimerReads, DiscreteBlinkingLamp) {
  const auto b = build_text(R"(
PROGRAM Main
  VAR_OUTPUT green : BOOL; END_VAR
  VAR Timer : TON; END_VAR
  Timer(IN := NOT Timer.Q, PT := T#40ms);
  green := Timer.ET < Timer.PT / 2;
END_PROGRAM
)",
                            discrete(10));
  ASSERT_TRUE(b.ts) << b.diagnostics;
  Runner r(*b.ts);
  std::string seen;
  for (int i = 0; i < 8; ++i) {
    ASSERT_TRUE(r.cycle()) << r.error;
    seen += std::to_string(r["green"]);
  }
  EXPECT_EQ(seen, "11000111");
}

// TwinCAT writes calls through the absolute instance path (xPPU 17's `MAIN.xPPU();`, PLC
// Control 3.5.6.1's `Main.XPPU.Crane.ACT_PickUpWP();`, also in another case): the instance, or
// the action of the instance, that the path names from the program, as the short path would.
TEST(AbsoluteInstancePaths, CallTheInstanceOrActionThePathNames) {
  const auto b = build_text(R"(
FUNCTION_BLOCK Motor
  VAR_OUTPUT on : BOOL; END_VAR
  ACTION ACT_On : on := TRUE; END_ACTION
  ACTION ACT_Off : on := FALSE; END_ACTION
END_FUNCTION_BLOCK
FUNCTION_BLOCK Cell
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT ticks : INT(0..3); END_VAR
  VAR m : Motor; END_VAR
  IF ticks < 3 THEN ticks := ticks + 1; END_IF;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT on : BOOL; END_VAR
  VAR cell : Cell; END_VAR
  MAIN.cell(go := go);
  IF go THEN Main.CELL.m.ACT_On(); ELSE MAIN.cell.M.act_off(); END_IF;
  on := cell.m.on;
END_PROGRAM
)");
  ASSERT_TRUE(b.ts) << b.diagnostics;
  Runner r(*b.ts);
  ASSERT_TRUE(r.cycle({{"go", 1}})) << r.error;
  EXPECT_EQ(r["on"], 1);
  EXPECT_EQ(r["Main.cell.ticks"], 1);
  ASSERT_TRUE(r.cycle({{"go", 0}})) << r.error;
  EXPECT_EQ(r["on"], 0);
  EXPECT_EQ(r["Main.cell.ticks"], 2);
}

// When the project's program cannot be run and several POUs have an SFC body, the error says
// why the program is not run before asking for --pou (xPPU 17 said only "several POUs").
TEST(AbsoluteInstancePaths, TheErrorSaysWhyTheProgramIsNotRun) {
  auto loaded = io::load_iec_text(R"(
FUNCTION_BLOCK A
  VAR_INPUT go : BOOL; END_VAR
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
END_FUNCTION_BLOCK
FUNCTION_BLOCK B
  VAR_INPUT go : BOOL; END_VAR
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR a : A; b : B; END_VAR
  a(go := TRUE);
END_PROGRAM
)",
                                  "select.st");
  ASSERT_TRUE(loaded.ok());
  auto& main = loaded.project->pous.back();
  main.body_unsupported = true;  // as a reader marks a body it cannot read
  main.unsupported_reason = "call of 'X.y'";
  model::Diagnostics diags;
  EXPECT_FALSE(semantics::make_iec61131_system(*loaded.project, {}, diags));
  ASSERT_FALSE(diags.empty());
  EXPECT_NE(diags.front().message.find("program 'Main' cannot be run (its body is not modelled: "
                                       "call of 'X.y'); several POUs have an SFC body (A, B): "
                                       "choose the one(s) to run with --pou"),
            std::string::npos)
      << diags.front().message;
}

}  // namespace
}  // namespace sfcv::test

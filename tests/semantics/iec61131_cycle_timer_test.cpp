// Timers read the cycle clock (docs/semantics.md §1.6), written from IEC 61131-3's definition of
// TON, TOF and TP: ET is the time since IN rose (TON, TP) or fell (TOF), whatever happened in
// between; Q is ET >= PT for TON, ET < PT for TOF, the pulse for TP. On a PLC a timer instance
// reads the clock when it is called, so an instance that is not called in some cycles (an IF
// not taken, an action of a step that was left) has aged by those cycles at its next call, and
// one called twice in a cycle reads the same time twice. Q and ET change only when it is
// called. Every expectation below failed on the old reading, where a timer aged by one cycle
// per call.

#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

struct Row {
  std::string q, et;
};

/// Runs `cycles` cycles with inputs `c` (call the timer) and `a` (its IN), 10 ms cycles.
Row run(const semantics::TransitionSystem& ts, const std::string& c, const std::string& a) {
  Runner r(ts);
  Row out;
  for (std::size_t k = 0; k < c.size(); ++k) {
    EXPECT_TRUE(r.cycle({{"c", c[k] - '0'}, {"a", a[k] - '0'}})) << r.error;
    out.q += std::to_string(r["q"]);
    out.et += std::to_string(r["et"]) + " ";
  }
  return out;
}

semantics::TransitionSystemPtr conditional(const std::string& type) {
  IecBuilder b("VAR_INPUT a, c : BOOL; END_VAR VAR_OUTPUT q : BOOL; et : TIME; END_VAR VAR t : " +
               type + "; END_VAR");
  b.step("S1", true);
  b.body("IF c THEN t(IN := a, PT := T#30ms); END_IF; q := t.Q; et := t.ET;");
  return b.build(discrete(10));
}

// (c) A TON inside an IF branch not taken for some cycles: started in cycle 1, not called in
// cycles 2 and 3 (Q and ET keep the values of the last call), called in cycle 4, 30 ms after
// IN rose: Q. The old reading saw its second call and ET = 10 ms.
TEST(Iec61131CycleTimers, TonNotCalledForSomeCyclesStillAges) {
  auto ts = conditional("TON");
  ASSERT_TRUE(ts);
  const auto r = run(*ts, "100111", "111111");
  EXPECT_EQ(r.q, "000111");
  EXPECT_EQ(r.et, "0 0 0 30 30 30 ");
  // IN fell at a call: the next rise starts from 0 again, however long ago the first was.
  const auto again = run(*ts, "11001", "10001");
  EXPECT_EQ(again.q, "00000");
  EXPECT_EQ(again.et, "0 0 0 0 0 ");
}

// TOF: ET is the time since IN fell (cycle 2); called again in cycle 5, 30 ms later: Q falls.
TEST(Iec61131CycleTimers, TofNotCalledForSomeCyclesStillAges) {
  auto ts = conditional("TOF");
  ASSERT_TRUE(ts);
  const auto r = run(*ts, "110010", "100000");
  EXPECT_EQ(r.q, "111100");
  EXPECT_EQ(r.et, "0 0 0 0 30 30 ");
}

// TP: the pulse started in cycle 1 is over at the call of cycle 4 (30 ms later); ET stays PT
// while IN is held, and the pulse is not restarted by a level.
TEST(Iec61131CycleTimers, TpNotCalledForSomeCyclesStillAges) {
  auto ts = conditional("TP");
  ASSERT_TRUE(ts);
  const auto r = run(*ts, "100110", "111110");
  EXPECT_EQ(r.q, "111000");
  EXPECT_EQ(r.et, "0 0 0 30 30 30 ");
}

// (b) A TON called twice in one cycle with the same IN reads the same time twice: ET is 0,
// 10, 20, 30 ms in the four cycles after IN rose and Q comes in the 4th, as with one call. The
// old reading aged it twice per cycle (ET 10, 30, ... and Q in the 2nd cycle).
TEST(Iec61131CycleTimers, TonCalledTwiceInACycleAgesOnce) {
  IecBuilder b(
      "VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT q, q1 : BOOL; et, et1 : TIME; END_VAR "
      "VAR t : TON; END_VAR");
  b.step("S1", true);
  b.body(
      "t(IN := a, PT := T#30ms); q1 := t.Q; et1 := t.ET; t(IN := a, PT := T#30ms); q := t.Q; "
      "et := t.ET;");
  auto ts = b.build(discrete(10));
  ASSERT_TRUE(ts);
  Runner r(*ts);
  std::string q, et;
  for (int k = 0; k < 5; ++k) {
    ASSERT_TRUE(r.cycle({{"a", 1}}));
    q += std::to_string(r["q"]);
    et += std::to_string(r["et"]) + " ";
    EXPECT_EQ(r["q1"], r["q"]);  // both calls of a cycle read the same clock
    EXPECT_EQ(r["et1"], r["et"]);
  }
  EXPECT_EQ(q, "00011");
  EXPECT_EQ(et, "0 10 20 30 30 ");
}

// CODESYS's reset idiom (the PPU, shared corpus 12): `T(IN := FALSE, PT := T#0MS)` in one step,
// `T(IN := TRUE, PT := T#30MS)` in the next. The reset call stops the timer, so each visit of
// Wait lasts its 30 ms again, however long the timer sat unused in between; and a reset and a
// start in one cycle start it afresh.
TEST(Iec61131CycleTimers, CodesysResetIdiomRestartsTheTimer) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR Timer : TON; END_VAR");
  b.step("Init", true).step("Wait").step("Done");
  b.trans("Init", "Wait", "a").trans("Wait", "Done", "Timer.Q").trans("Done", "Init", "a");
  b.action_st("Reset", "Timer(IN := FALSE, PT := T#0MS);").assoc("Init", "Reset", "N");
  b.action_st("Delay", "Timer(IN := TRUE, PT := T#30MS);").assoc("Wait", "Delay", "N");
  auto ts = b.build(discrete(10));
  ASSERT_TRUE(ts);
  Runner r(*ts);
  std::string wait;
  for (char v : std::string("10000001100000")) {
    ASSERT_TRUE(r.cycle({{"a", v - '0'}}));
    wait += std::to_string(r["Wait"]);
  }
  // Wait is entered in cycle 1, its action starts the timer in cycle 2 and sees Q in cycle 5
  // (30 ms later), so Done is reached in cycle 5. Back in Init (cycle 8), the reset call stops
  // the timer in cycle 9, which enters Wait again: the second visit is as long as the first.
  EXPECT_EQ(wait, "11110000111100");
}

// TwinCAT's xPPU 14 (issue 45): one TON called with PT := T#0ms in one step and a positive PT
// in the next. IEC 61131-3: Q := IN AND ET >= PT, ET counting from the rise of IN whatever PT
// a call gives. So the PT := 0 call sets Q at once, and the timer, started there, reaches the
// 30 ms of the next step's call counting from that start: Done in cycle 4, not 5.
TEST(Iec61131CycleTimers, OneTonWithAZeroAndAPositivePt) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR Timer : TON; END_VAR");
  b.step("Now", true).step("Wait").step("Done");
  b.trans("Now", "Wait", "Timer.Q").trans("Wait", "Done", "Timer.Q").trans("Done", "Now", "a");
  b.action_st("Zero", "Timer(IN := TRUE, PT := T#0ms);").assoc("Now", "Zero", "N");
  b.action_st("Delay", "Timer(IN := TRUE, PT := T#30ms);").assoc("Wait", "Delay", "N");
  auto ts = b.build(discrete(10));
  ASSERT_TRUE(ts);
  Runner r(*ts);
  std::string now, done;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(r.cycle({{"a", 0}}));
    now += std::to_string(r["Now"]);
    done += std::to_string(r["Done"]);
  }
  EXPECT_EQ(now, "00000");   // left in cycle 1: the PT := 0 call's Q is IN at once
  EXPECT_EQ(done, "00011");  // cycle 4: 30 ms after the start in cycle 1 (not cycle 5)
  // Abstract time builds too (it refused "zero and positive" before).
  auto abstract = b.build();
  EXPECT_TRUE(abstract);
  // ET after a PT := 0 call would be 0, not the running timer's: refused by name.
  IecBuilder c(
      "VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT et : TIME; END_VAR VAR Timer : TON; END_VAR");
  c.step("Now", true).step("Wait").trans("Now", "Wait", "Timer.Q").trans("Wait", "Now", "a");
  c.action_st("Zero", "Timer(IN := TRUE, PT := T#0ms);").assoc("Now", "Zero", "N");
  c.action_st("Delay", "Timer(IN := TRUE, PT := T#30ms); et := Timer.ET;")
      .assoc("Wait", "Delay", "N");
  EXPECT_NE(c.build_error(discrete(10)).find("ET after such a call is not modelled"),
            std::string::npos);
}

// (a) A TON in an N action of a step that is left and re-entered: the instance is not called
// while the step is inactive, and its last call had IN = TRUE, so it keeps running (a PLC keeps
// its start time); called again, it shows the time since the first start. Q and ET show the
// last call's values while it is not called.
TEST(Iec61131CycleTimers, TonInAnActionOfAStepLeftAndReEntered) {
  IecBuilder b(
      "VAR_INPUT a, b : BOOL; END_VAR VAR_OUTPUT q : BOOL; et : TIME; END_VAR "
      "VAR t : TON; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
  b.action_st("A", "t(IN := TRUE, PT := T#50ms);").assoc("S1", "A", "N");
  b.body("q := t.Q; et := t.ET;");
  auto ts = b.build(discrete(10));
  ASSERT_TRUE(ts);
  Runner r(*ts);
  // Cycles 1-3 in S1 (calls at 0, 10, 20 ms after the start; a leaves in cycle 3), cycles 4-6
  // in S2 (b returns in cycle 6), cycle 7 in S1 again: 60 ms since the start, Q, ET = PT. The
  // body reads Q and ET before the action runs, so each row shows the previous call's values.
  const std::string a = "0010000", bb = "0000010";
  std::string q, et;
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_TRUE(r.cycle({{"a", a[k] - '0'}, {"b", bb[k] - '0'}}));
    q += std::to_string(r["q"]);
    et += std::to_string(r["et"]) + " ";
  }
  ASSERT_TRUE(r.cycle());
  q += std::to_string(r["q"]);
  et += std::to_string(r["et"]) + " ";
  EXPECT_EQ(q, "00000001");
  EXPECT_EQ(et, "0 0 10 20 20 20 20 50 ");
}

// Abstract time: a timer cannot expire in the cycle it starts, however often it is called in
// that cycle (the old reading let the second call read the timeout input).
TEST(Iec61131CycleTimers, AbstractTimerCalledTwiceCannotExpireInItsFirstCycle) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT q : BOOL; END_VAR VAR t : TON; END_VAR");
  b.step("S1", true);
  b.body("t(IN := a, PT := T#1s); t(IN := a, PT := T#1s); q := t.Q;");
  auto ts = b.build();
  ASSERT_TRUE(ts);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}, {"timeout:MAIN.t", 1}}));
  EXPECT_EQ(r["q"], 0);
  ASSERT_TRUE(r.cycle({{"a", 1}, {"timeout:MAIN.t", 1}}));
  EXPECT_EQ(r["q"], 1);
  // Abstract time needs no clock for an instance that is not called: a later call may expire.
  IecBuilder c("VAR_INPUT a, c : BOOL; END_VAR VAR_OUTPUT q : BOOL; END_VAR VAR t : TON; END_VAR");
  c.step("S1", true);
  c.body("IF c THEN t(IN := a, PT := T#1s); END_IF; q := t.Q;");
  auto ts2 = c.build();
  ASSERT_TRUE(ts2);
  Runner r2(*ts2);
  ASSERT_TRUE(r2.cycle({{"a", 1}, {"c", 1}}));
  ASSERT_TRUE(r2.cycle({{"a", 1}, {"c", 0}, {"timeout:MAIN.t", 1}}));
  EXPECT_EQ(r2["q"], 0);  // not called: Q unchanged
  ASSERT_TRUE(r2.cycle({{"a", 1}, {"c", 1}, {"timeout:MAIN.t", 1}}));
  EXPECT_EQ(r2["q"], 1);
}

}  // namespace
}  // namespace sfcv::test

#include "engine/external/circuit_export.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "engine/external/spin_runner.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {
namespace {

using semantics::Aig;

// q' = x; p' = q; r' = r & x (r starts 0, so stays 0). "just_rose" = q & !p is reachable
// (x = 1, then one cycle later), "r" is not; under the assumption x = 0, neither is.
CircuitExport follower(bool with_assumption) {
  CircuitExport m;
  Aig& aig = m.aig;
  const auto x = aig.add_input("x");
  const auto q = aig.add_latch("MAIN.q");
  const auto p = aig.add_latch("p");
  const auto r = aig.add_latch("r");
  aig.set_next(0, x);
  aig.set_next(1, q);
  aig.set_next(2, aig.make_and(r, x));
  aig.add_output("MAIN.q", q);
  aig.add_output("both", aig.make_and(q, p));
  aig.add_bad("just_rose", aig.make_and(q, Aig::make_not(p)));
  aig.add_bad("r", r);
  if (with_assumption) aig.add_constraint("x_stays_low", Aig::make_not(x));
  m.header = {"test circuit"};
  m.latch_comments = {"step MAIN.q ready", "latch p", "latch r"};
  m.input_comments = {"input x"};
  m.ctl = {{"q_reachable", "EF {0}"}, {"both", "AG !{1}"}};  // outputs MAIN.q and both
  return m;
}

TEST(NusmvExport, DeclaresInputsAsIvarAndPropertiesAsSpecs) {
  std::ostringstream out;
  write_nusmv(out, follower(false));
  EXPECT_EQ(out.str(),
            "-- test circuit\n"
            "MODULE main\n"
            "IVAR\n"
            "  in_x : boolean;  -- input x\n"
            "VAR\n"
            "  s_MAIN_q : boolean;  -- step MAIN.q ready\n"
            "  s_p : boolean;  -- latch p\n"
            "  s_r : boolean;  -- latch r\n"
            "DEFINE\n"
            "  g_5 := in_x & s_r;\n"
            "  g_6 := s_MAIN_q & s_p;\n"
            "  g_7 := s_MAIN_q & !s_p;\n"
            "  o_MAIN_q := s_MAIN_q;  -- MAIN.q\n"
            "  o_both := g_6;  -- both\n"
            "ASSIGN\n"
            "  init(s_MAIN_q) := FALSE;\n"
            "  next(s_MAIN_q) := in_x;\n"
            "  init(s_p) := FALSE;\n"
            "  next(s_p) := s_MAIN_q;\n"
            "  init(s_r) := FALSE;\n"
            "  next(s_r) := g_5;\n"
            "INVARSPEC NAME p_just_rose := !(g_7);\n"
            "INVARSPEC NAME p_r := !(s_r);\n"
            "CTLSPEC NAME p_q_reachable := EF o_MAIN_q;\n"
            "CTLSPEC NAME p_both := AG !o_both;\n");
}

// A latch, an output and a property all called "p", and an output that is a latch's negation
// under the latch's own name (a nested step's activity): one identifier each.
TEST(NusmvExport, GivesEveryKindOfBitItsOwnIdentifier) {
  CircuitExport m;
  const auto x = m.aig.add_input("p");
  const auto p = m.aig.add_latch("p");
  m.aig.set_next(0, x);
  m.aig.add_output("p", Aig::make_not(p));
  m.aig.add_bad("p", p);
  m.ctl = {{"p", "EF {0}"}};
  std::ostringstream out;
  write_nusmv(out, m);
  const std::string s = out.str();
  for (const char* line : {"  in_p : boolean;", "  s_p : boolean;", "  o_p := !s_p;",
                           "INVARSPEC NAME p_p := !(s_p);", "CTLSPEC NAME p_p_2 := EF o_p;"})
    EXPECT_NE(s.find(line), std::string::npos) << line << "\n" << s;
}

TEST(CasmvExport, UsesTheSeedsDefaultCaseForm) {
  std::ostringstream out;
  write_casmv(out, follower(false));
  const std::string s = out.str();
  EXPECT_NE(s.find("module main()\n{\n  input in_x : boolean;  -- input x\n"), std::string::npos)
      << s;
  EXPECT_NE(s.find("  default next(s_MAIN_q) := s_MAIN_q;\n  in case {\n"
                   "    ~s_MAIN_q & in_x : next(s_MAIN_q) := 1;\n"
                   "    s_MAIN_q & ~in_x : next(s_MAIN_q) := 0;\n  }\n"),
            std::string::npos)
      << s;
  // r can only be reset: its set condition r & x under r = 0 folds to FALSE.
  EXPECT_NE(
      s.find("  default next(s_r) := s_r;\n  in case {\n    s_r & ~in_x : next(s_r) := 0;\n  }\n"),
      std::string::npos)
      << s;
  EXPECT_NE(s.find("p_just_rose : assert G ~g_7;"), std::string::npos) << s;
  EXPECT_NE(s.find("SPEC EF (s_MAIN_q);  -- q_reachable"), std::string::npos) << s;
}

TEST(PromelaExport, RefusesInvariantsThatReadInputs) {
  auto m = follower(false);
  m.aig.add_bad("reads_x", m.aig.inputs()[0].literal);
  std::ostringstream out;
  EXPECT_THROW(write_promela(out, m, 2), sfcv::UnsupportedConstruct);
}

TEST(PromelaExport, KeepsOnlyLatchesInTheStateVector) {
  std::ostringstream out;
  write_promela(out, follower(true), 0);
  const std::string s = out.str();
  EXPECT_NE(s.find("bit s_MAIN_q = 0;"), std::string::npos) << s;
  EXPECT_NE(s.find("hidden byte in_x;"), std::string::npos);
  EXPECT_NE(s.find("assert(!(g_7));"), std::string::npos) << s;
  EXPECT_EQ(s.find("assert(!(s_r));"), std::string::npos);  // only the chosen property
  EXPECT_NE(s.find("goto end_excluded"), std::string::npos);
}

TEST(PromelaExport, AvoidsTheNamesOfSpinsGeneratedVerifier) {
  // (No gates at all: an empty d_step was a Spin syntax error.)
  // A chart output Q0 clashed with pan.h's channel struct Q0 (found by the confirmation test).
  CircuitExport m;
  const auto x = m.aig.add_input("P0");
  const auto q = m.aig.add_latch("Q0");
  m.aig.set_next(0, x);
  m.aig.add_bad("q", q);
  std::ostringstream out;
  write_promela(out, m, 0);
  // (The s_ prefix of latches keeps them apart from those names; the reserved list stays.)
  EXPECT_NE(out.str().find("bit s_Q0 = 0;"), std::string::npos) << out.str();
  const auto spin = find_spin();
  if (!spin) GTEST_SKIP() << "spin not installed";
  const auto v = check_with_spin(*spin, m, 0);
  EXPECT_EQ(v.kind, SpinVerdict::Kind::Violated) << v.log;
}

// Spin refuses a d_step of more than 2048 statements (MAXDSTEP; 1024 in older Spins): "d_step
// sequence too long", on the export of every xPPU scenario (about 16,000 gates). The cycle is
// written as d_steps of at most 1000 statements, and Spin verifies it.
TEST(PromelaExport, ALongCycleIsSplitIntoDStepsSpinAccepts) {
  CircuitExport m;
  const auto x = m.aig.add_input("x");
  const auto y = m.aig.add_input("y");
  const auto q = m.aig.add_latch("q");
  const auto r = m.aig.add_latch("r");
  m.aig.set_next(0, x);
  m.aig.set_next(1, y);
  auto chain = r;  // q & r, 2,500 gates deep: each gate reads the previous one
  for (int k = 0; k < 2500; ++k) chain = m.aig.make_and(chain, k % 2 ? q : m.aig.make_or(q, r));
  ASSERT_GT(m.aig.nodes().size(), 2500u);
  m.aig.add_bad("deep", chain);
  std::ostringstream out;
  write_promela(out, m, 0);
  std::istringstream lines(out.str());
  std::size_t in_step = 0, largest = 0, d_steps = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.find("d_step {") != std::string::npos) {
      ++d_steps;
      in_step = 0;
    } else if (line.find(" = ") != std::string::npos && line.find("bit ") == std::string::npos) {
      largest = std::max(largest, ++in_step);
    }
  }
  EXPECT_LE(largest, 1000u);
  EXPECT_GE(d_steps, 6u);  // the gates before the assertion, then the cycle: 3 + 3
  const auto spin = find_spin();
  if (!spin) GTEST_SKIP() << "spin not installed";
  const auto v = check_with_spin(*spin, m, 0);
  EXPECT_EQ(v.kind, SpinVerdict::Kind::Violated) << v.log;  // x and y, then q and r
}

TEST(SpinRunner, ConfirmsAndRefutesInvariants) {
  const auto spin = find_spin();
  if (!spin) GTEST_SKIP() << "spin not installed";
  const auto m = follower(false);
  const auto violated = check_with_spin(*spin, m, 0);
  ASSERT_EQ(violated.kind, SpinVerdict::Kind::Violated) << violated.log;
  // The shortest trail: x = 1 in the first cycle makes q rise; the assertion fails on the next
  // state, before its inputs are chosen.
  ASSERT_EQ(violated.frames.size(), 1u) << violated.log;
  EXPECT_TRUE(violated.frames[0][0]);
  const auto holds = check_with_spin(*spin, m, 1);
  EXPECT_EQ(holds.kind, SpinVerdict::Kind::Holds) << holds.log;
  // Under the assumption x = 0 forever, q never rises.
  const auto assumed = check_with_spin(*spin, follower(true), 0);
  EXPECT_EQ(assumed.kind, SpinVerdict::Kind::Holds) << assumed.log;
}

}  // namespace
}  // namespace sfcv::engine

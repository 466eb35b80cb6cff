#include "engine/external/aiger_writer.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "model/errors.hpp"

namespace sfcv::engine {
namespace {

using semantics::Aig;

// A latch q that follows input x: q' = x; bad = q & !x.
Aig follower() {
  Aig aig;
  const auto x = aig.add_input("x");
  const auto q = aig.add_latch("q", false);
  aig.set_next(0, x);
  aig.add_bad("q_and_not_x", aig.make_and(q, Aig::make_not(x)));
  return aig;
}

TEST(AigerWriter, AsciiMatchesTheFormat) {
  std::ostringstream out;
  write_aiger(out, follower(), AigerMode::Ascii, "made by a test");
  EXPECT_EQ(out.str(),
            "aag 3 1 1 0 1 1 0\n"
            "2\n"
            "4 2\n"
            "6\n"
            "6 4 3\n"
            "i0 x\n"
            "l0 q\n"
            "b0 q_and_not_x\n"
            "c\nmade by a test\n");
}

TEST(AigerWriter, BinaryEncodesGatesAsDeltas) {
  std::ostringstream out;
  write_aiger(out, follower(), AigerMode::Binary);
  const std::string s = out.str();
  const std::string header = "aig 3 1 1 0 1 1 0\n2\n6\n";
  ASSERT_EQ(s.substr(0, header.size()), header);
  // Gate 6 = 4 & 3 (q and not x): deltas 6-4 = 2 and 4-3 = 1.
  EXPECT_EQ(s[header.size()], '\x02');
  EXPECT_EQ(s[header.size() + 1], '\x01');
  EXPECT_EQ(s.substr(header.size() + 2, 5), "i0 x\n");
}

TEST(AigerWriter, InitialValueOneIsWritten) {
  Aig aig;
  aig.add_input("x");
  aig.add_latch("q", true);
  std::ostringstream out;
  write_aiger(out, aig, AigerMode::Ascii);
  EXPECT_NE(out.str().find("\n4 4 1\n"), std::string::npos) << out.str();
}

// A name borne by two bits (an input and the variable that keeps it, a Boolean action of an
// instance and its variable) names one of them: the later ones get #2, #3, and a name that
// already ends so stays apart. ABC refused the files ("Repeated CI names") before.
TEST(AigerWriter, EverySymbolOfTheTableIsUnique) {
  Aig aig;
  const auto x = aig.add_input("Lift.Extend");
  aig.add_latch("Lift.Extend");
  aig.add_latch("Lift.Extend");
  aig.add_latch("Lift.Extend#2");
  aig.add_output("Lift.Extend", x);
  const auto symbols = aiger_symbols(aig);
  EXPECT_EQ(symbols.inputs, std::vector<std::string>{"Lift.Extend"});
  EXPECT_EQ(symbols.latches,
            (std::vector<std::string>{"Lift.Extend#2", "Lift.Extend#3", "Lift.Extend#2#2"}));
  EXPECT_EQ(symbols.outputs, std::vector<std::string>{"Lift.Extend#4"});
  std::ostringstream out;
  write_aiger(out, aig, AigerMode::Ascii);
  EXPECT_NE(out.str().find("\nl1 Lift.Extend#3\n"), std::string::npos) << out.str();
}

TEST(AigerWriter, RefusesCircuitsWithoutInputs) {
  Aig aig;
  aig.add_latch("q");
  std::ostringstream out;
  EXPECT_THROW(write_aiger(out, aig, AigerMode::Binary), sfcv::UnsupportedConstruct);
}

}  // namespace
}  // namespace sfcv::engine

#include "engine/external/abc_runner.hpp"

namespace sfcv::engine {
namespace {

// ABC confirms verdicts on our binary export (skipped where ABC is not installed).
TEST(AbcRunner, ProvesAndRefutesInvariants) {
  const auto abc = find_abc();
  if (!abc) GTEST_SKIP() << "berkeley-abc not installed";
  Aig aig;
  const auto x = aig.add_input("x");
  const auto q = aig.add_latch("q");
  const auto r = aig.add_latch("r");
  aig.set_next(0, x);                   // q' = x
  aig.set_next(1, aig.make_and(r, x));  // r stays 0 forever
  aig.add_bad("q_and_not_x", aig.make_and(q, Aig::make_not(x)));
  aig.add_bad("r", r);

  const auto violated = check_with_abc(*abc, aig, 0);
  ASSERT_EQ(violated.kind, AbcVerdict::Kind::Violated) << violated.log;
  // The counterexample: x = 1 then x = 0.
  ASSERT_EQ(violated.frames.size(), 2u) << violated.log;
  EXPECT_TRUE(violated.frames[0][0]);
  EXPECT_FALSE(violated.frames[1][0]);

  const auto holds = check_with_abc(*abc, aig, 1);
  EXPECT_EQ(holds.kind, AbcVerdict::Kind::Holds) << holds.log;
  const auto bmc = check_with_abc(*abc, aig, 0, "bmc3 -F 5");
  EXPECT_EQ(bmc.kind, AbcVerdict::Kind::Violated) << bmc.log;
}

}  // namespace
}  // namespace sfcv::engine

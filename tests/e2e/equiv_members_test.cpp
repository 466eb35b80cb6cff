// sfcv equiv (issue 50, docs/equivalence.md): signals inside function block instances, named by
// their path (`inst.q`, `Program.inst.q`, through nested instances) in --outputs, --compare,
// --map and --ignore; and a Grafcet side refused with the reason.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// A latch instance `inst` whose outputs the program does not pass on: only `lamp := a` is a
// program output, so by default nothing of the latch is compared.
std::string latch_program(const std::string& inst, const std::string& body) {
  return "FUNCTION_BLOCK Latch\n  VAR_INPUT set, reset : BOOL; END_VAR\n"
         "  VAR_OUTPUT q : BOOL; busy : BOOL; END_VAR\n  " +
         body +
         "\nEND_FUNCTION_BLOCK\n"
         "PROGRAM Main\n  VAR_INPUT a, b : BOOL; END_VAR\n"
         "  VAR_OUTPUT lamp : BOOL; END_VAR\n  VAR " +
         inst + " : Latch; END_VAR\n  " + inst + "(set := a, reset := b);\n  lamp := a;\n" +
         "END_PROGRAM\n";
}

const std::string kSetWins =
    "IF set THEN q := TRUE; ELSIF reset THEN q := FALSE; END_IF; busy := set OR reset;";
const std::string kResetWins =
    "IF reset THEN q := FALSE; ELSIF set THEN q := TRUE; END_IF; busy := set OR reset;";
const std::string kBusyOnSet =
    "IF set THEN q := TRUE; ELSIF reset THEN q := FALSE; END_IF; busy := set;";

TEST(EquivMembers, InstanceOutputsAreComparedByPathAndPairedByMap) {
  const auto old_file = write_temp(latch_program("l", kSetWins), ".st");
  const auto renamed = write_temp(latch_program("k", kSetWins), ".st");
  const auto changed = write_temp(latch_program("k", kResetWins), ".st");
  // By default only the program's outputs: lamp is the same, the latch's change is not seen.
  auto r = run_sfcv("-q equiv " + old_file + " " + changed + " --engine explicit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // The instance's output by its path, NEW's instance paired by --map (path or qualified path).
  for (const std::string engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    r = run_sfcv("-q equiv " + old_file + " " + changed + " --outputs l.q --map l.q=k.q --engine " +
                 engine);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    // Set and reset together in the first cycle: OLD sets, NEW resets.
    EXPECT_NE(r.out.find("differ after 1 cycle(s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("l.q"), std::string::npos) << r.out;
    r = run_sfcv("-q equiv " + old_file + " " + renamed +
                 " --outputs Main.l.q --map Main.l.q=k.q --engine " + engine);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  // --map of the instance itself renames NEW's instance: its members follow.
  r = run_sfcv("-q equiv " + old_file + " " + renamed + " --outputs l.q,l.busy --map l=k");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // A path that names nothing is a usage error, never a verdict.
  r = run_sfcv("-q equiv " + old_file + " " + old_file + " --outputs l.nothing");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("no variable 'l.nothing'"), std::string::npos) << r.err;
}

TEST(EquivMembers, IgnoreLeavesAnInstanceMemberOut) {
  const auto old_file = write_temp(latch_program("l", kSetWins), ".st");
  const auto busy = write_temp(latch_program("l", kBusyOnSet), ".st");
  auto r = run_sfcv("-q equiv " + old_file + " " + busy + " --outputs l.q,l.busy --changed");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  r = run_sfcv("-q equiv " + old_file + " " + busy + " --outputs l.q,l.busy --ignore l.busy");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("-q equiv " + old_file + " " + busy + " --compare l.busy --ignore Main.l.busy");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv("-q equiv " + old_file + " " + busy + " --compare Main.l.busy");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

TEST(EquivMembers, MembersOfStandardBlocksAreRefused) {
  const std::string text =
      "PROGRAM Main\n  VAR_INPUT a : BOOL; END_VAR\n  VAR_OUTPUT lamp : BOOL; END_VAR\n"
      "  VAR t : TON; END_VAR\n  t(IN := a, PT := T#1s);\n  lamp := t.Q;\nEND_PROGRAM\n";
  const auto f = write_temp(text, ".st");
  const auto r = run_sfcv("-q equiv " + f + " " + f + " --outputs t.Q");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("standard TON instance t"), std::string::npos) << r.err;
}

// docs/equivalence.md, "Grafcet against IEC 61131-3 code": no lockstep correspondence is sound,
// so the Grafcet side is refused, and the message says why.
TEST(EquivMembers, AGrafcetSideIsRefusedWithTheReason) {
  const auto st = write_temp(latch_program("l", kSetWins), ".st");
  const auto g = write_temp(g7_chain_text(2), ".g7");
  for (const auto& cmd : {"-q equiv " + g + " " + st, "-q equiv " + st + " " + g}) {
    const auto r = run_sfcv(cmd);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("transient evolutions"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("equivalent"), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace sfcv::test

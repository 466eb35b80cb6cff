// IEC 60848 Grafcet on the SAT engines (issue 53, issue 45 item 2): EF over several initial
// situations decided from the initial situations kept as a predicate of the machine
// (docs/engines.md, "Grafcet on the SAT engines"), never a wrong verdict on any engine.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// The minimal case of issue 53: step 2 encloses G0, entered at its activation-linked step 10.
// X10 or X11 is active whenever X2 is, and X10 is reachable from each of the six initial
// situations (a, b, c free at the start). ic3 and kind answered "not checked" on EF X10 (the
// Grafcet has several initial situations) and on every standard check.
const std::string kLinked =
    "input a; input b; input c;\n"
    "grafcet Main { step 1 initial; step 2 encloses G0; transition 1: 1 -> 2 when a;\n"
    "  transition 2: 2 -> 1 when b; }\n"
    "grafcet G0 { step 10 linked; step 11; transition 3: 10 -> 11 when c;\n"
    "  transition 4: 11 -> 10 when !c; }\n";

TEST(GrafcetSat, IssueMinimalCaseHoldsOnEveryEngine) {
  const auto file = write_temp(kLinked, ".g7");
  for (const std::string engine : {"explicit", "bdd", "bmc", "kind", "ic3", "auto"}) {
    const auto r = run_sfcv("check " + file + " --engine " + engine +
                            " --ctl 'AG (X2 -> X10 | X11)' --ctl 'EF X10' --checks none"
                            " --trace none --depth 40 --timeout 20");
    EXPECT_EQ(r.out.find("violated"), std::string::npos) << engine << r.out << r.err;
    EXPECT_EQ(r.out.find("not checked"), std::string::npos) << engine << r.out << r.err;
    EXPECT_EQ(r.exit_code, engine == "bmc" ? 3 : 0)
        << engine << r.out << r.err;  // BMC proves nothing
    // The standard checks: decided on every engine (the SAT engines through their observers of
    // the transient evolutions; BMC too, since each step's reachability has a witness).
    const auto c = run_sfcv("check " + file + " --engine " + engine +
                            " --checks reachable,dead-transitions --trace none --timeout 20");
    EXPECT_EQ(c.out.find("violated"), std::string::npos) << engine << c.out << c.err;
    EXPECT_EQ(c.exit_code, 0) << engine << c.out << c.err;
    EXPECT_NE(c.out.find("all 4 steps are reachable"), std::string::npos) << engine << c.out;
    EXPECT_NE(c.out.find("all 4 transitions can fire"), std::string::npos) << engine << c.out;
  }
}

// EF p holds only if it holds in EVERY initial situation. Here the start stabilises in step 2
// when a is true and in step 3 when it is false (IEC 60848: the initial situation evolves
// under the initial inputs), and neither is left: EF X2 is violated (from a = FALSE), though a
// run to X2 exists. The counterexample is the initial situation that never reaches X2.
// Step 4 is never active (every engine's finding; the SAT engines' since their observers).
TEST(GrafcetSat, EfFailsFromOneInitialSituationOnly) {
  const auto file = write_temp(
      "input a; input b;\n"
      "grafcet G { step 1 initial; step 2; step 3; step 4;\n"
      "  transition t1: 1 -> 2 when a; transition t2: 1 -> 3 when !a;\n"
      "  transition t3: 2 -> 2 when b & !b; transition t4: 3 -> 4 when a & !a; }\n",
      ".g7");
  for (const char* engine : {"explicit", "bdd", "kind", "ic3"}) {
    const auto r = run_sfcv("check " + file + " --engine " + engine +
                            " --ctl 'EF X2' --ctl 'EF (X2 | X3)' --checks reachable --timeout 20");
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("EF X2         violated"), std::string::npos) << engine << r.out;
    EXPECT_NE(r.out.find("EF (X2 | X3)  holds"), std::string::npos) << engine << r.out;
    EXPECT_NE(r.out.find("step X4 is never active"), std::string::npos) << engine << r.out;
  }
  // BMC finds the run to X2 but cannot show that X2 is unreachable from a = FALSE.
  const auto b = run_sfcv("check " + file + " --engine bmc --depth 20 --ctl 'EF X2' --checks none");
  EXPECT_EQ(b.exit_code, 3) << b.out << b.err;
  EXPECT_EQ(b.out.find("holds"), std::string::npos) << b.out;
}

// IEC 60848 (docs/semantics.md 2.11): a situation whose evolution leaves a transition enabled
// (upstream steps active, receptivity true) evolves again at once, and a cycle of such
// evolutions never reaches a stable situation: the instability check. Here a true `a` clears
// 1 -> 2 and then 2 -> 1 for ever, both at the start (a true initially) and after `a` rises in
// {1}. The SAT engines find it as a configuration repeated within one event; with 2 -> 1 on
// `!a` every evolution stabilises, which ic3 and kind prove.
TEST(GrafcetSat, AnEventThatNeverStabilisesIsAnInstabilityOnEveryEngine) {
  const auto unstable = write_temp(
      "input a;\n"
      "grafcet G { step 1 initial; step 2;\n"
      "  transition t1: 1 -> 2 when a; transition t2: 2 -> 1 when a; }\n",
      ".g7");
  for (const char* engine : {"explicit", "bdd", "bmc", "kind", "ic3"}) {
    const auto r = run_sfcv("check " + unstable + " --engine " + engine +
                            " --checks instability --timeout 20");
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("instability: "), std::string::npos) << engine << r.out;
  }
  // A start that never stabilises, whatever the inputs (5 -> 6 -> 5 on TRUE): no stable
  // situation exists, and the finding names the initial valuation, as `sfcv simulate` reads it.
  const auto start_file = write_temp(
      "input a;\n"
      "grafcet G { step 1 initial; step 2; transition t1: 1 -> 2 when a; }\n"
      "grafcet H { step 5 initial; step 6;\n"
      "  transition t5: 5 -> 6 when TRUE; transition t6: 6 -> 5 when TRUE; }\n",
      ".g7");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    const auto start =
        run_sfcv("check " + start_file + " --engine " + engine + " --checks instability");
    EXPECT_EQ(start.exit_code, 1) << engine << start.out << start.err;
    EXPECT_NE(start.out.find("nstability: "), std::string::npos) << engine << start.out;
  }
  const auto start = run_sfcv("check " + start_file + " --engine ic3 --checks instability");
  EXPECT_NE(start.out.find("under some initial input valuation the transient evolutions never "
                           "reach a stable situation (initial inputs "),
            std::string::npos)
      << start.out;

  const auto stable = write_temp(
      "input a;\n"
      "grafcet G { step 1 initial; step 2;\n"
      "  transition t1: 1 -> 2 when a; transition t2: 2 -> 1 when !a; }\n",
      ".g7");
  for (const char* engine : {"explicit", "bdd", "kind", "ic3"}) {
    const auto r =
        run_sfcv("check " + stable + " --engine " + engine + " --checks instability --timeout 20");
    EXPECT_EQ(r.exit_code, 0) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("every evolution reaches a stable situation"), std::string::npos)
        << engine << r.out;
  }
  const auto bmc = run_sfcv("check " + stable + " --engine bmc --checks instability");
  EXPECT_EQ(bmc.exit_code, 3) << bmc.out << bmc.err;  // BMC proves nothing
}

// The AG EF checks on a Grafcet by ic3, as on IEC 61131-3: a situation on a run from which
// IC3 proves the goal unreachable is a violation (the explicit engine's finding); no such
// situation is unknown, never "holds". Step 1 is left for the loop 2 <-> 3 and never comes
// back; step 9 of a second grafcet is reached and stops everything there.
TEST(GrafcetSat, Ic3FindsTheDeadlocksOfAGrafcet) {
  const auto loop = write_temp(
      "input a; input b;\n"
      "grafcet G { step 1 initial; step 2; step 3;\n"
      "  transition t1: 1 -> 2 when a; transition t2: 2 -> 3 when b;\n"
      "  transition t3: 3 -> 2 when !b; }\n",
      ".g7");
  for (const char* engine : {"explicit", "ic3"}) {
    const auto r =
        run_sfcv("check " + loop + " --engine " + engine + " --checks local-deadlock --timeout 20");
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("step X1, once inactive, never becomes active again"), std::string::npos)
        << engine << r.out;
  }
  // Steps 2 and 3 can always be re-entered: the explicit engine proves it, ic3 finds no
  // violation and says unknown.
  const auto reentry =
      run_sfcv("check " + loop + " --engine ic3 --checks reentry,global-deadlock --timeout 20");
  EXPECT_EQ(reentry.exit_code, 3) << reentry.out << reentry.err;
  EXPECT_EQ(reentry.out.find("violated"), std::string::npos) << reentry.out;
  EXPECT_NE(reentry.out.find("no situation found from which the property fails"), std::string::npos)
      << reentry.out;

  const auto stop = write_temp(
      "input a; input b;\n"
      "grafcet G { step 1 initial; step 9;\n"
      "  transition t1: 1 -> 9 when a; transition t2: 1 -> 1 when b; }\n",
      ".g7");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    const auto r = run_sfcv("check " + stop + " --engine " + engine +
                            " --checks global-deadlock,reentry --timeout 20");
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_NE(r.out.find("no transition can ever fire again, whatever the inputs"),
              std::string::npos)
        << engine << r.out;
    EXPECT_NE(r.out.find("step X1: a reachable situation exists from which it can never become "
                         "active again"),
              std::string::npos)
        << engine << r.out;
  }
}

}  // namespace
}  // namespace sfcv::test

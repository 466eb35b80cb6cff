// The vendor dialects (docs/semantics.md 1.4a), each test written from the vendor's help:
// - CODESYS SFC help, "Processing Order in SFC": "CODESYS executes IEC actions at least two
//   times. The first time is when the step is activated, and the second time when the step is
//   deactivated (but not until the next cycle)"; the cycle runs the exit actions, the entry
//   actions, the step actions, then "the IEC actions in alphabetical order ... in two passes":
//   first those deactivated in this cycle, then the active ones.
// - CODESYS, "Qualifiers for Actions in SFC": P "executes the action exactly two times".
// - Beckhoff TwinCAT 3 help, "Processing order in SFC": the same rules.

#include <set>

#include "io/load.hpp"
#include "model/names.hpp"
#include "semantics/iec_builder.hpp"
#include "support/boolean_action_chart.hpp"

namespace sfcv::test {
namespace {

semantics::Iec61131Options dialect(semantics::VendorDialect d) {
  semantics::Iec61131Options o;
  semantics::set_dialect(o, d);
  return o;
}

// S1 -a-> S2 -b-> S1; S2 runs Count (`n := n + 1`) with qualifier `q`.
IecBuilder counting(const std::string& q) {
  IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR VAR_OUTPUT n : INT (0..7); END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
  b.action_st("Count", "IF n < 7 THEN n := n + 1; END_IF;").assoc("S2", "Count", q);
  return b;
}

TEST(Iec61131Dialect, AnIecActionRunsOnceMoreInTheCycleAfterItsStepIsLeft) {
  for (auto d : {semantics::VendorDialect::Codesys, semantics::VendorDialect::Twincat}) {
    SCOPED_TRACE(std::string(semantics::to_string(d)));
    auto b = counting("N");
    auto ts = b.build(dialect(d));
    Runner r(*ts);
    ASSERT_TRUE(r.cycle({{"a", 1}}));  // enters S2
    EXPECT_EQ(r["n"], 0);
    ASSERT_TRUE(r.cycle());  // Count runs
    EXPECT_EQ(r["n"], 1);
    ASSERT_TRUE(r.cycle({{"b", 1}}));  // Count runs, S2 is left
    EXPECT_EQ(r["n"], 2);
    EXPECT_EQ(r["S1"], 1);
    ASSERT_TRUE(r.cycle());  // the final call, "not until the next cycle"
    EXPECT_EQ(r["n"], 3);
    ASSERT_TRUE(r.cycle());
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["n"], 3);
  }
  // IEC 61131-3 (and S7-GRAPH, Rockwell's SFCLastScan DontScan): no final call.
  for (auto d : {semantics::VendorDialect::Iec, semantics::VendorDialect::Siemens,
                 semantics::VendorDialect::Rockwell}) {
    SCOPED_TRACE(std::string(semantics::to_string(d)));
    auto b = counting("N");
    auto ts = b.build(dialect(d));
    Runner r(*ts);
    ASSERT_TRUE(r.cycle({{"a", 1}}));
    ASSERT_TRUE(r.cycle());
    ASSERT_TRUE(r.cycle({{"b", 1}}));
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["n"], 2);
  }
}

TEST(Iec61131Dialect, PRunsExactlyTwicePerEntry) {
  // CODESYS: "exactly two times"; TwinCAT: "once when the step becomes active and again in the
  // subsequent cycle". IEC 61131-3's P (read as P1): once.
  for (auto [d, runs] : {std::pair{semantics::VendorDialect::Codesys, 2},
                         std::pair{semantics::VendorDialect::Twincat, 2},
                         std::pair{semantics::VendorDialect::Iec, 1}}) {
    SCOPED_TRACE(std::string(semantics::to_string(d)));
    auto b = counting("P");
    auto ts = b.build(dialect(d));
    Runner r(*ts);
    ASSERT_TRUE(r.cycle({{"a", 1}}));
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["n"], 1);
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["n"], runs);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(r.cycle());  // S2 still active
    EXPECT_EQ(r["S2"], 1);
    EXPECT_EQ(r["n"], runs);
    // A second entry: twice again.
    ASSERT_TRUE(r.cycle({{"b", 1}}));
    ASSERT_TRUE(r.cycle({{"a", 1}}));
    ASSERT_TRUE(r.cycle());
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["n"], 2 * runs);
  }
}

TEST(Iec61131Dialect, FinalCallsRunBeforeTheActiveActions) {
  // Alphabetically B runs before Z; Z's final call, in the first pass, still runs before B.
  IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR VAR_OUTPUT y : INT (0..3); END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
  b.action_st("Z", "y := 1;").assoc("S1", "Z", "N");
  b.action_st("B", "y := 2;").assoc("S2", "B", "N");
  auto ts = b.build(dialect(semantics::VendorDialect::Codesys));
  Runner r(*ts);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["y"], 1);
  ASSERT_TRUE(r.cycle({{"a", 1}}));  // Z runs, S1 is left, S2 entered
  EXPECT_EQ(r["y"], 1);
  ASSERT_TRUE(r.cycle());  // Z's final call, then B
  EXPECT_EQ(r["y"], 2);
}

TEST(Iec61131Dialect, StepActionsRunFirstThenIecActionsAlphabetically) {
  // Declared Z, B, M: the declaration order ends with M (y = 3); CODESYS runs the step action M
  // first, then B and Z (y = 1).
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT y : INT (0..3); END_VAR");
  b.step("S1", true).trans("S1", "S1", "a");
  b.action_st("Z", "y := 1;").assoc("S1", "Z", "N");
  b.action_st("B", "y := 2;").assoc("S1", "B", "N");
  b.action_st("M", "y := 3;").assoc("S1", "M", "N");
  b.pou().associations.back().step_action = true;
  {
    auto ts = b.build();
    Runner r(*ts);
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["y"], 3);
  }
  auto ts = b.build(dialect(semantics::VendorDialect::Twincat));
  Runner r(*ts);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["y"], 1);
  // An explicit --action-order still wins over the vendor's.
  auto o = dialect(semantics::VendorDialect::Twincat);
  o.action_order = semantics::ActionOrder::Declaration;
  auto declared = b.build(o);
  Runner rd(*declared);
  ASSERT_TRUE(rd.cycle());
  EXPECT_EQ(rd["y"], 3);
}

TEST(Iec61131Dialect, ExitEntryAndMainStepActionsRunInThatOrder) {
  // S1's exit action X, S2's entry E and main M all run in the cycle after S1 -> S2 fires.
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR VAR_OUTPUT y : INT (0..7); END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "FALSE");
  b.action_st("M", "y := y * 2;").assoc("S2", "M", "N");
  b.pou().associations.back().step_action = true;
  b.action_st("E", "y := y + 1;").assoc("S2", "E", "P1");
  b.pou().associations.back().step_action = true;
  b.action_st("X", "y := 2;").assoc("S1", "X", "P0");
  b.pou().associations.back().step_action = true;
  auto ts = b.build(dialect(semantics::VendorDialect::Codesys));
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["y"], 6);  // (2 + 1) * 2; declaration order M, E, X would give 2
}

TEST(Iec61131Dialect, StepActionsAndBooleanActionsHaveNoFinalCall) {
  IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR VAR_OUTPUT n : INT (0..7); v : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
  b.action_st("Count", "IF n < 7 THEN n := n + 1; END_IF;").assoc("S2", "Count", "N");
  b.pou().associations.back().step_action = true;  // S2's main action
  b.action_var("V", "v").assoc("S2", "V", "N");
  auto ts = b.build(dialect(semantics::VendorDialect::Codesys));
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"a", 1}}));
  EXPECT_EQ(r["v"], 1);
  ASSERT_TRUE(r.cycle({{"b", 1}}));
  EXPECT_EQ(r["n"], 1);
  EXPECT_EQ(r["v"], 0);
  ASSERT_TRUE(r.cycle());
  EXPECT_EQ(r["n"], 1);
  EXPECT_EQ(r["v"], 0);
}

TEST(Iec61131Dialect, AnActionInBothRolesRunsInEach) {
  // TwinCAT's xPPU (corpus 11) uses Motor.ACT_Stop as one step's main action and another's IEC
  // action: the step phase and the IEC phase each call it, so in a cycle with S1's main call
  // and S2's final call it runs twice; IEC 61131-3 has one action, run once per cycle.
  for (auto [d, n] : {std::pair{semantics::VendorDialect::Codesys, 6},
                      std::pair{semantics::VendorDialect::Iec, 5}}) {
    SCOPED_TRACE(std::string(semantics::to_string(d)));
    auto b = counting("N");
    b.assoc("S1", "Count", "N");
    b.pou().associations.back().step_action = true;
    auto ts = b.build(dialect(d));
    Runner r(*ts);
    ASSERT_TRUE(r.cycle());            // S1's main call
    ASSERT_TRUE(r.cycle({{"a", 1}}));  // again; S2 entered
    ASSERT_TRUE(r.cycle());            // the IEC action
    ASSERT_TRUE(r.cycle({{"b", 1}}));  // again; S1 entered
    EXPECT_EQ(r["n"], 4);
    ASSERT_TRUE(r.cycle());  // vendor: the final call, then S1's main call
    EXPECT_EQ(r["n"], n);
  }
}

TEST(Iec61131Dialect, ABooleanActionWritesItsVariableOnlyWhenItRunsOrStops) {
  // CODESYS: the variable "is toggled between FALSE and TRUE each time the action is executed";
  // IEC 61131-3: it is the action's activity, written every cycle. B writes v in S1, where the
  // Boolean action V is inactive: under IEC, V's FALSE wins; under CODESYS, V does not run.
  for (auto [d, in_s1] : {std::pair{semantics::VendorDialect::Codesys, 1},
                          std::pair{semantics::VendorDialect::Iec, 0}}) {
    SCOPED_TRACE(std::string(semantics::to_string(d)));
    IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR VAR_OUTPUT v : BOOL; END_VAR");
    b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
    b.action_var("V", "v").assoc("S2", "V", "N");
    b.action_st("B", "v := TRUE;").assoc("S1", "B", "N");
    auto ts = b.build(dialect(d));
    Runner r(*ts);
    ASSERT_TRUE(r.cycle());
    EXPECT_EQ(r["v"], in_s1);
    ASSERT_TRUE(r.cycle({{"a", 1}}));  // B runs, S2 entered: V runs
    EXPECT_EQ(r["v"], 1);
    ASSERT_TRUE(r.cycle({{"b", 1}}));  // V stops: FALSE in both
    EXPECT_EQ(r["v"], 0);
    ASSERT_TRUE(r.cycle());  // B runs again
    EXPECT_EQ(r["v"], in_s1);
  }
}

// A Boolean action of an instance is named like the variable it drives: "Main.Lift.Extend" is
// the variable, whichever way it is written, and "Main.Lift.Extend.A" the action's activity
// (IEC 61131-3's A output of an action control block). Under TwinCAT's reading the two differ:
// Hold writes the variable in Idle, where the Boolean action does not run. Before, the full
// name meant the action and the instance's alias the variable.
TEST(Iec61131Dialect, ABooleanActionOfAnInstanceAndItsVariableHaveNamesOfTheirOwn) {
  auto loaded = io::load_iec_text(kCylinderWithHoldChart, "cylinder.st");
  ASSERT_TRUE(loaded.ok());
  model::Diagnostics diags;
  auto ts = semantics::make_iec61131_system(*loaded.project,
                                            dialect(semantics::VendorDialect::Twincat), diags);
  ASSERT_TRUE(ts) << (diags.empty() ? "" : diags.front().str());
  std::set<std::string> names;
  for (const auto& o : ts->observables())
    EXPECT_TRUE(names.insert(model::to_upper(o.name)).second) << "two observables " << o.name;
  const auto full = semantics::find_observable(*ts, "Main.Lift.Extend");
  ASSERT_TRUE(full);
  EXPECT_EQ(full, semantics::find_observable(*ts, "Lift.Extend"));
  EXPECT_EQ(ts->observables()[*full].kind, semantics::ObservableKind::Variable);
  const auto activity = semantics::find_observable(*ts, "Main.Lift.Extend.A");
  ASSERT_TRUE(activity);
  EXPECT_EQ(ts->observables()[*activity].kind, semantics::ObservableKind::Action);
  EXPECT_EQ(activity, semantics::find_observable(*ts, "Extend.A"));
  EXPECT_FALSE(semantics::find_observable(*ts, "Extend"));  // the variable's own bare name
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"F", 1}}));  // Idle: Hold writes the variable, the action is inactive
  EXPECT_EQ(r["Main.Lift.Extend"], 1);
  EXPECT_EQ(r["Main.Lift.Extend.A"], 0);
  ASSERT_TRUE(r.cycle({{"Button", 1}}));  // Out entered: the Boolean action runs
  ASSERT_TRUE(r.cycle({{"Button", 1}}));
  EXPECT_EQ(r["Main.Lift.Extend.A"], 1);
  EXPECT_EQ(r["Main.Lift.Extend"], 1);
}

// Neither help says what the final call of an action whose body is a chart does: under the
// vendors' dialects it is refused by name (docs/semantics.md 1.4a rule 5), and --dialect iec
// reads the same chart (its chart suspended, no final call).
TEST(Iec61131Dialect, TheFinalCallOfAChartActionIsRefusedByName) {
  IecBuilder b("VAR_INPUT a, b : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "b");
  b.assoc("S2", "Sub", "N");
  b.chart("sub", "Sub");
  b.step("U0", true);
  for (auto vendor : {semantics::VendorDialect::Codesys, semantics::VendorDialect::Twincat}) {
    SCOPED_TRACE(std::string(semantics::to_string(vendor)));
    model::Diagnostics d;
    EXPECT_FALSE(semantics::make_iec61131_system(b.project, dialect(vendor), d));
    std::string all;
    for (const auto& x : d) all += x.str() + "\n";
    EXPECT_NE(all.find("action 'MAIN.Sub' has a chart as its body and is an IEC action"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("--dialect iec reads it without final calls"), std::string::npos) << all;
  }
  model::Diagnostics d;
  EXPECT_TRUE(
      semantics::make_iec61131_system(b.project, dialect(semantics::VendorDialect::Iec), d));
  EXPECT_FALSE(model::has_errors(d));
}

TEST(Iec61131Dialect, TheFileSaysWhoseDialectItIs) {
  model::Project p;
  const std::pair<const char*, semantics::VendorDialect> formats[] = {
      {"plcopen-xml from 3S-Smart Software Solutions GmbH CODESYS V3.5 SP16",
       semantics::VendorDialect::Codesys},
      {"plcopen-xml from Beckhoff Automation GmbH TwinCAT PLC Control 3.5.8.40",
       semantics::VendorDialect::Twincat},
      {"codesys-export", semantics::VendorDialect::Codesys},
      {"twincat", semantics::VendorDialect::Twincat},
      {"simaticml-graph", semantics::VendorDialect::Siemens},
      {"simaticml-graph V20 (GRAPH 6.0)", semantics::VendorDialect::Siemens},
      {"simaticml-lad V19", semantics::VendorDialect::Siemens},
      {"rockwell-l5x", semantics::VendorDialect::Rockwell},
      {"plcopen-xml from Beremiz", semantics::VendorDialect::Iec},
      {"iec-text", semantics::VendorDialect::Iec}};
  for (const auto& [format, expected] : formats) {
    p.source_format = format;
    EXPECT_EQ(semantics::file_dialect(p), expected) << format;
  }
  p.vendor = "TwinCAT";  // sfcv's own export of a TwinCAT project says so in its addData
  EXPECT_EQ(semantics::file_dialect(p), semantics::VendorDialect::Twincat);
  EXPECT_EQ(semantics::parse_vendor_dialect("Rockwell"), semantics::VendorDialect::Rockwell);
  EXPECT_FALSE(semantics::parse_vendor_dialect("beremiz"));
}

TEST(Iec61131Dialect, IecOnAVendorsFileSaysWhichFinalCallsItLeavesOut) {
  auto b = counting("N");
  b.project.source_format = "plcopen-xml from CODESYS V3.5 SP14";
  model::Diagnostics d;
  ASSERT_TRUE(
      semantics::make_iec61131_system(b.project, dialect(semantics::VendorDialect::Iec), d));
  std::string all;
  for (const auto& x : d) all += x.str() + "\n";
  EXPECT_NE(all.find("codesys runs each IEC action once more"), std::string::npos) << all;
  EXPECT_NE(all.find("the final calls of MAIN.Count do"), std::string::npos) << all;
  d.clear();
  ASSERT_TRUE(
      semantics::make_iec61131_system(b.project, dialect(semantics::VendorDialect::Codesys), d));
  for (const auto& x : d) EXPECT_NE(x.severity, model::Severity::Warning) << x.str();
}

}  // namespace
}  // namespace sfcv::test

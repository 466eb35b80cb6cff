// build_export: what goes into the circuit exports, what is refused; aiger_circuit's valid latch;
// NuSMV's verdict lines.

#include "engine/external/export_model.hpp"

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "engine/external/nusmv_runner.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"
#include "support/loop_limit_chart.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::engine {
namespace {

using semantics::Aig;

const char* kChart = R"(
PROGRAM Small
  VAR_INPUT go : BOOL; level : INT(0..5); END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Run: lamp(N); END_STEP
  TRANSITION FROM Idle TO Run := go AND level > 2; END_TRANSITION
  TRANSITION FROM Run TO Idle := NOT go; END_TRANSITION
END_PROGRAM
)";

struct Sys {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  std::vector<logic::Property> props;
};

Sys make(const char* text, std::vector<std::string> ctl) {
  Sys s;
  auto loaded = io::load_iec_text(text, "small.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, {}, diags);
  EXPECT_TRUE(s.ts);
  logic::CheckInputs in;
  in.ctl = std::move(ctl);
  auto parsed = logic::parse_check_inputs(in);
  for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
  logic::CheckTask task;
  logic::resolve_into(parsed.spec, *s.ts, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  s.props = task.properties;
  return s;
}

TEST(ExportModel, InvariantsBecomeBadLiteralsAndTheRestCtlText) {
  auto s = make(kChart, {"AG !(Run & !lamp)", "AG EF Idle", "AG lamp -> Run"});
  ExportRequest r;
  r.properties = s.props;
  const auto e = build_export(*s.ts, r);
  // "AG lamp -> Run" parses as (AG lamp) -> Run: not an invariant.
  ASSERT_EQ(e.model.aig.bad().size(), 1u);
  EXPECT_EQ(e.bad_property, std::vector<std::int32_t>{0});
  ASSERT_EQ(e.model.ctl.size(), 2u);
  // Atoms are circuit outputs by index, never by name (a name may hold '}').
  std::size_t idle = e.model.aig.outputs().size();
  for (std::size_t o = 0; o < e.model.aig.outputs().size(); ++o)
    if (e.model.aig.outputs()[o].name == "Small.Idle") idle = o;
  ASSERT_LT(idle, e.model.aig.outputs().size());
  EXPECT_EQ(e.model.ctl[0].second, "AG EF {" + std::to_string(idle) + "}");
  EXPECT_EQ(e.ctl_only.size(), 2u);
  // Every latch and input has a comment naming the chart element.
  for (const auto& c : e.model.latch_comments) EXPECT_FALSE(c.empty());
  for (const auto& c : e.model.input_comments) EXPECT_FALSE(c.empty());
  // The integer input's range (0..5 in 3 bits) is a constraint.
  ASSERT_EQ(e.model.aig.constraints().size(), 1u);
  std::ostringstream out;
  write_nusmv(out, e.model);
  EXPECT_NE(out.str().find("CTLSPEC NAME"), std::string::npos);
  EXPECT_NE(out.str().find("IVAR\n  in_go : boolean;  -- input go\n"), std::string::npos)
      << out.str();
}

TEST(ExportModel, ComparisonsAreEvaluatedOnTheEncodedBits) {
  // level is an input, not observable: compare a variable instead.
  auto s = make(R"(
PROGRAM Count
  VAR_INPUT up : BOOL; END_VAR
  VAR_OUTPUT n : INT(-2..5); END_VAR
  INITIAL_STEP S: Inc(N); END_STEP
  ACTION Inc: IF up AND n < 5 THEN n := n + 1; END_IF; END_ACTION
END_PROGRAM
)",
                {"AG n < 4", "AG n >= -2", "AG n != 7"});
  ExportRequest r;
  r.properties = s.props;
  const auto e = build_export(*s.ts, r);
  ASSERT_EQ(e.model.aig.bad().size(), 3u);
  const auto& aig = e.model.aig;
  // Evaluate each bad literal on every value of n.
  const auto& field = e.circuit.field_latches;
  std::uint32_t nf = 0;
  for (std::uint32_t f = 0; f < s.ts->layout().fields().size(); ++f)
    if (s.ts->layout().fields()[f].name == "n") nf = f;
  for (std::int64_t n = -2; n <= 5; ++n) {
    std::vector<bool> latches(aig.latches().size()), inputs(aig.inputs().size());
    for (std::size_t k = 0; k < field[nf].size(); ++k)
      latches[field[nf][k]] = (((n + 2) >> k) & 1) != 0;
    const auto v = aig.evaluate(inputs, latches);
    EXPECT_EQ(Aig::value_of(v, aig.bad()[0].literal), !(n < 4)) << n;
    EXPECT_FALSE(Aig::value_of(v, aig.bad()[1].literal)) << n;
    EXPECT_FALSE(Aig::value_of(v, aig.bad()[2].literal)) << n;
  }
}

TEST(ExportModel, AigerCircuitFoldsTheConstraintIntoAValidLatch) {
  auto s = make(kChart, {"AG !(Run & Idle)"});
  ExportRequest r;
  r.target = ExportTarget::Circuit;
  r.properties = s.props;
  r.reachability = true;
  const auto e = build_export(*s.ts, r);
  ASSERT_EQ(e.model.aig.bad().size(), 3u);  // the invariant, then "Idle", "Run" unreachable
  EXPECT_EQ(e.bad_property, (std::vector<std::int32_t>{0, -1, -1}));
  const auto aig = aiger_circuit(e.model);
  EXPECT_TRUE(aig.constraints().empty());
  EXPECT_TRUE(aig.outputs().empty());
  ASSERT_EQ(aig.latches().size(), e.model.aig.latches().size() + 1);
  EXPECT_EQ(aig.latches().back().name, "sfcv_valid");
  EXPECT_TRUE(aig.latches().back().initial);
  // With valid = 0, no bad literal holds.
  std::vector<bool> latches(aig.latches().size(), true), inputs(aig.inputs().size(), true);
  latches.back() = false;
  const auto v = aig.evaluate(inputs, latches);
  for (const auto& b : aig.bad()) EXPECT_FALSE(Aig::value_of(v, b.literal)) << b.name;
}

TEST(ExportModel, AChartWithoutInputsGetsADummyOne) {
  auto s = make(R"(
PROGRAM Blink
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP A: lamp(N); END_STEP
  STEP B: END_STEP
  TRANSITION FROM A TO B := TRUE; END_TRANSITION
  TRANSITION FROM B TO A := TRUE; END_TRANSITION
END_PROGRAM
)",
                {});
  ASSERT_TRUE(s.ts->inputs().empty());
  const auto e = build_export(*s.ts, {});
  ASSERT_EQ(e.model.aig.inputs().size(), 1u);
  EXPECT_EQ(e.model.aig.inputs()[0].name, "sfcv_dummy");
  EXPECT_EQ(aiger_circuit(e.model).inputs().size(), 1u);
}

TEST(ExportModel, RefusesGrafcet) {
  auto loaded = io::load_file(test::source_path("examples/pistons/pistons.g7"));
  ASSERT_TRUE(loaded.project);
  model::Diagnostics diags;
  auto ts = semantics::make_grafcet_system(*loaded.project, {}, diags);
  ASSERT_TRUE(ts);
  try {
    build_export(*ts, {});
    FAIL() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("not supported for Grafcet yet"), std::string::npos);
  }
}

// Issue 53: a cycle whose ST loop meets sfcv's bound (1000 iterations) has no successor in
// sfcv, which answers unknown; the export once cut it too, so an outside tool proved `AG !bad`
// here although bad follows that cycle (the loop ends after 2000 iterations on a PLC).
const char* const kLoopChart = test::kLoopLimitChart;

TEST(ExportModel, ALoopLimitCycleSetsALatchWhereEveryPropertyFails) {
  auto s = make(kLoopChart, {"AG !bad", "AG EF !bad"});
  ExportRequest r;
  r.properties = s.props;
  r.reachability = false;
  const auto e = build_export(*s.ts, r);
  ASSERT_TRUE(e.loop_limit_latch);
  const auto& aig = e.model.aig;
  const auto flag = *e.loop_limit_latch;
  EXPECT_EQ(aig.latches()[flag].name, "sfcv_loop_limit");
  EXPECT_FALSE(aig.latches()[flag].initial);
  EXPECT_FALSE(e.model.latch_comments[flag].empty());
  // The invariant, then NuSMV's "no_loop_limit" (for reading CTL verdicts back).
  ASSERT_EQ(aig.bad().size(), 2u);
  ASSERT_TRUE(e.loop_limit_bad);
  EXPECT_EQ(aig.bad()[*e.loop_limit_bad].name, "no_loop_limit");
  EXPECT_EQ(e.bad_property, (std::vector<std::int32_t>{0, -1}));
  // A loop-limit cycle is not cut: go = 1 sets the flag, which stays set whatever follows.
  std::vector<bool> latches;
  for (const auto& l : aig.latches()) latches.push_back(l.initial);
  for (bool go : {false, true, false}) {
    const auto v = aig.evaluate({go}, latches);
    for (const auto& c : aig.constraints()) EXPECT_TRUE(Aig::value_of(v, c.literal));
    EXPECT_EQ(Aig::value_of(v, aig.bad()[0].literal), latches[flag]);  // bad is never set
    for (std::size_t l = 0; l < latches.size(); ++l)
      latches[l] = Aig::value_of(v, aig.latches()[l].next);
    EXPECT_TRUE(latches[flag] || !go);
  }
  EXPECT_TRUE(latches[flag]);
  const auto v = aig.evaluate({false}, latches);
  EXPECT_TRUE(Aig::value_of(v, aig.bad()[0].literal));  // AG !bad fails in the flag state
  EXPECT_TRUE(ends_in_loop_limit(e, {{false}, {true}}));
  EXPECT_FALSE(ends_in_loop_limit(e, {{false}, {false}}));
  EXPECT_FALSE(ends_in_loop_limit(e, {}));
  // CTL text fails wherever the flag is reachable.
  ASSERT_EQ(e.model.ctl.size(), 1u);
  const auto& ctl = e.model.ctl[0].second;
  ASSERT_EQ(ctl.rfind("(AG !{", 0), 0u) << ctl;
  const auto k = std::stoul(ctl.substr(6));
  EXPECT_EQ(aig.outputs().at(k).literal, aig.latches()[flag].current);
  EXPECT_NE(ctl.find("}) & (AG EF "), std::string::npos) << ctl;
  std::ostringstream out;
  write_nusmv(out, e.model);
  EXPECT_NE(out.str().find("INVARSPEC NAME p_no_loop_limit := !(s_sfcv_loop_limit);"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("-- sfcv_loop_limit: a loop (at small.st:"), std::string::npos);
}

TEST(ExportModel, ALoopLimitFlagsReachabilityAndRefusesLtl) {
  auto s = make(kLoopChart, {});
  ExportRequest r;
  r.target = ExportTarget::Circuit;
  r.reachability = true;
  const auto e = build_export(*s.ts, r);
  ASSERT_TRUE(e.loop_limit_latch);
  EXPECT_FALSE(e.loop_limit_bad);  // AIGER and Promela: each invariant carries the flag
  // "Done unreachable" fails in the flag state: Done follows the loop-limit cycle only.
  const auto& aig = e.model.aig;
  ASSERT_EQ(aig.bad().size(), 2u);
  EXPECT_EQ(aig.bad()[1].name, "unreachable_Chart.Done");
  std::vector<bool> latches;
  for (const auto& l : aig.latches()) latches.push_back(l.initial);
  EXPECT_FALSE(Aig::value_of(aig.evaluate({false}, latches), aig.bad()[1].literal));
  latches[*e.loop_limit_latch] = true;
  EXPECT_TRUE(Aig::value_of(aig.evaluate({false}, latches), aig.bad()[1].literal));
  logic::CheckInputs in;
  in.ltl = {"G !bad"};
  auto parsed = logic::parse_check_inputs(in);
  logic::CheckTask task;
  model::Diagnostics diags;
  logic::resolve_into(parsed.spec, *s.ts, task, diags);
  ASSERT_TRUE(diags.empty());
  r.properties = task.properties;
  try {
    build_export(*s.ts, r);
    FAIL() << "no error";
  } catch (const ExportError& x) {
    EXPECT_NE(std::string(x.what()).find("may run past the bound"), std::string::npos) << x.what();
  }
}

TEST(ExportModel, NoLoopLimitLatchWithoutALoopThatCanMeetTheBound) {
  auto s = make(R"(
PROGRAM Bounded
  VAR_INPUT go : BOOL; END_VAR
  VAR i : INT; n : INT(0..20); END_VAR
  n := 0;
  FOR i := 1 TO 10 DO
    IF go THEN n := n + 1; END_IF;
  END_FOR;
END_PROGRAM
)",
                {"AG n <= 10"});
  ExportRequest r;
  r.properties = s.props;
  const auto e = build_export(*s.ts, r);
  EXPECT_FALSE(e.loop_limit_latch);
  EXPECT_FALSE(e.loop_limit_bad);
  EXPECT_EQ(e.model.aig.bad().size(), 1u);
  for (const auto& l : e.model.aig.latches()) EXPECT_NE(l.name, "sfcv_loop_limit");
}

TEST(NusmvOutput, ReadsVerdictLinesByKindInFileOrder) {
  // NuSMV 2.6 prints CTL verdicts, then invariants, each with its trace when false.
  const std::string text = R"(*** This is NuSMV 2.6.0 (compiled on Wed Oct 14 15:37:51 2015)
*** Enabled addons are: compass
-- specification EF Small_Run  is true
-- specification AG (EF Small_Idle)  is false
-- as demonstrated by the following execution sequence
Trace Description: CTL Counterexample
Trace Type: Counterexample
  -> State: 1.1 <-
    Small_Idle = TRUE
-- invariant !(g12)  is true
-- invariant !(g15)  is false
-- as demonstrated by the following execution sequence
  -> State: 2.1 <-
)";
  const auto v = parse_nusmv_output(text);
  EXPECT_EQ(v.ctl, (std::vector<bool>{true, false}));
  EXPECT_EQ(v.invariants, (std::vector<bool>{true, false}));
  ASSERT_EQ(v.ctl_traces.size(), 2u);
  EXPECT_FALSE(v.ctl_traces[0]);
  ASSERT_TRUE(v.ctl_traces[1]);
  EXPECT_EQ(v.ctl_traces[1]->states, 1u);
  EXPECT_TRUE(v.errors.empty());
}

TEST(NusmvOutput, ReadsTracesWithCarriedOverInputsAndLoops) {
  // NuSMV prints only the values that changed; a lasso marks its loop state.
  const std::string text = R"(-- specification AG (s_x -> AF s_y)  is false
-- as demonstrated by the following execution sequence
Trace Description: CTL Counterexample
Trace Type: Counterexample
  -> State: 1.1 <-
    s_x = FALSE
  -> Input: 1.2 <-
    in_a = TRUE
    in_b = FALSE
  -- Loop starts here
  -> State: 1.2 <-
    s_x = TRUE
  -> Input: 1.3 <-
    in_b = TRUE
  -> State: 1.3 <-
  -> Input: 1.4 <-
    in_a = FALSE
  -> State: 1.4 <-
-- invariant !(g_3)  is true
)";
  const auto v = parse_nusmv_output(text);
  ASSERT_EQ(v.ctl_traces.size(), 1u);
  ASSERT_TRUE(v.ctl_traces[0]);
  const auto& t = *v.ctl_traces[0];
  EXPECT_EQ(t.states, 4u);
  EXPECT_EQ(t.loop_start, std::optional<std::size_t>(1));
  ASSERT_EQ(t.inputs.size(), 3u);
  EXPECT_EQ(t.inputs[0], (std::map<std::string, bool>{{"in_a", true}, {"in_b", false}}));
  EXPECT_EQ(t.inputs[1], (std::map<std::string, bool>{{"in_a", true}, {"in_b", true}}));
  EXPECT_EQ(t.inputs[2], (std::map<std::string, bool>{{"in_a", false}, {"in_b", true}}));
  EXPECT_EQ(v.invariants, (std::vector<bool>{true}));
}

TEST(NusmvOutput, KeepsErrorLines) {
  const auto v = parse_nusmv_output(
      "*** This is NuSMV 2.6.0\n"
      "file model.smv: line 40: multiple declaration of identifier: P_A3_N1\n");
  EXPECT_TRUE(v.ctl.empty());
  EXPECT_EQ(v.errors, (std::vector<std::string>{
                          "file model.smv: line 40: multiple declaration of identifier: P_A3_N1"}));
}

}  // namespace
}  // namespace sfcv::engine

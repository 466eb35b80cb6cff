// Rockwell Studio 5000 .L5X exports (docs/formats.md): an SFC main routine read through its
// DirectedLinks gives the model its IEC 61131-3 text twin gives; Rockwell's own constructs the
// model has no meaning for are refused at their element. The files are written in the vendor's
// shape (tests/support/l5x_text.hpp), never copied from public exports.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/expr.hpp"
#include "round_trip.hpp"
#include "support/l5x_text.hpp"

namespace sfcv::test {
namespace {

using namespace rockwell;

std::string errors_of(const io::LoadResult& r) {
  return diagnostics_text(r.diagnostics);
}

TEST(L5x, DemoChartGivesTheModelOfItsIecTwin) {
  const auto native = io::load_l5x(l5x(demo_tags(), demo_sfc()), "Press.L5X");
  ASSERT_TRUE(native.ok()) << errors_of(native);
  const auto twin = io::load_iec_text(demo_twin(), "press.st");
  ASSERT_TRUE(twin.ok()) << errors_of(twin);
  const auto diff = model::first_difference(*native.project, *twin.project);
  EXPECT_FALSE(diff.has_value()) << *diff;

  // And that model is the chart as drawn.
  const auto& p = *native.project;
  EXPECT_EQ(p.source_format, "rockwell-l5x 32.01");
  ASSERT_EQ(p.pous.size(), 1u);
  const auto& pou = p.pous[0];
  EXPECT_EQ(pou.name, "Press");
  ASSERT_EQ(pou.charts.size(), 1u);
  const auto& c = pou.charts[0];
  ASSERT_EQ(c.steps.size(), 6u);
  EXPECT_EQ(c.steps[0].name, "Init");
  EXPECT_TRUE(c.steps[0].initial);
  ASSERT_EQ(c.transitions.size(), 6u);
  const model::Transition* left = nullptr;
  const model::Transition* right = nullptr;
  const model::Transition* join = nullptr;
  for (const auto& t : c.transitions) {
    if (t.name == "Tran_000") left = &t;
    if (t.name == "Tran_001") right = &t;
    if (t.name == "Tran_005") join = &t;
    if (t.name == "Tran_004") {
      EXPECT_EQ(t.targets, (std::vector<std::string>{"P1", "P2"}));
    }
    if (t.name == "Tran_003") {
      EXPECT_EQ(t.targets, std::vector<std::string>{"Merge"});
    }
  }
  ASSERT_TRUE(left && right && join);
  EXPECT_LT(left->order, right->order);  // left to right by X, not by document order
  EXPECT_EQ(left->sources, std::vector<std::string>{"Init"});
  EXPECT_EQ(model::to_st(left->guard), "start AND a");
  EXPECT_EQ(join->sources, (std::vector<std::string>{"P1", "P2"}));
  EXPECT_EQ(join->targets, std::vector<std::string>{"Init"});
  // Tags: I/O aliases of one bit are Boolean inputs/outputs; the SFC_* tags are the chart's.
  ASSERT_NE(pou.find_variable("start"), nullptr);
  EXPECT_EQ(pou.find_variable("start")->direction, model::VarDirection::Input);
  EXPECT_EQ(pou.find_variable("lamp")->direction, model::VarDirection::Output);
  EXPECT_EQ(pou.find_variable("Init"), nullptr);
  ASSERT_EQ(pou.associations.size(), 4u);
  EXPECT_EQ(pou.find_action("A_Init")->body.size(), 2u);
}

TEST(L5x, DetectedByContentAndExtension) {
  EXPECT_EQ(io::detect_format("x.L5X", ""), io::Format::L5x);
  EXPECT_EQ(io::detect_format("x.xml", l5x("", "")), io::Format::L5x);
  // One SFC routine's content alone (as francisboudreau7/l5x_sfc tests/SFCContent.xml): the L5X
  // reader says what is missing.
  const std::string fragment =
      "<?xml version=\"1.0\"?>\n<SFCContent>\n" + demo_sfc() + "</SFCContent>\n";
  EXPECT_EQ(io::detect_format("SFCContent.xml", fragment), io::Format::L5x);
  const auto r = io::load_l5x(fragment, "SFCContent.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("a bare <SFCContent> (one SFC routine's content, without its "
                              "program, tags and controller options) is not read"),
            std::string::npos)
      << errors_of(r);
}

TEST(L5x, ConditionErrorsPointIntoTheFile) {
  auto sfc = demo_sfc();
  const std::string good = "NOT start";
  sfc.replace(sfc.find(good), good.size(), "NOT (start");
  const auto text = l5x(demo_tags(), sfc);
  const auto r = io::load_l5x(text, "Press.L5X");
  EXPECT_FALSE(r.ok());
  // The line of the broken condition's CDATA in the file.
  const auto at = text.find("NOT (start");
  const int line =
      1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  const auto e = errors_of(r);
  EXPECT_NE(e.find("Press.L5X:" + std::to_string(line) + ":"), std::string::npos) << e;
}

void expect_refused(const std::string& text, const std::string& message,
                    const std::string& path = "") {
  const auto r = io::load_l5x(text, "P.L5X");
  EXPECT_FALSE(r.ok());
  const auto e = errors_of(r);
  EXPECT_NE(e.find(message), std::string::npos) << e;
  if (!path.empty()) {
    EXPECT_NE(e.find(path), std::string::npos) << e;
  }
}

TEST(L5x, RockwellConstructsWithoutAModelAreRefusedByName) {
  // A step's done bit where its step may be inactive (it keeps its value after the step is
  // left), or without a PRE in its SFC_STEP tag; its other timer bits.
  auto sfc = demo_sfc();
  sfc.replace(sfc.find("NOT stop"), 8, "S1.DN");
  expect_refused(l5x(demo_tags() + step_tag("S1", 300), sfc),
                 "'S1.DN' (a step's DN is read in the conditions of the transitions leaving it",
                 "Routine[@name='Chart']/SFCContent/Transition[4]/Condition/STContent");
  sfc = demo_sfc();
  sfc.replace(sfc.find("NOT a"), 5, "S1.DN");
  expect_refused(l5x(demo_tags(), sfc), "'S1.DN' (a step's DN is read", "Transition[3]");
  sfc = demo_sfc();
  sfc.replace(sfc.find("NOT a"), 5, "S1.FS");
  expect_refused(l5x(demo_tags(), sfc), "'S1.FS': member FS of the SFC_STEP tag");
  // Qualifiers other than NonStored.
  sfc = demo_sfc();
  sfc.replace(sfc.find("NonStored"), 9, "Stored");
  expect_refused(l5x(demo_tags(), sfc), "action qualifier 'Stored' of action 'A_Init'");
  // JSR.
  sfc = demo_sfc();
  sfc.replace(sfc.find("valve := TRUE;"), 14, "JSR(Sub, 0);");
  expect_refused(l5x(demo_tags(), sfc), "unsupported: JSR");
  // A Stop element.
  expect_refused(
      l5x(demo_tags(), demo_sfc() + "<Stop ID=\"90\" X=\"1\" Y=\"1\" Operand=\"Stop_000\"/>\n"),
      "SFC Stop element 'Stop_000'");
  // A link the drawing rules do not allow: step to step.
  expect_refused(l5x(demo_tags(), demo_sfc() + links({{9, 2}})), "a link from step 9 to step 2");
  // SFC options the model does not run.
  expect_refused(l5x(demo_tags(), demo_sfc(), " SFCExecutionControl=\"UntilFalse\""),
                 "SFCExecutionControl 'UntilFalse'");
  expect_refused(l5x(demo_tags(), demo_sfc(),
                     " SFCExecutionControl=\"CurrentActive\" SFCLastScan=\"AutomaticReset\""),
                 "SFCLastScan 'AutomaticReset'");
  // An alias the model cannot type is left out; a use of it is an error.
  const auto w = io::load_l5x(l5x(demo_tags() + alias("w", "Local:1:I.Data"), demo_sfc()), "P.L5X");
  EXPECT_TRUE(w.ok()) << errors_of(w);
  EXPECT_NE(errors_of(w).find("alias tag 'w' for 'Local:1:I.Data' is not modelled"),
            std::string::npos);
  EXPECT_EQ(w.project->pous[0].find_variable("w"), nullptr);
}

TEST(L5x, TagsGiveTypesAndInitialValues) {
  const auto r = io::load_l5x(l5x(demo_tags() + bool_tag("ready", 1) +
                                      "<Tag Name=\"count\" TagType=\"Base\" DataType=\"DINT\">\n"
                                      "<Data Format=\"Decorated\">\n<DataValue DataType=\"DINT\" "
                                      "Value=\"-7\"/>\n</Data>\n</Tag>\n" +
                                      "<Tag Name=\"t1\" TagType=\"Base\" DataType=\"TIMER\"/>\n",
                                  demo_sfc()),
                              "P.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  ASSERT_NE(pou.find_variable("ready"), nullptr);
  EXPECT_EQ(pou.find_variable("ready")->initial, 1);
  ASSERT_NE(pou.find_variable("count"), nullptr);
  EXPECT_EQ(pou.find_variable("count")->initial, -7);
  EXPECT_EQ(pou.find_variable("count")->type.lo, -2147483648LL);
  // A TIMER is left out, said in a note: a use of it would be an error.
  EXPECT_EQ(pou.find_variable("t1"), nullptr);
  EXPECT_NE(errors_of(r).find("tag 't1' of type TIMER is not modelled"), std::string::npos);
}

TEST(L5x, DrawingsWithoutOneReadingAreRefused) {
  // Two transitions of one selection branch at the same X: no left-to-right order.
  auto sfc = demo_sfc();
  sfc.replace(sfc.find("X=\"400\" Y=\"300\" Operand=\"Tran_001\""), 7, "X=\"100\"");
  expect_refused(l5x(demo_tags(), sfc), "drawn at the same X");
  // A step with two outgoing links (alternatives without a selection branch).
  expect_refused(
      l5x(demo_tags(), demo_sfc() + transition(60, "Tran_060", "a") + links({{6, 60}, {60, 0}})),
      "step 'Merge' has 2 outgoing links");
  // A link to an ID that is not in the chart.
  expect_refused(l5x(demo_tags(), demo_sfc() + links({{9, 99}})), "unknown ID '99'");
}

TEST(L5x, MissingSfcOptionsAreAssumedAloud) {
  const auto r = io::load_l5x(l5x(demo_tags(), demo_sfc(), ""), "P.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_NE(errors_of(r).find("read as SFCExecutionControl CurrentActive"), std::string::npos);
}

TEST(L5x, AnSfcRoutineCalledFromLadderIsRefused) {
  auto text = l5x(demo_tags(), demo_sfc());
  text.replace(text.find("MainRoutineName=\"Chart\""), 23, "MainRoutineName=\"Main\"");
  text.replace(text.find("<Routines>\n"), 11,
               "<Routines>\n<Routine Name=\"Main\" Type=\"RLL\">\n<RLLContent>\n<Rung Number=\"0\" "
               "Type=\"N\">\n<Text>\n<![CDATA[JSR(Chart,0);]]>\n</Text>\n</Rung>\n</RLLContent>\n"
               "</Routine>\n");
  const auto r = io::load_l5x(text, "P.L5X");
  // The ladder main routine is read, but where an SFC routine runs within its scan is not.
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("JSR to the SFC routine 'Chart' (RLL routines are read as "
                              "subroutines)"),
            std::string::npos)
      << errors_of(r);
}

// 1756-PM006 (SFC programming manual): a step's DN turns on once its timer T reaches PRE, and
// stays on after the step is left until it is entered again; in a condition of a transition
// leaving the step, the step is active, so DN is `T >= PRE`.
TEST(L5x, AStepDoneBitLeavingItsStepIsItsTimeAgainstThePreset) {
  auto sfc = demo_sfc();
  sfc.replace(sfc.find("NOT a"), 5, "S1.DN AND NOT a");
  const auto r = io::load_l5x(l5x(demo_tags() + step_tag("S1", 300), sfc), "P.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  for (const auto& t : r.project->pous[0].charts[0].transitions)
    if (t.name == "Tran_002") {
      EXPECT_EQ(model::to_st(t.guard), "S1.T >= T#300ms AND NOT a");
    }
}

// Logix 5000 Structured Text manual: the non-retentive assignment `[:=]` assigns, and resets
// the tag to 0 when the controller enters Run or, with the SFC option Automatic reset (not
// read), when the step is left. The model's initial state is the entry into Run.
TEST(L5x, ANonRetentiveAssignmentAssignsAndStartsFromZero) {
  auto sfc = demo_sfc();
  sfc.replace(sfc.find("m := TRUE"), 9, "m [:=] TRUE");
  auto tags = demo_tags();
  tags.replace(tags.find(bool_tag("m", 0)), bool_tag("m", 0).size(), bool_tag("m", 1));
  const auto r = io::load_l5x(l5x(tags, sfc), "P.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  EXPECT_EQ(pou.find_variable("m")->initial, 0);
  EXPECT_NE(errors_of(r).find("tag 'm' is assigned with [:=]"), std::string::npos) << errors_of(r);
  EXPECT_EQ(model::to_st(pou.find_action("A_S2")->body), "m := TRUE;\n");
}

// Ladder, read from Logix 5000 Controllers General Instructions (1756-RM003): XIC/XIO AND the
// tag (or its negation) into the rung condition, each leg of a branch starts from the condition
// before it and the branch passes on the OR of its legs, OTE writes the condition, OTL/OTU set
// or reset where it is TRUE, TON runs the TIMER with it, JSR runs the routine where it is.
std::string ladder_body(const io::LoadResult& r) {
  return model::to_st(r.project->pous.back().body);
}

TEST(L5xLadder, RungsReadAsTheStatementsOfTheirRungConditions) {
  const auto r = io::load_l5x(l5x_ladder(ladder_tags(), ladder_routines()), "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous.back();
  EXPECT_EQ(pou.name, "Cell");
  EXPECT_FALSE(pou.body_unsupported);
  // Main's JSRs run the routines in its order; S:FS is TRUE in the first scan only.
  EXPECT_EQ(ladder_body(r),
            "motor := X_1;\n"
            "T1(IN := X_1, PT := T#1500ms);\n"
            "IF X_0 AND stop THEN\n  alarm := TRUE;\nEND_IF;\n"
            "X_0 := S_FS OR Y_1 OR X_0 AND NOT Y_0;\n"
            "X_1 := Y_0 OR X_1 AND NOT Y_1;\n"
            "Y_0 := X_0 AND start;\n"
            "Y_1 := X_1 AND T1.Q;\n"
            "S_FS := FALSE;\n");
  // X and Y are used only bit by bit: one BOOL per bit used; T1 is the TON TON runs.
  EXPECT_EQ(pou.find_variable("X"), nullptr);
  for (const char* bit : {"X_0", "X_1", "Y_0", "Y_1"}) {
    ASSERT_NE(pou.find_variable(bit), nullptr) << bit;
    EXPECT_EQ(pou.find_variable(bit)->type.kind, model::TypeKind::Bool) << bit;
  }
  ASSERT_NE(pou.find_variable("T1"), nullptr);
  EXPECT_EQ(pou.find_variable("T1")->type.fb, model::StandardFb::TON);
  EXPECT_EQ(pou.find_variable("S_FS")->initial, 1);
}

// issue 46: a native file's model goes through `sfcv export --to plcopen` (and IEC text) and
// loads back as the same model: the ladder body, its BOOL bits, the TON instance and S_FS.
TEST(L5xLadder, TheLadderModelRoundTripsThroughPlcopenAndIecText) {
  auto routines = ladder_routines();
  const std::string jsr = "JSR(Transitions,0);";
  routines.replace(routines.find(jsr), jsr.size(),
                   jsr + "]]>\n</Text>\n</Rung>\n" +
                       "<Rung Number=\"3\" Type=\"N\">\n<Text>\n"
                       "<![CDATA[JSR(Pulse,0);");
  routines += rll_routine("Pulse", {"XIC(start)ONS(mem)OTE(pulse);"});
  const auto r = io::load_l5x(
      l5x_ladder(ladder_tags() + bool_tag("mem", 0) + alias("pulse", "Local:1:O.Data.1"), routines),
      "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  ASSERT_NE(ladder_body(r).find("mem := start;"), std::string::npos) << ladder_body(r);
  plcopen_round_trip(*r.project);
  iec_round_trip(*r.project);
}

TEST(L5xLadder, ABitOfAnIntegerTagKeepsItsInitialValue) {
  const auto r = io::load_l5x(
      l5x_ladder(dint_tag("X", 5) + alias("q", "Local:1:O.Data.0"),
                 rll_routine("Main", {"XIC(X.0)XIO(X.1)XIC(X.2)OTE(q);", "XIC(q)OTU(X.2);"})),
      "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous.back();
  EXPECT_EQ(pou.find_variable("X_0")->initial, 1);
  EXPECT_EQ(pou.find_variable("X_1")->initial, 0);
  EXPECT_EQ(pou.find_variable("X_2")->initial, 1);
}

TEST(L5xLadder, AConditionReadAfterAWriteToWhatItReadsKeepsItsValue) {
  // XIC(a) OTU(a) OTE(b): b gets the condition as it was before OTU reset a (the rung runs left
  // to right on one condition); a hidden temporary keeps it, reset at the end of the body.
  const auto r = io::load_l5x(
      l5x_ladder(bool_tag("a", 0) + bool_tag("b", 0), rll_routine("Main", {"XIC(a)OTU(a)OTE(b);"})),
      "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(ladder_body(r),
            "SFCV_RLL_1_1 := a;\nIF SFCV_RLL_1_1 THEN\n  a := FALSE;\nEND_IF;\n"
            "b := SFCV_RLL_1_1;\nSFCV_RLL_1_1 := FALSE;\n");
  // ONS: the condition out is TRUE on the scan the condition in becomes TRUE, the storage bit
  // keeps the condition in.
  const auto ons = io::load_l5x(l5x_ladder(alias("go", "Local:1:I.Data.0") + bool_tag("mem", 0) +
                                               alias("pulse", "Local:1:O.Data.0"),
                                           rll_routine("Main", {"XIC(go)ONS(mem)OTE(pulse);"})),
                                "Cell.L5X");
  ASSERT_TRUE(ons.ok()) << errors_of(ons);
  EXPECT_EQ(ladder_body(ons),
            "SFCV_RLL_1_1 := go AND NOT mem;\nmem := go;\npulse := SFCV_RLL_1_1;\n"
            "SFCV_RLL_1_1 := FALSE;\n");
}

TEST(L5xLadder, WhatTheModelCannotSayIsRefusedAtItsRung) {
  const auto tags = ladder_tags() + dint_tag("n", 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"XIC(start)RTO(T1,?,?);", "rung 0 of routine 'Main': unsupported: RLL instruction RTO"},
      {"XIC(start)TON(T1,?,?)OTE(motor);", "unsupported: OTE after TON"},
      {"XIC(start)JSR(Main,0);", "recursive JSR: routine 'Main'"},
      {"JSR(Nowhere,0);", "JSR to 'Nowhere', which is not in the program"},
      {"JSR(Actions,1,start);", "unsupported: JSR with parameters"},
      {"XIC(start)[OTE(n.3) ,MOV(1,n) ];", "unsupported: writing 'n.3'"},
      {"XIC(start)TON(motor,?,?);", "TON on 'motor', which is not a TIMER tag"},
      {"XIC(start)OTE(Local:1:O.Data.3);", "unsupported: operand 'Local:1:O.Data.3'"},
      {"XIC(T1.ACC)TON(T1,?,?);", "'T1.ACC' (of a TIMER, .DN, .EN and .TT are read)"},
      {"XIC(start OTE(motor);", "rung 0 of routine 'Main': instruction XIC without its ')'"},
      {"[XIC(start) ,XIC(stop) OTE(motor);", "';' inside a branch"},
      {"[XIC(start) ,XIC(stop) OTE(motor)", "a branch '[' without its ']'"},
  };
  for (const auto& [text, message] : cases) {
    SCOPED_TRACE(text);
    auto routines = rll_routine("Main", {text});
    routines += rll_routine("Actions", {"XIC(X.1)OTE(motor);"});
    const auto r = io::load_l5x(l5x_ladder(tags, routines), "Cell.L5X");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(errors_of(r).find(message), std::string::npos) << errors_of(r);
    EXPECT_NE(errors_of(r).find("Routine[@name='Main']/RLLContent/Rung"), std::string::npos)
        << errors_of(r);
  }
}

TEST(L5xLadder, RoutinesMainDoesNotCallAreNotReadAndSaySo) {
  const auto routines =
      ladder_routines() + "<Routine Name=\"Chart\" Type=\"SFC\">\n<SFCContent>\n" + demo_sfc() +
      "</SFCContent>\n</Routine>\n" + rll_routine("Spare", {"XIC(start)CTU(C1,?,?);"});
  const auto r = io::load_l5x(l5x_ladder(ladder_tags(), routines), "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_NE(errors_of(r).find("routine 'Chart' (SFC) is not called from the main routine 'Main': "
                              "not read"),
            std::string::npos)
      << errors_of(r);
  EXPECT_TRUE(r.project->pous.back().charts.empty());
  // An SFC routine that main does call is refused: its place in the scan is not read.
  auto called = routines;
  called.replace(called.find("JSR(Transitions,0);"), 19, "JSR(Chart,0);");
  const auto refused = io::load_l5x(l5x_ladder(ladder_tags(), called), "Cell.L5X");
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(errors_of(refused).find("JSR to the SFC routine 'Chart'"), std::string::npos)
      << errors_of(refused);
}

// Online edits (1756-RM084 rung types): with TestEdits false the controller runs the original
// rungs (R to be replaced, D to be deleted), not the inserted ones (I, IR); with TestEdits true,
// the edited ones.
TEST(L5xLadder, PendingEditsRunAsTheControllerRunsThem) {
  const auto routine =
      "<Routine Name=\"Main\" Type=\"RLL\">\n<RLLContent>\n" + rung(0, "XIC(start)OTE(motor);") +
      "<Rung Number=\"1\" Type=\"IR\">\n<Text>\n<![CDATA[XIC(stop)OTE(alarm);]]>\n"
      "</Text>\n</Rung>\n<Rung Number=\"2\" Type=\"R\">\n<Text>\n<![CDATA[XIO(stop)"
      "OTE(alarm);]]>\n</Text>\n</Rung>\n</RLLContent>\n</Routine>\n";
  const auto original = io::load_l5x(l5x_ladder(ladder_tags(), routine), "Cell.L5X");
  ASSERT_TRUE(original.ok()) << errors_of(original);
  EXPECT_EQ(ladder_body(original), "motor := start;\nalarm := NOT stop;\n");
  EXPECT_NE(errors_of(original).find("rung 1 of routine 'Main' (Type 'IR') is a pending edit"),
            std::string::npos);
  auto tested_text = l5x_ladder(ladder_tags(), routine);
  const std::string program = "Name=\"Cell\" MainRoutineName";
  tested_text.replace(tested_text.find(program), program.size(),
                      "Name=\"Cell\" TestEdits=\"true\" MainRoutineName");
  const auto tested = io::load_l5x(tested_text, "Cell.L5X");
  ASSERT_TRUE(tested.ok()) << errors_of(tested);
  EXPECT_EQ(ladder_body(tested), "motor := start;\nalarm := stop;\n");
}

// Parts of tags of a user type: each part the rungs use is a variable of its own, named by its
// path, with the initial value of the tag's decorated data; the other parts are left out. The
// controller's tag's parts go to the controller's list.
TEST(L5xLadder, PartsOfStructuredTagsTheRungsUseAreVariables) {
  const auto r = io::load_l5x(
      l5x_ladder(dint_tag("n", 0),
                 rll_routine("Main", {"XIC(Cell1.BIT_Logic[1].0)XIO(Cell1.BIT_Logic[1].1)"
                                      "TON(Cell1.TMR[3],?,?);",
                                      "XIC(Cell1.TMR[3].DN)OTE(Cell1.Flag);",
                                      "XIC(Cell1.Flag)ADD(Cell1.SP[2],1,Cell1.SP[0]);",
                                      "XIC(Cell1.BIT_Logic[1].2)RES(Cell1.TMR[3]);",
                                      "XIC(cell1.bit_logic[1].3)SUB(Cell1.SP[0],Cell1.TMR[3].PRE,n)"
                                      "MUL(n,2,n);"}),
                 cell_data_type(), cell_tag("Cell1", 0b0101, 7, 2000)),
      "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(ladder_body(r),
            "Cell1_TMR_3(IN := Cell1_BIT_Logic_1_0 AND NOT Cell1_BIT_Logic_1_1, PT := T#2s);\n"
            "Cell1_Flag := Cell1_TMR_3.Q;\n"
            "IF Cell1_Flag THEN\n  Cell1_SP_0 := Cell1_SP_2 + 1;\nEND_IF;\n"
            "IF Cell1_BIT_Logic_1_2 THEN\n  Cell1_TMR_3(IN := FALSE, PT := T#2s);\nEND_IF;\n"
            "IF Cell1_BIT_Logic_1_3 THEN\n  n := Cell1_SP_0 - 2000;\nEND_IF;\n"
            "IF Cell1_BIT_Logic_1_3 THEN\n  n := n * 2;\nEND_IF;\n");
  const auto* globals = r.project->find_pou("Plant");
  ASSERT_NE(globals, nullptr);
  const std::vector<std::pair<const char*, std::int64_t>> initial = {
      {"Cell1_BIT_Logic_1_0", 1}, {"Cell1_BIT_Logic_1_1", 0}, {"Cell1_BIT_Logic_1_2", 1},
      {"Cell1_BIT_Logic_1_3", 0}, {"Cell1_SP_0", 0},          {"Cell1_SP_2", 7},
      {"Cell1_Flag", 0}};
  for (const auto& [name, value] : initial) {
    const auto* v = globals->find_variable(name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->direction, model::VarDirection::Global) << name;
    EXPECT_EQ(v->initial, value) << name;
  }
  EXPECT_EQ(globals->find_variable("Cell1_SP_2")->type.name, "DINT");
  // A TIMER is the TON instance of the program that runs it (the semantics calls the instances
  // a POU declares), even the controller's.
  EXPECT_EQ(globals->find_variable("Cell1_TMR_3"), nullptr);
  const auto* timer = r.project->pous.back().find_variable("Cell1_TMR_3");
  ASSERT_NE(timer, nullptr);
  EXPECT_EQ(timer->type.fb, model::StandardFb::TON);
  // Only what the rungs use: BIT_Logic[1] is read bit by bit, SP[1], TMR[0] and Level not at all.
  for (const char* absent : {"Cell1_BIT_Logic_1", "Cell1_SP_1", "Cell1_TMR_0", "Cell1_Level"})
    EXPECT_EQ(globals->find_variable(absent), nullptr) << absent;
  // The controller's list goes through PLCopen as a configuration's global variables.
  EXPECT_NE(plcopen_round_trip(*r.project).find("<globalVars name=\"Plant\">"), std::string::npos);
  iec_round_trip(*r.project);
}

// CTU, CTD and RES of a COUNTER as 1756-RM003 writes them: with the rung TRUE and .CU clear,
// .ACC goes up; with the rung TRUE, .CU is set and .DN is .ACC >= .PRE; with the rung FALSE,
// .CU is cleared. RES clears .ACC and the status bits; the prescan sets .CU and .CD.
TEST(L5xLadder, CountersAreTheirAccumulatorAndStatusBits) {
  const auto r = io::load_l5x(
      l5x_ladder(counter_tag("C1", 3) + alias("go", "Local:1:I.Data.0") +
                     alias("down", "Local:1:I.Data.1") + alias("rst", "Local:1:I.Data.2") +
                     alias("q", "Local:1:O.Data.0"),
                 rll_routine("Main", {"XIC(go)CTU(C1,?,?);", "CTD(C1,?,?);", "XIC(rst)RES(C1);",
                                      "XIC(C1.DN)GEQ(C1.ACC,C1.PRE)OTE(q);"})),
      "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(ladder_body(r),
            "IF go THEN\n  IF NOT C1_CU THEN\n    C1_ACC := C1_ACC + 1;\n  END_IF;\n"
            "  C1_CU := TRUE;\n  C1_DN := C1_ACC >= 3;\nELSE\n  C1_CU := FALSE;\nEND_IF;\n"
            "IF NOT C1_CD THEN\n  C1_ACC := C1_ACC - 1;\nEND_IF;\nC1_CD := TRUE;\n"
            "C1_DN := C1_ACC >= 3;\n"
            "IF rst THEN\n  C1_ACC := 0;\n  C1_CU := FALSE;\n  C1_CD := FALSE;\n"
            "  C1_DN := FALSE;\nEND_IF;\n"
            "q := C1_DN AND C1_ACC >= 3;\n");
  const auto& pou = r.project->pous.back();
  EXPECT_EQ(pou.find_variable("C1_CU")->initial, 1);
  EXPECT_EQ(pou.find_variable("C1_CD")->initial, 1);
  EXPECT_EQ(pou.find_variable("C1_DN")->initial, 0);
  EXPECT_EQ(pou.find_variable("C1_ACC")->type.name, "DINT");
  plcopen_round_trip(*r.project);
  iec_round_trip(*r.project);
}

// Two programs of one file read a controller tag's part as one global variable, and must read
// it alike (bit by bit in both, or whole in both).
TEST(L5xLadder, ProgramsShareTheControllerTagsParts) {
  auto two_programs = [](const std::string& first, const std::string& second) {
    auto text = l5x_ladder(alias("go", "Local:1:I.Data.0"), rll_routine("Main", {first}),
                           cell_data_type(), cell_tag("Cell1", 0, 0, 100));
    const auto from = text.find("<Program Use=");
    const auto to = text.find("</Program>") + std::string("</Program>\n").size();
    auto copy = text.substr(from, to - from);
    copy.replace(copy.find("Name=\"Cell\""), 11, "Name=\"Cell2\"");
    const auto rung = copy.find(first);
    copy.replace(rung, first.size(), second);
    return text.insert(to, copy);
  };
  auto r = io::load_l5x(two_programs("XIC(go)OTE(Cell1.BIT_Logic[1].0);",
                                     "XIC(Cell1.BIT_Logic[1].0)MOV(1,Cell1.SP[0]);"),
                        "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* globals = r.project->find_pou("Plant");
  ASSERT_NE(globals, nullptr);
  EXPECT_EQ(std::count_if(globals->variables.begin(), globals->variables.end(),
                          [](const auto& v) { return v.name == "Cell1_BIT_Logic_1_0"; }),
            1);
  EXPECT_NE(globals->find_variable("Cell1_SP_0"), nullptr);
  r = io::load_l5x(
      two_programs("XIC(go)OTE(Cell1.BIT_Logic[1].0);", "XIC(go)MOV(1,Cell1.BIT_Logic[1]);"),
      "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("'Cell1.BIT_Logic[1]' is used bit by bit in one program and as a "
                              "whole in another"),
            std::string::npos)
      << errors_of(r);
  r = io::load_l5x(
      two_programs("XIC(go)TON(Cell1.TMR[3],?,?);", "XIC(Cell1.TMR[3].DN)OTE(Cell1.Flag);"),
      "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("the controller's TIMER 'Cell1.TMR[3]' is used by two programs"),
            std::string::npos)
      << errors_of(r);
}

TEST(L5xLadder, ArithmeticAndComputeAssignWhereTheRungIsTrue) {
  const auto r =
      io::load_l5x(l5x_ladder(dint_tag("d", 0) + dint_tag("m", 0) + dint_tag("e", 0) +
                                  dint_tag("c", 0) + alias("go", "Local:1:I.Data.0"),
                              rll_routine("Main", {"XIC(go)DIV(-7,2,d)MOD(-7,2,m);", "NEG(d,e);",
                                                   "CPT(c,(d - 1) * 2 + ABS(m) MOD 2);"})),
                   "Cell.L5X");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(ladder_body(r),
            "IF go THEN\n  d := -7 / 2;\nEND_IF;\nIF go THEN\n  m := -7 MOD 2;\nEND_IF;\n"
            "e := -d;\nc := (d - 1) * 2 + ABS(m) MOD 2;\n");
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"CPT(c,d ** 2);", "CPT expression 'd ** 2': '**' is not read"},
      {"CPT(c,SQRT(d));", "CPT expression 'SQRT(d)': the function SQRT is not read (ABS is)"},
      {"CPT(c,d AND 3);", "unexpected 'A'"},
      {"CPT(c,(d + 1);", "without its ')'"},
      {"CPT(c,d * 1.5);", "the REAL literal 1.5 is not read"},
      {"CPT(c,Local:1:I.Data + 1);",
       "CPT expression 'Local:1:I.Data + 1': unsupported: operand 'Local:1:I.Data'"},
  };
  for (const auto& [text, message] : refused) {
    SCOPED_TRACE(text);
    const auto bad = io::load_l5x(
        l5x_ladder(dint_tag("d", 0) + dint_tag("c", 0), rll_routine("Main", {text})), "Cell.L5X");
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(errors_of(bad).find(message), std::string::npos) << errors_of(bad);
  }
}

// A consumed tag is written by the controller producing it: its parts are read like a base
// tag's (globals nothing in the file writes: inputs, docs/semantics.md 1.8), and a rung writing
// one is refused.
TEST(L5xLadder, ConsumedTagsAreReadAndNeverWritten) {
  auto consumed = cell_tag("Still", 0b10, 0, 100);
  const std::string base = "TagType=\"Base\"";
  consumed.replace(consumed.find(base), base.size(), "TagType=\"Consumed\"");
  const auto plain =
      "<Tag Name=\"Level\" TagType=\"Consumed\" DataType=\"DINT\">\n"
      "<Data Format=\"Decorated\">\n<DataValue DataType=\"DINT\" Value=\"4\"/>\n"
      "</Data>\n</Tag>\n";
  auto load = [&](const std::string& rung) {
    return io::load_l5x(l5x_ladder(alias("q", "Local:1:O.Data.0"), rll_routine("Main", {rung}),
                                   cell_data_type(), consumed + plain),
                        "Cell.L5X");
  };
  const auto r = load("XIC(Still.BIT_Logic[1].1)GRT(Level,3)OTE(q);");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* globals = r.project->find_pou("Plant");
  ASSERT_NE(globals, nullptr);
  ASSERT_NE(globals->find_variable("Still_BIT_Logic_1_1"), nullptr);
  EXPECT_EQ(globals->find_variable("Still_BIT_Logic_1_1")->initial, 1);
  EXPECT_EQ(globals->find_variable("Level")->initial, 4);
  for (const auto& [rung, operand] : std::vector<std::pair<std::string, std::string>>{
           {"XIC(q)OTE(Still.BIT_Logic[1].1);", "Still.BIT_Logic[1].1"},
           {"XIC(q)MOV(1,Level);", "Level"},
           {"XIC(q)ADD(Still.SP[0],1,Still.SP[0]);", "Still.SP[0]"}}) {
    SCOPED_TRACE(rung);
    const auto bad = load(rung);
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(errors_of(bad).find("unsupported: writing '" + operand + "', a consumed tag"),
              std::string::npos)
        << errors_of(bad);
  }
}

// An element chosen by a tag, read: MUX over the elements (each a variable), the index out of
// the array's bounds being MUX's range error; written: refused.
TEST(L5xLadder, AnElementChosenByATagIsReadAsAMux) {
  const std::string row_type =
      "<DataType Name=\"Row\" Family=\"NoFamily\" Class=\"User\">\n<Members>\n"
      "<Member Name=\"Cols\" DataType=\"DINT\" Dimension=\"4\" Radix=\"Decimal\" "
      "Hidden=\"false\"/>\n</Members>\n</DataType>\n";
  const std::string arrays =
      "<Tag Name=\"Grid\" TagType=\"Base\" DataType=\"DINT\" Dimensions=\"3 2\"/>\n"
      "<Tag Name=\"Rows\" TagType=\"Base\" DataType=\"Row\" Dimensions=\"3\"/>\n";
  auto load = [&](const std::string& rung) {
    return io::load_l5x(
        l5x_ladder(dint_tag("n", 0) + dint_tag("m", 0) + alias("q", "Local:1:O.Data.0") + arrays,
                   rll_routine("Main", {rung}), cell_data_type() + row_type,
                   cell_tag("Cell1", 0, 7, 100)),
        "Cell.L5X");
  };
  const auto r = load("XIC(Cell1.BIT_Logic[n].1)MOV(Cell1.SP[n],m)OTE(q);");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(ladder_body(r),
            "IF MUX(n, Cell1_BIT_Logic_0_1, Cell1_BIT_Logic_1_1, Cell1_BIT_Logic_2_1, "
            "Cell1_BIT_Logic_3_1) THEN\n  m := MUX(n, Cell1_SP_0, Cell1_SP_1, Cell1_SP_2);\n"
            "END_IF;\nq := MUX(n, Cell1_BIT_Logic_0_1, Cell1_BIT_Logic_1_1, Cell1_BIT_Logic_2_1, "
            "Cell1_BIT_Logic_3_1);\n");
  EXPECT_EQ(r.project->find_pou("Plant")->find_variable("Cell1_SP_2")->initial, 7);
  // Written: a CASE over the elements, its ELSE MUX's range error (lower_data_types' form).
  const auto written = load("XIC(q)OTL(Cell1.BIT_Logic[n].1)MOV(4,Cell1.SP[n]);");
  ASSERT_TRUE(written.ok()) << errors_of(written);
  plcopen_round_trip(*written.project);
  iec_round_trip(*written.project);
  EXPECT_EQ(ladder_body(written),
            "CASE n OF\n  0:\n    IF q THEN\n      Cell1_BIT_Logic_0_1 := TRUE;\n    END_IF;\n"
            "  1:\n    IF q THEN\n      Cell1_BIT_Logic_1_1 := TRUE;\n    END_IF;\n"
            "  2:\n    IF q THEN\n      Cell1_BIT_Logic_2_1 := TRUE;\n    END_IF;\n"
            "  3:\n    IF q THEN\n      Cell1_BIT_Logic_3_1 := TRUE;\n    END_IF;\n"
            "ELSE\n    Cell1_BIT_Logic_0_1 := MUX(n, Cell1_BIT_Logic_0_1, Cell1_BIT_Logic_1_1, "
            "Cell1_BIT_Logic_2_1, Cell1_BIT_Logic_3_1);\nEND_CASE;\n"
            "CASE n OF\n  0:\n    IF q THEN\n      Cell1_SP_0 := 4;\n    END_IF;\n"
            "  1:\n    IF q THEN\n      Cell1_SP_1 := 4;\n    END_IF;\n"
            "  2:\n    IF q THEN\n      Cell1_SP_2 := 4;\n    END_IF;\n"
            "ELSE\n    Cell1_SP_0 := MUX(n, Cell1_SP_0, Cell1_SP_1, Cell1_SP_2);\nEND_CASE;\n");
  // Program tags: an element of two dimensions, and a tag choosing an array of structures.
  const auto grid = load("MOV(Grid[2,1],m)MOV(Rows[n].Cols[2],m);");
  ASSERT_TRUE(grid.ok()) << errors_of(grid);
  EXPECT_EQ(ladder_body(grid),
            "m := Grid_2_1;\nm := MUX(n, Rows_0_Cols_2, Rows_1_Cols_2, Rows_2_Cols_2);\n");
  for (const auto& [rung, message] : std::vector<std::pair<std::string, std::string>>{
           {"XIC(q)TON(Cell1.TMR[n],?,?);",
            "operand 'Cell1.TMR[n]' (an element chosen by 'n' is read where it is a BOOL or an "
            "integer"},
           {"XIC(Cell1.SP[n].TMR)OTE(q);", "'Cell1.SP[0]' is DINT, 'TMR' of it"},
           {"XIC(Cell1[n].Flag)OTE(q);", "'Cell1' is not an array"},
           {"MOV(Grid[n,1],m);", "(an index list with a tag in it: 'n,1')"},
           {"XIC(Rows[n].Cols[m])OTE(q);",
            "operand 'Rows[n].Cols[m]' (an element chosen by 'n' is read where it is a BOOL or an "
            "integer and the operand's only such index)"},
           {"XIC(Cell1.TMR[Cell1.SP[n]].DN)OTE(q);", "TIMER 'Cell1.TMR[0]' is not run by a TON"}}) {
    SCOPED_TRACE(rung);
    const auto bad = load(rung);
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(errors_of(bad).find(message), std::string::npos) << errors_of(bad);
  }
}

// A part's name that is also a tag in the other scope would hide one of them: refused.
TEST(L5xLadder, APartNamedLikeATagOfTheOtherScopeIsRefused) {
  auto r = io::load_l5x(
      l5x_ladder(dint_tag("Cell1_SP_0", 0), rll_routine("Main", {"MOV(1,Cell1.SP[0]);"}),
                 cell_data_type(), cell_tag("Cell1", 0, 0, 100)),
      "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("its part 'Cell1.SP[0]' is read as 'Cell1_SP_0', which is already a "
                              "tag of the program 'Cell' (one would hide the other)"),
            std::string::npos)
      << errors_of(r);
  r = io::load_l5x(
      l5x_ladder(cell_tag("Mine", 0, 0, 100), rll_routine("Main", {"MOV(1,Mine.SP[0]);"}),
                 cell_data_type(), dint_tag("Mine_SP_0", 0)),
      "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(
      errors_of(r).find("which is already a tag of the controller (one would hide the other)"),
      std::string::npos)
      << errors_of(r);
  // The same for a plain integer tag read bit by bit (X.3 is X_3).
  r = io::load_l5x(l5x_ladder(dint_tag("X", 0), rll_routine("Main", {"XIC(X.3)OTE(X.4);"}),
                              cell_data_type(), bool_tag("X_3", 0)),
                   "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("the BOOL 'X_3' that a bit of an integer tag is read as is already "
                              "a tag of the controller"),
            std::string::npos)
      << errors_of(r);
}

TEST(L5xLadder, PartsTheModelCannotSayAreRefusedAtTheirRung) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"XIC(go)TON(Cell1.TMR[n],?,?);",
       "(an element chosen by 'n' is read where it is a BOOL or an integer"},
      {"XIC(go)MOV(Cell1.Level,n);", "'Cell1.Level' (REAL) as an integer"},
      {"XIC(go)MOV(1,Cell1.SP[3]);", "index 3 is out of the bounds of 'Cell1.SP' (0..2)"},
      {"XIC(go)MOV(1,Cell1.Nope);", "'Cell1' (of type Cell_Data) has no member 'Nope'"},
      {"XIC(go)MOV(1,Cell1.SP);", "a whole array, 'Cell1.SP', is not read"},
      {"XIC(go)MOV(Cell1,n);", "a whole structure, 'Cell1' of type Cell_Data, is not read"},
      {"XIC(go)TON(Cell1.TMR[2],?,?);XIC(go)MOV(5,Cell1.TMR[2].PRE);",
       "a TIMER's or COUNTER's preset is read from its tag's data"},
      {"XIC(Cell1.TMR[4].DN)OTE(q);", "TIMER 'Cell1.TMR[4]' is not run by a TON"},
      {"XIC(Cell1.SP[1].2)MOV(1,Cell1.SP[1]);",
       "a bit of 'Cell1.SP[1]' is read when the rungs use that element only bit by bit"},
      {"XIC(go)TON(Cell1.TMR[1],?,?);XIC(q)TON(Cell1.TMR[1],?,?);",
       "TON runs 2 times on TIMER 'Cell1.TMR[1]'"},
      {"XIC(go)RES(n);", "unsupported: RES on 'n'"},
      {"XIC(go)CTU(n,?,?);", "'n' is not a COUNTER tag"},
      {"XIC(go)CTU(Cell1.SP[1],?,?);", "'Cell1.SP[1]' is not a COUNTER tag (it is DINT)"},
      {"XIC(go)COP(Cell1.SP[0],n,1);", "unsupported: RLL instruction COP"},
  };
  for (const auto& [text, message] : cases) {
    SCOPED_TRACE(text);
    std::vector<std::string> rungs;
    for (std::size_t from = 0; from < text.size();) {
      const auto end = text.find(';', from);
      rungs.push_back(text.substr(from, end - from + 1));
      from = end + 1;
    }
    const auto r = io::load_l5x(
        l5x_ladder(
            dint_tag("n", 0) + alias("go", "Local:1:I.Data.0") + alias("q", "Local:1:O.Data.0"),
            rll_routine("Main", rungs), cell_data_type(), cell_tag("Cell1", 0, 0, 100)),
        "Cell.L5X");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(errors_of(r).find(message), std::string::npos) << errors_of(r);
  }
}

TEST(L5xLadder, InputsThatWouldExpandOrRecurseWithoutBoundAreRefused) {
  // 30 routines, each calling the next twice: 2^30 copies of the last one if unfolded.
  std::string routines = rll_routine("Main", {"JSR(R0,0);", "JSR(R0,0);"});
  for (int i = 0; i < 30; ++i) {
    const auto next = "R" + std::to_string(i + 1);
    routines +=
        rll_routine("R" + std::to_string(i), {"JSR(" + next + ",0);", "JSR(" + next + ",0);"});
  }
  routines += rll_routine("R30", {"XIC(start)OTE(motor);"});
  auto r = io::load_l5x(l5x_ladder(ladder_tags(), routines), "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("the JSR calls unfold into more than 200000 statements"),
            std::string::npos)
      << errors_of(r).substr(0, 2000);
  // A chain of 100 JSRs.
  routines = rll_routine("Main", {"JSR(R0,0);"});
  for (int i = 0; i < 100; ++i)
    routines += rll_routine("R" + std::to_string(i), {"JSR(R" + std::to_string(i + 1) + ",0);"});
  routines += rll_routine("R100", {"XIC(start)OTE(motor);"});
  r = io::load_l5x(l5x_ladder(ladder_tags(), routines), "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("JSR calls nested deeper than 64"), std::string::npos);
  // Branches nested 10,000 deep, and a rung of 20,000 instructions.
  r = io::load_l5x(
      l5x_ladder(ladder_tags(), rll_routine("Main", {std::string(10000, '[') + "XIC(start)" +
                                                     std::string(10000, ']') + "OTE(motor);"})),
      "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("branches nested too deep"), std::string::npos);
  std::string wide;
  for (int i = 0; i < 20000; ++i) wide += "XIC(start)";
  r = io::load_l5x(l5x_ladder(ladder_tags(), rll_routine("Main", {wide + "OTE(motor);"})),
                   "Cell.L5X");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("more than 10000 instructions in one rung"), std::string::npos);
  // A bit number no integer has is not a number the reader converts.
  r = io::load_l5x(
      l5x_ladder(ladder_tags(), rll_routine("Main", {"XIC(X.99999999999999999999)OTE(motor);"})),
      "Cell.L5X");
  EXPECT_TRUE(r.ok()) << errors_of(r);  // loads; the semantics refuses the bit access
}

}  // namespace
}  // namespace sfcv::test

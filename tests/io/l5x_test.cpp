// Rockwell Studio 5000 .L5X exports (docs/formats.md): an SFC main routine read through its
// DirectedLinks gives the model its IEC 61131-3 text twin gives; Rockwell's own constructs the
// model has no meaning for are refused at their element. The files are written in the vendor's
// shape (tests/support/l5x_text.hpp), never copied from public exports.

#include <gtest/gtest.h>

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
  // A step's timer bit: Rockwell's SFC_STEP.DN depends on its preset, not modelled.
  auto sfc = demo_sfc();
  sfc.replace(sfc.find("NOT a"), 5, "S1.DN");
  expect_refused(l5x(demo_tags(), sfc), "'S1.DN': member DN of the SFC_STEP tag",
                 "Routine[@name='Chart']/SFCContent/Transition[3]/Condition/STContent");
  // The non-retentive assignment.
  sfc = demo_sfc();
  sfc.replace(sfc.find("lamp := TRUE"), 12, "lamp [:=] TRUE");
  expect_refused(l5x(demo_tags(), sfc), "non-retentive assignment '[:=]'");
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
  // An alias the model cannot type.
  expect_refused(l5x(demo_tags() + alias("w", "Local:1:I.Data"), demo_sfc()),
                 "alias tag 'w' for 'Local:1:I.Data'");
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
  // The SFC routine is not the main one: called by JSR from ladder, which is not read.
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("SFC routine 'Chart' is not the program's main routine"),
            std::string::npos)
      << errors_of(r);
}

}  // namespace
}  // namespace sfcv::test

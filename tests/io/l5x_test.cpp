// Rockwell Studio 5000 .L5X exports (docs/formats.md): an SFC main routine read through its
// DirectedLinks gives the model its IEC 61131-3 text twin gives; Rockwell's own constructs the
// model has no meaning for are refused at their element. The files are written here in the
// vendor's shape (the layout of public exports such as francisboudreau7/l5x_sfc
// tests/MainProgram.L5X: Step/Transition/Branch elements, then the links), never copied.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/expr.hpp"
#include "round_trip.hpp"

namespace sfcv::test {
namespace {

std::string st(const std::vector<std::string>& lines) {
  std::string s = "<STContent>\n";
  for (std::size_t i = 0; i < lines.size(); ++i)
    s += "<Line Number=\"" + std::to_string(i) + "\">\n<![CDATA[" + lines[i] + "]]>\n</Line>\n";
  return s + "</STContent>\n";
}

std::string step(int id, const std::string& name, bool initial, int x = 200,
                 const std::string& actions = "") {
  return "<Step ID=\"" + std::to_string(id) + "\" X=\"" + std::to_string(x) +
         "\" Y=\"100\" Operand=\"" + name + "\" HideDesc=\"false\" InitialStep=\"" +
         (initial ? "true" : "false") + "\" PresetUsesExpr=\"false\" ShowActions=\"true\"" +
         (actions.empty() ? "/>\n" : ">\n" + actions + "</Step>\n");
}

std::string action(int id, const std::string& name, const std::vector<std::string>& body,
                   const std::string& qualifier = "NonStored") {
  return "<Action ID=\"" + std::to_string(id) + "\" Operand=\"" + name + "\" Qualifier=\"" +
         qualifier + "\" IsBoolean=\"false\" PresetUsesExpr=\"false\">\n<Body>\n" + st(body) +
         "</Body>\n</Action>\n";
}

std::string transition(int id, const std::string& name, const std::string& condition, int x = 200) {
  return "<Transition ID=\"" + std::to_string(id) + "\" X=\"" + std::to_string(x) +
         "\" Y=\"300\" Operand=\"" + name + "\" HideDesc=\"false\">\n<Condition>\n" +
         st({condition}) + "</Condition>\n</Transition>\n";
}

std::string branch(int id, const char* type, const char* flow, int leg1, int leg2) {
  return "<Branch ID=\"" + std::to_string(id) + "\" Y=\"500\" BranchType=\"" + type +
         "\" BranchFlow=\"" + flow + "\">\n<Leg ID=\"" + std::to_string(leg1) + "\"/>\n<Leg ID=\"" +
         std::to_string(leg2) + "\"/>\n</Branch>\n";
}

std::string links(const std::vector<std::pair<int, int>>& ls) {
  std::string s;
  for (const auto& [from, to] : ls)
    s += "<DirectedLink FromID=\"" + std::to_string(from) + "\" ToID=\"" + std::to_string(to) +
         "\" Show=\"true\"/>\n";
  return s;
}

std::string alias(const std::string& name, const std::string& io) {
  return "<Tag Name=\"" + name + "\" TagType=\"Alias\" Radix=\"Decimal\" AliasFor=\"" + io +
         "\" ExternalAccess=\"Read/Write\"/>\n";
}

std::string bool_tag(const std::string& name, int value) {
  return "<Tag Name=\"" + name +
         "\" TagType=\"Base\" DataType=\"BOOL\" Radix=\"Decimal\" Constant=\"false\">\n"
         "<Data Format=\"L5K\">\n<![CDATA[" +
         std::to_string(value) +
         "]]>\n</Data>\n<Data Format=\"Decorated\">\n<DataValue DataType=\"BOOL\" "
         "Radix=\"Decimal\" "
         "Value=\"" +
         std::to_string(value) + "\"/>\n</Data>\n</Tag>\n";
}

std::string sfc_tag(const std::string& name, const char* type) {
  return "<Tag Name=\"" + name + "\" TagType=\"Base\" DataType=\"" + type +
         "\" Constant=\"false\"/>\n";
}

std::string l5x(const std::string& tags, const std::string& sfc,
                const std::string& controller_attributes =
                    " SFCExecutionControl=\"CurrentActive\" SFCRestartPosition=\"MostRecent\" "
                    "SFCLastScan=\"DontScan\"") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n"
         "<RSLogix5000Content SchemaRevision=\"1.0\" SoftwareRevision=\"32.01\" "
         "TargetName=\"Press\" TargetType=\"Program\" ContainsContext=\"true\">\n"
         "<Controller Use=\"Context\" Name=\"Plant\"" +
         controller_attributes +
         ">\n<DataTypes Use=\"Context\">\n</DataTypes>\n<Tags Use=\"Context\">\n</Tags>\n"
         "<Programs Use=\"Context\">\n<Program Use=\"Target\" Name=\"Press\" "
         "MainRoutineName=\"Chart\" Disabled=\"false\" UseAsFolder=\"false\">\n<Tags>\n" +
         tags + "</Tags>\n<Routines>\n<Routine Name=\"Chart\" Type=\"SFC\">\n<SFCContent>\n" + sfc +
         "</SFCContent>\n</Routine>\n</Routines>\n</Program>\n</Programs>\n</Controller>\n"
         "</RSLogix5000Content>\n";
}

std::string demo_tags() {
  return alias("start", "Local:1:I.Data.0") + alias("stop", "Local:1:I.Data.1") +
         alias("a", "Local:1:I.Data.2") + alias("lamp", "Local:1:O.Data.0") +
         alias("valve", "Local:1:O.Data.1") + bool_tag("m", 0) + sfc_tag("Init", "SFC_STEP") +
         sfc_tag("A_Init", "SFC_ACTION");
}

// Init -> (selection) S1 | S2 -> Merge -> (simultaneous) P1 & P2 -> Init.
std::string demo_sfc() {
  return step(0, "Init", true, 200, action(1, "A_Init", {"lamp := FALSE;", "m := FALSE;"})) +
         step(2, "S1", false, 100, action(3, "A_S1", {"lamp := TRUE;"})) +
         step(4, "S2", false, 400, action(5, "A_S2", {"m := TRUE;", ""})) +
         step(6, "Merge", false) +
         step(7, "P1", false, 100, action(8, "A_P1", {"valve := TRUE;"})) +
         step(9, "P2", false, 400) +
         // the right leg's transition comes first in the file: the left one is still tried first
         transition(21, "Tran_001", "stop;", 400) + transition(20, "Tran_000", "start AND a", 100) +
         transition(22, "Tran_002", "NOT a", 100) +
         transition(23, "Tran_003", "S2.X AND NOT stop;", 400) +
         transition(24, "Tran_004", "TRUE") + transition(25, "Tran_005", "NOT start") +
         branch(30, "Selection", "Diverge", 31, 32) + branch(33, "Selection", "Converge", 34, 35) +
         branch(36, "Simultaneous", "Diverge", 37, 38) +
         branch(39, "Simultaneous", "Converge", 40, 41) +
         links({{0, 30},
                {31, 20},
                {32, 21},
                {20, 2},
                {21, 4},
                {2, 22},
                {4, 23},
                {22, 34},
                {23, 35},
                {33, 6},
                {6, 24},
                {24, 36},
                {37, 7},
                {38, 9},
                {7, 40},
                {9, 41},
                {39, 25},
                {25, 0}});
}

std::string demo_twin() {
  return R"(PROGRAM Press
  VAR_INPUT start, stop, a : BOOL; END_VAR
  VAR_OUTPUT lamp, valve : BOOL; END_VAR
  VAR m : BOOL := FALSE; END_VAR
  INITIAL_STEP Init: A_Init(N); END_STEP
  STEP S1: A_S1(N); END_STEP
  STEP S2: A_S2(N); END_STEP
  STEP Merge: END_STEP
  STEP P1: A_P1(N); END_STEP
  STEP P2: END_STEP
  TRANSITION Tran_000 FROM Init TO S1 := start AND a; END_TRANSITION
  TRANSITION Tran_001 FROM Init TO S2 := stop; END_TRANSITION
  TRANSITION Tran_002 FROM S1 TO Merge := NOT a; END_TRANSITION
  TRANSITION Tran_003 FROM S2 TO Merge := S2.X AND NOT stop; END_TRANSITION
  TRANSITION Tran_004 FROM Merge TO (P1, P2) := TRUE; END_TRANSITION
  TRANSITION Tran_005 FROM (P1, P2) TO Init := NOT start; END_TRANSITION
  ACTION A_Init: lamp := FALSE; m := FALSE; END_ACTION
  ACTION A_S1: lamp := TRUE; END_ACTION
  ACTION A_S2: m := TRUE; END_ACTION
  ACTION A_P1: valve := TRUE; END_ACTION
END_PROGRAM
)";
}

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

// Siemens TIA Portal SimaticML S7-GRAPH blocks (src/io/simatic_graph_reader.cpp) on small files
// written in the export's shape (tests/support/simatic_text.hpp; the layout of huaruiwh/portal
// MotorSequenceGRAPH_export.xml, never copied): steps, transitions, branches and jumps read from
// the Connections, LAD conditions (series, parallel, NC), S/R/N/L/D actions, and located
// refusals of what the model cannot say.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/expr.hpp"
#include "model/validate.hpp"
#include "round_trip.hpp"
#include "support/simatic_text.hpp"

namespace sfcv::test {
namespace {

using namespace simatic;

std::string errors_of(const io::LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Error)
      s += d.where.str() + " (" + d.where.element_path + "): " + d.message + "\n";
  return s;
}

io::LoadResult load(const std::string& text) {
  return io::load_simatic_graph(text, "Tank.xml");
}

const model::Transition* find(const model::Chart& c, const std::string& name) {
  for (const auto& t : c.transitions)
    if (t.name == name) return &t;
  return nullptr;
}

TEST(SimaticGraph, DetectedByItsRootAndReadAsAProgramWithOneChart) {
  const auto text = demo();
  EXPECT_EQ(io::detect_format("Tank.xml", text), io::Format::SimaticGraph);
  const auto r = load(text);
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& p = *r.project;
  EXPECT_EQ(p.source_format, "simaticml-graph V20 (GRAPH 6.0)");
  ASSERT_EQ(p.pous.size(), 1u);
  const auto& pou = p.pous[0];
  EXPECT_EQ(pou.name, "Tank");
  EXPECT_EQ(pou.kind, model::PouKind::Program);
  ASSERT_EQ(pou.charts.size(), 1u);
  const auto& c = pou.charts[0];
  ASSERT_EQ(c.steps.size(), 5u);
  EXPECT_TRUE(c.steps[0].initial);
  EXPECT_FALSE(c.steps[1].initial);
  EXPECT_EQ(c.transitions.size(), 5u);
  // The block's own member and the PLC tags it names are variables; the sequencer's system
  // parameters (OFF_SQ, INIT_SQ, S_NO) and structures (RT_DATA) are not.
  EXPECT_NE(pou.find_variable("full"), nullptr);
  EXPECT_NE(pou.find_variable("level_hi"), nullptr);
  EXPECT_EQ(pou.find_variable("INIT_SQ"), nullptr);
  EXPECT_EQ(pou.find_variable("RT_DATA"), nullptr);
  EXPECT_FALSE(model::has_errors(model::validate(p)));
}

TEST(SimaticGraph, DemoGivesTheModelOfItsIecTwinAndRoundTrips) {
  const auto native = load(demo());
  ASSERT_TRUE(native.ok()) << errors_of(native);
  const auto twin = io::load_iec_text(demo_twin(), "tank.st");
  ASSERT_TRUE(twin.ok()) << errors_of(twin);
  const auto diff = model::first_difference(*native.project, *twin.project);
  EXPECT_FALSE(diff.has_value()) << *diff;
  iec_round_trip(*native.project);
  plcopen_round_trip(*native.project);
}

TEST(SimaticGraph, BranchesAndJumpsGiveTheSourcesAndTargetsAsDrawn) {
  const auto r = load(demo());
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& c = r.project->pous[0].charts[0];
  using V = std::vector<std::string>;
  const auto* full = find(c, "T_Full");    // AltBegin leg 0, then a SimBegin
  const auto* stop = find(c, "T_Stop");    // AltBegin leg 1, a jump back
  const auto* mixed = find(c, "T_Mixed");  // after the SimEnd
  const auto* ack = find(c, "T_Ack");
  ASSERT_TRUE(full && stop && mixed && ack);
  EXPECT_EQ(full->sources, V{"Fill"});
  EXPECT_EQ(full->targets, (V{"Mix", "Heat"}));
  EXPECT_EQ(stop->sources, V{"Fill"});
  EXPECT_EQ(stop->targets, V{"Idle"});
  EXPECT_EQ(mixed->sources, (V{"Mix", "Heat"}));
  EXPECT_EQ(mixed->targets, V{"Done"});
  EXPECT_EQ(ack->targets, V{"Idle"});
  // The alternative branch's legs are tried left to right (Out 0 first).
  EXPECT_LT(full->order, stop->order);
}

TEST(SimaticGraph, LadConditionsSeriesParallelAndNormallyClosed) {
  const auto r = load(demo());
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& c = r.project->pous[0].charts[0];
  EXPECT_EQ(model::to_st(find(c, "T_Start")->guard), "start AND NOT stop");
  EXPECT_EQ(model::to_st(find(c, "T_Full")->guard), "full OR level_hi");
  EXPECT_EQ(model::to_st(find(c, "T_Mixed")->guard), "NOT busy");
  // A parallel branch of two series contacts.
  auto text = demo();
  const auto net = lad({{"#full"}, {"level_hi"}});
  text.replace(text.find(net), net.size(), lad({{"a", "!b"}, {"c"}, {"!d", "e"}}));
  const auto r2 = load(text);
  ASSERT_TRUE(r2.ok()) << errors_of(r2);
  EXPECT_EQ(model::to_st(find(r2.project->pous[0].charts[0], "T_Full")->guard),
            "a AND NOT b OR c OR NOT d AND e");
}

TEST(SimaticGraph, LadPowerFlowFanningOutOfAContactIntoParallelContacts) {
  // a AND NOT b, then three parallel contacts joined by an O box (the shape of a stop network
  // in the public LAD twin): one wire takes b's out to the three contacts' in.
  auto acc = [](int uid, const char* name) {
    return "<Access Scope=\"GlobalVariable\" UId=\"" + std::to_string(uid) +
           "\"><Symbol><Component Name=\"" + name + "\" /></Symbol></Access>";
  };
  auto con = [](int from, const char* pin, int to, const char* to_pin) {
    return "<Wire UId=\"" + std::to_string(100 + from * 10 + to) + "\"><NameCon UId=\"" +
           std::to_string(from) + "\" Name=\"" + pin + "\" /><NameCon UId=\"" + std::to_string(to) +
           "\" Name=\"" + to_pin + "\" /></Wire>";
  };
  auto op = [](int a, int p) {
    return "<Wire UId=\"" + std::to_string(200 + a) + "\"><IdentCon UId=\"" + std::to_string(a) +
           "\" /><NameCon UId=\"" + std::to_string(p) + "\" Name=\"operand\" /></Wire>";
  };
  const std::string net =
      "<FlgNet><Parts>" + acc(1, "a") + acc(2, "b") + acc(3, "c") + acc(4, "d") + acc(5, "e") +
      "<Part Name=\"Contact\" UId=\"11\" /><Part Name=\"Contact\" UId=\"12\"><Negated "
      "Name=\"operand\" /></Part><Part Name=\"Contact\" UId=\"13\" /><Part Name=\"Contact\" "
      "UId=\"14\" /><Part Name=\"Contact\" UId=\"15\" /><Part Name=\"O\" UId=\"16\"><TemplateValue "
      "Name=\"Card\" Type=\"Cardinality\">3</TemplateValue></Part><Part Name=\"TrCoil\" "
      "UId=\"17\" /></Parts><Wires><Wire UId=\"99\"><Powerrail /><NameCon UId=\"11\" "
      "Name=\"in\" /></Wire>" +
      op(1, 11) + op(2, 12) + op(3, 13) + op(4, 14) + op(5, 15) + con(11, "out", 12, "in") +
      "<Wire UId=\"98\"><NameCon UId=\"12\" Name=\"out\" /><NameCon UId=\"13\" Name=\"in\" "
      "/><NameCon UId=\"14\" Name=\"in\" /><NameCon UId=\"15\" Name=\"in\" /></Wire>" +
      con(13, "out", 16, "in1") + con(14, "out", 16, "in2") + con(15, "out", 16, "in3") +
      con(16, "out", 17, "in") + "</Wires></FlgNet>\n";
  auto text = demo();
  const auto old_net = lad({{"ack"}});
  text.replace(text.find(old_net), old_net.size(), net);
  const auto r = load(text);
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(find(r.project->pous[0].charts[0], "T_Ack")->guard),
            "a AND NOT b AND c OR a AND NOT b AND d OR a AND NOT b AND e");
}

TEST(SimaticGraph, ActionRowsBecomeAssociationsWithTheirQualifiers) {
  const auto r = load(demo());
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  auto qualifier_of = [&](const std::string& step, const std::string& action) {
    for (const auto& a : pou.associations)
      if (a.step == step && a.action == action) return std::string(model::to_string(a.qualifier));
    return std::string("none");
  };
  EXPECT_EQ(qualifier_of("Idle", "motor"), "R");
  EXPECT_EQ(qualifier_of("Fill", "motor"), "S");
  EXPECT_EQ(qualifier_of("Fill", "valve"), "N");
  EXPECT_EQ(qualifier_of("Heat", "heater"), "L");
  for (const auto& a : pou.associations)
    if (a.action == "lamp") {
      EXPECT_EQ(a.qualifier, model::Qualifier::D);
      EXPECT_EQ(a.duration_ms, 2000);
    }
  const auto* motor = pou.find_action("motor");
  ASSERT_NE(motor, nullptr);
  EXPECT_EQ(motor->kind, model::ActionBodyKind::Variable);
  EXPECT_EQ(pou.find_variable("motor")->type.kind, model::TypeKind::Bool);
}

TEST(SimaticGraph, ProvablyEmptySupervisionAndInterlockAreRead) {
  // The public export's "Stop AND NOT Stop" supervision can never hold; the interlock wired to
  // the rail is always satisfied.
  auto text = demo();
  const std::string empty_sv =
      "<FlgNet><Parts><Part Name=\"SvCoil\" UId=\"21\" /></Parts><Wires /></FlgNet>\n";
  text.replace(text.find(empty_sv), empty_sv.size(), lad({{"x", "!x"}}, "SvCoil"));
  const auto r = load(text);
  EXPECT_TRUE(r.ok()) << errors_of(r);
}

TEST(SimaticGraph, ASupervisionIsALocatedError) {
  auto text = demo();
  const std::string empty_sv =
      "<FlgNet><Parts><Part Name=\"SvCoil\" UId=\"21\" /></Parts><Wires /></FlgNet>\n";
  text.replace(text.find(empty_sv), empty_sv.size(), lad({{"trip"}}, "SvCoil"));
  const auto r = load(text);
  EXPECT_FALSE(r.ok());
  const auto e = errors_of(r);
  EXPECT_NE(e.find("unsupported: the supervision of step 'Idle' (trip)"), std::string::npos) << e;
  EXPECT_NE(e.find("Step[@name='Idle']/Supervisions/Supervision"), std::string::npos) << e;
}

TEST(SimaticGraph, AnInterlockThatCanFailIsALocatedError) {
  auto text = demo();
  const auto empty_il = lad({}, "IlCoil");
  text.replace(text.find(empty_il), empty_il.size(), lad({{"!guard_open"}}, "IlCoil"));
  const auto r = load(text);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("unsupported: the interlock of step 'Idle' (NOT guard_open)"),
            std::string::npos)
      << errors_of(r);
}

TEST(SimaticGraph, AnUnknownLadPartIsALocatedError) {
  auto text = demo();
  const std::string contact = "<Part Name=\"Contact\" UId=\"22\" />";
  const auto at = text.find(contact, text.find("T_Start"));
  ASSERT_NE(at, std::string::npos);
  text.replace(at, contact.size(), "<Part Name=\"PContact\" UId=\"22\" />");
  const auto r = load(text);
  EXPECT_FALSE(r.ok());
  const auto e = errors_of(r);
  EXPECT_NE(e.find("unsupported: LAD part 'PContact' (UId 22) in the LAD network of transition "
                   "'T_Start'"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("Transition[@name='T_Start']/FlgNet/Parts/Part"), std::string::npos) << e;
}

TEST(SimaticGraph, WhatTheModelCannotSayIsRefusedByName) {
  struct Case {
    std::string from, to, message;
  };
  const std::string sr = action("S", q("motor"));
  const Case cases[] = {
      // An interlocked qualifier, an event action, a data block's time.
      {sr, action("SC", q("motor")), "qualifier 'SC'"},
      {sr, "<Action Qualifier=\"S\" Event=\"S1\"><Token Text=\"&quot;motor&quot;\" /></Action>",
       "with Event='S1'"},
      {action("D", q("lamp") + ", T#2s"), action("D", q("lamp") + ", &quot;Settings&quot;.Delay"),
       "sfcv needs a constant duration"},
      // S after R of one operand in one step: S7-GRAPH's last write wins.
      {action("R", q("motor")), action("R", q("motor")) + action("S", q("motor")),
       "'motor' is reset, then set in step 'Idle'"},
      // N and S on one operand: S7-GRAPH resets the N operand when its step is left.
      {action("N", q("valve")), action("N", q("motor")), "the operand of N/D/L and of S/R"},
      // Steps of two simultaneous legs on one operand.
      {action("N", q("mixer")), action("N", q("heater")), "steps that may be active together"},
      {"<PostOperations />",
       "<PostOperations><PermanentOperation ProgrammingLanguage=\"LAD\">" +
           rung({{"a"}}, std::nullopt, {{"Coil", "b"}}) + "</PermanentOperation></PostOperations>",
       "permanent instruction after the sequencer"},
      {"MaximumStepTime=\"T#0ms\"", "MaximumStepTime=\"T#10S\"", "MaximumStepTime of T#10S"},
      {"\"GlobalVariable\" UId=\"21\"><Symbol><Component Name=\"ack\" />",
       "\"LocalVariable\" UId=\"21\"><Symbol><Component Name=\"INIT_SQ\" />",
       "parameter of S7-GRAPH's sequencer control"},
      {"<LinkType>Jump</LinkType>", "<LinkType>Stop</LinkType>", "link type 'Stop'"},
      {"NetworkSource/Graph/v5", "NetworkSource/Graph/v9", "Graph namespace"},
      {"<GraphVersion>", "<SkipSteps>true</SkipSteps><GraphVersion>", "with SkipSteps"},
  };
  for (const auto& c : cases) {
    auto text = demo();
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    const auto r = load(text);
    EXPECT_FALSE(r.ok()) << c.to;
    const auto e = errors_of(r);
    EXPECT_NE(e.find(c.message), std::string::npos) << c.message << "\n" << e;
    EXPECT_NE(e.find("Tank.xml:"), std::string::npos) << e;
  }
}

TEST(SimaticGraph, ATransitionEndingInABranchStopIsRefused) {
  auto text = demo();
  const std::string jump = connections({}, {{"T5", "S1"}});
  text.replace(text.find(jump), jump.size(), "");
  const auto r = load(text);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("transition 'T_Ack' ends in a branch stop"), std::string::npos)
      << errors_of(r);
}

TEST(SimaticGraph, OtherBlocksOfTheFileAreRefusedByName) {
  const auto scl_block = io::load_simatic_graph(
      "<?xml version=\"1.0\"?><Document><Engineering version=\"V17\"/><SW.Blocks.FB ID=\"0\">"
      "<AttributeList><Name>Motor</Name><ProgrammingLanguage>SCL</ProgrammingLanguage>"
      "</AttributeList></SW.Blocks.FB></Document>",
      "Motor.xml");
  EXPECT_FALSE(scl_block.ok());
  EXPECT_NE(errors_of(scl_block).find("<SW.Blocks.FB> 'Motor' in SCL is not read (S7-GRAPH "
                                      "function blocks and LAD blocks are)"),
            std::string::npos)
      << errors_of(scl_block);
}

// A permanent instruction before the sequencer runs in every cycle before the chart: the POU's
// body (docs/semantics.md 1.13a).
TEST(SimaticGraph, PermanentInstructionsBeforeTheSequencerAreItsBody) {
  const auto r = load(demo("<PermanentOperation ProgrammingLanguage=\"LAD\">" +
                           rung({{"start", "!stop"}}, std::nullopt, {{"Coil", "armed"}}) +
                           "</PermanentOperation>"));
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(r.project->pous[0].body), "armed := start AND NOT stop;\n");
  EXPECT_EQ(r.project->pous[0].charts.size(), 1u);
}

io::LoadResult load_lad(const std::string& text) {
  return io::load_simatic_graph(text, "Starter.xml");
}

TEST(SimaticLad, DemoGivesTheModelOfItsIecTwinAndRoundTrips) {
  const auto text = lad_demo();
  EXPECT_EQ(io::detect_format("Starter.xml", text), io::Format::SimaticGraph);
  const auto native = load_lad(text);
  ASSERT_TRUE(native.ok()) << errors_of(native);
  EXPECT_EQ(native.project->source_format, "simaticml-lad V20");
  const auto twin = io::load_iec_text(lad_demo_twin(), "starter.st");
  ASSERT_TRUE(twin.ok()) << errors_of(twin);
  const auto diff = model::first_difference(*native.project, *twin.project);
  EXPECT_FALSE(diff.has_value()) << *diff << "\n" << model::to_st(native.project->pous[0].body);
  iec_round_trip(*native.project);
  plcopen_round_trip(*native.project);
}

// TIA Portal's coils: "=" writes the power flow, "S" and "R" write TRUE and FALSE when it flows,
// a negated coil writes its negation; one wire may feed several coils.
TEST(SimaticLad, CoilsOfOnePowerFlow) {
  const auto r =
      load_lad(lad_block("M", "",
                         {rung({{"a", "!b"}, {"c"}}, std::nullopt,
                               {{"Coil", "x"}, {"!Coil", "y"}, {"SCoil", "s"}, {"RCoil", "r"}}),
                          rung({{"x"}, {"hold"}}, std::nullopt, {{"Coil", "hold"}})},
                         "SW.Blocks.OB"));
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(model::to_st(r.project->pous[0].body),
            "x := a AND NOT b OR c;\n"
            "y := NOT (a AND NOT b OR c);\n"
            "IF a AND NOT b OR c THEN\n  s := TRUE;\nEND_IF;\n"
            "IF a AND NOT b OR c THEN\n  r := FALSE;\nEND_IF;\n"
            "hold := x OR hold;\n");
}

TEST(SimaticLad, WhatTheModelCannotSayIsRefusedByName) {
  struct Case {
    std::string statics, network, message;
  };
  const Case cases[] = {
      // The second coil would read the first one's write: TIA evaluates the flow once.
      {"", rung({{"a", "x"}}, std::nullopt, {{"Coil", "x"}, {"Coil", "y"}}),
       "reads 'x' after one of its coils wrote it"},
      {"", rung({{"a"}}, TimerBox{"TON", "T1", "T#1s"}, {{"Coil", "y"}}),
       "the TON box's instance 'T1' is not a static TON member"},
      {timer_member("T1", "TOF_TIME"),
       rung({{"a"}}, TimerBox{"TON", "T1", "T#1s"}, {{"Coil", "y"}}), "is not a static TON member"},
      {"", rung({{"a"}}, std::nullopt, {{"Coil", "T#1s"}}), "on an operand that is not a variable"},
      {timer_member("T1", "IEC_TIMER"), "", "member 'T1' of type IEC_TIMER"},
  };
  for (const auto& c : cases) {
    const auto r = load_lad(
        lad_block("M", c.statics,
                  {c.network.empty() ? rung({{"a"}}, std::nullopt, {{"Coil", "y"}}) : c.network}));
    EXPECT_FALSE(r.ok()) << c.message;
    const auto e = errors_of(r);
    EXPECT_NE(e.find(c.message), std::string::npos) << c.message << "\n" << e;
    EXPECT_NE(e.find("Starter.xml:"), std::string::npos) << e;
  }
  // A part that is not read, and a DB member (its data block is not in the file).
  auto text = lad_demo();
  const std::string contact = "<Part Name=\"Contact\" UId=\"22\" />";
  text.replace(text.find(contact), contact.size(), "<Part Name=\"PContact\" UId=\"22\" />");
  EXPECT_NE(errors_of(load_lad(text)).find("LAD part 'PContact' (UId 22)"), std::string::npos);
  text = lad_demo();
  const std::string literal = "Scope=\"LiteralConstant\"";
  text.replace(text.find(literal), literal.size(), "Scope=\"GlobalVariable\"");
  const std::string pt =
      "<Constant><ConstantType>Time</ConstantType><ConstantValue>T#5s</ConstantValue></Constant>";
  text.replace(text.find(pt), pt.size(),
               "<Symbol><Component Name=\"Settings\" /><Component Name=\"Delay\" /></Symbol>");
  EXPECT_NE(errors_of(load_lad(text))
                .find("a member of a global data block, which is not in the "
                      "file"),
            std::string::npos)
      << errors_of(load_lad(text));
}

// The public LAD twin of the GRAPH sample, huaruiwh/portal MotorSequenceLAD_export.xml, when
// SFCV_VENDOR_SAMPLES names a folder holding it: every network is read but the TON presets,
// which are members of a data block the file does not hold.
TEST(SimaticLad, PublicSampleWhenPresent) {
  const char* dir = std::getenv("SFCV_VENDOR_SAMPLES");
  const auto path = std::filesystem::path(dir ? dir : "") / "MotorSequenceLAD_export.xml";
  if (!dir || !std::filesystem::exists(path))
    GTEST_SKIP() << "SFCV_VENDOR_SAMPLES does not hold MotorSequenceLAD_export.xml";
  const auto r = io::load_file(path.string());
  int errors = 0;
  for (const auto& d : r.diagnostics) {
    if (d.severity != model::Severity::Error) continue;
    ++errors;
    EXPECT_NE(d.message.find("\"MotorSequence_Settings\"."), std::string::npos) << d.message;
  }
  EXPECT_EQ(errors, 4);
}

// The public export huaruiwh/portal MotorSequenceGRAPH_export.xml, when SFCV_VENDOR_SAMPLES
// names a folder holding it: loads, or is refused for the constructs it uses.
TEST(SimaticGraph, PublicSampleWhenPresent) {
  const char* dir = std::getenv("SFCV_VENDOR_SAMPLES");
  const auto path = std::filesystem::path(dir ? dir : "") / "MotorSequenceGRAPH_export.xml";
  if (!dir || !std::filesystem::exists(path))
    GTEST_SKIP() << "SFCV_VENDOR_SAMPLES does not hold MotorSequenceGRAPH_export.xml";
  const auto r = io::load_file(path.string());
  const auto e = errors_of(r);
  // Its permanent instructions (an edge of Start_Command before the sequencer, the motor
  // outputs after it) and its data block's D times are refused by name.
  EXPECT_NE(e.find("permanent instruction before the sequencer"), std::string::npos) << e;
  EXPECT_EQ(e.find("supervision of step"), std::string::npos) << e;  // provably empty ones
}

}  // namespace
}  // namespace sfcv::test

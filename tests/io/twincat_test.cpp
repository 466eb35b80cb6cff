// TwinCAT 3 native files (docs/formats.md): a .TcPOU SFC chart read through its XmlArchive gives
// the model its PLCopen TC6 export gives; the archive's attribute table, not fixed GUIDs, names
// the attributes; what is not modelled is refused at its place. Files are written here in the
// vendor's shape (tests/support/twincat_text.hpp), never copied from public projects.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/expr.hpp"
#include "round_trip.hpp"
#include "support/twincat_text.hpp"

namespace sfcv::test {
namespace {

using namespace tc;

std::string errors_of(const io::LoadResult& r) {
  return diagnostics_text(r.diagnostics);
}

const model::Transition* find_transition(const model::Chart& c,
                                         const std::vector<std::string>& sources) {
  for (const auto& t : c.transitions)
    if (t.sources == sources) return &t;
  return nullptr;
}

TEST(TwinCat, DemoChartGivesTheModelOfItsPlcopenTwin) {
  const auto native = io::load_twincat(demo_tcpou(vendor_guids()), "FB_Demo.TcPOU");
  ASSERT_TRUE(native.ok()) << errors_of(native);
  const auto twin = io::load_plcopen_xml(demo_plcopen(), "demo.xml");
  ASSERT_TRUE(twin.ok()) << errors_of(twin);
  const auto diff = model::first_difference(*native.project, *twin.project);
  EXPECT_FALSE(diff.has_value()) << *diff;

  // And that model is the chart as drawn, not merely the same mistake twice.
  const auto& p = *native.project;
  EXPECT_EQ(p.source_format, "twincat 3.1.4024.12");  // TcPlcObject's ProductVersion
  ASSERT_EQ(p.pous.size(), 1u);
  const auto& pou = p.pous[0];
  EXPECT_EQ(pou.kind, model::PouKind::FunctionBlock);
  ASSERT_EQ(pou.charts.size(), 1u);
  const auto& c = pou.charts[0];
  ASSERT_EQ(c.steps.size(), 7u);
  EXPECT_EQ(c.steps[0].name, "Init");
  EXPECT_TRUE(c.steps[0].initial);
  for (std::size_t i = 1; i < c.steps.size(); ++i) EXPECT_FALSE(c.steps[i].initial);
  ASSERT_EQ(c.transitions.size(), 7u);
  // The alternative legs leave Init in document order (left leg first) and meet at Merge.
  EXPECT_EQ(c.transitions[0].sources, std::vector<std::string>{"Init"});
  EXPECT_EQ(c.transitions[0].targets, std::vector<std::string>{"S1"});
  EXPECT_EQ(model::to_st(c.transitions[0].guard), "start AND a");
  EXPECT_EQ(c.transitions[1].targets, std::vector<std::string>{"Merge"});
  const auto* done = find_transition(c, {"S2"});
  ASSERT_NE(done, nullptr);
  EXPECT_EQ(done->name, "TrDone");  // the named transition object gives its ST condition
  EXPECT_EQ(model::to_st(done->guard), "NOT stop AND a");
  EXPECT_EQ(done->targets, std::vector<std::string>{"Merge"});
  // The parallel branch: one transition into both legs, one out of both last steps.
  const auto* fork = find_transition(c, {"Merge"});
  ASSERT_NE(fork, nullptr);
  EXPECT_EQ(fork->targets, (std::vector<std::string>{"P1", "P2"}));
  const auto* join = find_transition(c, {"P1b", "P2"});
  ASSERT_NE(join, nullptr);
  EXPECT_EQ(join->targets, std::vector<std::string>{"Init"});  // the jump
  // Step actions: entry P1, main N, exit P0.
  ASSERT_EQ(pou.associations.size(), 5u);
  auto qualifier_of = [&](const std::string& step, const std::string& action) {
    for (const auto& a : pou.associations)
      if (a.step == step && a.action == action) return std::string(model::to_string(a.qualifier));
    return std::string("none");
  };
  EXPECT_EQ(qualifier_of("S1", "A_S1"), "N");
  EXPECT_EQ(qualifier_of("S1", "A_E"), "P1");
  EXPECT_EQ(qualifier_of("S2", "A_X"), "P0");
  EXPECT_EQ(qualifier_of("P1", "A_P1"), "N");
  ASSERT_NE(pou.find_action("A_Init"), nullptr);
  EXPECT_EQ(pou.find_action("A_Init")->body.size(), 2u);
}

TEST(TwinCat, AttributesAreReadThroughTheArchivesOwnTable) {
  const auto vendor = io::load_twincat(demo_tcpou(vendor_guids()), "a.TcPOU");
  const auto invented = io::load_twincat(demo_tcpou(invented_guids()), "b.TcPOU");
  ASSERT_TRUE(vendor.ok() && invented.ok()) << errors_of(vendor) << errors_of(invented);
  const auto diff = model::first_difference(*vendor.project, *invented.project);
  EXPECT_FALSE(diff.has_value()) << *diff;
}

TEST(TwinCat, AnAttributeTheTableDoesNotDescribeIsRefused) {
  auto text = demo_tcpou(vendor_guids());
  // Drop the table's entry for InitStep: the records using that GUID cannot be read.
  const std::string guid = vendor_guids().at("InitStep");
  const auto at = text.find("<v>" + guid + "</v>");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, text.find("</o>", at) + 4 - at);
  const auto r = io::load_twincat(text, "FB_Demo.TcPOU");
  EXPECT_FALSE(r.ok());
  const auto e = errors_of(r);
  EXPECT_NE(e.find("{" + guid + "} is not in the archive's attribute table"), std::string::npos)
      << e;
  EXPECT_NE(e.find("SFCStep (archive object"), std::string::npos) << e;
  EXPECT_NE(e.find("/TcPlcObject/POU[@name='FB_Demo']/Implementation/SFC"), std::string::npos) << e;
}

TEST(TwinCat, AMainSequenceEndingWithATransitionGoesBackToItsTop) {
  Archive ar(vendor_guids());
  const std::string e =
      ar.step("Idle", true) + ar.transition("go") + ar.step("Run") + ar.transition("NOT go");
  const auto r =
      io::load_twincat(tcpou("P", "PROGRAM P\nVAR\n go : BOOL;\nEND_VAR", ar.sfc(e)), "P.TcPOU");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& c = r.project->pous[0].charts[0];
  ASSERT_EQ(c.transitions.size(), 2u);
  EXPECT_EQ(c.transitions[1].sources, std::vector<std::string>{"Run"});
  EXPECT_EQ(c.transitions[1].targets, std::vector<std::string>{"Idle"});
  EXPECT_EQ(r.project->pous[0].kind, model::PouKind::Program);
}

// Each construct the model cannot express is an error naming it, with the file and place.
std::string refused(const std::string& text) {
  const auto r = io::load_twincat(text, "F.TcPOU");
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.project.has_value());
  return errors_of(r);
}

TEST(TwinCat, StepTimeMonitoringIsRefused) {
  Archive ar(vendor_guids());
  const std::string e =
      ar.step("S0", true, "", "", "", ar.attr("MaxTime", "T#5S")) + ar.transition("TRUE");
  const auto err = refused(tcpou("P", "PROGRAM P", ar.sfc(e)));
  EXPECT_NE(err.find("F.TcPOU"), std::string::npos) << err;
  EXPECT_NE(err.find("unsupported: MaxTime on step 'S0' (step time monitoring)"), std::string::npos)
      << err;
}

TEST(TwinCat, EmbeddedImplementationsAndStepAssociationsAreRefused) {
  Archive ar(vendor_guids());
  std::string e =
      ar.step("S0", true) + ar.transition("TRUE", "<o n=\"EmbeddedTransition\" t=\"X\"></o>");
  auto err = refused(tcpou("P", "PROGRAM P", ar.sfc(e)));
  EXPECT_NE(err.find("unsupported: EmbeddedTransition of SFCTransition"), std::string::npos) << err;
  Archive ar2(vendor_guids());
  e = ar2.step("S0", true, "", "", "", "", "<o t=\"SFCActionAssociation\"></o>") +
      ar2.transition("TRUE");
  err = refused(tcpou("P", "PROGRAM P", ar2.sfc(e)));
  EXPECT_NE(err.find("unsupported: action associations inside step 'S0'"), std::string::npos)
      << err;
}

TEST(TwinCat, MisplacedBranchesAndUnknownElementsAreRefused) {
  Archive ar(vendor_guids());
  // A parallel branch must follow a transition.
  std::string e = ar.step("S0", true) +
                  ar.branch(true, {ar.step("A") + ar.transition("x"), ar.step("B")}) +
                  ar.transition("TRUE");
  auto err = refused(tcpou("P", "PROGRAM P\nVAR x : BOOL; END_VAR", ar.sfc(e)));
  EXPECT_NE(err.find("parallel SFCBranch (archive object"), std::string::npos) << err;
  EXPECT_NE(err.find("does not follow a transition"), std::string::npos) << err;
  Archive ar2(vendor_guids());
  e = ar2.step("S0", true) + "<o t=\"SFCMacroStep\"><v n=\"Id\">99L</v></o>";
  err = refused(tcpou("P", "PROGRAM P", ar2.sfc(e)));
  EXPECT_NE(err.find("unsupported: SFC element SFCMacroStep (archive object 99)"),
            std::string::npos)
      << err;
}

TEST(TwinCat, BranchesNestedPastTheLimitAreAnErrorNotACrash) {
  Archive ar(vendor_guids());
  // Alternative branches each holding the next in a leg, 205 deep (the limit is 200).
  std::string inner = ar.transition("TRUE");
  for (int i = 0; i < 205; ++i)
    inner = ar.transition("TRUE") + ar.step("S" + std::to_string(i)) +
            ar.branch(false, {inner, ar.transition("TRUE")});
  const std::string e = ar.step("Top", true) + ar.branch(false, {inner, ar.transition("TRUE")}) +
                        ar.step("End") + ar.transition("TRUE");
  const auto err = refused(tcpou("P", "PROGRAM P", ar.sfc(e)));
  EXPECT_NE(err.find("branches nested deeper than 200"), std::string::npos) << err.substr(0, 500);
}

TEST(TwinCat, ObjectOrientedPousAreRefusedAtTheirPlace) {
  // EXTENDS: located by line and column inside the declaration's CDATA (line 4 of the file).
  auto err =
      refused(tcpou("FB_A", "// c\nFUNCTION_BLOCK INTERNAL FB_A EXTENDS FB_Base\n", "<ST/>"));
  EXPECT_NE(err.find("F.TcPOU:5:30"), std::string::npos) << err;
  EXPECT_NE(err.find("unsupported: EXTENDS"), std::string::npos) << err;
  err = refused(tcpou("FB_A", "FUNCTION_BLOCK FB_A", "<ST><![CDATA[]]></ST>",
                      "<Method Name=\"M_Go\" Id=\"{1}\"><Declaration/></Method>"));
  EXPECT_NE(err.find("unsupported: METHOD 'M_Go' of POU 'FB_A'"), std::string::npos) << err;
  EXPECT_NE(err.find("/TcPlcObject/POU[@name='FB_A']/Method[@name='M_Go']"), std::string::npos)
      << err;
  err = refused(tcpou("FB_A", "FUNCTION_BLOCK FB_B", "<ST/>"));
  EXPECT_NE(err.find("the declaration names 'FB_B', the file's POU is 'FB_A'"), std::string::npos)
      << err;
}

TEST(TwinCat, StBodiesLoadAndUnreadableBodiesAreMarkedNotModelled) {
  const auto r = io::load_twincat(
      tcpou("MAIN", "PROGRAM MAIN\nVAR\n x, y : BOOL;\nEND_VAR", "<ST><![CDATA[y := NOT x;]]></ST>",
            "<Action Name=\"A_Ld\" Id=\"{2}\"><Implementation><NWL><XmlArchive/></NWL>"
            "</Implementation></Action>"),
      "MAIN.TcPOU");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& pou = r.project->pous[0];
  EXPECT_EQ(pou.body.size(), 1u);
  const auto* ld = pou.find_action("A_Ld");
  ASSERT_NE(ld, nullptr);
  EXPECT_TRUE(ld->body_unsupported);  // refused when something runs it, never a no-op
  // A POU body in LD is recorded as not modelled.
  const auto nwl = io::load_twincat(
      tcpou("LD", "PROGRAM LD\nVAR x : BOOL; END_VAR", "<NWL><XmlArchive/></NWL>"), "LD.TcPOU");
  ASSERT_TRUE(nwl.ok()) << errors_of(nwl);
  EXPECT_TRUE(nwl.project->pous[0].body_unsupported);
  EXPECT_NE(nwl.project->pous[0].unsupported_reason.find("<NWL>"), std::string::npos);
}

class TwinCatFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("sfcv_twincat_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "POUs");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& rel, const std::string& text) {
    const auto p = dir_ / rel;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::filesystem::path dir_;
};

TEST_F(TwinCatFiles, APlcprojOrAFolderLoadsEveryPouListAndType) {
  write("POUs/MAIN.TcPOU", tcpou("MAIN", "PROGRAM MAIN\nVAR\n  s : ST_Pair;\nEND_VAR",
                                 "<ST><![CDATA[s.a := GVL_IO.bIn;\nGVL_IO.bOut := s.a;]]></ST>"));
  write("GVL_IO.TcGVL",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">"
        "<GVL Name=\"GVL_IO\" Id=\"{3}\"><Declaration><![CDATA[{attribute 'qualified_only'}\n"
        "VAR_GLOBAL\n  bIn AT %I* : BOOL;\n  bOut : BOOL;\nEND_VAR]]></Declaration></GVL>"
        "</TcPlcObject>\n");
  write("ST_Pair.TcDUT",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">"
        "<DUT Name=\"ST_Pair\" Id=\"{4}\"><Declaration><![CDATA[TYPE ST_Pair :\nSTRUCT\n"
        "  a, b : BOOL;\nEND_STRUCT\nEND_TYPE]]></Declaration></DUT></TcPlcObject>\n");
  write("PlcTask.TcTTO", "<TcPlcObject/>");
  const auto proj =
      write("Demo.plcproj",
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Project DefaultTargets=\"Build\" "
            "xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\"><ItemGroup>"
            "<Compile Include=\"POUs\\MAIN.TcPOU\"><SubType>Code</SubType></Compile>"
            "<Compile Include=\"GVL_IO.TcGVL\"><SubType>Code</SubType></Compile>"
            "<Compile Include=\"ST_Pair.TcDUT\"><SubType>Code</SubType></Compile>"
            "<Compile Include=\"PlcTask.TcTTO\"><SubType>Code</SubType></Compile>"
            "</ItemGroup></Project>\n");
  // A folder is read as a project when the format says so (auto keeps refusing folders).
  for (const auto& path : {proj, dir_.string()}) {
    const auto r = io::load_file(path, path == proj ? io::Format::Auto : io::Format::TwinCat);
    ASSERT_TRUE(r.ok()) << path << "\n" << errors_of(r);
    const auto& p = *r.project;
    EXPECT_EQ(p.source_format, "twincat 3.1.4024.12");  // MAIN.TcPOU's ProductVersion
    ASSERT_NE(p.find_pou("MAIN"), nullptr) << path;
    ASSERT_NE(p.find_pou("GVL_IO"), nullptr) << path;
    EXPECT_EQ(p.find_pou("GVL_IO")->variables.size(), 2u);
    EXPECT_EQ(p.find_pou("MAIN")->body.size(), 2u);
  }
  EXPECT_FALSE(io::load_file(dir_.string()).ok());
  // A compiled file that is missing is an error naming it.
  std::filesystem::remove(dir_ / "GVL_IO.TcGVL");
  const auto r = io::load_file(proj);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("GVL_IO.TcGVL"), std::string::npos) << errors_of(r);
}

TEST_F(TwinCatFiles, VendorFilesGoToTheirReaders) {
  const std::pair<const char*, const char*> cases[] = {
      {"Seq.xml",
       "<?xml version=\"1.0\"?><Document><Engineering version=\"V17\"/><SW.Blocks.FB ID=\"0\"/>"
       "</Document>"}};
  const char* names[] = {"Siemens TIA Portal SimaticML"};
  for (std::size_t i = 0; i < 1; ++i) {
    const auto r = io::load_file(write(cases[i].first, cases[i].second));
    EXPECT_FALSE(r.ok());
    EXPECT_NE(errors_of(r).find(std::string("unsupported: ") + names[i]), std::string::npos)
        << errors_of(r);
  }
  // An L5X is read now (tests/io/l5x_test.cpp): an empty one fails in its reader.
  const auto l5x = io::load_file(
      write("Main.L5X", "<?xml version=\"1.0\"?><RSLogix5000Content SchemaRevision=\"1.0\"/>"));
  EXPECT_FALSE(l5x.ok());
  EXPECT_NE(errors_of(l5x).find("no <Controller>"), std::string::npos) << errors_of(l5x);
  // So is a CODESYS export (tests/io/codesys_export_test.cpp): an empty one fails in its reader.
  const auto cx = io::load_file(
      write("Project.export",
            "<?xml version=\"1.0\"?><ExportFile><StructuredView Guid=\"{1}\"/></ExportFile>"));
  EXPECT_FALSE(cx.ok());
  EXPECT_NE(errors_of(cx).find("CODESYS export without objects"), std::string::npos)
      << errors_of(cx);
}

}  // namespace
}  // namespace sfcv::test

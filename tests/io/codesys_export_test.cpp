// CODESYS native exports (docs/formats.md): a `.export` POU with an SFC body (the archive TwinCAT
// also writes, in CODESYS's verbose XML spelling), its ST action and transition objects, a GVL
// and a DUT read into the model; the archive's table names the attributes; what is not modelled
// is refused at its place. Files are written here in the vendor's shape
// (tests/support/codesys_export_text.hpp), never copied from public projects.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/load.hpp"
#include "model/compare.hpp"
#include "model/expr.hpp"
#include "round_trip.hpp"
#include "support/codesys_export_text.hpp"

namespace sfcv::test {
namespace {

using namespace cx;

std::string errors_of(const io::LoadResult& r) {
  return diagnostics_text(r.diagnostics);
}

const model::Transition* find_transition(const model::Chart& c,
                                         const std::vector<std::string>& sources) {
  for (const auto& t : c.transitions)
    if (t.sources == sources) return &t;
  return nullptr;
}

std::string qualifier_of(const model::Pou& pou, const std::string& step,
                         const std::string& action) {
  for (const auto& a : pou.associations)
    if (a.step == step && a.action == action) return std::string(model::to_string(a.qualifier));
  return "none";
}

TEST(CodesysExport, DemoChartReadsAsDrawn) {
  const auto r = io::load_codesys_export(demo_export(), "Demo.export");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto& p = *r.project;
  EXPECT_EQ(p.source_format, "codesys-export");
  EXPECT_EQ(p.name, "PLC_SEQ");
  const auto* pou = p.find_pou("PLC_SEQ");
  ASSERT_NE(pou, nullptr);
  EXPECT_EQ(pou->kind, model::PouKind::Program);
  ASSERT_EQ(pou->charts.size(), 1u);
  const auto& c = pou->charts[0];
  ASSERT_EQ(c.steps.size(), 7u);
  EXPECT_EQ(c.steps[0].name, "Init");
  EXPECT_TRUE(c.steps[0].initial);
  ASSERT_EQ(c.transitions.size(), 7u);
  // Alternative branch: left leg tried first, both meet at Merge.
  EXPECT_EQ(c.transitions[0].sources, std::vector<std::string>{"Init"});
  EXPECT_EQ(c.transitions[0].targets, std::vector<std::string>{"S1"});
  EXPECT_EQ(model::to_st(c.transitions[0].guard), "start AND a");
  const auto* done = find_transition(c, {"S2"});
  ASSERT_NE(done, nullptr);
  EXPECT_EQ(done->name, "TrDone");  // the transition child object gives its ST condition
  EXPECT_EQ(model::to_st(done->guard), "NOT stop AND a");
  EXPECT_EQ(done->targets, std::vector<std::string>{"Merge"});
  // Simultaneous branch: one transition into both legs, one out of both last steps, and the
  // jump back to Init.
  const auto* fork = find_transition(c, {"Merge"});
  ASSERT_NE(fork, nullptr);
  EXPECT_EQ(fork->targets, (std::vector<std::string>{"P1", "P2"}));
  const auto* join = find_transition(c, {"P1b", "P2"});
  ASSERT_NE(join, nullptr);
  EXPECT_EQ(join->targets, std::vector<std::string>{"Init"});
  // Step actions (entry P1, main N, exit P0) and the IEC associations inside the steps, whose
  // Boolean variable `busy` becomes an action.
  EXPECT_EQ(qualifier_of(*pou, "S1", "A_S1"), "N");
  EXPECT_EQ(qualifier_of(*pou, "S1", "A_E"), "P1");
  EXPECT_EQ(qualifier_of(*pou, "S2", "A_X"), "P0");
  EXPECT_EQ(qualifier_of(*pou, "Init", "busy"), "R");
  EXPECT_EQ(qualifier_of(*pou, "S1", "busy"), "S");
  EXPECT_EQ(qualifier_of(*pou, "P1", "A_P1"), "N");
  ASSERT_NE(pou->find_action("busy"), nullptr);
  EXPECT_EQ(pou->find_action("busy")->kind, model::ActionBodyKind::Variable);
  ASSERT_NE(pou->find_action("A_Init"), nullptr);
  EXPECT_EQ(pou->find_action("A_Init")->body.size(), 2u);
  // CODESYS's dialect (docs/semantics.md 1.4a): the step actions (entry, main, exit) are told
  // apart from the IEC actions, which get a final call.
  EXPECT_EQ(model::vendor_of(p), "codesys");
  for (const auto& as : pou->associations)
    EXPECT_EQ(as.step_action, as.action == "A_S1" || as.action == "A_E" || as.action == "A_X" ||
                                  as.action == "A_Init")
        << as.action;
  // The global list and the data type came along.
  const auto* gvl = p.find_pou("GVL_Plant");
  ASSERT_NE(gvl, nullptr);
  ASSERT_EQ(gvl->variables.size(), 1u);
  EXPECT_EQ(gvl->variables[0].direction, model::VarDirection::Global);
}

TEST(CodesysExport, GivesTheModelOfTheSameChartInTwinCatsSpelling) {
  // The same objects in TwinCAT's compact spelling read to the same chart: the walk is shared.
  const auto cx = io::load_codesys_export(demo_export(), "Demo.export");
  ASSERT_TRUE(cx.ok()) << errors_of(cx);
  const auto tc = io::load_twincat(tc::demo_tcpou(tc::vendor_guids()), "FB_Demo.TcPOU");
  ASSERT_TRUE(tc.ok()) << errors_of(tc);
  const auto& a = cx.project->find_pou("PLC_SEQ")->charts[0];
  const auto& b = tc.project->pous[0].charts[0];
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t i = 0; i < a.steps.size(); ++i) EXPECT_EQ(a.steps[i].name, b.steps[i].name);
  ASSERT_EQ(a.transitions.size(), b.transitions.size());
  for (std::size_t i = 0; i < a.transitions.size(); ++i) {
    EXPECT_EQ(a.transitions[i].sources, b.transitions[i].sources);
    EXPECT_EQ(a.transitions[i].targets, b.transitions[i].targets);
  }
}

TEST(CodesysExport, AttributesAreReadThroughTheArchivesOwnTable) {
  auto invented = tc::invented_guids();
  invented["Qualifier"] = "00000000-0000-4000-8000-000000000099";
  const auto vendor = io::load_codesys_export(demo_export(), "a.export");
  const auto other = io::load_codesys_export(demo_export(invented), "b.export");
  ASSERT_TRUE(vendor.ok() && other.ok()) << errors_of(vendor) << errors_of(other);
  const auto diff = model::first_difference(*vendor.project, *other.project);
  EXPECT_FALSE(diff.has_value()) << *diff;
}

TEST(CodesysExport, LoadFileDetectsTheExportByExtensionAndRoot) {
  EXPECT_EQ(io::detect_format("P.export", ""), io::Format::CodesysExport);
  // codescribe-style exports are named .xml: the root element decides.
  EXPECT_EQ(io::detect_format("SFC_TEST.xml", demo_export()), io::Format::CodesysExport);
}

TEST(CodesysExport, UnmodelledQualifiersAreRefusedAtTheirPlace) {
  Archive ar(export_guids());
  // P is read: CODESYS's "exactly two times" is its final call (docs/semantics.md 1.4a).
  const auto p = io::load_codesys_export(demo_export(export_guids(), ar.association("m2", "P")),
                                         "Demo.export");
  ASSERT_TRUE(p.ok()) << errors_of(p);
  const auto* pou = p.project->find_pou("PLC_SEQ");
  ASSERT_NE(pou, nullptr);
  EXPECT_TRUE(std::any_of(pou->associations.begin(), pou->associations.end(), [](const auto& as) {
    return as.action == "m2" && as.qualifier == model::Qualifier::P && !as.step_action;
  }));
  for (const char* q : {"L"}) {
    const auto r = io::load_codesys_export(demo_export(export_guids(), ar.association("m2", q)),
                                           "Demo.export");
    EXPECT_FALSE(r.ok());
    const auto e = errors_of(r);
    EXPECT_NE(e.find(std::string("unsupported: qualifier ") + q + " of action 'm2' in step 'P2'"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("Demo.export:"), std::string::npos) << e;
    EXPECT_NE(e.find("/ExportFile/StructuredView/Single/List2[@name='EntryList']"),
              std::string::npos)
        << e;
  }
}

TEST(CodesysExport, ObjectOrientedAndUnknownObjectsAreRefusedByName) {
  const auto method = entry("33333333-0000-4000-8000-000000000001", kPouGuid, "M_Run", kMethod,
                            interface("METHOD M_Run : BOOL"));
  const auto r = io::load_codesys_export(demo_export(export_guids(), "", method), "Demo.export");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("unsupported: METHOD 'M_Run' (Device/Application/M_Run)"),
            std::string::npos)
      << errors_of(r);
  const auto odd = entry("33333333-0000-4000-8000-000000000002", kPouGuid, "Odd",
                         "01234567-89ab-4def-8123-456789abcdef", "");
  const auto u = io::load_codesys_export(demo_export(export_guids(), "", odd), "Demo.export");
  EXPECT_FALSE(u.ok());
  EXPECT_NE(errors_of(u).find("unsupported: object 'Odd'"), std::string::npos) << errors_of(u);
  // An action object without an implementation is an error, not an empty action.
  const auto empty = entry("33333333-0000-4000-8000-000000000004", kPouGuid, "A_None", kAction, "");
  const auto n = io::load_codesys_export(demo_export(export_guids(), "", empty), "Demo.export");
  EXPECT_FALSE(n.ok());
  EXPECT_NE(errors_of(n).find("action 'A_None' (Device/Application/A_None) has no implementation"),
            std::string::npos)
      << errors_of(n);
}

TEST(CodesysExport, UsedSfcFlagsAreRefused) {
  // SFCReset & co. act on the chart from outside: a POU that uses one CODESYS declares
  // implicitly (not in the POU's declaration) is refused.
  auto text = demo_export();
  const std::string flags =
      "<Dictionary Type=\"{2c41fa04-1834-41c1-816e-303c7aa2c05b}\" Name=\"Properties\"><Entry>"
      "<Key><Single Type=\"System.Guid\">58548d2c-f1b1-453d-9195-66c94e2a3ae0</Single></Key>"
      "<Value><Single Type=\"{58548d2c-f1b1-453d-9195-66c94e2a3ae0}\" Method=\"IArchivable\">"
      "<Dictionary2 Name=\"Flags\"><Entry><Key><Single Type=\"{27d8150b}\">Reset</Single></Key>"
      "<Value><Single Type=\"{24565a38}\" Method=\"IArchivable\"><Single Name=\"Use\" "
      "Type=\"bool\">True</Single></Single></Value></Entry></Dictionary2></Single></Value>"
      "</Entry></Dictionary>";
  const std::string name = "<Single Name=\"Name\" Type=\"string\">PLC_SEQ</Single>";
  const auto at = text.find(name);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + name.size(), flags);
  const auto r = io::load_codesys_export(text, "Demo.export");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(errors_of(r).find("unsupported: SFC flag 'SFCReset' of POU 'PLC_SEQ' is used but "
                              "not declared in the POU"),
            std::string::npos)
      << errors_of(r);
  // Declared in the POU, the flag is a variable the semantics models (docs/semantics.md 1.3a).
  const std::string decl = "m1, m2, lamp, busy : BOOL;";
  const auto d = text.find(decl);
  ASSERT_NE(d, std::string::npos);
  text.insert(d + decl.size(), " SFCReset : BOOL;");
  const auto declared = io::load_codesys_export(text, "Demo.export");
  EXPECT_TRUE(declared.ok()) << errors_of(declared);
}

TEST(CodesysExport, GraphicalBodiesLoadAsNotModelled) {
  // An FBD action (the network editor's archive) loads; running it is refused later.
  const auto fbd = entry("33333333-0000-4000-8000-000000000003", kPouGuid, "A_Fbd", kAction,
                         std::string("<Single Name=\"Implementation\" Type=\"{") + kNetworkImpl +
                             "}\" Method=\"IArchivable\">" +
                             single("DefaultViewMode", "string", "Fbd") + "</Single>");
  const auto r = io::load_codesys_export(demo_export(export_guids(), "", fbd), "Demo.export");
  ASSERT_TRUE(r.ok()) << errors_of(r);
  const auto* a = r.project->find_pou("PLC_SEQ")->find_action("A_Fbd");
  ASSERT_NE(a, nullptr);
  EXPECT_TRUE(a->body_unsupported);
  EXPECT_EQ(a->unsupported_language, "FBD");
}

TEST(CodesysExport, DeclarationErrorsPointIntoTheFile) {
  auto text = demo_export();
  const std::string bad = "start, stop, a, b : BOOL;";
  const auto at = text.find(bad);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, bad.size(), "start, stop, a, b : BOOL");  // no ';'
  const auto r = io::load_codesys_export(text, "Demo.export");
  EXPECT_FALSE(r.ok());
  // The error is at a line of the file (its TextLines), not at line 1 of the declaration.
  bool located = false;
  for (const auto& d : r.diagnostics)
    if (d.severity == model::Severity::Error && d.where.line > 5) located = true;
  EXPECT_TRUE(located) << errors_of(r);
}

}  // namespace
}  // namespace sfcv::test

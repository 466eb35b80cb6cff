#pragma once
// Small CODESYS native exports (`.export`) written here, mimicking what CODESYS's "Export..."
// writes (the public greenforge-labs/codescribe `GraphicalTesting/StandardPLC/application/
// SFC_TEST.xml` was read for the shape; nothing of it is copied): an `<ExportFile>` whose
// `StructuredView` archive lists entries (MetaObject Guid/ParentGuid/Name/TypeGuid, Object),
// in CODESYS's verbose spelling (`<Single Name Type>`, `<List2>`, `<Dictionary2>`). Objects
// are typed by class GUID; an SFC body is the SFCImplementationObject archive TwinCAT also
// writes, its attributes keyed by GUIDs described by the archive's own table. Also the IEC
// text twin of the demo chart, for verdict comparisons.

#include <string>
#include <vector>

#include "support/twincat_text.hpp"

namespace sfcv::test::cx {

using tc::Guids;

// Class GUIDs (object and implementation types) as CODESYS writes them.
inline const char* const kPou = "6f9dac99-8de1-4efc-8465-68ac443b7d08";
inline const char* const kAction = "8ac092e5-3128-4e26-9e7e-11016c6684f2";
inline const char* const kTransition = "a10c6218-cb94-436f-91c6-e1652575253d";
inline const char* const kGvl = "ffbfa93a-b94d-45fc-a329-229860183b1d";
inline const char* const kDut = "2db5746d-d284-4425-9f7f-2663a34b0ebc";
inline const char* const kMethod = "f8a58466-d7f6-439f-bbb8-d4600e41d099";
inline const char* const kStImpl = "3b83b776-fb25-43b8-99f2-3c507c9143fc";
inline const char* const kSfcImpl = "74f81948-1328-492c-b6c1-a9ea72048b28";
inline const char* const kNetworkImpl = "25e509de-33d4-4447-93f8-c9e4ea381c8b";

/// The attribute GUIDs of an archive, with the association qualifier CODESYS adds.
inline Guids export_guids() {
  Guids g = tc::vendor_guids();
  g["Qualifier"] = "e174fc0d-80b0-4a9e-a530-ca239c249a50";
  return g;
}

inline std::string single(const std::string& name, const std::string& type,
                          const std::string& text) {
  return "<Single Name=\"" + name + "\" Type=\"" + type + "\">" + text + "</Single>";
}

/// A text document: one `TextLines` element per line.
inline std::string text_document(const std::string& text) {
  std::string s =
      "<Single Name=\"TextDocument\" Type=\"{f3878285-8e4f-490b-bb1b-9acbb7eb04db}\" "
      "Method=\"IArchivable\">\n<Array Name=\"TextLines\" "
      "Type=\"{a5de0b0b-1cb5-4913-ac21-9d70293ec00d}\">\n";
  std::size_t start = 0;
  int id = 1;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    const std::string line =
        text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    s += "<Single Type=\"{a5de0b0b-1cb5-4913-ac21-9d70293ec00d}\" Method=\"IArchivable\">" +
         single("Id", "long", std::to_string(id++)) + "<Null Name=\"Tag\" />" +
         single("Text", "string", line) + "</Single>\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return s + "</Array>\n</Single>\n";
}

inline std::string interface(const std::string& declaration) {
  return "<Single Name=\"Interface\" Type=\"{a9ed5b7e-75c5-4651-af16-d2c27e98cb94}\" "
         "Method=\"IArchivable\">\n" +
         text_document(declaration) + "</Single>\n";
}

inline std::string st_implementation(const std::string& body) {
  return std::string("<Single Name=\"Implementation\" Type=\"{") + kStImpl +
         "}\" Method=\"IArchivable\">\n" + text_document(body) + "</Single>\n";
}

/// Builds SFC archive objects (verbose spelling) with increasing ids.
class Archive {
 public:
  explicit Archive(Guids guids) : guids_(std::move(guids)) {}

  std::string attr(const std::string& id, const std::string& value) {
    return "<Single Type=\"{21f3f16e-04fa-4637-b6b7-d84e4192e99f}\" Method=\"IArchivable\">" +
           single("AttributeId", "System.Guid", guids_.at(id)) +
           "<Single Name=\"Value\" Type=\"{778c8bac-3fa0-41e1-99d3-2b628d12d3e5}\" "
           "Method=\"IArchivable\">" +
           single("Value", "string", value) + single("DefaultValue", "string", "") + "</Single>" +
           single("Id", "long", next()) + "</Single>\n";
  }

  std::string element_list(const std::string& inner) {
    return "<Single Name=\"ElementList\" Type=\"{587d6556-cfe6-4e76-9cc9-fc0daf0c8c29}\" "
           "Method=\"IArchivable\"><List2 Name=\"InnerList\">\n" +
           inner + "</List2></Single>\n";
  }

  /// An IEC action association inside a step.
  std::string association(const std::string& action, const std::string& qualifier) {
    return "<Single Type=\"{a94bb75d-5fb3-40ad-9d01-41d5b980784d}\" Method=\"IArchivable\">"
           "<List2 Name=\"Attributes\">\n" +
           attr("Name", action) + attr("Comment", "") + attr("Exclude", "FALSE") +
           attr("Qualifier", qualifier) + "</List2>" + single("Id", "long", next()) + "</Single>\n";
  }

  std::string step(const std::string& name, bool initial = false, const std::string& main = "",
                   const std::string& entry = "", const std::string& exit = "",
                   const std::string& associations = "") {
    return "<Single Type=\"{86ee92a2-d863-4136-be27-82b36d84211c}\" Method=\"IArchivable\">"
           "<Null Name=\"EmbeddedMainAction\" /><Null Name=\"EmbeddedEntryAction\" />"
           "<Null Name=\"EmbeddedExitAction\" />" +
           element_list(associations) + "<List2 Name=\"Attributes\">\n" + attr("Name", name) +
           attr("Comment", "") + attr("Exclude", "FALSE") +
           attr("InitStep", initial ? "TRUE" : "FALSE") + attr("MinTime", "") +
           attr("MaxTime", "") + attr("MainAction", main) + attr("EntryAction", entry) +
           attr("ExitAction", exit) + "</List2>" + single("Id", "long", next()) + "</Single>\n";
  }

  std::string transition(const std::string& condition) {
    return "<Single Type=\"{4ecb29e8-a90a-4646-84ac-2ff54215ab29}\" Method=\"IArchivable\">" +
           single("VariableName", "string", "T" + std::to_string(ids_)) +
           "<Null Name=\"EmbeddedTransition\" /><List2 Name=\"Attributes\">\n" +
           attr("Name", condition) + attr("Comment", "") + attr("Exclude", "FALSE") + "</List2>" +
           single("Id", "long", next()) + "</Single>\n";
  }

  std::string jump(const std::string& target) {
    return "<Single Type=\"{7e39ac27-154f-419a-a255-6a6cf37d5ed0}\" Method=\"IArchivable\">"
           "<List2 Name=\"Attributes\">" +
           attr("Name", target) + "</List2>" + single("Id", "long", next()) + "</Single>\n";
  }

  /// Legs are element sequences; each becomes an SFCSegment of the branch (with the segment
  /// attributes CODESYS writes).
  std::string branch(bool parallel, const std::vector<std::string>& legs) {
    std::string inner;
    for (const auto& leg : legs)
      inner += "<Single Type=\"{f1db7f6f-4774-46a6-ad9b-a94414f875fc}\" Method=\"IArchivable\">" +
               element_list(leg) + "<List2 Name=\"Attributes\">" + attr("Name", "") +
               attr("Comment", "") + attr("Exclude", "FALSE") + "</List2>" +
               single("Id", "long", next()) + "</Single>\n";
    return "<Single Type=\"{e221b778-bb8f-44ba-8a6a-f796287d4e62}\" Method=\"IArchivable\">" +
           element_list(inner) + "<List2 Name=\"Attributes\">" + attr("Name", "Branch0") +
           attr("Parallel", parallel ? "TRUE" : "FALSE") + "</List2>" +
           single("Id", "long", next()) + "</Single>\n";
  }

  /// The SFC `Implementation` object: the root sequence and the attribute table.
  std::string implementation(const std::string& elements) {
    std::string table = "<Dictionary2 Name=\"Attributes\">\n";
    for (const auto& [id, guid] : guids_)
      table += "<Entry><Key><Single Type=\"System.Guid\">" + guid +
               "</Single></Key><Value><Single Type=\"{d851789d-af2c-4990-9d48-a7bdc9181773}\" "
               "Method=\"IArchivable\">" +
               single("Id", "System.Guid", guid) + single("Identifier", "string", id) +
               "</Single></Value></Entry>\n";
    table += "</Dictionary2>\n";
    return std::string("<Single Name=\"Implementation\" Type=\"{") + kSfcImpl +
           "}\" Method=\"IArchivable\">\n<Single Name=\"Root\" "
           "Type=\"{f1db7f6f-4774-46a6-ad9b-a94414f875fc}\" Method=\"IArchivable\">" +
           element_list(elements) + "</Single>\n" + table + "</Single>\n";
  }

 private:
  std::string next() { return std::to_string(++ids_); }
  Guids guids_;
  int ids_ = 1;
};

/// One export entry: a project object with its class GUID, parent and object members.
inline std::string entry(const std::string& guid, const std::string& parent,
                         const std::string& name, const std::string& type,
                         const std::string& members, const std::string& path = "Application",
                         const std::string& meta_extra = "") {
  return "<Single Type=\"{6198ad31-4b98-445c-927f-3258a0e82fe3}\" Method=\"IArchivable\">\n" +
         single("IsRoot", "bool", "True") +
         "<Single Name=\"MetaObject\" Type=\"{81297157-7ec9-45ce-845e-84cab2b88ade}\" "
         "Method=\"IArchivable\">" +
         single("Guid", "System.Guid", guid) + single("ParentGuid", "System.Guid", parent) +
         single("Name", "string", name) + meta_extra + single("TypeGuid", "System.Guid", type) +
         "</Single>\n<Single Name=\"Object\" Type=\"{" + type + "}\" Method=\"IArchivable\">\n" +
         members + "</Single>\n<Array Name=\"Path\" Type=\"string\">" +
         single("", "string", "Device") + single("", "string", path) + "</Array>\n</Single>\n";
}

inline std::string export_file(const std::string& entries) {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<ExportFile>\n"
         "  <StructuredView Guid=\"{d9b2b2cc-ea99-4c3b-aa42-1e5c49e65b84}\">\n"
         "<Single xml:space=\"preserve\" Type=\"{3daac5e4-660e-42e4-9cea-3711b98bfb63}\" "
         "Method=\"IArchivable\">\n<Null Name=\"Profile\" />\n<List2 Name=\"EntryList\">\n" +
         entries +
         "</List2>\n<Null Name=\"ProfileName\" />\n</Single>  </StructuredView>\n"
         "</ExportFile>\n";
}

inline const char* const kPouGuid = "11111111-0000-4000-8000-000000000001";

inline std::string st_child(const std::string& n, const std::string& type,
                            const std::string& body) {
  static int k = 100;
  return entry("11111111-0000-4000-8000-000000000" + std::to_string(k++), kPouGuid, n, type,
               st_implementation(body), "Application/PLC_SEQ");
}

inline const char* const kDemoDeclaration =
    "PROGRAM PLC_SEQ\nVAR_INPUT\n\tstart, stop, a, b : BOOL;\nEND_VAR\n"
    "VAR_OUTPUT\n\tm1, m2, lamp, busy : BOOL;\nEND_VAR";

/// The demo: Init (A_Init, busy R), an alternative branch {start AND a: S1 (entry A_E, main
/// A_S1, busy S) -stop->, b AND NOT a: S2 (exit A_X) -TrDone->} meeting at Merge, -TRUE->, a
/// simultaneous branch {P1 (A_P1 N) -a-> P1b, P2}, -NOT start->, jump to Init. TrDone is a
/// transition object in ST; the actions are ST action objects; a GVL and a DUT come along.
/// `extra_step_associations` adds IEC associations to P2 (for refusal tests).
inline std::string demo_export(const Guids& guids = export_guids(),
                               const std::string& extra_step_associations = "",
                               const std::string& extra_entries = "") {
  Archive ar(guids);
  std::string e = ar.step("Init", true, "A_Init", "", "", ar.association("busy", "R"));
  const std::string leg1 = ar.transition("start AND a") +
                           ar.step("S1", false, "A_S1", "A_E", "", ar.association("busy", "S")) +
                           ar.transition("stop");
  const std::string leg2 =
      ar.transition("b AND NOT a") + ar.step("S2", false, "", "", "A_X") + ar.transition("TrDone");
  e += ar.branch(false, {leg1, leg2});
  e += ar.step("Merge");
  e += ar.transition("TRUE");
  const std::string p1 = ar.step("P1", false, "", "", "", ar.association("A_P1", "N")) +
                         ar.transition("a") + ar.step("P1b");
  const std::string p2 = ar.step("P2", false, "", "", "", extra_step_associations);
  e += ar.branch(true, {p1, p2});
  e += ar.transition("NOT start");
  e += ar.jump("Init");
  const std::string pou =
      entry(kPouGuid, "f9c00bdb-2f18-4e80-863e-6da977e8f304", "PLC_SEQ", kPou,
            "<Single Name=\"SpecialFunc\" Type=\"{0db3d7bb-cde0-4416-9a7b-ce49a0124323}\">None"
            "</Single>\n" +
                ar.implementation(e) + interface(kDemoDeclaration));
  return export_file(
      pou + st_child("A_Init", kAction, "m1 := FALSE;\nm2 := FALSE;") +
      st_child("A_S1", kAction, "m1 := TRUE;") + st_child("A_E", kAction, "lamp := TRUE;") +
      st_child("A_X", kAction, "lamp := FALSE;") + st_child("A_P1", kAction, "m2 := TRUE;") +
      st_child("TrDone", kTransition, "NOT stop AND a") +
      entry("22222222-0000-4000-8000-000000000001", "f9c00bdb-2f18-4e80-863e-6da977e8f304",
            "GVL_Plant", kGvl, interface("VAR_GLOBAL\n\tlimit : INT := 3;\nEND_VAR")) +
      entry("22222222-0000-4000-8000-000000000002", "f9c00bdb-2f18-4e80-863e-6da977e8f304",
            "E_Mode", kDut, interface("TYPE E_Mode :\n(\n\tIDLE := 0,\n\tRUN := 1\n);\nEND_TYPE")) +
      extra_entries);
}

/// The IEC 61131-3 text twin of demo_export's chart.
inline const char* const kDemoIecTwin = R"(PROGRAM PLC_SEQ
  VAR_INPUT start, stop, a, b : BOOL; END_VAR
  VAR_OUTPUT m1, m2, lamp, busy : BOOL; END_VAR
  INITIAL_STEP Init: A_Init(N); busy(R); END_STEP
  STEP S1: A_S1(N); A_E(P1); busy(S); END_STEP
  STEP S2: A_X(P0); END_STEP
  STEP Merge: END_STEP
  STEP P1: A_P1(N); END_STEP
  STEP P1b: END_STEP
  STEP P2: END_STEP
  ACTION A_Init: m1 := FALSE; m2 := FALSE; END_ACTION
  ACTION A_S1: m1 := TRUE; END_ACTION
  ACTION A_E: lamp := TRUE; END_ACTION
  ACTION A_X: lamp := FALSE; END_ACTION
  ACTION A_P1: m2 := TRUE; END_ACTION
  TRANSITION FROM Init TO S1 := start AND a; END_TRANSITION
  TRANSITION FROM Init TO S2 := b AND NOT a; END_TRANSITION
  TRANSITION FROM S1 TO Merge := stop; END_TRANSITION
  TRANSITION FROM S2 TO Merge := NOT stop AND a; END_TRANSITION
  TRANSITION FROM Merge TO (P1, P2) := TRUE; END_TRANSITION
  TRANSITION FROM P1 TO P1b := a; END_TRANSITION
  TRANSITION FROM (P1b, P2) TO Init := NOT start; END_TRANSITION
END_PROGRAM
)";

}  // namespace sfcv::test::cx

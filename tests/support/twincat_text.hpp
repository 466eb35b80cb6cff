#pragma once
// Small TwinCAT 3 `.TcPOU` files written here, mimicking the files TwinCAT users commit (the
// public MrFrakt/Fraktal FB_SFC_PressDemoAuto.TcPOU was read for the shape; nothing of it is
// copied): an SFC body as `<XmlArchive>` (SFCImplementationObject -> Root SFCSegment ->
// ElementList of SFCStep/SFCTransition/SFCJump/SFCBranch), element attributes as records keyed
// by GUIDs, and the archive's own attribute table giving each GUID its Identifier. The GUIDs
// are parameters: a file with invented GUIDs must read the same, since readers go through the
// table. Also the PLCopen TC6 twin of the demo chart, for model and verdict comparisons.

#include <map>
#include <string>
#include <vector>

#include "support/plcopen_text.hpp"

namespace sfcv::test::tc {

/// Identifier -> GUID (without braces), the table an archive carries.
using Guids = std::map<std::string, std::string>;

/// The GUIDs TwinCAT 3.1 writes (the same CODESYS puts in PLCopen addData).
inline Guids vendor_guids() {
  return {{"Name", "38391c6d-6d4a-42f8-8ee7-9f45e5adafa8"},
          {"Comment", "7d894980-aeea-405c-a0f6-e2b26429c58f"},
          {"Exclude", "01580b27-6378-448b-8ecb-0e4b795b58d6"},
          {"InitStep", "6844a48e-46c2-4cc8-a185-a478f3b99cc0"},
          {"Parallel", "23bdaa98-72ec-41f7-817b-9dede5697086"},
          {"MainAction", "700a583f-b4d4-43e4-8c14-629c7cd3bec8"},
          {"EntryAction", "a6b08bd8-b696-47e3-9cbf-7408b61c9ff8"},
          {"ExitAction", "a2621e18-7de3-4ea6-ae6d-89e9e0b7befd"},
          {"MinTime", "cacf1a68-236e-47c2-b7b1-1cf9199718cb"},
          {"MaxTime", "b693554c-1b01-4a8d-afde-9e3a46f7465d"}};
}

/// Made-up GUIDs for the same identifiers: a reader that hard-coded the vendor's would fail.
inline Guids invented_guids() {
  Guids g = vendor_guids();
  int i = 0;
  for (auto& [id, guid] : g) {
    (void)id;
    guid = "00000000-0000-4000-8000-0000000000" + std::to_string(10 + i++);
  }
  return g;
}

/// Builds archive objects with increasing ids.
class Archive {
 public:
  explicit Archive(Guids guids) : guids_(std::move(guids)) {}

  std::string attr(const std::string& id, const std::string& value, bool boolean = false) {
    return "<o><v n=\"AttributeId\">{" + guids_.at(id) + "}</v><o n=\"Value\" t=\"" +
           (boolean ? "BoolValue" : "StringValue") + "\"><v n=\"Value\">\"" + value +
           "\"</v><v n=\"DefaultValue\">\"\"</v></o><v n=\"Id\">" + next() + "L</v></o>\n";
  }

  std::string step(const std::string& name, bool initial = false, const std::string& main = "",
                   const std::string& entry = "", const std::string& exit = "",
                   const std::string& extra_attrs = "", const std::string& inner = "") {
    return "<o t=\"SFCStep\"><n n=\"EmbeddedMainAction\" /><n n=\"EmbeddedEntryAction\" />"
           "<n n=\"EmbeddedExitAction\" /><o n=\"ElementList\" t=\"SFCElementList\">"
           "<l2 n=\"InnerList\">" +
           inner + "</l2></o><l2 n=\"Attributes\" cet=\"SFCAttribute\">\n" + attr("Name", name) +
           attr("Comment", "") + attr("Exclude", "FALSE", true) +
           attr("InitStep", initial ? "TRUE" : "FALSE", true) + attr("MinTime", "") +
           attr("MaxTime", "") + attr("MainAction", main) + attr("EntryAction", entry) +
           attr("ExitAction", exit) + extra_attrs + "</l2><v n=\"Id\">" + next() + "L</v></o>\n";
  }

  std::string transition(const std::string& condition, const std::string& embedded = "") {
    return "<o t=\"SFCTransition\"><v n=\"VariableName\">\"T" + std::to_string(ids_) + "\"</v>" +
           (embedded.empty() ? "<n n=\"EmbeddedTransition\" />" : embedded) +
           "<l2 n=\"Attributes\" cet=\"SFCAttribute\">\n" + attr("Name", condition) +
           attr("Comment", "") + attr("Exclude", "FALSE", true) + "</l2><v n=\"Id\">" + next() +
           "L</v></o>\n";
  }

  std::string jump(const std::string& target) {
    return "<o t=\"SFCJump\"><l2 n=\"Attributes\" cet=\"SFCAttribute\">" + attr("Name", target) +
           "</l2><v n=\"Id\">" + next() + "L</v></o>\n";
  }

  /// Legs are element sequences; each becomes an SFCSegment of the branch.
  std::string branch(bool parallel, const std::vector<std::string>& legs) {
    std::string s =
        "<o t=\"SFCBranch\"><o n=\"ElementList\" t=\"SFCElementList\">"
        "<l2 n=\"InnerList\" cet=\"SFCSegment\">\n";
    for (const auto& leg : legs)
      s += "<o><o n=\"ElementList\" t=\"SFCElementList\"><l2 n=\"InnerList\">" + leg +
           "</l2></o><v n=\"Id\">" + next() + "L</v></o>\n";
    return s + "</l2></o><l2 n=\"Attributes\" cet=\"SFCAttribute\">" + attr("Name", "") +
           attr("Parallel", parallel ? "TRUE" : "FALSE", true) + "</l2><v n=\"Id\">" + next() +
           "L</v></o>\n";
  }

  /// The `<SFC>` element: the root sequence and the attribute table.
  std::string sfc(const std::string& elements) const {
    std::string table = "<d2 n=\"Attributes\" ckt=\"Guid\" cvt=\"SFCAttributeDescription\">\n";
    for (const auto& [id, guid] : guids_)
      table += "<v>" + guid + "</v><o><v n=\"Id\">{" + guid + "}</v><v n=\"Identifier\">\"" + id +
               "\"</v></o>\n";
    table += "</d2>\n";
    return "<SFC><XmlArchive><Data><o xml:space=\"preserve\" t=\"SFCImplementationObject\">"
           "<o n=\"Root\" t=\"SFCSegment\"><o n=\"ElementList\" t=\"SFCElementList\">"
           "<l2 n=\"InnerList\">\n" +
           elements + "</l2></o><v n=\"Id\">1L</v></o>\n" + table +
           "</o></Data><TypeList><Type n=\"SFCStep\">{86ee92a2-d863-4136-be27-82b36d84211c}"
           "</Type></TypeList></XmlArchive></SFC>";
  }

 private:
  std::string next() { return std::to_string(++ids_); }
  Guids guids_;
  int ids_ = 1;
};

inline std::string st_action(const std::string& name, const std::string& body) {
  return "<Action Name=\"" + name +
         "\" Id=\"{00000000-0000-0000-0000-000000000001}\">"
         "<Implementation><ST><![CDATA[" +
         body + "]]></ST></Implementation></Action>\n";
}

/// A `.TcPOU` document: declaration text, implementation element and sibling objects.
inline std::string tcpou(const std::string& name, const std::string& declaration,
                         const std::string& implementation, const std::string& siblings = "") {
  return "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n"
         "  <POU Name=\"" +
         name +
         "\" Id=\"{5a6ce38f-0000-4b54-b6a4-05132bef8883}\" SpecialFunc=\"None\">\n"
         "    <Declaration><![CDATA[" +
         declaration + "]]></Declaration>\n    <Implementation>\n" + implementation +
         "\n    </Implementation>\n" + siblings + "  </POU>\n</TcPlcObject>\n";
}

inline const char* const kDemoDeclaration =
    "// demo chart\nFUNCTION_BLOCK FB_Demo\nVAR_INPUT\n    start, stop, a, b : BOOL;\nEND_VAR\n"
    "VAR_OUTPUT\n    {attribute 'hide'}\n    m1, m2, lamp : BOOL;\nEND_VAR\n";

inline std::string demo_actions() {
  return st_action("A_Init", "m1 := FALSE;\nm2 := FALSE;") + st_action("A_S1", "m1 := TRUE;") +
         st_action("A_E", "lamp := TRUE;") + st_action("A_X", "lamp := FALSE;") +
         st_action("A_P1", "m2 := TRUE;") +
         "<Transition Name=\"TrDone\" Id=\"{00000000-0000-0000-0000-000000000002}\">"
         "<Implementation><ST><![CDATA[NOT stop AND a]]></ST></Implementation></Transition>\n";
}

/// The demo chart: Init, an alternative branch {start AND a: S1 -stop->, b AND NOT a: S2
/// -TrDone->} meeting at Merge, -TRUE->, a parallel branch {P1 -a-> P1b, P2}, -NOT start->, jump
/// to Init. S1 has a main and an entry action, S2 an exit action.
inline std::string demo_tcpou(const Guids& guids) {
  Archive ar(guids);
  std::string e = ar.step("Init", true, "A_Init");
  const std::string leg1 =
      ar.transition("start AND a") + ar.step("S1", false, "A_S1", "A_E") + ar.transition("stop");
  const std::string leg2 =
      ar.transition("b AND NOT a") + ar.step("S2", false, "", "", "A_X") + ar.transition("TrDone");
  e += ar.branch(false, {leg1, leg2});
  e += ar.step("Merge");
  e += ar.transition("TRUE");
  const std::string p1 = ar.step("P1", false, "A_P1") + ar.transition("a") + ar.step("P1b");
  const std::string p2 = ar.step("P2");
  e += ar.branch(true, {p1, p2});
  e += ar.transition("NOT start");
  e += ar.jump("Init");
  return tcpou("FB_Demo", kDemoDeclaration, ar.sfc(e), demo_actions());
}

// ----------------------------------------------------------------- the PLCopen TC6 twin

inline std::string plc_step(int id, const std::string& name, int from, bool initial = false,
                            const std::string& main = "", const std::string& entry = "",
                            const std::string& exit = "") {
  const auto g = vendor_guids();
  std::string attrs;
  if (!main.empty())
    attrs += "<attribute guid=\"" + g.at("MainAction") + "\">" + main + "</attribute>";
  if (!entry.empty())
    attrs += "<attribute guid=\"" + g.at("EntryAction") + "\">" + entry + "</attribute>";
  if (!exit.empty())
    attrs += "<attribute guid=\"" + g.at("ExitAction") + "\">" + exit + "</attribute>";
  return "<step localId=\"" + std::to_string(id) + "\" name=\"" + name + "\"" +
         (initial ? " initialStep=\"true\"" : "") + ">" +
         (from ? "<connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
                     "\"/></connectionPointIn>"
               : std::string()) +
         "<connectionPointOut formalParameter=\"sfc\"/>"
         "<addData><data name=\"http://www.3s-software.com/plcopenxml/sfc/element\" "
         "handleUnknown=\"implementation\"><attributes xmlns=\"\">" +
         attrs + "</attributes></data></addData></step>\n";
}

inline std::string plc_from(const std::string& tag, int id, const std::vector<int>& from,
                            const std::string& inner = "") {
  std::string s = "<" + tag + " localId=\"" + std::to_string(id) + "\"><connectionPointIn>";
  for (int f : from) s += "<connection refLocalId=\"" + std::to_string(f) + "\"/>";
  return s + "</connectionPointIn>" + inner + "</" + tag + ">\n";
}

inline std::string plc_transition(int id, int from, const std::string& condition,
                                  bool reference = false) {
  const std::string cond =
      reference ? "<condition><reference name=\"" + condition + "\"/></condition>"
                : "<condition><inline name=\"\">" + plcopen_st(condition) + "</inline></condition>";
  return plc_from("transition", id, {from}, cond);
}

/// The PLCopen TC6 export of the same chart as demo_tcpou (CODESYS style: step actions in
/// addData, TrDone in pou/transitions).
inline std::string demo_plcopen() {
  std::string sfc;
  sfc += plc_step(1, "Init", 0, true, "A_Init");
  sfc += plc_from("selectionDivergence", 2, {1});
  sfc += plc_transition(3, 2, "start AND a");
  sfc += plc_step(4, "S1", 3, false, "A_S1", "A_E");
  sfc += plc_transition(5, 4, "stop");
  sfc += plc_transition(6, 2, "b AND NOT a");
  sfc += plc_step(7, "S2", 6, false, "", "", "A_X");
  sfc += plc_transition(8, 7, "TrDone", true);
  sfc += plc_from("selectionConvergence", 9, {5, 8});
  sfc += plc_step(10, "Merge", 9);
  sfc += plc_transition(11, 10, "TRUE");
  sfc += plc_from("simultaneousDivergence", 12, {11});
  sfc += plc_step(13, "P1", 12, false, "A_P1");
  sfc += plc_transition(14, 13, "a");
  sfc += plc_step(15, "P1b", 14);
  sfc += plc_step(16, "P2", 12);
  sfc += plc_from("simultaneousConvergence", 17, {15, 16});
  sfc += plc_transition(18, 17, "NOT start");
  sfc +=
      "<jumpStep localId=\"19\" targetName=\"Init\"><connectionPointIn>"
      "<connection refLocalId=\"18\"/></connectionPointIn></jumpStep>\n";
  auto action = [](const std::string& name, const std::string& body) {
    return "<action name=\"" + name + "\"><body>" + plcopen_st(body) + "</body></action>";
  };
  return kPlcopenHeader + "<pou name=\"FB_Demo\" pouType=\"functionBlock\"><interface>" +
         plcopen_vars("inputVars", {"start", "stop", "a", "b"}) +
         plcopen_vars("outputVars", {"m1", "m2", "lamp"}) + "</interface><actions>" +
         action("A_Init", "m1 := FALSE;\nm2 := FALSE;") + action("A_S1", "m1 := TRUE;") +
         action("A_E", "lamp := TRUE;") + action("A_X", "lamp := FALSE;") +
         action("A_P1", "m2 := TRUE;") +
         "</actions><transitions><transition name=\"TrDone\"><body>" +
         plcopen_st("NOT stop AND a") + "</body></transition></transitions><body><SFC>\n" + sfc +
         "</SFC></body></pou>\n" + kPlcopenFooter;
}

}  // namespace sfcv::test::tc

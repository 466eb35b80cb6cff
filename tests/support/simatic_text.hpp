#pragma once
// A TIA Portal SimaticML export of an S7-GRAPH function block written in the vendor's shape for
// tests (the layout of public exports such as huaruiwh/portal
// examples/motor-sequence-lad/graph/verify/MotorSequenceGRAPH_export.xml: Steps with action
// tables, Transitions with LAD networks ending in a TrCoil, Branches and Connections), never
// copied from one; and a demo chart with its IEC 61131-3 text twin.

#include <string>
#include <utility>
#include <vector>

namespace sfcv::test::simatic {

/// A LAD network (FlgNet) from a small description: `contacts` is a list of parallel branches,
/// each a series of contacts "tag", "!tag" (NC) or "#member"; the branches join in an O box
/// before `coil`.
inline std::string lad(const std::vector<std::vector<std::string>>& branches,
                       const std::string& coil = "TrCoil") {
  std::string parts, wires;
  int uid = 21;
  std::vector<std::pair<int, std::string>> accesses;  // uid, operand
  std::vector<int> branch_ends;
  std::vector<int> firsts;
  int wire = 500;
  auto w = [&](const std::string& body) {
    wires += "<Wire UId=\"" + std::to_string(wire++) + "\">" + body + "</Wire>\n";
  };
  for (const auto& branch : branches) {
    int prev = -1;
    for (const auto& c : branch) {
      const bool nc = c[0] == '!';
      const std::string name = nc ? c.substr(1) : c;
      const int a = uid++, p = uid++;
      if (name[0] == '#')
        parts += "<Access Scope=\"LocalVariable\" UId=\"" + std::to_string(a) +
                 "\"><Symbol><Component Name=\"" + name.substr(1) + "\" /></Symbol></Access>\n";
      else
        parts += "<Access Scope=\"GlobalVariable\" UId=\"" + std::to_string(a) +
                 "\"><Symbol><Component Name=\"" + name + "\" /></Symbol></Access>\n";
      parts += "<Part Name=\"Contact\" UId=\"" + std::to_string(p) + "\"" +
               (nc ? "><Negated Name=\"operand\" /></Part>\n" : " />\n");
      w("<IdentCon UId=\"" + std::to_string(a) + "\" /><NameCon UId=\"" + std::to_string(p) +
        "\" Name=\"operand\" />");
      if (prev < 0)
        firsts.push_back(p);
      else
        w("<NameCon UId=\"" + std::to_string(prev) + "\" Name=\"out\" /><NameCon UId=\"" +
          std::to_string(p) + "\" Name=\"in\" />");
      prev = p;
    }
    branch_ends.push_back(prev);
  }
  std::string rail = "<Powerrail />";
  for (int f : firsts) rail += "<NameCon UId=\"" + std::to_string(f) + "\" Name=\"in\" />";
  if (!firsts.empty()) w(rail);
  const int coil_uid = uid++;
  if (branch_ends.size() > 1) {
    const int o = uid++;
    parts += "<Part Name=\"O\" UId=\"" + std::to_string(o) +
             "\"><TemplateValue Name=\"Card\" Type=\"Cardinality\">" +
             std::to_string(branch_ends.size()) + "</TemplateValue></Part>\n";
    for (std::size_t i = 0; i < branch_ends.size(); ++i)
      w("<NameCon UId=\"" + std::to_string(branch_ends[i]) + "\" Name=\"out\" /><NameCon UId=\"" +
        std::to_string(o) + "\" Name=\"in" + std::to_string(i + 1) + "\" />");
    w("<NameCon UId=\"" + std::to_string(o) + "\" Name=\"out\" /><NameCon UId=\"" +
      std::to_string(coil_uid) + "\" Name=\"in\" />");
  } else if (branch_ends.size() == 1) {
    w("<NameCon UId=\"" + std::to_string(branch_ends[0]) + "\" Name=\"out\" /><NameCon UId=\"" +
      std::to_string(coil_uid) + "\" Name=\"in\" />");
  } else {
    w("<Powerrail /><NameCon UId=\"" + std::to_string(coil_uid) + "\" Name=\"in\" />");
  }
  parts += "<Part Name=\"" + coil + "\" UId=\"" + std::to_string(coil_uid) + "\" />\n";
  return "<FlgNet>\n<Parts>\n" + parts + "</Parts>\n<Wires>\n" + wires + "</Wires>\n</FlgNet>\n";
}

/// One action row: qualifier and the operand text ("\"Lamp\"", "\"X\", T#2s").
inline std::string action(const std::string& qualifier, const std::string& text) {
  std::string tokens;
  std::size_t comma = text.find(", ");
  if (comma == std::string::npos) {
    tokens = "<Token Text=\"" + text + "\" />";
  } else {
    tokens = "<Token Text=\"" + text.substr(0, comma) + "\" /><Token Text=\",\" /><Token Text=\"" +
             text.substr(comma + 2) + "\" />";
  }
  return "<Action Qualifier=\"" + qualifier + "\">" + tokens +
         "<Token Text=\"&#xA;\" /></Action>\n";
}

/// The quoted tag "name" as an action table writes it in XML.
inline std::string q(const std::string& name) {
  return "&quot;" + name + "&quot;";
}

/// A step with its action rows (and the table's empty last row), its default (empty)
/// supervision and interlock; `extra` goes inside the step after the interlocks.
inline std::string step(int number, const std::string& name, bool init,
                        const std::string& actions = "", const std::string& supervision = "",
                        const std::string& extra = "") {
  return "<Step Number=\"" + std::to_string(number) + "\" Init=\"" + (init ? "true" : "false") +
         "\" Name=\"" + name + "\" MaximumStepTime=\"T#0ms\" WarningTime=\"T#0ms\">\n<Actions>\n" +
         actions +
         "<Action />\n</Actions>\n<Supervisions>\n<Supervision ProgrammingLanguage=\"LAD\">\n" +
         (supervision.empty() ? "<FlgNet><Parts><Part Name=\"SvCoil\" UId=\"21\" /></Parts>"
                                "<Wires /></FlgNet>\n"
                              : supervision) +
         "</Supervision>\n</Supervisions>\n<Interlocks>\n<Interlock "
         "ProgrammingLanguage=\"LAD\">\n" +
         lad({}, "IlCoil") + "</Interlock>\n</Interlocks>\n" + extra + "</Step>\n";
}

inline std::string transition(int number, const std::string& name, const std::string& net) {
  return "<Transition IsMissing=\"false\" Name=\"" + name + "\" Number=\"" +
         std::to_string(number) + "\" ProgrammingLanguage=\"LAD\">\n" + net + "</Transition>\n";
}

/// A node of a connection: "S3", "T2", "B1.in0", "B1.out1".
inline std::string node(const std::string& n) {
  if (n[0] == 'S') return "<StepRef Number=\"" + n.substr(1) + "\" />";
  if (n[0] == 'T') return "<TransitionRef Number=\"" + n.substr(1) + "\" />";
  const auto dot = n.find('.');
  const bool in = n.compare(dot + 1, 2, "in") == 0;
  return "<BranchRef Number=\"" + n.substr(1, dot - 1) + "\" " + (in ? "In" : "Out") + "=\"" +
         n.substr(dot + (in ? 3 : 4)) + "\" />";
}

inline std::string connections(const std::vector<std::pair<std::string, std::string>>& links,
                               const std::vector<std::pair<std::string, std::string>>& jumps) {
  std::string s;
  auto one = [&](const std::string& a, const std::string& b, const char* type) {
    s += "<Connection><NodeFrom>" + node(a) + "</NodeFrom><NodeTo>" + node(b) +
         "</NodeTo><LinkType>" + type + "</LinkType></Connection>\n";
  };
  for (const auto& [a, b] : links) one(a, b, "Direct");
  for (const auto& [a, b] : jumps) one(a, b, "Jump");
  return s;
}

inline std::string member(const std::string& name, const std::string& type,
                          const std::string& start = "") {
  return "<Member Name=\"" + name + "\" Datatype=\"" + type + "\" Remanence=\"NonRetain\">" +
         (start.empty() ? "" : "<StartValue Informative=\"true\">" + start + "</StartValue>") +
         "</Member>\n";
}

/// The whole document: one GRAPH FB named `name`.
inline std::string document(const std::string& name, const std::string& statics,
                            const std::string& steps, const std::string& transitions,
                            const std::string& branches, const std::string& connections,
                            const std::string& pre = "", const std::string& block_attrs = "",
                            const std::string& ns_version = "v5") {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Document>\n<Engineering version=\"V20\" />\n"
         "<SW.Blocks.FB ID=\"0\">\n<AttributeList>\n<GraphVersion>6.0</GraphVersion>\n"
         "<Interface><Sections "
         "xmlns=\"http://www.siemens.com/automation/Openness/SW/Interface/v5\">\n"
         "<Section Name=\"Base\"><Sections Datatype=\"GRAPH_BASE\" Version=\"1.0\">"
         "<Section Name=\"Static\"><Member Name=\"OFF_SQ_BASE\" Datatype=\"Bool\" /></Section>"
         "</Sections></Section>\n"
         "<Section Name=\"Input\">" +
         member("OFF_SQ", "Bool", "false") + member("INIT_SQ", "Bool", "false") +
         "</Section>\n<Section Name=\"Output\">" + member("S_NO", "Int", "0") +
         "</Section>\n<Section Name=\"InOut\" />\n<Section Name=\"Static\">\n"
         "<Member Name=\"RT_DATA\" Datatype=\"G7_RTDataPlus_V6\" Version=\"1.0\" />\n" +
         statics +
         "</Section>\n<Section Name=\"Temp\" />\n<Section Name=\"Constant\" />\n"
         "</Sections></Interface>\n<Name>" +
         name + "</Name>\n<Number>2</Number>\n<ProgrammingLanguage>GRAPH</ProgrammingLanguage>\n" +
         block_attrs +
         "</AttributeList>\n<ObjectList>\n<SW.Blocks.CompileUnit ID=\"3\" "
         "CompositionName=\"CompileUnits\">\n<AttributeList>\n<NetworkSource><Graph "
         "xmlns=\"http://www.siemens.com/automation/Openness/SW/NetworkSource/Graph/" +
         ns_version + "\">\n<PreOperations>" + pre + "</PreOperations>\n<Sequence>\n<Steps>\n" +
         steps + "</Steps>\n<Transitions>\n" + transitions + "</Transitions>\n<Branches>\n" +
         branches + "</Branches>\n<Connections>\n" + connections +
         "</Connections>\n</Sequence>\n<PostOperations />\n</Graph></NetworkSource>\n"
         "<ProgrammingLanguage>GRAPH</ProgrammingLanguage>\n</AttributeList>\n"
         "</SW.Blocks.CompileUnit>\n</ObjectList>\n</SW.Blocks.FB>\n</Document>\n";
}

/// The demo: Idle -T1(start & !stop)-> an alternative branch: Fill -T2(#full | level_hi)-> a
/// simultaneous branch {Mix, Heat} -T4(!busy)-> Done -T5(ack)-> jump to Idle; or
/// Fill's alternative T3(stop) -> jump to Idle. Idle resets `motor` (R), Fill sets it (S);
/// Fill drives `valve` (N), Mix `mixer` (N), Heat `heater` (L, 5 s); Done `lamp` (D, 2 s).
inline std::string demo(const std::string& pre = "") {
  const std::string statics = member("full", "Bool", "false");
  const std::string steps =
      step(1, "Idle", true, action("R", q("motor"))) +
      step(2, "Fill", false, action("S", q("motor")) + action("N", q("valve"))) +
      step(3, "Mix", false, action("N", q("mixer"))) +
      step(4, "Heat", false, action("L", q("heater") + ", T#5s")) +
      step(5, "Done", false, action("D", q("lamp") + ", T#2s"));
  const std::string transitions = transition(1, "T_Start", lad({{"start", "!stop"}})) +
                                  transition(2, "T_Full", lad({{"#full"}, {"level_hi"}})) +
                                  transition(3, "T_Stop", lad({{"stop"}})) +
                                  transition(4, "T_Mixed", lad({{"!busy"}})) +
                                  transition(5, "T_Ack", lad({{"ack"}}));
  const std::string branches =
      "<Branch Number=\"1\" Type=\"AltBegin\" Cardinality=\"2\" />\n"
      "<Branch Number=\"2\" Type=\"SimBegin\" Cardinality=\"2\" />\n"
      "<Branch Number=\"3\" Type=\"SimEnd\" Cardinality=\"2\" />\n";
  const std::string links = connections({{"S1", "T1"},
                                         {"T1", "S2"},
                                         {"S2", "B1.in0"},
                                         {"B1.out0", "T2"},
                                         {"B1.out1", "T3"},
                                         {"T2", "B2.in0"},
                                         {"B2.out0", "S3"},
                                         {"B2.out1", "S4"},
                                         {"S3", "B3.in0"},
                                         {"S4", "B3.in1"},
                                         {"B3.out0", "T4"},
                                         {"T4", "S5"},
                                         {"S5", "T5"}},
                                        {{"T3", "S1"}, {"T5", "S1"}});
  return document("Tank", statics, steps, transitions, branches, links, pre);
}

/// The demo's IEC 61131-3 text twin, written from the drawing (the PLC tags declared in the
/// order the block first names them: its action tables, then its transitions).
inline std::string demo_twin() {
  return R"(PROGRAM Tank
VAR
  full : BOOL := FALSE;
  motor, valve, mixer, heater, lamp : BOOL;
  start, stop, level_hi, busy, ack : BOOL;
END_VAR
INITIAL_STEP Idle : motor(R); END_STEP
STEP Fill : motor(S); valve(N); END_STEP
STEP Mix : mixer(N); END_STEP
STEP Heat : heater(L, T#5s); END_STEP
STEP Done : lamp(D, T#2s); END_STEP
TRANSITION T_Start FROM Idle TO Fill := start AND NOT stop; END_TRANSITION
TRANSITION T_Full FROM Fill TO (Mix, Heat) := full OR level_hi; END_TRANSITION
TRANSITION T_Stop FROM Fill TO Idle := stop; END_TRANSITION
TRANSITION T_Mixed FROM (Mix, Heat) TO Done := NOT busy; END_TRANSITION
TRANSITION T_Ack FROM Done TO Idle := ack; END_TRANSITION
END_PROGRAM
)";
}

}  // namespace sfcv::test::simatic

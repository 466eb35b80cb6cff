#pragma once
// A TIA Portal SimaticML export of an S7-GRAPH function block written in the vendor's shape for
// tests (the layout of public exports such as huaruiwh/portal
// examples/motor-sequence-lad/graph/verify/MotorSequenceGRAPH_export.xml: Steps with action
// tables, Transitions with LAD networks ending in a TrCoil, Branches and Connections), never
// copied from one; and a demo chart with its IEC 61131-3 text twin.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sfcv::test::simatic {

/// Contacts of a LAD network: `branches` is a list of parallel branches, each a series of
/// contacts "tag", "!tag" (NC) or "#member"; the branches join in an O box. `end`/`end_pin`
/// are the part and pin whose power flow leaves them (the rail when there is none).
struct Contacts {
  std::string parts, wires;
  int uid = 21, wire = 500;
  int end = -1;  ///< -1: the power rail
  std::string end_pin = "out";
  void w(const std::string& body) {
    wires += "<Wire UId=\"" + std::to_string(wire++) + "\">" + body + "</Wire>\n";
  }
  int access(const std::string& operand) {
    const int a = uid++;
    if (operand[0] == '#')
      parts += "<Access Scope=\"LocalVariable\" UId=\"" + std::to_string(a) +
               "\"><Symbol><Component Name=\"" + operand.substr(1) + "\" /></Symbol></Access>\n";
    else if (operand.rfind("T#", 0) == 0)
      parts += "<Access Scope=\"LiteralConstant\" UId=\"" + std::to_string(a) +
               "\"><Constant><ConstantType>Time</ConstantType><ConstantValue>" + operand +
               "</ConstantValue></Constant></Access>\n";
    else
      parts += "<Access Scope=\"GlobalVariable\" UId=\"" + std::to_string(a) +
               "\"><Symbol><Component Name=\"" + operand + "\" /></Symbol></Access>\n";
    return a;
  }
  /// Wires the power flow reaching here into pin `pin` of part `to`.
  void feed(int to, const std::string& pin) {
    if (end < 0)
      w("<Powerrail /><NameCon UId=\"" + std::to_string(to) + "\" Name=\"" + pin + "\" />");
    else
      w("<NameCon UId=\"" + std::to_string(end) + "\" Name=\"" + end_pin + "\" /><NameCon UId=\"" +
        std::to_string(to) + "\" Name=\"" + pin + "\" />");
  }
  /// Wires operand `operand` into pin `pin` of part `to`.
  void operand(int to, const std::string& pin, const std::string& operand) {
    const int a = access(operand);
    w("<IdentCon UId=\"" + std::to_string(a) + "\" /><NameCon UId=\"" + std::to_string(to) +
      "\" Name=\"" + pin + "\" />");
  }
};

inline Contacts contacts(const std::vector<std::vector<std::string>>& branches) {
  Contacts n;
  std::vector<int> branch_ends, firsts;
  for (const auto& branch : branches) {
    int prev = -1;
    for (const auto& c : branch) {
      const bool nc = c[0] == '!';
      const std::string name = nc ? c.substr(1) : c;
      const int a = n.access(name), p = n.uid++;
      n.parts += "<Part Name=\"Contact\" UId=\"" + std::to_string(p) + "\"" +
                 (nc ? "><Negated Name=\"operand\" /></Part>\n" : " />\n");
      n.w("<IdentCon UId=\"" + std::to_string(a) + "\" /><NameCon UId=\"" + std::to_string(p) +
          "\" Name=\"operand\" />");
      if (prev < 0)
        firsts.push_back(p);
      else
        n.w("<NameCon UId=\"" + std::to_string(prev) + "\" Name=\"out\" /><NameCon UId=\"" +
            std::to_string(p) + "\" Name=\"in\" />");
      prev = p;
    }
    branch_ends.push_back(prev);
  }
  std::string rail = "<Powerrail />";
  for (int f : firsts) rail += "<NameCon UId=\"" + std::to_string(f) + "\" Name=\"in\" />";
  if (!firsts.empty()) n.w(rail);
  if (branch_ends.size() > 1) {
    const int o = n.uid++;
    n.parts += "<Part Name=\"O\" UId=\"" + std::to_string(o) +
               "\"><TemplateValue Name=\"Card\" Type=\"Cardinality\">" +
               std::to_string(branch_ends.size()) + "</TemplateValue></Part>\n";
    for (std::size_t i = 0; i < branch_ends.size(); ++i)
      n.w("<NameCon UId=\"" + std::to_string(branch_ends[i]) + "\" Name=\"out\" /><NameCon UId=\"" +
          std::to_string(o) + "\" Name=\"in" + std::to_string(i + 1) + "\" />");
    n.end = o;
  } else if (branch_ends.size() == 1) {
    n.end = branch_ends[0];
  }
  return n;
}

inline std::string flgnet(const Contacts& n) {
  return "<FlgNet xmlns=\"http://www.siemens.com/automation/Openness/SW/NetworkSource/FlgNet/"
         "v5\">\n<Parts>\n" +
         n.parts + "</Parts>\n<Wires>\n" + n.wires + "</Wires>\n</FlgNet>\n";
}

/// A LAD network (FlgNet) of a GRAPH condition: the contacts of `branches` (as contacts())
/// into `coil` (TrCoil, SvCoil, IlCoil), which has no operand.
inline std::string lad(const std::vector<std::vector<std::string>>& branches,
                       const std::string& coil = "TrCoil") {
  auto n = contacts(branches);
  const int coil_uid = n.uid++;
  n.feed(coil_uid, "in");
  n.parts += "<Part Name=\"" + coil + "\" UId=\"" + std::to_string(coil_uid) + "\" />\n";
  return flgnet(n);
}

/// A timer box on a rung: TON, TOF or TP on the static member `instance`, PT a constant.
struct TimerBox {
  std::string kind, instance, pt;
};

/// A network of a LAD block: the contacts of `branches`, then an optional timer box whose Q
/// goes on (its ET left open), then every coil of `coils` on that power flow: {"Coil", "y"},
/// {"SCoil", "y"}, {"RCoil", "y"}, {"!Coil", "y"} (negated), operands as contacts().
inline std::string rung(const std::vector<std::vector<std::string>>& branches,
                        const std::optional<TimerBox>& timer,
                        const std::vector<std::pair<std::string, std::string>>& coils) {
  auto n = contacts(branches);
  std::string timer_part;
  if (timer) {
    const int t = n.uid++, inst = n.uid++;
    n.feed(t, "IN");
    n.operand(t, "PT", timer->pt);
    timer_part = "<Part Name=\"" + timer->kind + "\" Version=\"1.0\" UId=\"" + std::to_string(t) +
                 "\"><Instance Scope=\"LocalVariable\" UId=\"" + std::to_string(inst) +
                 "\"><Component Name=\"" + timer->instance +
                 "\" /></Instance><TemplateValue Name=\"time_type\" Type=\"Type\">Time"
                 "</TemplateValue></Part>\n";
    n.w("<NameCon UId=\"" + std::to_string(t) + "\" Name=\"ET\" /><OpenCon UId=\"" +
        std::to_string(n.uid++) + "\" />");
    n.end = t;
    n.end_pin = "Q";
  }
  std::string coil_parts;
  std::vector<int> coil_uids;
  for (const auto& [kind, op] : coils) {
    const int c = n.uid++;
    coil_uids.push_back(c);
    const bool negated = kind[0] == '!';
    coil_parts += "<Part Name=\"" + (negated ? kind.substr(1) : kind) + "\" UId=\"" +
                  std::to_string(c) + "\"" +
                  (negated ? "><Negated Name=\"operand\" /></Part>\n" : " />\n");
    n.operand(c, "operand", op);
  }
  // One wire from the power flow into every coil, as TIA Portal writes a fan-out.
  std::string targets;
  for (int c : coil_uids) targets += "<NameCon UId=\"" + std::to_string(c) + "\" Name=\"in\" />";
  if (n.end < 0)
    n.w("<Powerrail />" + targets);
  else
    n.w("<NameCon UId=\"" + std::to_string(n.end) + "\" Name=\"" + n.end_pin + "\" />" + targets);
  n.parts += timer_part + coil_parts;
  return flgnet(n);
}

/// A LAD block (`kind` SW.Blocks.FB, FC or OB) with `statics` (Member elements) and one
/// compile unit per network.
inline std::string lad_block(const std::string& name, const std::string& statics,
                             const std::vector<std::string>& networks,
                             const std::string& kind = "SW.Blocks.FB") {
  std::string units;
  int id = 3;
  for (const auto& net : networks) {
    units += "<SW.Blocks.CompileUnit ID=\"" + std::to_string(id++) +
             "\" CompositionName=\"CompileUnits\">\n<AttributeList>\n<NetworkSource>" + net +
             "</NetworkSource>\n<ProgrammingLanguage>LAD</ProgrammingLanguage>\n"
             "</AttributeList>\n</SW.Blocks.CompileUnit>\n";
  }
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Document>\n<Engineering version=\"V20\" "
         "/>\n<" +
         kind +
         " ID=\"0\">\n<AttributeList>\n<Interface><Sections "
         "xmlns=\"http://www.siemens.com/automation/Openness/SW/Interface/v5\">\n"
         "<Section Name=\"Input\" />\n<Section Name=\"Output\" />\n<Section Name=\"InOut\" />\n"
         "<Section Name=\"Static\">\n" +
         statics +
         "</Section>\n<Section Name=\"Temp\" />\n<Section Name=\"Constant\" />\n"
         "</Sections></Interface>\n<MemoryLayout>Optimized</MemoryLayout>\n<Name>" +
         name +
         "</Name>\n<Number>1</Number>\n<ProgrammingLanguage>LAD</ProgrammingLanguage>\n"
         "</AttributeList>\n<ObjectList>\n" +
         units + "</ObjectList>\n</" + kind + ">\n</Document>\n";
}

/// A static TON_TIME member as TIA Portal writes it (its members in its own Sections).
inline std::string timer_member(const std::string& name, const std::string& type = "TON_TIME") {
  return "<Member Name=\"" + name + "\" Datatype=\"" + type +
         "\" Version=\"1.0\" Remanence=\"NonRetain\" Accessibility=\"Public\">"
         "<Sections><Section Name=\"None\"><Member Name=\"PT\" Datatype=\"Time\" />"
         "<Member Name=\"ET\" Datatype=\"Time\" /><Member Name=\"IN\" Datatype=\"Bool\" />"
         "<Member Name=\"Q\" Datatype=\"Bool\" /></Section></Sections></Member>\n";
}

/// The LAD demo (the shape of the motor sequence's LAD twin in huaruiwh/portal, never copied):
/// a start pulse from an edge kept by hand, a run latch set by the pulse and reset by stop
/// (reset last: stop wins), a second motor after a TON delay, the edge memory last.
inline std::string lad_demo() {
  return lad_block("Starter", timer_member("Delay"),
                   {rung({{"start", "!start_prev"}}, std::nullopt, {{"Coil", "pulse"}}),
                    rung({{"pulse", "!stop"}}, std::nullopt, {{"SCoil", "running"}}),
                    rung({{"stop"}}, std::nullopt, {{"RCoil", "running"}}),
                    rung({{"running"}}, TimerBox{"TON", "Delay", "T#5s"}, {{"Coil", "motor2"}}),
                    rung({{"start"}}, std::nullopt, {{"Coil", "start_prev"}})});
}

/// The LAD demo's IEC 61131-3 text twin, written from the networks (the PLC tags declared in
/// the order the networks first name them).
inline std::string lad_demo_twin() {
  return R"(PROGRAM Starter
VAR
  Delay : TON;
  start, start_prev, pulse, stop, running, motor2 : BOOL;
END_VAR
pulse := start AND NOT start_prev;
IF pulse AND NOT stop THEN running := TRUE; END_IF;
IF stop THEN running := FALSE; END_IF;
Delay(IN := running, PT := T#5s);
motor2 := Delay.Q;
start_prev := start;
END_PROGRAM
)";
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

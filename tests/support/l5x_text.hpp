#pragma once
// A Rockwell Studio 5000 .L5X export written in the vendor's shape for tests (the layout of
// public exports such as francisboudreau7/l5x_sfc tests/MainProgram.L5X: Step, Transition and
// Branch elements, then the DirectedLinks), never copied from one; and the demo chart with its
// IEC 61131-3 text twin.

#include <string>
#include <utility>
#include <vector>

namespace sfcv::test::rockwell {

inline std::string st(const std::vector<std::string>& lines) {
  std::string s = "<STContent>\n";
  for (std::size_t i = 0; i < lines.size(); ++i)
    s += "<Line Number=\"" + std::to_string(i) + "\">\n<![CDATA[" + lines[i] + "]]>\n</Line>\n";
  return s + "</STContent>\n";
}

inline std::string step(int id, const std::string& name, bool initial, int x = 200,
                        const std::string& actions = "") {
  return "<Step ID=\"" + std::to_string(id) + "\" X=\"" + std::to_string(x) +
         "\" Y=\"100\" Operand=\"" + name + "\" HideDesc=\"false\" InitialStep=\"" +
         (initial ? "true" : "false") + "\" PresetUsesExpr=\"false\" ShowActions=\"true\"" +
         (actions.empty() ? "/>\n" : ">\n" + actions + "</Step>\n");
}

inline std::string action(int id, const std::string& name, const std::vector<std::string>& body,
                          const std::string& qualifier = "NonStored") {
  return "<Action ID=\"" + std::to_string(id) + "\" Operand=\"" + name + "\" Qualifier=\"" +
         qualifier + "\" IsBoolean=\"false\" PresetUsesExpr=\"false\">\n<Body>\n" + st(body) +
         "</Body>\n</Action>\n";
}

inline std::string transition(int id, const std::string& name, const std::string& condition,
                              int x = 200) {
  return "<Transition ID=\"" + std::to_string(id) + "\" X=\"" + std::to_string(x) +
         "\" Y=\"300\" Operand=\"" + name + "\" HideDesc=\"false\">\n<Condition>\n" +
         st({condition}) + "</Condition>\n</Transition>\n";
}

inline std::string branch(int id, const char* type, const char* flow, int leg1, int leg2) {
  return "<Branch ID=\"" + std::to_string(id) + "\" Y=\"500\" BranchType=\"" + type +
         "\" BranchFlow=\"" + flow + "\">\n<Leg ID=\"" + std::to_string(leg1) + "\"/>\n<Leg ID=\"" +
         std::to_string(leg2) + "\"/>\n</Branch>\n";
}

inline std::string links(const std::vector<std::pair<int, int>>& ls) {
  std::string s;
  for (const auto& [from, to] : ls)
    s += "<DirectedLink FromID=\"" + std::to_string(from) + "\" ToID=\"" + std::to_string(to) +
         "\" Show=\"true\"/>\n";
  return s;
}

inline std::string alias(const std::string& name, const std::string& io) {
  return "<Tag Name=\"" + name + "\" TagType=\"Alias\" Radix=\"Decimal\" AliasFor=\"" + io +
         "\" ExternalAccess=\"Read/Write\"/>\n";
}

// A base tag of an elementary type with its value, in both of Studio 5000's data formats.
inline std::string base_tag(const std::string& name, const std::string& type, long value) {
  return "<Tag Name=\"" + name + "\" TagType=\"Base\" DataType=\"" + type +
         "\" Radix=\"Decimal\" Constant=\"false\">\n<Data Format=\"L5K\">\n<![CDATA[" +
         std::to_string(value) +
         "]]>\n</Data>\n<Data Format=\"Decorated\">\n<DataValue DataType=\"" + type +
         "\" Radix=\"Decimal\" Value=\"" + std::to_string(value) + "\"/>\n</Data>\n</Tag>\n";
}

inline std::string bool_tag(const std::string& name, int value) {
  return base_tag(name, "BOOL", value);
}

inline std::string sfc_tag(const std::string& name, const char* type) {
  return "<Tag Name=\"" + name + "\" TagType=\"Base\" DataType=\"" + type +
         "\" Constant=\"false\"/>\n";
}

/// An SFC_STEP tag with its timer preset PRE (ms), as Studio 5000 writes its decorated data.
inline std::string step_tag(const std::string& name, long preset_ms) {
  return "<Tag Name=\"" + name +
         "\" TagType=\"Base\" DataType=\"SFC_STEP\" Constant=\"false\">\n<Data "
         "Format=\"Decorated\">\n<Structure DataType=\"SFC_STEP\">\n<DataValueMember "
         "Name=\"X\" DataType=\"BOOL\" Value=\"0\"/>\n<DataValueMember Name=\"DN\" "
         "DataType=\"BOOL\" Value=\"0\"/>\n<DataValueMember Name=\"PRE\" DataType=\"DINT\" "
         "Radix=\"Decimal\" Value=\"" +
         std::to_string(preset_ms) + "\"/>\n</Structure>\n</Data>\n</Tag>\n";
}

inline std::string l5x(
    const std::string& tags, const std::string& sfc,
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

inline std::string demo_tags() {
  return alias("start", "Local:1:I.Data.0") + alias("stop", "Local:1:I.Data.1") +
         alias("a", "Local:1:I.Data.2") + alias("lamp", "Local:1:O.Data.0") +
         alias("valve", "Local:1:O.Data.1") + bool_tag("m", 0) + sfc_tag("Init", "SFC_STEP") +
         sfc_tag("A_Init", "SFC_ACTION");
}

// Init -> (selection) S1 | S2 -> Merge -> (simultaneous) P1 & P2 -> Init.
inline std::string demo_sfc() {
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

inline std::string demo_twin() {
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

// Ladder (RLL) routines, as Studio 5000 writes them: one <Rung> per line of neutral text.
inline std::string rung(int number, const std::string& text) {
  return "<Rung Number=\"" + std::to_string(number) + "\" Type=\"N\">\n<Text>\n<![CDATA[" + text +
         "]]>\n</Text>\n</Rung>\n";
}

inline std::string rll_routine(const std::string& name, const std::vector<std::string>& rungs) {
  std::string out = "<Routine Name=\"" + name + "\" Type=\"RLL\">\n<RLLContent>\n";
  for (std::size_t i = 0; i < rungs.size(); ++i) out += rung(static_cast<int>(i), rungs[i]);
  return out + "</RLLContent>\n</Routine>\n";
}

inline std::string dint_tag(const std::string& name, long value) {
  return base_tag(name, "DINT", value);
}

inline std::string timer_tag(const std::string& name, long preset_ms) {
  const auto pre = std::to_string(preset_ms);
  return "<Tag Name=\"" + name +
         "\" TagType=\"Base\" DataType=\"TIMER\" Constant=\"false\">\n<Data Format=\"L5K\">\n"
         "<![CDATA[[0," +
         pre +
         ",0]]]>\n</Data>\n<Data Format=\"Decorated\">\n<Structure DataType=\"TIMER\">\n"
         "<DataValueMember Name=\"PRE\" DataType=\"DINT\" Radix=\"Decimal\" Value=\"" +
         pre +
         "\"/>\n<DataValueMember Name=\"ACC\" DataType=\"DINT\" Radix=\"Decimal\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"EN\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"TT\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"DN\" DataType=\"BOOL\" Value=\"0\"/>\n</Structure>\n</Data>\n"
         "</Tag>\n";
}

inline std::string counter_tag(const std::string& name, long preset) {
  return "<Tag Name=\"" + name +
         "\" TagType=\"Base\" DataType=\"COUNTER\" Constant=\"false\">\n"
         "<Data Format=\"Decorated\">\n<Structure DataType=\"COUNTER\">\n"
         "<DataValueMember Name=\"PRE\" DataType=\"DINT\" Radix=\"Decimal\" Value=\"" +
         std::to_string(preset) +
         "\"/>\n<DataValueMember Name=\"ACC\" DataType=\"DINT\" Radix=\"Decimal\" "
         "Value=\"0\"/>\n<DataValueMember Name=\"CU\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"CD\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"DN\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"OV\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"UN\" DataType=\"BOOL\" Value=\"0\"/>\n</Structure>\n"
         "</Data>\n</Tag>\n";
}

/// A program whose main routine `Main` is ladder, with `routines` (<Routine> elements) beside it
/// (the shape of francisboudreau7/l5x_sfc tests/MainProgram.L5X: a main routine of JSRs).
/// With the controller's user data types (<DataType> elements) and tags beside the program.
inline std::string l5x_ladder(const std::string& tags, const std::string& routines,
                              const std::string& data_types, const std::string& controller_tags) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n"
         "<RSLogix5000Content SchemaRevision=\"1.0\" SoftwareRevision=\"32.01\" "
         "TargetName=\"Cell\" TargetType=\"Program\" ContainsContext=\"true\">\n"
         "<Controller Use=\"Context\" Name=\"Plant\" SFCExecutionControl=\"CurrentActive\" "
         "SFCRestartPosition=\"MostRecent\" SFCLastScan=\"DontScan\">\n"
         "<DataTypes Use=\"Context\">\n" +
         data_types + "</DataTypes>\n<Tags Use=\"Context\">\n" + controller_tags +
         "</Tags>\n<Programs Use=\"Context\">\n<Program Use=\"Target\" "
         "Name=\"Cell\" MainRoutineName=\"Main\" Disabled=\"false\" UseAsFolder=\"false\">\n"
         "<Tags>\n" +
         tags + "</Tags>\n<Routines>\n" + routines +
         "</Routines>\n</Program>\n</Programs>\n</Controller>\n</RSLogix5000Content>\n";
}

/// A user data type as Studio 5000 exports it (reh3376/acd-l5x-tool-lib's
/// Cooker_1_AutoLogic_Program.L5X has this shape: arrays of DINT bit words, TIMERs and REALs
/// in one structure, BOOL members as BITs of a hidden SINT).
inline std::string cell_data_type() {
  return "<DataType Name=\"Cell_Data\" Family=\"NoFamily\" Class=\"User\">\n<Members>\n"
         "<Member Name=\"BIT_Logic\" DataType=\"DINT\" Dimension=\"4\" Radix=\"Decimal\" "
         "Hidden=\"false\"/>\n"
         "<Member Name=\"TMR\" DataType=\"TIMER\" Dimension=\"5\" Radix=\"NullType\" "
         "Hidden=\"false\"/>\n"
         "<Member Name=\"SP\" DataType=\"DINT\" Dimension=\"3\" Radix=\"Decimal\" "
         "Hidden=\"false\"/>\n"
         "<Member Name=\"ZZZZZZZZZZCell_Data4\" DataType=\"SINT\" Dimension=\"0\" "
         "Radix=\"Decimal\" Hidden=\"true\"/>\n"
         "<Member Name=\"Flag\" DataType=\"BIT\" Dimension=\"0\" Radix=\"Decimal\" "
         "Hidden=\"false\" Target=\"ZZZZZZZZZZCell_Data4\" BitNumber=\"0\"/>\n"
         "<Member Name=\"Level\" DataType=\"REAL\" Dimension=\"0\" Radix=\"Float\" "
         "Hidden=\"false\"/>\n"
         "</Members>\n</DataType>\n";
}

/// A controller tag `name` of Cell_Data: BIT_Logic[1] = bits, SP[2] = sp, TMR[3].PRE = pre.
inline std::string cell_tag(const std::string& name, long bits, long sp, long pre) {
  auto timer = [](long p) {
    return "<Structure DataType=\"TIMER\">\n<DataValueMember Name=\"PRE\" DataType=\"DINT\" "
           "Radix=\"Decimal\" Value=\"" +
           std::to_string(p) +
           "\"/>\n<DataValueMember Name=\"ACC\" DataType=\"DINT\" Radix=\"Decimal\" "
           "Value=\"0\"/>\n<DataValueMember Name=\"DN\" DataType=\"BOOL\" Value=\"0\"/>\n"
           "</Structure>\n";
  };
  std::string out = "<Tag Name=\"" + name +
                    "\" Class=\"Standard\" TagType=\"Base\" DataType=\"Cell_Data\" "
                    "Constant=\"false\">\n<Data Format=\"Decorated\">\n"
                    "<Structure DataType=\"Cell_Data\">\n"
                    "<ArrayMember Name=\"BIT_Logic\" DataType=\"DINT\" Dimensions=\"4\" "
                    "Radix=\"Decimal\">\n";
  for (int i = 0; i < 4; ++i)
    out += "<Element Index=\"[" + std::to_string(i) + "]\" Value=\"" +
           std::to_string(i == 1 ? bits : 0) + "\"/>\n";
  out += "</ArrayMember>\n<ArrayMember Name=\"TMR\" DataType=\"TIMER\" Dimensions=\"5\">\n";
  for (int i = 0; i < 5; ++i)
    out += "<Element Index=\"[" + std::to_string(i) + "]\">\n" + timer(i == 3 ? pre : 0) +
           "</Element>\n";
  out +=
      "</ArrayMember>\n<ArrayMember Name=\"SP\" DataType=\"DINT\" Dimensions=\"3\" "
      "Radix=\"Decimal\">\n";
  for (int i = 0; i < 3; ++i)
    out += "<Element Index=\"[" + std::to_string(i) + "]\" Value=\"" +
           std::to_string(i == 2 ? sp : 0) + "\"/>\n";
  return out +
         "</ArrayMember>\n<DataValueMember Name=\"Flag\" DataType=\"BOOL\" Value=\"0\"/>\n"
         "<DataValueMember Name=\"Level\" DataType=\"REAL\" Radix=\"Float\" "
         "Value=\"0.0\"/>\n</Structure>\n</Data>\n</Tag>\n";
}

inline std::string l5x_ladder(const std::string& tags, const std::string& routines) {
  return l5x_ladder(tags, routines, "", "");
}

/// A two-step sequence written in ladder as the French school writes grafcets (step bits X.i
/// in a DINT, transition bits Y.i, a routine each for actions, steps and transitions, called
/// in that order; S:FS activates the initial step): X.0 -(start)-> X.1 -(T1.DN)-> X.0, with
/// `motor` on in X.1, T1 timing X.1, and `alarm` latched by `stop` in X.0.
inline std::string ladder_tags() {
  return alias("start", "Local:1:I.Data.0") + alias("stop", "Local:1:I.Data.1") +
         alias("motor", "Local:1:O.Data.0") + bool_tag("alarm", 0) + dint_tag("X", 0) +
         dint_tag("Y", 0) + timer_tag("T1", 1500);
}

inline std::string ladder_routines() {
  return rll_routine("Main", {"JSR(Actions,0);", "JSR(Steps,0);", "JSR(Transitions,0);"}) +
         rll_routine("Actions", {"XIC(X.1)OTE(motor);", "XIC(X.1)TON(T1,?,?);",
                                 "XIC(X.0)XIC(stop)OTL(alarm);"}) +
         rll_routine("Steps", {"[XIC(S:FS) ,XIC(Y.1) ,XIC(X.0) XIO(Y.0) ]OTE(X.0);",
                               "[XIC(Y.0) ,XIC(X.1) XIO(Y.1) ]OTE(X.1);"}) +
         rll_routine("Transitions", {"XIC(X.0)XIC(start)OTE(Y.0);", "XIC(X.1)XIC(T1.DN)OTE(Y.1);"});
}

}  // namespace sfcv::test::rockwell

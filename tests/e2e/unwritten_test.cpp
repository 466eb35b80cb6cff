// Variables that no POU of the run writes, end to end (issue 53, docs/semantics.md 1.8): free by
// default (a flaw reachable only through a sensor is found, its trace names the sensor), held
// with --unwritten keep, listed in one note, in `sfcv lint` (a warning each) and `sfcv info`.
// The PLCopen project is written here in the style of a CODESYS export of the pick-and-place
// unit: the sensors are plain VARs of Main (the export has no I/O mapping).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

std::string q(const std::string& s) {
  return "'" + s + "'";
}

std::string bool_vars(const std::string& section, const std::vector<std::string>& names,
                      const std::string& type = "<BOOL/>") {
  std::string s = "<" + section + ">";
  for (const auto& n : names)
    s += "<variable name=\"" + n + "\"><type>" + type + "</type></variable>";
  return s + "</" + section + ">";
}

std::string st(const std::string& text) {
  return "<ST><xhtml:p><![CDATA[" + text + "]]></xhtml:p></ST>";
}

std::string step(int id, const std::string& name, int from) {
  const std::string in = from < 0 ? "<connectionPointIn/>"
                                  : "<connectionPointIn><connection refLocalId=\"" +
                                        std::to_string(from) + "\"/></connectionPointIn>";
  return "<step localId=\"" + std::to_string(id) + "\" name=\"" + name + "\"" +
         (from < 0 ? " initialStep=\"true\"" : "") + ">" + in + "<connectionPointOut/></step>\n";
}

std::string transition(int id, int from, const std::string& guard) {
  return "<transition localId=\"" + std::to_string(id) + "\"><connectionPointIn><connection " +
         "refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn><connectionPointOut/><condition><inline name=\"\">" + st(guard) +
         "</inline></condition></transition>\n";
}

std::string action_block(int id, int step_id, const std::string& action) {
  return "<actionBlock localId=\"" + std::to_string(id) +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(step_id) +
         "\"/></connectionPointIn><action localId=\"" + std::to_string(id + 1) +
         "\" qualifier=\"N\"><reference name=\"" + action + "\"/></action></actionBlock>\n";
}

// The crane: Init -(NOT Up)-> Lowering -(Down)-> Turning -(Up)-> Init. Turning forgets to stop
// lowering (the flaw): the crane turns while lowered, which needs the sensor `Down`.
// Main calls it only while the emergency stop (normally closed) reads TRUE, as the PPU does.
std::string ppu_like() {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\" "
         "xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n"
         "<fileHeader companyName=\"t\" productName=\"CODESYS\" productVersion=\"3.5\" "
         "creationDateTime=\"2026-01-01T00:00:00\"/>\n<contentHeader name=\"ppu\"/>\n"
         "<types><dataTypes/><pous>\n"
         "<pou name=\"Crane\" pouType=\"functionBlock\">\n<interface>" +
         bool_vars("inputVars", {"Up", "Down"}) + bool_vars("outputVars", {"Lower", "Turn"}) +
         "</interface>\n<actions><action name=\"A_Rest\"><body>" +
         st("Lower := FALSE; Turn := FALSE;") + "</body></action><action name=\"A_Lower\"><body>" +
         st("Lower := TRUE; Turn := FALSE;") + "</body></action><action name=\"A_Turn\"><body>" +
         st("Turn := TRUE;") + "</body></action></actions>\n<body><SFC>\n" + step(1, "Init", -1) +
         transition(2, 1, "NOT Up") + step(3, "Lowering", 2) + transition(4, 3, "Down") +
         step(5, "Turning", 4) + transition(6, 5, "Up") +
         "<jumpStep localId=\"7\" targetName=\"Init\"><connectionPointIn><connection "
         "refLocalId=\"6\"/></connectionPointIn></jumpStep>\n" +
         action_block(10, 1, "A_Rest") + action_block(12, 3, "A_Lower") +
         action_block(14, 5, "A_Turn") + "</SFC></body>\n</pou>\n" +
         "<pou name=\"Main\" pouType=\"program\">\n<interface><localVars>"
         "<variable name=\"Sensor_EmergencyStop\"><type><BOOL/></type></variable>"
         "<variable name=\"Sensor_CraneUp\"><type><BOOL/></type></variable>"
         "<variable name=\"Sensor_CraneDown\"><type><BOOL/></type></variable>"
         "<variable name=\"Actuator_CraneLower\"><type><BOOL/></type></variable>"
         "<variable name=\"Actuator_CraneTurn\"><type><BOOL/></type></variable>"
         "<variable name=\"Crane\"><type><derived name=\"Crane\"/></type></variable>"
         "</localVars></interface>\n<body>" +
         st("IF Sensor_EmergencyStop THEN\n"
            "  Crane(Up := Sensor_CraneUp, Down := Sensor_CraneDown);\n"
            "  Actuator_CraneLower := Crane.Lower;\n"
            "  Actuator_CraneTurn := Crane.Turn;\n"
            "ELSE\n"
            "  Actuator_CraneLower := FALSE;\n"
            "  Actuator_CraneTurn := FALSE;\n"
            "END_IF;") +
         "</body>\n</pou>\n</pous></types>\n"
         "<instances><configurations/></instances>\n</project>\n";
}

const char* kInterlock = " --checks none --ctl 'AG !(Actuator_CraneLower & Actuator_CraneTurn)'";

TEST(Unwritten, FlawFoundOnlyThroughASensor) {
  const auto path = write_temp(ppu_like(), ".xml");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv("check " + q(path) + kInterlock + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("violated"), std::string::npos) << r.out;
    // The counterexample moves the sensors.
    EXPECT_NE(r.out.find("Sensor_CraneDown"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Sensor_EmergencyStop"), std::string::npos) << r.out;
  }
  // One note lists the sensors, where they are read, and the way back (in full: --verbose;
  // by default a note is cut to a line, issue 48).
  const auto r = run_sfcv("--verbose check " + q(path) + kInterlock);
  EXPECT_NE(r.err.find("note: 3 variables that no POU of the run writes are read as inputs "
                       "(free each cycle): Sensor_EmergencyStop (read in Main"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("Sensor_CraneUp (read in Main"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--unwritten keep holds them at their initial values"), std::string::npos)
      << r.err;
  // Reachability of the crane's steps, decided (before: Lowering "never active").
  const auto reach = run_sfcv("check " + q(path) + " --checks none --ctl 'EF Crane.Turning'");
  EXPECT_EQ(reach.exit_code, 0) << reach.out << reach.err;
}

TEST(Unwritten, KeepFreezesTheSensorsAsBefore) {
  const auto path = write_temp(ppu_like(), ".xml");
  // The old reading: the emergency stop reads FALSE for ever, the crane is never called, and
  // the interlock "holds" on a machine that cannot move.
  const auto r = run_sfcv("check " + q(path) + kInterlock + " --unwritten keep");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.err.find("3 variables that no POU of the run writes are held at their initial "
                       "values (--unwritten keep)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(run_sfcv("check " + q(path) + " --unwritten maybe --ctl TRUE").exit_code, 2);
  // --quiet drops the note, not the reading.
  const auto quiet = run_sfcv("check " + q(path) + kInterlock + " --quiet");
  EXPECT_EQ(quiet.exit_code, 1);
  EXPECT_EQ(quiet.err.find("no POU of the run writes"), std::string::npos) << quiet.err;
}

TEST(Unwritten, EverySubcommandThatBuildsTheSystemTakesTheOption) {
  const auto path = write_temp(ppu_like(), ".xml");
  for (const char* args : {"rsg", "query", "export --to nusmv"}) {
    SCOPED_TRACE(args);
    std::string cmd = std::string(args) + " " + q(path);
    if (std::string(args) == "query") cmd += " 'Y0'";
    auto r = run_sfcv(cmd);
    EXPECT_NE(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("are read as inputs (free each cycle)"), std::string::npos) << r.err;
    r = run_sfcv(cmd + " --unwritten keep");
    EXPECT_NE(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("(--unwritten keep)"), std::string::npos) << r.err;
  }
  // simulate: the sensors are columns of the input trace; kept, there are none to give.
  const auto csv = write_temp(
      "Sensor_EmergencyStop,Sensor_CraneUp,Sensor_CraneDown\n1,0,0\n1,0,0\n1,0,1\n", ".csv");
  auto r = run_sfcv("simulate " + q(path) + " --inputs " + q(csv));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("Crane.Turning"), std::string::npos) << r.out;
  const auto cycles = write_temp("cycle\n1\n2\n", ".csv");
  r = run_sfcv("simulate " + q(path) + " --unwritten keep --inputs " + q(cycles));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("Crane.Turning"), std::string::npos) << r.out;
}

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(Unwritten, LintWarnsOncePerVariableAndInfoListsThem) {
  const auto path = write_temp(ppu_like(), ".xml");
  const auto lint = run_sfcv("lint " + q(path));
  EXPECT_EQ(lint.exit_code, 0) << lint.out << lint.err;
  // One warning per unwritten variable (3). The file's CODESYS header makes CODESYS's dialect
  // the default, whose final calls of IEC actions are modelled: no warning about them
  // (docs/semantics.md 1.4a).
  EXPECT_NE(lint.out.find("0 errors, 3 warnings"), std::string::npos) << lint.out;
  EXPECT_EQ(count_of(lint.out, "warning: variable '"), 3u) << lint.out;
  EXPECT_EQ(lint.out.find("final call"), std::string::npos) << lint.out;
  EXPECT_NE(lint.out.find("warning: variable 'Sensor_CraneDown' is read (in Main, line "),
            std::string::npos)
      << lint.out;
  const auto info = run_sfcv("info --json " + q(path));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);
  ASSERT_TRUE(j.contains("unwritten"));
  ASSERT_EQ(j["unwritten"].size(), 3u);
  EXPECT_EQ(j["unwritten"][0]["name"], "Sensor_EmergencyStop");
  EXPECT_EQ(j["unwritten"][0]["type"], "BOOL");
  EXPECT_EQ(j["unwritten"][0]["read_in"], "Main");
  const auto text = run_sfcv("info " + q(path));
  EXPECT_NE(text.out.find("unwritten variables (read as inputs, free each cycle; --unwritten "
                          "keep holds them): 3"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("  Sensor_CraneDown : BOOL (read in Main"), std::string::npos)
      << text.out;
}

// Done when (issue 53): a PPU scenario checked with default options explores more than 2
// states, and its note lists the variables read as inputs.
TEST(UnwrittenCorpus, PpuMovesWithItsSensorsFree) {
  SFCV_REQUIRE_CORPUS(corpus);
  const std::string path = q((corpus / "07_codesys_ppu_scenario3v1.xml").string());
  const auto r = run_sfcv("check " + path +
                          " --checks none --ctl 'AG !Actuator_CraneLower' --trace none --timeout 60"
                          " --engine bmc");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // the crane lowers
  EXPECT_NE(r.err.find("variables that no POU of the run writes are read as inputs (free each "
                       "cycle): "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("Sensor_StartButtonMagazin (read in Main"), std::string::npos) << r.err;
  // Main copies each sensor into an instance: about 2 million successors of the initial state,
  // too many for the explicit engine in seconds; the BDD engine's rings go far past 2 states.
  const auto j = run_sfcv("check " + path +
                          " --checks none --ctl TRUE --json --timeout 15 --engine bdd --quiet");
  EXPECT_TRUE(j.exit_code == 0 || j.exit_code == 3) << j.out << j.err;
  EXPECT_GT(nlohmann::json::parse(j.out)["states"].get<std::uint64_t>(), 2u) << j.out;
}

}  // namespace
}  // namespace sfcv::test

// sfcv export: golden files for NuSMV and Cadence SMV, the DOT picture rendered by Graphviz,
// refusals with exit 2, and `check --engine nusmv` without a NuSMV.
// Regenerate the golden files with SFCV_UPDATE_GOLDEN=1 (then review the diff).

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/boolean_action_chart.hpp"
#include "support/hostile_names.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string quoted(const std::string& relative) {
  return "'" + source_path(relative) + "'";
}

// The export of `chart` with `args`, compared with tests/data/exports/<golden>.
void expect_golden(const std::string& chart, const std::string& args, const std::string& golden) {
  const auto r = run_sfcv("export " + chart + " " + args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto path = source_path("tests/data/exports/" + golden);
  if (const char* u = std::getenv("SFCV_UPDATE_GOLDEN"); u && *u) {
    std::ofstream(path, std::ios::binary) << r.out;
    return;
  }
  EXPECT_EQ(r.out, slurp(path)) << "golden file " << golden
                                << " differs (SFCV_UPDATE_GOLDEN=1 regenerates it)";
}

// The charts copied to a fixed temporary directory (the header comment names the model).
std::string staged(const std::string& name) {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / "sfcv-export-golden";
  fs::create_directories(dir);
  fs::copy_file(source_path("tests/data/exports/" + name), dir / name,
                fs::copy_options::overwrite_existing);
  return (dir / name).string();
}

class Golden : public ::testing::Test {
 protected:
  void SetUp() override {
    // The header names the model as given: run from its directory with a bare file name.
    namespace fs = std::filesystem;
    old_ = fs::current_path();
    fs::current_path(fs::path(staged("light.st")).parent_path());
    staged("mixer.st");
  }
  void TearDown() override { std::filesystem::current_path(old_); }
  std::filesystem::path old_;
};

TEST_F(Golden, LightNusmv) {
  expect_golden("light.st", "--to nusmv --ctl 'AG (lamp -> On)' --ctl 'AG EF Off'", "light.smv");
}
TEST_F(Golden, LightCadenceSmv) {
  expect_golden("light.st", "--to casmv --ctl 'AG (lamp -> On)' --ctl 'AG EF Off'",
                "light.casmv.smv");
}
TEST_F(Golden, MixerNusmv) {
  expect_golden("mixer.st",
                "--to nusmv --ctl 'AG !(VA & VB)' --ctl 'AG batches <= 3' --checks reachable "
                "--assume '!(full & empty)'",
                "mixer.smv");
}
TEST_F(Golden, MixerCadenceSmv) {
  expect_golden("mixer.st",
                "--to casmv --ctl 'AG !(VA & VB)' --ctl 'AG batches <= 3' --checks reachable "
                "--assume '!(full & empty)'",
                "mixer.casmv.smv");
}

TEST(Export, DotRendersWithGraphviz) {
  if (std::system("command -v dot >/dev/null 2>&1") != 0) GTEST_SKIP() << "graphviz not installed";
  const auto dot = write_temp("", ".dot");
  const auto r = run_sfcv("export " + quoted("examples/chemical_plant/chemical_plant.st") +
                          " --to dot -o '" + dot + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto svg = dot + ".svg";
  ASSERT_EQ(std::system(("dot -Tsvg '" + dot + "' -o '" + svg + "'").c_str()), 0) << slurp(dot);
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
  EXPECT_NE(slurp(svg).find("s12"), std::string::npos);  // a step of the chart is drawn
  std::filesystem::remove(dot);
  std::filesystem::remove(svg);
}

TEST(Export, IecTextAndPromelaAndAag) {
  const auto plant = quoted("examples/chemical_plant/chemical_plant.st");
  const auto iec = run_sfcv("export " + plant + " --to iec");
  ASSERT_EQ(iec.exit_code, 0) << iec.err;
  EXPECT_NE(iec.out.find("PROGRAM ChemicalPlant"), std::string::npos);
  const auto pml = run_sfcv("export " + plant + " --to promela --ctl 'AG !(V2 & V4)'");
  ASSERT_EQ(pml.exit_code, 0) << pml.err;
  EXPECT_NE(pml.out.find("active proctype cycle()"), std::string::npos);
  EXPECT_NE(pml.out.find("assert(!("), std::string::npos);
  const auto aag = run_sfcv("export " + plant + " --to aag --ctl 'AG !(V2 & V4)'");
  ASSERT_EQ(aag.exit_code, 0) << aag.err;
  EXPECT_EQ(aag.out.rfind("aag ", 0), 0u);
  EXPECT_EQ(aag.out.find("sfcv_valid"), std::string::npos);  // nothing to cut
  const auto cut = run_sfcv("export " + plant +
                            " --to aag --ctl 'AG !(V2 & V4)' --assume '!(LIS1plus & LIS1minus)'");
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  EXPECT_NE(cut.out.find("\nl27 sfcv_valid\n"), std::string::npos) << cut.out;
  EXPECT_NE(cut.out.find("l8 ChemicalPlant.s2: step ChemicalPlant.s2 ready"), std::string::npos);
  const auto aig = run_sfcv("export " + plant + " --to aiger --ctl 'AG !(V2 & V4)'");
  ASSERT_EQ(aig.exit_code, 0) << aig.err;
  EXPECT_EQ(aig.out.rfind("aig ", 0), 0u);
}

// A Boolean action of an instance and its variable are two latches of one name: the AIGER
// file `sfcv export` writes names them apart (its comment lines too), so ABC reads it and
// finds the violation sfcv finds. Before, ABC refused every xPPU export: "Repeated CI names".
TEST(Export, AigerOfABooleanActionAndItsVariableReadsInAbc) {
  const auto st = write_temp(kCylinderChart, ".st");
  const auto aag = run_sfcv("export '" + st + "' --to aag --checks none -q");
  ASSERT_EQ(aag.exit_code, 0) << aag.err;
  EXPECT_NE(aag.out.find("\nl1 Main.Lift.Extend\n"), std::string::npos) << aag.out;
  EXPECT_NE(aag.out.find("\nl4 Main.Lift.Extend#2\n"), std::string::npos) << aag.out;
  EXPECT_NE(aag.out.find("\nl4 Main.Lift.Extend#2: action Main.Lift.Extend active\n"),
            std::string::npos)
      << aag.out;
  if (std::system("command -v berkeley-abc >/dev/null 2>&1") != 0) {
    std::filesystem::remove(st);
    GTEST_SKIP() << "berkeley-abc not installed";
  }
  const auto aig = st + ".aig";
  ASSERT_EQ(run_sfcv("export '" + st + "' --to aiger --ctl 'AG !Lift.Extend' -q -o '" + aig + "'")
                .exit_code,
            0);
  std::string abc;
  if (FILE* p =
          ::popen(("berkeley-abc -c 'read_aiger " + aig + "; fold; pdr' 2>&1").c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) abc += buf;
    ::pclose(p);
  }
  std::filesystem::remove(st);
  std::filesystem::remove(aig);
  EXPECT_EQ(abc.find("Repeated"), std::string::npos) << abc;
  EXPECT_NE(abc.find("was asserted in frame"), std::string::npos) << abc;
}

TEST(Export, PlcopenXmlReadsBackToTheSameChart) {
  const auto plant = quoted("examples/chemical_plant/chemical_plant.st");
  const auto xml = run_sfcv("export " + plant + " --to plcopen");
  ASSERT_EQ(xml.exit_code, 0) << xml.err;
  EXPECT_NE(xml.out.find("xmlns=\"http://www.plcopen.org/xml/tc6_0201\""), std::string::npos);
  const auto file = sfcv::test::write_temp(xml.out, ".xml");
  // Printed as IEC text, the re-loaded XML is the chart printed directly.
  const auto direct = run_sfcv("export " + plant + " --to iec");
  const auto via_xml = run_sfcv("export '" + file + "' --to iec");
  ASSERT_EQ(via_xml.exit_code, 0) << via_xml.err;
  EXPECT_EQ(via_xml.out, direct.out);
  std::filesystem::remove(file);
  const auto grafcet =
      run_sfcv("export " + quoted("examples/pistons/pistons.g7") + " --to plcopen");
  EXPECT_EQ(grafcet.exit_code, 2);
  EXPECT_NE(grafcet.err.find("cannot write as PLCopen XML: a Grafcet (IEC 60848) project"),
            std::string::npos)
      << grafcet.err;
}

TEST(Export, RefusesWhatTheTargetCannotSay) {
  const auto plant = quoted("examples/chemical_plant/chemical_plant.st");
  const auto ctl = run_sfcv("export " + plant + " --to promela --ctl 'AG EF s9'");
  EXPECT_EQ(ctl.exit_code, 2);
  EXPECT_NE(ctl.err.find("only invariants"), std::string::npos) << ctl.err;
  const auto aiger = run_sfcv("export " + plant + " --to aiger --ctl 'AF s9'");
  EXPECT_EQ(aiger.exit_code, 2);
  const auto grafcet = run_sfcv("export " + quoted("examples/pistons/pistons.g7") + " --to nusmv");
  EXPECT_EQ(grafcet.exit_code, 2);
  EXPECT_NE(grafcet.err.find("not supported for Grafcet yet"), std::string::npos) << grafcet.err;
  const auto bad = run_sfcv("export " + plant + " --to lustre");
  EXPECT_EQ(bad.exit_code, 2);
  // The picture of a Grafcet is fine.
  EXPECT_EQ(run_sfcv("export " + quoted("examples/pistons/pistons.g7") + " --to g7").exit_code, 0);
}

// A PLCopen project whose unreferenced inputs, steps and local variables carry the hostile
// names (tests/support/hostile_names.hpp): PLCopen names are XML attributes, so any of them
// loads. Made by exporting an IEC chart to PLCopen and renaming u<k>, H<k> and v<k>.
std::string xml_attribute(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '"':
        r += "&quot;";
        break;
      case '\n':
        r += "&#10;";
        break;
      case '\r':
        r += "&#13;";
        break;
      default:
        r += c;
    }
  }
  return r;
}

std::string hostile_plcopen() {
  const auto& names = hostile_names();
  std::string inputs, locals, steps, transitions;
  std::string previous = "Start";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto k = std::to_string(i);
    if (i % 3 == 0) inputs += " u" + k + " : BOOL;";
    if (i % 3 == 2) locals += " v" + k + " : BOOL;";
    if (i % 3 == 1) {
      steps += "  STEP H" + k + ": END_STEP\n";
      transitions += "  TRANSITION FROM " + previous + " TO H" + k + " := go; END_TRANSITION\n";
      previous = "H" + k;
    }
  }
  const std::string chart = "PROGRAM P\n  VAR_INPUT go :BOOL;" + inputs + " END_VAR\n  VAR" +
                            locals + " END_VAR\n  INITIAL_STEP Start: END_STEP\n" + steps +
                            "  STEP Bad: END_STEP\n" + transitions + "  TRANSITION FROM " +
                            previous + " TO Bad := go; END_TRANSITION\nEND_PROGRAM\n";
  const auto st = write_temp(chart, ".st");
  auto xml = run_sfcv("export '" + st + "' --to plcopen");
  std::filesystem::remove(st);
  EXPECT_EQ(xml.exit_code, 0) << xml.err;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string plain = std::string(i % 3 == 0   ? "u"
                                          : i % 3 == 1 ? "H"
                                                       : "v") +
                              std::to_string(i);
    const auto at = xml.out.find("name=\"" + plain + "\"");
    EXPECT_NE(at, std::string::npos) << plain;
    if (at != std::string::npos)
      xml.out.replace(at, plain.size() + 7, "name=\"" + xml_attribute(names[i]) + "\"");
  }
  return write_temp(xml.out, ".xml");
}

// Every export and trace format of a chart with hostile names stays well-formed and keeps
// its meaning (issue 53: a name put a live INIT into the SMV export, a '"' added a DOT
// attribute, an input "x,y" gave a CSV trace that did not replay).
TEST(Export, HostileNamesKeepEveryFormatWellFormed) {
  const auto file = hostile_plcopen();
  const auto q = "'" + file + "'";
  ASSERT_EQ(run_sfcv("lint " + q).exit_code, 0);

  // The CSV trace quotes the names and replays to Bad.
  const auto csv = write_temp("", ".csv");
  const auto check = run_sfcv("check " + q + " --checks none --engine explicit --ctl 'AG !Bad' " +
                              "--trace csv --trace-file '" + csv + "'");
  ASSERT_EQ(check.exit_code, 1) << check.err;
  EXPECT_NE(slurp(csv).find("\"x,y\""), std::string::npos) << slurp(csv);
  const auto replay = run_sfcv("simulate " + q + " --inputs '" + csv + "'");
  ASSERT_EQ(replay.exit_code, 0) << replay.err << slurp(csv);
  EXPECT_NE(replay.out.find("P.Bad"), std::string::npos) << replay.out;

  // JSON (the trace file and the report) parses and keeps the names.
  const auto json_trace = write_temp("", ".json");
  run_sfcv("check " + q + " --checks none --engine explicit --ctl 'AG !Bad' --trace json " +
           "--trace-file '" + json_trace + "'");
  const auto trace = nlohmann::json::parse(slurp(json_trace));
  EXPECT_TRUE(trace["steps"][1]["inputs"].contains("x,y")) << trace.dump();
  const auto report = run_sfcv("check " + q + " --checks none --ctl 'AG !Bad' --json");
  EXPECT_TRUE(nlohmann::json::accept(report.out)) << report.out;
  const auto sarif = write_temp("", ".sarif"), junit = write_temp("", ".xml");
  EXPECT_EQ(run_sfcv("check " + q + " --checks none --ctl 'AG !Bad' --sarif '" + sarif +
                     "' --junit '" + junit + "'")
                .exit_code,
            1);
  EXPECT_TRUE(nlohmann::json::accept(slurp(sarif))) << slurp(sarif);
  if (std::system("command -v xmllint >/dev/null 2>&1") == 0) {
    EXPECT_EQ(std::system(("xmllint --noout '" + junit + "'").c_str()), 0) << slurp(junit);
  }

  // VCD: every declaration is `$var type width code reference $end`.
  const auto vcd =
      run_sfcv("check " + q + " --checks none --engine explicit --ctl 'AG !Bad' " + "--trace vcd");
  std::istringstream vcd_lines(vcd.out);
  std::size_t vars = 0;
  for (std::string line; std::getline(vcd_lines, line);) {
    if (line.rfind("$var ", 0) != 0) continue;
    ++vars;
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    ASSERT_EQ(w.size(), 6u) << line;
    EXPECT_EQ(w[5], "$end") << line;
  }
  EXPECT_GT(vars, hostile_names().size() / 3);

  // NuSMV: no line starts with what follows a line break in a name.
  const auto smv = run_sfcv("export " + q + " --to nusmv --ctl 'AG !Bad'");
  ASSERT_EQ(smv.exit_code, 0) << smv.err;
  std::istringstream smv_lines(smv.out);
  for (std::string line; std::getline(smv_lines, line);)
    for (const char* word : {"INIT", "VAR --", "#define", "l0 evil", "/* "})
      EXPECT_NE(line.rfind(word, 0), 0u) << line;

  // IEC text cannot say these names: refused, not written.
  const auto iec = run_sfcv("export " + q + " --to iec");
  EXPECT_EQ(iec.exit_code, 2);
  EXPECT_NE(iec.err.find("is not an IEC identifier"), std::string::npos) << iec.err;
  // PLCopen XML can: written back, it reads as the same chart.
  const auto xml = run_sfcv("export " + q + " --to plcopen");
  ASSERT_EQ(xml.exit_code, 0) << xml.err;
  const auto again = write_temp(xml.out, ".xml");
  const auto smv_again = run_sfcv("export '" + again + "' --to nusmv --ctl 'AG !Bad'");
  auto body = [](const std::string& text) { return text.substr(text.find("\nMODULE main")); };
  EXPECT_EQ(body(smv_again.out), body(smv.out));

  // DOT: the chart and both situation graphs render (a '"' in a name once added attributes).
  if (std::system("command -v dot >/dev/null 2>&1") == 0) {
    const auto dot = write_temp("", ".dot");
    ASSERT_EQ(run_sfcv("export " + q + " --to dot -o '" + dot + "'").exit_code, 0);
    const auto rsg = write_temp("", ".dot");
    const auto states = write_temp("", ".dot");
    ASSERT_EQ(run_sfcv("rsg " + q + " --dot '" + rsg + "' --dot-states '" + states + "'").exit_code,
              0);
    for (const auto& d : {dot, rsg, states}) {
      const auto svg = d + ".svg";
      EXPECT_EQ(std::system(("dot -Tsvg '" + d + "' -o '" + svg + "' 2>/dev/null").c_str()), 0)
          << slurp(d);
      EXPECT_EQ(slurp(svg).find("javascript:alert(1)\""), std::string::npos);
      EXPECT_EQ(slurp(svg).find("URL="), std::string::npos);
      std::filesystem::remove(d);
      std::filesystem::remove(svg);
    }
  } else {
    std::cerr << "[ NOTE ] graphviz not installed: the DOT files are not rendered\n";
  }
  for (const auto& f : {file, csv, json_trace, again, sarif, junit}) std::filesystem::remove(f);
}

// A loop that may run past sfcv's loop bound (issue 53): the circuit exports carry the latch
// sfcv_loop_limit where every property fails (docs/exports.md), the command says so on
// standard error, and an LTL property is refused with the loop named.
TEST(Export, ALoopThatMayMeetTheBoundIsFlaggedNotCut) {
  const auto file = write_temp(R"(
PROGRAM Loop
  VAR_INPUT go : BOOL; END_VAR
  VAR n : INT; bad : BOOL; END_VAR
  n := 0;
  WHILE go AND n < 2000 DO
    n := n + 1;
  END_WHILE;
  IF n >= 2000 THEN
    bad := TRUE;
  END_IF;
END_PROGRAM
)",
                               ".st");
  const auto q = "'" + file + "'";
  const auto smv = run_sfcv("export " + q + " --to nusmv --ctl 'AG !bad' --ctl 'AG EF !bad'");
  ASSERT_EQ(smv.exit_code, 0) << smv.err;
  EXPECT_NE(smv.err.find("sets the latch sfcv_loop_limit"), std::string::npos) << smv.err;
  EXPECT_NE(smv.out.find("INVARSPEC NAME p_no_loop_limit := !(s_sfcv_loop_limit);"),
            std::string::npos)
      << smv.out;
  EXPECT_NE(smv.out.find(":= (AG !o_sfcv_loop_limit) & (AG EF !o_bad);"), std::string::npos)
      << smv.out;
  const auto pml = run_sfcv("export " + q + " --to promela --ctl 'AG !bad'");
  ASSERT_EQ(pml.exit_code, 0) << pml.err;
  EXPECT_NE(pml.out.find("bit s_sfcv_loop_limit = 0;"), std::string::npos) << pml.out;
  const auto ltl = run_sfcv("export " + q + " --to promela --ltl 'G !bad'");
  EXPECT_EQ(ltl.exit_code, 2);
  EXPECT_NE(ltl.err.find("may run past the bound"), std::string::npos) << ltl.err;
  std::filesystem::remove(file);
}

TEST(CheckNusmv, SaysSoWhenNoNusmvIsFound) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", "/nonexistent-sfcv-test", 1);
  const auto r = run_sfcv("check " + quoted("examples/chemical_plant/chemical_plant.st") +
                          " --engine nusmv --ctl 'AG !(V1 & V3)'");
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no NuSMV found on PATH"), std::string::npos) << r.err;
}

// A stand-in NuSMV (the real one is not packaged in Debian) printing NuSMV 2.6's verdict lines:
// the verdicts must be mapped back to the properties in order, and NuSMV's exit code 0 ignored.
TEST(CheckNusmv, MapsVerdictLinesBackToTheProperties) {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / ("sfcv-fake-nusmv-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "NuSMV");
    f << "#!/bin/sh\n"
         "echo '*** This is NuSMV 2.6.0'\n"
         "echo '-- specification AG (EF ChemicalPlant_s9)  is true'\n"
         "echo '-- invariant !(g80)  is true'\n"
         "echo '-- invariant !(g93)  is false'\n"
         "echo '-- as demonstrated by the following execution sequence'\n"
         "exit 0\n";
  }
  fs::permissions(dir / "NuSMV", fs::perms::owner_all);
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", dir.c_str(), 1);
  const auto r = run_sfcv("check " + quoted("examples/chemical_plant/chemical_plant.st") +
                          " --engine nusmv --ctl 'AG !(V1 & V3)' --ctl 'AG !(V2 & V4)' "
                          "--ctl 'AG EF s9' --json");
  ::setenv("PATH", saved.c_str(), 1);
  fs::remove_all(dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto v13 = r.out.find("AG !(V1 & V3)"), v24 = r.out.find("AG !(V2 & V4)");
  ASSERT_NE(v13, std::string::npos) << r.out;
  ASSERT_NE(v24, std::string::npos) << r.out;
  // Each property's verdict follows its name in the JSON report.
  EXPECT_NE(r.out.substr(v13, v24 - v13).find("\"holds\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.substr(v24).find("\"violated\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"nusmv\""), std::string::npos) << r.out;
}

// A stand-in NuSMV in `dir` printing `script` (a shell script body); PATH points at it while
// `args` run.
RunResult run_with_fake_nusmv(const std::string& script, const std::string& args) {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / ("sfcv-fake-nusmv-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "NuSMV");
    f << "#!/bin/sh\n" << script;
  }
  fs::permissions(dir / "NuSMV", fs::perms::owner_all);
  {
    std::ofstream f(dir / "small.st");
    f << "PROGRAM Small\n  VAR_INPUT go : BOOL; stop : BOOL; END_VAR\n"
         "  INITIAL_STEP Idle: END_STEP\n  STEP Run: END_STEP\n"
         "  TRANSITION FROM Idle TO Run := go AND NOT stop; END_TRANSITION\n"
         "  TRANSITION FROM Run TO Idle := stop; END_TRANSITION\nEND_PROGRAM\n";
  }
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", dir.c_str(), 1);
  auto r = run_sfcv("check '" + (dir / "small.st").string() + "' " + args);
  ::setenv("PATH", saved.c_str(), 1);
  fs::remove_all(dir);
  return r;
}

// NuSMV's counterexample (values printed only when they change) replayed into sfcv's table.
TEST(CheckNusmv, MapsTheCounterexampleBackToTheTraceTable) {
  const auto r = run_with_fake_nusmv(
      "echo '-- invariant !(o_Small_Run)  is false'\n"
      "echo '-- as demonstrated by the following execution sequence'\n"
      "echo 'Trace Type: Counterexample '\n"
      "echo '  -> State: 1.1 <-'\n"
      "echo '    s_Small_Idle = TRUE'\n"
      "echo '  -> Input: 1.2 <-'\n"
      "echo '    in_go = FALSE'\n"
      "echo '    in_stop = FALSE'\n"
      "echo '  -> State: 1.2 <-'\n"
      "echo '  -> Input: 1.3 <-'\n"
      "echo '    in_go = TRUE'\n"
      "echo '  -> State: 1.3 <-'\n"
      "echo '    s_Small_Idle = FALSE'\n"
      "echo '    s_Small_Run = TRUE'\n",
      "--engine nusmv --checks none --ctl 'AG !Run' --json");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& p = j.at("properties").at(0);
  EXPECT_EQ(p.at("verdict"), "violated") << r.out;
  ASSERT_TRUE(p.contains("trace")) << r.out;
  const auto& steps = p.at("trace").at("steps");
  ASSERT_EQ(steps.size(), 3u) << r.out;
  EXPECT_NE(steps.at(2).dump().find("\"go\":true"), std::string::npos) << steps.dump();
  EXPECT_NE(steps.at(1).dump().find("\"go\":false"), std::string::npos) << steps.dump();
}

// A trace that does not replay (go never rises, so Run is never entered) is not shown as one.
TEST(CheckNusmv, SaysSoWhenItsTraceDoesNotReplay) {
  const auto r = run_with_fake_nusmv(
      "echo '-- invariant !(o_Small_Run)  is false'\n"
      "echo '  -> State: 1.1 <-'\n"
      "echo '  -> Input: 1.2 <-'\n"
      "echo '    in_go = FALSE'\n"
      "echo '  -> State: 1.2 <-'\n",
      "--engine nusmv --checks none --ctl 'AG !Run'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.out.find("counterexample ("), std::string::npos) << r.out;
}

// NuSMV's own error line, not the last 400 bytes of its output.
TEST(CheckNusmv, ReportsNusmvsErrorLine) {
  const auto r = run_with_fake_nusmv(
      "echo '*** This is NuSMV 2.6.0'\n"
      "echo 'file model.smv: line 40: multiple declaration of identifier: s_x'\nexit 1\n",
      "--engine nusmv --checks none --ctl 'AG !Run'");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.out.find("NuSMV gave no verdict for every property (exit code 1): file model.smv: "
                       "line 40: multiple declaration of identifier: s_x"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace sfcv::test

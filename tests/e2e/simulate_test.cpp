// End-to-end: sfcv simulate on the chemical plant example and on bad traces.

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::source_path;
using sfcv::test::write_temp;

const std::string kPlant = "'" + source_path("examples/chemical_plant/chemical_plant.st") + "'";

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string l;
  while (std::getline(ss, l)) out.push_back(l);
  return out;
}

TEST(Simulate, ChemicalPlantTraceOpensV2AndV4AtOnce) {
  const auto r = run_sfcv("simulate " + kPlant + " --inputs '" +
                          source_path("examples/chemical_plant/v2_v4_overlap.csv") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 7u) << r.out;  // header, initial, 5 cycles
  EXPECT_NE(rows[0].find("active steps"), std::string::npos);
  bool overlap = false;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const bool both =
        rows[i].find("V2=1") != std::string::npos && rows[i].find("V4=1") != std::string::npos;
    if (both) {
      overlap = true;
      EXPECT_EQ(rows[i].rfind("5 |", 0), 0u) << rows[i];
      EXPECT_NE(rows[i].find("ChemicalPlant.a3.s12"), std::string::npos);
      EXPECT_NE(rows[i].find("ChemicalPlant.s5"), std::string::npos);
    }
    EXPECT_FALSE(rows[i].find("V1=1") != std::string::npos &&
                 rows[i].find("V3=1") != std::string::npos);
  }
  EXPECT_TRUE(overlap) << r.out;
}

TEST(Simulate, WritesAVcdWaveform) {
  const auto vcd =
      std::filesystem::temp_directory_path() / ("sfcv-sim-" + std::to_string(::getpid()) + ".vcd");
  const auto r = run_sfcv("simulate " + kPlant + " --inputs '" +
                          source_path("examples/chemical_plant/v2_v4_overlap.csv") + "' --vcd '" +
                          vcd.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream f(vcd);
  std::stringstream ss;
  ss << f.rdbuf();
  const auto text = ss.str();
  std::filesystem::remove(vcd);
  for (const char* s : {"$timescale", "$scope module steps", "$scope module inputs",
                        "ChemicalPlant_a3_s12", " V4 $end", "$enddefinitions $end", "#50"})
    EXPECT_NE(text.find(s), std::string::npos) << s;
}

TEST(Simulate, MaxCyclesStopsEarly) {
  const auto r =
      run_sfcv("simulate " + kPlant + " --inputs '" +
               source_path("examples/chemical_plant/v2_v4_overlap.csv") + "' --max-cycles 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines(r.out).size(), 4u);
}

TEST(Simulate, UnknownColumnIsAnErrorWithItsPosition) {
  const auto csv = write_temp("start, LIS1plus, bogus\n1,0,0\n", ".csv");
  const auto r = run_sfcv("simulate " + kPlant + " --inputs '" + csv + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(csv + ":1:18: unknown input 'bogus'"), std::string::npos) << r.err;
}

TEST(Simulate, BadValueIsAnErrorWithItsPosition) {
  const auto csv = write_temp(
      "start,LIS1plus,LIS1minus,LIS2plus,LIS2minus,LIS3minus\n1,0,0,0,0,0\n0,0,maybe,0,0,0\n",
      ".csv");
  const auto r = run_sfcv("simulate " + kPlant + " --inputs '" + csv + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(csv + ":3:5: bad value 'maybe' for input 'LIS1minus'"), std::string::npos)
      << r.err;
}

TEST(Simulate, MissingInputColumnIsAnError) {
  const auto csv = write_temp("start\n1\n", ".csv");
  const auto r = run_sfcv("simulate " + kPlant + " --inputs '" + csv + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no column for input 'LIS1plus'"), std::string::npos) << r.err;
}

TEST(Simulate, AssumptionViolatedByTheTraceIsReported) {
  const auto r = run_sfcv("simulate " + kPlant + " --inputs '" +
                          source_path("examples/chemical_plant/v2_v4_overlap.csv") +
                          "' --assume 'NOT (LIS1minus AND LIS2minus)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cycle 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("assumption"), std::string::npos) << r.err;
}

TEST(Simulate, HelpDocumentsPseudoInputs) {
  const auto r = run_sfcv("simulate --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("timeout:"), std::string::npos);
  EXPECT_NE(r.out.find("choice:"), std::string::npos);
}

}  // namespace

namespace {

TEST(Simulate, ACycleColumnLetsAModelWithoutInputsRun) {
  const auto st = sfcv::test::write_temp(
      "PROGRAM Counter\n VAR_OUTPUT n : INT; END_VAR\n INITIAL_STEP S1: Inc(N); END_STEP\n"
      " ACTION Inc: n := n + 1; END_ACTION\nEND_PROGRAM\n",
      ".st");
  const auto csv = sfcv::test::write_temp("cycle\n1\n2\n3\n", ".csv");
  const auto r = sfcv::test::run_sfcv("simulate '" + st + "' --inputs '" + csv + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 | - | Counter.S1 | Counter.Inc | n=3"), std::string::npos) << r.out;
}

TEST(Simulate, RangeErrorStopsTheRun) {
  const auto st = sfcv::test::write_temp(
      "PROGRAM Counter\n VAR_OUTPUT n : INT(0..1); END_VAR\n INITIAL_STEP S1: Inc(N); END_STEP\n"
      " ACTION Inc: n := n + 1; END_ACTION\nEND_PROGRAM\n",
      ".st");
  const auto csv = sfcv::test::write_temp("cycle\n1\n2\n3\n", ".csv");
  const auto r = sfcv::test::run_sfcv("simulate '" + st + "' --inputs '" + csv + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cycle 2: value out of the range"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(":4:"), std::string::npos) << r.err;  // where the assignment is
}

}  // namespace

namespace {

const char* kTimed =
    "PROGRAM Lamp\n VAR_INPUT button : BOOL; END_VAR\n VAR_OUTPUT light : BOOL; END_VAR\n"
    " INITIAL_STEP Off: END_STEP\n STEP On: light(L, T#30ms); END_STEP\n"
    " TRANSITION FROM Off TO On := button; END_TRANSITION\n"
    " TRANSITION FROM On TO Off := NOT button; END_TRANSITION\nEND_PROGRAM\n";

TEST(Simulate, DiscreteTimeCountsCycles) {
  const auto st = sfcv::test::write_temp(kTimed, ".st");
  const auto csv = sfcv::test::write_temp("button\n1\n1\n1\n1\n", ".csv");
  const auto r = sfcv::test::run_sfcv("simulate '" + st + "' --inputs '" + csv +
                                      "' --time discrete --cycle 10ms");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_NE(rows[2].find("light=1"), std::string::npos) << r.out;
  EXPECT_NE(rows[4].find("light=1"), std::string::npos) << r.out;
  EXPECT_NE(rows[5].find("light=0"), std::string::npos) << r.out;
}

TEST(Simulate, AbstractTimeTakesTimeoutsFromThePseudoInputColumn) {
  const auto st = sfcv::test::write_temp(kTimed, ".st");
  const auto csv =
      sfcv::test::write_temp("button,timeout:Lamp.On.light.L\n1,0\n1,0\n1,1\n", ".csv");
  const auto r = sfcv::test::run_sfcv("simulate '" + st + "' --inputs '" + csv + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_NE(rows[3].find("light=1"), std::string::npos) << r.out;
  EXPECT_NE(rows[4].find("light=0"), std::string::npos) << r.out;
}

}  // namespace

// Grafcet (docs/semantics.md 2.15): the first row is the initial inputs, each later row one
// event; the table shows the stable situation after each.
namespace {

const char* kGrafcet =
    "project sim;\ninput a, b;\noutput y;\ngrafcet G {\n  step 1 initial;\n  step 2, 3, 4;\n"
    "  transition 1: 1 -> 2 when RE a;\n  transition 2: 2 -> 3 when b;\n"
    "  transition 3: 3 -> 4 when 2s/X3;\n  transition 4: 4 -> 1 when !a;\n  action 4: y;\n}\n";

TEST(Simulate, GrafcetRunsEventByEvent) {
  const auto g7 = sfcv::test::write_temp(kGrafcet, ".g7");
  // b rises first (nothing clears), then a rises: 1 -> 2 -> 3 in one event (transient 2);
  // a row that changes nothing keeps the situation; the delay elapses as an event of its own.
  const auto csv = sfcv::test::write_temp(
      "a,b,elapse(2000ms/X3/0ms)\n0,0,0\n0,1,0\n1,1,0\n1,1,0\n1,1,1\n0,1,0\n", ".csv");
  const auto r = sfcv::test::run_sfcv("simulate '" + g7 + "' --inputs '" + csv + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 7u) << r.out;
  EXPECT_EQ(rows[0].rfind("event |", 0), 0u) << r.out;
  EXPECT_NE(rows[1].find("0 | a=0 b=0 elapse(2000ms/X3/0ms)=0 | X1 | - | y=0"), std::string::npos)
      << r.out;
  EXPECT_NE(rows[2].find("| X1 |"), std::string::npos) << r.out;
  EXPECT_NE(rows[3].find("| X3 |"), std::string::npos) << r.out;
  EXPECT_NE(rows[4].find("| X3 |"), std::string::npos) << r.out;
  EXPECT_NE(rows[5].find("| X4 | - | y=1"), std::string::npos) << r.out;
  EXPECT_NE(rows[6].find("| X1 | - | y=0"), std::string::npos) << r.out;
}

TEST(Simulate, GrafcetRowChangingTwoInputsIsNotAnEvent) {
  const auto g7 = sfcv::test::write_temp(kGrafcet, ".g7");
  const auto csv = sfcv::test::write_temp("a,b\n0,0\n1,1\n", ".csv");
  auto r = sfcv::test::run_sfcv("simulate '" + g7 + "' --inputs '" + csv + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("row 2: inputs a and b change at once"), std::string::npos) << r.err;
  r = sfcv::test::run_sfcv("simulate '" + g7 + "' --inputs '" + csv + "' --multi-input-change");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 | a=1 b=1 | X3 |"), std::string::npos) << r.out;
}

TEST(Simulate, GrafcetInstabilityStopsTheRun) {
  const auto g7 = sfcv::test::write_temp(
      "project u;\ninput a;\ngrafcet G {\n  step 1 initial;\n  step 2;\n"
      "  transition 1: 1 -> 2 when a;\n  transition 2: 2 -> 1 when a;\n}\n",
      ".g7");
  const auto csv = sfcv::test::write_temp("a\n0\n1\n", ".csv");
  const auto r = sfcv::test::run_sfcv("simulate '" + g7 + "' --inputs '" + csv + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("row 2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("instab"), std::string::npos) << r.err;
}

// A counterexample of `sfcv check` replays in `sfcv simulate`, in both trace formats, and
// ends where the property fails.
TEST(Simulate, GrafcetCounterexampleReplays) {
  const auto g7 = sfcv::test::write_temp(kGrafcet, ".g7");
  for (const std::string format : {"csv", "json"}) {
    const auto trace = sfcv::test::write_temp("", "." + format);
    auto r = sfcv::test::run_sfcv("check '" + g7 + "' --ctl 'AG !y' --trace " + format +
                                  " --trace-file '" + trace + "'");
    ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
    r = sfcv::test::run_sfcv("simulate '" + g7 + "' --inputs '" + trace + "'");
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.out << r.err;
    const auto rows = lines(r.out);
    ASSERT_GE(rows.size(), 3u) << r.out;
    EXPECT_NE(rows.back().find("| X4 | - | y=1"), std::string::npos) << format << ": " << r.out;
    for (std::size_t i = 1; i + 1 < rows.size(); ++i)
      EXPECT_NE(rows[i].find("y=0"), std::string::npos) << format << ": " << r.out;
  }
}

// The IEC side replays its JSON counterexamples too (step 0 is the initial state).
TEST(Simulate, IecJsonCounterexampleReplays) {
  const auto trace = sfcv::test::write_temp("", ".json");
  auto r = run_sfcv("check " + kPlant + " --ctl 'AG !(V2 & V4)' --trace json --trace-file '" +
                    trace + "'");
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  r = run_sfcv("simulate " + kPlant + " --inputs '" + trace + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto rows = lines(r.out);
  ASSERT_GE(rows.size(), 2u);
  EXPECT_NE(rows.back().find("V2=1"), std::string::npos) << r.out;
  EXPECT_NE(rows.back().find("V4=1"), std::string::npos) << r.out;
}

// docs/semantics.md 2.15: a Grafcet trace's first row is an initial valuation the start
// stabilises under, and under the single-input-change hypothesis each later row changes one
// input. Here X3 needs a true at the start (1 -> 2 at once) and then a rise of b: every engine
// writes the rows a,b = 1,0 then 1,1, which replay. The BDD engine used to write 0,0 (the
// start then stays in X1) then 1,1 (two inputs changing in one row): issue 53 item 9.
TEST(Simulate, GrafcetTraceStartsFromItsInitialInputsAndChangesOneInputPerRow) {
  const auto g7 = sfcv::test::write_temp(
      "project ab;\ninput a;\ninput b;\ngrafcet G {\n  step 1 initial;\n  step 2, 3;\n"
      "  transition 1: 1 -> 2 when a;\n  transition 2: 2 -> 3 when RE b;\n}\n",
      ".g7");
  for (const std::string engine : {"explicit", "bdd", "bmc", "ic3"}) {
    const auto trace = sfcv::test::write_temp("", ".csv");
    auto r = run_sfcv("check '" + g7 + "' --engine " + engine +
                      " --checks none --ctl 'AG !X3' --trace csv --trace-file '" + trace + "'");
    ASSERT_EQ(r.exit_code, 1) << engine << ": " << r.out << r.err;
    std::ifstream f(trace);
    std::stringstream text;
    text << f.rdbuf();
    auto rows = lines(text.str());
    ASSERT_EQ(rows.size(), 4u) << engine << ": " << text.str();  // comment, header, two rows
    EXPECT_EQ(rows[1], "a,b") << engine;
    EXPECT_EQ(rows[2], "1,0") << engine;
    EXPECT_EQ(rows[3], "1,1") << engine;
    r = run_sfcv("simulate '" + g7 + "' --inputs '" + trace + "'");
    ASSERT_EQ(r.exit_code, 0) << engine << ": " << r.out << r.err;
    rows = lines(r.out);
    ASSERT_EQ(rows.size(), 3u) << r.out;
    EXPECT_NE(rows[1].find("| X2 |"), std::string::npos) << engine << ": " << r.out;
    EXPECT_NE(rows[2].find("| X3 |"), std::string::npos) << engine << ": " << r.out;
  }
}

}  // namespace

// RFC 4180 fields (what `check --trace csv` writes for names that need them): quoted names
// holding the separator, a doubled quote and a leading '#' (not a comment once quoted), with
// ',' or ';' between fields; an unclosed quote is an error with its line.
TEST(Simulate, ReadsQuotedCsvFields) {
  const auto g7 = write_temp(
      "project q;\ninput \"x,y\";\ninput \"a\\\"b\";\ninput \"#c\";\n"
      "grafcet G {\n  step 1 initial;\n  step 2;\n"
      "  transition t1: 1 -> 2 when \"x,y\" & \"a\\\"b\" & \"#c\";\n}\n",
      ".g7");
  for (const char* text : {"\"x,y\",\"a\"\"b\" , \"#c\"\n0,0,0\n1,1,1\n",
                           "\"#c\";\"x,y\";\"a\"\"b\"\n0;0;0\n1;1;1\n"}) {
    const auto csv = write_temp(text, ".csv");
    const auto r = run_sfcv("simulate '" + g7 + "' --multi-input-change --inputs '" + csv + "'");
    ASSERT_EQ(r.exit_code, 0) << text << r.err;
    EXPECT_NE(lines(r.out).back().find("X2"), std::string::npos) << r.out;
    std::filesystem::remove(csv);
  }
  const auto open = write_temp("\"x,y\",\"a\"\"b\",\"#c\n0,0,0\n", ".csv");
  const auto r = run_sfcv("simulate '" + g7 + "' --inputs '" + open + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(":1:1: a quoted field is not closed"), std::string::npos) << r.err;
  std::filesystem::remove(open);
  std::filesystem::remove(g7);
}

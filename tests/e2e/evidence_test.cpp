// Reports an engineer can file as evidence (issue 48): the provenance block of every report
// (text, JSON, JUnit, SARIF, HTML), JSON errors under --json, and where traces go (one file per
// property, or one alone on standard output; a lasso's loop point kept).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "report/sha256.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

namespace fs = std::filesystem;

const std::string kPlant = source_path("examples/chemical_plant/chemical_plant.st");

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string plant_sha256() {
  return report::sha256_hex(slurp(kPlant));
}

/// A fresh, empty directory, removed at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    static int n = 0;
    path = fs::temp_directory_path() /
           ("sfcv-evidence-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(Evidence, TextReportEndsWithItsProvenance) {
  const auto r = run_sfcv("check " + kPlant + " --quiet --ctl 'AG !(V2 & V4)' --engine bdd");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(std::regex_search(
      r.out, std::regex("\n# sfcv [0-9.]+ \\(commit [^,]+, buddy [^,]+, cadical [^\n]+\\), "
                        "[0-9-]+T[0-9:]+Z\n")))
      << r.out;
  EXPECT_NE(r.out.find("\n# command: "), std::string::npos);
  EXPECT_NE(r.out.find(" check " + kPlant + " --quiet --ctl 'AG !(V2 & V4)' --engine bdd\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n# input: " + kPlant + " sha256:" + plant_sha256() + "\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n# engine: bdd; settings: semantics=iec61131 "), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(" reorder=dynamic "), std::string::npos) << r.out;
}

TEST(Evidence, JsonCarriesSchemaVersionIdsAndProvenance) {
  const auto spec = source_path("examples/chemical_plant/requirements.spec");
  const auto r = run_sfcv("check " + kPlant + " --quiet --json --spec " + spec +
                          " --timeout 60 --max-states 100000");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema_version"], "1.0");
  const auto& p = j["provenance"];
  EXPECT_EQ(p["tool"], "sfcv");
  ASSERT_EQ(p["inputs"].size(), 2u);  // the model and the spec file
  EXPECT_EQ(p["inputs"][0]["path"], kPlant);
  EXPECT_EQ(p["inputs"][0]["sha256"], plant_sha256());
  EXPECT_EQ(p["inputs"][1]["sha256"], report::sha256_hex(slurp(spec)));
  EXPECT_EQ(p["engine"], "auto");
  EXPECT_EQ(p["settings"]["timeout"], "60");
  EXPECT_EQ(p["settings"]["max_states"], "100000");
  EXPECT_EQ(p["command_line"].back(), "100000");
  EXPECT_TRUE(std::regex_match(p["date"].get<std::string>(),
                               std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:]{8}Z")));
  // Each result names the engine that decided it, and has a stable id.
  for (const auto& prop : j["properties"]) {
    EXPECT_TRUE(prop["decided_by"].is_string()) << prop;
    EXPECT_EQ(prop["id"], "property/" + prop["name"].get<std::string>()) << prop;
  }
}

TEST(Evidence, JunitSarifAndHtmlCarryTheProvenance) {
  TempDir dir;
  const auto r = run_sfcv("check " + kPlant + " --quiet --ctl 'AG !(V2 & V4)' --junit " +
                          (dir / "j.xml") + " --sarif " + (dir / "s.sarif") + " --html " +
                          (dir / "r.html") + " --sarif-root " + SFCV_SOURCE_DIR);
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto junit = slurp(dir / "j.xml");
  EXPECT_NE(junit.find("<property name=\"sfcv.input." + kPlant +
                       "\" value=\"sha256:" + plant_sha256() + "\""),
            std::string::npos)
      << junit;
  EXPECT_NE(junit.find("<property name=\"sfcv.commit\""), std::string::npos);
  EXPECT_NE(junit.find("<property name=\"sfcv.setting.semantics\" value=\"iec61131\""),
            std::string::npos);
  const auto sarif = nlohmann::json::parse(slurp(dir / "s.sarif"));
  const auto& run = sarif["runs"][0];
  EXPECT_EQ(run["artifacts"][0]["hashes"]["sha-256"], plant_sha256());
  EXPECT_EQ(run["artifacts"][0]["location"]["uri"], "examples/chemical_plant/chemical_plant.st");
  EXPECT_EQ(run["invocations"][0]["exitCode"], 1);
  EXPECT_FALSE(run["tool"]["driver"]["version"].get<std::string>().empty());
  const auto html = slurp(dir / "r.html");
  EXPECT_NE(html.find(plant_sha256()), std::string::npos);
  EXPECT_NE(html.find("class=\"provenance\""), std::string::npos);
}

// `sfcv report` renders the saved result's provenance, and refuses a result of another major
// schema version rather than half reading it.
TEST(Evidence, ReportKeepsTheSavedProvenanceAndChecksTheSchemaVersion) {
  TempDir dir;
  auto r = run_sfcv("check " + kPlant + " --quiet --ctl 'AG !(V1 & V3)' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ofstream(dir / "r.json") << r.out;
  r = run_sfcv("report " + (dir / "r.json") + " --html " + (dir / "r.html"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto html = slurp(dir / "r.html");
  EXPECT_NE(html.find("class=\"provenance\""), std::string::npos);
  EXPECT_NE(html.find("--ctl 'AG !(V1 &amp; V3)' --json"), std::string::npos)
      << html.substr(0, 3000);
  std::ofstream(dir / "v2.json") << R"({"schema_version": "2.0", "model": ")" << kPlant
                                 << R"(", "properties": []})";
  r = run_sfcv("report " + (dir / "v2.json") + " --html " + (dir / "v2.html"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("schema_version \"2.0\" is not one this sfcv reads"), std::string::npos)
      << r.err;
}

TEST(Evidence, ErrorsUnderJsonAreJsonObjectsWithTheSameExitCode) {
  auto r = run_sfcv("check /nonexistent/chart.st --json");
  EXPECT_EQ(r.exit_code, 2);
  auto j = nlohmann::json::parse(r.out);  // standard output is one JSON document
  EXPECT_EQ(j["error"]["kind"], "input");
  EXPECT_EQ(j["exit_code"], 2);
  EXPECT_NE(r.err.find("sfcv: error:"), std::string::npos);  // the text is still there
  r = run_sfcv("check " + kPlant + " --json --no-such-option");
  EXPECT_EQ(r.exit_code, 2);
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["kind"], "usage");
  r = run_sfcv("check " + kPlant + " --json --max-states 3 --ctl 'AG !(V1 & V3)'");
  EXPECT_EQ(r.exit_code, 3);  // a verdict (unknown), not an error: the result document
  j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("error"));
  r = run_sfcv("check /nonexistent/chart.st");
  EXPECT_EQ(r.out, "");  // without --json nothing on standard output
}

// `--trace vcd > t.vcd` gives a VCD file: nothing before it, nothing after; the report goes to
// standard error.
TEST(Evidence, OneVcdAloneOnStandardOutput) {
  const auto r = run_sfcv("check " + kPlant + " --quiet --ctl 'AG !(V2 & V4)' --trace vcd");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out.rfind("$comment sfcv trace", 0), 0u) << r.out;
  EXPECT_EQ(count(r.out, "$enddefinitions"), 1u);
  EXPECT_EQ(r.out.find("violated"), std::string::npos);
  EXPECT_NE(r.err.find("violated"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("counterexample (6 situations): standard output"), std::string::npos)
      << r.err;
}

// Several traces are never concatenated into one invalid file: without --trace-dir nothing is
// written to standard output, the verdicts are still shown, and the exit code says the output
// asked for could not be made.
TEST(Evidence, SeveralTracesOnStandardOutputAskForATraceDirectory) {
  const auto r = run_sfcv("check " + kPlant +
                          " --quiet --checks local-deadlock --ctl 'AG !(V2 & V4)' --trace vcd");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("2 traces, and standard output holds one: give --trace-dir DIR"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("violated"), std::string::npos) << r.err;
  const auto j = run_sfcv("check " + kPlant + " --json --ctl 'AG !(V2 & V4)' --trace vcd");
  EXPECT_EQ(j.exit_code, 2);  // --json holds standard output: said before the run
  EXPECT_EQ(nlohmann::json::parse(j.out)["error"]["kind"], "usage");
}

TEST(Evidence, TraceDirectoryHoldsOneFilePerPropertyNamedByItsId) {
  TempDir dir;
  const auto traces = dir / "traces";  // created by sfcv
  const auto r = run_sfcv("check " + kPlant +
                          " --quiet --checks local-deadlock --ctl 'AG !(V2 & V4)' --trace vcd "
                          "--trace-dir " +
                          traces + " --json");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::size_t files = 0;
  for (const auto& p : j["properties"]) {
    if (p["trace"].is_null()) continue;
    auto stem = p["id"].get<std::string>();
    std::replace(stem.begin(), stem.end(), '/', '-');
    const auto vcd = slurp(traces + "/" + stem + ".vcd");
    EXPECT_EQ(vcd.rfind("$comment sfcv trace", 0), 0u) << stem;
    EXPECT_EQ(count(vcd, "$enddefinitions"), 1u) << stem;
    // One timestamp per situation and the end.
    EXPECT_EQ(count(vcd, "\n#"), p["trace"]["steps"].size() + 1) << stem;
    ++files;
  }
  EXPECT_EQ(files, 2u);
  EXPECT_TRUE(fs::exists(traces + "/check-local-deadlock.vcd"));
  std::size_t on_disk = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(traces)) ++on_disk;
  EXPECT_EQ(on_disk, 2u);
}

TEST(Evidence, TraceFileWithSeveralTracesWritesOneBesideItPerProperty) {
  TempDir dir;
  const auto r = run_sfcv("check " + kPlant +
                          " --checks local-deadlock --ctl 'AG !(V2 & V4)' --trace csv "
                          "--trace-file " +
                          (dir / "t.csv"));
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(fs::exists(dir / "t.check-local-deadlock.csv"));
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) {
    const auto name = e.path().filename().string();
    EXPECT_TRUE(std::regex_match(
        name, std::regex("t\\.(check-local-deadlock|property-ctl-[0-9a-f]{12})\\.csv")))
        << name;
    EXPECT_NE(r.out.find(e.path().string()), std::string::npos) << r.out;  // the text names it
    ++files;
  }
  EXPECT_EQ(files, 2u);
  // One trace: the file itself.
  const auto one = run_sfcv("check " + kPlant + " --quiet --ctl 'AG !(V2 & V4)' --trace vcd " +
                            "--trace-file " + (dir / "one.vcd"));
  ASSERT_EQ(one.exit_code, 1);
  EXPECT_EQ(slurp(dir / "one.vcd").rfind("$comment sfcv trace", 0), 0u);
}

// Issue 48 saw two VCDs concatenated in the text on corpus 01: now one file per property.
TEST(Evidence, Corpus01TracesAreOneVcdFileEach) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto model = (corpus / "01_beremiz_traffic_light.xml").string();
  auto r = run_sfcv("check '" + model + "' --quiet --trace vcd --timeout 60");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.out, "");
  TempDir dir;
  r = run_sfcv("check '" + model + "' --quiet --trace vcd --timeout 60 --trace-dir " + (dir / "t"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir / "t")) {
    const auto vcd = slurp(e.path().string());
    EXPECT_EQ(vcd.rfind("$comment sfcv trace", 0), 0u) << e.path();
    EXPECT_EQ(count(vcd, "$enddefinitions"), 1u) << e.path();
    ++files;
  }
  EXPECT_EQ(files, 2u);
}

// An LTL counterexample is a lasso: its loop point survives in the VCD file.
TEST(Evidence, VcdFileKeepsALassosLoopPoint) {
  TempDir dir;
  const auto r = run_sfcv("check " + kPlant + " --quiet --ltl 'G F s9' --trace vcd --trace-file " +
                          (dir / "lasso.vcd"));
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto vcd = slurp(dir / "lasso.vcd");
  EXPECT_NE(vcd.find("$comment loop: the last step is step 2 again"), std::string::npos) << vcd;
  EXPECT_NE(vcd.find(" in_loop $end"), std::string::npos) << vcd;
}

}  // namespace
}  // namespace sfcv::test

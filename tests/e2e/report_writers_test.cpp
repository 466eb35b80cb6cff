// Every report writer of sfcv check (text, --json, --junit, --sarif, --html, and sfcv report on
// the JSON) on every engine, for each verdict: holds, violated, unknown, not checked and n/a
// (issue 53: the HTML report stopped with exit 4 when a SAT engine or --engine auto's race
// decided, "not checked" exited 0, and names with invalid UTF-8 broke JSON and XML). Each run:
// the exit code, every output parses, and no verdict is lost (each property and check is in each
// output with its verdict).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "chart_families.hpp"
#include "report/text_encoding.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

namespace fs = std::filesystem;

// A three-step loop: s0 -> s1 -> s2 -> s0 on `go`, y while s1 is active. AG !(s0 & s1) holds but
// is not 0-inductive (k-induction at --depth 0: unknown).
const std::string kIec =
    "PROGRAM p\nVAR_INPUT go : BOOL; END_VAR\nVAR y : BOOL; END_VAR\n"
    "INITIAL_STEP s0 : END_STEP\nSTEP s1 : a1(N); END_STEP\nSTEP s2 : END_STEP\n"
    "TRANSITION FROM s0 TO s1 := go; END_TRANSITION\n"
    "TRANSITION FROM s1 TO s2 := go; END_TRANSITION\n"
    "TRANSITION FROM s2 TO s0 := go; END_TRANSITION\n"
    "ACTION a1 : y := TRUE; END_ACTION\nEND_PROGRAM\n";
// Two steps, y emitted at step 2; every standard check holds.
const std::string kGrafcet =
    "project g;\ninput a, b;\noutput y;\ngrafcet main {\n  step 1 initial;\n  step 2;\n"
    "  transition 1: 1 -> 2 when a;\n  transition 2: 2 -> 1 when b & !a;\n  action 2: y;\n}\n";
// Both transitions always clearable: no initial situation is ever stable, so no property can be
// judged (unknown on every engine, never a vacuous "holds").
const std::string kUnstable =
    "project u;\ninput a;\noutput y;\ngrafcet main {\n  step 1 initial;\n  step 2;\n"
    "  transition 1: 1 -> 2 when 1;\n  transition 2: 2 -> 1 when 1;\n  action 2: y;\n}\n";

const std::vector<std::string> kEngines = {"explicit", "bdd", "bmc", "kind", "ic3", "auto"};

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string html_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// Every character is one XML 1.0 allows, in valid UTF-8, and pugixml parses the document.
void expect_well_formed_xml(const std::string& xml, pugi::xml_document& doc) {
  EXPECT_TRUE(report::is_valid_utf8(xml));
  EXPECT_EQ(report::xml_text(xml), xml) << "a character XML 1.0 excludes";
  const auto parsed = doc.load_string(xml.c_str());
  EXPECT_TRUE(parsed) << parsed.description() << "\n" << xml;
}

// The verdict on the text report's line of `name` (the name padded to a column, the verdict in
// 11 characters).
std::string text_verdict(const std::string& out, const std::string& name) {
  for (std::size_t at = 0; at < out.size();) {
    const auto end = std::min(out.find('\n', at), out.size());
    const auto line = out.substr(at, end - at);
    at = end + 1;
    if (!line.starts_with(name + " ")) continue;
    auto rest = line.substr(line.find_first_not_of(' ', name.size()));
    rest = rest.substr(0, std::min<std::size_t>(11, rest.size()));
    return rest.substr(0, rest.find_last_not_of(' ') + 1);
  }
  return "(no line)";
}

struct Scenario {
  std::string what;
  std::string file;
  std::string options;
  int exit_code;
  std::map<std::string, std::string> verdicts;  ///< property or check name -> verdict
};

// One scenario on every writer: the checks described at the top of the file.
void run_every_writer(const Scenario& s, const std::string& engine) {
  SCOPED_TRACE(s.what + " on --engine " + engine);
  const auto dir =
      fs::temp_directory_path() / ("sfcv-writers-" + std::to_string(::getpid()) + "-" + engine +
                                   "-" + std::to_string(std::hash<std::string>{}(s.what)));
  fs::create_directories(dir);
  const std::string base = "check '" + s.file + "' --engine " + engine + " --quiet " + s.options;
  const auto junit = dir / "r.xml", sarif = dir / "r.sarif", html = dir / "r.html",
             json_file = dir / "r.json", again = dir / "again.html";

  // Text, with the three report files beside it.
  const auto text = run_sfcv(base + " --junit '" + junit.string() + "' --sarif '" + sarif.string() +
                             "' --html '" + html.string() + "'");
  ASSERT_EQ(text.exit_code, s.exit_code) << text.out << text.err;
  EXPECT_TRUE(report::is_valid_utf8(text.out));
  for (const auto& [name, verdict] : s.verdicts)
    EXPECT_EQ(text_verdict(text.out, name), verdict) << name << "\n" << text.out;

  // JSON: every property with its verdict, and the exit code.
  const auto json = run_sfcv(base + " --json");
  ASSERT_EQ(json.exit_code, s.exit_code) << json.err;
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(json.out)) << json.out;
  EXPECT_EQ(j["exit_code"], s.exit_code);
  EXPECT_TRUE(j["states"].is_null() || j["states"].is_number() || j["states"].is_string());
  ASSERT_EQ(j["properties"].size(), s.verdicts.size()) << json.out;
  for (const auto& p : j["properties"]) {
    const auto it = s.verdicts.find(p["name"].get<std::string>());
    ASSERT_NE(it, s.verdicts.end()) << p.dump();
    EXPECT_EQ(p["verdict"], it->second) << p.dump();
  }
  std::ofstream(json_file) << json.out;

  // JUnit: one test case per property; a failure, an error, a skipped element, or none.
  pugi::xml_document doc;
  expect_well_formed_xml(slurp(junit), doc);
  const auto suite = doc.child("testsuites").child("testsuite");
  std::size_t cases = 0;
  for (auto tc = suite.child("testcase"); tc; tc = tc.next_sibling("testcase")) ++cases;
  EXPECT_EQ(cases, s.verdicts.size());
  for (const auto& [name, verdict] : s.verdicts) {
    const auto tc = suite.find_child_by_attribute("testcase", "name", name.c_str());
    ASSERT_TRUE(tc) << name;
    const char* element = verdict == "violated"                              ? "failure"
                          : verdict == "unknown" || verdict == "not checked" ? "error"
                          : verdict == "n/a"                                 ? "skipped"
                                                                             : nullptr;
    if (!element) {
      EXPECT_FALSE(tc.child("failure") || tc.child("error") || tc.child("skipped")) << name;
    } else {
      EXPECT_TRUE(tc.child(element)) << name << " " << verdict;
    }
  }

  // SARIF: a rule per property; a result per answer other than holds, at its level.
  nlohmann::json log;
  ASSERT_NO_THROW(log = nlohmann::json::parse(slurp(sarif)));
  const auto& run = log["runs"][0];
  EXPECT_EQ(run["tool"]["driver"]["rules"].size(), s.verdicts.size());
  for (const auto& [name, verdict] : s.verdicts) {
    // Rule ids are stable ids, not names (issue 48): the rule named so gives the id.
    std::string rule_id;
    for (const auto& rule : run["tool"]["driver"]["rules"])
      if (rule["name"] == name) rule_id = rule["id"];
    EXPECT_FALSE(rule_id.empty()) << name;
    std::string level;
    for (const auto& r : run["results"])
      if (r["ruleId"] == rule_id) level = r["level"];
    const std::string expected = verdict == "holds"      ? ""
                                 : verdict == "violated" ? "error"
                                 : verdict == "n/a"      ? "none"
                                                         : "warning";
    EXPECT_EQ(level, expected) << name << " " << verdict;
  }

  // HTML, from check --html and from sfcv report on the JSON: every name with its verdict.
  const auto report = run_sfcv("report '" + json_file.string() + "' --html '" + again.string() +
                               "' --model '" + s.file + "'");
  EXPECT_EQ(report.exit_code, 0) << report.out << report.err;
  for (const auto& page : {slurp(html), slurp(again)}) {
    EXPECT_TRUE(report::is_valid_utf8(page));
    EXPECT_NE(page.find("</html>"), std::string::npos);
    for (const auto& [name, verdict] : s.verdicts) {
      std::string cls = verdict;
      for (auto& c : cls)
        if (c == ' ' || c == '/') c = '-';
      const auto row = page.find("<td class=\"name\">" + html_escaped(name));
      ASSERT_NE(row, std::string::npos) << name;
      EXPECT_EQ(page.find("<span class=\"verdict ", row),
                page.find("<span class=\"verdict " + cls + "\">" + verdict + "</span>", row))
          << name << " " << verdict;
    }
  }
  fs::remove_all(dir);
}

class ReportWriters : public ::testing::Test {
 protected:
  void SetUp() override {
    iec_ = write_temp(kIec, ".st");
    grafcet_ = write_temp(kGrafcet, ".g7");
    unstable_ = write_temp(kUnstable, ".g7");
  }
  std::string iec_, grafcet_, unstable_;
};

TEST_F(ReportWriters, HoldsOnEveryEngine) {
  for (const auto& e : kEngines) {
    // BMC proves no invariant: its "holds" is a reachability witness.
    const std::string ag = e == "bmc" ? "" : " --ctl 'AG !(s0 & s1)'";
    std::map<std::string, std::string> iec = {{"EF s2", "holds"}};
    if (!ag.empty()) iec["AG !(s0 & s1)"] = "holds";
    run_every_writer({"IEC holds", iec_, "--checks none --ctl 'EF s2'" + ag, 0, iec}, e);
    // The SAT engines do not decide EF on this Grafcet (one initial situation per input
    // valuation, and EF needs a run from each: not checked, below), and BMC no AG: no "holds"
    // on a Grafcet from BMC.
    if (e == "bmc") continue;
    const bool sat = e == "kind" || e == "ic3";
    std::map<std::string, std::string> g = {{"AG !(X1 & X2)", "holds"}};
    if (!sat) g["EF X2"] = "holds";
    run_every_writer(
        {"Grafcet holds", grafcet_,
         "--checks none --ctl 'AG !(X1 & X2)'" + std::string(sat ? "" : " --ctl 'EF X2'"), 0, g},
        e);
  }
}

TEST_F(ReportWriters, ViolatedOnEveryEngine) {
  for (const auto& e : kEngines) {
    run_every_writer({"IEC violated",
                      iec_,
                      "--checks none --ctl 'AG !y' --ctl 'EF s1'",
                      1,
                      {{"AG !y", "violated"}, {"EF s1", "holds"}}},
                     e);
    run_every_writer(
        {"Grafcet violated", grafcet_, "--checks none --ctl 'AG !y'", 1, {{"AG !y", "violated"}}},
        e);
  }
}

TEST_F(ReportWriters, UnknownOnEveryEngine) {
  // A limit: --max-states for the engines that count states, --depth for BMC and k-induction.
  const std::map<std::string, std::string> limit = {{"explicit", "--max-states 1"},
                                                    {"bdd", "--max-states 1"},
                                                    {"auto", "--max-states 1"},
                                                    {"bmc", "--depth 1"},
                                                    {"kind", "--depth 0"}};
  for (const auto& e : kEngines) {
    if (const auto it = limit.find(e); it != limit.end())
      run_every_writer({"IEC unknown at a limit",
                        iec_,
                        it->second + " --checks none --ctl 'AG !(s0 & s1)'",
                        3,
                        {{"AG !(s0 & s1)", "unknown"}}},
                       e);
    // No stable initial situation: nothing to judge, on every engine (the BDD engine used to
    // answer a vacuous "holds" here).
    run_every_writer({"Grafcet without an initial situation",
                      unstable_,
                      "--checks none --ctl 'AG !(X1 & X2)'",
                      3,
                      {{"AG !(X1 & X2)", "unknown"}}},
                     e);
  }
}

TEST_F(ReportWriters, NotCheckedCountsAsUnknown) {
  // The SAT engines decide AG p and EF p, not AG EF p: not checked, exit 3 beside a holds.
  for (const auto& e : {"bmc", "kind", "ic3"}) {
    run_every_writer({"IEC not checked",
                      iec_,
                      "--checks none --ctl 'AG EF s0' --ctl 'EF s1'",
                      3,
                      {{"AG EF s0", "not checked"}, {"EF s1", "holds"}}},
                     e);
    // EF on a Grafcet with several initial situations (one per valuation of a, b): decided
    // by kind and ic3 since issue 53 (it was "not checked"), unknown on BMC, which proves
    // nothing.
    const bool bmc = std::string(e) == "bmc";
    run_every_writer(
        {"Grafcet EF",
         grafcet_,
         "--checks none --ctl 'EF X2' --ctl 'AG !(X1 & X2)'",
         bmc ? 3 : 0,
         {{"EF X2", bmc ? "unknown" : "holds"}, {"AG !(X1 & X2)", bmc ? "unknown" : "holds"}}},
        e);
    // Their standard checks of an IEC chart: some decided, the others not checked, conflicts
    // n/a (the standard priority). IC3 searches the AG EF checks for a violation and, finding
    // none on this chart (they hold), answers unknown; global-deadlock it proves (a transition
    // can always fire at once).
    const bool ic3 = std::string(e) == "ic3";
    const std::string ag_ef = ic3 ? "unknown" : "not checked";
    std::map<std::string, std::string> checks = {
        {"reachable", "holds"},
        {"dead-transitions", "holds"},
        {"reentry", ag_ef},
        {"global-deadlock", ic3 ? "holds" : "not checked"},
        {"local-deadlock", ag_ef},
        {"initial-return", ag_ef},
        {"conflicts", "n/a"},
        {"stored-actions", "holds"},
        {"output-conflicts", "holds"},
        {"order-dependence", "n/a"},
        {"instability", std::string(e) == "bmc" ? "unknown" : "holds"}};
    run_every_writer({"IEC standard checks", iec_, "", 3, checks}, e);
  }
}

TEST_F(ReportWriters, AutoRaceThatCountsNoStates) {
  // Past its explicit probe (2^31 states) --engine auto races: IC3 proves the bound, BMC or the
  // BDD engine meets the violation, and the BDD engine is cancelled before it counts the states
  // ("states": null; the HTML report and sfcv report used to stop there with exit 4).
  const auto counter = write_temp(bench::counter_iec(30), ".st");
  const std::string bound = std::to_string((std::uint64_t{1} << 30) - 2);
  run_every_writer({"auto race",
                    counter,
                    "--checks none --ctl 'AG c <= " + bound + "' --ctl 'AG c <= 5'",
                    1,
                    {{"AG c <= " + bound, "holds"}, {"AG c <= 5", "violated"}}},
                   "auto");
}

TEST_F(ReportWriters, DefaultChecksExitZeroWhenEverythingThatAppliesHolds) {
  // IEC under the standard priority: conflicts is n/a, which is neither a pass nor unknown.
  for (const auto& e : {"explicit", "bdd", "auto"}) {
    std::map<std::string, std::string> iec, g;
    for (const char* c :
         {"reachable", "dead-transitions", "reentry", "global-deadlock", "local-deadlock",
          "initial-return", "conflicts", "stored-actions", "output-conflicts", "instability"}) {
      iec[c] = std::string(c) == "conflicts" ? "n/a" : "holds";
      g[c] = "holds";
    }
    // No order:<variable> input under the default (declaration) order: nothing to choose.
    iec["order-dependence"] = g["order-dependence"] = "n/a";
    run_every_writer({"IEC default checks", iec_, "", 0, iec}, e);
    run_every_writer({"Grafcet default checks", grafcet_, "", 0, g}, e);
  }
}

TEST_F(ReportWriters, AnEngineThatDecidesNothingAskedIsAUsageError) {
  // Issue 53: `sfcv check FILE.g7 --engine bmc` answered "not checked" ten times and exited 0.
  for (const auto& e : {"bmc", "kind", "ic3"}) {
    SCOPED_TRACE(e);
    const auto junit = write_temp("", ".xml");
    // A standard check of a Grafcet they do not decide (bmc and kind: the AG EF checks; ic3
    // decides every one) and CTL beyond their reach, alone, are a usage error.
    const bool ic3 = std::string(e) == "ic3";
    const auto r = run_sfcv("check '" + grafcet_ + "' --engine " + e +
                            (ic3 ? " --checks none --ctl 'AF X1'" : " --checks initial-return") +
                            " --ctl 'AG EF X1' --junit '" + junit + "'");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(std::string("--engine ") + e + " decides none of the 2 questions asked"),
              std::string::npos)
        << r.err;
    if (!ic3) {
      EXPECT_NE(r.err.find(std::string("not checked by the ") + e +
                           " engine on an IEC 60848 grafcet; use --engine explicit, bdd or auto"),
                std::string::npos)
          << r.err;
    }
    // Only AG EF, which it cannot decide: the same.
    const auto p =
        run_sfcv("check '" + iec_ + "' --engine " + e + " --checks none --ctl 'AG EF s0'");
    EXPECT_EQ(p.exit_code, 2) << p.out << p.err;
    EXPECT_NE(p.err.find("use --engine explicit or bdd"), std::string::npos) << p.err;
  }
}

// A PLCopen chart whose step names hold a byte that is no UTF-8 (0xFF) and a control character
// (&#1;): lint accepts it; every writer must print valid UTF-8, XML without the control
// character (before: exit 4 in --json, --sarif, --html, rsg --json and query --json, and a JUnit
// file that is not well-formed).
std::string invalid_utf8_chart() {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n"
         "<fileHeader companyName=\"t\" productName=\"CODESYS\" productVersion=\"3.5\" "
         "creationDateTime=\"2024-01-01T00:00:00\"/>\n<contentHeader name=\"plant\"/>\n"
         "<types><dataTypes/><pous>\n<pou name=\"seq\" pouType=\"program\">\n<interface>"
         "<inputVars><variable name=\"go\"><type><BOOL/></type></variable></inputVars>"
         "<outputVars><variable name=\"lamp\"><type><BOOL/></type></variable></outputVars>"
         "</interface>\n<body><SFC>\n"
         "<step localId=\"1\" name=\"S\xFF"
         "0\" initialStep=\"true\"><connectionPointIn><connection refLocalId=\"4\"/>"
         "</connectionPointIn><connectionPointOut/></step>\n"
         "<transition localId=\"3\"><connectionPointIn><connection refLocalId=\"1\"/>"
         "</connectionPointIn><connectionPointOut/><condition><inline name=\"\"><ST><xhtml:p>"
         "<![CDATA[go]]></xhtml:p></ST></inline></condition></transition>\n"
         "<step localId=\"2\" name=\"S1&#1;x\"><connectionPointIn><connection refLocalId=\"3\"/>"
         "</connectionPointIn><connectionPointOut/></step>\n"
         "<transition localId=\"4\"><connectionPointIn><connection refLocalId=\"2\"/>"
         "</connectionPointIn><connectionPointOut/><condition><inline name=\"\"><ST><xhtml:p>"
         "<![CDATA[NOT go]]></xhtml:p></ST></inline></condition></transition>\n"
         "</SFC></body>\n</pou>\n</pous></types>\n<instances><configurations/></instances>\n"
         "</project>\n";
}

TEST(ReportWritersUtf8, InvalidUtf8StepNameThroughEveryWriter) {
  const auto file = write_temp(invalid_utf8_chart(), ".xml");
  const auto lint = run_sfcv("lint '" + file + "' --json");
  ASSERT_EQ(lint.exit_code, 0) << lint.out << lint.err;
  EXPECT_TRUE(nlohmann::json::accept(lint.out));
  const auto info = run_sfcv("info '" + file + "' --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_TRUE(nlohmann::json::accept(info.out));
  const std::string replaced =
      "S\xEF\xBF\xBD"
      "0";  // U+FFFD
  for (const auto& e : kEngines) {
    SCOPED_TRACE(e);
    // AG !go is violated: its counterexample names both steps.
    const std::string base = "check '" + file + "' --engine " + e +
                             " --quiet --checks reachable,dead-transitions --ctl 'AG !go'";
    const auto junit = write_temp("", ".xml"), sarif = write_temp("", ".sarif"),
               html = write_temp("", ".html"), json_file = write_temp("", ".json"),
               again = write_temp("", ".html");
    const auto text =
        run_sfcv(base + " --junit '" + junit + "' --sarif '" + sarif + "' --html '" + html + "'");
    ASSERT_EQ(text.exit_code, 1) << text.out << text.err;
    EXPECT_TRUE(report::is_valid_utf8(text.out));
    const auto json = run_sfcv(base + " --json");
    ASSERT_EQ(json.exit_code, 1) << json.err;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(json.out));
    EXPECT_NE(json.out.find(replaced), std::string::npos) << json.out;
    EXPECT_EQ(j["properties"][0]["verdict"], "violated");
    std::ofstream(json_file) << json.out;
    pugi::xml_document doc;
    const auto xml = slurp(junit);
    expect_well_formed_xml(xml, doc);
    EXPECT_TRUE(doc.child("testsuites")
                    .child("testsuite")
                    .find_child_by_attribute("testcase", "name", "AG !go"));
    EXPECT_NE(xml.find(replaced), std::string::npos) << xml;
    const auto log = slurp(sarif);
    EXPECT_TRUE(nlohmann::json::accept(log));
    EXPECT_TRUE(report::is_valid_utf8(log));
    const auto report =
        run_sfcv("report '" + json_file + "' --html '" + again + "' --model '" + file + "'");
    EXPECT_EQ(report.exit_code, 0) << report.err;
    for (const auto& page : {slurp(html), slurp(again)}) {
      EXPECT_TRUE(report::is_valid_utf8(page));
      EXPECT_NE(page.find("<span class=\"verdict violated\">violated</span>"), std::string::npos);
    }
  }
  const auto rsg = run_sfcv("rsg '" + file + "' --json");
  ASSERT_EQ(rsg.exit_code, 0) << rsg.err;
  EXPECT_TRUE(nlohmann::json::accept(rsg.out));
  EXPECT_NE(rsg.out.find(replaced), std::string::npos);
  const auto query = run_sfcv("query '" + file + "' --json 'Y'");
  ASSERT_EQ(query.exit_code, 0) << query.err;
  EXPECT_TRUE(nlohmann::json::accept(query.out));
  const auto trace = run_sfcv("check '" + file +
                              "' --quiet --checks none --ctl 'AG !go' "
                              "--trace json");
  EXPECT_EQ(trace.exit_code, 1);
  EXPECT_TRUE(report::is_valid_utf8(trace.out));
}

}  // namespace
}  // namespace sfcv::test

#include "report/check_junit.hpp"

#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <string>

#include "support/toy_system.hpp"

namespace sfcv::report {
namespace {

using test::ToySystem;

// One result per verdict; the violated one carries a finding and a two-state counterexample.
struct Fixture {
  ToySystem ts{2, {"go"}, {"A", "B"}};
  logic::CheckReport report;
  Fixture() {
    ts.set_true(0, 0);
    ts.set_true(1, 1);
    ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
    auto state = [&](std::uint32_t s) {
      std::vector<semantics::StateWord> w(ts.layout().words(), 0);
      ts.layout().set(w, 0, s);
      return w;
    };
    report.engine = "explicit";
    report.states = 2;
    report.seconds = 0.5;
    logic::PropertyResult holds;
    holds.name = "safe";
    holds.formula = "AG !(A & B)";
    holds.verdict = logic::Verdict::Holds;
    holds.where.file = "plant.spec";
    holds.where.line = 3;
    logic::PropertyResult violated;
    violated.name = "never B";
    violated.formula = "AG !B";
    violated.verdict = logic::Verdict::Violated;
    violated.findings = {"B & <reached> in 1 cycle"};
    violated.where.file = "--ctl";
    logic::Trace trace;
    trace.kind = logic::TraceKind::Counterexample;
    trace.steps.push_back({{0}, state(0), {}});
    trace.steps.push_back({{1}, state(1), {0}});
    violated.trace = trace;
    logic::PropertyResult unknown;
    unknown.name = "live";
    unknown.verdict = logic::Verdict::Unknown;
    unknown.message = "the states limit was reached";
    logic::PropertyResult skipped;
    skipped.name = "conflicts";
    skipped.check = "conflicts";
    skipped.verdict = logic::Verdict::NotApplicable;
    skipped.message = "the priority resolves conflicts";
    logic::PropertyResult not_checked;
    not_checked.name = "reentry";
    not_checked.check = "reentry";
    not_checked.verdict = logic::Verdict::NotChecked;
    not_checked.message = "not checked by the bmc engine";
    report.results = {holds, violated, unknown, skipped, not_checked};
  }
};

TEST(CheckJunit, OneTestCasePerResultWithItsVerdict) {
  Fixture f;
  RenderOptions options;
  options.model = "/some/dir/plant.st";
  options.semantics = "iec61131";
  const auto xml = check_junit(f.report, f.ts, options);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str())) << xml;
  const auto suites = doc.child("testsuites");
  EXPECT_EQ(suites.attribute("tests").as_int(), 5);
  EXPECT_EQ(suites.attribute("failures").as_int(), 1);
  // Unknown and not checked are never a pass (exit code 3); n/a is skipped.
  EXPECT_EQ(suites.attribute("errors").as_int(), 2);
  // Jenkins' junit-10.xsd has no skipped on testsuites: the suite carries it.
  EXPECT_FALSE(suites.attribute("skipped"));
  const auto suite = suites.child("testsuite");
  EXPECT_EQ(suite.attribute("skipped").as_int(), 1);
  EXPECT_STREQ(suite.attribute("name").value(), "plant.st");
  EXPECT_STREQ(suite.child("properties")
                   .find_child_by_attribute("property", "name", "engine")
                   .attribute("value")
                   .value(),
               "explicit");

  const auto safe = suite.find_child_by_attribute("testcase", "name", "safe");
  ASSERT_TRUE(safe);
  // A pass has no verdict element; where the property was written goes to system-out (no file
  // or line attribute in Jenkins' junit-10.xsd).
  EXPECT_FALSE(safe.child("failure") || safe.child("error") || safe.child("skipped"));
  EXPECT_FALSE(safe.attribute("file"));
  EXPECT_FALSE(safe.attribute("line"));
  const std::string safe_out = safe.child("system-out").text().get();
  EXPECT_NE(safe_out.find("where: plant.spec:3"), std::string::npos) << safe_out;
  EXPECT_NE(safe_out.find("decided by: explicit"), std::string::npos) << safe_out;
  EXPECT_STREQ(safe.attribute("classname").value(), "plant.st.properties");

  const auto failure =
      suite.find_child_by_attribute("testcase", "name", "never B").child("failure");
  ASSERT_TRUE(failure);
  EXPECT_STREQ(failure.attribute("type").value(), "violated");
  const std::string body = failure.text().get();
  EXPECT_NE(body.find("formula: AG !B"), std::string::npos) << body;
  EXPECT_NE(body.find("- B & <reached> in 1 cycle"), std::string::npos)
      << body;  // escaped and back
  EXPECT_NE(body.find("counterexample (2 situations)"), std::string::npos) << body;
  EXPECT_NE(body.find("+go"), std::string::npos) << body;

  // A command-line property belongs to the model file, with no line.
  const auto never_b = suite.find_child_by_attribute("testcase", "name", "never B");
  EXPECT_FALSE(never_b.attribute("file"));
  const std::string never_b_out = never_b.child("system-out").text().get();
  EXPECT_NE(never_b_out.find("where: /some/dir/plant.st\n"), std::string::npos) << never_b_out;
  // The verdict element comes before system-out, as Maven Surefire writes them.
  EXPECT_STREQ(never_b.first_child().name(), "failure");

  const auto error = suite.find_child_by_attribute("testcase", "name", "live").child("error");
  ASSERT_TRUE(error);
  EXPECT_STREQ(error.attribute("message").value(), "unknown: the states limit was reached");

  const auto conflicts = suite.find_child_by_attribute("testcase", "name", "conflicts");
  EXPECT_STREQ(conflicts.attribute("classname").value(), "plant.st.standard_checks");
  EXPECT_TRUE(conflicts.child("skipped"));
  EXPECT_STREQ(conflicts.child("skipped").attribute("message").value(),
               "n/a: the priority resolves conflicts");
  const auto reentry = suite.find_child_by_attribute("testcase", "name", "reentry").child("error");
  ASSERT_TRUE(reentry);
  EXPECT_STREQ(reentry.attribute("type").value(), "not checked");
}

TEST(CheckJunit, StatesLeftOutWhenTheEngineDidNotCountThem) {
  Fixture f;
  const auto counted = check_junit(f.report, f.ts, {});
  EXPECT_NE(counted.find("name=\"states\" value=\"2\""), std::string::npos) << counted;
  f.report.states_known = false;  // SAT engines
  const auto xml = check_junit(f.report, f.ts, {});
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str())) << xml;
  EXPECT_FALSE(doc.child("testsuites")
                   .child("testsuite")
                   .child("properties")
                   .find_child_by_attribute("property", "name", "states"));
}

TEST(CheckJunit, NamesWithInvalidUtf8AndControlCharactersGiveWellFormedXml) {
  // Names are bytes (a Latin-1 export, a hostile file): XML 1.0 allows neither invalid UTF-8
  // nor control characters other than tab, line feed and carriage return.
  Fixture f;
  f.report.results[0].name =
      "S\xFF"
      "1";
  f.report.results[1].message = "step S\x01x (bell\x07) never left";
  f.report.results[1].findings = {"at \xC3"};
  RenderOptions options;
  options.model = "pl\xE4nt.xml";
  const auto xml = check_junit(f.report, f.ts, options);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8))
      << xml;
  EXPECT_EQ(xml.find('\x01'), std::string::npos);
  EXPECT_EQ(xml.find('\x07'), std::string::npos);
  EXPECT_EQ(xml.find("\xFF"), std::string::npos);
  const auto suite = doc.child("testsuites").child("testsuite");
  EXPECT_STREQ(suite.attribute("name").value(), "pl\xEF\xBF\xBDnt.xml");  // U+FFFD
  EXPECT_TRUE(suite.find_child_by_attribute("testcase", "name",
                                            "S\xEF\xBF\xBD"
                                            "1"));
  const auto failure =
      suite.find_child_by_attribute("testcase", "name", "never B").child("failure");
  EXPECT_STREQ(failure.attribute("message").value(),
               "violated: step S\xEF\xBF\xBDx (bell\xEF\xBF\xBD) never left");
}

}  // namespace
}  // namespace sfcv::report

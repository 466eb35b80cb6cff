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
    skipped.verdict = logic::Verdict::NotChecked;
    skipped.message = "the priority resolves conflicts";
    report.results = {holds, violated, unknown, skipped};
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
  EXPECT_EQ(suites.attribute("tests").as_int(), 4);
  EXPECT_EQ(suites.attribute("failures").as_int(), 1);
  EXPECT_EQ(suites.attribute("errors").as_int(), 1);  // unknown is never a pass
  EXPECT_EQ(suites.attribute("skipped").as_int(), 1);
  const auto suite = suites.child("testsuite");
  EXPECT_STREQ(suite.attribute("name").value(), "plant.st");
  EXPECT_STREQ(suite.child("properties")
                   .find_child_by_attribute("property", "name", "engine")
                   .attribute("value")
                   .value(),
               "explicit");

  const auto safe = suite.find_child_by_attribute("testcase", "name", "safe");
  ASSERT_TRUE(safe);
  EXPECT_FALSE(safe.first_child());  // a pass has no child element
  EXPECT_STREQ(safe.attribute("file").value(), "plant.spec");
  EXPECT_EQ(safe.attribute("line").as_int(), 3);
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
  EXPECT_STREQ(never_b.attribute("file").value(), "/some/dir/plant.st");
  EXPECT_FALSE(never_b.attribute("line"));

  const auto error = suite.find_child_by_attribute("testcase", "name", "live").child("error");
  ASSERT_TRUE(error);
  EXPECT_STREQ(error.attribute("message").value(), "unknown: the states limit was reached");

  const auto conflicts = suite.find_child_by_attribute("testcase", "name", "conflicts");
  EXPECT_STREQ(conflicts.attribute("classname").value(), "plant.st.standard_checks");
  EXPECT_TRUE(conflicts.child("skipped"));
}

}  // namespace
}  // namespace sfcv::report

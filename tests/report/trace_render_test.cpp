#include "report/trace_render.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "report/check_render.hpp"
#include "report/provenance.hpp"
#include "support/toy_system.hpp"

namespace sfcv::report {
namespace {

using test::ToySystem;

// Toy states 0 (A), 1 (B, output Y); a lasso 0 -> 1 -> 0 on input go.
struct Fixture {
  ToySystem ts{2, {"go", "stop"}, {"A", "B", "Y"}};
  logic::Trace trace;
  Fixture() {
    ts.set_kind(2, semantics::ObservableKind::Variable, true);
    ts.set_true(0, 0);
    ts.set_true(1, 1);
    ts.set_true(1, 2);
    ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
    ts.add_arc(1, 0, ToySystem::lit(0, false), {1});
    auto state = [&](std::uint32_t s) {
      std::vector<semantics::StateWord> w(ts.layout().words(), 0);
      ts.layout().set(w, 0, s);
      return w;
    };
    trace.steps.push_back({{0, 0}, state(0), {}});
    trace.steps.push_back({{1, 0}, state(1), {0}});
    trace.steps.push_back({{0, 0}, state(0), {1}});
    trace.loop_start = 0;
    trace.marked = {1};
    trace.note = "B is visited forever";
  }
};

TEST(TraceRender, TableShowsChangesStepsOutputsAndMarks) {
  Fixture f;
  const auto t = trace_table(f.trace, f.ts);
  EXPECT_NE(t.find("B is visited forever"), std::string::npos);
  EXPECT_NE(t.find("inputs (changed)"), std::string::npos);
  EXPECT_NE(t.find("+go"), std::string::npos);
  EXPECT_NE(t.find("-go"), std::string::npos);
  EXPECT_EQ(t.find("stop"), std::string::npos);      // never changed
  EXPECT_NE(t.find("B*"), std::string::npos);        // marked atom
  EXPECT_NE(t.find("| Y"), std::string::npos) << t;  // output column
  EXPECT_NE(t.find("t0"), std::string::npos);
  EXPECT_NE(t.find("->0"), std::string::npos);
  EXPECT_NE(t.find("repeats rows 0..2 forever"), std::string::npos);
}

TEST(TraceRender, JsonHasOneObjectPerStep) {
  Fixture f;
  const auto j = nlohmann::json::parse(trace_json(f.trace, f.ts));
  EXPECT_EQ(j["kind"], "counterexample");
  EXPECT_EQ(j["loop_start"], 0);
  ASSERT_EQ(j["steps"].size(), 3u);
  EXPECT_EQ(j["steps"][1]["inputs"]["go"], true);
  EXPECT_EQ(j["steps"][1]["changed"], nlohmann::json::array({"go"}));
  EXPECT_EQ(j["steps"][1]["fired"], nlohmann::json::array({"t0"}));
  EXPECT_EQ(j["steps"][1]["active_steps"], nlohmann::json::array({"B"}));
  EXPECT_EQ(j["steps"][1]["values"]["Y"], true);
  EXPECT_EQ(j["marked"], nlohmann::json::array({"B"}));
}

TEST(TraceRender, VcdDeclaresSignalsAndDumpsChanges) {
  Fixture f;
  const auto v = trace_vcd(f.trace, f.ts);
  EXPECT_NE(v.find("$timescale"), std::string::npos);
  EXPECT_NE(v.find("$var wire 1 ! go $end"), std::string::npos) << v;
  EXPECT_NE(v.find(" B $end"), std::string::npos);
  EXPECT_NE(v.find("$enddefinitions $end"), std::string::npos);
  EXPECT_NE(v.find("#0\n$dumpvars\n0!"), std::string::npos);
  EXPECT_NE(v.find("#1\n1!"), std::string::npos);
  EXPECT_NE(v.find("#2\n0!"), std::string::npos);
}

TEST(TraceRender, VcdGolden) {
  Fixture f;
  EXPECT_EQ(trace_vcd(f.trace, f.ts, {10}),
            "$comment sfcv trace: one scan cycle of 10 ms per step $end\n"
            "$comment loop: the last step is step 0 again (time 0): steps 0..2 repeat forever "
            "(signal trace.in_loop) $end\n"
            "$version sfcv " +
                build_version() +
                " $end\n"
                "$timescale 1 ms $end\n"
                "$scope module inputs $end\n"
                "$var wire 1 ! go $end\n"
                "$var wire 1 \" stop $end\n"
                "$upscope $end\n"
                "$scope module steps $end\n"
                "$var wire 1 # A $end\n"
                "$var wire 1 $ B $end\n"
                "$upscope $end\n"
                "$scope module outputs $end\n"
                "$var wire 1 % Y $end\n"
                "$upscope $end\n"
                "$scope module trace $end\n"
                "$var wire 1 & in_loop $end\n"
                "$upscope $end\n"
                "$enddefinitions $end\n"
                "#0\n$dumpvars\n0!\n0\"\n1#\n0$\n0%\n1&\n$end\n"
                "#10\n1!\n0#\n1$\n1%\n"
                "#20\n0!\n1#\n0$\n0%\n"
                "#30\n");
}

// Issue 48: a lasso's loop point survives in the VCD: a comment in the header and the signal
// trace.in_loop, 0 before the step the run returns to and 1 from it on.
TEST(TraceRender, VcdKeepsALassosLoopPoint) {
  Fixture f;
  f.trace.loop_start = 1;
  const auto v = trace_vcd(f.trace, f.ts, {10});
  EXPECT_NE(v.find("$comment loop: the last step is step 1 again (time 10): steps 1..2 repeat "
                   "forever (signal trace.in_loop) $end"),
            std::string::npos)
      << v;
  EXPECT_NE(v.find("$var wire 1 & in_loop $end"), std::string::npos) << v;
  EXPECT_NE(v.find("0%\n0&\n$end\n"), std::string::npos) << v;  // not in the loop at time 0
  EXPECT_NE(v.find("#10\n1!\n0#\n1$\n1%\n1&\n"), std::string::npos) << v;
  // Without a loop there is no such signal.
  f.trace.loop_start.reset();
  EXPECT_EQ(trace_vcd(f.trace, f.ts).find("in_loop"), std::string::npos);
}

TEST(TraceRender, VcdNamesAreIdentifiersAndIntegersBinary) {
  ToySystem ts{1, {"timeout:T1"}, {"Plant.s1"}};
  ts.set_input_type(0, model::Type::integer("INT", -2, 5));
  logic::Trace trace;
  std::vector<semantics::StateWord> w(ts.layout().words(), 0);
  trace.steps.push_back({{5}, w, {}});
  trace.steps.push_back({{-1}, w, {}});
  const auto v = trace_vcd(trace, ts);
  EXPECT_NE(v.find("$var integer 64 ! timeout_T1 $end\n"), std::string::npos) << v;
  EXPECT_NE(v.find("$var wire 1 \" Plant_s1 $end\n"), std::string::npos) << v;
  EXPECT_NE(v.find("#0\n$dumpvars\nb101 !\n"), std::string::npos) << v;
  EXPECT_NE(v.find("#1\nb" + std::string(64, '1') + " !\n"), std::string::npos) << v;
}

TEST(TraceRender, TableShowsIntegerInputsThatNeverChange) {
  ToySystem ts{2, {"level", "go"}, {"A", "B"}};
  ts.set_input_type(0, model::Type::integer("INT", 0, 9));
  ts.set_true(0, 0);
  ts.set_true(1, 1);
  auto state = [&](std::uint32_t s) {
    std::vector<semantics::StateWord> w(ts.layout().words(), 0);
    ts.layout().set(w, 0, s);
    return w;
  };
  logic::Trace trace;
  trace.steps.push_back({{0, 0}, state(0), {}});
  trace.steps.push_back({{0, 1}, state(1), {}});
  EXPECT_EQ(trace_table(trace, ts),
            "  # | inputs (changed) | fired | active steps | outputs\n"
            "  --+------------------+-------+--------------+--------\n"
            "  0 | level=0          |       | A\n"
            "  1 | +go              |       | B\n");
}

TEST(TraceRender, GrafcetCsvStartsWithTheInitialInputs) {
  Fixture f;
  f.ts.set_semantics(semantics::SemanticsKind::Grafcet);
  f.trace.steps[0].inputs = {0, 1};
  EXPECT_EQ(trace_csv(f.trace, f.ts),
            "# sfcv check trace: one row per stable situation, the first the initial inputs; rows "
            "from situation 0 on repeat forever\n"
            "go,stop\n0,1\n1,0\n0,0\n");
}

TEST(TraceRender, CsvIsTheSimulateInput) {
  Fixture f;
  const auto c = trace_csv(f.trace, f.ts);
  EXPECT_NE(c.find("go,stop\n1,0\n0,0\n"), std::string::npos) << c;
  EXPECT_EQ(c.front(), '#');
}

TEST(CheckRender, SaysHowManyFindingsWereCut) {
  Fixture f;
  logic::CheckReport report;
  logic::PropertyResult c;
  c.name = c.check = "dead-transitions";
  c.verdict = logic::Verdict::Violated;
  c.findings = {"transition t1 never fires", "transition t2 never fires"};
  c.findings_total = 137;
  report.results.push_back(c);
  const auto text = check_text(report, f.ts, {});
  EXPECT_NE(
      text.find(
          "  - transition t2 never fires\n  (2 of 137 findings shown; --all for every one)\n"),
      std::string::npos)
      << text;
  EXPECT_EQ(check_json(report, f.ts, {})["properties"][0]["findings_total"], 137);
  report.results[0].findings_total = 2;
  EXPECT_EQ(check_text(report, f.ts, {}).find("findings shown"), std::string::npos);
}

TEST(CheckRender, NamesTheEngineThatDecided) {
  // --engine auto: the text marks an answer given by another engine than the report's; JSON
  // names the engine of every definite answer, and none for an unknown one.
  Fixture f;
  logic::CheckReport report;
  report.engine = "auto";
  logic::PropertyResult p;
  p.name = p.formula = "AG !go";
  p.verdict = logic::Verdict::Holds;
  p.decided_by = "ic3";
  report.results.push_back(p);
  p.name = p.formula = "AF go";
  p.verdict = logic::Verdict::Unknown;
  p.decided_by.clear();
  report.results.push_back(p);
  const auto text = check_text(report, f.ts, {});
  EXPECT_NE(text.find("AG !go  holds       0.000s  [ic3]\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("AF go   unknown     0.000s  ["), std::string::npos) << text;
  const auto j = check_json(report, f.ts, {});
  EXPECT_EQ(j["properties"][0]["decided_by"], "ic3");
  EXPECT_TRUE(j["properties"][1]["decided_by"].is_null());
  // The report's own engine is not repeated in the text; JSON still names it.
  report.engine = "explicit";
  report.results[0].decided_by = "explicit";
  EXPECT_EQ(check_text(report, f.ts, {}).find("[explicit]"), std::string::npos);
  report.results[0].decided_by.clear();
  EXPECT_EQ(check_json(report, f.ts, {})["properties"][0]["decided_by"], "explicit");
}

TEST(CheckRender, TextAndJsonReports) {
  Fixture f;
  logic::CheckReport report;
  report.engine = "explicit";
  report.states = 2;
  report.edges = 2;
  logic::PropertyResult p;
  p.name = "no_b";
  p.formula = "AG !B";
  p.verdict = logic::Verdict::Violated;
  p.trace = f.trace;
  report.results.push_back(p);
  logic::PropertyResult c;
  c.name = c.check = "reachable";
  c.verdict = logic::Verdict::Holds;
  c.message = "all 2 steps are reachable";
  report.results.push_back(c);
  RenderOptions opts;
  opts.model = "toy.st";
  opts.semantics = "iec61131";
  const auto text = check_text(report, f.ts, opts);
  EXPECT_NE(text.find("no_b       violated"), std::string::npos) << text;
  EXPECT_NE(text.find("formula: AG !B"), std::string::npos);
  EXPECT_NE(text.find("counterexample (3 situations)"), std::string::npos);
  EXPECT_NE(text.find("reachable  holds"), std::string::npos);
  const auto j = check_json(report, f.ts, opts);
  EXPECT_EQ(j["model"], "toy.st");
  EXPECT_EQ(j["exit_code"], 1);
  ASSERT_EQ(j["properties"].size(), 2u);
  EXPECT_EQ(j["properties"][0]["verdict"], "violated");
  EXPECT_EQ(j["properties"][0]["kind"], "property");
  EXPECT_EQ(j["properties"][0]["trace"]["steps"].size(), 3u);
  EXPECT_EQ(j["properties"][1]["kind"], "standard-check");
  EXPECT_TRUE(j["properties"][1]["trace"].is_null());
}

}  // namespace
}  // namespace sfcv::report

// Requirement patterns (logic/pattern.hpp) decided on small charts whose runs are known: every
// pattern and every scope both holding and violated, on the explicit and the BDD engine; then
// both engines agree on random patterns over random charts.

#include <gtest/gtest.h>

#include <random>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::engine {
namespace {

struct Both {
  logic::CheckReport explicit_report, bdd_report;
};

Both check_patterns(const std::string& chart, const std::vector<std::string>& patterns) {
  auto loaded = io::load_iec_text(chart, "chart.st");
  EXPECT_TRUE(loaded.ok());
  model::Diagnostics diags;
  const auto base = semantics::make_iec61131_system(*loaded.project, {}, diags);
  EXPECT_TRUE(base);
  logic::CheckInputs in;
  in.patterns = patterns;
  auto parsed = logic::parse_check_inputs(in);
  for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
  // Inputs and prev() in the arguments: the system keeps them (as sfcv check does).
  const auto history = logic::history_system_for(parsed.spec, *base, diags);
  const semantics::TransitionSystem* ts = history ? history.get() : base.get();
  logic::CheckTask task;
  task.system = ts;
  task.project = &*loaded.project;
  logic::resolve_into(parsed.spec, *ts, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  EXPECT_EQ(task.properties.size(), patterns.size());
  Both out;
  out.explicit_report = make_explicit_model_checker()->check(task);
  const auto bdd = make_bdd_model_checker({});
  EXPECT_TRUE(bdd->can_handle(task));
  out.bdd_report = bdd->check(task);
  return out;
}

struct Expected {
  const char* pattern;
  bool holds;
};

void expect_verdicts(const std::string& chart, const std::vector<Expected>& cases) {
  std::vector<std::string> patterns;
  for (const auto& c : cases) patterns.push_back(c.pattern);
  const auto both = check_patterns(chart, patterns);
  for (const auto* report : {&both.explicit_report, &both.bdd_report}) {
    ASSERT_EQ(report->results.size(), cases.size()) << report->engine;
    for (std::size_t k = 0; k < cases.size(); ++k)
      EXPECT_EQ(report->results[k].verdict,
                cases[k].holds ? logic::Verdict::Holds : logic::Verdict::Violated)
          << report->engine << ": " << cases[k].pattern << " = " << report->results[k].formula;
  }
}

// One run, no input: S0 S1 S2 S3 S4 S4 ... (each cycle fires the next transition).
const std::string kLine = R"(
PROGRAM MAIN
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  STEP S2 : END_STEP
  STEP S3 : END_STEP
  STEP S4 : END_STEP
  TRANSITION FROM S0 TO S1 := TRUE; END_TRANSITION
  TRANSITION FROM S1 TO S2 := TRUE; END_TRANSITION
  TRANSITION FROM S2 TO S3 := TRUE; END_TRANSITION
  TRANSITION FROM S3 TO S4 := TRUE; END_TRANSITION
END_PROGRAM
)";

// S2 & S3 is never true: a scope bound that never comes.
TEST(PatternVerdicts, CycleTemplatesOnALine) {
  expect_verdicts(kLine, {
                             {"always(S0 | S1 | S2 | S3 | S4)", true},
                             {"always(S0)", false},
                             {"never(S2 & S3)", true},
                             {"never(S2)", false},
                             {"implies(S2, !S3)", true},
                             {"implies(S2, S3)", false},
                             {"next_cycle(S2, S3)", true},
                             {"next_cycle(S2, S4)", false},
                             {"between_cycles(S2, S3, !S1)", true},
                             {"between_cycles(S2, S3, S4)", false},
                             {"infinitely_often(S4)", true},
                             {"infinitely_often(S3)", false},
                             {"never_before(S3, S1)", true},
                             {"never_before(S1, S3)", false},
                             {"reachable(S3)", true},
                             {"reachable(S2 & S3)", false},
                             {"repeatable(S4)", true},
                             {"repeatable(S0)", false},
                             {"response(S1, S3, within 2 cycles)", true},
                             {"response(S1, S3, within 1 cycle)", false},
                             {"response(S0, S0, within 0 cycles)", true},
                             {"response(S0, S4, within 3 cycles)", false},
                         });
}

TEST(PatternVerdicts, GlobalScopeOnALine) {
  expect_verdicts(kLine, {
                             {"absence(S2 & S3)", true},
                             {"absence(S2)", false},
                             {"universality(!(S2 & S3))", true},
                             {"universality(!S3)", false},
                             {"existence(S3)", true},
                             {"existence(S2 & S3)", false},
                             {"precedence(S1, S3)", true},
                             {"precedence(S3, S1)", false},
                             {"response(S1, S3)", true},
                             {"response(S4, S0)", false},
                             {"absence(S2, globally)", false},
                         });
}

TEST(PatternVerdicts, BeforeScopeOnALine) {
  expect_verdicts(kLine,
                  {
                      {"absence(S4, before S3)", true},
                      {"absence(S1, before S3)", false},
                      {"absence(S1, before S0)", true},       // the scope is empty: R at once
                      {"absence(S1, before S2 & S3)", true},  // R never comes: nothing is required
                      {"universality(!S3, before S3)", true},
                      {"universality(S0, before S2)", false},
                      {"existence(S1, before S3)", true},
                      {"existence(S4, before S3)", false},
                      {"existence(S4, before S2 & S3)", true},
                      {"precedence(S1, S2, before S3)", true},
                      {"precedence(S2, S1, before S3)", false},
                      {"precedence(S2, S1, before S1)", true},
                      {"response(S1, S2, before S3)", true},
                      {"response(S1, S3, before S3)", false},
                  });
}

TEST(PatternVerdicts, AfterScopeOnALine) {
  expect_verdicts(kLine, {
                             {"absence(S1, after S2)", true},
                             {"absence(S3, after S2)", false},
                             {"absence(S0, after S2 & S3)", true},  // Q never comes
                             {"universality(S3 | S4, after S3)", true},
                             {"universality(S3, after S3)", false},
                             {"existence(S4, after S3)", true},
                             {"existence(S1, after S2)", false},
                             {"precedence(S3, S4, after S2)", true},
                             {"precedence(S4, S3, after S2)", false},
                             {"response(S3, S4, after S2)", true},
                             {"response(S3, S1, after S2)", false},
                         });
}

TEST(PatternVerdicts, BetweenScopeOnALine) {
  expect_verdicts(kLine,
                  {
                      {"absence(S4, between S1 and S3)", true},
                      {"absence(S2, between S1 and S3)", false},
                      {"absence(S2, between S1 and S2 & S3)", true},  // R never comes: no interval
                      {"universality(S1 | S2, between S1 and S3)", true},
                      {"universality(S1, between S1 and S3)", false},
                      {"existence(S2, between S1 and S3)", true},
                      {"existence(S4, between S1 and S3)", false},
                      {"existence(S4, between S1 and S2 & S3)", true},
                      {"precedence(S1, S2, between S1 and S3)", true},
                      {"precedence(S2, S1, between S0 and S3)", false},
                      {"response(S1, S2, between S0 and S3)", true},
                      {"response(S2, S4, between S1 and S3)", false},
                  });
}

TEST(PatternVerdicts, AfterUntilScopeOnALine) {
  expect_verdicts(kLine, {
                             {"absence(S4, after S1 until S3)", true},
                             {"absence(S2, after S1 until S3)", false},
                             {"absence(S4, after S1 until S2 & S3)",
                              false},  // R never comes: the scope lasts for ever
                             {"universality(S1 | S2, after S1 until S3)", true},
                             {"universality(S1 | S2, after S1 until S2 & S3)", false},
                             {"existence(S2, after S1 until S3)", true},
                             {"existence(S4, after S1 until S3)", false},
                             {"existence(S4, after S1 until S2 & S3)", true},
                             {"precedence(S1, S2, after S1 until S3)", true},
                             {"precedence(S2, S1, after S0 until S3)", false},
                             {"response(S1, S2, after S0 until S3)", true},
                             {"response(S2, S4, after S1 until S2 & S3)", true},
                             {"response(S2, S4, after S1 until S3)", false},
                         });
}

// Branching on an input: S0 waits for x, S1 moves on, S2 waits for x and returns to S0.
const std::string kLoop = R"(
PROGRAM MAIN
  VAR_INPUT x : BOOL; END_VAR
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  STEP S2 : END_STEP
  TRANSITION FROM S0 TO S1 := x; END_TRANSITION
  TRANSITION FROM S1 TO S2 := TRUE; END_TRANSITION
  TRANSITION FROM S2 TO S0 := x; END_TRANSITION
END_PROGRAM
)";

TEST(PatternVerdicts, BranchingLoop) {
  expect_verdicts(kLoop, {
                             {"existence(S1)", false},  // a run may wait in S0 for ever
                             {"reachable(S1)", true},
                             {"repeatable(S1)", true},
                             {"infinitely_often(S1)", false},
                             {"response(S1, S2, within 1 cycle)", true},
                             {"response(S0, S1)", false},
                             {"precedence(S1, S2)", true},
                             {"precedence(S2, S1)", false},
                             {"absence(S2, before S1)", true},
                             {"existence(S2, after S1)", true},
                             {"universality(S1 | S2, after S1 until S0)", true},
                             {"next_cycle(S1, S2)", true},
                             {"next_cycle(S0, S1)", false},
                             {"implies(rise(S1), prev(S0))", true},
                             {"implies(S1, x)",
                              true},  // S1 is entered in a cycle that read x, and left in the next
                             {"implies(S2, x)", false},
                             {"never_before(S2, S1)", true},
                         });
}

// The BDD engine's traces on a chart without inputs (every hop has no input bits to pick).
TEST(PatternVerdicts, BddTracesOnAChartWithoutInputs) {
  const auto both = check_patterns(kLine, {"reachable(S4)", "never(S2)"});
  ASSERT_EQ(both.bdd_report.results.size(), 2u);
  ASSERT_TRUE(both.bdd_report.results[0].trace);
  EXPECT_EQ(both.bdd_report.results[0].trace->steps.size(), 5u);  // S0 .. S4
  ASSERT_TRUE(both.bdd_report.results[1].trace);
  EXPECT_EQ(both.bdd_report.results[1].trace->steps.size(), 3u);  // S0 S1 S2
}

TEST(PatternVerdicts, EnginesAgreeOnRandomPatterns) {
  static const char* unary[] = {"always",     "never",   "infinitely_often", "reachable",
                                "repeatable", "absence", "universality",     "existence"};
  static const char* binary[] = {"implies", "next_cycle", "never_before", "precedence", "response"};
  static const char* scopes[] = {
      "", ", before R", ", after Q", ", between Q and R", ", after Q until R", ", within 2 cycles"};
  int verdicts = 0, holds = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto chart = bench::random_chart_iec(7 + static_cast<std::uint32_t>(seed % 4), 2, seed);
    auto loaded = io::load_iec_text(chart, "generated.st");
    ASSERT_TRUE(loaded.ok());
    model::Diagnostics diags;
    const auto ts = semantics::make_iec61131_system(*loaded.project, {}, diags);
    ASSERT_TRUE(ts);
    std::vector<std::string> steps;
    for (const auto& o : ts->observables())
      if (o.kind == semantics::ObservableKind::Step) steps.push_back(o.name);
    std::mt19937_64 rng(seed);
    auto atom = [&] {
      const auto& a = steps[rng() % steps.size()];
      return rng() % 3 == 0 ? "!" + a : a;
    };
    auto with = [&](std::string s, const char* letter, const std::string& by) {
      if (const auto at = s.find(letter); at != std::string::npos) s.replace(at, 1, by);
      return s;
    };
    std::vector<std::string> patterns;
    for (int i = 0; i < 24; ++i) {
      const bool two = rng() % 2 == 0;
      std::string scope = scopes[rng() % 6];
      const std::string name = two ? binary[rng() % 5] : unary[rng() % 8];
      const bool scoped = name == "absence" || name == "universality" || name == "existence" ||
                          name == "precedence" || name == "response";
      if (!scoped || (scope.find("within") != std::string::npos && name != "response"))
        scope.clear();
      scope = with(with(scope, "R", atom()), "Q", atom());  // R first: names contain R
      patterns.push_back(name + "(" + atom() + (two ? ", " + atom() : "") + scope + ")");
    }
    const auto both = check_patterns(chart, patterns);
    ASSERT_EQ(both.explicit_report.results.size(), both.bdd_report.results.size());
    for (std::size_t k = 0; k < both.explicit_report.results.size(); ++k) {
      const auto& e = both.explicit_report.results[k];
      SCOPED_TRACE(patterns[k] + " = " + e.formula);
      EXPECT_EQ(e.verdict, both.bdd_report.results[k].verdict);
      ++verdicts;
      holds += e.verdict == logic::Verdict::Holds;
    }
  }
  EXPECT_GT(holds, 30);
  EXPECT_GT(verdicts - holds, 30);
}

}  // namespace
}  // namespace sfcv::engine

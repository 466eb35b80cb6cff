// Successor generation (docs/semantics.md, Part 1, "Successors"): grouped by exact input
// conditions, integer inputs split by comparisons, assumptions, POU selection, plant models.

#include <algorithm>
#include <deque>
#include <set>

#include "io/load.hpp"
#include "semantics/iec_builder.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

TEST(Iec61131Successors, ConditionsAreExactAndMergedByTarget) {
  IecBuilder b("VAR_INPUT a, b, c : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "(a AND b) OR c");
  auto ts = b.build();
  auto c = successors_of(*ts, Runner(*ts).state());
  ASSERT_EQ(c.all.size(), 2u);
  EXPECT_EQ(c.all[0].condition, "!a & !c | a & !b & !c");
  EXPECT_TRUE(c.all[0].fired.empty());
  EXPECT_EQ(c.all[1].condition, "!a & c | a & !b & c | a & b");
  EXPECT_EQ(c.all[1].fired, (std::vector<std::uint32_t>{0}));
}

TEST(Iec61131Successors, OnlyInputsTheCycleReadsAppear) {
  IecBuilder b("VAR_INPUT a, b, c, d, e : BOOL; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "a").trans("S2", "S1", "e");
  auto ts = b.build();
  auto c = successors_of(*ts, Runner(*ts).state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!a", "a"}));
}

TEST(Iec61131Successors, IntegerInputsSplitIntoTheIntervalsOfTheirComparisons) {
  IecBuilder b("VAR_INPUT level : INT; END_VAR");
  b.step("S1", true).step("S2").step("S3");
  b.trans("S1", "S2", "level > 100").trans("S1", "S3", "5 = level");
  auto ts = b.build();
  auto c = successors_of(*ts, Runner(*ts).state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"level <= 4 | 6 <= level <= 100", "level = 5",
                                                     "level >= 101"}));
}

TEST(Iec61131Successors, IntegerInputComparedWithAVariableSplitsAtItsCurrentValue) {
  IecBuilder b("VAR_INPUT level : INT; END_VAR VAR limit : INT := 50; END_VAR");
  b.step("S1", true).step("S2").trans("S1", "S2", "limit < level").trans("S2", "S1", "TRUE");
  b.action_st("Up", "limit := limit + 10;").assoc("S2", "Up", "N");
  auto ts = b.build();
  Runner r(*ts);
  EXPECT_EQ(conditions(successors_of(*ts, r.state())),
            (std::vector<std::string>{"level <= 50", "level >= 51"}));
  ASSERT_TRUE(r.cycle({{"level", 51}}));
  ASSERT_TRUE(r.cycle());  // Up runs: limit = 60
  EXPECT_EQ(conditions(successors_of(*ts, r.state())),
            (std::vector<std::string>{"level <= 60", "level >= 61"}));
}

TEST(Iec61131Successors, ManyDistinctTargetsAreMergedCorrectly) {
  IecBuilder b("VAR_INPUT sel : INT(0..999); END_VAR VAR_OUTPUT x : INT; END_VAR");
  b.step("S1", true).action_st("Copy", "x := sel MOD 10;").assoc("S1", "Copy", "N");
  auto ts = b.build();
  auto c = successors_of(*ts, Runner(*ts).state());
  ASSERT_EQ(c.all.size(), 10u);
  std::size_t cubes = 0;
  for (const auto& s : c.all)
    cubes += static_cast<std::size_t>(std::count(s.condition.begin(), s.condition.end(), '|')) + 1;
  EXPECT_EQ(cubes, 1000u);
  EXPECT_EQ(c.all[3].condition.substr(0, 22), "sel = 3 | sel = 13 | s");
  // A second call on the same system gives the same answer (scratch reuse).
  auto again = successors_of(*ts, Runner(*ts).state());
  EXPECT_EQ(conditions(again), conditions(c));
}

TEST(Iec61131Successors, IntegerInputsCopiedIntoTheStateAreEnumeratedWithinTheirRange) {
  IecBuilder b("VAR_INPUT sel : INT(0..3); END_VAR VAR_OUTPUT x : INT; END_VAR");
  b.step("S1", true).action_st("Copy", "x := sel * 2;").assoc("S1", "Copy", "N");
  auto ts = b.build();
  auto c = successors_of(*ts, Runner(*ts).state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"sel = 0", "sel = 1", "sel = 2", "sel = 3"}));
}

TEST(Iec61131Successors, TooWideAnEnumerationIsAnErrorNotAHang) {
  IecBuilder b("VAR_INPUT sel : INT; END_VAR VAR_OUTPUT x : INT; END_VAR");
  b.step("S1", true).action_st("Copy", "x := sel;").assoc("S1", "Copy", "N");
  auto ts = b.build();
  Collector c(*ts);
  EXPECT_THROW(ts->successors(Runner(*ts).state(), c), semantics::SemanticsLimitError);
  // Simulation follows given values and has no such limit.
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"sel", 12345}}));
  EXPECT_EQ(r["x"], 12345);
}

TEST(Iec61131Successors, AssumptionsRemoveBehaviour) {
  IecBuilder b("VAR_INPUT full, empty : BOOL; END_VAR VAR_OUTPUT v : BOOL; END_VAR");
  b.step("S1", true).step("S2").step("S3");
  b.trans("S1", "S2", "full").trans("S2", "S3", "empty").trans("S3", "S1", "TRUE");
  b.action_var("A", "v").assoc("S2", "A", "N");
  semantics::Iec61131Options o;
  model::Diagnostics d;
  o.assumptions.push_back(io::parse_st_expression("NOT (full AND empty)", {}, d));
  o.assumptions.push_back(io::parse_st_expression("NOT S2.X OR NOT full", {}, d));  // on state too
  auto ts = b.build(o);
  Runner r(*ts);
  auto c = successors_of(*ts, r.state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!full", "full & !empty"}));
  ASSERT_TRUE(r.cycle({{"full", 1}}));
  c = successors_of(*ts, r.state());
  EXPECT_EQ(conditions(c), (std::vector<std::string>{"!full & !empty", "!full & empty"}));
  EXPECT_FALSE(r.cycle({{"full", 1}}));
  EXPECT_NE(r.error.find("assumption"), std::string::npos);
}

TEST(Iec61131Successors, ManyAlternativesCostLinearlyNotExponentially) {
  std::string vars = "VAR_INPUT ";
  for (int i = 0; i < 64; ++i)
    vars += "i" + std::to_string(i) + (i < 63 ? ", " : " : BOOL; END_VAR");
  IecBuilder b(vars);
  b.step("S", true);
  for (int i = 0; i < 64; ++i) b.step("T" + std::to_string(i));
  for (int i = 0; i < 64; ++i) b.trans("S", "T" + std::to_string(i), "i" + std::to_string(i));
  auto ts = b.build();
  auto c = successors_of(*ts, Runner(*ts).state());
  ASSERT_EQ(c.all.size(), 65u);
  EXPECT_EQ(c.all[64].condition, "i0");
}

TEST(Iec61131Successors, PouSelection) {
  IecBuilder b("VAR_INPUT a : BOOL; END_VAR", "P1");
  b.step("S1", true);
  model::Pou second = b.pou();
  second.name = "P2";
  b.project.pous.push_back(second);
  // Two PROGRAMs: both run, in document order.
  {
    auto both = b.build();
    ASSERT_TRUE(both);
    int steps = 0;
    for (const auto& o : both->observables())
      if (o.kind == semantics::ObservableKind::Step) ++steps;
    EXPECT_EQ(steps, 2);
  }
  // Two function blocks with SFC bodies: which one runs is the user's choice.
  for (auto& q : b.project.pous) q.kind = model::PouKind::FunctionBlock;
  const auto err = b.build_error();
  EXPECT_NE(err.find("P1, P2"), std::string::npos);
  EXPECT_NE(err.find("--pou"), std::string::npos);
  semantics::Iec61131Options o;
  o.pous = {"P2"};
  EXPECT_TRUE(b.build(o));
  o.pous = {"P3"};
  EXPECT_NE(b.build_error(o).find("no POU named 'P3'"), std::string::npos);
}

TEST(Iec61131Successors, APlantModelRunsInTheSameCycleConnectedByName) {
  // Controller: fills while not full. Plant: the level rises while the valve is open.
  IecBuilder b("VAR_INPUT full : BOOL; END_VAR VAR_OUTPUT valve : BOOL; END_VAR", "Ctrl");
  b.step("Fill", true).step("Done").trans("Fill", "Done", "full");
  b.action_var("Open", "valve").assoc("Fill", "Open", "N");
  model::Pou plant;
  plant.name = "Plant";
  plant.kind = model::PouKind::Program;
  model::Diagnostics d;
  plant.variables = io::parse_var_sections(
      "VAR_INPUT valve : BOOL; END_VAR VAR_OUTPUT full : BOOL; END_VAR VAR level : INT(0..3); "
      "END_VAR",
      {}, d);
  plant.body = io::parse_st_statements(
      "IF valve AND level < 3 THEN level := level + 1; END_IF; full := level >= 2;", {}, d);
  ASSERT_FALSE(model::has_errors(d));
  b.project.pous.push_back(plant);
  semantics::Iec61131Options o;
  o.pous = {"Ctrl", "Plant"};
  auto ts = b.build(o);
  EXPECT_TRUE(ts->inputs().empty());  // both inputs are connected outputs
  Runner r(*ts);
  std::string s;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(r.cycle());
    s += std::to_string(r["Done"]) + std::to_string(r["valve"]) + std::to_string(r["level"]) + " ";
  }
  // The plant sees the valve as the controller left it in the same cycle (closed in cycle 3,
  // so the level stays 2); the controller sees `full` as the plant left it in the previous cycle.
  EXPECT_EQ(s, "011 012 102 102 ");
}

// The seed's case study: explore every reachable configuration of the example.
TEST(Iec61131Successors, ChemicalPlantExampleHasTheSeedsVerdicts) {
  auto loaded = io::load_file(source_path("examples/chemical_plant/chemical_plant.st"));
  ASSERT_TRUE(loaded.ok()) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics.front().str());
  model::Diagnostics d;
  auto ts = semantics::make_iec61131_system(*loaded.project, {}, d);
  ASSERT_TRUE(ts);
  std::set<std::vector<semantics::StateWord>> seen;
  std::deque<std::vector<semantics::StateWord>> todo;
  auto start = semantics::first_initial_state(*ts);
  seen.insert(start);
  todo.push_back(start);
  struct Sink : semantics::SuccessorSink {
    std::vector<std::vector<semantics::StateWord>> out;
    void successor(const semantics::Successor& s) override {
      out.emplace_back(s.target.begin(), s.target.end());
    }
  };
  const auto v1 = obs(*ts, "V1");
  const auto v2 = obs(*ts, "V2");
  const auto v3 = obs(*ts, "V3");
  const auto v4 = obs(*ts, "V4");
  bool v1v3 = false, v2v4 = false;
  std::set<std::uint32_t> steps_seen;
  while (!todo.empty()) {
    auto s = todo.front();
    todo.pop_front();
    v1v3 |= ts->observe(s, v1) && ts->observe(s, v3);
    v2v4 |= ts->observe(s, v2) && ts->observe(s, v4);
    for (std::uint32_t i = 0; i < ts->observables().size(); ++i)
      if (ts->observables()[i].kind == semantics::ObservableKind::Step && ts->observe(s, i))
        steps_seen.insert(i);
    Sink sink;
    ts->successors(s, sink);
    for (auto& t : sink.out)
      if (seen.insert(t).second) todo.push_back(t);
  }
  EXPECT_FALSE(v1v3);                 // AG !(V1 & V3) holds
  EXPECT_TRUE(v2v4);                  // AG !(V2 & V4) is violated
  EXPECT_EQ(steps_seen.size(), 13u);  // s1..s10, s11..s13: every step is reachable
}

}  // namespace
}  // namespace sfcv::test

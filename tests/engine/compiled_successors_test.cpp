// The compiled successor function (the scan cycle's circuit evaluated bit-parallel) against the
// interpreter, state by state, on random charts with timers, priorities, nested charts, integer
// ranges and assumptions; and the on-the-fly invariant search against the graph-based checker
// (same verdicts, same shortest counterexamples, same counts when everything is explored).

#include "engine/explicit/compiled_successors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "chart_families.hpp"
#include "engine/explicit/ctl_checker.hpp"
#include "engine/explicit/invariant_search.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "io/load.hpp"
#include "io/st_parser.hpp"
#include "logic/formula.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::engine {
namespace {

using semantics::StateView;
using semantics::StateWord;

struct Loaded {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

std::unique_ptr<Loaded> load(const std::string& text, semantics::Iec61131Options options = {},
                             const std::vector<std::string>& assumptions = {}) {
  auto loaded = io::load_iec_text(text, "test.st");
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) return nullptr;
  auto out = std::make_unique<Loaded>();
  out->project = std::move(*loaded.project);
  model::Diagnostics d;
  for (const auto& a : assumptions)
    options.assumptions.push_back(io::parse_st_expression(a, {}, d));
  out->ts = semantics::make_iec61131_system(out->project, options, d);
  for (const auto& x : d) ADD_FAILURE() << x.str();
  return out->ts ? std::move(out) : nullptr;
}

std::set<std::vector<StateWord>> distinct(const std::vector<StateWord>& flat, std::uint32_t words) {
  std::set<std::vector<StateWord>> r;
  for (std::size_t k = 0; k < flat.size(); k += words)
    r.emplace(flat.begin() + k, flat.begin() + k + words);
  return r;
}

/// Compares the compiled and interpreted successors on every reachable state (up to
/// `max_states`); returns the number of states compared. `merged`, if given, is raised when
/// the compiled enumerator stores some latch once for several (StateCodec).
std::uint32_t expect_same_successors(const semantics::TransitionSystem& ts,
                                     std::uint32_t max_states, std::uint32_t* merged = nullptr) {
  auto compiled = make_compiled_enumerator(ts, model::Budget{});
  EXPECT_TRUE(compiled) << "no compiled successor function";
  if (!compiled) return 0;
  if (merged && compiled->codec()) ++*merged;
  auto interpreted = make_interpreted_enumerator(ts);
  ExplorationOptions opts;
  opts.max_states = max_states;
  opts.keep_conditions = false;
  opts.keep_fired = false;
  const auto graph = build_reachable_situation_graph(ts, opts);
  const auto words = std::max<std::uint32_t>(ts.layout().words(), 1);
  // The compiled enumerator reads and writes its codec's stored form: every reachable state
  // of the interpreter must have one (the latches it merges follow each other there).
  const StateCodec* codec = compiled->codec();
  const auto stored_words = codec ? codec->stored_words() : words;
  auto stored_form = [&](StateView full) {
    if (!codec) return std::vector<StateWord>(full.begin(), full.end());
    std::vector<StateWord> stored(stored_words);
    EXPECT_TRUE(codec->to_stored(full.data(), stored.data()))
        << "a reachable state outside the stored form: " << ts.describe(full);
    return stored;
  };
  auto full_forms = [&](const std::vector<StateWord>& stored) {
    if (!codec) return stored;
    std::vector<StateWord> full(stored.size() / stored_words * words);
    for (std::size_t k = 0; k * stored_words < stored.size(); ++k)
      codec->to_full(stored.data() + k * stored_words, full.data() + k * words);
    return full;
  };
  std::vector<StateWord> a, b;
  std::uint32_t compared = 0;
  for (std::uint32_t s = 0; s < graph.num_states(); ++s) {
    const auto view = graph.states().at(s);
    const std::vector<StateWord> state(view.begin(), view.end());
    a.clear();
    b.clear();
    compiled->targets(stored_form(state), a);
    interpreted->targets(state, b);
    const auto ca = distinct(full_forms(a), words), cb = distinct(b, words);
    EXPECT_EQ(ca, cb) << "successors differ in state " << ts.describe(state);
    if (ca != cb) return compared;
    // The graph (interpreted) has one edge per distinct target.
    if (graph.expanded(s)) {
      EXPECT_EQ(cb.size(), graph.edges_end(s) - graph.edges_begin(s));
    }
    ++compared;
  }
  // Several states at once: the same targets in the same order as state by state, in chunks
  // of every size up to 64 states (so every packing of states into lanes is met).
  std::vector<StateWord> states, one_by_one, together;
  std::vector<std::uint32_t> ends;
  for (std::uint32_t s = 0; s < compared; ++s) {
    const auto stored = stored_form(graph.states().at(s));
    states.insert(states.end(), stored.begin(), stored.end());
  }
  for (std::uint32_t first = 0, size = 1; first < compared; first += size, size = size % 64 + 1) {
    const auto count = std::min(size, compared - first);
    const auto chunk = StateView(states).subspan(static_cast<std::size_t>(first) * stored_words,
                                                 static_cast<std::size_t>(count) * stored_words);
    one_by_one.clear();
    together.clear();
    ends.clear();
    std::vector<std::uint32_t> expected_ends;
    for (std::uint32_t i = 0; i < count; ++i) {
      compiled->targets(chunk.subspan(static_cast<std::size_t>(i) * stored_words, stored_words),
                        one_by_one);
      expected_ends.push_back(static_cast<std::uint32_t>(one_by_one.size()));
    }
    compiled->targets_of(chunk, count, together, ends);
    EXPECT_EQ(together, one_by_one) << "states " << first << " to " << first + count - 1;
    EXPECT_EQ(ends, expected_ends);
    if (together != one_by_one) break;
  }
  return compared;
}

TEST(CompiledSuccessors, AgreeWithTheInterpreterOnRandomCharts) {
  std::uint32_t total = 0, merged = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    // 4 inputs: one pass of 16 lanes; 9 inputs: the per-state support pass and several passes.
    auto m = load(bench::random_chart_iec(14, seed % 2 ? 4 : 9, seed));
    ASSERT_TRUE(m);
    total += expect_same_successors(*m->ts, 3000, &merged);
  }
  EXPECT_GT(total, 400u);  // enough states compared to mean something
  EXPECT_GE(merged, 5u);   // and the stored form met on most charts
}

TEST(CompiledSuccessors, AgreeWithoutPrioritiesAndWithAssumptions) {
  std::uint32_t total = 0;
  for (std::uint64_t seed = 20; seed <= 27; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    semantics::Iec61131Options options;
    if (seed % 2) options.priority = semantics::PriorityMode::None;
    auto m = load(bench::random_chart_iec(12, 5, seed), options,
                  {"NOT (i0 AND i1)", "NOT S2.X OR NOT i2"});
    ASSERT_TRUE(m);
    total += expect_same_successors(*m->ts, 3000);
  }
  EXPECT_GT(total, 120u);
}

TEST(CompiledSuccessors, AgreeWithTimedQualifiersAndNesting) {
  bench::RandomChartFeatures features;
  features.timed_qualifiers = true;
  features.nested_chart = true;
  std::uint32_t total = 0;
  for (std::uint64_t seed = 40; seed <= 49; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    semantics::Iec61131Options options;
    options.time = seed % 2 == 0 ? semantics::TimeMode::Abstract : semantics::TimeMode::Discrete;
    auto m = load(bench::random_chart_iec(12, seed % 3 ? 3 : 8, seed, features), options);
    ASSERT_TRUE(m);
    total += expect_same_successors(*m->ts, 3000);
  }
  EXPECT_GT(total, 300u);
}

// Integer inputs and variables, arithmetic with range errors, counters and timers.
TEST(CompiledSuccessors, AgreeOnIntegerRangesAndFamilies) {
  const char* data = R"(
PROGRAM Data
  VAR_INPUT go, stop : BOOL; level : INT(0..20); END_VAR
  VAR_OUTPUT lamp : BOOL; count : INT(0..7); END_VAR
  VAR t1 : TON; c : CTU; n : INT(-5..5); END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Run: Work(N); lamp(D, T#2s); END_STEP
  STEP Wait: Tick(P1); END_STEP
  ACTION Work:
    t1(IN := go, PT := T#500ms);
    c(CU := go, R := stop, PV := 3);
    IF level > n + 8 THEN n := n + 1; ELSIF level = 3 THEN n := n - 1; END_IF;
  END_ACTION
  ACTION Tick: count := count + 1; END_ACTION
  TRANSITION FROM Idle TO Run := go AND NOT stop; END_TRANSITION
  TRANSITION FROM Run TO Wait := t1.Q OR c.Q; END_TRANSITION
  TRANSITION FROM Wait TO Idle := level < 4; END_TRANSITION
END_PROGRAM
)";
  for (auto time : {semantics::TimeMode::Abstract, semantics::TimeMode::Discrete}) {
    semantics::Iec61131Options options;
    options.time = time;
    options.cycle_ms = 250;
    auto m = load(data, options, {"level <> 7"});
    ASSERT_TRUE(m);
    EXPECT_GT(expect_same_successors(*m->ts, 3000), 20u);
  }
  auto tanks = load(bench::tanks_iec(2, true));
  ASSERT_TRUE(tanks);
  EXPECT_GT(expect_same_successors(*tanks->ts, 3000), 50u);
  auto selector = load(bench::parallel_branches_iec(5, true));
  ASSERT_TRUE(selector);
  EXPECT_EQ(expect_same_successors(*selector->ts, 3000), 33u);
  auto nested = load(bench::nested_charts_iec(3));
  ASSERT_TRUE(nested);
  EXPECT_GT(expect_same_successors(*nested->ts, 3000), 5u);
}

// ------------------------------------------------------------------ the on-the-fly search

logic::Property invariant(const semantics::TransitionSystem& ts, const std::string& a,
                          const std::string& b) {
  auto atom = [&](const std::string& name) {
    const auto i = semantics::find_observable(ts, name);
    EXPECT_TRUE(i) << name;
    auto f = logic::make_atom(name);
    return logic::with_observable(*f, static_cast<std::int32_t>(i.value_or(0)));
  };
  logic::Property p;
  p.name = "AG !(" + a + " & " + b + ")";
  p.formula = logic::make_op(logic::Op::AG, {logic::make_not(logic::make_and(atom(a), atom(b)))});
  return p;
}

/// The report of a threaded search against the one-thread one: everything equal.
void expect_same_report(const logic::CheckReport& threaded, const logic::CheckReport& single) {
  SCOPED_TRACE("threaded against one thread");
  EXPECT_EQ(threaded.states, single.states);
  EXPECT_EQ(threaded.edges, single.edges);
  EXPECT_EQ(threaded.depth, single.depth);
  EXPECT_EQ(threaded.complete, single.complete);
  EXPECT_EQ(threaded.limit, single.limit);
  ASSERT_EQ(threaded.results.size(), single.results.size());
  for (std::size_t i = 0; i < single.results.size(); ++i) {
    const auto& a = threaded.results[i];
    const auto& b = single.results[i];
    EXPECT_EQ(a.verdict, b.verdict) << b.name;
    EXPECT_EQ(a.message, b.message) << b.name;
    ASSERT_EQ(a.trace.has_value(), b.trace.has_value()) << b.name;
    if (!b.trace) continue;
    ASSERT_EQ(a.trace->steps.size(), b.trace->steps.size()) << b.name;
    for (std::size_t k = 0; k < b.trace->steps.size(); ++k) {
      EXPECT_EQ(a.trace->steps[k].state, b.trace->steps[k].state) << k;
      EXPECT_EQ(a.trace->steps[k].inputs, b.trace->steps[k].inputs) << k;
    }
  }
}

void expect_same_results(const semantics::TransitionSystem& ts,
                         const std::vector<logic::Property>& props, std::uint64_t max_states,
                         std::uint32_t& violated, std::uint32_t& held) {
  logic::CheckTask task;
  task.system = &ts;
  task.properties = props;
  task.limits.max_states = max_states;
  ASSERT_TRUE(invariants_only(task));
  auto compiled = make_compiled_enumerator(ts, model::Budget{});
  const auto fast = check_invariants(task, compiled.get());
  const auto slow = check_invariants(task);  // interpreted successors
  expect_same_report(check_invariants(task, compiled.get(), 3), fast);
  ExplorationOptions opts;
  opts.max_states = max_states;
  const auto graph = build_reachable_situation_graph(ts, opts);
  CtlChecker checker(graph);
  bool all_hold = true;
  for (std::size_t i = 0; i < props.size(); ++i) {
    SCOPED_TRACE(props[i].name);
    const auto r = checker.check(props[i]);
    for (const auto* x : {&fast.results[i], &slow.results[i]}) {
      EXPECT_EQ(x->verdict, r.verdict);
      EXPECT_EQ(x->message, r.message);
      ASSERT_EQ(x->trace.has_value(), r.trace.has_value());
      if (!r.trace) continue;
      ASSERT_EQ(x->trace->steps.size(), r.trace->steps.size());
      for (std::size_t k = 0; k < r.trace->steps.size(); ++k) {
        EXPECT_EQ(x->trace->steps[k].state, r.trace->steps[k].state) << k;
        EXPECT_EQ(x->trace->steps[k].inputs, r.trace->steps[k].inputs) << k;
        EXPECT_EQ(x->trace->steps[k].fired, r.trace->steps[k].fired) << k;
      }
      EXPECT_EQ(x->trace->marked, r.trace->marked);
    }
    all_hold &= r.verdict == logic::Verdict::Holds;
    violated += r.verdict == logic::Verdict::Violated;
    held += r.verdict == logic::Verdict::Holds;
  }
  if (all_hold) {  // everything explored: the same counts
    EXPECT_EQ(fast.states, graph.num_states());
    EXPECT_EQ(fast.edges, graph.num_edges());
    EXPECT_EQ(slow.edges, graph.num_edges());
  }
}

TEST(InvariantSearch, AgreesWithTheGraphCheckerOnRandomCharts) {
  std::uint32_t violated = 0, held = 0;
  std::mt19937_64 rng(5);
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    bench::RandomChartFeatures features;
    features.timed_qualifiers = seed % 3 == 0;
    features.nested_chart = seed % 4 == 0;
    auto m = load(bench::random_chart_iec(10, seed % 2 ? 3 : 7, seed, features));
    ASSERT_TRUE(m);
    std::vector<logic::Property> props;
    for (int k = 0; k < 3; ++k)
      props.push_back(
          invariant(*m->ts, "S" + std::to_string(rng() % 10), "S" + std::to_string(rng() % 10)));
    props.push_back(invariant(*m->ts, "S0", "S0"));
    expect_same_results(*m->ts, props, 0, violated, held);
    // A state limit: verdicts and counterexamples still agree.
    expect_same_results(*m->ts, props, 20, violated, held);
  }
  EXPECT_GT(violated, 10u);
  EXPECT_GT(held, 3u);
}

TEST(InvariantSearch, AgreesWithTheGraphCheckerOnNestedSteps) {
  // A nested step is active while it is ready and its chart's action is active: the search
  // memoises verdicts on both fields' bits (TransitionSystem::observed_fields()).
  auto m = load(bench::nested_charts_iec(3));
  ASSERT_TRUE(m);
  const auto& ts = *m->ts;
  std::uint32_t violated = 0, held = 0;
  const char* pairs[][2] = {{"L0_B", "L1_A"}, {"L1_B", "L2_A"}, {"L0_B", "L2_B"}, {"L2_A", "L2_B"}};
  for (const auto& [a, b] : pairs)
    expect_same_results(ts, {invariant(ts, a, b)}, 0, violated, held);
  // AG (L1_A | L1_B): it holds in the initial state, where L1_A is ready and A1 active, and
  // fails once L0_B has suspended A1 with L1_A still ready. The ready bits alone do not decide.
  // (The compiled successors order a state's targets by input valuation, the interpreter by
  // its input decisions: the searches may end at different violations, of the same depth.)
  for (const char* level : {"1", "2"}) {
    const std::string a = std::string("L") + level + "_A", b = std::string("L") + level + "_B";
    const auto oa = *semantics::find_observable(ts, a), ob = *semantics::find_observable(ts, b);
    logic::CheckTask task;
    task.system = &ts;
    task.properties.resize(1);
    task.properties[0].name = "AG (" + a + " | " + b + ")";
    task.properties[0].formula = logic::make_op(
        logic::Op::AG,
        {logic::make_or(
            logic::with_observable(*logic::make_atom(a), static_cast<std::int32_t>(oa)),
            logic::with_observable(*logic::make_atom(b), static_cast<std::int32_t>(ob)))});
    auto compiled = make_compiled_enumerator(ts, model::Budget{});
    const auto fast = check_invariants(task, compiled.get());
    const auto slow = check_invariants(task);  // interpreted successors
    for (const auto* report : {&fast, &slow}) {
      const auto& r = report->results[0];
      ASSERT_EQ(r.verdict, logic::Verdict::Violated) << task.properties[0].name;
      ASSERT_TRUE(r.trace);
      EXPECT_EQ(r.trace->steps.size(), slow.results[0].trace->steps.size());
      const auto& last = r.trace->steps.back().state;
      EXPECT_EQ(ts.observe(last, oa) + ts.observe(last, ob), 0);
    }
    ++violated;
  }
  EXPECT_EQ(violated, 2u);  // the nested-step pairs above all hold
  EXPECT_GE(held, 2u);
}

// Charts large enough for many batches of the threaded search (4096 states each), with
// violations found deep in the search, mid-batch state limits and complete explorations.
/// A compiled enumerator that meets the deadline at one chosen state, on every thread, and
/// may record the sources it is asked for (on one thread: the states in BFS order).
class DeadlineAt final : public TargetEnumerator {
 public:
  using State = std::vector<StateWord>;
  DeadlineAt(std::unique_ptr<TargetEnumerator> inner, State at, std::vector<State>* asked = nullptr)
      : inner_(std::move(inner)), at_(std::move(at)), asked_(asked) {}
  void targets(StateView state, std::vector<StateWord>& out) override {
    if (asked_) asked_->emplace_back(state.begin(), state.end());
    if (std::equal(state.begin(), state.end(), at_.begin(), at_.end()))
      throw LimitReached(Limit::Time, "time limit reached (test)");
    inner_->targets(state, out);
  }
  std::unique_ptr<TargetEnumerator> clone() const override {
    return std::make_unique<DeadlineAt>(inner_->clone(), at_);
  }
  const StateCodec* codec() const override { return inner_->codec(); }

 private:
  std::unique_ptr<TargetEnumerator> inner_;
  State at_;  ///< none when empty
  std::vector<State>* asked_;
};

// A limit met inside a worker's enumeration: the chunk is enumerated again on the search's
// thread, which meets it at the same state, so the search stops where one thread stops.
TEST(InvariantSearch, ThreadsStopAtTheStateWhoseEnumerationMeetsALimit) {
  auto broad = load(bench::parallel_branches_iec(16, true));
  ASSERT_TRUE(broad);
  const auto& ts = *broad->ts;
  logic::CheckTask task;
  task.system = &ts;
  task.properties = {invariant(ts, "A0", "B0")};
  std::vector<DeadlineAt::State> bfs;
  {
    DeadlineAt recording(make_compiled_enumerator(ts, model::Budget{}), {}, &bfs);
    ASSERT_EQ(check_invariants(task, &recording, 1).states, 65537u);
  }
  ASSERT_EQ(bfs.size(), 65537u);
  // Past the first blocks, where the workers enumerate ahead of the search.
  for (const std::size_t index : {std::size_t{20000}, std::size_t{40000}}) {
    SCOPED_TRACE(index);
    DeadlineAt failing(make_compiled_enumerator(ts, model::Budget{}), bfs[index]);
    const auto single = check_invariants(task, &failing, 1);
    EXPECT_EQ(single.limit, "time");
    EXPECT_FALSE(single.complete);
    EXPECT_EQ(single.results[0].verdict, logic::Verdict::Unknown);
    for (unsigned threads : {2U, 4U}) {
      SCOPED_TRACE(std::to_string(threads) + " threads");
      expect_same_report(check_invariants(task, &failing, threads), single);
    }
  }
}

TEST(InvariantSearch, ThreadsGiveTheOneThreadResults) {
  auto selector = load(bench::parallel_branches_iec(14, true));
  auto tanks = load(bench::tanks_iec(3, true));
  auto wide = load(bench::parallel_branches_iec(40, true));
  // Levels wider than a batch: the workers enumerate the next batch while one is committed.
  auto broad = load(bench::parallel_branches_iec(16, true));
  ASSERT_TRUE(selector && tanks && wide && broad);
  ASSERT_GT(wide->ts->layout().words(), 1u);
  struct Case {
    const semantics::TransitionSystem* ts;
    std::vector<logic::Property> props;
    std::uint64_t max_states;
  };
  const auto& p = *selector->ts;
  std::vector<Case> cases = {
      {&p, {invariant(p, "A0", "B0")}, 0},                             // holds: all 16385 states
      {&p, {invariant(p, "A0", "B0")}, 9000},                          // a limit inside a batch
      {&p, {invariant(p, "B0", "B13"), invariant(p, "A0", "B0")}, 0},  // one violated at depth 3
      {tanks->ts.get(), {invariant(*tanks->ts, "FB_0", "EB_0")}, 0},
      // States of two words; limits inside the sixth batch and exactly at a batch's end.
      {wide->ts.get(), {invariant(*wide->ts, "A0", "B0")}, 25000},
      {wide->ts.get(), {invariant(*wide->ts, "A0", "B0")}, 4096},
      {broad->ts.get(), {invariant(*broad->ts, "A0", "B0")}, 0},  // holds: all 65537 states
      {broad->ts.get(), {invariant(*broad->ts, "A0", "B0")}, 30000},
  };
  // State limits falling anywhere: between two sources, after a source's last new state,
  // before one of its repeated targets, at the last state.
  for (std::uint64_t limit : {4097U, 4098U, 5000U, 8191U, 12345U, 16384U, 16385U, 16386U})
    cases.push_back({&p, {invariant(p, "A0", "B0")}, limit});
  for (std::uint64_t limit : {100U, 700U, 729U, 730U, 1000U})
    cases.push_back({tanks->ts.get(), {invariant(*tanks->ts, "FB_0", "EB_0")}, limit});
  std::uint32_t complete = 0, violated = 0;
  for (const auto& c : cases) {
    logic::CheckTask task;
    task.system = c.ts;
    task.properties = c.props;
    task.limits.max_states = c.max_states;
    auto compiled = make_compiled_enumerator(*c.ts, model::Budget{});
    ASSERT_TRUE(compiled);
    const auto single = check_invariants(task, compiled.get(), 1);
    for (unsigned threads : {2U, 4U}) {
      SCOPED_TRACE(std::to_string(threads) + " threads");
      expect_same_report(check_invariants(task, compiled.get(), threads), single);
    }
    complete += single.complete;
    for (const auto& r : single.results) violated += r.verdict == logic::Verdict::Violated;
  }
  EXPECT_GE(complete, 3u);
  EXPECT_GE(violated, 1u);
  EXPECT_EQ(check_invariants(
                [&] {
                  logic::CheckTask t;
                  t.system = selector->ts.get();
                  t.properties = {invariant(p, "A0", "B0")};
                  return t;
                }(),
                nullptr, 4)
                .states,
            16385u);
}

}  // namespace
TEST(CompiledSuccessors, StoresALatchThatFollowsAnotherOnce) {
  // Each branch's step B_i, the activity of its N action and the output O_i it drives take
  // the same next value and start at FALSE: one stored bit for the three.
  auto m = load(bench::parallel_branches_iec(16, true));
  ASSERT_TRUE(m);
  auto compiled = make_compiled_enumerator(*m->ts, model::Budget{});
  ASSERT_TRUE(compiled);
  const StateCodec* codec = compiled->codec();
  ASSERT_TRUE(codec);
  EXPECT_EQ(m->ts->layout().words(), 2u);
  EXPECT_EQ(codec->stored_words(), 1u);
  EXPECT_EQ(codec->stored_bits(), m->ts->layout().bits() - 2 * 16);
  // The search on the stored form: the counts of the full one.
  logic::CheckTask task;
  task.system = m->ts.get();
  task.properties = {invariant(*m->ts, "A0", "B0")};
  const auto report = check_invariants(task, compiled.get());
  EXPECT_EQ(report.states, 65537u);
  EXPECT_EQ(report.edges, 1048577u);
  EXPECT_EQ(report.results[0].verdict, logic::Verdict::Holds);
}

TEST(StateCodec, StoresFollowersOnceAndRejectsStatesWhereTheyDoNotFollow) {
  // Full state of 4 bits: bit 0 stored; bit 2 follows it, bit 3 is its opposite; bit 1 is
  // always set. Stored: 1 bit.
  const StateCodec codec(1, 1, {{0, 0, false}, {0, 2, false}, {0, 3, true}}, {0b0010});
  StateWord full = 0, stored = 0;
  codec.to_full(&stored, &full);
  EXPECT_EQ(full, 0b1010U);
  stored = 1;
  codec.to_full(&stored, &full);
  EXPECT_EQ(full, 0b0111U);
  EXPECT_TRUE(codec.to_stored(&full, &stored));
  EXPECT_EQ(stored, 1U);
  for (StateWord bad : {0b0011U, 0b0101U, 0b1111U, 0b0110U, 0b10111U})
    EXPECT_FALSE(codec.to_stored(&bad, &stored)) << bad;
}

}  // namespace sfcv::engine

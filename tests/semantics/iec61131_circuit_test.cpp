// The circuit of the scan cycle against the explicit successor function: for every reachable
// state and many input valuations, the circuit's next state must be the explicit successor.

#include "semantics/iec61131_circuit.hpp"

#include <gtest/gtest.h>

#include <random>

#include "chart_families.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::semantics {
namespace {

struct Collect final : SuccessorSink {
  struct Entry {
    std::vector<StateWord> target;
    InputCondition condition;
    std::vector<std::uint32_t> fired;
  };
  std::vector<Entry> entries;
  bool anomalies = false;
  void successor(const Successor& s) override {
    entries.push_back(
        {{s.target.begin(), s.target.end()}, s.condition, {s.fired.begin(), s.fired.end()}});
  }
  void anomaly(const Anomaly&) override { anomalies = true; }
};

TransitionSystemPtr system_for(const std::string& text, Iec61131Options options = {}) {
  auto loaded = io::load_iec_text(text, "test.st");
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) {
    for (const auto& d : loaded.diagnostics) ADD_FAILURE() << d.str();
    return nullptr;
  }
  model::Diagnostics diags;
  auto ts = make_iec61131_system(*loaded.project, options, diags);
  // The note listing variables read as inputs (docs/semantics.md 1.8) is expected: the circuit
  // must agree with the machine on them too.
  for (const auto& d : diags)
    if (d.severity != model::Severity::Note ||
        d.message.find("no POU of the run writes") == std::string::npos)
      ADD_FAILURE() << d.str();
  return ts;
}

// Compares circuit and explicit successors on every reachable state (up to `max_states`).
void expect_agreement(const TransitionSystem& ts, std::uint32_t max_states, std::uint64_t seed) {
  const auto circuit = build_iec61131_circuit(ts);

  engine::ExplorationOptions opts;
  opts.max_states = max_states;
  const auto graph = engine::build_reachable_situation_graph(ts, opts);
  std::mt19937_64 rng(seed);
  const auto& aig = circuit.aig;
  const auto& layout = ts.layout();

  // The initial latch values are the explicit initial state.
  {
    std::vector<bool> init;
    for (const auto& l : aig.latches()) init.push_back(l.initial);
    EXPECT_EQ(state_from_latches(ts, circuit, init),
              std::vector<StateWord>(graph.states().at(graph.initial_states()[0]).begin(),
                                     graph.states().at(graph.initial_states()[0]).end()));
  }
  for (std::uint32_t s = 0; s < graph.num_states(); ++s) {
    const auto state = graph.states().at(s);
    Collect succ;
    ts.successors(state, succ);
    std::vector<bool> latches(aig.latches().size());
    for (std::uint32_t f = 0; f < circuit.field_latches.size(); ++f) {
      const auto v = static_cast<std::uint64_t>(layout.get(state, f) - layout.fields()[f].lo);
      for (std::size_t k = 0; k < circuit.field_latches[f].size(); ++k)
        latches[circuit.field_latches[f][k]] = ((v >> k) & 1U) != 0;
    }
    for (int trial = 0; trial < 16; ++trial) {
      std::vector<bool> bits(aig.inputs().size());
      for (std::size_t i = 0; i < bits.size(); ++i) bits[i] = (rng() & 1U) != 0;
      // Half of the trials use the witness of a successor, to cover rare conditions.
      if (trial % 2 == 1 && !succ.entries.empty()) {
        const auto& e = succ.entries[rng() % succ.entries.size()];
        const auto w = e.condition.witness(ts.inputs());
        for (std::size_t i = 0; i < w.size(); ++i) {
          const auto& t = ts.inputs()[i].type;
          const std::int64_t lo = t.kind == model::TypeKind::Bool ? 0 : t.lo;
          const auto enc = static_cast<std::uint64_t>(w[i] - lo);
          for (std::size_t k = 0; k < circuit.input_bits[i].size(); ++k)
            bits[aig.nodes()[Aig::node_of(circuit.input_bits[i][k])].index] =
                ((enc >> k) & 1U) != 0;
        }
      }
      const auto nodes = aig.evaluate(bits, latches);
      if (!Aig::value_of(nodes, circuit.allowed)) continue;
      const auto valuation = inputs_from_bits(ts, circuit, bits);
      const bool error = Aig::value_of(nodes, circuit.range_error);
      const Collect::Entry* match = nullptr;
      for (const auto& e : succ.entries)
        if (e.condition.holds(valuation)) {
          ASSERT_EQ(match, nullptr) << "two successors for one valuation";
          match = &e;
        }
      if (error) {
        EXPECT_EQ(match, nullptr) << "the circuit raises a range error, the machine does not";
        continue;
      }
      ASSERT_NE(match, nullptr) << "no explicit successor in state " << ts.describe(state);
      std::vector<bool> next(aig.latches().size());
      for (std::size_t l = 0; l < next.size(); ++l)
        next[l] = Aig::value_of(nodes, aig.latches()[l].next);
      EXPECT_EQ(state_from_latches(ts, circuit, next), match->target)
          << "from " << ts.describe(state) << " expected " << ts.describe(match->target);
      std::vector<std::uint32_t> fired;
      for (std::uint32_t t = 0; t < circuit.fired.size(); ++t)
        if (Aig::value_of(nodes, circuit.fired[t])) fired.push_back(t);
      EXPECT_EQ(fired, match->fired);
      for (std::uint32_t o = 0; o < ts.observables().size(); ++o) {
        std::uint64_t v = 0;
        for (std::size_t k = 0; k < circuit.observable_bits[o].size(); ++k)
          if (Aig::value_of(nodes, circuit.observable_bits[o][k])) v |= 1ULL << k;
        EXPECT_EQ(static_cast<std::int64_t>(v) + circuit.observable_lo[o], ts.observe(state, o))
            << ts.observables()[o].name;
      }
    }
  }
}

// expect_agreement on `text` in both time modes (discrete time adds the timers' elapsed
// cycles to the state).
void expect_agreement_in_both_time_modes(const char* text, std::uint32_t max_states,
                                         std::uint64_t seed, std::uint32_t cycle_ms = 500) {
  for (auto time : {TimeMode::Abstract, TimeMode::Discrete}) {
    SCOPED_TRACE(time == TimeMode::Abstract ? "abstract time" : "discrete time");
    Iec61131Options options;
    options.time = time;
    options.cycle_ms = cycle_ms;
    auto ts = system_for(text, options);
    ASSERT_TRUE(ts);
    expect_agreement(*ts, max_states, seed);
  }
}

TEST(Iec61131Circuit, AgreesWithTheMachineOnRandomCharts) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("random chart seed " + std::to_string(seed));
    auto ts = system_for(bench::random_chart_iec(14, 4, seed));
    ASSERT_TRUE(ts);
    expect_agreement(*ts, 3000, seed);
  }
}

TEST(Iec61131Circuit, AgreesWithoutPriorities) {
  for (std::uint64_t seed = 20; seed <= 26; ++seed) {
    SCOPED_TRACE("random chart seed " + std::to_string(seed));
    Iec61131Options options;
    options.priority = PriorityMode::None;
    auto ts = system_for(bench::random_chart_iec(12, 3, seed), options);
    ASSERT_TRUE(ts);
    expect_agreement(*ts, 3000, seed);
  }
}

// Timed qualifiers (L, D, SD, DS, SL) and a nested chart started and stopped by steps, in
// abstract and in discrete time.
TEST(Iec61131Circuit, AgreesWithTimedQualifiersAndNesting) {
  bench::RandomChartFeatures features;
  features.timed_qualifiers = true;
  features.nested_chart = true;
  for (std::uint64_t seed = 40; seed <= 51; ++seed) {
    SCOPED_TRACE("random chart seed " + std::to_string(seed));
    Iec61131Options options;
    options.time = seed % 2 == 0 ? TimeMode::Abstract : TimeMode::Discrete;
    auto ts = system_for(bench::random_chart_iec(12, 3, seed, features), options);
    ASSERT_TRUE(ts);
    expect_agreement(*ts, 3000, seed);
  }
}

// Inputs overwritten by the chart's code (corpus 03/04 and CODESYS's PPU do it) and a timer
// called with two positive PTs in abstract time.
TEST(Iec61131Circuit, AgreesOnWrittenInputsAndSharedTimers) {
  auto ts = system_for(R"(FUNCTION_BLOCK fb
  VAR_INPUT go : BOOL; n : INT (0..3); END_VAR
  VAR_OUTPUT seen : BOOL; m : INT (0..3); END_VAR
  VAR t : TON; IX1 AT %IX1 : BOOL; END_VAR
  INITIAL_STEP S1 : Force(N); END_STEP
  STEP S2 : Look(N); END_STEP
  STEP S3 : END_STEP
  TRANSITION FROM S1 TO S2 := go AND IX1; END_TRANSITION
  TRANSITION FROM S2 TO S3 := t.Q OR n = 2; END_TRANSITION
  TRANSITION FROM S3 TO S1 := t.Q; END_TRANSITION
  ACTION Force : go := TRUE; IX1 := NOT IX1; t(IN := TRUE, PT := T#1s); END_ACTION
  ACTION Look : seen := go; n := n + 1; m := n; t(IN := go, PT := T#3s); END_ACTION
END_FUNCTION_BLOCK
)");
  ASSERT_TRUE(ts);
  expect_agreement(*ts, 3000, 99);
}

// CODESYS's SFCInit and SFCReset (a free input, or set and cleared by actions), also with
// timed qualifiers and a nested chart whose history the reset restores.
TEST(Iec61131Circuit, AgreesOnSfcInitAndSfcReset) {
  bench::RandomChartFeatures features;
  features.sfc_flags = true;
  for (std::uint64_t seed = 60; seed <= 71; ++seed) {
    SCOPED_TRACE("random chart seed " + std::to_string(seed));
    features.timed_qualifiers = features.nested_chart = seed % 3 != 0;
    Iec61131Options options;
    options.time = seed % 2 == 0 ? TimeMode::Abstract : TimeMode::Discrete;
    auto ts = system_for(bench::random_chart_iec(10, 2, seed, features), options);
    ASSERT_TRUE(ts);
    expect_agreement(*ts, 3000, seed);
  }
}

// CODESYS's and TwinCAT's dialect (docs/semantics.md 1.4a): the final calls of the IEC actions
// that write Y and count C, in a first pass, and the vendor's action order.
TEST(Iec61131Circuit, AgreesUnderTheVendorsFinalCalls) {
  bench::RandomChartFeatures features;
  features.writing_actions = features.counter = true;
  int final_calls = 0;
  for (std::uint64_t seed = 80; seed <= 91; ++seed) {
    SCOPED_TRACE("random chart seed " + std::to_string(seed));
    features.timed_qualifiers = seed % 2 == 0;
    features.sfc_flags = seed % 3 == 0;
    Iec61131Options options;
    set_dialect(options, seed % 2 ? VendorDialect::Codesys : VendorDialect::Twincat);
    options.time = seed % 4 < 2 ? TimeMode::Abstract : TimeMode::Discrete;
    auto ts = system_for(bench::random_chart_iec(10, 2, seed, features), options);
    ASSERT_TRUE(ts);
    for (const auto& f : ts->layout().fields()) final_calls += f.name.ends_with(".final");
    expect_agreement(*ts, 3000, seed);
  }
  EXPECT_GE(final_calls, 24);  // every chart has Up, Clear and W0..W2
}

TEST(Iec61131Circuit, AgreesOnFamilies) {
  auto tanks = system_for(bench::tanks_iec(2, true));
  ASSERT_TRUE(tanks);
  expect_agreement(*tanks, 2000, 7);
  auto nested = system_for(bench::nested_charts_iec(3));
  ASSERT_TRUE(nested);
  expect_agreement(*nested, 2000, 8);
  auto selector = system_for(bench::parallel_branches_iec(4, true));
  ASSERT_TRUE(selector);
  expect_agreement(*selector, 2000, 9);
}

const char* kTimersAndData = R"(
PROGRAM Timed
  VAR_INPUT go, stop : BOOL; level : INT(0..20); END_VAR
  VAR_OUTPUT lamp, horn, pump, siren, beacon : BOOL; count : INT(0..7); END_VAR
  VAR t1 : TON; c : CTU; trig : R_TRIG; latch : SR; n : INT(-5..5); END_VAR
  INITIAL_STEP Idle:
    Reset(N);
  END_STEP
  STEP Run:
    lamp(D, T#2s);
    horn(L, T#1s);
    Work(N);
    pump(SD, T#3s);
  END_STEP
  STEP Wait:
    pump(R);
    Tick(P1);
    siren(SL, T#1s);
    beacon(DS, T#1s);
  END_STEP
  STEP Rest:
    beacon(R);
  END_STEP
  ACTION Reset:
    n := 0;
  END_ACTION
  ACTION Work:
    t1(IN := go, PT := T#500ms);
    trig(CLK := go);
    c(CU := trig.Q, R := stop, PV := 3);
    latch(S1 := c.Q, R := stop);
    IF level > n + 8 THEN
      n := n + 1;
    ELSIF level = 3 THEN
      n := n - 1;
    ELSE
      CASE level OF
        0: n := 0;
        1..2: n := n * 2;
      END_CASE;
    END_IF;
  END_ACTION
  ACTION Tick:
    IF count < 7 THEN count := count + 1; END_IF;
  END_ACTION
  TRANSITION FROM Idle TO Run := go AND NOT stop; END_TRANSITION
  TRANSITION FROM Run TO Wait := t1.Q OR Run.T > T#3s; END_TRANSITION
  TRANSITION FROM Wait TO Rest := stop OR latch.Q1; END_TRANSITION
  TRANSITION FROM Rest TO Idle := NOT go; END_TRANSITION
END_PROGRAM
)";

TEST(Iec61131Circuit, AgreesOnTimersCountersAndData) {
  expect_agreement_in_both_time_modes(kTimersAndData, 1500, 11, 250);
}

// Programs without steps (ST bodies that run every cycle), two programs in one cycle in
// document order sharing a global, a timer without PT (T#0s), the
// CODESYS timer reset idiom (IN := FALSE with another PT) and CTU's RESET input.
const char* kBodyPrograms = R"(
PROGRAM Producer
  VAR_INPUT start, stop : BOOL; END_VAR
  VAR_GLOBAL run : BOOL; n : INT(0..3); END_VAR
  VAR t : TON; z : TON; c : CTU; e : R_TRIG; END_VAR
  IF start AND NOT stop THEN run := TRUE; ELSIF stop THEN run := FALSE; END_IF;
  IF stop THEN t(IN := FALSE, PT := T#0ms); ELSE t(IN := run, PT := T#2s); END_IF;
  z(IN := run);
  e(CLK := t.Q);
  c(CU := e.Q, RESET := stop, PV := 2);
  IF c.Q AND n < 3 THEN n := n + 1; END_IF;
END_PROGRAM
PROGRAM Consumer
  VAR_EXTERNAL run : BOOL; n : INT(0..3); END_VAR
  VAR_OUTPUT M1, M2, fast : BOOL; END_VAR
  M1 := run;
  M2 := run AND n = 3;
  fast := M1 AND NOT M2;
END_PROGRAM
)";

TEST(Iec61131Circuit, AgreesOnProgramsWithoutSteps) {
  const auto ts = system_for(kBodyPrograms);
  ASSERT_TRUE(ts);
  EXPECT_GT(ts->layout().fields().size(), 5u);
  expect_agreement_in_both_time_modes(kBodyPrograms, 1500, 21);
}

// Loops with state- and input-dependent bounds, EXIT/CONTINUE/RETURN, a loop that never ends
// as a range error, standard functions (with range errors in conversions and MUX) and bit
// strings: every reached state's successors agree between the int64 machine and the circuit.
const char* kLoopPrograms[] = {
    R"(
PROGRAM Loops
  VAR_INPUT n : INT(0..4); go : BOOL; END_VAR
  VAR_OUTPUT total : INT(0..50); k : INT(-5..5); done : BOOL; END_VAR
  VAR i : INT; END_VAR
  total := 0;
  FOR i := 1 TO n DO
    IF i = 2 THEN CONTINUE; END_IF;
    total := total + i;
    IF go AND i >= 3 THEN EXIT; END_IF;
  END_FOR;
  WHILE k < n DO k := k + 1; END_WHILE;
  REPEAT k := k - 2; UNTIL k <= 0 END_REPEAT;
  done := TRUE;
  IF total > 5 THEN RETURN; END_IF;
  done := FALSE;
END_PROGRAM
)",
    R"(
PROGRAM Bound
  VAR_INPUT a, b : BOOL; END_VAR
  VAR_OUTPUT x : INT(0..3); END_VAR
  WHILE a AND x < 3 DO x := x + 1; END_WHILE;
  WHILE b DO x := 0; END_WHILE;
END_PROGRAM
)",
    R"(
PROGRAM Funcs
  VAR_INPUT n : INT(-3..3); g : BOOL; END_VAR
  VAR_OUTPUT y : INT; s : SINT; q : BOOL; m : INT; END_VAR
  y := MAX(n, 0, m) + MIN(n, 1) + ABS(n) + LIMIT(-1, n, 2) + SEL(g, 10, 20);
  m := MUX(n + 1, 5, 6, 7);
  s := INT_TO_SINT(n * 50);
  q := INT_TO_BOOL(n) AND GT(n, 0, -1) OR NOT(g) AND BOOL_TO_INT(g) = 0;
END_PROGRAM
)",
    R"(
PROGRAM Bits
  VAR_INPUT v : BYTE; r : BOOL; END_VAR
  VAR_OUTPUT w : WORD; b : BYTE; bit : BOOL; END_VAR
  VAR i : INT; END_VAR
  b := v AND 16#F0 OR NOT v AND 16#0F;
  w := ROL(w, 3) XOR b;
  IF r THEN w := SHR(w, 2) OR 16#8000; END_IF;
  bit := w.15 OR b.0;
  FOR i := 7 TO 0 BY -2 DO
    IF b.0 THEN b := ROR(b, 1); ELSE b := SHL(b, 1); END_IF;
  END_FOR;
END_PROGRAM
)",
    // Shifts and rotations by a variable count: counts past the width, rotations modulo it,
    // a negative count (a range error).
    R"(
PROGRAM VarShifts
  VAR_INPUT v : BYTE; c : INT(-1..19); END_VAR
  VAR_OUTPUT w : WORD; b, d : BYTE; END_VAR
  b := SHL(v, c) XOR SHR(v, c + 1);
  d := ROL(v, c) OR ROR(b, c);
  w := SHL(w, c) XOR b;
END_PROGRAM
)"};

TEST(Iec61131Circuit, AgreesOnLoopsFunctionsAndBitStrings) {
  std::uint64_t seed = 31;
  for (const char* text : kLoopPrograms) {
    SCOPED_TRACE(text);
    auto ts = system_for(text, Iec61131Options{});
    ASSERT_TRUE(ts);
    expect_agreement(*ts, 1500, seed++);
  }
}

// The loop bound (docs/semantics.md 1.9.1) is not a finding for the int64 machine. A loop whose
// variables repeat never ends: a range error ("loop never ends"), in the circuit too. A loop
// that reaches 1000 iterations without repeating may still end: the machine stops with a
// LimitReached naming the bound (unknown); the circuit makes the same repeat test and marks
// the cycles past the bound as `loop_limit` (a limit every engine answers unknown), not as a
// plain range error (issue 53: a range error there was a finding the program may not have).
TEST(Iec61131Circuit, LoopBoundIsALimitAndANeverEndingLoopARangeError) {
  const char* forever = R"(
PROGRAM Forever
  VAR_INPUT b : BOOL; END_VAR
  VAR_OUTPUT x : INT(0..3); END_VAR
  WHILE b DO x := 0; END_WHILE;
END_PROGRAM
)";
  auto ts = system_for(forever);
  ASSERT_TRUE(ts);
  const auto g = engine::build_reachable_situation_graph(*ts);
  ASSERT_FALSE(g.anomalies().empty());
  EXPECT_NE(g.anomalies().front().message.find("loop never ends"), std::string::npos)
      << g.anomalies().front().message;
  const auto forever_circuit = build_iec61131_circuit(*ts);
  EXPECT_NE(forever_circuit.range_error, Aig::kFalse);
  EXPECT_EQ(forever_circuit.loop_limit, Aig::kFalse);  // it repeats at iteration 65

  const char* long_loop = R"(
PROGRAM Long
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT i : INT(0..2000); END_VAR
  i := 0;
  WHILE a AND i < 1500 DO i := i + 1; END_WHILE;
END_PROGRAM
)";
  ts = system_for(long_loop);
  ASSERT_TRUE(ts);
  try {
    engine::build_reachable_situation_graph(*ts);
    ADD_FAILURE() << "no limit";
  } catch (const LimitReached& e) {
    EXPECT_EQ(e.which(), Limit::Enumeration);
    EXPECT_NE(std::string(e.what()).find("ran 1000 iterations (the bound kMaxLoopIterations)"),
              std::string::npos)
        << e.what();
  }
  {
    // The circuit: the cut cycles are the limit's, named by the loop's location; a = TRUE
    // reaches the bound from the initial state (the circuit is evaluated, not trusted).
    auto c = build_iec61131_circuit(*ts);
    ASSERT_NE(c.loop_limit, Aig::kFalse);
    EXPECT_NE(c.loop_limit_message().find("kMaxLoopIterations"), std::string::npos);
    EXPECT_NE(c.loop_limit_where.find("6:3"), std::string::npos) << c.loop_limit_where;
    std::vector<bool> latches;
    for (const auto& l : c.aig.latches()) latches.push_back(l.initial);
    const std::vector<bool> a_true(c.aig.inputs().size(), true);
    const auto nodes = c.aig.evaluate(a_true, latches);
    EXPECT_TRUE(Aig::value_of(nodes, c.loop_limit));
    EXPECT_FALSE(Aig::value_of(nodes, c.anomaly_step()));
    const auto still = c.aig.evaluate(std::vector<bool>(c.aig.inputs().size(), false), latches);
    EXPECT_FALSE(Aig::value_of(still, c.loop_limit));
  }
  // 999 iterations: exact, no limit, no anomaly, and none in the circuit.
  std::string fits = long_loop;
  fits.replace(fits.find("1500"), 4, "999");
  ts = system_for(fits);
  ASSERT_TRUE(ts);
  const auto ok = engine::build_reachable_situation_graph(*ts);
  EXPECT_TRUE(ok.anomalies().empty());
  EXPECT_EQ(build_iec61131_circuit(*ts).range_error, Aig::kFalse);
  EXPECT_EQ(build_iec61131_circuit(*ts).loop_limit, Aig::kFalse);
}

// User function block instances (issue 18): an SFC-bodied FB called conditionally and twice
// in one cycle, an FB holding two nested instances (one called only on a rising edge), member
// reads and writes through them, `=>` outputs, and an instance that is never called.
const char* kInstances = R"(
FUNCTION_BLOCK Lamp
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT lit : BOOL; n : INT(0..3); END_VAR
  VAR t : TON; END_VAR
  INITIAL_STEP Off : Dark(N); END_STEP
  STEP On : Light(N); END_STEP
  TRANSITION FROM Off TO On := go; END_TRANSITION
  TRANSITION FROM On TO Off := NOT go OR t.Q; END_TRANSITION
  ACTION Dark : lit := FALSE; t(IN := FALSE, PT := T#1s); END_ACTION
  ACTION Light : lit := TRUE; t(IN := TRUE, PT := T#1s); IF n < 3 THEN n := n + 1; END_IF; END_ACTION
END_FUNCTION_BLOCK
FUNCTION_BLOCK Pair
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT both : BOOL; END_VAR
  VAR l1 : Lamp; l2 : Lamp; e : R_TRIG; END_VAR
  e(CLK := a);
  l1(go := a);
  IF e.Q THEN l2(go := NOT l2.lit); END_IF;
  both := l1.lit AND l2.lit;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT x, y : BOOL; END_VAR
  VAR_OUTPUT out1, out2, seen : BOOL; END_VAR
  VAR p : Pair; k : Lamp; idle : Lamp; END_VAR
  p(a := x, both => out1);
  IF y THEN k(go := x); k(go := NOT k.lit); END_IF;
  out2 := k.lit OR p.l1.lit;
  p.l2.go := y;
  seen := k.On.X AND p.l2.lit;
END_PROGRAM
)";

TEST(Iec61131Circuit, AgreesOnUserFunctionBlockInstances) {
  expect_agreement_in_both_time_modes(kInstances, 3000, 31);
}

// SFC actions of an instance run as units (issue 18, docs/semantics.md 1.3b): called from ST
// with and without SFCReset, twice in one cycle, and from a step of another unit; their steps
// call ST actions of a nested instance and copy the instance's own actions (P1) and Boolean
// variables; a sensor `AT %IX1` of the instance. Also DIV and MOD by constants of either sign
// on negative and positive values (the circuit divides by a constant bit by bit), and a
// MOD 0 range error.
const char* kUnits = R"(
FUNCTION_BLOCK Motor
  VAR_OUTPUT on : BOOL; dir : INT(-1..1); END_VAR
  ACTION ACT_Fwd : on := TRUE; dir := 1; END_ACTION
  ACTION ACT_Stop : on := FALSE; dir := 0; END_ACTION
END_FUNCTION_BLOCK
FUNCTION_BLOCK Station
  VAR_INPUT SFCReset : BOOL; req : BOOL; END_VAR
  VAR_OUTPUT busy, ready : BOOL; n : INT(-8..8); END_VAR
  VAR m : Motor; sensor AT %IX1 : BOOL; END_VAR
  ACTION Count : IF n < 8 THEN n := n + 1; ELSE n := -8; END_IF; END_ACTION
  ACTION ACT_Init :
    INITIAL_STEP I0 : m.ACT_Stop; END_STEP
    STEP I1 : ready; Count(P1); END_STEP
    TRANSITION FROM I0 TO I1 := NOT SFCReset; END_TRANSITION
    TRANSITION FROM I1 TO I0 := sensor; END_TRANSITION
  END_ACTION
  ACTION ACT_Run :
    INITIAL_STEP R0 : END_STEP
    STEP R1 : m.ACT_Fwd; busy; ACT_Init; Count(P1); END_STEP
    STEP R2 : m.ACT_Stop(P1); END_STEP
    TRANSITION FROM R0 TO R1 := req; END_TRANSITION
    TRANSITION FROM R1 TO R2 := sensor OR ready; END_TRANSITION
    TRANSITION FROM R2 TO R0 := NOT req; END_TRANSITION
  END_ACTION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT a, b, r : BOOL; k : INT(-7..7); END_VAR
  VAR_OUTPUT q1, q2, q3, q4 : INT; END_VAR
  VAR s : Station; END_VAR
  IF r THEN
    s.ACT_Init(SFCReset := TRUE); s.ACT_Run(SFCReset := TRUE);
  ELSE
    s.ACT_Run(SFCReset := FALSE, req := a);
  END_IF;
  IF b THEN s.ACT_Run(); END_IF;
  q1 := k / 2 + s.n MOD 5 - s.n / 4;
  q2 := k MOD 3;
  q3 := k / -3 + s.n / -2;
  q4 := k MOD -2 + s.n MOD -3;
  IF a AND b AND r AND k = 7 THEN q4 := k MOD 0; END_IF;
END_PROGRAM
)";

TEST(Iec61131Circuit, AgreesOnSfcActionUnitsAndDivisionByConstants) {
  expect_agreement_in_both_time_modes(kUnits, 3000, 53);
}

// User FUNCTIONs in ST (issue 18): formal calls with defaulted inputs and positional ones,
// calls nested in arguments, a function calling a function, RETURN and EXIT in a function,
// range errors on the result and on an input reached only for some inputs, calls in guards, in
// IF/ELSIF conditions behind short-circuit AND, in a WHILE condition, in action bodies and in
// the body of an FB instance called under a condition.
// (The loops' counters start from a function's fresh temporaries, so the circuit folds them.)
const char* kFunctions = R"(
FUNCTION Clamp : INT
  VAR_INPUT x : INT; lo : INT := -2; hi : INT := 2; END_VAR
  IF x < lo THEN Clamp := lo; RETURN; END_IF;
  Clamp := x;
  IF x > hi THEN Clamp := hi; END_IF;
END_FUNCTION
FUNCTION Tri : SINT
  VAR_INPUT n : INT; END_VAR
  VAR i : INT; acc : INT; END_VAR
  FOR i := 1 TO n DO
    acc := acc + i;
    IF acc > 8 THEN EXIT; END_IF;
  END_FOR;
  Tri := acc * 20;
END_FUNCTION
FUNCTION Busy : BOOL
  VAR_INPUT a : BOOL; b : BOOL; END_VAR
  VAR_TEMP t : BOOL; END_VAR
  t := a XOR b;
  Busy := t AND Clamp(x := BOOL_TO_INT(a) + 1) = 2;
END_FUNCTION
FUNCTION Steps : INT
  VAR_INPUT start : INT; limit : INT; END_VAR
  VAR i : INT; END_VAR
  Steps := start;
  WHILE i < 3 AND Clamp(Steps, 0, 5) < limit DO Steps := Steps + 1; i := i + 1; END_WHILE;
END_FUNCTION
FUNCTION_BLOCK Acc
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT total : INT(0..9); END_VAR
  IF go THEN total := Clamp(total + 1, 0, 9); END_IF;
END_FUNCTION_BLOCK
FUNCTION Small : BOOL
  VAR_INPUT v : INT(0..3); END_VAR
  Small := v < 2;
END_FUNCTION
FUNCTION Mask : BYTE
  VAR_INPUT v : BYTE; END_VAR
  Mask := SHL(v, 1) OR 16#01;
END_FUNCTION
FUNCTION Split : BOOL
  VAR_INPUT v : INT(0..7); END_VAR
  VAR_OUTPUT lo : INT(0..3); hi : BOOL; END_VAR
  IF v > 6 THEN RETURN; END_IF;
  lo := v MOD 4;
  hi := v >= 4;
  Split := lo = 0;
END_FUNCTION
PROGRAM Main
  VAR_INPUT n : INT(0..5); x, y : BOOL; END_VAR
  VAR_OUTPUT c : INT; s : SINT; q, w : BOOL; m : BYTE; k : INT(0..6); d : INT(0..3); e : BOOL;
  f : BOOL; END_VAR
  VAR a : Acc; END_VAR
  INITIAL_STEP Idle : Calc(N); END_STEP
  STEP Run : Count(N); END_STEP
  TRANSITION FROM Idle TO Run := Busy(x, y) AND Clamp(hi := 4, x := n - 1) >= 3; END_TRANSITION
  TRANSITION FROM Run TO Idle := NOT Busy(b := x, a := y) OR Clamp(k, 0, 5) = 2; END_TRANSITION
  ACTION Calc :
    c := Clamp(n - 4, -2, 2) + Clamp(Clamp(n, 0, 1), -1, 0);
    IF y AND Tri(n) > 100 THEN q := TRUE; ELSIF Busy(x, NOT y) THEN q := FALSE; END_IF;
    m := Mask(m) AND 16#3F;
  END_ACTION
  ACTION Count :
    k := Steps(k, n);
    IF y THEN s := Tri(k); END_IF;
    IF x THEN a(go := Busy(TRUE, y)); END_IF;
    w := x AND Busy(y, w);
    IF x AND NOT y THEN w := Small(k); END_IF;
    IF y AND NOT x THEN q := Split(v := k + BOOL_TO_INT(e), lo => d, hi => e); END_IF;
    IF x THEN Split(v := k + 1, hi => f); END_IF;
  END_ACTION
END_PROGRAM
)";

TEST(Iec61131Circuit, AgreesOnUserFunctions) {
  expect_agreement_in_both_time_modes(kFunctions, 3000, 47);
}

// NOT on signed and unsigned integers (the bitwise complement, written as a subtraction), and
// a timer's PT and ET read in both time modes (TwinCAT's blinking lamp, xPPU 19-23).
const char* const kIntegerNotAndTimerReads = R"(
FUNCTION Half : UINT
  VAR_INPUT v : UINT; END_VAR
  Half := v / 2;
END_FUNCTION
PROGRAM Main
  VAR_INPUT a : BOOL; k : INT(-2..1); END_VAR
  VAR_OUTPUT n : INT(-8..8); m : INT; s : SINT; u : UINT; green, done : BOOL; et, pt : TIME;
  END_VAR
  VAR blink, once : TON; END_VAR
  n := NOT (n + k);
  m := NOT k;
  IF m >= 0 THEN s := NOT s; ELSE s := 127; END_IF;
  u := NOT Half(u);
  blink(IN := NOT blink.Q, PT := T#6ms);
  green := blink.ET < blink.PT / 2;
  IF a THEN once(IN := TRUE, PT := T#4ms); ELSE once(IN := FALSE, PT := T#0ms); END_IF;
  et := once.ET;
  pt := once.PT;
  done := once.Q AND once.ET = once.PT;
END_PROGRAM
)";

TEST(Iec61131Circuit, AgreesOnIntegerNotAndTimerReads) {
  expect_agreement_in_both_time_modes(kIntegerNotAndTimerReads, 200, 53);
}

}  // namespace
}  // namespace sfcv::semantics

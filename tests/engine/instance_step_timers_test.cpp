// The step timers of a chart inside a user function block instance read the cycle clock
// (docs/semantics.md §1.6), as TON does. IEC 61131-3 defines a step's elapsed time .T and the
// times of the timed qualifiers (L, D, SD, DS, SL) as time since the step's (or the action's)
// activation: time of the plant, not a count of the instance's calls. So an instance called
// under an IF that is not taken for some cycles finds its step older at its next call, and one
// called twice in a cycle does not age twice. Every expectation marked "old" below is what the
// old reading (step timers aged once per call of the instance) gave instead. Checked on the
// machine (runs written from the definition), on explicit, bdd and ic3, and the circuit against
// the machine for every input valuation along runs, in both time modes, SFCReset included.

#include <gtest/gtest.h>

#include <random>

#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/ctl_task.hpp"

namespace sfcv::engine {
namespace {

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

std::unique_ptr<Setup> load(const std::string& text, semantics::Iec61131Options options) {
  auto loaded = io::load_iec_text(text, "instance_timers.st");
  EXPECT_TRUE(loaded.ok()) << text;
  if (!loaded.ok()) return nullptr;
  auto s = std::make_unique<Setup>();
  s->project = std::move(*loaded.project);
  model::Diagnostics d;
  s->ts = semantics::make_iec61131_system(s->project, options, d);
  for (const auto& x : d) ADD_FAILURE() << x.str() << "\n" << text;
  return s->ts ? std::move(s) : nullptr;
}

semantics::Iec61131Options discrete10() {
  semantics::Iec61131Options o;
  o.time = semantics::TimeMode::Discrete;
  o.cycle_ms = 10;
  return o;
}

std::uint32_t observable(const semantics::TransitionSystem& ts, const std::string& name) {
  std::string err;
  const auto i = semantics::find_observable(ts, name, &err);
  EXPECT_TRUE(i.has_value()) << err;
  return i.value_or(0);
}

/// Runs the cycles of `inputs` (one string per input name, a digit per cycle) from the initial
/// state; returns, per name of `watch`, a digit per cycle.
std::vector<std::string> run(const semantics::TransitionSystem& ts,
                             const std::vector<std::pair<std::string, std::string>>& inputs,
                             const std::vector<std::string>& watch) {
  std::vector<std::string> out(watch.size());
  auto state = semantics::first_initial_state(ts);
  const auto cycles = inputs.front().second.size();
  for (std::size_t k = 0; k < cycles; ++k) {
    std::vector<std::int64_t> in(ts.inputs().size(), 0);
    for (std::size_t i = 0; i < ts.inputs().size(); ++i)
      for (const auto& [name, digits] : inputs)
        if (ts.inputs()[i].name == name) in[i] = digits[k] - '0';
    const auto r = semantics::simulate(ts, state, {in});
    EXPECT_TRUE(r.ok) << r.error;
    if (!r.ok) return out;
    state = r.states.back();
    for (std::size_t w = 0; w < watch.size(); ++w)
      out[w] += std::to_string(ts.observe(state, observable(ts, watch[w])));
  }
  return out;
}

void expect_on_every_engine(const std::string& text, const std::string& ctl,
                            logic::Verdict expected) {
  SCOPED_TRACE(ctl);
  auto s = load(text, discrete10());
  ASSERT_TRUE(s);
  auto task = test::task_for(s->project, *s->ts, {ctl}, {});
  task.checks.clear();
  SatEngineOptions ic3;
  ic3.algorithm = SatAlgorithm::Ic3;
  for (const auto& checker :
       {make_explicit_model_checker(), make_bdd_model_checker(), make_sat_model_checker(ic3)}) {
    const auto report = checker->check(task);
    ASSERT_EQ(report.results.size(), 1u) << checker->name();
    EXPECT_EQ(report.results[0].verdict, expected)
        << checker->name() << ": " << logic::to_string(report.results[0].verdict) << " "
        << report.results[0].message;
  }
}

// Idle -go-> Run -(Run.T >= 50 ms)-> Done -(NOT go)-> Idle; Run holds `lamp` for 30 ms (L).
const std::string kSeq = R"(FUNCTION_BLOCK Seq
  VAR_INPUT go, SFCReset : BOOL; END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Run: lamp(L, T#30ms); END_STEP
  STEP Done: END_STEP
  TRANSITION FROM Idle TO Run := go; END_TRANSITION
  TRANSITION FROM Run TO Done := Run.T >= T#50ms; END_TRANSITION
  TRANSITION FROM Done TO Idle := NOT go; END_TRANSITION
END_FUNCTION_BLOCK
)";

// The instance is called only when c: once to enter Run (cycle 1), then not for cycles 2-3.
const std::string kConditional = kSeq + R"(PROGRAM Main
  VAR_INPUT c, r : BOOL; END_VAR
  VAR_OUTPUT light : BOOL; calls : INT(0..7); END_VAR
  VAR s : Seq; END_VAR
  IF c THEN
    s(go := NOT r, SFCReset := r);
    IF calls < 7 THEN calls := calls + 1; END_IF;
  END_IF;
  light := s.lamp;
END_PROGRAM
)";

// Cycle 1 enters Run; at the call of cycle 4, 30 ms later, L's time is over: the lamp goes
// out (old: 10 ms, lit until cycle 6). Guards read .T as the last cycle left it, as in a
// program: 50 ms in cycle 7, which leaves Run (old: at the 7th call).
TEST(InstanceStepTimers, AnInstanceNotCalledForSomeCyclesStillAgesItsSteps) {
  auto s = load(kConditional, discrete10());
  ASSERT_TRUE(s);
  const auto w = run(*s->ts, {{"c", "1001111"}}, {"light", "s.Run", "s.Done"});
  EXPECT_EQ(w[0], "1110000");
  EXPECT_EQ(w[1], "1111110");
  EXPECT_EQ(w[2], "0000001");
  // Not called at all for five cycles: Run.T is 50 ms at the next call, which leaves Run.
  const auto late = run(*s->ts, {{"c", "1000001"}}, {"light", "s.Done"});
  EXPECT_EQ(late[0], "1111110");
  EXPECT_EQ(late[1], "0000001");
}

// SFCReset at a call restarts the chart in Idle; Run's times start again at its next entry,
// however long the instance then goes uncalled (as in a program's reset cycle, the reset chart
// is one cycle old at the end of it).
TEST(InstanceStepTimers, SfcResetRestartsTheStepTimes) {
  auto s = load(kConditional, discrete10());
  ASSERT_TRUE(s);
  const auto w = run(*s->ts, {{"c", "10110001"}, {"r", "00100000"}}, {"light", "s.Run", "s.Idle"});
  // Cycle 3 resets (Idle, lamp off), cycle 4 enters Run again, the lamp lasts until cycle 7.
  EXPECT_EQ(w[1], "11011111");
  EXPECT_EQ(w[2], "00100000");
  EXPECT_EQ(w[0], "11011110");
}

TEST(InstanceStepTimers, AnInstanceCalledUnderAnIfOnEveryEngine) {
  // Done after two calls: the one entering Run and one 50 ms later (old: seven calls).
  expect_on_every_engine(kConditional, "AG !(s.Done & calls < 3)", logic::Verdict::Violated);
  expect_on_every_engine(kConditional, "AG !(s.Done & calls < 2)", logic::Verdict::Holds);
  // The lamp is out at the second call if it comes 30 ms after the first (old: still lit).
  expect_on_every_engine(kConditional, "AG (s.Run & calls = 2 -> light)", logic::Verdict::Violated);
}

// Called twice in every cycle: the second call does not age the steps. The lamp lasts 30 ms
// (cycles 1-3; old: cycle 1 only) and Done comes 50 ms after Run's entry (cycle 6; old: 4).
const std::string kTwice = kSeq + R"(PROGRAM Main
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT first, light : BOOL; n : INT(0..7); END_VAR
  VAR s : Seq; END_VAR
  s(go := TRUE);
  first := s.lamp;
  s(go := TRUE);
  light := s.lamp;
  IF n < 7 THEN n := n + 1; END_IF;
END_PROGRAM
)";

TEST(InstanceStepTimers, AnInstanceCalledTwiceInACycleAgesOnce) {
  auto s = load(kTwice, discrete10());
  ASSERT_TRUE(s);
  const auto w = run(*s->ts, {{"a", "0000000"}}, {"first", "light", "s.Done"});
  EXPECT_EQ(w[0], "1110000");
  EXPECT_EQ(w[1], "1110000");
  EXPECT_EQ(w[2], "0000011");
}

TEST(InstanceStepTimers, AnInstanceCalledTwiceInACycleOnEveryEngine) {
  expect_on_every_engine(kTwice, "AG (n >= 1 & n <= 3 -> light)", logic::Verdict::Holds);
  expect_on_every_engine(kTwice, "AG (s.Done -> n >= 6)", logic::Verdict::Holds);
  expect_on_every_engine(kTwice, "EF (s.Done & n = 6)", logic::Verdict::Holds);
}

// ------------------------------------------------------------ the circuit against the machine

std::optional<std::vector<semantics::StateWord>> circuit_step(
    const semantics::TransitionSystem& ts, semantics::TransitionCircuit& c,
    const std::vector<semantics::StateWord>& state, const std::vector<std::int64_t>& inputs) {
  const auto& layout = ts.layout();
  std::vector<bool> latches(c.aig.latches().size());
  for (std::uint32_t f = 0; f < c.field_latches.size(); ++f) {
    const auto v = static_cast<std::uint64_t>(layout.get(state, f) - layout.fields()[f].lo);
    for (std::size_t b = 0; b < c.field_latches[f].size(); ++b)
      latches[c.field_latches[f][b]] = ((v >> b) & 1U) != 0;
  }
  std::vector<bool> bits(c.aig.inputs().size());
  for (std::size_t i = 0; i < c.input_bits.size(); ++i)
    for (std::size_t b = 0; b < c.input_bits[i].size(); ++b) {
      const auto& node = c.aig.nodes()[semantics::Aig::node_of(c.input_bits[i][b])];
      bits[node.index] = ((static_cast<std::uint64_t>(inputs[i]) >> b) & 1U) != 0;
    }
  const auto values = c.aig.evaluate(bits, latches);
  if (!semantics::Aig::value_of(values, c.step_ok())) return std::nullopt;
  std::vector<bool> next;
  for (const auto& l : c.aig.latches()) next.push_back(semantics::Aig::value_of(values, l.next));
  return semantics::state_from_latches(ts, c, next);
}

/// Every field's value, for a failure's message.
std::string fields(const semantics::TransitionSystem& ts,
                   const std::vector<semantics::StateWord>& state) {
  std::string out;
  const auto& layout = ts.layout();
  for (std::uint32_t f = 0; f < layout.fields().size(); ++f)
    out += layout.fields()[f].name + "=" + std::to_string(layout.get(state, f)) + " ";
  return out;
}

/// Every valuation of the inputs (each over its range) from `state`: circuit = machine.
void expect_circuit_agrees(const semantics::TransitionSystem& ts,
                           semantics::TransitionCircuit& circuit,
                           const std::vector<semantics::StateWord>& state) {
  const auto& ins = ts.inputs();
  std::vector<std::int64_t> in(ins.size());
  for (std::size_t i = 0; i < ins.size(); ++i) in[i] = ins[i].type.lo;
  for (;;) {
    const auto machine = semantics::simulate(ts, state, {in});
    const auto symbolic = circuit_step(ts, circuit, state, in);
    ASSERT_EQ(machine.ok, symbolic.has_value()) << machine.error;
    if (machine.ok) {
      ASSERT_EQ(machine.states.back(), *symbolic)
          << fields(ts, state) << " -> machine " << fields(ts, machine.states.back())
          << ", circuit " << fields(ts, *symbolic) << ", inputs " << ::testing::PrintToString(in);
    }
    std::size_t i = 0;
    for (; i < ins.size(); ++i) {
      if (in[i] < ins[i].type.hi) {
        ++in[i];
        break;
      }
      in[i] = ins[i].type.lo;
    }
    if (i == ins.size()) return;
  }
}

// Every timed qualifier and .T in an instance called under an IF, twice, with SFCReset; both
// time modes, along random runs.
TEST(InstanceStepTimers, CircuitAgreesWithTheMachine) {
  const std::string text = R"(FUNCTION_BLOCK Box
  VAR_INPUT go, SFCReset : BOOL; END_VAR
  VAR_OUTPUT l, d, sd, ds, sl : BOOL; END_VAR
  INITIAL_STEP A: END_STEP
  STEP B: l(L, T#20ms); d(D, T#20ms); sd(SD, T#30ms); ds(DS, T#20ms); sl(SL, T#30ms); END_STEP
  STEP C: sd(R); ds(R); END_STEP
  TRANSITION FROM A TO B := go; END_TRANSITION
  TRANSITION FROM B TO C := B.T >= T#40ms OR NOT go; END_TRANSITION
  TRANSITION FROM C TO A := C.T >= T#20ms; END_TRANSITION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT a, b, c, r : BOOL; END_VAR
  VAR x : Box; END_VAR
  IF c THEN x(go := a, SFCReset := r); END_IF;
  IF b THEN x(go := a OR c); END_IF;
END_PROGRAM
)";
  int states = 0;
  for (const bool discrete : {true, false}) {
    SCOPED_TRACE(discrete ? "discrete" : "abstract");
    auto s = load(text, discrete ? discrete10() : semantics::Iec61131Options{});
    ASSERT_TRUE(s);
    const auto& ts = *s->ts;
    auto circuit = semantics::build_iec61131_circuit(ts);
    std::mt19937_64 rng(discrete ? 7 : 11);
    for (int run = 0; run < 4; ++run) {
      auto state = semantics::first_initial_state(ts);
      for (int cycle = 0; cycle < 12; ++cycle) {
        expect_circuit_agrees(ts, circuit, state);
        if (HasFatalFailure()) return;
        ++states;
        std::vector<std::int64_t> in(ts.inputs().size());
        for (std::size_t i = 0; i < in.size(); ++i) {
          const auto& t = ts.inputs()[i].type;
          in[i] =
              t.lo + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(t.hi - t.lo + 1));
          if (ts.inputs()[i].name == "r" && rng() % 4 != 0) in[i] = 0;  // resets: now and then
        }
        const auto r = semantics::simulate(ts, state, {in});
        ASSERT_TRUE(r.ok) << r.error;
        state = r.states.back();
      }
    }
  }
  EXPECT_EQ(states, 2 * 4 * 12);
}

}  // namespace
}  // namespace sfcv::engine

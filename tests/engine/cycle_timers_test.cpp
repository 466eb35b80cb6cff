// Timers read the cycle clock (docs/semantics.md §1.6) on every engine, and the rule against an
// independent reading. Verdicts: a TON that is not called in some cycles (an IF, an action of a
// step left and re-entered) and one called twice per cycle, checked by explicit, bdd and ic3;
// each property's verdict was the opposite under the old reading (a timer aged once per call).
// Then random programs with TON/TOF/TP called conditionally, twice, or from an action of a
// step that comes and goes, run against a reference written here from IEC 61131-3's
// definitions with a per-cycle clock (start time stamps, ET = now - start), and the scan
// cycle's circuit against the machine in every state met, for every input valuation.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/iec_builder.hpp"
#include "semantics/simulate.hpp"
#include "support/ctl_task.hpp"

namespace sfcv::engine {
namespace {

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

std::unique_ptr<Setup> load(const std::string& text, semantics::Iec61131Options options) {
  auto loaded = io::load_iec_text(text, "timers.st");
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

/// The verdict of `ctl` on explicit, bdd and ic3: all three must give `expected`.
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

// A TON in an IF: started at one call, not called for two cycles, called again 30 ms after
// the start: Q after two calls. The old reading needed four calls: "holds", wrongly.
TEST(CycleTimers, ATimerNotCalledForSomeCyclesAgesOnEveryEngine) {
  const std::string text = R"(PROGRAM Main
  VAR_INPUT a, c : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; calls : INT(0..7); END_VAR
  VAR t : TON; END_VAR
  IF c THEN
    t(IN := a, PT := T#30ms);
    IF calls < 7 THEN calls := calls + 1; END_IF;
  END_IF;
  q := t.Q;
END_PROGRAM
)";
  expect_on_every_engine(text, "AG !(q & calls < 4)", logic::Verdict::Violated);
  expect_on_every_engine(text, "AG !(q & calls < 2)", logic::Verdict::Holds);
}

// The same inside a user function block instance that is called only under an IF: the
// instance's TON reads the cycle clock too.
TEST(CycleTimers, ATimerInAnInstanceCalledUnderAnIfAgesOnEveryEngine) {
  const std::string text = R"(FUNCTION_BLOCK Delay
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT done : BOOL; END_VAR
  VAR t : TON; END_VAR
  t(IN := go, PT := T#30ms);
  done := t.Q;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT a, c : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; calls : INT(0..7); END_VAR
  VAR d : Delay; END_VAR
  IF c THEN
    d(go := a);
    IF calls < 7 THEN calls := calls + 1; END_IF;
  END_IF;
  q := d.done;
END_PROGRAM
)";
  expect_on_every_engine(text, "AG !(q & calls < 4)", logic::Verdict::Violated);
  expect_on_every_engine(text, "AG !(q & calls < 2)", logic::Verdict::Holds);
}

// A TON called twice per cycle with the same IN reads one clock: Q 30 ms after IN rose, in
// the 4th cycle at the earliest. The old reading aged it twice per cycle: "violated", wrongly.
TEST(CycleTimers, ATimerCalledTwicePerCycleAgesOnceOnEveryEngine) {
  const std::string text = R"(PROGRAM Main
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; n : INT(0..7); END_VAR
  VAR t : TON; END_VAR
  t(IN := a, PT := T#30ms);
  t(IN := a, PT := T#30ms);
  IF n < 7 THEN n := n + 1; END_IF;
  q := t.Q;
END_PROGRAM
)";
  expect_on_every_engine(text, "AG (q -> n >= 4)", logic::Verdict::Holds);
  expect_on_every_engine(text, "EF (q & n = 4)", logic::Verdict::Holds);
}

// A TON in an N action of a step left and re-entered keeps running (its last call had IN =
// TRUE): at its 4th call, 60 ms after the start, Q (PT = 50 ms). The old reading needed six
// calls: "holds", wrongly. Two calls suffice when S1 is away long enough.
TEST(CycleTimers, ATimerInAStepLeftAndReEnteredAgesOnEveryEngine) {
  const std::string text = R"(PROGRAM Main
  VAR_INPUT a, b : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; calls : INT(0..7); END_VAR
  VAR t : TON; END_VAR
  INITIAL_STEP S1: A(N); R(N); END_STEP
  STEP S2: R(N); END_STEP
  ACTION A:
    t(IN := TRUE, PT := T#50ms);
    IF calls < 7 THEN calls := calls + 1; END_IF;
  END_ACTION
  ACTION R: q := t.Q; END_ACTION
  TRANSITION FROM S1 TO S2 := a; END_TRANSITION
  TRANSITION FROM S2 TO S1 := b; END_TRANSITION
END_PROGRAM
)";
  expect_on_every_engine(text, "AG !(q & calls < 6)", logic::Verdict::Violated);
  expect_on_every_engine(text, "EF (q & calls = 2)", logic::Verdict::Holds);
  expect_on_every_engine(text, "AG !(q & calls < 2)", logic::Verdict::Holds);
}

// ------------------------------------------------------------------ the reference reading

enum class Kind { Ton, Tof, Tp };

/// A timer as IEC 61131-3 defines it, on a per-cycle clock: the call reads `now` (the cycle's
/// number); ET = (now - start) * cycle, capped at PT.
struct RefTimer {
  Kind kind = Kind::Ton;
  std::int64_t pt = 0;
  bool running = false, q = false, last_in = false;
  std::int64_t start = 0, et = 0;

  void call(bool in, std::int64_t now, std::int64_t cycle) {
    auto elapsed = [&] { return (now - start) * cycle; };
    switch (kind) {
      case Kind::Ton:  // Q = ET >= PT while IN; ET counts from IN's rise
        if (!in) {
          running = q = false;
          et = 0;
          return;
        }
        if (!running) running = true, start = now;
        q = elapsed() >= pt;
        et = std::min(elapsed(), pt);
        return;
      case Kind::Tof:  // Q = IN or ET < PT; ET counts from IN's fall
        if (in) {
          running = false, q = true, et = 0;
          return;
        }
        if (!running && q) running = true, start = now;
        if (running) {
          q = elapsed() < pt;
          et = std::min(elapsed(), pt);
        }
        return;
      case Kind::Tp: {  // a pulse of PT from a rise of IN; ET held at PT while IN stays
        const bool rising = in && !last_in;
        last_in = in;
        if (!running) {
          if (!rising) {
            q = false, et = 0;
            return;
          }
          running = true, start = now;
        }
        const bool done = elapsed() >= pt;
        q = !done;
        et = std::min(elapsed(), pt);
        if (done && !in) running = false, et = 0;
        return;
      }
    }
  }
};

/// Inputs a, b, c, d; outputs q0.. and e0.. (Q and ET of timer k).
struct Env {
  bool in[4] = {false, false, false, false};
  std::vector<bool> q;
  std::vector<std::int64_t> e;
};

struct Condition {
  const char* text;
  bool (*eval)(const Env&);
};

const Condition kIns[] = {
    {"a", [](const Env& v) { return v.in[0]; }},
    {"b", [](const Env& v) { return v.in[1]; }},
    {"NOT a", [](const Env& v) { return !v.in[0]; }},
    {"a AND b", [](const Env& v) { return v.in[0] && v.in[1]; }},
    {"TRUE", [](const Env&) { return true; }},
    {"FALSE", [](const Env&) { return false; }},
    {"q0", [](const Env& v) { return static_cast<bool>(v.q[0]); }},
};
const Condition kIfs[] = {
    {"c", [](const Env& v) { return v.in[2]; }},
    {"NOT c", [](const Env& v) { return !v.in[2]; }},
    {"b OR c", [](const Env& v) { return v.in[1] || v.in[2]; }},
    {"c AND NOT a", [](const Env& v) { return v.in[2] && !v.in[0]; }},
};

/// One statement: a call of timer `timer` (under IF `cond` when >= 0), or the copy of its Q and
/// ET into q<timer>, e<timer> (in == -1).
struct Stmt {
  int timer = 0, in = -1, cond = -1;
};

struct RandomProgram {
  std::vector<RefTimer> timers;
  std::vector<Stmt> body, action;  ///< the action runs while S1 is active (N)
  std::string vars, body_text, action_text, text;
};

std::string stmt_text(const RandomProgram& p, const Stmt& s, bool et) {
  const auto k = std::to_string(s.timer);
  if (s.in < 0)
    return "q" + k + " := t" + k + ".Q;" + (et ? " e" + k + " := t" + k + ".ET;" : "") + "\n";
  std::string call = "t" + k + "(IN := " + kIns[s.in].text + ", PT := T#" +
                     std::to_string(p.timers[static_cast<std::size_t>(s.timer)].pt) + "ms);";
  if (s.cond < 0) return call + "\n";
  return std::string("IF ") + kIfs[s.cond].text + " THEN " + call + " END_IF;\n";
}

/// `et`: the program reads ET (discrete time only).
RandomProgram random_program(std::uint64_t seed, bool et = true) {
  std::mt19937_64 rng(seed);
  auto pick = [&](std::size_t n) { return static_cast<int>(rng() % n); };
  RandomProgram p;
  const int n = 1 + pick(3);
  static const std::int64_t pts[] = {0, 10, 20, 30, 50, 25};
  for (int k = 0; k < n; ++k) {
    RefTimer t;
    t.kind = static_cast<Kind>(pick(3));
    t.pt = pts[pick(6)];
    p.timers.push_back(t);
  }
  auto statements = [&](std::vector<Stmt>& out, int count) {
    for (int i = 0; i < count; ++i) {
      Stmt s;
      s.timer = pick(static_cast<std::size_t>(n));
      if (pick(3) > 0) {
        s.in = pick(std::size(kIns));
        if (pick(2)) s.cond = pick(std::size(kIfs));
      }
      out.push_back(s);
      if (s.in >= 0 && pick(4) == 0) out.push_back(s);  // the same call twice
    }
  };
  statements(p.body, 2 + pick(4));
  if (pick(2)) statements(p.action, 1 + pick(3));
  // The program, for the log; the system is built from the same pieces (IecBuilder: a POU
  // body beside a chart).
  std::ostringstream t;
  std::string vars = "VAR_INPUT a, b, c, d : BOOL; END_VAR VAR_OUTPUT ";
  for (int k = 0; k < n; ++k) {
    const auto ks = std::to_string(k);
    vars += "q" + ks + " : BOOL; e" + ks + " : TIME; ";
  }
  vars += "END_VAR VAR ";
  static const char* kinds[] = {"TON", "TOF", "TP"};
  for (int k = 0; k < n; ++k)
    vars += "t" + std::to_string(k) + " : " +
            kinds[static_cast<int>(p.timers[static_cast<std::size_t>(k)].kind)] + "; ";
  vars += "END_VAR";
  p.vars = vars;
  for (const auto& s : p.body) p.body_text += stmt_text(p, s, et);
  for (const auto& s : p.action) p.action_text += stmt_text(p, s, et);
  t << vars << "\nBODY\n"
    << p.body_text << "S1 -(d)-> S2 -(c AND NOT d)-> S1\nACTION A (N in S1)\n"
    << p.action_text;
  p.text = t.str();
  return p;
}

semantics::TransitionSystemPtr build(const RandomProgram& p,
                                     semantics::Iec61131Options options = discrete10()) {
  test::IecBuilder b(p.vars);
  b.step("S1", true).step("S2").trans("S1", "S2", "d").trans("S2", "S1", "c AND NOT d");
  if (!p.action_text.empty()) b.action_st("A", p.action_text).assoc("S1", "A", "N");
  b.body(p.body_text);
  // The reference holds an output the program reads but never assigns (q0 when no `q0 := t0.Q`
  // was drawn) at its initial FALSE: so does the system under test.
  options.unwritten = semantics::UnwrittenMode::Keep;
  return b.build(options);
}

/// The reference cycle: body, then the action if S1 was active, then the transitions.
void reference_cycle(RandomProgram& p, Env& env, bool& s1, std::int64_t now) {
  auto exec = [&](const std::vector<Stmt>& stmts) {
    for (const auto& s : stmts) {
      auto& t = p.timers[static_cast<std::size_t>(s.timer)];
      const auto k = static_cast<std::size_t>(s.timer);
      if (s.in < 0) {
        env.q[k] = t.q;
        env.e[k] = t.et;
        continue;
      }
      if (s.cond >= 0 && !kIfs[s.cond].eval(env)) continue;
      t.call(kIns[s.in].eval(env), now, 10);
    }
  };
  exec(p.body);
  if (s1) exec(p.action);
  s1 = s1 ? !env.in[3] : env.in[2] && !env.in[3];  // S1 -(d)-> S2 -(c AND NOT d)-> S1
}

/// The circuit's successor of `state` under `inputs` (the machine's layout), or nothing when
/// the cycle has no successor.
std::uint32_t observable(const semantics::TransitionSystem& ts, const std::string& name) {
  std::string err;
  const auto i = semantics::find_observable(ts, name, &err);
  EXPECT_TRUE(i.has_value()) << err;
  return i.value_or(0);
}

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

/// The circuit's successor and the machine's in `state`, for every valuation of the (Boolean)
/// inputs.
void expect_circuit_agrees(const semantics::TransitionSystem& ts,
                           semantics::TransitionCircuit& circuit,
                           const std::vector<semantics::StateWord>& state) {
  const auto count = ts.inputs().size();
  ASSERT_LE(count, 10u);
  for (std::uint32_t m = 0; m < (1U << count); ++m) {
    std::vector<std::int64_t> inputs(count);
    for (std::size_t i = 0; i < count; ++i) inputs[i] = (m >> i) & 1U;
    const auto machine = semantics::simulate(ts, state, {inputs});
    const auto symbolic = circuit_step(ts, circuit, state, inputs);
    ASSERT_EQ(machine.ok, symbolic.has_value()) << machine.error;
    if (machine.ok) {
      ASSERT_EQ(machine.states.back(), *symbolic) << ts.describe(state);
    }
  }
}

TEST(CycleTimers, RandomProgramsAgreeWithAPerCycleClockReference) {
  int programs = 0, rows = 0, calls_skipped = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    auto prog = random_program(seed);
    SCOPED_TRACE(prog.text);
    const auto system = build(prog);
    ASSERT_TRUE(system);
    const auto& ts = *system;
    auto circuit = semantics::build_iec61131_circuit(ts);
    ++programs;
    std::mt19937_64 rng(seed * 7919);
    for (int run = 0; run < 3; ++run) {
      auto ref = prog;
      const auto n = ref.timers.size();
      Env env;
      env.q.assign(std::max<std::size_t>(n, 1), false);
      env.e.assign(n, 0);
      bool s1 = true;
      auto state = semantics::first_initial_state(ts);
      for (std::int64_t now = 1; now <= 16; ++now) {
        for (int i = 0; i < 3; ++i) env.in[i] = (rng() & 1U) != 0;
        env.in[3] = rng() % 4 == 0;  // d leaves S1: rarely, so that S1's action runs a while
        std::vector<std::int64_t> inputs(ts.inputs().size(), 0);
        for (std::size_t i = 0; i < ts.inputs().size(); ++i) {
          const auto& name = ts.inputs()[i].name;
          ASSERT_EQ(name.size(), 1u) << name;  // a, b, c or d: no pseudo-input
          inputs[i] = env.in[name[0] - 'a'];
        }
        // The circuit against the machine here, for every valuation of the four inputs.
        expect_circuit_agrees(ts, circuit, state);
        if (HasFatalFailure()) return;
        const auto r = semantics::simulate(ts, state, {inputs});
        ASSERT_TRUE(r.ok) << r.error;
        state = r.states.back();
        const bool was_s1 = s1;
        reference_cycle(ref, env, s1, now);
        if (!was_s1 && !ref.action.empty()) ++calls_skipped;
        for (std::size_t k = 0; k < n; ++k) {
          const auto ks = std::to_string(k);
          ASSERT_EQ(ts.observe(state, observable(ts, "q" + ks)), env.q[k] ? 1 : 0)
              << "cycle " << now << ", q" << k;
          ASSERT_EQ(ts.observe(state, observable(ts, "e" + ks)), env.e[k])
              << "cycle " << now << ", e" << k;
        }
        ++rows;
      }
    }
  }
  EXPECT_EQ(programs, 150);
  EXPECT_GT(rows, 7000);
  EXPECT_GT(calls_skipped, 100);  // actions of a step that comes and goes were met
}

// Abstract time: the circuit and the machine agree on the same programs (without ET), for
// every valuation of the inputs and timeouts, along random runs; a timer started in a cycle
// does not expire at a second call in it (the Iec61131CycleTimers test) in both.
TEST(CycleTimers, RandomProgramsInAbstractTimeCircuitAgreesWithTheMachine) {
  int states = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto prog = random_program(seed, false);
    SCOPED_TRACE(prog.text);
    const auto system = build(prog, semantics::Iec61131Options{});
    ASSERT_TRUE(system);
    const auto& ts = *system;
    auto circuit = semantics::build_iec61131_circuit(ts);
    std::mt19937_64 rng(seed);
    auto state = semantics::first_initial_state(ts);
    for (int cycle = 0; cycle < 12; ++cycle) {
      expect_circuit_agrees(ts, circuit, state);
      if (HasFatalFailure()) return;
      ++states;
      std::vector<std::int64_t> inputs(ts.inputs().size());
      for (auto& v : inputs) v = static_cast<std::int64_t>(rng() & 1U);
      const auto r = semantics::simulate(ts, state, {inputs});
      ASSERT_TRUE(r.ok) << r.error;
      state = r.states.back();
    }
  }
  EXPECT_EQ(states, 40 * 12);
}

}  // namespace
}  // namespace sfcv::engine

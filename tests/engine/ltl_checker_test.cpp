// The explicit LTL checker against the CTL labelling where an LTL formula has a CTL equivalent
// on total systems (G p = AG p, F p = AF p, X p = AX p, p U q = A[p U q], G F p = AG AF p,
// G (p -> F q) = AG (p -> AF q), G (p -> X q) = AG (p -> AX q)), on random charts; every LTL
// counterexample is a lasso that replays through `simulate` and falsifies the formula when the
// formula is evaluated on it (an independent evaluator over the ultimately periodic run). The
// BDD engine's symbolic LTL agrees with the explicit checker on random (chart, formula) pairs
// under both readings of deadlocks, and its lassos are genuine too (IEC 61131-3; on Grafcet the
// bdd engine refuses LTL and the explicit lassos are checked).

#include <gtest/gtest.h>

#include <random>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "logic/ltl_automaton.hpp"
#include "logic/parser.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"
#include "support/random_grafcet.hpp"

namespace sfcv::engine {
namespace {

using logic::Formula;
using logic::Op;

struct Setup {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Setup load(const std::string& text, const std::vector<std::string>& assume = {}) {
  Setup s;
  auto loaded = io::load_iec_text(text, "generated.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  semantics::Iec61131Options options;
  if (!assume.empty()) {
    logic::CheckInputs in;
    in.assume = assume;
    options.assumptions = logic::assumption_exprs(logic::parse_check_inputs(in).spec);
  }
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts);
  return s;
}

logic::CheckTask task_of(const Setup& s, const std::vector<std::string>& ctl,
                         const std::vector<std::string>& ltl,
                         const std::vector<std::string>& fair = {},
                         const model::Budget& budget = {}) {
  logic::CheckInputs in;
  in.ctl = ctl;
  in.ltl = ltl;
  in.fair = fair;
  auto parsed = logic::parse_check_inputs(in);
  for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
  logic::CheckTask task;
  task.system = s.ts.get();
  task.project = &s.project;
  task.limits = budget;
  model::Diagnostics diags;
  logic::resolve_into(parsed.spec, *s.ts, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  return task;
}

logic::CheckReport check(const Setup& s, const std::vector<std::string>& ctl,
                         const std::vector<std::string>& ltl,
                         const std::vector<std::string>& fair = {},
                         const model::Budget& budget = {}) {
  return make_explicit_model_checker()->check(task_of(s, ctl, ltl, fair, budget));
}

bool has_successor(const semantics::TransitionSystem& ts, semantics::StateView s) {
  struct Any final : semantics::SuccessorSink {
    bool any = false;
    void successor(const semantics::Successor&) override { any = true; }
  } sink;
  ts.successors(s, sink);
  return sink.any;
}

bool holds_in(const semantics::TransitionSystem& ts, const Formula& f, semantics::StateView s) {
  switch (f.op) {
    case Op::True:
      return true;
    case Op::False:
      return false;
    case Op::Atom:
      return ts.observe(s, static_cast<std::uint32_t>(f.observable)) != 0;
    case Op::Compare:
      return logic::compare(f.cmp, ts.observe(s, static_cast<std::uint32_t>(f.observable)),
                            f.value);
    case Op::Not:
      return !holds_in(ts, *f.args[0], s);
    case Op::And:
      return holds_in(ts, *f.args[0], s) && holds_in(ts, *f.args[1], s);
    case Op::Or:
      return holds_in(ts, *f.args[0], s) || holds_in(ts, *f.args[1], s);
    case Op::Implies:
      return !holds_in(ts, *f.args[0], s) || holds_in(ts, *f.args[1], s);
    case Op::Iff:
      return holds_in(ts, *f.args[0], s) == holds_in(ts, *f.args[1], s);
    case Op::Xor:
      return holds_in(ts, *f.args[0], s) != holds_in(ts, *f.args[1], s);
    default:
      ADD_FAILURE() << "not propositional";
      return false;
  }
}

/// LTL on the lasso steps[0..n-1], n = steps.size() - 1, position n-1 followed by loop_start:
/// per position, whether `f` holds there (U and F as least, R, W and G as greatest fixpoints).
std::vector<bool> on_lasso(const semantics::TransitionSystem& ts, const logic::Trace& t,
                           const Formula& f) {
  const std::size_t n = t.steps.size() - 1;
  auto succ = [&](std::size_t i) { return i + 1 < n ? i + 1 : *t.loop_start; };
  std::vector<bool> v(n);
  if (logic::is_propositional(f)) {
    for (std::size_t i = 0; i < n; ++i) v[i] = holds_in(ts, f, t.steps[i].state);
    return v;
  }
  const auto a = on_lasso(ts, t, *f.args[0]);
  const auto b = f.args.size() > 1 ? on_lasso(ts, t, *f.args[1]) : a;
  auto fix = [&](bool start, auto step) {
    std::vector<bool> x(n, start);
    for (std::size_t round = 0; round < 2 * n + 2; ++round)
      for (std::size_t k = n; k-- > 0;) x[k] = step(k, x[succ(k)]);
    return x;
  };
  switch (f.op) {
    case Op::Not:
      for (std::size_t i = 0; i < n; ++i) v[i] = !a[i];
      return v;
    case Op::And:
      for (std::size_t i = 0; i < n; ++i) v[i] = a[i] && b[i];
      return v;
    case Op::Or:
      for (std::size_t i = 0; i < n; ++i) v[i] = a[i] || b[i];
      return v;
    case Op::Implies:
      for (std::size_t i = 0; i < n; ++i) v[i] = !a[i] || b[i];
      return v;
    case Op::Iff:
      for (std::size_t i = 0; i < n; ++i) v[i] = a[i] == b[i];
      return v;
    case Op::Xor:
      for (std::size_t i = 0; i < n; ++i) v[i] = a[i] != b[i];
      return v;
    case Op::X:
      for (std::size_t i = 0; i < n; ++i) v[i] = a[succ(i)];
      return v;
    case Op::F:
      return fix(false, [&](std::size_t i, bool next) { return a[i] || next; });
    case Op::G:
      return fix(true, [&](std::size_t i, bool next) { return a[i] && next; });
    case Op::U:
      return fix(false, [&](std::size_t i, bool next) { return b[i] || (a[i] && next); });
    case Op::W:
      return fix(true, [&](std::size_t i, bool next) { return b[i] || (a[i] && next); });
    case Op::R:
      return fix(true, [&](std::size_t i, bool next) { return b[i] && (a[i] || next); });
    default:
      ADD_FAILURE() << "CTL in an LTL formula";
      return v;
  }
}

void expect_genuine_lasso(const Setup& s, const logic::PropertyResult& r, const Formula& f,
                          bool stutter = true) {
  ASSERT_TRUE(r.trace) << r.name;
  const auto& t = *r.trace;
  ASSERT_TRUE(t.loop_start) << r.name;
  ASSERT_LT(*t.loop_start, t.steps.size() - 1);
  EXPECT_EQ(t.steps.back().state, t.steps[*t.loop_start].state);
  for (std::size_t k = 1; k < t.steps.size(); ++k) {
    const auto& from = t.steps[k - 1].state;
    // A state without a successor repeats (stutter), unless deadlocks are dropped.
    if (t.steps[k].state == from && t.steps[k].fired.empty() && !has_successor(*s.ts, from)) {
      EXPECT_TRUE(stutter) << r.name << ": a deadlock repeats although deadlocks are dropped";
      EXPECT_NE(t.note.find("deadlock"), std::string::npos);
      continue;
    }
    const auto run = semantics::simulate(*s.ts, from, {t.steps[k].inputs});
    ASSERT_TRUE(run.ok) << r.name << " row " << k << ": " << run.error;
    EXPECT_EQ(run.states.back(), t.steps[k].state) << r.name << " row " << k;
    EXPECT_EQ(run.fired.back(), t.steps[k].fired) << r.name << " row " << k;
  }
  EXPECT_FALSE(on_lasso(*s.ts, t, f)[0]) << r.name << ": the lasso satisfies the formula";
}

/// Random LTL over the chart's Boolean observables (every operator).
class LtlGenerator {
 public:
  LtlGenerator(const semantics::TransitionSystem& ts, std::uint64_t seed) : rng_(seed) {
    for (const auto& o : ts.observables())
      if (o.type.kind == model::TypeKind::Bool) atoms_.push_back(o.name);
  }
  std::string prop(int depth) {
    if (depth == 0 || pick(3) == 0) return atoms_[pick(static_cast<std::uint32_t>(atoms_.size()))];
    static const char* binary[] = {" & ", " | ", " -> "};
    if (pick(3) == 0) return "!(" + prop(depth - 1) + ")";
    return "(" + prop(depth - 1) + binary[pick(3)] + prop(depth - 1) + ")";
  }
  std::string ltl(int depth) {
    if (depth == 0 || pick(5) == 0) return prop(1);
    static const char* unary[] = {"!", "X ", "F ", "G "};
    static const char* binary[] = {" & ", " | ", " -> ", " U ", " R ", " W "};
    if (pick(2) == 0) return std::string(unary[pick(4)]) + "(" + ltl(depth - 1) + ")";
    return "(" + ltl(depth - 1) + binary[pick(6)] + ltl(depth - 1) + ")";
  }
  std::uint32_t pick(std::uint32_t n) { return static_cast<std::uint32_t>(rng_() % n); }

 private:
  std::mt19937_64 rng_;
  std::vector<std::string> atoms_;
};

TEST(LtlChecker, AgreesWithCtlEquivalents) {
  std::size_t holds = 0, violated = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(8 + static_cast<std::uint32_t>(seed % 5), 3, seed));
    ASSERT_TRUE(s.ts);
    LtlGenerator gen(*s.ts, seed);
    std::vector<std::string> ctl, ltl;
    for (int k = 0; k < 6; ++k) {
      const auto p = gen.prop(2), q = gen.prop(2);
      ltl.insert(ltl.end(), {"G " + p, "F " + p, "X " + p, "(" + p + ") U (" + q + ")", "G F " + p,
                             "G (" + p + " -> F " + q + ")", "G (" + p + " -> X " + q + ")"});
      ctl.insert(ctl.end(),
                 {"AG " + p, "AF " + p, "AX " + p, "A[" + p + " U " + q + "]", "AG AF " + p,
                  "AG (" + p + " -> AF " + q + ")", "AG (" + p + " -> AX " + q + ")"});
    }
    const auto report = check(s, ctl, ltl);
    ASSERT_EQ(report.results.size(), 2 * ltl.size());
    for (std::size_t k = 0; k < ltl.size(); ++k) {
      const auto& c = report.results[k];
      const auto& l = report.results[ctl.size() + k];
      EXPECT_EQ(c.verdict, l.verdict) << c.formula << " vs " << l.formula;
      holds += l.verdict == logic::Verdict::Holds;
      violated += l.verdict == logic::Verdict::Violated;
    }
  }
  EXPECT_GT(holds, 50u);
  EXPECT_GT(violated, 50u);
}

TEST(LtlChecker, CounterexamplesAreGenuineLassos) {
  std::size_t lassos = 0, holds = 0;
  for (std::uint64_t seed = 20; seed <= 31; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(9, 3, seed));
    LtlGenerator gen(*s.ts, seed);
    std::vector<std::string> ltl;
    for (int k = 0; k < 15; ++k) ltl.push_back(gen.ltl(4));
    const auto report = check(s, {}, ltl);
    logic::CheckInputs in;
    in.ltl = ltl;
    auto parsed = logic::parse_check_inputs(in);
    logic::CheckTask task;
    task.system = s.ts.get();
    model::Diagnostics diags;
    logic::resolve_into(parsed.spec, *s.ts, task, diags);
    for (std::size_t k = 0; k < ltl.size(); ++k) {
      const auto& r = report.results[k];
      ASSERT_NE(r.verdict, logic::Verdict::Unknown) << r.formula;
      // A propositional formula is a state property: checked like CTL, no lasso.
      if (r.verdict == logic::Verdict::Violated && logic::is_ltl(*task.properties[k].formula)) {
        expect_genuine_lasso(s, r, *task.properties[k].formula);
        ++lassos;
      } else {
        ++holds;
      }
    }
  }
  EXPECT_GT(lassos, 40u);
  EXPECT_GT(holds, 20u);
}

struct Agreement {
  std::size_t holds = 0, violated = 0, lassos = 0, stutters = 0;
};

/// The explicit and BDD engines on the same LTL task: equal verdicts, and every BDD
/// counterexample is a genuine lasso (the explicit ones are checked above).
void expect_engines_agree(const Setup& s, const std::vector<std::string>& ltl,
                          const std::vector<std::string>& fair, logic::DeadlockPaths paths,
                          Agreement& a) {
  auto task = task_of(s, {}, ltl, fair);
  logic::set_deadlock_paths(task, paths);
  const auto e = make_explicit_model_checker()->check(task);
  const auto bdd = make_bdd_model_checker();
  ASSERT_TRUE(bdd->can_handle(task));
  const auto b = bdd->check(task);
  ASSERT_EQ(e.results.size(), b.results.size());
  for (std::size_t k = 0; k < e.results.size(); ++k) {
    const auto& x = e.results[k];
    const auto& y = b.results[k];
    ASSERT_NE(x.verdict, logic::Verdict::Unknown) << x.formula << ": " << x.message;
    EXPECT_EQ(x.verdict, y.verdict) << x.formula << ": explicit " << logic::to_string(x.verdict)
                                    << ", bdd " << logic::to_string(y.verdict);
    a.holds += y.verdict == logic::Verdict::Holds;
    a.violated += y.verdict == logic::Verdict::Violated;
    if (y.verdict == logic::Verdict::Violated && logic::is_ltl(*task.properties[k].formula)) {
      expect_genuine_lasso(s, y, *task.properties[k].formula,
                           paths == logic::DeadlockPaths::Stutter);
      ++a.lassos;
      a.stutters += y.trace && y.trace->note.find("deadlock") != std::string::npos;
    }
  }
}

Setup load_grafcet(std::uint64_t seed) {
  Setup s;
  s.project = test::random_grafcet(seed);
  model::Diagnostics diags;
  s.ts = semantics::make_grafcet_system(s.project, {}, diags);
  EXPECT_TRUE(s.ts);
  return s;
}

TEST(LtlChecker, BddAgreesWithExplicitOnIecCharts) {
  Agreement a;
  for (std::uint64_t seed = 40; seed <= 57; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    // Every third chart deadlocks where S1 is active and i0 is false (no input is allowed
    // there), so that both readings of deadlocks are exercised.
    const auto s = seed % 3 == 0 ? load(bench::random_chart_iec(9, 3, seed), {"S1 -> i0 & !i0"})
                                 : load(bench::random_chart_iec(9, 3, seed));
    LtlGenerator gen(*s.ts, seed);
    std::vector<std::string> ltl, fair;
    for (int k = 0; k < 12; ++k) ltl.push_back(gen.ltl(4));
    if (seed % 4 == 1) fair.push_back(gen.prop(1));
    for (auto paths : {logic::DeadlockPaths::Stutter, logic::DeadlockPaths::Drop})
      expect_engines_agree(s, ltl, fair, paths, a);
  }
  EXPECT_GT(a.holds, 60u);
  EXPECT_GT(a.violated, 60u);
  EXPECT_GT(a.lassos, 60u);
  EXPECT_GT(a.stutters, 0u);
}

// Grafcet: the bdd engine refuses LTL (its lassos are not built symbolically yet, see
// BddModelChecker::can_handle); the explicit engine checks it under both readings.
TEST(LtlChecker, GrafcetLtlIsExplicitOnly) {
  std::size_t holds = 0, violated = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load_grafcet(seed);
    ASSERT_TRUE(s.ts);
    LtlGenerator gen(*s.ts, seed);
    std::vector<std::string> ltl;
    for (int k = 0; k < 6; ++k) ltl.push_back(gen.ltl(3));
    auto task = task_of(s, {}, ltl);
    std::string why;
    EXPECT_FALSE(make_bdd_model_checker()->can_handle(task, &why));
    EXPECT_NE(why.find("IEC 61131-3 charts only"), std::string::npos) << why;
    for (auto paths : {logic::DeadlockPaths::Stutter, logic::DeadlockPaths::Drop}) {
      auto t = task_of(s, {}, ltl);
      logic::set_deadlock_paths(t, paths);
      const auto e = make_explicit_model_checker()->check(t);
      for (std::size_t k = 0; k < e.results.size(); ++k) {
        const auto& r = e.results[k];
        ASSERT_NE(r.verdict, logic::Verdict::Unknown) << r.formula << ": " << r.message;
        holds += r.verdict == logic::Verdict::Holds;
        violated += r.verdict == logic::Verdict::Violated;
        if (r.verdict == logic::Verdict::Violated && logic::is_ltl(*t.properties[k].formula))
          expect_genuine_lasso(s, r, *t.properties[k].formula,
                               paths == logic::DeadlockPaths::Stutter);
      }
    }
  }
  EXPECT_GT(holds, 20u);
  EXPECT_GT(violated, 20u);
}

TEST(LtlChecker, FairnessAndDeadlocks) {
  const auto s = load(bench::random_chart_iec(8, 3, 4));
  // With `fair FALSE` no path is fair: every property holds.
  const auto r = check(s, {}, {"G F S2", "F FALSE"}, {"FALSE"});
  EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds);
  EXPECT_EQ(r.results[1].verdict, logic::Verdict::Holds);
  // A state whose every input is excluded repeats forever (stutter): the initial S0 stays,
  // F !S0 fails, and the lasso is the deadlock repeated.
  const auto d = load(bench::random_chart_iec(8, 3, 4), {"FALSE"});
  const auto dr = check(d, {}, {"G X TRUE", "G (S0 -> G S0)", "F !S0"});
  EXPECT_EQ(dr.results[0].verdict, logic::Verdict::Holds);
  EXPECT_EQ(dr.results[1].verdict, logic::Verdict::Holds);
  EXPECT_EQ(dr.results[2].verdict, logic::Verdict::Violated);
  ASSERT_TRUE(dr.results[2].trace);
  EXPECT_NE(dr.results[2].trace->note.find("deadlock"), std::string::npos);
}

TEST(LtlChecker, LimitsGiveUnknown) {
  const auto s = load(bench::random_chart_iec(12, 3, 7));
  model::Budget budget;
  budget.max_states = 3;
  const auto r = check(s, {}, {"G F S1"}, {}, budget);
  EXPECT_NE(r.results[0].verdict, logic::Verdict::Holds);
  model::Budget memory;
  memory.max_memory_bytes = 1;
  const auto m = check(s, {}, {"G F S1"}, {}, memory);
  EXPECT_EQ(m.results[0].verdict, logic::Verdict::Unknown);
  const auto ok = check(s, {}, {"G TRUE"}, {}, budget);
  EXPECT_EQ(ok.results[0].verdict, logic::Verdict::Unknown);
  model::Budget past = model::Budget::with_timeout(1e-9);
  const auto late = check(s, {}, {"G F S1"}, {}, past);
  EXPECT_EQ(late.results[0].verdict, logic::Verdict::Unknown);
  // The BDD engine: a state limit or the deadline leaves LTL unknown, never holds.
  const auto bdd = make_bdd_model_checker();
  for (const auto& b : {budget, past}) {
    const auto limited = bdd->check(task_of(s, {}, {"G TRUE", "G F S1"}, {}, b));
    ASSERT_EQ(limited.results.size(), 2u);
    for (const auto& x : limited.results)
      EXPECT_EQ(x.verdict, logic::Verdict::Unknown) << x.formula;
  }
}

TEST(LtlAutomaton, SmallTableaux) {
  auto f = [](const char* text) { return logic::parse_ltl(text).formula; };
  // G a: one node, no acceptance set; F a: needs one set.
  const auto g = logic::ltl_to_buchi(f("G a"));
  EXPECT_EQ(g.num_sets, 0u);
  EXPECT_EQ(g.nodes.size(), 1u);
  const auto fa = logic::ltl_to_buchi(f("F a"));
  EXPECT_EQ(fa.num_sets, 1u);
  EXPECT_FALSE(fa.initial.empty());
  // G a & F !a: a node never keeps both a and its complement !a.
  const auto contra = logic::ltl_to_buchi(f("G a & F !a"));
  EXPECT_FALSE(contra.nodes.empty());
  for (const auto& n : contra.nodes) EXPECT_LE(n.label.size(), 1u);
}

}  // namespace
}  // namespace sfcv::engine

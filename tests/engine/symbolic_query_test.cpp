// The symbolic (BDD) evaluation of set queries: each operator on a small hand-written chart with
// known sets, then agreement with the explicit evaluation (engine/explicit/query_evaluator.hpp)
// on generated charts and random queries: same sorts, same sets element by element, same
// counts and tests, and the same canonical numbering of situations and evolutions.

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "chart_families.hpp"
#include "engine/bdd/symbolic_query_evaluator.hpp"
#include "engine/explicit/canonical_order.hpp"
#include "engine/explicit/query_evaluator.hpp"
#include "engine/query/query_service.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::engine {
namespace {

using State = std::vector<semantics::StateWord>;
using Edge = std::pair<State, State>;

struct Chart {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Chart load(const std::string& text, semantics::Iec61131Options options = {}) {
  Chart s;
  auto loaded = io::load_iec_text(text, "generated.st");
  EXPECT_TRUE(loaded.ok());
  s.project = std::move(*loaded.project);
  model::Diagnostics diags;
  s.ts = semantics::make_iec61131_system(s.project, options, diags);
  EXPECT_TRUE(s.ts) << (diags.empty() ? "" : diags.front().str());
  return s;
}

constexpr std::uint64_t kLimit = 1'000'000;

/// A symbolic system with its evaluator (one at a time: BuDDy has one global manager).
struct Symbolic {
  explicit Symbolic(const semantics::TransitionSystem& ts)
      : sys(ts, semantics::build_iec61131_circuit(ts)), ev(sys) {}
  SymbolicSystem sys;
  SymbolicQueryEvaluator ev;

  std::set<State> states(const bdd::Bdd& b) const {
    auto v = ev.states_of(b, kLimit);
    return {v.begin(), v.end()};
  }
  std::set<Edge> edges(const bdd::Bdd& b) const {
    auto v = ev.evolutions_of(b, kLimit);
    return {v.begin(), v.end()};
  }
};

// ---------------------------------------------------------------------------------------------
// Each operator on a small chart:
//   Idle -[go & level > 2]-> Run (lamp) -[!go]-> Idle, Run -[go & level = 5]-> Stop
// Every scan cycle is an evolution, so there are self-loops: 3 situations, 6 evolutions.

const char* kSmall = R"(
PROGRAM Small
  VAR_INPUT go : BOOL; level : INT(0..5); END_VAR
  VAR_OUTPUT lamp : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Run: lamp(N); END_STEP
  STEP Stop: END_STEP
  TRANSITION FROM Idle TO Run := go AND level > 2; END_TRANSITION
  TRANSITION FROM Run TO Idle := NOT go; END_TRANSITION
  TRANSITION FROM Run TO Stop := go AND level = 5; END_TRANSITION
END_PROGRAM
)";

class SmallChart : public ::testing::Test {
 protected:
  SmallChart() : s_(load(kSmall)), sym_(*s_.ts) {}

  /// The one active step of a state, by its short name.
  std::string step_of(const State& st) const {
    std::string r;
    const auto& obs = s_.ts->observables();
    for (std::uint32_t o = 0; o < obs.size(); ++o)
      if (obs[o].kind == semantics::ObservableKind::Step && s_.ts->observe(st, o))
        r += (r.empty() ? "" : "+") + obs[o].name.substr(obs[o].name.find('.') + 1);
    return r;
  }
  SymbolicQueryResult run(const std::string& q) {
    return sym_.ev.evaluate(logic::compile_query(q, lib_, *s_.ts));
  }
  std::set<std::string> S(const std::string& q) {
    const auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::States) << q;
    std::set<std::string> out;
    for (const auto& st : sym_.states(r.set.bdd)) out.insert(step_of(st));
    return out;
  }
  std::set<std::string> E(const std::string& q) {
    const auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Evolutions) << q;
    std::set<std::string> out;
    for (const auto& [a, b] : sym_.edges(r.set.bdd)) out.insert(step_of(a) + ">" + step_of(b));
    return out;
  }
  std::set<std::string> St(const std::string& q) {
    const auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Steps) << q;
    std::set<std::string> out;
    const auto& obs = s_.ts->observables();
    r.set.steps.for_each([&](std::uint64_t o) { out.insert(obs[o].name); });
    return out;
  }
  std::int64_t N(const std::string& q) {
    const auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Int) << q;
    return r.number;
  }
  bool B(const std::string& q) {
    const auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Bool) << q;
    return r.truth;
  }

  Chart s_;
  Symbolic sym_;
  logic::QueryLibrary lib_;
};

using Strings = std::set<std::string>;

TEST_F(SmallChart, Constants) {
  EXPECT_EQ(S("Y"), (Strings{"Idle", "Run", "Stop"}));
  EXPECT_EQ(S("Y0"), (Strings{"Idle"}));
  EXPECT_EQ(E("T"),
            (Strings{"Idle>Idle", "Idle>Run", "Run>Idle", "Run>Run", "Run>Stop", "Stop>Stop"}));
  EXPECT_EQ(E("Tclear"), (Strings{"Idle>Run", "Run>Idle", "Run>Stop"}));
  EXPECT_EQ(St("Steps"), (Strings{"Small.Idle", "Small.Run", "Small.Stop"}));
  EXPECT_EQ(N("#Y"), 3);
  EXPECT_EQ(N("#T"), 6);
  EXPECT_EQ(N("#Steps"), 3);
  EXPECT_EQ(N("#Tclear"), 3);
}

TEST_F(SmallChart, BooleanOperators) {
  EXPECT_EQ(S("Y - Y0"), (Strings{"Run", "Stop"}));
  EXPECT_EQ(S("Y0 + Act(Stop)"), (Strings{"Idle", "Stop"}));
  EXPECT_EQ(S("Act(Run) * Emis(lamp)"), (Strings{"Run"}));
  EXPECT_EQ(E("T - Tclear"), (Strings{"Idle>Idle", "Run>Run", "Stop>Stop"}));
  EXPECT_EQ(St("Steps - {Idle}"), (Strings{"Small.Run", "Small.Stop"}));
}

TEST_F(SmallChart, IntExtAmontAval) {
  EXPECT_EQ(E("Int(Act(Run))"), (Strings{"Run>Idle", "Run>Run", "Run>Stop"}));
  EXPECT_EQ(E("Ext(Act(Run))"), (Strings{"Idle>Run", "Run>Run"}));
  EXPECT_EQ(S("Amont(Tclear)"), (Strings{"Idle", "Run"}));
  EXPECT_EQ(S("Aval(Tclear)"), (Strings{"Idle", "Run", "Stop"}));
  EXPECT_EQ(S("Upstream(Ext(Act(Stop)))"), (Strings{"Run", "Stop"}));
  EXPECT_EQ(S("Downstream(Int(Y0))"), (Strings{"Idle", "Run"}));
  EXPECT_EQ(S("Y - Amont(T)"), Strings{});  // every cycle has a successor
}

TEST_F(SmallChart, SuccPredIncludeTheirStart) {
  EXPECT_EQ(S("Succ(Y0, T - Nec(go))"), (Strings{"Idle"}));
  EXPECT_EQ(S("Succ(Y0, Tclear)"), (Strings{"Idle", "Run", "Stop"}));
  EXPECT_EQ(S("Succ(Act(Stop), {})"), (Strings{"Stop"}));
  EXPECT_EQ(S("Pred(Act(Stop), T)"), (Strings{"Idle", "Run", "Stop"}));
  EXPECT_EQ(S("Pred(Act(Stop), T - Ext(Act(Run)))"), (Strings{"Run", "Stop"}));
  EXPECT_EQ(S("Pred(Act(Stop), T - Ext(Act(Stop)))"), (Strings{"Stop"}));
  EXPECT_EQ(S("Y - Pred(Y0, T)"), (Strings{"Stop"}));
}

TEST_F(SmallChart, ActDes) {
  EXPECT_EQ(S("Act({Run, Stop})"), Strings{});
  EXPECT_EQ(S("Des({Run, Stop})"), (Strings{"Idle"}));
  EXPECT_EQ(S("Act({})"), (Strings{"Idle", "Run", "Stop"}));
  EXPECT_EQ(S("Des(Steps - {Stop})"), (Strings{"Stop"}));
}

TEST_F(SmallChart, NecIsImplicationOverEveryInputOfTheEdge) {
  EXPECT_EQ(E("Nec(go)"), (Strings{"Idle>Run", "Run>Run", "Run>Stop"}));
  EXPECT_EQ(E("Nec(level > 2)"), (Strings{"Idle>Run", "Run>Stop"}));
  EXPECT_EQ(E("Nec(level = 5)"), (Strings{"Run>Stop"}));
  EXPECT_EQ(E("Nec(!go)"), (Strings{"Run>Idle"}));
  EXPECT_EQ(E("Nec(TRUE)"), E("T"));
  EXPECT_EQ(E("Nec(go | !go)"), E("T"));
  // Step names read the upstream situation.
  EXPECT_EQ(E("Nec(Run & go)"), (Strings{"Run>Run", "Run>Stop"}));
  EXPECT_EQ(E("Nec(lamp | level <= 2)"), (Strings{"Run>Idle", "Run>Run", "Run>Stop"}));
}

TEST_F(SmallChart, Emis) {
  EXPECT_EQ(S("Emis(lamp)"), (Strings{"Run"}));
  EXPECT_EQ(S("Emis(!lamp & !Stop)"), (Strings{"Idle"}));
  EXPECT_EQ(S("Emis(lamp = Run)"), (Strings{"Idle", "Run", "Stop"}));
  EXPECT_EQ(S("Emis(FALSE)"), Strings{});
}

TEST_F(SmallChart, LetSetBuilderTestsCounts) {
  EXPECT_EQ(E("let c = Act(Run); Ext(c) - Int(c)"), (Strings{"Idle>Run"}));
  EXPECT_EQ(St("{e in Steps | Act({e}) * Y0 != {}}"), (Strings{"Small.Idle"}));
  EXPECT_EQ(St("{e | Emis(e & lamp) != {}}"), (Strings{"Small.Run"}));
  EXPECT_EQ(St("{e | #Int(Act({e})) > 2}"), (Strings{"Small.Run"}));
  EXPECT_TRUE(B("Act({Run, Stop}) = {}"));
  EXPECT_FALSE(B("Y - Pred(Y0, T) = {}"));
  EXPECT_TRUE(B("Emis(lamp) = Act(Run)"));
  EXPECT_TRUE(B("#Pred(Y0, T) < #Y & !(T = {})"));
  EXPECT_EQ(N("#Nec(go)"), 3);
  const auto r = run("Y - Pred(Y0, T) = {}");
  ASSERT_TRUE(r.witness_sort);
  EXPECT_EQ(*r.witness_sort, logic::Sort::States);
  EXPECT_EQ(sym_.states(r.witness.bdd).size(), 1u);
}

TEST_F(SmallChart, NumberingIsBreadthFirstThenCanonical) {
  // Idle (depth 0) is #0, Run (depth 1) #1, Stop (depth 2) #2; evolutions by (source, target).
  const auto states = sym_.states(sym_.ev.reachable());
  std::map<std::string, std::uint64_t> id;
  for (const auto& st : states) id[step_of(st)] = sym_.ev.state_id(st);
  EXPECT_EQ(id, (std::map<std::string, std::uint64_t>{{"Idle", 0}, {"Run", 1}, {"Stop", 2}}));
  std::map<std::string, std::uint64_t> eid;
  for (const auto& [a, b] : sym_.edges(sym_.ev.evolutions()))
    eid[step_of(a) + ">" + step_of(b)] = sym_.ev.evolution_id(a, b);
  EXPECT_EQ(eid, (std::map<std::string, std::uint64_t>{{"Idle>Idle", 0},
                                                       {"Idle>Run", 1},
                                                       {"Run>Idle", 2},
                                                       {"Run>Run", 3},
                                                       {"Run>Stop", 4},
                                                       {"Stop>Stop", 5}}));
}

// ---------------------------------------------------------------------------------------------
// Agreement with the explicit evaluation.

/// Random queries over a chart's steps, Boolean outputs and inputs, covering every operator.
class QueryGenerator {
 public:
  QueryGenerator(const semantics::TransitionSystem& ts, std::uint64_t seed) : rng_(seed) {
    for (const auto& o : ts.observables()) {
      if (o.kind == semantics::ObservableKind::Step)
        steps_.push_back(o.name);
      else if (o.type.kind == model::TypeKind::Bool &&
               o.kind == semantics::ObservableKind::Variable)
        outputs_.push_back(o.name);
      else if (o.kind == semantics::ObservableKind::Variable)
        int_outputs_.push_back({o.name, o.type.lo, o.type.hi});
    }
    for (const auto& in : ts.inputs()) {
      if (in.pseudo) continue;
      if (in.type.kind == model::TypeKind::Bool)
        inputs_.push_back(in.name);
      else
        int_inputs_.push_back({in.name, in.type.lo, in.type.hi});
    }
  }

  std::string query() {
    switch (pick(6)) {
      case 0:
        return states(3);
      case 1:
        return evolutions(3);
      case 2:
        return step_set(2);
      case 3:
        return "#" + any_set(3);
      case 4:
        return any_set(3) + (pick(2) ? " = {}" : " != {}");
      default:
        return test(2);
    }
  }

 private:
  struct IntName {
    std::string name;
    std::int64_t lo, hi;
  };
  std::uint32_t pick(std::size_t n) { return static_cast<std::uint32_t>(rng_() % n); }
  template <class V>
  const auto& one(const V& v) {
    return v[pick(v.size())];
  }

  std::string any_set(int d) {
    switch (pick(3)) {
      case 0:
        return states(d);
      case 1:
        return evolutions(d);
      default:
        return step_set(d);
    }
  }
  std::string bin(const std::string& a, const std::string& b) {
    static const char* ops[] = {" + ", " * ", " - "};
    return "(" + a + ops[pick(3)] + b + ")";
  }
  std::string step_literal() {
    std::string r = "{";
    const auto n = pick(3);
    for (std::uint32_t k = 0; k < n && !steps_.empty(); ++k) r += (k ? ", " : "") + one(steps_);
    return r + "}";
  }
  std::string step_set(int d) {
    if (d <= 0) return pick(2) ? "Steps" : step_literal();
    switch (pick(5)) {
      case 0:
        return "Steps";
      case 1:
        return step_literal();
      case 2:
        return bin(step_set(d - 1), step_set(d - 1));
      case 3: {
        const std::string e = "e" + std::to_string(d);
        std::string t;
        switch (pick(4)) {
          case 0:
            t = "Act({" + e + "}) * " + states(d - 1) + " != {}";
            break;
          case 1:
            t = "Des({" + e + "}) = {}";
            break;
          case 2:
            t = "Emis(" + e + " & " + out_expr(1) + ") != {}";
            break;
          default:
            t = "#Int(Act({" + e + "})) > " + std::to_string(pick(4));
            break;
        }
        return "{" + e + " in " + step_set(d - 1) + " | " + t + "}";
      }
      default:
        return step_literal();
    }
  }
  std::string out_atom() {
    const auto k = pick(4);
    if (k == 0 && !int_outputs_.empty()) {
      const auto& v = one(int_outputs_);
      static const char* cmp[] = {" = ", " != ", " < ", " <= ", " > ", " >= "};
      const auto c =
          v.lo + static_cast<std::int64_t>(pick(static_cast<std::size_t>(v.hi - v.lo + 1)));
      return "(" + v.name + cmp[pick(6)] + std::to_string(c) + ")";
    }
    if (k == 1 && !outputs_.empty()) return one(outputs_);
    if (k == 2 && !steps_.empty()) return one(steps_);
    return pick(2) ? "TRUE" : (steps_.empty() ? "FALSE" : one(steps_));
  }
  std::string out_expr(int d) {
    if (d <= 0 || pick(3) == 0) return out_atom();
    switch (pick(3)) {
      case 0:
        return "!(" + out_expr(d - 1) + ")";
      case 1:
        return "(" + out_expr(d - 1) + " & " + out_expr(d - 1) + ")";
      default:
        return "(" + out_expr(d - 1) + " | " + out_expr(d - 1) + ")";
    }
  }
  std::string in_atom() {
    const auto k = pick(5);
    if (k <= 1 && !inputs_.empty()) return one(inputs_);
    if (k == 2 && !int_inputs_.empty()) {
      const auto& v = one(int_inputs_);
      static const char* cmp[] = {" = ", " != ", " < ", " <= ", " > ", " >= "};
      const auto c =
          v.lo + static_cast<std::int64_t>(pick(static_cast<std::size_t>(v.hi - v.lo + 1)));
      return "(" + v.name + cmp[pick(6)] + std::to_string(c) + ")";
    }
    return out_atom();
  }
  std::string in_expr(int d) {
    if (d <= 0 || pick(3) == 0) return in_atom();
    switch (pick(3)) {
      case 0:
        return "!(" + in_expr(d - 1) + ")";
      case 1:
        return "(" + in_expr(d - 1) + " & " + in_expr(d - 1) + ")";
      default:
        return "(" + in_expr(d - 1) + " | " + in_expr(d - 1) + ")";
    }
  }
  std::string states(int d) {
    if (d <= 0) {
      switch (pick(4)) {
        case 0:
          return "Y";
        case 1:
          return "Y0";
        case 2:
          return "Act(" + step_literal() + ")";
        default:
          return "Emis(" + out_expr(1) + ")";
      }
    }
    switch (pick(11)) {
      case 0:
        return "Act(" + step_set(d - 1) + ")";
      case 1:
        return "Des(" + step_set(d - 1) + ")";
      case 2:
        return "Emis(" + out_expr(2) + ")";
      case 3:
        return "Amont(" + evolutions(d - 1) + ")";
      case 4:
        return "Aval(" + evolutions(d - 1) + ")";
      case 5:
        return "Succ(" + states(d - 1) + ", " + evolutions(d - 1) + ")";
      case 6:
        return "Pred(" + states(d - 1) + ", " + evolutions(d - 1) + ")";
      case 7:
        return bin(states(d - 1), states(d - 1));
      case 8:
        return "(let x = " + states(d - 1) + "; " + "Pred(x, Int(x)) + Aval(Ext(x)))";
      case 9:
        return "(" + states(d - 1) + " - {})";
      default:
        return pick(2) ? "Y" : "Y0";
    }
  }
  std::string evolutions(int d) {
    if (d <= 0) return pick(3) == 0 ? "Tclear" : pick(2) ? "T" : "Nec(" + in_expr(1) + ")";
    switch (pick(7)) {
      case 0:
        return "Int(" + states(d - 1) + ")";
      case 1:
        return "Ext(" + states(d - 1) + ")";
      case 2:
        return "Nec(" + in_expr(2) + ")";
      case 3:
        return bin(evolutions(d - 1), evolutions(d - 1));
      case 4:
        return "(let c = " + states(d - 1) + "; Ext(c) - Int(c))";
      case 5:
        return "Tclear";
      default:
        return "T";
    }
  }
  std::string test(int d) {
    if (d <= 0) {
      switch (pick(3)) {
        case 0:
          return "#" + states(1) + " < #" + states(1);
        case 1:
          return states(2) + " = " + states(2);
        default:
          return evolutions(2) + " != {}";
      }
    }
    switch (pick(3)) {
      case 0:
        return "(" + test(d - 1) + " & " + test(d - 1) + ")";
      case 1:
        return "(" + test(d - 1) + " | " + test(d - 1) + ")";
      default:
        return "!(" + test(d - 1) + ")";
    }
  }

  std::mt19937_64 rng_;
  std::vector<std::string> steps_, outputs_, inputs_;
  std::vector<IntName> int_outputs_, int_inputs_;
};

struct Explicit {
  explicit Explicit(const semantics::TransitionSystem& ts)
      : g(build_reachable_situation_graph(ts)), ev(g) {}
  ReachableSituationGraph g;
  QueryEvaluator ev;

  std::set<State> states(const DynamicBitset& b) const {
    std::set<State> r;
    b.for_each([&](std::uint64_t s) {
      const auto v = g.states().at(static_cast<std::uint32_t>(s));
      r.emplace(v.begin(), v.end());
    });
    return r;
  }
  std::set<Edge> edges(const DynamicBitset& b) const {
    std::set<Edge> r;
    b.for_each([&](std::uint64_t e) {
      const auto a = g.states().at(ev.source(e)), t = g.states().at(g.target(e));
      r.emplace(State(a.begin(), a.end()), State(t.begin(), t.end()));
    });
    return r;
  }
};

void expect_same_set(logic::Sort sort, const Explicit& x, const DynamicBitset& xs,
                     const Symbolic& y, const SymbolicSet& ys, const std::string& q) {
  switch (sort) {
    case logic::Sort::States: {
      const auto a = x.states(xs), b = y.states(ys.bdd);
      EXPECT_EQ(a, b) << q;
      EXPECT_EQ(xs.count(), static_cast<std::uint64_t>(y.sys.count(ys.bdd))) << q;
      break;
    }
    case logic::Sort::Evolutions: {
      EXPECT_EQ(x.edges(xs), y.edges(ys.bdd)) << q;
      EXPECT_EQ(xs.count(), static_cast<std::uint64_t>(y.sys.count_pairs(ys.bdd))) << q;
      break;
    }
    case logic::Sort::Steps:
      EXPECT_EQ(xs.elements(), ys.steps.elements()) << q;
      break;
    default:
      EXPECT_TRUE(xs.none() && ys.bdd.is_false() && ys.steps.none()) << q;
      break;
  }
}

/// Random queries whose answer is a non-empty set, a true test or a non-zero count: the
/// generator must not only produce trivial queries.
int g_nontrivial = 0;

/// Evaluates `count` random queries both ways; returns how many were compared.
int compare_on(const Chart& s, std::uint64_t seed, int count) {
  Explicit x(*s.ts);
  EXPECT_TRUE(x.g.complete());
  Symbolic y(*s.ts);
  EXPECT_EQ(static_cast<double>(x.g.num_states()), y.ev.num_states());
  EXPECT_EQ(static_cast<double>(x.g.num_edges()), y.ev.num_evolutions());

  // The same numbering.
  const auto numbering = canonical_numbering(x.g, x.ev.sources());
  for (std::uint32_t st = 0; st < x.g.num_states(); ++st)
    EXPECT_EQ(numbering.state[st], y.ev.state_id(x.g.states().at(st))) << "state " << st;
  for (std::uint64_t e = 0; e < x.g.num_edges(); e += 1 + e / 16)  // a sample on big graphs
    EXPECT_EQ(numbering.edge[e],
              y.ev.evolution_id(x.g.states().at(x.ev.source(e)), x.g.states().at(x.g.target(e))))
        << "edge " << e;

  QueryGenerator gen(*s.ts, seed);
  logic::QueryLibrary lib;
  int compared = 0;
  for (int i = 0; i < count; ++i) {
    const auto text = gen.query();
    logic::CompiledQuery q;
    try {
      q = logic::compile_query(text, lib, *s.ts);
    } catch (const logic::QueryError& e) {
      ADD_FAILURE() << "the generator wrote an invalid query: " << text << ": " << e.what();
      continue;
    }
    const auto a = x.ev.evaluate(q);
    const auto b = y.ev.evaluate(q);
    ++compared;
    g_nontrivial += a.sort == logic::Sort::Bool  ? a.truth
                    : a.sort == logic::Sort::Int ? a.number != 0
                                                 : !a.set.none();
    if (a.sort != b.sort) {
      ADD_FAILURE() << "sorts differ: " << text;
      continue;
    }
    switch (a.sort) {
      case logic::Sort::Bool:
        EXPECT_EQ(a.truth, b.truth) << text;
        EXPECT_EQ(a.witness_sort.has_value(), b.witness_sort.has_value()) << text;
        if (a.witness_sort && b.witness_sort)
          expect_same_set(*a.witness_sort, x, a.witness, y, b.witness, text);
        break;
      case logic::Sort::Int:
        EXPECT_EQ(a.number, b.number) << text;
        break;
      default:
        expect_same_set(a.sort, x, a.set, y, b.set, text);
        break;
    }
  }
  return compared;
}

TEST(SymbolicQueryAgreement, RandomChartsAndQueries) {
  int compared = 0;
  g_nontrivial = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(8 + static_cast<std::uint32_t>(seed % 7), 3, seed));
    ASSERT_TRUE(s.ts);
    compared += compare_on(s, seed, 60);
  }
  EXPECT_EQ(compared, 12 * 60);
  EXPECT_GT(g_nontrivial, compared / 3) << "mostly trivial queries";
  std::cout << "[ info ] " << g_nontrivial << " of " << compared << " answers are non-trivial\n";
}

TEST(SymbolicQueryAgreement, NondeterministicConflicts) {
  semantics::Iec61131Options options;
  options.priority = semantics::PriorityMode::None;
  for (std::uint64_t seed = 30; seed <= 33; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto s = load(bench::random_chart_iec(10, 3, seed), options);
    ASSERT_TRUE(s.ts);
    EXPECT_EQ(compare_on(s, seed, 40), 40);
  }
}

TEST(SymbolicQueryAgreement, FamiliesWithIntegerInputsAndNesting) {
  std::uint64_t seed = 200;
  for (const auto& text :
       {bench::parallel_branches_iec(3, true), bench::parallel_branches_iec(3, false),
        bench::tanks_iec(2, true), bench::nested_charts_iec(3), std::string(kSmall)}) {
    const auto s = load(text);
    ASSERT_TRUE(s.ts);
    EXPECT_EQ(compare_on(s, ++seed, 60), 60);
  }
}

TEST(SymbolicQueryAgreement, ChemicalPlant) {
  std::ifstream f(std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st");
  std::stringstream text;
  text << f.rdbuf();
  const auto s = load(text.str());
  ASSERT_TRUE(s.ts);
  EXPECT_EQ(compare_on(s, 7, 40), 40);
}

// An integer variable, compared inside Emis, and a range error (the explicit graph's anomaly):
// the situations that raise it are the same ones, and the sets agree.
TEST(SymbolicQueryAgreement, IntegerVariablesAndRangeErrors) {
  const auto s = load(R"(
PROGRAM Count
  VAR_INPUT a : BOOL; k : INT(-2..3); END_VAR
  VAR_OUTPUT n : INT(0..3); busy : BOOL; END_VAR
  INITIAL_STEP S1: END_STEP
  STEP S2: Inc(N); busy(N); END_STEP
  TRANSITION FROM S1 TO S2 := a AND k >= 0; END_TRANSITION
  TRANSITION FROM S2 TO S1 := NOT a OR k < -1; END_TRANSITION
  ACTION Inc: n := n + 1; END_ACTION
END_PROGRAM
)");
  ASSERT_TRUE(s.ts);
  {
    Explicit x(*s.ts);
    Symbolic y(*s.ts);
    EXPECT_FALSE(x.g.anomalies().empty());
    std::set<State> explicit_error_states;
    for (std::uint32_t st = 0; st < x.g.num_states(); ++st) {
      struct Sink final : semantics::SuccessorSink {
        bool error = false;
        void successor(const semantics::Successor&) override {}
        void anomaly(const semantics::Anomaly&) override { error = true; }
      } sink;
      s.ts->successors(x.g.states().at(st), sink);
      if (sink.error) {
        const auto v = x.g.states().at(st);
        explicit_error_states.emplace(v.begin(), v.end());
      }
    }
    EXPECT_EQ(explicit_error_states, y.states(y.ev.range_error_states()));
  }
  EXPECT_EQ(compare_on(s, 99, 80), 80);
}

// A timer and a step duration (pseudo-inputs in abstract time, counters in discrete time),
// bounded integers with a negative range, timed, stored and pulse qualifiers.
const char* kTimersAndData = R"(
PROGRAM Timed
  VAR_INPUT go, stop : BOOL; level : INT(0..4); END_VAR
  VAR_OUTPUT lamp, pump : BOOL; count : INT(0..3); END_VAR
  VAR t1 : TON; n : INT(-2..2); END_VAR
  INITIAL_STEP Idle: Reset(N); END_STEP
  STEP Run: lamp(D, T#1s); Work(N); pump(S); END_STEP
  STEP Wait: pump(R); Tick(P1); END_STEP
  ACTION Reset: n := 0; END_ACTION
  ACTION Work:
    t1(IN := go, PT := T#500ms);
    IF level > 2 AND n < 2 THEN n := n + 1; ELSIF level = 0 AND n > -2 THEN n := n - 1; END_IF;
  END_ACTION
  ACTION Tick: IF count < 3 THEN count := count + 1; END_IF; END_ACTION
  TRANSITION FROM Idle TO Run := go AND NOT stop; END_TRANSITION
  TRANSITION FROM Run TO Wait := t1.Q OR Run.T > T#1s; END_TRANSITION
  TRANSITION FROM Wait TO Idle := stop; END_TRANSITION
END_PROGRAM
)";

TEST(SymbolicQueryAgreement, TimersCountersAndData) {
  for (auto time : {semantics::TimeMode::Abstract, semantics::TimeMode::Discrete}) {
    SCOPED_TRACE(time == semantics::TimeMode::Abstract ? "abstract time" : "discrete time");
    semantics::Iec61131Options options;
    options.time = time;
    options.cycle_ms = 250;
    const auto s = load(kTimersAndData, options);
    ASSERT_TRUE(s.ts);
    EXPECT_EQ(compare_on(s, 5 + static_cast<std::uint64_t>(time), 60), 60);
  }
}

// The query service (engine/query/query_service.hpp) gives the same answers through either
// engine, listed alike: ids, states, conditions and fired transitions; `auto` says which it took.
void expect_same_listing(const logic::QueryListing& a, const logic::QueryListing& b,
                         const std::string& q) {
  EXPECT_EQ(a.sort, b.sort) << q;
  ASSERT_EQ(a.states.size(), b.states.size()) << q;
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    EXPECT_EQ(a.states[i].id, b.states[i].id) << q;
    EXPECT_EQ(a.states[i].state, b.states[i].state) << q;
  }
  ASSERT_EQ(a.edges.size(), b.edges.size()) << q;
  for (std::size_t i = 0; i < a.edges.size(); ++i) {
    EXPECT_EQ(a.edges[i].id, b.edges[i].id) << q;
    EXPECT_EQ(a.edges[i].source.id, b.edges[i].source.id) << q;
    EXPECT_EQ(a.edges[i].target.state, b.edges[i].target.state) << q;
    EXPECT_EQ(a.edges[i].fired, b.edges[i].fired) << q;
  }
  EXPECT_EQ(a.steps, b.steps) << q;
}

TEST(QueryService, ExplicitAndBddListTheSameAnswers) {
  const auto s = load(bench::random_chart_iec(9, 3, 77));
  ASSERT_TRUE(s.ts);
  std::vector<std::string> notes;
  QueryServiceOptions xo;
  xo.engine = QueryEngineChoice::Auto;
  xo.note = [&](const std::string& n) { notes.push_back(n); };
  auto x = make_query_service(*s.ts, xo);
  EXPECT_EQ(x->name(), "explicit");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "using the explicit engine");
  QueryGenerator gen(*s.ts, 77);
  logic::QueryLibrary lib;
  std::vector<logic::CompiledQuery> queries;
  for (int i = 0; i < 40; ++i) queries.push_back(logic::compile_query(gen.query(), lib, *s.ts));
  std::vector<logic::QueryAnswer> explicit_answers;
  for (const auto& q : queries) explicit_answers.push_back(x->answer(q));
  const auto summary = x->graph();
  x.reset();  // one BuDDy manager at a time

  QueryServiceOptions yo;
  yo.engine = QueryEngineChoice::Bdd;
  auto y = make_query_service(*s.ts, yo);
  EXPECT_EQ(y->name(), "bdd");
  EXPECT_EQ(y->graph().situations, summary.situations);
  EXPECT_EQ(y->graph().evolutions, summary.evolutions);
  EXPECT_TRUE(summary.exact());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto b = y->answer(queries[i]);
    const auto& a = explicit_answers[i];
    const std::string q = "query " + std::to_string(i);
    EXPECT_EQ(a.sort, b.sort) << q;
    EXPECT_EQ(a.truth, b.truth) << q;
    EXPECT_EQ(a.number, b.number) << q;
    expect_same_listing(a.set, b.set, q);
    expect_same_listing(a.witness, b.witness, q);
  }
}

TEST(QueryService, AutoSwitchesToBddBeyondTheStateBudget) {
  // 2^18 situations: more than kAutoProbeStates.
  const auto s = load(bench::parallel_branches_iec(18, false));
  ASSERT_TRUE(s.ts);
  std::vector<std::string> notes;
  QueryServiceOptions o;
  o.engine = QueryEngineChoice::Auto;
  o.note = [&](const std::string& n) { notes.push_back(n); };
  auto svc = make_query_service(*s.ts, o);
  EXPECT_EQ(svc->name(), "bdd");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("switching to the bdd engine"), std::string::npos) << notes[0];
  EXPECT_GT(svc->graph().situations, kAutoProbeStates);
}

}  // namespace
}  // namespace sfcv::engine

// The Grafcet micro-step circuit against the explicit evolutions, without BDDs: from every node
// of the RSG of generated grafcets, under the valuation of every explicit edge, running the
// circuit concretely (first situation, evolutions until stable, emitted node) reaches the
// edge's target; and the initial situations under every input valuation are the RSG's initial
// nodes.

#include "semantics/grafcet_circuit.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <set>

#include "support/random_grafcet.hpp"

namespace sfcv::semantics {
namespace {

/// Circuit input bits of a valuation (value - lo per input, LSB first).
std::vector<bool> bits_of(const TransitionSystem& ts, const GrafcetCircuit& c,
                          const std::vector<std::int64_t>& values) {
  std::vector<bool> bits(c.aig.inputs().size(), false);
  for (std::size_t i = 0; i < c.input_bits.size(); ++i) {
    const auto& t = ts.inputs()[i].type;
    const std::int64_t lo = t.kind == model::TypeKind::Bool ? 0 : t.lo;
    const auto v = static_cast<std::uint64_t>(values[i] - lo);
    for (std::size_t k = 0; k < c.input_bits[i].size(); ++k)
      bits[c.aig.nodes()[Aig::node_of(c.input_bits[i][k])].index] = ((v >> k) & 1U) != 0;
  }
  return bits;
}

std::vector<bool> latches_of(const TransitionSystem& ts, const GrafcetCircuit& c, StateView s) {
  std::vector<bool> latches(c.aig.latches().size(), false);
  const auto& layout = ts.layout();
  for (std::uint32_t f = 0; f < c.field_latches.size(); ++f) {
    const auto v = static_cast<std::uint64_t>(layout.get(s, f) - layout.fields()[f].lo);
    for (std::size_t k = 0; k < c.field_latches[f].size(); ++k)
      latches[c.field_latches[f][k]] = ((v >> k) & 1U) != 0;
  }
  return latches;
}

/// Runs the evolutions from the first situation `x` (state and prev latches); returns the
/// emitted node, or nothing on an anomaly or after too many evolutions.
std::optional<std::vector<StateWord>> run(const TransitionSystem& ts, const GrafcetCircuit& c,
                                          std::vector<bool> x, const std::vector<bool>& in) {
  const std::size_t n = c.num_state_latches;
  for (int k = 0; k < 1000; ++k) {
    const auto nodes = c.aig.evaluate(in, x);
    if (Aig::value_of(nodes, c.range_error)) return std::nullopt;
    if (Aig::value_of(nodes, c.stable)) {
      std::vector<bool> fin(x.size());
      for (std::size_t l = 0; l < n; ++l) fin[l] = Aig::value_of(nodes, c.final_next[l]);
      return state_from_latches(ts, c, fin);
    }
    std::vector<bool> y(x.size());
    for (std::size_t l = 0; l < n; ++l) y[l] = Aig::value_of(nodes, c.aig.latches()[l].next);
    for (std::size_t p = 0; p < c.prev_of.size(); ++p) y[n + p] = x[c.prev_of[p]];
    x = std::move(y);
  }
  return std::nullopt;
}

struct Collect final : SuccessorSink {
  std::vector<std::pair<std::vector<StateWord>, std::vector<std::int64_t>>> edges;
  const TransitionSystem* ts = nullptr;
  void successor(const Successor& s) override {
    // A valuation inside the condition: each literal's low end, unconstrained inputs 0 (for a
    // pseudo-input: no elapse).
    std::vector<std::int64_t> v(ts->inputs().size(), 0);
    for (std::size_t i = 0; i < v.size(); ++i)
      if (ts->inputs()[i].type.kind == model::TypeKind::Int) v[i] = ts->inputs()[i].type.lo;
    for (const auto& l : s.condition.cubes.front().literals) v[l.input] = l.lo;
    edges.emplace_back(std::vector<StateWord>(s.target.begin(), s.target.end()), v);
  }
};

void check(const model::Project& p, bool single, std::size_t& checked) {
  GrafcetOptions o;
  o.single_input_change = single;
  model::Diagnostics d;
  const auto ts = make_grafcet_system(p, o, d);
  ASSERT_TRUE(ts);
  const auto c = build_grafcet_circuit(*ts);
  const auto g = test::build_rsg(p, o);
  ASSERT_TRUE(g.graph.complete());
  const std::size_t n = c.num_state_latches;
  // Edges: the circuit from the source under the edge's valuation gives the target.
  for (std::uint32_t s = 0; s < g.graph.num_states(); ++s) {
    const auto view = g.graph.states().at(s);
    const std::vector<StateWord> src(view.begin(), view.end());
    Collect out;
    out.ts = ts.get();
    ts->successors(src, out);
    for (const auto& [target, values] : out.edges) {
      const auto in = bits_of(*ts, c, values);
      const auto latches = latches_of(*ts, c, src);
      const auto nodes = c.aig.evaluate(in, latches);
      ASSERT_TRUE(Aig::value_of(nodes, c.event)) << ts->describe(src);
      std::vector<bool> x(latches.size());
      for (std::size_t l = 0; l < n; ++l) x[l] = Aig::value_of(nodes, c.start_next[l]);
      for (std::size_t q = 0; q < c.prev_of.size(); ++q) x[n + q] = latches[c.prev_of[q]];
      const auto reached = run(*ts, c, x, in);
      ASSERT_TRUE(reached) << ts->describe(src);
      EXPECT_EQ(*reached, target) << ts->describe(src) << " -> " << ts->describe(target)
                                  << ", circuit: " << ts->describe(*reached);
      ++checked;
    }
  }
  // Initial nodes: every valuation of the (non-pseudo) inputs, stabilised.
  std::set<std::vector<StateWord>> expected, got;
  for (auto s : g.graph.initial_states()) {
    const auto st = g.graph.states().at(s);
    expected.insert(std::vector<StateWord>(st.begin(), st.end()));
  }
  const auto& inputs = ts->inputs();
  std::vector<std::int64_t> v(inputs.size(), 0);
  std::function<void(std::size_t)> all = [&](std::size_t i) {
    if (i == inputs.size()) {
      const auto in = bits_of(*ts, c, v);
      const auto nodes = c.aig.evaluate(in, std::vector<bool>(c.aig.latches().size(), false));
      std::vector<bool> x(c.aig.latches().size());
      for (std::size_t l = 0; l < n; ++l) x[l] = Aig::value_of(nodes, c.initial_next[l]);
      for (std::size_t q = 0; q < c.prev_of.size(); ++q) x[n + q] = x[c.prev_of[q]];
      if (auto r = run(*ts, c, x, in)) got.insert(*r);
      return;
    }
    if (inputs[i].pseudo) {
      v[i] = 0;
      all(i + 1);
      return;
    }
    const auto& t = inputs[i].type;
    const std::int64_t lo = t.kind == model::TypeKind::Bool ? 0 : t.lo,
                       hi = t.kind == model::TypeKind::Bool ? 1 : t.hi;
    for (std::int64_t x = lo; x <= hi; ++x) {
      v[i] = x;
      all(i + 1);
    }
  };
  all(0);
  EXPECT_EQ(got, expected);
}

TEST(GrafcetCircuit, EvolutionsMatchTheExplicitSystemOnRandomGrafcets) {
  std::size_t checked = 0;  // edges compared
  for (std::uint64_t seed = 1; seed <= 40; ++seed)
    for (bool single : {true, false}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (single ? "" : " --multi-input-change"));
      check(test::random_grafcet(seed), single, checked);
    }
  EXPECT_GT(checked, 1000u);
}

TEST(GrafcetCircuit, RejectsAProductOfVariables) {
  test::GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.local("k", model::Type::integer("INT", 0, 3));
  b.transition({"1"}, {"2"}, test::v("a"));
  b.transition({"2"}, {"1"},
               test::cmp(model::ExprKind::Gt,
                         model::make_binary(model::ExprKind::Mul, test::v("k"), test::v("k")),
                         test::num(1)));
  b.stored("2", model::StoredWhen::Activation, "k", test::num(2));
  model::Diagnostics d;
  const auto ts = make_grafcet_system(b.project(), {}, d);
  ASSERT_TRUE(ts);
  EXPECT_THROW(build_grafcet_circuit(*ts), CircuitUnsupported);
}

}  // namespace
}  // namespace sfcv::semantics

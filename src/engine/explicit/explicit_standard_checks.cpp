// The standard checks on an explicit graph: the situation sets the shared runner works on
// (engine/standard_check_runner.hpp) as one flag per graph state.

#include <span>

#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/standard_check_runner.hpp"
#include "logic/formula.hpp"

namespace sfcv::engine {

namespace {

constexpr std::uint32_t kNone = ReachableSituationGraph::kNone;

class ExplicitSpace {
 public:
  using Set = StateSet;
  using State = std::uint32_t;

  ExplicitSpace(const ReachableSituationGraph& g, CtlChecker& fair)
      : g_(g), ts_(g.system()), fair_(fair), plain_(g), n_(g.num_states()) {}

  std::string_view name() const { return "explicit"; }
  bool complete() const { return g_.complete(); }
  std::string limit_name() const { return g_.limit_reached(); }
  std::string state_count() const { return std::to_string(n_); }
  std::uint64_t progress_states() const { return n_; }
  bool has_fairness() const { return fair_.has_fairness(); }

  Set reached() const { return Set(n_, 1); }
  Set initial() const {
    Set r(n_, 0);
    for (auto s : g_.initial_states()) r[s] = 1;
    return r;
  }
  Set none() const { return Set(n_, 0); }
  Set meet(const Set& a, const Set& b) const {
    Set r(n_);
    for (std::uint32_t s = 0; s < n_; ++s) r[s] = a[s] && b[s];
    return r;
  }
  Set join(const Set& a, const Set& b) const {
    Set r(n_);
    for (std::uint32_t s = 0; s < n_; ++s) r[s] = a[s] || b[s];
    return r;
  }
  Set minus(const Set& a, const Set& b) const {
    Set r(n_);
    for (std::uint32_t s = 0; s < n_; ++s) r[s] = a[s] && !b[s];
    return r;
  }
  bool empty(const Set& a) const { return first_of(a) == kNone; }
  logic::BigCount count(const Set& a) const {
    std::uint64_t c = 0;
    for (auto x : a) c += x != 0;
    return c;
  }

  Set observable(std::uint32_t o) const {
    Set r(n_);
    for (std::uint32_t s = 0; s < n_; ++s) r[s] = ts_.observe(g_.states().at(s), o) != 0;
    return r;
  }
  Set field_nonzero(std::uint32_t f) const {
    Set r(n_);
    for (std::uint32_t s = 0; s < n_; ++s) r[s] = ts_.layout().get(g_.states().at(s), f) != 0;
    return r;
  }
  bool can_fire(std::uint32_t t) const { return g_.fired_somewhere()[t]; }
  bool fires_initially(std::uint32_t t) const { return g_.fired_initially()[t]; }
  /// An evolution back to the situation itself clears transitions too (docs/semantics.md 2.5).
  Set fires(std::uint32_t t) const {
    Set r = edge_sources([&](std::uint64_t e) {
      for (auto x : g_.fired(e))
        if (x == t) return true;
      return false;
    });
    const auto& back = g_.returning_states();
    for (std::size_t i = 0; i < back.size(); ++i)
      for (auto x : g_.returning_fired(i)) r[back[i]] = r[back[i]] || x == t;
    return r;
  }
  Set fires_any() const {
    Set r = edge_sources([&](std::uint64_t e) { return !g_.fired(e).empty(); });
    for (auto s : g_.returning_states()) r[s] = 1;
    return r;
  }
  /// The situations with an evolution in a situation of which step observable o is active,
  /// o being inactive in the situation itself: at the evolution's end (an edge's target), or
  /// in between (the crossed steps, Successor::entered). A step's activity is an OR of step
  /// fields (a macro-step's, of its expansion's), so it holds in some situation of a set of
  /// evolutions iff it holds on the union of their crossed fields.
  Set enters(std::uint32_t o) const {
    Set r = edge_sources(
        [&](std::uint64_t e) { return ts_.observe(g_.states().at(g_.target(e)), o) != 0; });
    const auto& states = g_.crossing_states();
    for (std::size_t i = 0; i < states.size(); ++i)
      if (!r[states[i]] && on_fields(g_.crossed(i), o)) r[states[i]] = 1;
    for (std::uint32_t s = 0; s < n_; ++s)
      if (r[s] && ts_.observe(g_.states().at(s), o)) r[s] = 0;
    return r;
  }
  /// Whether step observable o is active in a situation an initial situation crosses while it
  /// stabilises (the initial situation itself included) or ends in.
  bool enters_initially(std::uint32_t o) const {
    for (auto s : g_.initial_states())
      if (ts_.observe(g_.states().at(s), o)) return true;
    return on_fields(g_.entered_initially(), o);
  }
  Set stuck() const {
    Set r(n_, 0);
    for (std::uint32_t s = 0; s < n_; ++s)
      r[s] = g_.expanded(s) && g_.edges_begin(s) == g_.edges_end(s);
    return r;
  }
  Set pre(const Set& to) const {
    return edge_sources([&](std::uint64_t e) { return to[g_.target(e)] != 0; });
  }
  Set post(const Set& from) const {
    Set r(n_, 0);
    for (std::uint32_t s = 0; s < n_; ++s)
      if (from[s] && g_.expanded(s))
        for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) r[g_.target(e)] = 1;
    return r;
  }
  /// Backward closure of `seeds` over all edges.
  Set backward(Set seeds) const {
    const auto& po = g_.predecessor_offsets();
    const auto& pe = g_.predecessor_edges();
    return closure(std::move(seeds), [&](std::uint32_t t, auto&& add) {
      for (auto i = po[t]; i < po[t + 1]; ++i) add(g_.source(pe[i]));
    });
  }
  /// Forward closure of `seeds`.
  Set forward(Set seeds) const {
    return closure(std::move(seeds), [&](std::uint32_t s, auto&& add) {
      if (!g_.expanded(s)) return;
      for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) add(g_.target(e));
    });
  }
  /// `seeds` and every state `neighbours(x, add)` adds from a state x in it, transitively.
  template <class Neighbours>
  Set closure(Set seeds, Neighbours&& neighbours) const {
    std::vector<std::uint32_t> queue;
    for (std::uint32_t s = 0; s < seeds.size(); ++s)
      if (seeds[s]) queue.push_back(s);
    auto add = [&](std::uint32_t x) {
      if (seeds[x]) return;
      seeds[x] = 1;
      queue.push_back(x);
    };
    while (!queue.empty()) {
      const auto x = queue.back();
      queue.pop_back();
      neighbours(x, add);
    }
    return seeds;
  }
  Set ctl(const logic::FormulaPtr& f, bool fair) { return (fair ? fair_ : plain_).sat(f); }
  logic::Trace explain(const logic::FormulaPtr& f, const Set& from, bool fair) {
    std::vector<std::uint32_t> sources;
    for (auto s : g_.initial_states())
      if (from[s]) sources.push_back(s);
    return (fair ? fair_ : plain_).explain(f, sources);
  }
  /// A shortest run to the shallowest state of `set` (the first one among equally deep).
  logic::Trace path_to(const Set& set) {
    std::uint32_t best = kNone;
    for (std::uint32_t s = 0; s < n_; ++s)
      if (set[s] && (best == kNone || g_.depth(s) < g_.depth(best))) best = s;
    return plain_.path_to(best);
  }

  State one(const Set& a) const { return first_of(a); }
  std::vector<State> first(const Set& a, std::size_t k) const {
    std::vector<State> out;
    for (std::uint32_t s = 0; s < n_ && out.size() < k; ++s)
      if (a[s]) out.push_back(s);
    return out;
  }
  Set singleton(State s) const {
    Set r(n_, 0);
    r[s] = 1;
    return r;
  }
  std::uint32_t depth(State s) const { return g_.depth(s); }
  std::string describe(State s) const { return ts_.describe(g_.states().at(s)); }

  /// IEC 61131-3: pairs of edges out of one state under overlapping input conditions;
  /// Grafcet: every event, with the transitions it clears. An edge merges the events that end
  /// in its target, so a state whose edges clear two transitions or more is expanded again and
  /// its events visited one by one (FiredPerEvent; `visit` pairs them, polling the deadline).
  template <class Visit, class Related>
  bool simultaneous(Visit&& visit, Related&& /*related*/) const {
    const bool iec = ts_.kind() == semantics::SemanticsKind::Iec61131;
    const auto ignored = conflict_ignored_inputs(ts_);
    std::vector<char> returns_pair(iec ? 0 : n_, 0);  // an event back to s clears two or more
    for (std::size_t i = 0; i < g_.returning_states().size() && !iec; ++i)
      if (g_.returning_fired(i).size() > 1) returns_pair[g_.returning_states()[i]] = 1;
    for (std::uint32_t s = 0; s < n_; ++s) {
      if (!g_.expanded(s)) continue;
      if (!iec) {
        bool expand = returns_pair[s] != 0;
        for (auto a = g_.edges_begin(s); a < g_.edges_end(s) && !expand; ++a)
          expand = g_.fired(a).size() > 1;
        if (!expand) continue;
        FiredPerEvent events;
        ts_.successors(g_.states().at(s), events);
        for (const auto& fired : events.fired)
          visit(std::span<const std::uint32_t>(fired), std::span<const std::uint32_t>{}, s);
        continue;
      }
      for (auto a = g_.edges_begin(s); a < g_.edges_end(s); ++a) {
        for (auto b = a + 1; b < g_.edges_end(s); ++b)
          if (conditions_intersect(g_.condition(a), g_.condition(b), ignored))
            visit(g_.fired(a), g_.fired(b), s);
      }
    }
    return true;
  }

  /// Every pair of edges out of one state (edges are merged by target: their targets differ)
  /// where at least one names an `order:` input.
  template <class Visit>
  bool order_dependent(Visit&& visit) const {
    const auto order = logic::order_inputs(ts_);
    const auto& states = g_.states();
    for (std::uint32_t s = 0; s < n_; ++s) {
      if (!g_.expanded(s)) continue;
      for (auto a = g_.edges_begin(s); a < g_.edges_end(s); ++a) {
        const bool a_ordered = mentions_input(g_.condition(a), order);
        for (auto b = a + 1; b < g_.edges_end(s); ++b)
          if (g_.target(a) != g_.target(b) && (a_ordered || mentions_input(g_.condition(b), order)))
            visit(s, OrderEdge{g_.condition(a), states.at(g_.target(a)), g_.fired(a)},
                  OrderEdge{g_.condition(b), states.at(g_.target(b)), g_.fired(b)});
      }
    }
    return true;
  }

  std::vector<Anomaly<Set>> anomalies() const {
    std::vector<Anomaly<Set>> out;
    for (const auto& a : g_.anomalies()) {
      const std::string kind =
          a.kind == semantics::Anomaly::Kind::Instability ? "instability" : "range error";
      // The semantics may name the kind itself (`sfcv simulate` prints its message alone).
      const bool named = a.message.starts_with(kind + ":");
      out.push_back(
          {(named ? "" : kind + ": ") + a.message +
               (a.condition.is_false() ? ""
                                       : " (inputs " + a.condition.to_string(ts_.inputs()) + ")"),
           std::nullopt});
    }
    return out;
  }

  std::optional<std::string> failure() const { return std::nullopt; }
  std::string note_limit(const LimitReached& e) const { return e.what(); }

 private:
  /// Observable o on the situation whose only non-zero fields are the (one-bit) `fields`.
  bool on_fields(std::span<const std::uint32_t> fields, std::uint32_t o) const {
    if (fields.empty()) return false;
    std::vector<semantics::StateWord> x(ts_.layout().words(), 0);
    for (auto f : fields) ts_.layout().set(x, f, 1);
    return ts_.observe(x, o) != 0;
  }
  std::uint32_t first_of(const Set& a) const {
    for (std::uint32_t s = 0; s < n_; ++s)
      if (a[s]) return s;
    return kNone;
  }
  template <class Pred>
  Set edge_sources(Pred&& pred) const {
    Set r(n_, 0);
    for (std::uint32_t s = 0; s < n_; ++s)
      if (g_.expanded(s))
        for (auto e = g_.edges_begin(s); e < g_.edges_end(s) && !r[s]; ++e)
          if (pred(e)) r[s] = 1;
    return r;
  }

  const ReachableSituationGraph& g_;
  const semantics::TransitionSystem& ts_;
  CtlChecker& fair_;
  CtlChecker plain_;
  std::uint32_t n_;
};

}  // namespace

std::vector<logic::PropertyResult> run_standard_checks(const ReachableSituationGraph& graph,
                                                       CtlChecker& checker,
                                                       const logic::CheckTask& task) {
  if (task.checks.empty()) return {};
  ExplicitSpace space(graph, checker);
  return run_standard_checks_on(space, graph.system(), task);
}

}  // namespace sfcv::engine

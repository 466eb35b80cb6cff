#include "engine/bdd/bdd_model_checker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <unordered_map>

#include "engine/bdd/symbolic_ctl.hpp"
#include "engine/bdd/symbolic_ltl.hpp"
#include "engine/bdd/symbolic_system.hpp"
#include "engine/standard_check_runner.hpp"
#include "logic/formula.hpp"
#include "logic/push_negation.hpp"
#include "logic/standard_checks.hpp"
#include "model/names.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine {

using bdd::Bdd;
using logic::Op;
using logic::PropertyResult;
using logic::Verdict;

namespace {

constexpr const char* kNoInitialState =
    "no initial state: the assumptions exclude every initial situation, or none is stable (see "
    "the instability check)";

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

class Run {
 public:
  Run(const logic::CheckTask& task, SymbolicSystem& sys)
      : task_(task), sys_(sys), ts_(sys.system()) {}

  logic::CheckReport check() {
    const auto start = Clock::now();
    logic::CheckReport report;
    report.engine = "bdd";
    // A limit (the node table full under --memory, the deadline) ends the work: what is
    // decided stays, everything after it is unknown.
    try {
      explore(report, start);
    } catch (const LimitReached& e) {
      failed_ = e.what();
      failed_limit_ = e.which();
      report.complete = false;
      report.limit = to_string(e.which());
      // The rings so far are exact: count them (a walk, no BDD node made), unless a limit
      // stops that too.
      try {
        last_count_ = sys_.count_exact(reached_);
      } catch (const LimitReached&) {
      }
      report.states = last_count_;
      report.depth = static_cast<std::uint32_t>(rings_.empty() ? 0 : rings_.size() - 1);
    }
    std::optional<SymbolicCtl> ctl;
    for (const auto& p : task_.properties) {
      const auto t0 = Clock::now();
      auto r = guarded(p.name, logic::to_string(p.formula), "", [&] {
        if (!ctl) ctl.emplace(sys_, task_.fairness);
        return property(p, *ctl, report);
      });
      r.where = p.where;
      r.seconds = since(t0);
      report.results.push_back(std::move(r));
    }
    {
      BddSpace space(*this, report, ctl);
      for (auto& r : run_standard_checks_on(space, ts_, task_))
        report.results.push_back(std::move(r));
    }
    // Edges last: on a huge model their relation may not fit where the verdicts did.
    report.edges_known = false;
    if (failed_.empty()) {
      try {
        if (report.stopped_early) {
          // Only rings so far: the edges out of the last one are not known.
        } else if (imaged_edges_) {
          // Every imaged ring was simulated, which counted its edges: the imaged rings are
          // the reached set, or all of it but the frontier when a limit stopped the rings.
          report.edges = logic::BigCount(*imaged_edges_);
          report.edges_known = true;
        } else if (!time_for_edges(start)) {
          // Left out: see time_for_edges.
        } else if (const auto edges =
                       sys_.count_edges(report.complete ? reached_ : reached_ & !frontier_)) {
          report.edges = *edges;
          report.edges_known = true;
        }
      } catch (const LimitReached&) {
        // Not counted: the report leaves the number out rather than print a wrong one.
      }
    }
    report.seconds = since(start);
    return report;
  }

 private:
  /// The edges are a figure, not a verdict, and one BuDDy operation of their count is not
  /// interrupted: the pair relation may be far larger than the reached set (an ST loop unrolled
  /// 900 times: one and_exist ran 2.8 s past --timeout 10 in --engine auto's race, and the
  /// backstop ended the run without its report). Under a deadline they are counted only while
  /// a quarter of the time this run has taken is left (a count costs about one image, and a
  /// long exploration under a generous limit keeps its count).
  bool time_for_edges(Clock::time_point start) const {
    return !task_.limits.deadline || 4 * task_.limits.seconds_left() > since(start);
  }

  template <class F>
  PropertyResult guarded(const std::string& name, const std::string& formula,
                         const std::string& check, F&& compute) {
    if (failed_.empty()) {
      try {
        return compute();
      } catch (const LimitReached& e) {
        failed_ = e.what();
        failed_limit_ = e.which();
      }
    }
    PropertyResult r;
    r.name = name;
    r.formula = formula;
    r.check = check;
    r.verdict = Verdict::Unknown;
    r.message = failed_limit_ == Limit::Memory
                    ? "the BDD package ran out of resources: " + failed_
                    : failed_;  // the deadline, or the loop bound that names itself
    return r;
  }

  // The bad states of each property when every property is an invariant AG p (without
  // fairness: a bad state must then also be fair, which needs the whole set) and no standard
  // check needs the whole reachable set; empty otherwise.
  std::vector<Bdd> invariant_bad_states() {
    std::vector<Bdd> bad;
    if (!task_.checks.empty() || !task_.fairness.empty()) return {};
    for (const auto& p : task_.properties) {
      const auto& f = *p.formula;
      if (f.op != Op::AG || !logic::is_propositional(*f.args[0])) return {};
      bad.push_back(!sys_.atom(*f.args[0]));
    }
    return bad;
  }

  void explore(logic::CheckReport& report, Clock::time_point start) {
    reached_ = sys_.initial();
    rings_.push_back(reached_);
    frontier_ = reached_;
    const auto& limits = task_.limits;
    // Invariants ring by ring: once each has met a bad state, the rings so far hold a shortest
    // counterexample for each (path_to) and the rest of the reachable set changes nothing.
    auto undecided = invariant_bad_states();
    auto every_invariant_violated = [&](const Bdd& ring) {
      std::erase_if(undecided, [&](const Bdd& bad) { return !(ring & bad).is_false(); });
      return undecided.empty() && !task_.properties.empty();
    };
    const bool early = !undecided.empty();
    meets_loop_bound(reached_);
    bool stopped = early && every_invariant_violated(reached_);
    while (!stopped && !frontier_.is_false()) {
      // Counting walks the whole set: only when a limit or the progress line needs it (a
      // counter chart takes tens of thousands of rings).
      const bool counting = limits.progress || limits.max_states > 0;
      if (counting) last_count_ = sys_.count_exact(reached_);
      const double states = counting ? last_count_.to_double() : 0;
      if (limits.progress) {
        logic::Progress p;
        p.phase = "explore (bdd)";
        p.states = last_count_.to_u64().value_or(~std::uint64_t{0});
        p.depth = static_cast<std::uint32_t>(rings_.size() - 1);
        p.seconds = since(start);
        limits.progress(p);
      }
      if (limits.max_states > 0 && states > static_cast<double>(limits.max_states)) {
        report.complete = false;
        report.limit = "states";
        break;
      }
      if (limits.expired()) {
        report.complete = false;
        report.limit = "time";
        break;
      }
      auto step = sys_.step(frontier_, reached_);
      // --max-states bounds the reached set: a ring that would take it past the bound is not
      // kept (it held up to 4,096 states more before), so the states explored are at most
      // max_states (unless the initial states alone are more).
      if (limits.max_states > 0 && !step.ring.is_false() &&
          sys_.count_exact(step.reached).to_double() > static_cast<double>(limits.max_states)) {
        report.complete = false;
        report.limit = "states";
        break;
      }
      imaged_edges_ =
          imaged_edges_ && step.edges ? std::optional(*imaged_edges_ + *step.edges) : std::nullopt;
      const Bdd next = std::move(step.ring);
      if (next.is_false()) {
        frontier_ = next;
        break;
      }
      meets_loop_bound(next);
      reached_ = std::move(step.reached);
      rings_.push_back(next);
      frontier_ = next;
      stopped = early && every_invariant_violated(next);
    }
    report.stopped_early = stopped;
    report.states = sys_.count_exact(reached_);
    last_count_ = report.states;
    report.depth = static_cast<std::uint32_t>(rings_.size() - 1);
    sys_.restrict_sources(reached_);  // Grafcet: its relation is computed from these only
  }

  /// A ring with a state whose cycle may meet the ST loop bound: the successors of that cycle
  /// are not known, so no verdict past it is (docs/semantics.md 1.9.1): the run stops here,
  /// as the explicit engine's does.
  void meets_loop_bound(const Bdd& ring) {
    if ((ring & sys_.loop_limit_states()).is_false()) return;
    throw LimitReached(Limit::Enumeration, sys_.circuit().loop_limit_message());
  }

  std::string limit_message(const logic::CheckReport& report) const {
    return "exploration stopped at the " + report.limit + " limit after " + report.states.str() +
           " states";
  }

  /// A shortest run from an initial state into `target` (which must meet the reached states).
  logic::Trace path_to(const Bdd& target) {
    std::size_t k = 0;
    while (k < rings_.size() && (rings_[k] & target).is_false()) ++k;
    std::vector<std::vector<semantics::StateWord>> states{sys_.pick(rings_[k] & target)};
    for (std::size_t j = k; j-- > 0;)
      states.push_back(sys_.pick(sys_.preimage(sys_.singleton(states.back())) & rings_[j]));
    std::reverse(states.begin(), states.end());
    return to_trace(SymbolicRun{std::move(states), std::nullopt, false});
  }

  /// Each hop is labelled with inputs found on the BDDs and the transitions the circuit fires
  /// under them (enumerating explicit successors would cost 2^inputs per hop on wide charts).
  logic::Trace to_trace(const SymbolicRun& run) {
    const auto& states = run.states;
    logic::Trace t;
    t.loop_start = run.loop_start;
    t.ends_in_deadlock = run.ends_in_deadlock;
    if (states.empty()) return t;
    const auto& circuit = sys_.circuit();
    std::vector<std::int64_t> inputs =
        logic::pick_inputs(semantics::InputCondition::always(), ts_.inputs(), {});
    // Grafcet: the first row is an initial valuation the start stabilises under, and each
    // later row changes as few inputs as the event allows (one under the single-input-change
    // hypothesis), so that `sfcv simulate` replays the rows (docs/semantics.md 2.15).
    if (const auto bits = sys_.initial_inputs(states.front(), inputs); !bits.empty())
      inputs = semantics::inputs_from_bits(ts_, circuit, bits);
    t.steps.push_back({inputs, states.front(), {}});
    for (std::size_t k = 1; k < states.size(); ++k) {
      const auto bits = sys_.inputs_between(states[k - 1], states[k], inputs);
      // Consecutive states of a run are related by construction: a gap is a bug, never a trace.
      // No bits is also the answer of a system without inputs: then the relation decides.
      if (bits.empty() &&
          (sys_.preimage(sys_.singleton(states[k])) & sys_.singleton(states[k - 1])).is_false()) {
        // An LTL lasso may repeat a state without a successor (symbolic_ltl.hpp).
        const bool stutter = states[k] == states[k - 1] &&
                             (sys_.singleton(states[k]) & sys_.has_successor()).is_false();
        if (!stutter) throw std::logic_error("bdd engine: a trace step without a transition");
        t.steps.push_back({inputs, states[k], {}});
        t.note = "the loop stays in a state without a successor: a deadlock repeats forever";
        continue;
      }
      inputs = semantics::inputs_from_bits(ts_, circuit, bits);
      t.steps.push_back({inputs, states[k], sys_.fired_between(states[k - 1], bits)});
    }
    return t;
  }

  PropertyResult property(const logic::Property& p, SymbolicCtl& ctl,
                          const logic::CheckReport& report) {
    PropertyResult r;
    r.name = p.name;
    r.formula = logic::to_string(p.formula);
    r.where = p.where;
    const auto marked = logic::atom_observables(*p.formula);
    const auto& f = p.formula;
    const bool ag = f->op == Op::AG && logic::is_propositional(*f->args[0]);
    const bool ef = f->op == Op::EF && logic::is_propositional(*f->args[0]);
    if (!report.complete || report.stopped_early) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message(report);
      // Reached states are real: a bad one refutes AG p, a good one proves EF p.
      if ((ag && task_.fairness.empty()) || (ef && task_.fairness.empty())) {
        const Bdd inner = sys_.atom(*f->args[0]);
        const Bdd hit = reached_ & (ag ? !inner : inner);
        if (!hit.is_false()) {
          r.verdict = ag ? Verdict::Violated : Verdict::Holds;
          r.message.clear();
          r.trace = path_to(hit);
          r.trace->kind = ag ? logic::TraceKind::Counterexample : logic::TraceKind::Witness;
          r.trace->marked = marked;
        }
      }
      return r;
    }
    // No initial state: every property would hold vacuously; the other engines answer
    // unknown, and so must this one (a run that judged nothing is not a pass).
    if (sys_.initial().is_false()) {
      r.verdict = Verdict::Unknown;
      r.message = kNoInitialState;
      return r;
    }
    if (logic::is_ltl(*f)) return ltl_property(p, ctl, std::move(r));
    // An invariant is decided on the reached states, and a bad one is met by a shortest run
    // through the rings: no fixpoint, and no relation when every image was simulated.
    if (ag && task_.fairness.empty()) {
      const Bdd hit = reached_ & !sys_.atom(*f->args[0]);
      r.verdict = hit.is_false() ? Verdict::Holds : Verdict::Violated;
      if (!hit.is_false()) {
        r.trace = path_to(hit);
        r.trace->kind = logic::TraceKind::Counterexample;
        r.trace->marked = marked;
      }
      return r;
    }
    const Bdd holds = ctl.sat(f);
    const Bdd bad = sys_.initial() & !holds;
    if (bad.is_false()) {
      r.verdict = Verdict::Holds;
      if (!logic::is_propositional(*f)) {
        auto t = to_trace(ctl.explain(f, sys_.initial()));
        if (t.steps.size() > 1 || t.loop_start) {
          t.kind = logic::TraceKind::Witness;
          r.trace = std::move(t);
        }
      }
    } else {
      r.verdict = Verdict::Violated;
      const auto neg = logic::push_negation(f);
      r.trace = to_trace(ctl.explain(neg, bad));
      r.trace->kind = logic::TraceKind::Counterexample;
    }
    if (r.trace) r.trace->marked = marked;
    return r;
  }

  PropertyResult ltl_property(const logic::Property& p, SymbolicCtl& ctl, PropertyResult r) {
    if (sys_.initial().is_false()) {
      r.verdict = Verdict::Unknown;
      r.message = kNoInitialState;
      return r;
    }
    const SymbolicLtlQuery q{p.formula, task_.fairness,
                             task_.deadlock_paths == logic::DeadlockPaths::Stutter};
    const auto run = symbolic_ltl_counterexample(sys_, ctl, reached_, q, task_.limits);
    r.verdict = run ? Verdict::Violated : Verdict::Holds;
    if (run) {
      r.trace = to_trace(*run);
      r.trace->kind = logic::TraceKind::Counterexample;
      r.trace->marked = logic::atom_observables(*p.formula);
    }
    return r;
  }

  /// One situation's successors merged by target, as the explicit graph stores its edges:
  /// the union of the conditions and of the fired transitions.
  struct MergedEdges final : semantics::SuccessorSink {
    struct Edge {
      std::vector<semantics::StateWord> target;
      semantics::InputCondition condition;
      std::vector<std::uint32_t> fired;
    };
    std::vector<Edge> list;
    void successor(const semantics::Successor& s) override {
      auto it = std::find_if(list.begin(), list.end(), [&](const Edge& e) {
        return std::equal(e.target.begin(), e.target.end(), s.target.begin(), s.target.end());
      });
      if (it == list.end())
        it = list.insert(list.end(), Edge{{s.target.begin(), s.target.end()}, {}, {}});
      for (const auto& cube : s.condition.cubes)
        if (std::find(it->condition.cubes.begin(), it->condition.cubes.end(), cube) ==
            it->condition.cubes.end())
          it->condition.cubes.push_back(cube);
      std::vector<std::uint32_t> merged;
      std::set_union(it->fired.begin(), it->fired.end(), s.fired.begin(), s.fired.end(),
                     std::back_inserter(merged));
      it->fired = std::move(merged);
    }
  };

  /// The reached situations as the standard-check runner sees them
  /// (engine/standard_check_runner.hpp): BDDs over the current variables.
  class BddSpace {
   public:
    using Set = Bdd;
    using State = std::vector<semantics::StateWord>;

    BddSpace(Run& run, const logic::CheckReport& report, std::optional<SymbolicCtl>& fair)
        : run_(run), sys_(run.sys_), report_(report), fair_(fair) {}

    std::string_view name() const { return "bdd"; }
    bool complete() const { return report_.complete; }
    std::string limit_name() const { return report_.limit; }
    std::string state_count() const { return report_.states.str(); }
    std::uint64_t progress_states() const {
      return report_.states.to_u64().value_or(~std::uint64_t{0});
    }
    bool has_fairness() const { return !run_.task_.fairness.empty(); }

    Set reached() const { return run_.reached_; }
    Set initial() const { return sys_.initial(); }
    Set none() const { return Bdd::constant(false); }
    Set meet(const Set& a, const Set& b) const { return a & b; }
    Set join(const Set& a, const Set& b) const { return a | b; }
    Set minus(const Set& a, const Set& b) const { return a & !b; }
    bool empty(const Set& a) const { return a.is_false(); }
    logic::BigCount count(const Set& a) const { return sys_.count_exact(a); }

    Set observable(std::uint32_t o) {
      return run_.reached_ & sys_.atom(*logic::observable_atom(run_.ts_, o));
    }
    Set field_nonzero(std::uint32_t f) { return run_.reached_ & sys_.field_nonzero(f); }
    bool can_fire(std::uint32_t t) { return !fires(t).is_false(); }
    bool fires_initially(std::uint32_t t) const { return sys_.fires_initially(t); }
    Set fires(std::uint32_t t) { return run_.reached_ & sys_.fires(t); }
    Set fires_any() { return run_.reached_ & sys_.fires_any(); }
    Set enters(std::uint32_t o) {
      return run_.reached_ & sys_.enters(sys_.atom(*logic::observable_atom(run_.ts_, o)));
    }
    bool enters_initially(std::uint32_t o) {
      return sys_.enters_initially(sys_.atom(*logic::observable_atom(run_.ts_, o)));
    }
    Set stuck() const { return run_.reached_ & !sys_.has_successor(); }
    Set pre(const Set& to) const { return run_.reached_ & sys_.preimage(to); }
    Set post(const Set& from) const { return run_.reached_ & sys_.image(from); }
    // Both closures stay inside the reached set and take the image of the last ring only:
    // from one situation, the full-space preimage of everything found so far blew up (a
    // 39,027-state random chart: 33 s for one closure).
    // On the reached graph, each closure is one search.
    Set backward(const Set& to) const {
      if (auto on_graph = sys_.reach_on_reached_graph(to, Bdd::constant(true), true))
        return *on_graph;
      return closure(to, [&](const Bdd& ring) { return pre(ring); });
    }
    Set forward(const Set& from) const {
      if (auto on_graph = sys_.reach_on_reached_graph(from, Bdd::constant(true), false))
        return *on_graph;
      return closure(from, [&](const Bdd& ring) { return post(ring); });
    }
    template <class Step>
    Set closure(const Set& seeds, Step&& step) const {
      Bdd all = run_.reached_ & seeds, ring = all;
      while (!ring.is_false()) {
        ring = step(ring) & !all;
        all = all | ring;
      }
      return all;
    }
    Set ctl(const logic::FormulaPtr& f, bool fair) { return checker(fair).sat(f); }
    logic::Trace explain(const logic::FormulaPtr& f, const Set& from, bool fair) {
      return run_.to_trace(checker(fair).explain(f, from));
    }
    logic::Trace path_to(const Set& set) { return run_.path_to(set); }

    State one(const Set& set) const { return first(set, 1).front(); }
    /// Ring by ring: the shallowest situations first.
    std::vector<State> first(const Set& set, std::size_t k) const {
      std::vector<State> out;
      for (const auto& ring : run_.rings_)
        for (Bdd rest = ring & set; !rest.is_false() && out.size() < k;) {
          out.push_back(sys_.pick(rest));
          rest = rest & !sys_.singleton(out.back());
        }
      return out;
    }
    Set singleton(const State& x) const { return sys_.singleton(x); }
    std::uint32_t depth(const State& x) const {
      const Bdd one = sys_.singleton(x);
      std::uint32_t k = 0;
      while (k + 1 < run_.rings_.size() && (run_.rings_[k] & one).is_false()) ++k;
      return k;
    }
    std::string describe(const State& x) const { return run_.ts_.describe(x); }

    /// Evolutions enabled together (engine/standard_check_runner.hpp, conflicts()): the
    /// situations to look at are found on the BDDs, ring by ring, and each is expanded
    /// through the system's successor function, so that its edges are the explicit graph's
    /// (merged by target). IEC 61131-3 (--priority none): the (x, plant inputs) where the
    /// choice inputs change the fired set; once a situation is expanded, every (x, plant
    /// inputs) whose fired sets are among its own is dropped. Grafcet: per pair of
    /// transitions related(i, j), the situations where both fire; a pair is dropped once one
    /// evolution fired both, a situation once expanded. (Each situation is expanded through the
    /// successor function: on corpus 22, looking at all 2,346 pairs instead of the few with a
    /// common upstream step took the whole --timeout.)
    template <class Visit, class Related>
    bool simultaneous(Visit&& visit, Related&& related) {
      const auto& ts = run_.ts_;
      const auto& limits = run_.task_.limits;
      const auto ignored = conflict_ignored_inputs(ts);
      const bool iec = ts.kind() == semantics::SemanticsKind::Iec61131;
      if (iec) {
        auto expand = [&](const State& x) {
          MergedEdges edges;
          ts.successors(x, edges);
          for (std::size_t a = 0; a < edges.list.size(); ++a)
            for (std::size_t b = a + 1; b < edges.list.size(); ++b)
              if (conditions_intersect(edges.list[a].condition, edges.list[b].condition, ignored))
                visit(std::span<const std::uint32_t>(edges.list[a].fired),
                      std::span<const std::uint32_t>(edges.list[b].fired), x);
        };
        Bdd open = sys_.choice_matters(run_.reached_);
        for (const auto& ring : run_.rings_)
          for (Bdd here = open & ring; !here.is_false(); here = open & ring) {
            limits.check_time("looking for conflicts");
            const Bdd point = sys_.pick_point(here);
            expand(sys_.pick(sys_.point_state(point)));
            open = open & sys_.beyond_fired_sets_of(point);
          }
        return true;
      }
      const auto n = static_cast<std::uint32_t>(ts.transitions().size());
      std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
      std::vector<Bdd> open;
      for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = i + 1; j < n; ++j) {
          if (!related(i, j)) continue;
          limits.check_time("looking for conflicts");
          if ((fires(i) & fires(j)).is_false()) continue;  // cheap, and usually settles it
          const Bdd both = run_.reached_ & sys_.fires_on_one_edge(i, j);
          if (both.is_false()) continue;
          pairs.emplace_back(i, j);
          open.push_back(both);
        }
      for (const auto& ring : run_.rings_)
        for (;;) {
          limits.check_time("looking for conflicts");
          Bdd any = Bdd::constant(false);
          for (const auto& o : open) any = any | o;
          const Bdd here = any & ring;
          if (here.is_false()) break;
          const State x = sys_.pick(here);
          const Bdd done = !sys_.singleton(x);
          // One event at a time (FiredPerEvent): an edge merges the events ending in its target.
          FiredPerEvent events;
          ts.successors(x, events);
          for (const auto& fired : events.fired)
            visit(std::span<const std::uint32_t>(fired), std::span<const std::uint32_t>{}, x);
          for (std::size_t p = 0; p < pairs.size(); ++p) {
            bool settled = false;
            for (const auto& fired : events.fired)
              settled =
                  settled || (std::binary_search(fired.begin(), fired.end(), pairs[p].first) &&
                              std::binary_search(fired.begin(), fired.end(), pairs[p].second));
            open[p] = settled ? Bdd::constant(false) : open[p] & done;
          }
        }
      return true;
    }

    /// Order-dependence (engine/standard_check_runner.hpp): the situations where the order
    /// inputs change the next state are found on the BDDs (SymbolicSystem::order_matters), then
    /// each, ring by ring, is expanded through the system's successor function, so that its
    /// edges are the explicit graph's. At most kMaxOrderSituations are expanded: the verdict
    /// needs one, the findings are the first ones (the explicit engine lists every one).
    template <class Visit>
    bool order_dependent(Visit&& visit) {
      static constexpr std::size_t kMaxOrderSituations = 64;
      const auto& ts = run_.ts_;
      const auto order = logic::order_inputs(ts);
      Bdd open = sys_.order_matters(run_.reached_);
      std::size_t expanded = 0;
      for (const auto& ring : run_.rings_)
        for (Bdd here = open & ring; !here.is_false() && expanded < kMaxOrderSituations;
             here = open & ring, ++expanded) {
          run_.task_.limits.check_time("looking for order dependence");
          const State x = sys_.pick(here);
          open = open & !sys_.singleton(x);
          MergedEdges edges;
          ts.successors(x, edges);
          for (std::size_t a = 0; a < edges.list.size(); ++a)
            for (std::size_t b = a + 1; b < edges.list.size(); ++b) {
              const auto& ea = edges.list[a];
              const auto& eb = edges.list[b];
              if (mentions_input(ea.condition, order) || mentions_input(eb.condition, order))
                visit(x, OrderEdge{ea.condition, ea.target, ea.fired},
                      OrderEdge{eb.condition, eb.target, eb.fired});
            }
        }
      return true;
    }

    /// Range errors (IEC 61131-3); Grafcet (docs/semantics.md 2.11): events whose transient
    /// evolutions never stabilise or raise a range error, from reached situations or at the start.
    std::vector<Anomaly<Set>> anomalies() const {
      std::vector<Anomaly<Set>> out;
      const auto& ts = run_.ts_;
      const Bdd err = run_.reached_ & sys_.range_error_states();
      if (ts.kind() != semantics::SemanticsKind::Grafcet) {
        if (!err.is_false())
          out.push_back(
              {"a range error (integer overflow, division by zero or a value out of "
               "its type) can occur in " +
                   ts.describe(sys_.pick(err)),
               err});
        return out;
      }
      if (sys_.initial_unstable())
        out.push_back(
            {"instability: under some initial input valuation the transient "
             "evolutions never reach a stable situation",
             std::nullopt});
      if (sys_.initial_range_error())
        out.push_back(
            {"range error: under some initial input valuation an evolution raises "
             "a range error or a forcing conflict",
             std::nullopt});
      const Bdd unstable = run_.reached_ & sys_.unstable_states();
      if (!unstable.is_false())
        out.push_back({"instability: from " + ts.describe(sys_.pick(unstable)) +
                           " an input event starts transient evolutions that never reach a "
                           "stable situation",
                       unstable});
      if (!err.is_false())
        out.push_back({"range error: from " + ts.describe(sys_.pick(err)) +
                           " an input event raises a range error or a forcing conflict",
                       err});
      return out;
    }

    std::optional<std::string> failure() const {
      if (run_.failed_.empty()) return std::nullopt;
      return run_.failed_limit_ == Limit::Memory
                 ? "the BDD package ran out of resources: " + run_.failed_
                 : run_.failed_;
    }
    std::string note_limit(const LimitReached& e) {
      run_.failed_ = e.what();
      run_.failed_limit_ = e.which();
      return *failure();
    }

   private:
    SymbolicCtl& checker(bool fair) {
      auto& slot = fair ? fair_ : plain_;
      if (!slot) slot.emplace(sys_, fair ? run_.task_.fairness : std::vector<logic::FormulaPtr>{});
      return *slot;
    }

    Run& run_;
    SymbolicSystem& sys_;
    const logic::CheckReport& report_;
    std::optional<SymbolicCtl>& fair_;  ///< shared with the properties
    std::optional<SymbolicCtl> plain_;
  };

  const logic::CheckTask& task_;
  SymbolicSystem& sys_;
  const semantics::TransitionSystem& ts_;
  Bdd reached_;
  Bdd frontier_;  ///< the last ring, not expanded when a limit stopped exploration
  std::vector<Bdd> rings_;
  logic::BigCount last_count_;
  /// The edges out of the rings imaged so far, while every image counted them (simulated).
  std::optional<std::uint64_t> imaged_edges_ = 0;
  std::string failed_;  ///< the limit that ended the run, if any
  Limit failed_limit_ = Limit::Memory;
};

class BddModelChecker final : public ModelChecker {
 public:
  explicit BddModelChecker(BddEngineOptions options) : options_(options) {}

  std::string_view name() const override { return "bdd"; }

  bool can_handle(const logic::CheckTask& task, std::string* why) const override {
    if (!task.system) {
      if (why) *why = "no system to check";
      return false;
    }
    // Grafcet lassos are not built symbolically yet: BuDDy's node table was seen corrupted
    // (a crash in a later garbage collection) after them, so the explicit engine checks LTL.
    if (const auto* ltl = logic::first_ltl_property(task);
        ltl && task.system->kind() == semantics::SemanticsKind::Grafcet) {
      if (why)
        *why = "the bdd engine checks LTL on IEC 61131-3 charts only ('" + ltl->name +
               "' on a Grafcet); use --engine explicit (or auto)";
      return false;
    }
    try {
      if (task.system->kind() == semantics::SemanticsKind::Grafcet)
        semantics::build_grafcet_circuit(*task.system, task.limits.deadline,
                                         task.limits.max_memory_bytes);
      else
        semantics::build_iec61131_circuit(*task.system, task.limits.deadline,
                                          task.limits.max_memory_bytes);
    } catch (const semantics::CircuitUnsupported& e) {
      if (why) *why = std::string("the bdd engine cannot encode ") + e.what();
      return false;
    } catch (const LimitReached&) {
      return true;  // check() meets the limit again and answers unknown
    }
    return true;
  }

  logic::CheckReport check(const logic::CheckTask& task) const override {
    SymbolicOptions so;
    so.reorder = options_.reorder;
    so.nodes = options_.initial_nodes;
    if (task.limits.max_memory_bytes > 0) {
      const auto nodes = task.limits.max_memory_bytes / bdd::kBytesPerNode;
      so.max_nodes = static_cast<int>(std::clamp<std::uint64_t>(nodes, 1, 2'000'000'000));
    }
    so.timeout_seconds = task.limits.seconds_left();
    so.deadline = task.limits.deadline;
    if (options_.relation_share > 0 && task.limits.deadline)
      so.relation_deadline =
          Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                             task.limits.seconds_left() * options_.relation_share));
    so.max_circuit_bytes = task.limits.max_memory_bytes;
    // The run's one deadline, in every BDD operation (the fixpoints are loops of them).
    const bdd::DeadlineScope deadline(task.limits.deadline, task.limits.cancel.get());
    try {
      const auto symbolic = make_symbolic_system(*task.system, so);
      Run run(task, *symbolic);
      return run.check();
    } catch (const LimitReached& e) {
      // The relation (or the Grafcet closure) does not fit, or the deadline passed while it
      // was built: every answer is unknown.
      logic::CheckReport report;
      report.engine = "bdd";
      report.complete = false;
      const bool time = e.which() == Limit::Time;
      report.limit = to_string(e.which());
      report.edges_known = false;
      const std::string why =
          (time ? std::string() : "the BDD package ran out of resources: ") + e.what();
      for (const auto& p : task.properties) {
        PropertyResult r;
        r.name = p.name;
        r.formula = logic::to_string(p.formula);
        r.where = p.where;
        r.verdict = Verdict::Unknown;
        r.message = why;
        report.results.push_back(std::move(r));
      }
      // Checks too: a check left without a result must not read as holding.
      for (auto c : task.checks) {
        PropertyResult r;
        r.name = std::string(logic::to_string(c));
        r.check = r.name;
        const auto na = logic::not_applicable(c, *task.system, task.priority_resolves_conflicts);
        r.verdict = na ? Verdict::NotApplicable : Verdict::Unknown;
        r.message = na ? *na : why;
        report.results.push_back(std::move(r));
      }
      return report;
    }
  }

 private:
  BddEngineOptions options_;
};

}  // namespace

ModelCheckerPtr make_bdd_model_checker(const BddEngineOptions& options) {
  return std::make_unique<BddModelChecker>(options);
}

}  // namespace sfcv::engine

#include "engine/bdd/bdd_model_checker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "engine/bdd/symbolic_ctl.hpp"
#include "engine/bdd/symbolic_system.hpp"
#include "engine/explicit/ctl_checker.hpp"
#include "logic/formula.hpp"
#include "logic/standard_checks.hpp"
#include "model/names.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine {

using bdd::Bdd;
using logic::Op;
using logic::PropertyResult;
using logic::StandardCheck;
using logic::Verdict;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

class Run {
 public:
  Run(const logic::CheckTask& task, SymbolicSystem& sys) : task_(task), sys_(sys), ts_(sys.system()) {}

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
      report.states = last_count_;
      report.depth = static_cast<std::uint32_t>(rings_.empty() ? 0 : rings_.size() - 1);
    }
    std::optional<SymbolicCtl> ctl, plain;
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
    for (auto c : task_.checks) {
      const auto t0 = Clock::now();
      const std::string name(logic::to_string(c));
      auto r = guarded(name, "", name, [&] {
        if (!plain) plain.emplace(sys_, std::vector<logic::FormulaPtr>{});
        return standard(c, *plain, report);
      });
      r.seconds = since(t0);
      report.results.push_back(std::move(r));
    }
    // Edges last: on a huge model their relation may not fit where the verdicts did.
    report.edges_known = false;
    if (failed_.empty()) {
      try {
        if (report.stopped_early) {
          // Only rings so far: the edges out of the last one are not known.
        } else if (const auto edges = sys_.count_edges(report.complete ? reached_ : reached_ & !frontier_)) {
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
    r.message = failed_limit_ == Limit::Time ? failed_
                                             : "the BDD package ran out of resources: " + failed_;
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
      const Bdd next = sys_.image(frontier_) & !reached_;
      if (next.is_false()) {
        frontier_ = next;
        break;
      }
      reached_ = reached_ | next;
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

  std::string limit_message(const logic::CheckReport& report) const {
    return "exploration stopped at the " + report.limit + " limit after " +
           report.states.str() + " states";
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
    std::vector<std::int64_t> inputs = logic::pick_inputs(semantics::InputCondition::always(),
                                                          ts_.inputs(), {});
    t.steps.push_back({inputs, states.front(), {}});
    for (std::size_t k = 1; k < states.size(); ++k) {
      const auto bits = sys_.inputs_between(states[k - 1], states[k]);
      // Consecutive states of a run are related by construction: a gap is a bug, never a trace.
      // No bits is also the answer of a system without inputs: then the relation decides.
      if (bits.empty() &&
          (sys_.preimage(sys_.singleton(states[k])) & sys_.singleton(states[k - 1])).is_false())
        throw std::logic_error("bdd engine: a trace step without a transition");
      inputs = semantics::inputs_from_bits(ts_, circuit, bits);
      t.steps.push_back({inputs, states[k], sys_.fired_between(states[k - 1], bits)});
    }
    return t;
  }

  bool all_initial(const Bdd& set) const { return (sys_.initial() & !set).is_false(); }

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
      const auto neg = push_negation(f);
      r.trace = to_trace(ctl.explain(neg, bad));
      r.trace->kind = logic::TraceKind::Counterexample;
    }
    if (r.trace) r.trace->marked = marked;
    return r;
  }

  /// Grafcet steps never active in a reached stable situation but entered by a transition that
  /// fires (crossed during transient evolutions), as the explicit checks treat them: index into
  /// `steps` -> the reached situations with an evolution entering the step.
  std::map<std::size_t, Bdd> transient_steps(const std::vector<logic::StepRef>& steps) {
    std::map<std::size_t, Bdd> out;
    if (ts_.kind() != semantics::SemanticsKind::Grafcet || !task_.project) return out;
    std::vector<const model::Transition*> matched;
    for (const auto& info : ts_.transitions()) {
      const model::Transition* hit = nullptr;
      for (const auto& pou : task_.project->pous) {
        if (!info.pou.empty() && !model::iequals(pou.name, info.pou)) continue;
        for (const auto& chart : pou.charts) {
          if (!info.chart.empty() && !model::iequals(chart.name, info.chart)) continue;
          for (const auto& t : chart.transitions)
            if (info.where.known() ? t.where.str() == info.where.str()
                                   : (!t.name.empty() && t.name == info.name))
              hit = &t;
        }
      }
      if (!hit) return out;
      matched.push_back(hit);
    }
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (!(reached_ & sys_.atom(*logic::observable_atom(ts_, steps[i].observable))).is_false())
        continue;
      Bdd entry = Bdd::constant(false);
      for (std::uint32_t t = 0; t < matched.size(); ++t) {
        if (!model::iequals(ts_.transitions()[t].chart, steps[i].chart)) continue;
        bool enters = false;
        for (const auto& d : matched[t]->targets) enters = enters || model::iequals(d, steps[i].step);
        if (enters) entry = entry | (reached_ & sys_.fires(t));
      }
      if (!entry.is_false()) out.emplace(i, entry);
    }
    return out;
  }

  /// Re-entry of a transient step: from every reached situation an evolution entering it stays
  /// reachable.
  void transient_reentry(PropertyResult& r, const logic::StepRef& step, const Bdd& entry,
                         const std::string& what) {
    Bdd back = entry;
    for (;;) {
      const Bdd next = entry | sys_.preimage(back);
      if (next == back) break;
      back = next;
    }
    const Bdd bad = reached_ & !back;
    if (bad.is_false()) return;
    r.findings.push_back("step " + logic::describe_step(step) +
                         " (crossed only during transient evolutions)" + what);
    if (!r.trace) {
      r.trace = path_to(bad);
      r.trace->note = "from the last situation " + logic::describe_step(step) +
                      " can never be crossed again";
    }
  }

  /// Grafcet anomalies (docs/semantics.md 2.11): events whose transient evolutions never
  /// stabilise or raise a range error, from reached situations or at the start.
  void grafcet_instability(PropertyResult& r, const logic::CheckReport& report) {
    if (sys_.initial_unstable())
      r.findings.push_back("instability: under some initial input valuation the transient "
                           "evolutions never reach a stable situation");
    if (sys_.initial_range_error())
      r.findings.push_back("range error: under some initial input valuation an evolution raises "
                           "a range error or a forcing conflict");
    const Bdd unstable = reached_ & sys_.unstable_states();
    if (!unstable.is_false()) {
      r.findings.push_back("instability: from " + ts_.describe(sys_.pick(unstable)) +
                           " an input event starts transient evolutions that never reach a "
                           "stable situation");
      r.trace = path_to(unstable);
    }
    const Bdd err = reached_ & sys_.range_error_states();
    if (!err.is_false()) {
      r.findings.push_back("range error: from " + ts_.describe(sys_.pick(err)) +
                           " an input event raises a range error or a forcing conflict");
      if (!r.trace) r.trace = path_to(err);
    }
    finish(r, report, "every evolution reaches a stable situation");
  }

  void finish(PropertyResult& r, const logic::CheckReport& report, const std::string& ok) {
    if (!r.findings.empty()) {
      r.verdict = Verdict::Violated;
    } else if (!report.complete) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message(report);
    } else {
      r.verdict = Verdict::Holds;
      r.message = ok;
    }
  }

  PropertyResult standard(StandardCheck c, SymbolicCtl& ctl, const logic::CheckReport& report) {
    PropertyResult r;
    r.name = std::string(logic::to_string(c));
    r.check = r.name;
    const auto steps = logic::step_refs(ts_, task_.project);
    switch (c) {
      case StandardCheck::Reachable: {
        if (steps.empty()) {
          r.verdict = Verdict::NotChecked;
          r.message = "not checked: the system has no steps";
          break;
        }
        std::size_t missing = 0;
        const auto transient = report.complete ? transient_steps(steps) : std::map<std::size_t, Bdd>{};
        for (std::size_t i = 0; i < steps.size(); ++i)
          if (const auto& s = steps[i];
              !transient.count(i) &&
              (reached_ & sys_.atom(*logic::observable_atom(ts_, s.observable))).is_false()) {
            ++missing;
            if (report.complete) r.findings.push_back("step " + logic::describe_step(s) + " is never active");
          }
        if (missing && !report.complete) {
          r.verdict = Verdict::Unknown;
          r.message = std::to_string(missing) + " of " + std::to_string(steps.size()) +
                      " steps not reached before the limit; " + limit_message(report);
          break;
        }
        finish(r, report, "all " + std::to_string(steps.size()) + " steps are reachable" +
                              (transient.empty() ? "" : " (" + std::to_string(transient.size()) +
                                                            " only during transient evolutions)"));
        break;
      }
      case StandardCheck::DeadTransitions: {
        const auto& trs = ts_.transitions();
        if (trs.empty()) {
          r.verdict = Verdict::NotChecked;
          r.message = "not checked: the system has no transitions";
          break;
        }
        std::size_t dead = 0;
        for (std::uint32_t t = 0; t < trs.size(); ++t)
          if ((reached_ & sys_.fires(t)).is_false()) {
            ++dead;
            if (report.complete)
              r.findings.push_back("transition " + trs[t].name +
                                   (trs[t].where.known() ? " (" + trs[t].where.str() + ")" : "") +
                                   " never fires");
          }
        if (dead && !report.complete) {
          r.verdict = Verdict::Unknown;
          r.message = std::to_string(dead) + " transitions not fired before the limit; " +
                      limit_message(report);
          break;
        }
        finish(r, report, "all " + std::to_string(trs.size()) + " transitions can fire");
        break;
      }
      case StandardCheck::GlobalDeadlock: {
        if (ts_.transitions().empty()) {
          r.verdict = Verdict::NotChecked;
          r.message = "not checked: the system has no transitions";
          break;
        }
        // Dead: no state that fires a transition can be reached any more.
        const Bdd firing = sys_.fires_any();
        Bdd live = firing;
        for (;;) {
          const Bdd next = firing | sys_.preimage(live);
          if (next == live) break;
          live = next;
        }
        const Bdd dead = report.complete ? reached_ & !live : reached_ & !sys_.has_successor();
        if (!dead.is_false()) {
          r.findings.push_back(sys_.count_exact(dead).str() +
                               " reachable situations from which no transition can ever fire, "
                               "e.g. " + ts_.describe(sys_.pick(dead)));
          r.trace = path_to(dead);
          r.trace->note = "the last situation is a global deadlock";
        }
        finish(r, report, "no reachable situation is a global deadlock");
        break;
      }
      case StandardCheck::InitialReturn: {
        if (!report.complete) {
          r.verdict = Verdict::Unknown;
          r.message = limit_message(report);
          break;
        }
        r.formula = "AG EF init";
        // The initial situation is the step activity of the initial state.
        Bdd target = Bdd::constant(true);
        if (steps.empty()) {
          target = sys_.initial();
        } else {
          // Any initial state's step activity (a Grafcet has one per initial valuation), as the
          // explicit check: one pattern per distinct activity.
          target = Bdd::constant(false);
          for (Bdd rest = sys_.initial(); !rest.is_false();) {
            const auto init = sys_.pick(rest);
            Bdd pattern = Bdd::constant(true);
            for (const auto& s : steps) {
              const Bdd x = sys_.atom(*logic::observable_atom(ts_, s.observable));
              pattern = pattern & (ts_.observe(init, s.observable) ? x : !x);
            }
            target = target | pattern;
            rest = rest & !pattern;
          }
        }
        Bdd back = target;
        for (;;) {
          const Bdd next = target | sys_.preimage(back);
          if (next == back) break;
          back = next;
        }
        const Bdd bad = reached_ & !back;
        if (!bad.is_false()) {
          r.findings.push_back(sys_.count_exact(bad).str() +
                               " reachable situations from which the initial situation cannot "
                               "be reached again, e.g. " + ts_.describe(sys_.pick(bad)));
          r.trace = path_to(bad);
        }
        finish(r, report, "the initial situation can be reached again from every situation");
        break;
      }
      case StandardCheck::Reentry:
      case StandardCheck::LocalDeadlock: {
        if (steps.empty()) {
          r.verdict = Verdict::NotChecked;
          r.message = "not checked: the system has no steps";
          break;
        }
        if (!report.complete) {
          r.verdict = Verdict::Unknown;
          r.message = limit_message(report);
          break;
        }
        std::size_t considered = 0;
        const auto transient = transient_steps(steps);
        for (std::size_t i = 0; i < steps.size(); ++i) {
          const auto& step = steps[i];
          if (c == StandardCheck::Reentry && !step.on_loop && task_.project) continue;
          if (auto it = transient.find(i); it != transient.end()) {
            ++considered;
            transient_reentry(r, step, it->second,
                              c == StandardCheck::Reentry
                                  ? ": a reachable situation exists from which it can never be "
                                    "crossed again"
                                  : ", once crossed, is never crossed again");
            continue;
          }
          if (c == StandardCheck::Reentry) {
            ++considered;
            if (!all_initial(ctl.sat(logic::reentry_formula(ts_, step.observable))))
              r.findings.push_back("step " + logic::describe_step(step) +
                                   ": a reachable situation exists from which it can never "
                                   "become active again (AG EF " +
                                   ts_.observables()[step.observable].name + " is violated)");
            continue;
          }
          r.formula = "AG (X -> EF !X) & AG (!X -> EF X)";
          ++considered;
          const auto x = logic::observable_atom(ts_, step.observable);
          const auto nx = logic::make_not(x);
          const auto never_left =
              logic::make_op(Op::EF, {logic::make_and(x, logic::make_op(Op::AG, {x}))});
          const auto never_back =
              logic::make_op(Op::EF, {logic::make_and(nx, logic::make_op(Op::AG, {nx}))});
          if (!(sys_.initial() & ctl.sat(never_left)).is_false())
            r.findings.push_back("step " + logic::describe_step(step) + ", once active, is never left");
          if (!(sys_.initial() & ctl.sat(never_back)).is_false())
            r.findings.push_back("step " + logic::describe_step(step) +
                                 ", once inactive, never becomes active again");
        }
        if (c == StandardCheck::Reentry && considered == 0) {
          r.verdict = Verdict::Holds;
          r.message = "no step lies on a loop";
          break;
        }
        finish(r, report, c == StandardCheck::Reentry
                              ? "every step of a loop can be re-entered from every situation"
                              : "no step is locally deadlocked");
        break;
      }
      case StandardCheck::Instability: {
        // IEC 61131-3 has no transient evolutions; range errors are its anomalies.
        const Bdd err = reached_ & sys_.range_error_states();
        if (ts_.kind() == semantics::SemanticsKind::Grafcet) {
          grafcet_instability(r, report);
          break;
        }
        if (!err.is_false()) {
          r.findings.push_back("a range error (integer overflow, division by zero or a value "
                               "out of its type) can occur in " + ts_.describe(sys_.pick(err)));
          r.trace = path_to(err);
        }
        finish(r, report, "no range error can occur");
        break;
      }
      case StandardCheck::Conflicts:
      case StandardCheck::StoredActions:
      case StandardCheck::OutputConflicts:
        r.verdict = Verdict::NotChecked;
        r.message = "not checked by the bdd engine (it needs the graph's edges); use --engine "
                    "explicit";
        break;
    }
    return r;
  }

  const logic::CheckTask& task_;
  SymbolicSystem& sys_;
  const semantics::TransitionSystem& ts_;
  Bdd reached_;
  Bdd frontier_;  ///< the last ring, not expanded when a limit stopped exploration
  std::vector<Bdd> rings_;
  logic::BigCount last_count_;
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
    if (const auto* ltl = logic::first_ltl_property(task)) {
      if (why) *why = logic::ltl_refusal("bdd", *ltl);
      return false;
    }
    try {
      if (task.system->kind() == semantics::SemanticsKind::Grafcet)
        semantics::build_grafcet_circuit(*task.system, task.limits.deadline);
      else
        semantics::build_iec61131_circuit(*task.system, task.limits.deadline);
    } catch (const semantics::CircuitUnsupported& e) {
      if (why) *why = std::string("the bdd engine cannot encode ") + e.what();
      return false;
    }
    // The standard checks that need the graph's edges are reported as not checked.
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
    // The run's one deadline, in every BDD operation (the fixpoints are loops of them).
    const bdd::DeadlineScope deadline(task.limits.deadline);
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
      const std::string why = (time ? std::string() : "the BDD package ran out of resources: ") + e.what();
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
        r.verdict = Verdict::Unknown;
        r.message = why;
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

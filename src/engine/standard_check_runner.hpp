#pragma once
// The standard checks (catalogue and formulas: logic/standard_checks.hpp), written once for
// every engine. The runner owns each check's logic, its messages and findings (with the
// max_findings cap), the not-checked and unknown rules, and the per-check timing, progress and
// limit handling. An engine supplies a `Space`: the reachable situations as sets it can
// intersect and close, with these members (State: one situation; Set: a set of them):
//
//   std::string_view name()                  the engine, for "not checked by the <name> engine"
//   bool complete(); std::string limit_name(), state_count(); std::uint64_t progress_states()
//   bool has_fairness()                      the task's fairness (adds the reentry-fair row)
//   Set reached(), initial(), none()
//   Set meet(a, b), join(a, b), minus(a, b); bool empty(s); logic::BigCount count(s)
//   Set observable(o)                        reached situations where observable o is non-zero
//   Set field_nonzero(f)                     reached situations where layout field f is non-zero
//   bool can_fire(t); Set fires(t), fires_any()   reached situations where t (any) fires
//                                            (Grafcet: on an evolution, one back to the
//                                            situation itself included)
//   bool fires_initially(t)                  t is cleared while an initial situation
//                                            stabilises (Grafcet; IEC 61131-3: false)
//   Set enters(o)                            Grafcet: reached situations, o inactive there,
//                                            with an evolution that has step observable o
//                                            active in one of its situations (transient or
//                                            the stable end; IEC 61131-3: none)
//   bool enters_initially(o)                 Grafcet: o active in a situation an initial
//                                            situation crosses while it stabilises or ends in
//   Set stuck()                              reached situations without any successor
//   Set pre(s), post(s)                      reached predecessors / successors of s
//   Set backward(s)                          the reached situations from which s is reachable
//   Set forward(s)                           the situations reachable from s (s included)
//   Set ctl(f, fair)                         the situations satisfying CTL formula f
//   logic::Trace explain(f, from, fair)      a run from `from` explaining f
//   logic::Trace path_to(s)                  a shortest run from an initial situation into s
//   State one(s); std::vector<State> first(s, k); Set singleton(x)
//   std::uint32_t depth(x); std::string describe(x)
//   bool simultaneous(visit, related)        calls visit(fired_a, fired_b, x) for transitions
//                                            enabled together (see conflicts()); false when
//                                            the engine cannot enumerate them. Grafcet: only
//                                            evolutions that clear two transitions i, j with
//                                            related(i, j) need be visited
//   bool order_dependent(visit)              calls visit(x, a, b) (OrderEdge) for pairs of
//                                            evolutions of a reached situation x to different
//                                            targets, at least one under an `order:` input
//                                            (IEC 61131-3, docs/semantics.md 1.2a); false when
//                                            the engine cannot enumerate them
//   std::vector<Anomaly<Set>> anomalies()    instabilities and range errors, described
//   std::optional<std::string> failure()     set once a limit ended the engine's work
//   std::string note_limit(e)                the message of a limit that stopped a check
//
// "one" and "first" list situations in the engine's own order (the explicit engine: discovery
// order; the BDD engine: ring by ring).

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "logic/check_result.hpp"
#include "logic/check_task.hpp"
#include "logic/formula.hpp"
#include "logic/push_negation.hpp"
#include "logic/standard_checks.hpp"
#include "model/errors.hpp"
#include "model/names.hpp"

namespace sfcv::engine {

/// Grafcet conflicts: the transitions each event of a situation clears, one list per event
/// (a successor, or an event that returns to the situation itself). The graphs merge the
/// events that end in one situation, and the union of their lists would pair transitions
/// that two different events clear (docs/semantics.md 3.2, `conflicts`).
struct FiredPerEvent final : semantics::SuccessorSink {
  std::vector<std::vector<std::uint32_t>> fired;
  void successor(const semantics::Successor& s) override {
    fired.emplace_back(s.fired.begin(), s.fired.end());
  }
  void returning(const semantics::Successor& s) override { successor(s); }
};

/// The inputs a conflict ignores: IEC 61131-3's `choice:<step>` pseudo-inputs, which pick one of
/// the enabled alternatives under --priority none. Two evolutions of one situation conflict when
/// they happen under the same values of every other input (plant inputs and the abstract-time
/// pseudo-inputs), whatever the choice: the choice only makes the conflict explicit.
inline std::vector<bool> conflict_ignored_inputs(const semantics::TransitionSystem& ts) {
  std::vector<bool> out;
  for (const auto& in : ts.inputs()) out.push_back(in.pseudo && in.name.starts_with("choice:"));
  return out;
}

/// Whether two input conditions share a valuation of the inputs not ignored.
inline bool conditions_intersect(const semantics::InputCondition& a,
                                 const semantics::InputCondition& b,
                                 const std::vector<bool>& ignored) {
  auto cubes = [&](const semantics::InputCube& x, const semantics::InputCube& y) {
    for (const auto& l : x.literals)
      for (const auto& m : y.literals)
        if (l.input == m.input && !(l.input < ignored.size() && ignored[l.input]) &&
            (l.hi < m.lo || m.hi < l.lo))
          return false;
    return true;
  };
  for (const auto& x : a.cubes)
    for (const auto& y : b.cubes)
      if (cubes(x, y)) return true;
  return false;
}

/// One evolution of a situation, as order_dependent() shows it.
struct OrderEdge {
  const semantics::InputCondition& condition;
  semantics::StateView target;
  std::span<const std::uint32_t> fired;
};

/// Whether an evolution's condition names an `order:` input (logic::order_inputs).
inline bool mentions_input(const semantics::InputCondition& c, const std::vector<bool>& which) {
  for (const auto& cube : c.cubes)
    for (const auto& l : cube.literals)
      if (l.input < which.size() && which[l.input]) return true;
  return false;
}

/// An anomaly found by an engine: its description and, when known, where it occurs.
template <class Set>
struct Anomaly {
  std::string text;
  std::optional<Set> at;
};

template <class Space>
class StandardCheckRunner {
 public:
  using Set = typename Space::Set;
  using State = typename Space::State;
  using PropertyResult = logic::PropertyResult;
  using StandardCheck = logic::StandardCheck;
  using StepRef = logic::StepRef;
  using Verdict = logic::Verdict;

  StandardCheckRunner(Space& space, const semantics::TransitionSystem& ts,
                      const logic::CheckTask& task)
      : sp_(space), ts_(ts), task_(task), steps_(logic::step_refs(ts, task.project)) {}

  /// Every check of task.checks, in order; a check a limit interrupts is unknown, the ones
  /// before it keep their verdicts.
  std::vector<PropertyResult> run() {
    using Clock = std::chrono::steady_clock;
    std::vector<PropertyResult> out;
    std::uint64_t done = 0;
    const auto started = Clock::now();
    auto timed = [&](const std::string& name, StandardCheck id, auto&& compute) {
      const auto t0 = Clock::now();
      PropertyResult r;
      // A question without meaning on this system is not applicable, whatever the engine did.
      if (const auto why = logic::not_applicable(id, ts_, task_.priority_resolves_conflicts)) {
        r = not_applicable(name, id, *why);
      } else if (const auto failed = sp_.failure()) {
        r = unknown(name, id, *failed);
      } else {
        try {
          task_.limits.check_time("starting the standard check");
          r = compute();
        } catch (const LimitReached& stop) {
          r = unknown(name, id, sp_.note_limit(stop));
        }
      }
      r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      return r;
    };
    for (auto id : task_.checks) {
      out.push_back(timed(std::string(logic::to_string(id)), id, [&] { return check(id); }));
      if (id == StandardCheck::Reentry && sp_.has_fairness())
        out.push_back(timed("reentry-fair", id, [&] { return reentry_fair(); }));
      model::Progress p;
      p.phase = "standard checks";
      p.states = sp_.progress_states();
      p.done = ++done;
      p.total = task_.checks.size();
      p.seconds = std::chrono::duration<double>(Clock::now() - started).count();
      task_.limits.report(p);
    }
    return out;
  }

 private:
  static constexpr std::size_t kMaxSituations = 3;  ///< situation findings listed before a summary
  /// Rounds of bottom_components() before the checks fall back to one formula per step.
  static constexpr std::size_t kMaxBottomRounds = 64;

  static PropertyResult unknown(const std::string& name, StandardCheck id, const std::string& why) {
    PropertyResult r;
    r.name = name;
    r.check = std::string(logic::to_string(id));
    r.verdict = Verdict::Unknown;
    r.message = why;
    return r;
  }

  static PropertyResult not_applicable(const std::string& name, StandardCheck id,
                                       const std::string& why) {
    PropertyResult r;
    r.name = name;
    r.check = std::string(logic::to_string(id));
    r.verdict = Verdict::NotApplicable;
    r.message = why;
    return r;
  }

  PropertyResult check(StandardCheck id) {
    PropertyResult r;
    r.name = std::string(logic::to_string(id));
    r.check = r.name;
    // Without an initial state every other check would hold or fail vacuously ("step X1 is
    // never active", "no deadlock"): unknown instead; instability names why (a range error of
    // the first evolution, or an assumption excluding every situation).
    if (id != StandardCheck::Instability && sp_.complete() && sp_.empty(sp_.initial())) {
      r.verdict = Verdict::Unknown;
      r.message = "no initial state (the instability check says why): nothing to check";
      return r;
    }
    switch (id) {
      case StandardCheck::Reachable:
        reachable(r);
        break;
      case StandardCheck::DeadTransitions:
        dead_transitions(r);
        break;
      case StandardCheck::Reentry:
        per_step_formula(r, false);
        break;
      case StandardCheck::GlobalDeadlock:
        global_deadlock(r);
        break;
      case StandardCheck::LocalDeadlock:
        local_deadlock(r);
        break;
      case StandardCheck::InitialReturn:
        initial_return(r);
        break;
      case StandardCheck::Conflicts:
        conflicts(r);
        break;
      case StandardCheck::StoredActions:
        stored_actions(r);
        break;
      case StandardCheck::OutputConflicts:
        output_conflicts(r);
        break;
      case StandardCheck::OrderDependence:
        order_dependence(r);
        break;
      case StandardCheck::Instability:
        instability(r);
        break;
    }
    return r;
  }

  PropertyResult reentry_fair() {
    PropertyResult r;
    r.name = "reentry-fair";
    r.check = "reentry";
    per_step_formula(r, true);
    return r;
  }

  // ---------------------------------------------------------------------------- helpers

  static std::string qualify(const std::string& pou, const std::string& name) {
    return pou.empty() ? name : pou + "." + name;
  }
  std::string limit_message() const {
    return "exploration stopped at the " + sp_.limit_name() + " limit after " + sp_.state_count() +
           " states";
  }
  void add(PropertyResult& r, std::string finding) const {
    ++r.findings_total;
    if (task_.max_findings == 0 || r.findings.size() < task_.max_findings)
      r.findings.push_back(std::move(finding));
  }
  /// Throws LimitReached(Time) once the run's deadline has passed.
  void poll() const { task_.limits.check_time("running the standard checks"); }
  bool contains(const Set& set, const State& x) {
    return !sp_.empty(sp_.meet(set, sp_.singleton(x)));
  }
  Set step_set(const StepRef& step) { return sp_.observable(step.observable); }

  /// The bottom strongly connected components of the reached graph: the classes of mutually
  /// reachable situations that no evolution leaves (a situation without a successor is one on
  /// its own). AG EF p holds iff p meets every one of them: from any situation one is reached,
  /// and inside it every situation stays reachable. The checks that hold read it from here in a
  /// few fixpoints; the formulas run only for a step that fails (to explain it), instead of
  /// three fixpoints per step (50 steps: 12.6 s to 0.1 s on the BDD engine). Each round picks a
  /// situation x: when nothing ahead of x lies outside what reaches x, what lies ahead is a
  /// component; either way nothing that reaches x belongs to another one, and the next pick
  /// descends into what lies ahead. Nothing after kMaxBottomRounds rounds (each round finds a
  /// component or drops one of the graph's components above them).
  const std::optional<std::vector<Set>>& bottom_components() {
    if (bottoms_tried_) return bottoms_;
    bottoms_tried_ = true;
    if (!sp_.complete()) return bottoms_;
    std::vector<Set> found;
    Set candidates = sp_.reached();
    Set below = sp_.none();
    for (std::size_t round = 0; !sp_.empty(candidates); ++round) {
      if (round == kMaxBottomRounds) return bottoms_;
      poll();
      const Set inside = sp_.meet(candidates, below);
      const Set x = sp_.singleton(sp_.one(sp_.empty(inside) ? candidates : inside));
      const Set ahead = sp_.forward(x);
      const Set behind = sp_.backward(x);
      below = sp_.minus(ahead, behind);
      if (sp_.empty(below)) found.push_back(ahead);
      candidates = sp_.minus(candidates, behind);
    }
    bottoms_ = std::move(found);
    return bottoms_;
  }
  /// Whether `set` meets every bottom component, i.e. whether AG EF set holds; nothing when
  /// the components are not known. The checks of one set (global-deadlock, initial-return)
  /// ask only when the per-step checks need the components anyway: for them alone, the two
  /// closures of a round cost more than their one backward closure.
  std::optional<bool> meets_every_bottom(const Set& set, bool for_one_set = false) {
    if (for_one_set && !bottoms_tried_) {
      const auto& c = task_.checks;
      if (std::find(c.begin(), c.end(), StandardCheck::Reentry) == c.end() &&
          std::find(c.begin(), c.end(), StandardCheck::LocalDeadlock) == c.end())
        return std::nullopt;
    }
    const auto& bottoms = bottom_components();
    if (!bottoms) return std::nullopt;
    for (const auto& b : *bottoms)
      if (sp_.empty(sp_.meet(b, set))) return false;
    return true;
  }
  /// "and N more": the count of `set` beyond the `shown` situations listed.
  std::string more_than(const Set& set, std::size_t shown) {
    const auto total = sp_.count(set).to_u64();
    return total ? std::to_string(*total - shown) : "many";
  }
  /// Keeps the shallowest situation noted, the first one noted among equally deep ones.
  void note(std::optional<State>& first, const State& x) {
    if (!first || sp_.depth(x) < sp_.depth(*first)) first = x;
  }
  void finish(PropertyResult& r, const std::string& holds_message) const {
    if (!r.findings.empty()) {
      r.verdict = Verdict::Violated;
    } else if (!sp_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
    } else {
      r.verdict = Verdict::Holds;
      r.message = holds_message;
    }
  }

  /// Grafcet steps never active in a stable situation but active in a transient situation of
  /// an evolution (docs/semantics.md 2.5: entered by a clearing, with their enclosing step, by
  /// a forcing order, and not emptied in the same evolution by an enclosing step's
  /// deactivation, 2.12 c): index into steps_ -> the situations with such an evolution. The
  /// engine follows each evolution to its end (Space::enters). Empty for IEC 61131-3.
  std::map<std::size_t, Set> transient_steps() {
    std::map<std::size_t, Set> out;
    if (ts_.kind() != semantics::SemanticsKind::Grafcet) return out;
    for (std::size_t i = 0; i < steps_.size(); ++i) {
      poll();
      if (!sp_.empty(step_set(steps_[i]))) continue;
      Set entry = sp_.enters(steps_[i].observable);
      if (!sp_.empty(entry)) out.emplace(i, std::move(entry));
    }
    return out;
  }

  /// Grafcet steps never active in a stable situation nor crossed after an event, but active
  /// in a situation an initial situation crosses while it stabilises (2.2, 2.11: the initial
  /// steps, and those the start runs through).
  std::set<std::size_t> initially_crossed_steps(const std::map<std::size_t, Set>& transient) {
    std::set<std::size_t> out;
    if (ts_.kind() != semantics::SemanticsKind::Grafcet) return out;
    for (std::size_t i = 0; i < steps_.size(); ++i) {
      poll();
      if (!transient.count(i) && sp_.empty(step_set(steps_[i])) &&
          sp_.enters_initially(steps_[i].observable))
        out.insert(i);
    }
    return out;
  }

  /// Re-entry of a transient step: from every reachable situation an evolution entering it
  /// stays reachable. Adds a finding and a trace when not.
  void transient_reentry(PropertyResult& r, std::size_t step, const Set& entry,
                         const std::string& what) {
    const Set bad = sp_.minus(sp_.reached(), sp_.backward(entry));
    if (sp_.empty(bad)) return;
    add(r, "step " + logic::describe_step(steps_[step]) +
               " (crossed only during transient "
               "evolutions)" +
               what);
    if (!r.trace) {
      r.trace = sp_.path_to(bad);
      r.trace->note = "from the last situation " + logic::describe_step(steps_[step]) +
                      " can never be crossed again";
    }
  }

  // ----------------------------------------------------------------------------- checks

  // The checks below run on systems where they apply (logic::not_applicable, run()): the step
  // checks have steps, the transition checks transitions.

  void reachable(PropertyResult& r) {
    std::vector<bool> seen(steps_.size(), false);
    for (std::size_t i = 0; i < steps_.size(); ++i) {
      poll();
      seen[i] = !sp_.empty(step_set(steps_[i]));
    }
    const auto transient = sp_.complete() ? transient_steps() : std::map<std::size_t, Set>{};
    const auto at_start = initially_crossed_steps(transient);
    std::size_t missing = 0;
    r.target_answers.assign(steps_.size(), logic::TargetAnswer::Clear);
    for (std::size_t i = 0; i < steps_.size(); ++i)
      if (!seen[i] && !transient.count(i) && !at_start.count(i)) {
        ++missing;
        r.target_answers[i] =
            sp_.complete() ? logic::TargetAnswer::Defect : logic::TargetAnswer::Undecided;
        if (sp_.complete()) add(r, "step " + logic::describe_step(steps_[i]) + " is never active");
      }
    if (missing && !sp_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = std::to_string(missing) + " of " + std::to_string(steps_.size()) +
                  " steps not reached before the limit; " + limit_message();
      return;
    }
    std::string apart;
    if (!transient.empty())
      apart = std::to_string(transient.size()) + " only during transient evolutions";
    if (!at_start.empty())
      apart += (apart.empty() ? "" : ", ") + std::to_string(at_start.size()) +
               " only while the initial situation stabilises";
    finish(r, "all " + std::to_string(steps_.size()) + " steps are reachable" +
                  (apart.empty() ? "" : " (" + apart + ")"));
  }

  void dead_transitions(PropertyResult& r) {
    const auto& trs = ts_.transitions();
    std::size_t dead = 0;
    r.target_answers.assign(trs.size(), logic::TargetAnswer::Undecided);
    for (std::uint32_t t = 0; t < trs.size(); ++t) {
      poll();
      r.target_answers[t] = logic::TargetAnswer::Clear;
      // Cleared while an initial situation stabilises counts as firing (docs/semantics.md 2.11).
      if (!sp_.can_fire(t) && !sp_.fires_initially(t)) {
        ++dead;
        r.target_answers[t] =
            sp_.complete() ? logic::TargetAnswer::Defect : logic::TargetAnswer::Undecided;
        if (sp_.complete())
          add(r, "transition " + trs[t].name +
                     (trs[t].where.known() ? " (" + trs[t].where.str() + ")" : "") +
                     " never fires");
      }
    }
    if (dead && !sp_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message =
          std::to_string(dead) + " transitions not fired before the limit; " + limit_message();
      return;
    }
    finish(r, "all " + std::to_string(trs.size()) + " transitions can fire");
  }

  // AG EF X (or AG AF X under fairness) for the steps of a loop.
  void per_step_formula(PropertyResult& r, bool af) {
    std::vector<const StepRef*> loop;
    for (const auto& s : steps_)
      if (s.on_loop || !task_.project) loop.push_back(&s);
    if (loop.empty()) {
      r.verdict = Verdict::Holds;
      r.message = "no step lies on a loop";
      return;
    }
    if (!sp_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
      return;
    }
    if (sp_.empty(sp_.initial())) {
      r.verdict = Verdict::Unknown;
      r.message = "no initial state";
      return;
    }
    const auto transient = transient_steps();
    for (const auto* step : loop) {
      poll();
      const auto index = static_cast<std::size_t>(step - steps_.data());
      if (auto it = transient.find(index); it != transient.end()) {
        if (!af)
          transient_reentry(r, index, it->second,
                            ": a reachable situation exists from "
                            "which it can never be crossed again");
        continue;
      }
      const auto known = af ? std::nullopt : meets_every_bottom(step_set(*step));
      if (known == true) continue;
      auto f = af ? logic::reentry_fair_formula(ts_, step->observable)
                  : logic::reentry_formula(ts_, step->observable);
      // Once the components decided the step, the formula runs only for the first trace.
      const Set bad = known && r.trace ? sp_.none() : sp_.minus(sp_.initial(), sp_.ctl(f, af));
      if (!known && sp_.empty(bad)) continue;
      add(r, "step " + logic::describe_step(*step) +
                 (af ? " is not re-entered on every fair run (AG AF "
                     : ": a reachable situation exists from which it can never become active "
                       "again (AG EF ") +
                 ts_.observables()[step->observable].name + " is violated)");
      if (!r.trace) {
        auto t = sp_.explain(logic::push_negation(f), bad, af);
        t.marked = {step->observable};
        t.note = af ? "a fair run on which " + logic::describe_step(*step) +
                          " never becomes active again"
                    : "after the last situation, " + logic::describe_step(*step) +
                          " can never become active again";
        r.trace = std::move(t);
      }
    }
    r.formula = af ? "AG AF X" : "AG EF X";
    finish(r, std::to_string(loop.size()) + " steps on loops can always be re-entered" +
                  (af ? " on fair runs" : ""));
  }

  void global_deadlock(PropertyResult& r) {
    const Set stuck = sp_.stuck();
    // On an incomplete graph only a situation without any successor is certainly dead. A
    // transition fires in every bottom component: none is dead.
    const Set dead = !sp_.complete() ? stuck
                     : meets_every_bottom(sp_.fires_any(), true) == true
                         ? sp_.none()
                         : sp_.minus(sp_.reached(), sp_.backward(sp_.fires_any()));
    const auto shown = sp_.first(dead, kMaxSituations + 1);
    for (std::size_t i = 0; i < shown.size() && i < kMaxSituations; ++i) {
      const auto& s = shown[i];
      const auto depth = sp_.depth(s);
      add(r, "situation " + sp_.describe(s) + " (after " + std::to_string(depth) +
                 (depth == 1 ? " evolution): " : " evolutions): ") +
                 (contains(stuck, s)
                      ? (ts_.kind() == semantics::SemanticsKind::Grafcet
                             ? "no successor at all (no input event leads to an evolution)"
                             : "no successor at all (the assumptions exclude every input)")
                      : "no transition can ever fire again, whatever the inputs"));
    }
    if (shown.size() > kMaxSituations)
      add(r, "(and " + more_than(dead, kMaxSituations) + " more deadlocked situations)");
    if (!sp_.empty(dead)) {
      r.trace = sp_.path_to(dead);
      r.trace->note = "the last situation is a global deadlock";
    }
    finish(r, "from every reachable situation some transition can still fire");
  }

  void local_deadlock(PropertyResult& r) {
    if (!sp_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
      return;
    }
    r.formula = "AG (X -> EF !X) & AG (!X -> EF X)";
    const auto transient = transient_steps();
    for (const auto& step : steps_) {
      poll();
      const auto index = static_cast<std::size_t>(&step - steps_.data());
      if (auto it = transient.find(index); it != transient.end()) {
        transient_reentry(r, index, it->second, ", once crossed, is never crossed again");
        continue;
      }
      const Set active = step_set(step);
      const std::optional<bool> known[] = {meets_every_bottom(sp_.minus(sp_.reached(), active)),
                                           meets_every_bottom(active)};
      if (known[0] == true && known[1] == true) continue;
      // The two ways logic::local_deadlock_formula fails, each explained on its own.
      const auto x = logic::observable_atom(ts_, step.observable);
      const auto never_left =
          logic::make_op(logic::Op::EF, {logic::make_and(x, logic::make_op(logic::Op::AG, {x}))});
      const auto nx = logic::make_not(x);
      const auto never_back =
          logic::make_op(logic::Op::EF, {logic::make_and(nx, logic::make_op(logic::Op::AG, {nx}))});
      for (std::size_t way = 0; way < 2; ++way) {
        const auto& f = way == 0 ? never_left : never_back;
        const char* what =
            way == 0 ? "once active, is never left" : "once inactive, never becomes active again";
        if (known[way] == true) continue;
        const Set at =
            known[way] && r.trace ? sp_.none() : sp_.meet(sp_.initial(), sp_.ctl(f, false));
        if (!known[way] && sp_.empty(at)) continue;
        add(r, "step " + logic::describe_step(step) + ", " + what);
        if (!r.trace) {
          auto t = sp_.explain(f, at, false);
          t.kind = logic::TraceKind::Counterexample;
          t.marked = {step.observable};
          t.note = "from the last situation on, " + logic::describe_step(step) + " " + what;
          r.trace = std::move(t);
        }
      }
    }
    finish(r, "every step can always be left and re-entered");
  }

  /// The reached situations whose step activity is that of some situation of `from`, split
  /// step by step (one branch per distinct activity); `rest` is the candidates so far.
  Set same_activity(const Set& from, const Set& rest, std::size_t k) {
    if (sp_.empty(from) || sp_.empty(rest)) return sp_.none();
    if (k == steps_.size()) return rest;
    poll();
    const Set x = step_set(steps_[k]);
    return sp_.join(same_activity(sp_.meet(from, x), sp_.meet(rest, x), k + 1),
                    same_activity(sp_.minus(from, x), sp_.minus(rest, x), k + 1));
  }

  void initial_return(PropertyResult& r) {
    if (sp_.empty(sp_.initial())) {
      r.verdict = Verdict::Unknown;
      r.message = "no initial state";
      return;
    }
    if (!sp_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
      return;
    }
    r.formula = "AG EF init";
    // The initial situation is the step activity of an initial state (inputs and variables
    // may differ); a system without steps compares whole states.
    const Set target =
        steps_.empty() ? sp_.initial() : same_activity(sp_.initial(), sp_.reached(), 0);
    const Set bad = meets_every_bottom(target, true) == true
                        ? sp_.none()
                        : sp_.minus(sp_.reached(), sp_.backward(target));
    const auto shown = sp_.first(bad, kMaxSituations + 1);
    const auto init = sp_.describe(sp_.one(sp_.initial()));
    for (std::size_t i = 0; i < shown.size() && i < kMaxSituations; ++i)
      add(r, "from situation " + sp_.describe(shown[i]) + " the initial situation " + init +
                 " can never be reached again");
    if (shown.size() > kMaxSituations)
      add(r, "(and " + more_than(bad, kMaxSituations) + " more such situations)");
    if (!sp_.empty(bad)) {
      r.trace = sp_.path_to(bad);
      r.trace->note = "from the last situation the initial situation is unreachable";
    }
    finish(r, "the initial situation can be reached again from every reachable situation");
  }

  // IEC 61131-3 without priority: the engine visits pairs of evolutions (edges, merged by
  // target) from one situation whose conditions intersect outside the choice pseudo-inputs
  // (conditions_intersect; fired_a, fired_b: what each fires). Grafcet: it visits each
  // evolution once (fired_a: every transition it clears, fired_b empty).
  // (Under the standard priority IEC 61131-3 conflicts are not applicable: run().)
  void conflicts(PropertyResult& r) {
    std::set<std::string> seen;
    std::optional<State> first;
    const auto& trs = ts_.transitions();
    auto names = [&](std::span<const std::uint32_t> fired) {
      std::string out;
      for (auto t : fired) out += (out.empty() ? "" : ", ") + trs[t].name;
      return "{" + out + "}";
    };
    bool visited = false;
    if (ts_.kind() == semantics::SemanticsKind::Iec61131) {
      visited = sp_.simultaneous(
          [&](std::span<const std::uint32_t> a, std::span<const std::uint32_t> b, const State& s) {
            poll();
            // One order for a pair, whichever evolution an engine meets first.
            if (std::lexicographical_compare(b.begin(), b.end(), a.begin(), a.end()))
              std::swap(a, b);
            const auto text = names(a) + " and " + names(b);
            if (!seen.insert(text).second) return;
            if (!first) first = s;
            add(r, "transitions " + text + " can both fire from situation " + sp_.describe(s) +
                       " (no priority between them)");
          },
          [](std::uint32_t, std::uint32_t) { return true; });
    } else {
      // Grafcet clears every clearable transition at once: a conflict is two transitions
      // with a common upstream step cleared together.
      const auto upstream = task_.project ? logic::grafcet_upstream_steps(ts_, *task_.project)
                                          : std::vector<std::vector<std::string>>{};
      if (upstream.empty()) {
        r.verdict = Verdict::NotChecked;
        r.message =
            "not checked: the transitions of the system could not be matched with the "
            "chart's transitions";
        return;
      }
      auto common_upstream = [&](std::uint32_t i, std::uint32_t j) {
        return logic::common_steps(upstream[i], upstream[j]);
      };
      visited = sp_.simultaneous(
          [&](std::span<const std::uint32_t> fired, std::span<const std::uint32_t>,
              const State& s) {
            poll();  // once per event: a space may expand situations again to list them
            for (std::size_t i = 0; i < fired.size(); ++i)
              for (std::size_t j = i + 1; j < fired.size(); ++j) {
                poll();
                const auto common = common_upstream(fired[i], fired[j]);
                if (common.empty()) continue;
                const auto text = trs[fired[i]].name + " and " + trs[fired[j]].name;
                if (!seen.insert(text).second) continue;
                if (!first) first = s;
                add(r, "transitions " + text + " share the upstream step " + common.front() +
                           " and are cleared together from situation " + sp_.describe(s));
              }
          },
          [&](std::uint32_t i, std::uint32_t j) { return !common_upstream(i, j).empty(); });
    }
    if (!visited) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked by the " + std::string(sp_.name()) +
                  " engine (it needs the graph's edges); use --engine explicit";
      return;
    }
    if (first) {
      r.trace = sp_.path_to(sp_.singleton(*first));
      r.trace->note = "in the last situation conflicting transitions are enabled together";
    }
    finish(r, "no two alternative transitions are enabled together");
  }

  void stored_actions(PropertyResult& r) {
    if (!task_.project) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: needs the chart (no project given)";
      return;
    }
    std::vector<std::string> not_checked;
    std::size_t stored = 0;
    std::optional<State> first;
    for (const auto& pou : task_.project->pous)
      for (const auto& instance : logic::instances_of(ts_, pou)) {
        const auto& path = instance.path;
        // IEC 61131-3: S (and SD, DS, SL) sets an action's stored flag, R resets it. Each
        // instance of the POU has its own steps and stored flags.
        for (const auto& entry : logic::stored_action_steps(pou, instance, steps_, not_checked)) {
          const auto& sets = entry.sets;
          const auto& resets = entry.resets;
          ++stored;
          const std::string name = qualify(entry.scope, entry.action);
          if (!entry.reset_anywhere)
            add(r, "action " + name + " is stored at step " + entry.first_set +
                       " and never reset (no R qualifier anywhere)");
          // Set and reset in one situation.
          std::vector<Set> set_at, reset_at;
          Set any_set = sp_.none(), any_reset = sp_.none();
          for (const auto* x : sets) any_set = sp_.join(any_set, set_at.emplace_back(step_set(*x)));
          for (const auto* y : resets)
            any_reset = sp_.join(any_reset, reset_at.emplace_back(step_set(*y)));
          poll();
          if (const Set both = sp_.meet(any_set, any_reset); !sp_.empty(both)) {
            const State s = sp_.one(both);
            std::size_t i = 0, j = 0;
            while (!contains(set_at[i], s)) ++i;
            while (!contains(reset_at[j], s)) ++j;
            add(r, "action " + name + " is set (S at " + sets[i]->step + ") and reset (R at " +
                       resets[j]->step + ") in the same situation " + sp_.describe(s));
            note(first, s);
          }
          // Set again while stored: needs the stored flag.
          const auto field = logic::stored_flag_field(ts_, entry.scope, entry.action);
          if (!field) {
            not_checked.push_back("set again while stored (" + name +
                                  "): the system exposes no "
                                  "stored flag for it");
            continue;
          }
          const Set flagged = sp_.field_nonzero(*field);
          std::vector<Set> again;
          Set any_again = sp_.none();
          for (const auto& x : set_at) {
            poll();
            any_again = sp_.join(any_again,
                                 again.emplace_back(sp_.meet(sp_.minus(flagged, x), sp_.pre(x))));
          }
          if (!sp_.empty(any_again)) {
            const State s = sp_.one(any_again);
            std::size_t i = 0;
            while (!contains(again[i], s)) ++i;
            add(r, "action " + name + " is set again (S at " + sets[i]->step +
                       ") while already stored, from situation " + sp_.describe(s));
            note(first, sp_.one(sp_.meet(sp_.post(sp_.singleton(s)), set_at[i])));
          }
        }
        // IEC 60848 stored actions: a variable set to 1 and never to 0, or to different values
        // on one evolution.
        for (const auto& v : logic::grafcet_stored_variables(pou)) {
          ++stored;
          if (v.never_reset)
            add(r, "output " + v.variable + " is set to 1 by stored actions (" +
                       v.first->where.str() + ") and never reset to 0");
          for (const auto& [a, b] : v.different) {
            const auto* sa = logic::find_step(steps_, path, a->chart, a->step);
            const auto* sb = logic::find_step(steps_, path, b->chart, b->step);
            if (!sa || !sb) {
              not_checked.push_back("stored actions on " + a->variable +
                                    " at steps without "
                                    "an observable");
              continue;
            }
            poll();
            // Both steps activated by one evolution.
            const Set both = sp_.meet(step_set(*sa), step_set(*sb));
            const Set from = sp_.meet(
                sp_.minus(sp_.minus(sp_.reached(), step_set(*sa)), step_set(*sb)), sp_.pre(both));
            if (sp_.empty(from)) continue;
            const State s = sp_.one(from);
            add(r, "output " + a->variable +
                       " is set to different values at once by the "
                       "activation of " +
                       sa->step + " and " + sb->step + ", from situation " + sp_.describe(s));
            note(first, sp_.one(sp_.meet(sp_.post(sp_.singleton(s)), both)));
          }
          // "Set again while stored" is about IEC 61131-3's stored flag of an action; an
          // IEC 60848 stored action assigns a variable and has no flag: not applicable.
        }
      }
    if (first) {
      r.trace = sp_.path_to(sp_.singleton(*first));
      r.trace->note = "the last situation shows the stored-action defect";
    }
    if (stored == 0) {
      finish(r, "the chart has no stored action");
      return;
    }
    finish(r, "stored actions are used correctly");
    if (r.verdict == Verdict::Holds && !not_checked.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message =
          "no defect found in the parts checked; not checked: " + not_checked.front() +
          (not_checked.size() > 1 ? " (and " + std::to_string(not_checked.size() - 1) + " more)"
                                  : "");
    } else if (!not_checked.empty()) {
      r.message = "not checked: " + not_checked.front();
    }
  }

  void output_conflicts(PropertyResult& r) {
    if (!task_.project) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: needs the chart (no project given)";
      return;
    }
    if (ts_.kind() == semantics::SemanticsKind::Grafcet) {
      grafcet_output_conflicts(r);
      return;
    }
    std::vector<std::string> not_checked;
    std::optional<State> first;
    const auto conflicts = logic::instance_write_conflicts(ts_, *task_.project);
    for (const auto& c : conflicts) {
      if (!c.not_checked.empty()) {
        not_checked.push_back(c.not_checked);
        continue;
      }
      poll();
      Set both = sp_.none();
      for (const auto& [a, b] : c.together)
        both = sp_.join(both, sp_.meet(sp_.observable(a), sp_.observable(b)));
      if (sp_.empty(both)) continue;
      const State s = sp_.one(both);
      add(r, c.what + " in the same cycle, in situation " + sp_.describe(s));
      note(first, s);
    }
    if (first) {
      r.trace = sp_.path_to(sp_.singleton(*first));
      r.trace->note = "in the last cycle both actions are active";
    }
    finish(r, conflicts.empty() ? "no variable is written by two actions with different values"
                                : "actions writing the same variable are never active together");
    if (r.verdict == Verdict::Holds && !not_checked.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: " + not_checked.front();
    }
  }

  /// Grafcet: a variable written by both continuous and stored actions, in the situations
  /// where its continuous assignation and its stored value disagree (docs/semantics.md 2.7).
  /// Continuous actions only assert their output, and stored actions writing different values
  /// in one evolution are stored-actions' findings.
  void grafcet_output_conflicts(PropertyResult& r) {
    std::optional<State> first;
    const auto mixed = logic::grafcet_mixed_writers(ts_, *task_.project);
    for (const auto& m : mixed) {
      poll();
      const Set assigned = sp_.field_nonzero(m.assigned), stored = sp_.field_nonzero(m.stored);
      const std::pair<Set, const char*> disagreements[] = {
          {sp_.minus(assigned, stored),
           "a continuous action assigns it 1 while its stored value is 0"},
          {sp_.minus(stored, assigned),
           "its stored value is 1 while no continuous action assigns it (the assignation rule "
           "gives 0)"}};
      for (const auto& [where, what] : disagreements) {
        if (sp_.empty(where)) continue;
        const State s = sp_.one(where);
        add(r, m.what + ": " + what + ", in situation " + sp_.describe(s));
        note(first, s);
      }
    }
    if (first) {
      r.trace = sp_.path_to(sp_.singleton(*first));
      r.trace->note =
          "in the last situation the continuous assignation and the stored value disagree";
    }
    finish(r, mixed.empty() ? "no variable is written by both continuous and stored actions"
                            : "the continuous assignation and the stored value of every variable "
                              "written both ways always agree");
  }

  /// order-dependence (docs/semantics.md 1.2a): a reached situation and plant inputs under
  /// which two admissible action orders give different next situations. Once every input is
  /// fixed the semantics is deterministic, so two evolutions of one situation to different
  /// targets whose conditions share a valuation of every input but the `order:` ones differ by
  /// the order alone. The trace ends with the evolution under the first order; the finding and
  /// the trace's note name the second and the variables whose values differ.
  void order_dependence(PropertyResult& r) {
    const auto order = logic::order_inputs(ts_);
    const auto& inputs = ts_.inputs();
    const auto& layout = ts_.layout();
    std::set<std::string> seen;
    std::optional<logic::Trace> first_trace;
    std::uint32_t first_depth = 0;
    // The cube of `x` with the literals of `y` on every input but the order ones; nullopt
    // when they contradict.
    auto joined = [&](const semantics::InputCube& x, const semantics::InputCube& y) {
      std::optional<semantics::InputCube> out = x;
      for (const auto& m : y.literals) {
        if (m.input < order.size() && order[m.input]) continue;
        auto it =
            std::find_if(out->literals.begin(), out->literals.end(),
                         [&](const semantics::InputLiteral& l) { return l.input == m.input; });
        if (it == out->literals.end()) {
          out->literals.push_back(m);
        } else {
          it->lo = std::max(it->lo, m.lo);
          it->hi = std::min(it->hi, m.hi);
          if (it->lo > it->hi) return std::optional<semantics::InputCube>{};
        }
      }
      std::sort(out->literals.begin(), out->literals.end(),
                [](const auto& a, const auto& b) { return a.input < b.input; });
      return out;
    };
    // The order literals as the traces show them ("order:motor=Stop<Start"), or the others.
    auto only = [&](const semantics::InputCube& c, bool orders) {
      semantics::InputCube out;
      std::string text;
      for (const auto& l : c.literals) {
        if ((l.input < order.size() && order[l.input]) != orders) continue;
        out.literals.push_back(l);
        if (!orders) continue;
        std::string value = std::to_string(l.lo);
        for (const auto& [name, v] : inputs[l.input].type.enumerators)
          if (v == l.lo && l.lo == l.hi) value = name;
        text += (text.empty() ? "" : " & ") + inputs[l.input].name + "=" + value;
      }
      if (!orders)
        return out.literals.empty() ? std::string()
                                    : semantics::InputCondition{{out}}.to_string(inputs);
      return text;
    };
    const bool visited =
        sp_.order_dependent([&](const State& x, const OrderEdge& a, const OrderEdge& b) {
          poll();
          if (!mentions_input(a.condition, order) && !mentions_input(b.condition, order)) return;
          for (const auto& ca : a.condition.cubes)
            for (const auto& cb : b.condition.cubes) {
              const auto under_a = joined(ca, cb);
              const auto under_b = joined(cb, ca);
              if (!under_a || !under_b) continue;
              std::string diff, values_a, values_b;
              for (std::uint32_t f = 0; f < layout.fields().size(); ++f) {
                const auto va = layout.get(a.target, f), vb = layout.get(b.target, f);
                if (va == vb) continue;
                const auto& name = layout.fields()[f].name;
                diff += (diff.empty() ? "" : ", ") + name;
                values_a += (values_a.empty() ? "" : ", ") + name + " = " + std::to_string(va);
                values_b += (values_b.empty() ? "" : ", ") + name + " = " + std::to_string(vb);
              }
              auto oa = only(*under_a, true), ob = only(*under_b, true);
              if (ob < oa) {
                std::swap(oa, ob);
                std::swap(values_a, values_b);
              }
              if (!seen.insert(oa + "|" + ob + "|" + diff).second) return;
              const auto plant = only(*under_a, false);
              const std::string text = oa + " gives " + values_a + ", " + ob + " gives " + values_b;
              add(r, "the next situation depends on the action order: from situation " +
                         sp_.describe(x) + (plant.empty() ? "" : " under inputs " + plant) + ", " +
                         text);
              if (!first_trace || sp_.depth(x) < first_depth) {
                first_depth = sp_.depth(x);
                first_trace = sp_.path_to(sp_.singleton(x));
                // The evolution under the first order closes the trace.
                const bool a_first = only(*under_a, true) == oa;
                const auto& e = a_first ? a : b;
                logic::TraceStep step;
                step.inputs =
                    semantics::InputCondition{{a_first ? *under_a : *under_b}}.witness(inputs);
                step.state.assign(e.target.begin(), e.target.end());
                step.fired.assign(e.fired.begin(), e.fired.end());
                first_trace->steps.push_back(std::move(step));
                first_trace->note = "the last cycle runs " + oa + "; under " + ob +
                                    " it would end with " + values_b + " instead of " + values_a;
              }
              return;
            }
        });
    if (!visited) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked by the " + std::string(sp_.name()) +
                  " engine (it needs each situation's evolutions); use --engine explicit or bdd";
      return;
    }
    if (first_trace) r.trace = std::move(first_trace);
    finish(r, "every admissible action order gives the same next situation");
  }

  void instability(PropertyResult& r) {
    std::set<std::string> seen;
    for (auto& a : sp_.anomalies()) {
      if (!seen.insert(a.text).second) continue;
      add(r, a.text);
      if (!r.trace && a.at) r.trace = sp_.path_to(*a.at);
    }
    finish(r, ts_.kind() == semantics::SemanticsKind::Grafcet
                  ? "every evolution reaches a stable situation"
                  : "no value out of range");
  }

  Space& sp_;
  const semantics::TransitionSystem& ts_;
  const logic::CheckTask& task_;
  std::vector<StepRef> steps_;
  bool bottoms_tried_ = false;
  std::optional<std::vector<Set>> bottoms_;  ///< bottom_components(), once tried
};

/// Runs task.checks through the runner on `space`.
template <class Space>
std::vector<logic::PropertyResult> run_standard_checks_on(Space& space,
                                                          const semantics::TransitionSystem& ts,
                                                          const logic::CheckTask& task) {
  if (task.checks.empty()) return {};
  return StandardCheckRunner<Space>(space, ts, task).run();
}

}  // namespace sfcv::engine

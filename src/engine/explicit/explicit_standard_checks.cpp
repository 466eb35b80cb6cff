// The standard checks on an explicit graph (catalogue and formulas: logic/standard_checks.hpp).

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include "engine/explicit/explicit_model_checker.hpp"
#include "logic/formula.hpp"
#include "model/names.hpp"

namespace sfcv::engine {

using logic::PropertyResult;
using logic::StandardCheck;
using logic::StepRef;
using logic::Verdict;

namespace {

constexpr std::size_t kMaxSituations = 3;  ///< situation findings listed before a summary
constexpr std::uint32_t kNone = ReachableSituationGraph::kNone;

std::string qualify(const std::string& pou, const std::string& name) {
  return pou.empty() ? name : pou + "." + name;
}

bool cubes_intersect(const semantics::InputCube& a, const semantics::InputCube& b) {
  for (const auto& x : a.literals)
    for (const auto& y : b.literals)
      if (x.input == y.input && (x.hi < y.lo || y.hi < x.lo)) return false;
  return true;
}

bool conditions_intersect(const semantics::InputCondition& a, const semantics::InputCondition& b) {
  for (const auto& x : a.cubes)
    for (const auto& y : b.cubes)
      if (cubes_intersect(x, y)) return true;
  return false;
}

class Checks {
 public:
  Checks(const ReachableSituationGraph& g, CtlChecker& fair, const logic::CheckTask& task)
      : g_(g), ts_(g.system()), fair_(fair), plain_(g), task_(task),
        steps_(logic::step_refs(g.system(), task.project)) {}

  PropertyResult run(StandardCheck id) {
    PropertyResult r;
    r.name = std::string(logic::to_string(id));
    r.check = r.name;
    switch (id) {
      case StandardCheck::Reachable: reachable(r); break;
      case StandardCheck::DeadTransitions: dead_transitions(r); break;
      case StandardCheck::Reentry: reentry(r); break;
      case StandardCheck::GlobalDeadlock: global_deadlock(r); break;
      case StandardCheck::LocalDeadlock: local_deadlock(r); break;
      case StandardCheck::InitialReturn: initial_return(r); break;
      case StandardCheck::Conflicts: conflicts(r); break;
      case StandardCheck::StoredActions: stored_actions(r); break;
      case StandardCheck::OutputConflicts: output_conflicts(r); break;
      case StandardCheck::Instability: instability(r); break;
    }
    return r;
  }

  PropertyResult reentry_fair() {
    PropertyResult r;
    r.name = "reentry-fair";
    r.check = "reentry";
    per_step_formula(r, fair_, true);
    return r;
  }

 private:
  std::string situation(std::uint32_t s) const { return ts_.describe(g_.states().at(s)); }
  std::string limit_message() const {
    return "exploration stopped at the " + g_.limit_reached() + " limit after " +
           std::to_string(g_.num_states()) + " states";
  }
  void add(PropertyResult& r, std::string finding) const {
    ++r.findings_total;
    if (task_.max_findings == 0 || r.findings.size() < task_.max_findings)
      r.findings.push_back(std::move(finding));
  }
  bool step_active(std::uint32_t s, const StepRef& step) const {
    return ts_.observe(g_.states().at(s), step.observable) != 0;
  }
  const StepRef* find_step(const std::string& pou, const std::string& chart,
                           const std::string& step) const {
    for (const auto& s : steps_)
      if (model::iequals(s.pou, pou) && model::iequals(s.chart, chart) &&
          model::iequals(s.step, step))
        return &s;
    return nullptr;
  }
  /// Backward closure of `seeds` over all edges.
  StateSet backward(StateSet seeds) const {
    const auto& po = g_.predecessor_offsets();
    const auto& pe = g_.predecessor_edges();
    std::vector<std::uint32_t> queue;
    for (std::uint32_t s = 0; s < seeds.size(); ++s)
      if (seeds[s]) queue.push_back(s);
    while (!queue.empty()) {
      const auto t = queue.back();
      queue.pop_back();
      for (auto i = po[t]; i < po[t + 1]; ++i) {
        const auto s = g_.source(pe[i]);
        if (!seeds[s]) {
          seeds[s] = 1;
          queue.push_back(s);
        }
      }
    }
    return seeds;
  }
  /// The shallowest state of `set`, or kNone.
  std::uint32_t shallowest(const StateSet& set) const {
    std::uint32_t best = kNone;
    for (std::uint32_t s = 0; s < set.size(); ++s)
      if (set[s] && (best == kNone || g_.depth(s) < g_.depth(best))) best = s;
    return best;
  }
  void finish(PropertyResult& r, const std::string& holds_message) const {
    if (!r.findings.empty()) {
      r.verdict = Verdict::Violated;
    } else if (!g_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
    } else {
      r.verdict = Verdict::Holds;
      r.message = holds_message;
    }
  }

  // ------------------------------------------------------------------------------ checks

  void reachable(PropertyResult& r) {
    if (steps_.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: the system has no steps";
      return;
    }
    std::vector<bool> seen(steps_.size(), false);
    std::size_t found = 0;
    for (std::uint32_t s = 0; s < g_.num_states() && found < steps_.size(); ++s)
      for (std::size_t i = 0; i < steps_.size(); ++i)
        if (!seen[i] && step_active(s, steps_[i])) {
          seen[i] = true;
          ++found;
        }
    const auto transient = g_.complete() ? transient_steps() : std::map<std::size_t, StateSet>{};
    std::size_t missing = 0;
    for (std::size_t i = 0; i < steps_.size(); ++i)
      if (!seen[i] && !transient.count(i)) {
        ++missing;
        if (g_.complete()) add(r, "step " + logic::describe_step(steps_[i]) + " is never active");
      }
    if (missing && !g_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = std::to_string(missing) + " of " + std::to_string(steps_.size()) +
                  " steps not reached before the limit; " + limit_message();
      return;
    }
    finish(r, "all " + std::to_string(steps_.size()) + " steps are reachable" +
                  (transient.empty() ? ""
                                     : " (" + std::to_string(transient.size()) +
                                           " only during transient evolutions)"));
  }

  void dead_transitions(PropertyResult& r) {
    const auto& trs = ts_.transitions();
    if (trs.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: the system has no transitions";
      return;
    }
    std::size_t dead = 0;
    for (std::size_t t = 0; t < trs.size(); ++t)
      if (!g_.fired_somewhere()[t]) {
        ++dead;
        if (g_.complete())
          add(r, "transition " + trs[t].name +
                     (trs[t].where.known() ? " (" + trs[t].where.str() + ")" : "") +
                     " never fires");
      }
    if (dead && !g_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = std::to_string(dead) + " transitions not fired before the limit; " +
                  limit_message();
      return;
    }
    finish(r, "all " + std::to_string(trs.size()) + " transitions can fire");
  }

  void reentry(PropertyResult& r) { per_step_formula(r, plain_, false); }

  // AG EF X (or AG AF X under fairness) for the steps of a loop.
  void per_step_formula(PropertyResult& r, CtlChecker& checker, bool af) {
    std::vector<const StepRef*> loop;
    for (const auto& s : steps_)
      if (s.on_loop || !task_.project) loop.push_back(&s);
    if (loop.empty()) {
      r.verdict = steps_.empty() ? Verdict::NotChecked : Verdict::Holds;
      r.message = steps_.empty() ? "not checked: the system has no steps" : "no step lies on a loop";
      return;
    }
    if (!g_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
      return;
    }
    if (g_.initial_states().empty()) {
      r.verdict = Verdict::Unknown;
      r.message = "no initial state";
      return;
    }
    const auto transient = transient_steps();
    for (const auto* step : loop) {
      const auto index = static_cast<std::size_t>(step - steps_.data());
      if (auto it = transient.find(index); it != transient.end()) {
        if (!af) transient_reentry(r, index, it->second, ": a reachable situation exists from "
                                                          "which it can never be crossed again");
        continue;
      }
      auto f = af ? logic::reentry_fair_formula(ts_, step->observable)
                  : logic::reentry_formula(ts_, step->observable);
      const auto& holds = checker.sat(f);
      std::vector<std::uint32_t> bad;
      for (auto s : g_.initial_states())
        if (!holds[s]) bad.push_back(s);
      if (bad.empty()) continue;
      add(r, "step " + logic::describe_step(*step) +
                 (af ? " is not re-entered on every fair run (AG AF " : 
                       ": a reachable situation exists from which it can never become active "
                       "again (AG EF ") +
                 ts_.observables()[step->observable].name + " is violated)");
      if (!r.trace) {
        auto t = checker.explain(push_negation(f), bad);
        t.marked = {step->observable};
        t.note = af ? "a fair run on which " + logic::describe_step(*step) + " never becomes active again"
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
    if (ts_.transitions().empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: the system has no transitions";
      return;
    }
    const std::uint32_t n = g_.num_states();
    StateSet firing(n, 0);
    for (std::uint32_t s = 0; s < n; ++s)
      if (g_.expanded(s))
        for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e)
          if (!g_.fired(e).empty()) firing[s] = 1;
    const auto live = backward(firing);
    StateSet dead(n, 0);
    for (std::uint32_t s = 0; s < n; ++s) {
      const bool stuck = g_.expanded(s) && g_.edges_begin(s) == g_.edges_end(s);
      // On an incomplete graph only a state without any successor is certainly dead.
      dead[s] = g_.complete() ? !live[s] : stuck;
    }
    std::size_t count = 0;
    for (std::uint32_t s = 0; s < n; ++s)
      if (dead[s] && ++count <= kMaxSituations)
        add(r, "situation " + situation(s) + " (after " + std::to_string(g_.depth(s)) +
                   " evolutions): " +
                   (g_.edges_begin(s) == g_.edges_end(s)
                        ? (ts_.kind() == semantics::SemanticsKind::Grafcet
                               ? "no successor at all (no input event leads to an evolution)"
                               : "no successor at all (the assumptions exclude every input)")
                        : "no transition can ever fire again, whatever the inputs"));
    if (count > kMaxSituations)
      add(r, "(and " + std::to_string(count - kMaxSituations) + " more deadlocked situations)");
    if (const auto s = shallowest(dead); s != kNone) {
      r.trace = plain_.path_to(s);
      r.trace->note = "the last situation is a global deadlock";
    }
    finish(r, "from every reachable situation some transition can still fire");
  }

  void local_deadlock(PropertyResult& r) {
    if (steps_.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: the system has no steps";
      return;
    }
    if (!g_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
      return;
    }
    r.formula = "AG (X -> EF !X) & AG (!X -> EF X)";
    const auto transient = transient_steps();
    for (const auto& step : steps_) {
      const auto index = static_cast<std::size_t>(&step - steps_.data());
      if (auto it = transient.find(index); it != transient.end()) {
        transient_reentry(r, index, it->second, ", once crossed, is never crossed again");
        continue;
      }
      const auto x = logic::observable_atom(ts_, step.observable);
      const auto never_left =
          logic::make_op(logic::Op::EF, {logic::make_and(x, logic::make_op(logic::Op::AG, {x}))});
      const auto nx = logic::make_not(x);
      const auto never_back =
          logic::make_op(logic::Op::EF, {logic::make_and(nx, logic::make_op(logic::Op::AG, {nx}))});
      for (const auto& [f, what] : {std::pair{never_left, "once active, is never left"},
                                    std::pair{never_back, "once inactive, never becomes active again"}}) {
        const auto& holds = plain_.sat(f);
        std::vector<std::uint32_t> at;
        for (auto s : g_.initial_states())
          if (holds[s]) at.push_back(s);
        if (at.empty()) continue;
        add(r, "step " + logic::describe_step(step) + ", " + what);
        if (!r.trace) {
          auto t = plain_.explain(f, at);
          t.kind = logic::TraceKind::Counterexample;
          t.marked = {step.observable};
          t.note = "from the last situation on, " + logic::describe_step(step) + " " + what;
          r.trace = std::move(t);
        }
      }
    }
    finish(r, "every step can always be left and re-entered");
  }

  void initial_return(PropertyResult& r) {
    if (g_.initial_states().empty()) {
      r.verdict = Verdict::Unknown;
      r.message = "no initial state";
      return;
    }
    if (!g_.complete()) {
      r.verdict = Verdict::Unknown;
      r.message = limit_message();
      return;
    }
    r.formula = "AG EF init";
    // The initial situation is the step activity of an initial state (inputs and variables
    // may differ); a system without steps compares whole states.
    auto key = [&](std::uint32_t s) {
      std::string k;
      if (steps_.empty()) {
        for (auto w : g_.states().at(s)) k += std::to_string(w) + ",";
      } else {
        for (const auto& st : steps_) k += step_active(s, st) ? '1' : '0';
      }
      return k;
    };
    std::set<std::string> init_keys;
    for (auto s : g_.initial_states()) init_keys.insert(key(s));
    const std::uint32_t n = g_.num_states();
    StateSet target(n, 0);
    for (std::uint32_t s = 0; s < n; ++s) target[s] = init_keys.count(key(s)) > 0;
    const auto back = backward(target);
    StateSet bad(n, 0);
    std::size_t count = 0;
    for (std::uint32_t s = 0; s < n; ++s) {
      bad[s] = !back[s];
      if (bad[s] && ++count <= kMaxSituations)
        add(r, "from situation " + situation(s) + " the initial situation " +
                   situation(g_.initial_states().front()) + " can never be reached again");
    }
    if (count > kMaxSituations)
      add(r, "(and " + std::to_string(count - kMaxSituations) + " more such situations)");
    if (const auto s = shallowest(bad); s != kNone) {
      r.trace = plain_.path_to(s);
      r.trace->note = "from the last situation the initial situation is unreachable";
    }
    finish(r, "the initial situation can be reached again from every reachable situation");
  }

  void conflicts(PropertyResult& r) {
    if (ts_.kind() == semantics::SemanticsKind::Iec61131 && task_.priority_resolves_conflicts) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: alternative transitions are resolved by the standard priority "
                  "(explicit priority, then document order); run with --priority none to find "
                  "the conflicts";
      return;
    }
    std::set<std::string> seen;
    std::uint32_t first = kNone;
    const auto& trs = ts_.transitions();
    auto names = [&](std::span<const std::uint32_t> fired) {
      std::string out;
      for (auto t : fired) out += (out.empty() ? "" : ", ") + trs[t].name;
      return "{" + out + "}";
    };
    if (ts_.kind() == semantics::SemanticsKind::Iec61131) {
      // No priority: a conflict is nondeterminism, two evolutions under overlapping inputs.
      for (std::uint32_t s = 0; s < g_.num_states(); ++s) {
        if (!g_.expanded(s)) continue;
        for (auto a = g_.edges_begin(s); a < g_.edges_end(s); ++a)
          for (auto b = a + 1; b < g_.edges_end(s); ++b) {
            if (!conditions_intersect(g_.condition(a), g_.condition(b))) continue;
            const auto text = names(g_.fired(a)) + " and " + names(g_.fired(b));
            if (!seen.insert(text).second) continue;
            if (first == kNone) first = s;
            add(r, "transitions " + text + " can both fire from " + situation(s) +
                       " (no priority between them)");
          }
      }
    } else {
      // Grafcet clears every clearable transition at once: a conflict is two transitions
      // with a common upstream step cleared together.
      const auto upstream = grafcet_upstream();
      if (upstream.empty()) {
        r.verdict = Verdict::NotChecked;
        r.message = "not checked: the transitions of the system could not be matched with the "
                    "chart's transitions";
        return;
      }
      for (std::uint32_t s = 0; s < g_.num_states(); ++s) {
        if (!g_.expanded(s)) continue;
        for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) {
          const auto fired = g_.fired(e);
          for (std::size_t i = 0; i < fired.size(); ++i)
            for (std::size_t j = i + 1; j < fired.size(); ++j) {
              std::vector<std::string> common;
              for (const auto& x : upstream[fired[i]])
                for (const auto& y : upstream[fired[j]])
                  if (x == y) common.push_back(x);
              if (common.empty()) continue;
              const auto text = trs[fired[i]].name + " and " + trs[fired[j]].name;
              if (!seen.insert(text).second) continue;
              if (first == kNone) first = s;
              add(r, "transitions " + text + " share the upstream step " + common.front() +
                         " and are cleared together from " + situation(s));
            }
        }
      }
    }
    if (first != kNone) {
      r.trace = plain_.path_to(first);
      r.trace->note = "in the last situation conflicting transitions are enabled together";
    }
    finish(r, "no two alternative transitions are enabled together");
  }

  /// The chart transition behind each system transition, matched by location (or name);
  /// empty when some transition cannot be matched.
  std::vector<const model::Transition*> chart_transitions() const {
    std::vector<const model::Transition*> out;
    if (!task_.project) return out;
    for (const auto& info : ts_.transitions()) {
      const model::Transition* hit = nullptr;
      for (const auto& pou : task_.project->pous) {
        if (!info.pou.empty() && !model::iequals(pou.name, info.pou)) continue;
        for (const auto& chart : pou.charts) {
          if (!info.chart.empty() && !model::iequals(chart.name, info.chart)) continue;
          for (const auto& t : chart.transitions) {
            const bool same = info.where.known() ? t.where.str() == info.where.str()
                                                 : (!t.name.empty() && t.name == info.name);
            if (same) hit = &t;
          }
        }
      }
      if (!hit) return {};
      out.push_back(hit);
    }
    return out;
  }

  /// Upstream step names of each system transition (chart-qualified); empty when unmatched.
  std::vector<std::vector<std::string>> grafcet_upstream() const {
    std::vector<std::vector<std::string>> out;
    const auto matched = chart_transitions();
    for (std::size_t i = 0; i < matched.size(); ++i) {
      std::vector<std::string> ups;
      for (const auto& s : matched[i]->sources) ups.push_back(qualify(ts_.transitions()[i].chart, s));
      out.push_back(std::move(ups));
    }
    return out;
  }

  /// Grafcet steps never active in a stable situation but entered by a transition that fires
  /// (they are crossed during transient evolutions): index into steps_ -> the states with an
  /// evolution entering the step. Empty for IEC 61131-3.
  std::map<std::size_t, StateSet> transient_steps() {
    std::map<std::size_t, StateSet> out;
    if (ts_.kind() != semantics::SemanticsKind::Grafcet) return out;
    const auto matched = chart_transitions();
    if (matched.empty()) return out;
    const std::uint32_t n = g_.num_states();
    for (std::size_t i = 0; i < steps_.size(); ++i) {
      bool stable = false;
      for (std::uint32_t s = 0; s < n && !stable; ++s) stable = step_active(s, steps_[i]);
      if (stable) continue;
      std::vector<bool> enters(matched.size(), false);
      bool any = false;
      for (std::size_t t = 0; t < matched.size(); ++t) {
        if (!model::iequals(ts_.transitions()[t].chart, steps_[i].chart)) continue;
        for (const auto& d : matched[t]->targets) enters[t] = enters[t] || model::iequals(d, steps_[i].step);
        any = any || enters[t];
      }
      if (!any) continue;
      StateSet entry(n, 0);
      bool fired = false;
      for (std::uint32_t s = 0; s < n; ++s) {
        if (!g_.expanded(s)) continue;
        for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e)
          for (auto t : g_.fired(e))
            if (enters[t]) entry[s] = 1, fired = true;
      }
      if (fired) out.emplace(i, std::move(entry));
    }
    return out;
  }

  /// Re-entry of a transient step: from every reachable state an evolution entering it stays
  /// reachable. Adds a finding and a trace when not.
  void transient_reentry(PropertyResult& r, std::size_t step, const StateSet& entry,
                         const std::string& what) {
    const auto back = backward(entry);
    StateSet bad(back.size(), 0);
    bool any = false;
    for (std::size_t s = 0; s < back.size(); ++s) any |= (bad[s] = !back[s]) != 0;
    if (!any) return;
    add(r, "step " + logic::describe_step(steps_[step]) + " (crossed only during transient "
           "evolutions)" + what);
    if (!r.trace) {
      r.trace = plain_.path_to(shallowest(bad));
      r.trace->note = "from the last situation " + logic::describe_step(steps_[step]) +
                      " can never be crossed again";
    }
  }

  void stored_actions(PropertyResult& r) {
    if (!task_.project) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: needs the chart (no project given)";
      return;
    }
    std::vector<std::string> not_checked;
    std::size_t stored = 0;
    std::uint32_t first = kNone;
    auto note_state = [&](std::uint32_t s) {
      if (first == kNone || g_.depth(s) < g_.depth(first)) first = s;
    };
    for (const auto& pou : task_.project->pous) {
      // IEC 61131-3: S (and SD, DS, SL) sets an action's stored flag, R resets it.
      std::map<std::string, std::pair<std::vector<const StepRef*>, std::vector<const StepRef*>>> sr;
      std::map<std::string, std::string> first_set_where;
      for (const auto& a : pou.associations) {
        const bool set = a.qualifier == model::Qualifier::S || a.qualifier == model::Qualifier::SD ||
                         a.qualifier == model::Qualifier::DS || a.qualifier == model::Qualifier::SL;
        const bool reset = a.qualifier == model::Qualifier::R;
        if (!set && !reset) continue;
        auto& entry = sr[model::to_upper(a.action)];
        const auto* step = find_step(pou.name, a.chart, a.step);
        if (set && !first_set_where.count(model::to_upper(a.action)))
          first_set_where[model::to_upper(a.action)] =
              a.step + (a.where.known() ? " (" + a.where.str() + ")" : "");
        if (!step) {
          not_checked.push_back("step " + a.step + " of " + a.action + " has no observable");
          continue;
        }
        (set ? entry.first : entry.second).push_back(step);
      }
      for (const auto& [action, lists] : sr) {
        const auto& [sets, resets] = lists;
        if (!first_set_where.count(action)) continue;
        ++stored;
        const std::string name = qualify(pou.name, action);
        if (resets.empty())
          add(r, "action " + name + " is stored at step " + first_set_where[action] +
                     " and never reset (no R qualifier anywhere)");
        // Set and reset in one situation.
        for (std::uint32_t s = 0; s < g_.num_states(); ++s) {
          const auto* on = [&]() -> const StepRef* {
            for (const auto* x : sets)
              if (step_active(s, *x)) return x;
            return nullptr;
          }();
          if (!on) continue;
          for (const auto* y : resets)
            if (step_active(s, *y)) {
              add(r, "action " + name + " is set (S at " + on->step + ") and reset (R at " +
                         y->step + ") in the same situation " + situation(s));
              note_state(s);
              s = g_.num_states() - 1;
              break;
            }
        }
        // Set again while stored: needs the stored flag.
        std::int64_t field = -1;
        const auto& fields = ts_.layout().fields();
        for (std::size_t i = 0; i < fields.size(); ++i)
          if (fields[i].kind == semantics::FieldKind::ActionStored) {
            std::string fname = fields[i].name;
            if (fname.size() > 7 && model::iequals(fname.substr(fname.size() - 7), ".stored"))
              fname.resize(fname.size() - 7);
            if (model::iequals(fname, name) || model::iequals(fname, action)) field = static_cast<std::int64_t>(i);
          }
        if (field < 0) {
          not_checked.push_back("set again while stored (" + name + "): the system exposes no "
                                "stored flag for it");
          continue;
        }
        bool found = false;
        for (std::uint32_t s = 0; s < g_.num_states() && !found; ++s) {
          if (!g_.expanded(s) || !ts_.layout().get(g_.states().at(s), static_cast<std::uint32_t>(field)))
            continue;
          for (auto e = g_.edges_begin(s); e < g_.edges_end(s) && !found; ++e)
            for (const auto* x : sets)
              if (!step_active(s, *x) && step_active(g_.target(e), *x)) {
                add(r, "action " + name + " is set again (S at " + x->step +
                           ") while already stored, from situation " + situation(s));
                note_state(g_.target(e));
                found = true;
                break;
              }
        }
      }
      // IEC 60848 stored actions: a variable set to 1 and never to 0, or to different values
      // on one evolution.
      std::map<std::string, std::vector<const model::StoredAction*>> by_var;
      for (const auto& a : pou.stored_actions) by_var[model::to_upper(a.variable)].push_back(&a);
      for (const auto& [var, list] : by_var) {
        ++stored;
        std::set<std::int64_t> values;
        bool non_constant = false;
        for (const auto* a : list) {
          if (a->value && (a->value->kind == model::ExprKind::BoolConst ||
                           a->value->kind == model::ExprKind::IntConst))
            values.insert(a->value->value);
          else
            non_constant = true;
        }
        if (!non_constant && values.size() == 1 && *values.begin() == 1)
          add(r, "output " + list.front()->variable + " is set to 1 by stored actions (" +
                     list.front()->where.str() + ") and never reset to 0");
        for (std::size_t i = 0; i < list.size(); ++i)
          for (std::size_t j = i + 1; j < list.size(); ++j) {
            const auto* a = list[i];
            const auto* b = list[j];
            if (a->when != model::StoredWhen::Activation || b->when != model::StoredWhen::Activation)
              continue;
            if (!a->value || !b->value || model::equal(a->value, b->value)) continue;
            const auto* sa = find_step(pou.name, a->chart, a->step);
            const auto* sb = find_step(pou.name, b->chart, b->step);
            if (!sa || !sb) {
              not_checked.push_back("stored actions on " + a->variable + " at steps without "
                                    "an observable");
              continue;
            }
            bool found = false;
            for (std::uint32_t s = 0; s < g_.num_states() && !found; ++s) {
              if (!g_.expanded(s)) continue;
              for (auto e = g_.edges_begin(s); e < g_.edges_end(s) && !found; ++e) {
                const auto t = g_.target(e);
                if (!step_active(s, *sa) && step_active(t, *sa) && !step_active(s, *sb) &&
                    step_active(t, *sb)) {
                  add(r, "output " + a->variable + " is set to different values at once by the "
                         "activation of " + sa->step + " and " + sb->step + ", from situation " +
                         situation(s));
                  note_state(t);
                  found = true;
                }
              }
            }
          }
        if (list.size() > 0)
          not_checked.push_back("set again while stored (" + list.front()->variable +
                                "): not checked for IEC 60848 stored actions");
      }
    }
    if (first != kNone) {
      r.trace = plain_.path_to(first);
      r.trace->note = "the last situation shows the stored-action defect";
    }
    if (stored == 0) {
      finish(r, "the chart has no stored action");
      return;
    }
    finish(r, "stored actions are used correctly");
    if (r.verdict == Verdict::Holds && !not_checked.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "no defect found in the parts checked; not checked: " + not_checked.front() +
                  (not_checked.size() > 1 ? " (and " + std::to_string(not_checked.size() - 1) +
                                                " more)"
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
      r.verdict = Verdict::NotChecked;
      r.message = "not checked for Grafcet: continuous actions only assert their output; stored "
                  "actions assigning different values at once are reported by stored-actions";
      return;
    }
    std::vector<std::string> not_checked;
    std::uint32_t first = kNone;
    std::size_t pairs = 0;
    for (const auto& pou : task_.project->pous) {
      // variable -> (action, constant value or none) for every assignment in an action body.
      struct Write {
        std::string action;
        std::optional<std::int64_t> value;
      };
      std::map<std::string, std::vector<Write>> writes;
      std::function<void(const model::StmtList&, const std::string&, bool)> walk =
          [&](const model::StmtList& body, const std::string& action, bool conditional) {
            for (const auto& st : body) {
              if (st->kind == model::StmtKind::Assign) {
                std::optional<std::int64_t> v;
                if (!conditional && st->value &&
                    (st->value->kind == model::ExprKind::BoolConst ||
                     st->value->kind == model::ExprKind::IntConst))
                  v = st->value->value;
                auto& list = writes[model::to_upper(st->target)];
                bool dup = false;
                for (const auto& w : list) dup |= w.action == action;
                if (!dup) list.push_back({action, v});
              }
              for (const auto& b : st->bodies) walk(b, action, true);
              walk(st->else_body, action, true);
            }
          };
      for (const auto& a : pou.actions)
        if (a.kind == model::ActionBodyKind::Statements) walk(a.body, a.name, false);
      for (const auto& [var, list] : writes)
        for (std::size_t i = 0; i < list.size(); ++i)
          for (std::size_t j = i + 1; j < list.size(); ++j) {
            const auto& a = list[i];
            const auto& b = list[j];
            if (a.value && b.value && *a.value == *b.value) continue;  // same value: harmless
            ++pairs;
            std::uint32_t ia = 0, ib = 0;
            bool ok = true;
            for (auto [name, idx] : {std::pair{&a.action, &ia}, std::pair{&b.action, &ib}}) {
              std::optional<std::uint32_t> hit;
              for (const auto& cand : {qualify(pou.name, *name), *name}) {
                hit = semantics::find_observable(ts_, cand);
                if (hit && ts_.observables()[*hit].kind == semantics::ObservableKind::Action) break;
                hit.reset();
              }
              if (hit) *idx = *hit; else ok = false;
            }
            if (!ok) {
              not_checked.push_back(var + " written by " + a.action + " and " + b.action +
                                    ": the system exposes no activity for these actions");
              continue;
            }
            for (std::uint32_t s = 0; s < g_.num_states(); ++s) {
              const auto st = g_.states().at(s);
              if (ts_.observe(st, ia) && ts_.observe(st, ib)) {
                auto show = [](const Write& w) {
                  return w.action + (w.value ? " (:= " + std::to_string(*w.value) + ")" : "");
                };
                add(r, "variable " + var + " is written by " + show(a) + " and " + show(b) +
                           " in the same cycle, in situation " + situation(s));
                if (first == kNone || g_.depth(s) < g_.depth(first)) first = s;
                break;
              }
            }
          }
    }
    if (first != kNone) {
      r.trace = plain_.path_to(first);
      r.trace->note = "in the last cycle both actions are active";
    }
    finish(r, pairs == 0 ? "no variable is written by two actions with different values"
                         : "actions writing the same variable are never active together");
    if (r.verdict == Verdict::Holds && !not_checked.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked: " + not_checked.front();
    }
  }

  void instability(PropertyResult& r) {
    std::set<std::string> seen;
    for (const auto& a : g_.anomalies()) {
      const std::string kind =
          a.kind == semantics::Anomaly::Kind::Instability ? "instability" : "range error";
      const auto text = kind + ": " + a.message +
                        (a.condition.is_false() ? "" : " (inputs " + a.condition.to_string(ts_.inputs()) + ")");
      if (seen.insert(text).second) add(r, text);
    }
    finish(r, ts_.kind() == semantics::SemanticsKind::Grafcet
                  ? "every evolution reaches a stable situation"
                  : "no value out of range");
  }

  const ReachableSituationGraph& g_;
  const semantics::TransitionSystem& ts_;
  CtlChecker& fair_;
  CtlChecker plain_;
  const logic::CheckTask& task_;
  std::vector<StepRef> steps_;
};

}  // namespace

std::vector<PropertyResult> run_standard_checks(const ReachableSituationGraph& graph,
                                                CtlChecker& checker,
                                                const logic::CheckTask& task) {
  using Clock = std::chrono::steady_clock;
  std::vector<PropertyResult> out;
  if (task.checks.empty()) return out;
  Checks checks(graph, checker, task);
  for (auto id : task.checks) {
    const auto t0 = Clock::now();
    out.push_back(checks.run(id));
    out.back().seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (id == StandardCheck::Reentry && checker.has_fairness()) {
      const auto t1 = Clock::now();
      out.push_back(checks.reentry_fair());
      out.back().seconds = std::chrono::duration<double>(Clock::now() - t1).count();
    }
  }
  return out;
}

}  // namespace sfcv::engine

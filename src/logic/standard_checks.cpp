#include "logic/standard_checks.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "logic/formula.hpp"
#include "model/names.hpp"
#include "semantics/grafcet_system.hpp"

namespace sfcv::logic {

const std::vector<StandardCheckInfo>& standard_checks() {
  static const std::vector<StandardCheckInfo> table = {
      {StandardCheck::Reachable, "reachable", "every step can become active (EF X)"},
      {StandardCheck::DeadTransitions, "dead-transitions", "every transition can fire"},
      {StandardCheck::Reentry, "reentry",
       "every step of a loop can be re-entered (AG EF X; AG AF X under fairness)"},
      {StandardCheck::GlobalDeadlock, "global-deadlock",
       "no reachable situation from which no transition can ever fire"},
      {StandardCheck::LocalDeadlock, "local-deadlock",
       "no step that once active is never left, or once inactive never re-entered"},
      {StandardCheck::InitialReturn, "initial-return",
       "the initial situation can be reached again from everywhere (AG EF init)"},
      {StandardCheck::Conflicts, "conflicts",
       "no alternative transitions enabled together without a priority"},
      {StandardCheck::StoredActions, "stored-actions",
       "stored actions: not set and reset together, not set while stored, always reset"},
      {StandardCheck::OutputConflicts, "output-conflicts",
       "no output written with different values by two actions in one cycle"},
      {StandardCheck::OrderDependence, "order-dependence",
       "no reachable situation where two admissible action orders give different results"},
      {StandardCheck::Instability, "instability",
       "no endless transient evolution (Grafcet) and no value out of range"},
  };
  return table;
}

std::string_view to_string(StandardCheck c) {
  for (const auto& i : standard_checks())
    if (i.id == c) return i.name;
  return "?";
}

std::optional<std::string> not_applicable(StandardCheck c, const semantics::TransitionSystem& ts,
                                          bool priority_resolves_conflicts) {
  bool has_steps = false;
  for (const auto& o : ts.observables()) has_steps |= o.kind == semantics::ObservableKind::Step;
  switch (c) {
    case StandardCheck::Reachable:
    case StandardCheck::Reentry:
    case StandardCheck::LocalDeadlock:
      if (!has_steps) return "the system has no steps";
      break;
    case StandardCheck::DeadTransitions:
    case StandardCheck::GlobalDeadlock:
      if (ts.transitions().empty()) return "the system has no transitions";
      break;
    case StandardCheck::Conflicts:
      if (ts.kind() == semantics::SemanticsKind::Iec61131 && priority_resolves_conflicts)
        return "alternative transitions are resolved by the standard priority (explicit "
               "priority, then document order); run with --priority none to find the conflicts";
      break;
    case StandardCheck::OrderDependence: {
      // Under a total order (declaration, alphabetical, a FILE total on every group) no input
      // chooses an order: the next situation cannot depend on one.
      const auto order = order_inputs(ts);
      if (std::find(order.begin(), order.end(), true) == order.end())
        return "every set of actions writing a common variable runs in one order (no "
               "order:<variable> input); run with --action-order unordered or a partial FILE "
               "order to ask";
      break;
    }
    default:
      break;
  }
  return std::nullopt;
}

std::vector<bool> order_inputs(const semantics::TransitionSystem& ts) {
  std::vector<bool> out;
  for (const auto& in : ts.inputs()) out.push_back(in.pseudo && in.name.starts_with("order:"));
  return out;
}

std::optional<std::vector<StandardCheck>> parse_check_selection(std::string_view text,
                                                                std::string* error) {
  std::vector<StandardCheck> out;
  if (text == "none") return out;
  if (text == "all") {
    for (const auto& i : standard_checks()) out.push_back(i.id);
    return out;
  }
  std::size_t start = 0;
  while (start <= text.size()) {
    auto end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    const auto item = text.substr(start, end - start);
    bool found = false;
    for (const auto& i : standard_checks())
      if (model::iequals(i.name, item)) {
        found = true;
        bool dup = false;
        for (auto c : out) dup |= c == i.id;
        if (!dup) out.push_back(i.id);
      }
    if (!found) {
      if (error) {
        *error = "unknown check '" + std::string(item) + "' (expected all, none or a list of:";
        for (const auto& i : standard_checks()) *error += " " + std::string(i.name);
        *error += ")";
      }
      return std::nullopt;
    }
    start = end + 1;
  }
  return out;
}

namespace {
// Steps of `chart` that lie on a cycle of its step -> transition -> step graph.
std::vector<bool> loop_steps(const model::Chart& chart) {
  const auto n = chart.steps.size();
  // Indexed once: Chart::step_index is a linear search, quadratic on long charts.
  std::unordered_map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < n; ++i) index.try_emplace(model::to_upper(chart.steps[i].name), i);
  std::vector<std::vector<std::size_t>> succ(n);
  std::vector<bool> on_loop(n, false);
  for (const auto& t : chart.transitions)
    for (const auto& s : t.sources)
      for (const auto& d : t.targets) {
        const auto a = index.find(model::to_upper(s));
        const auto b = index.find(model::to_upper(d));
        if (a == index.end() || b == index.end()) continue;
        succ[a->second].push_back(b->second);
        if (a->second == b->second) on_loop[a->second] = true;  // a step that loops on itself
      }
  // A step lies on a cycle when its strongly connected component holds another step: Tarjan's
  // algorithm, iterative (charts of 100,000 steps; one search per step was quadratic).
  constexpr auto kUnseen = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> order(n, kUnseen), low(n, 0), component;
  std::vector<bool> on_stack(n, false);
  std::vector<std::pair<std::size_t, std::size_t>> calls;  // (step, its next successor)
  std::size_t counter = 0;
  auto visit = [&](std::size_t v) {
    order[v] = low[v] = counter++;
    component.push_back(v);
    on_stack[v] = true;
    calls.emplace_back(v, 0);
  };
  for (std::size_t root = 0; root < n; ++root) {
    if (order[root] != kUnseen) continue;
    visit(root);
    while (!calls.empty()) {
      const auto v = calls.back().first;
      if (calls.back().second < succ[v].size()) {
        const auto w = succ[v][calls.back().second++];
        if (order[w] == kUnseen)
          visit(w);
        else if (on_stack[w])
          low[v] = std::min(low[v], order[w]);
        continue;
      }
      calls.pop_back();
      if (!calls.empty()) low[calls.back().first] = std::min(low[calls.back().first], low[v]);
      if (low[v] != order[v]) continue;
      // v's component is the top of the stack down to v: searched from the top.
      const auto first = std::find(component.rbegin(), component.rend(), v).base() - 1;
      const bool cycle = component.end() - first > 1;
      for (auto it = first; it != component.end(); ++it) {
        on_stack[*it] = false;
        if (cycle) on_loop[*it] = true;
      }
      component.erase(first, component.end());
    }
  }
  return on_loop;
}
}  // namespace

std::vector<semantics::PouInstance> instances_of(const semantics::TransitionSystem& ts,
                                                 const model::Pou& pou) {
  auto instances = ts.pou_instances();
  if (instances.empty()) return {{pou.name, pou.name, {}}};
  std::erase_if(instances, [&](const auto& i) { return !model::iequals(i.pou, pou.name); });
  return instances;
}

std::string chart_scope(const semantics::PouInstance& instance, const std::string& chart) {
  for (const auto& u : instance.units)
    if (u.size() > instance.path.size() + 1 &&
        model::iequals(u.substr(instance.path.size() + 1), chart))
      return u;
  return instance.path;
}

std::vector<StepRef> step_refs(const semantics::TransitionSystem& ts,
                               const model::Project* project) {
  const auto& obs = ts.observables();
  const bool by_instance = !ts.pou_instances().empty();
  std::map<std::uint32_t, StepRef> matched;
  if (project) {
    for (const auto& pou : project->pous)
      for (const auto& instance : instances_of(ts, pou))
        for (const auto& chart : pou.charts) {
          const auto& path = instance.path;
          const auto loops = loop_steps(chart);
          for (std::size_t i = 0; i < chart.steps.size(); ++i) {
            const auto& step = chart.steps[i];
            // A system with instances names every step from its instance; else the bare names
            // are tried too (Grafcet: "X12").
            std::vector<std::string> candidates{path + "." + chart.name + "." + step.name,
                                                path + "." + step.name};
            if (!by_instance) {
              candidates.push_back(chart.name + "." + step.name);
              candidates.push_back(step.name);
            }
            for (const auto& candidate : candidates) {
              const auto hit = semantics::find_observable(ts, candidate);
              if (!hit || obs[*hit].kind != semantics::ObservableKind::Step) continue;
              if (!matched.count(*hit))
                matched[*hit] = StepRef{*hit, pou.name, chart.name, step.name,
                                        path, loops[i], step.where, obs[*hit].name};
              break;
            }
          }
        }
  }
  std::vector<StepRef> out;
  for (std::uint32_t i = 0; i < obs.size(); ++i) {
    if (obs[i].kind != semantics::ObservableKind::Step) continue;
    auto it = matched.find(i);
    if (it != matched.end()) {
      out.push_back(it->second);
    } else {
      StepRef r;
      r.observable = i;
      r.step = obs[i].name;
      r.display = obs[i].name;
      out.push_back(std::move(r));
    }
  }
  return out;
}

std::vector<std::uint32_t> action_observables(const semantics::TransitionSystem& ts,
                                              const semantics::PouInstance& instance,
                                              const std::string& action) {
  // A Boolean action's activity is "<name>.A" when its variable bears the name (the IEC
  // compiler's name_boolean_action_activities).
  auto find = [&](const std::string& name) -> std::optional<std::uint32_t> {
    for (const auto& candidate : {name, name + ".A"}) {
      const auto hit = semantics::find_observable(ts, candidate);
      if (hit && ts.observables()[*hit].kind == semantics::ObservableKind::Action) return hit;
    }
    return std::nullopt;
  };
  std::vector<std::uint32_t> out;
  const auto& path = instance.path;
  if (const auto own = find(path.empty() ? action : path + "." + action)) {
    out.push_back(*own);
  } else if (ts.pou_instances().empty()) {  // Grafcet: the bare name too
    if (const auto bare = find(action)) out.push_back(*bare);
  }
  for (const auto& u : instance.units)
    if (const auto copy = find(u + "." + action)) out.push_back(*copy);
  return out;
}

const StepRef* find_step(const std::vector<StepRef>& steps, const std::string& path,
                         const std::string& chart, const std::string& step) {
  for (const auto& s : steps)
    if (model::iequals(s.instance, path) && model::iequals(s.chart, chart) &&
        model::iequals(s.step, step))
      return &s;
  return nullptr;
}

std::vector<StoredActionSteps> stored_action_steps(const model::Pou& pou,
                                                   const semantics::PouInstance& instance,
                                                   const std::vector<StepRef>& steps,
                                                   std::vector<std::string>& not_checked) {
  std::vector<StoredActionSteps> out;
  std::map<std::pair<std::string, std::string>, std::size_t> at;  // (scope, ACTION) -> out
  for (const auto& a : pou.associations) {
    const bool set = a.qualifier == model::Qualifier::S || a.qualifier == model::Qualifier::SD ||
                     a.qualifier == model::Qualifier::DS || a.qualifier == model::Qualifier::SL;
    const bool reset = a.qualifier == model::Qualifier::R;
    if (!set && !reset) continue;
    const auto scope = chart_scope(instance, a.chart);
    const auto action = model::to_upper(a.action);
    const auto [it, added] = at.try_emplace({model::to_upper(scope), action}, out.size());
    if (added) out.push_back({scope, action, {}, false, {}, {}});
    auto& entry = out[it->second];
    if (set && entry.first_set.empty())
      entry.first_set = a.step + (a.where.known() ? " (" + a.where.str() + ")" : "");
    entry.reset_anywhere |= reset;
    const auto* step = find_step(steps, instance.path, a.chart, a.step);
    if (!step) {
      not_checked.push_back("step " + a.step + " of " + a.action + " has no observable");
      continue;
    }
    (set ? entry.sets : entry.resets).push_back(step);
  }
  // Only actions that something sets are stored; reported by scope and name.
  std::erase_if(out, [](const StoredActionSteps& s) { return s.first_set.empty(); });
  std::sort(out.begin(), out.end(), [](const StoredActionSteps& x, const StoredActionSteps& y) {
    return std::pair(x.scope, x.action) < std::pair(y.scope, y.action);
  });
  return out;
}

std::optional<std::uint32_t> stored_flag_field(const semantics::TransitionSystem& ts,
                                               const std::string& scope,
                                               const std::string& action) {
  const std::string qualified = scope.empty() ? action : scope + "." + action;
  const bool bare_too = ts.pou_instances().empty();
  std::optional<std::uint32_t> field;
  const auto& fields = ts.layout().fields();
  for (std::uint32_t i = 0; i < fields.size(); ++i) {
    if (fields[i].kind != semantics::FieldKind::ActionStored) continue;
    std::string name = fields[i].name;
    if (name.size() > 7 && model::iequals(name.substr(name.size() - 7), ".stored"))
      name.resize(name.size() - 7);
    if (model::iequals(name, qualified) || (bare_too && model::iequals(name, action))) field = i;
  }
  return field;
}

FormulaPtr observable_atom(const semantics::TransitionSystem& ts, std::uint32_t index) {
  const auto& o = ts.observables()[index];
  auto atom = make_atom(o.name);
  return with_observable(*atom, static_cast<std::int32_t>(index));
}

FormulaPtr reentry_formula(const semantics::TransitionSystem& ts, std::uint32_t step) {
  return make_op(Op::AG, {make_op(Op::EF, {observable_atom(ts, step)})});
}

FormulaPtr reentry_fair_formula(const semantics::TransitionSystem& ts, std::uint32_t step) {
  return make_op(Op::AG, {make_op(Op::AF, {observable_atom(ts, step)})});
}

FormulaPtr local_deadlock_formula(const semantics::TransitionSystem& ts, std::uint32_t step) {
  const auto x = observable_atom(ts, step);
  auto left = make_op(Op::AG, {make_op(Op::Implies, {x, make_op(Op::EF, {make_not(x)})})});
  auto back = make_op(Op::AG, {make_op(Op::Implies, {make_not(x), make_op(Op::EF, {x})})});
  return make_and(std::move(left), std::move(back));
}

std::string describe_step(const StepRef& s) {
  std::string out = !s.display.empty() ? s.display : s.pou.empty() ? s.step : s.pou + "." + s.step;
  if (s.where.known()) out += " (" + s.where.str() + ")";
  return out;
}

std::string ActionWrite::shown() const {
  return action + (value ? " (:= " + std::to_string(*value) + ")" : "");
}

std::vector<WriteConflict> write_conflicts(const model::Pou& pou, const model::Project* project) {
  std::map<std::string, std::vector<ActionWrite>> writes;  // by variable, in action order
  std::string action;                                      // the action being walked
  std::set<std::string> entered;  // actions and functions on the walk's stack (recursion)
  auto add = [&](const std::string& variable, std::optional<std::int64_t> v) {
    auto& list = writes[model::to_upper(variable)];
    bool dup = false;
    for (const auto& w : list) dup |= w.action == action;
    if (!dup) list.push_back({action, v});
  };
  std::function<void(const model::StmtList&, bool)> walk;
  // A call of a user FUNCTION writes what its body writes outside its own variables (globals),
  // wherever the call stands: in a value, a condition or an argument.
  std::function<void(const model::ExprPtr&)> calls_in = [&](const model::ExprPtr& e) {
    if (!e) return;
    for (const auto& a : e->args) calls_in(a);
    if (e->kind != model::ExprKind::Call || !project) return;
    const auto* f = project->find_pou(e->name);
    if (!f || f->kind != model::PouKind::Function) return;
    const auto key = "F|" + model::to_upper(f->name);
    if (!entered.insert(key).second) return;
    std::function<void(const model::StmtList&)> globals = [&](const model::StmtList& body) {
      for (const auto& st : body) {
        const auto* own = f->find_variable(st->target);
        if ((st->kind == model::StmtKind::Assign || st->kind == model::StmtKind::For) &&
            !model::iequals(st->target, f->name) &&
            (!own || own->direction == model::VarDirection::External ||
             own->direction == model::VarDirection::Global))
          add(st->target, std::nullopt);
        calls_in(st->value);
        for (const auto& c : st->conditions) calls_in(c);
        for (const auto& [param, value] : st->arguments) calls_in(value);
        for (const auto& b : st->bodies) globals(b);
        globals(st->else_body);
      }
    };
    globals(f->body);
    entered.erase(key);
  };
  walk = [&](const model::StmtList& body, bool conditional) {
    for (const auto& st : body) {
      if (st->kind == model::StmtKind::Assign) {
        std::optional<std::int64_t> v;
        if (!conditional && st->value &&
            (st->value->kind == model::ExprKind::BoolConst ||
             st->value->kind == model::ExprKind::IntConst))
          v = st->value->value;
        add(st->target, v);
      }
      // A FOR loop assigns its index, and `inst(Q => y)` copies an output into y: writes
      // as much as an assignment (their values are not constants).
      if (st->kind == model::StmtKind::For) add(st->target, std::nullopt);
      // `inst(q => y)` and `x := F(q => y)` copy an output into y.
      for (const auto& [output, variable] : st->outputs) add(variable, std::nullopt);
      for (const auto& variable : model::in_out_bindings(project, pou.name, *st))
        add(variable, std::nullopt);
      if (st->kind == model::StmtKind::FbCall) {
        const auto* called = st->target.find('.') == std::string::npos && st->arguments.empty() &&
                                     !pou.find_variable(st->target)
                                 ? pou.find_action(st->target)
                                 : nullptr;
        if (called && called->kind == model::ActionBodyKind::Statements) {
          // `ACT();`: the called action's writes are the caller's.
          const auto key = "A|" + model::to_upper(called->name);
          if (entered.insert(key).second) {
            walk(called->body, true);
            entered.erase(key);
          }
        } else {
          // `inst(...)`, `inst.ACT(...)`: a call changes the instance (its inputs, its state,
          // what its body and actions write), so two actions calling one instance in a cycle
          // are a conflict on the instance.
          add(st->target.substr(0, st->target.find('.')), std::nullopt);
        }
      }
      calls_in(st->value);
      for (const auto& c : st->conditions) calls_in(c);
      for (const auto& [param, value] : st->arguments) calls_in(value);
      for (const auto& b : st->bodies) walk(b, true);
      walk(st->else_body, true);
    }
  };
  for (const auto& a : pou.actions) {
    if (a.kind != model::ActionBodyKind::Statements) continue;
    action = a.name;
    entered = {"A|" + model::to_upper(a.name)};
    walk(a.body, false);
  }
  std::vector<WriteConflict> out;
  for (const auto& [var, list] : writes)
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        if (list[i].value && list[j].value && *list[i].value == *list[j].value)
          continue;  // the same value: harmless
        out.push_back({var, list[i], list[j]});
      }
  return out;
}

std::vector<InstanceWriteConflict> instance_write_conflicts(const semantics::TransitionSystem& ts,
                                                            const model::Project& project) {
  std::vector<InstanceWriteConflict> out;
  for (const auto& pou : project.pous) {
    const auto conflicts = write_conflicts(pou, &project);
    // Each instance writes its own variables: its actions are judged among themselves.
    for (const auto& instance : instances_of(ts, pou))
      for (const auto& c : conflicts) {
        auto& q = out.emplace_back();
        q.what = "variable " + c.variable +
                 (model::iequals(instance.path, pou.name) ? "" : " of " + instance.path) +
                 " is written by " + c.first.shown() + " and " + c.second.shown();
        const auto as = action_observables(ts, instance, c.first.action);
        const auto bs = action_observables(ts, instance, c.second.action);
        if (as.empty() || bs.empty()) {
          q.not_checked = c.variable + " written by " + c.first.action + " and " + c.second.action +
                          ": the system exposes no activity for these actions";
          continue;
        }
        for (const auto a : as)
          for (const auto b : bs)
            if (a != b) q.together.emplace_back(a, b);
      }
  }
  return out;
}

std::vector<GrafcetStoredVariable> grafcet_stored_variables(const model::Pou& pou) {
  std::map<std::string, std::vector<const model::StoredAction*>> by_var;
  for (const auto& a : pou.stored_actions) by_var[model::to_upper(a.variable)].push_back(&a);
  std::vector<GrafcetStoredVariable> out;
  for (const auto& [var, list] : by_var) {
    GrafcetStoredVariable v;
    v.variable = list.front()->variable;
    v.first = list.front();
    std::set<std::int64_t> values;
    bool non_constant = false;
    for (const auto* a : list) {
      if (a->value && (a->value->kind == model::ExprKind::BoolConst ||
                       a->value->kind == model::ExprKind::IntConst))
        values.insert(a->value->value);
      else
        non_constant = true;
    }
    v.never_reset = !non_constant && values.size() == 1 && *values.begin() == 1;
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const auto* a = list[i];
        const auto* b = list[j];
        if (a->when != model::StoredWhen::Activation || b->when != model::StoredWhen::Activation)
          continue;
        if (!a->value || !b->value || model::equal(a->value, b->value)) continue;
        v.different.emplace_back(a, b);
      }
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<const model::Transition*> chart_transitions(const semantics::TransitionSystem& ts,
                                                        const model::Project& project) {
  // Per chart, its transitions by location and by name (the last of a kind wins, as a scan
  // in document order would): a chart of 6,000 transitions is matched in linear time.
  struct Index {
    std::map<std::string, const model::Transition*> by_where, by_name;
  };
  std::map<std::pair<std::string, std::string>, Index> charts;  // (POU, chart), upper case
  for (const auto& pou : project.pous)
    for (const auto& chart : pou.charts) {
      auto& index = charts[{model::to_upper(pou.name), model::to_upper(chart.name)}];
      for (const auto& t : chart.transitions) {
        index.by_where[t.where.str()] = &t;
        if (!t.name.empty()) index.by_name[t.name] = &t;
      }
    }
  std::vector<const model::Transition*> out;
  for (const auto& info : ts.transitions()) {
    const model::Transition* hit = nullptr;
    const auto pou = model::to_upper(info.pou), chart = model::to_upper(info.chart);
    const auto where = info.where.known() ? info.where.str() : std::string();
    for (const auto& [key, index] : charts) {
      if ((!pou.empty() && key.first != pou) || (!chart.empty() && key.second != chart)) continue;
      const auto& by = info.where.known() ? index.by_where : index.by_name;
      if (const auto it = by.find(info.where.known() ? where : info.name); it != by.end())
        hit = it->second;
    }
    if (!hit) return {};
    out.push_back(hit);
  }
  return out;
}

std::vector<std::vector<std::string>> grafcet_upstream_steps(const semantics::TransitionSystem& ts,
                                                             const model::Project& project) {
  std::vector<std::vector<std::string>> upstream;
  const auto matched = chart_transitions(ts, project);
  const auto& trs = ts.transitions();
  for (std::size_t i = 0; i < matched.size(); ++i) {
    std::vector<std::string> ups;
    for (const auto& s : matched[i]->sources)
      ups.push_back(trs[i].chart.empty() ? s : trs[i].chart + "." + s);
    upstream.push_back(std::move(ups));
  }
  return upstream;
}

std::vector<std::string> common_steps(const std::vector<std::string>& a,
                                      const std::vector<std::string>& b) {
  std::vector<std::string> common;
  for (const auto& x : a)
    for (const auto& y : b)
      if (x == y) common.push_back(x);
  return common;
}

std::vector<MixedWriter> grafcet_mixed_writers(const semantics::TransitionSystem& ts,
                                               const model::Project& project) {
  std::vector<MixedWriter> out;
  auto steps_list = [](const std::vector<std::string>& steps) {
    std::string text = steps.size() == 1 ? "step " : "steps ";
    for (std::size_t i = 0; i < steps.size(); ++i) text += (i ? ", " : "") + steps[i];
    return text;
  };
  auto add_once = [](std::vector<std::string>& list, const std::string& step) {
    if (std::find(list.begin(), list.end(), step) == list.end()) list.push_back(step);
  };
  for (const auto& mixed : ts.mixed_variables()) {
    MixedWriter m;
    m.variable = mixed.name;
    m.assigned = mixed.assigned_field;
    m.stored = mixed.stored_field;
    std::vector<std::string> continuous, stored;
    for (const auto& pou : project.pous) {
      for (const auto& sa : pou.stored_actions)
        if (model::iequals(sa.variable, m.variable)) add_once(stored, sa.step);
      for (const auto& as : pou.associations)
        if (model::iequals(pou.assigned_variable(as), m.variable)) add_once(continuous, as.step);
    }
    m.what = m.variable + " is written by continuous actions (" + steps_list(continuous) +
             ") and by stored actions (" + steps_list(stored) + ")";
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace sfcv::logic

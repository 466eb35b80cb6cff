// The IEC compiler's SFC actions called by name (TwinCAT, CODESYS): a function block's SFC
// actions that its own SFC body does not drive run as units, one cycle of their chart per call
// (docs/semantics.md 1.3b). A unit is an instance Pou: the machine and the circuit run it with
// their instance call (body, flags, actions, transitions, next configuration, commit).

#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

namespace {

/// Whether association `as` belongs to a chart whose upper-case name is in `charts` (an
/// association without a chart name: a step of that name in one of them).
bool in_charts(const model::Pou& type, const model::ActionAssociation& as,
               const std::set<std::string>& charts) {
  if (!as.chart.empty()) return charts.count(model::to_upper(as.chart)) > 0;
  for (const auto& ch : type.charts)
    if (charts.count(model::to_upper(ch.name)) && ch.step_index(as.step) >= 0) return true;
  return false;
}

}  // namespace

const model::ActionAssociation* Compiler::driving_association(const model::Pou& type,
                                                              const std::string& action) {
  // IEC 61131-3 nested charts (1.3): an SFC action that a step of the SFC body names, or a
  // step of a chart nested in it, evolves while that association keeps it active.
  std::set<std::string> charts, driven;
  for (const auto& ch : type.charts)
    if (ch.parent_action.empty()) charts.insert(model::to_upper(ch.name));
  const model::ActionAssociation* found = nullptr;
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& as : type.associations) {
      const auto* a = type.find_action(as.action);
      if (!a || a->kind != model::ActionBodyKind::Chart || !in_charts(type, as, charts)) continue;
      if (!driven.insert(model::to_upper(a->name)).second) continue;
      grew = true;
      if (!found && model::iequals(a->name, action)) found = &as;
      for (const auto& ch : type.charts)
        if (model::iequals(ch.parent_action, a->name)) charts.insert(model::to_upper(ch.name));
    }
  }
  return found;
}

bool Compiler::is_unit_action(const model::Pou& type, const model::Action& a) {
  return type.kind == model::PouKind::FunctionBlock && a.kind == model::ActionBodyKind::Chart &&
         !driving_association(type, a.name);
}

std::string Compiler::sfc_action_call_error(const model::Pou& type, const model::Action& act,
                                            const std::string& target) const {
  const std::string head = "call of action '" + target + "' of " + type.name + ": ";
  if (const auto* d = driving_association(type, act.name))
    return head + "step '" + d->step + "' of the SFC body of " + type.name +
           " runs it as its nested chart; " + nested_and_called;
  if (type.kind != model::PouKind::FunctionBlock)
    return head + "calling an SFC action of a " +
           (type.kind == model::PouKind::Program ? "program" : "function") +
           " (one cycle of its chart per call) is not modelled";
  return head + "calling it by name is not modelled";
}

bool Compiler::runs_sfc_actions_as_units(const model::Pou& type) {
  for (const auto& a : type.actions)
    if (is_unit_action(type, a)) return true;
  return false;
}

const model::Pou* Compiler::instance_view(const model::Pou* type) {
  if (!type || !runs_sfc_actions_as_units(*type)) return type;
  auto [it, fresh] = instance_views.try_emplace(type, nullptr);
  if (fresh) {
    // Without the units' charts, the associations of their steps and the units themselves;
    // an SFC body and the SFC actions it drives stay (an ST body: nothing of that).
    model::Pou view = *type;
    std::set<std::string> unit_charts;
    view.charts.clear();
    for (const auto& ch : type->charts) {
      const auto* a = ch.parent_action.empty() ? nullptr : type->find_action(ch.parent_action);
      if (a && is_unit_action(*type, *a))
        unit_charts.insert(model::to_upper(ch.name));
      else
        view.charts.push_back(ch);
    }
    std::erase_if(view.associations, [&](const model::ActionAssociation& as) {
      if (!as.chart.empty()) return unit_charts.count(model::to_upper(as.chart)) > 0;
      return std::none_of(view.charts.begin(), view.charts.end(),
                          [&](const model::Chart& ch) { return ch.step_index(as.step) >= 0; });
    });
    std::erase_if(view.actions, [&](const model::Action& a) { return is_unit_action(*type, a); });
    // A Boolean variable that only the units' steps drive: the body's action control would
    // write its (never active) action to it every cycle, over the units' writes.
    if (!view.charts.empty())
      std::erase_if(view.actions, [&](const model::Action& a) {
        return a.kind == model::ActionBodyKind::Variable &&
               std::none_of(view.associations.begin(), view.associations.end(),
                            [&](const auto& as) { return model::iequals(as.action, a.name); });
      });
    for (auto& a : view.actions)
      if (a.kind == model::ActionBodyKind::Chart) {
        a.chart = -1;
        for (std::size_t i = 0; i < view.charts.size(); ++i)
          if (model::iequals(view.charts[i].parent_action, a.name)) a.chart = static_cast<int>(i);
      }
    synthetic_pous.push_back(std::move(view));
    it->second = &synthetic_pous.back();
  }
  return it->second;
}

void Compiler::make_units(std::uint32_t inst, const model::Pou& type) {
  if (!runs_sfc_actions_as_units(type)) return;
  for (const auto& a : type.actions) {
    if (!is_unit_action(type, a)) continue;
    int ci = a.chart;
    if (ci < 0 || static_cast<std::size_t>(ci) >= type.charts.size() ||
        !model::iequals(type.charts[static_cast<std::size_t>(ci)].parent_action, a.name)) {
      ci = -1;
      for (std::size_t i = 0; i < type.charts.size(); ++i)
        if (model::iequals(type.charts[i].parent_action, a.name)) ci = static_cast<int>(i);
    }
    if (ci < 0) {
      error(a.where, "SFC action '" + a.name + "' of " + type.name + " has no chart");
      continue;
    }
    // The unit: the action's chart at top level, the associations of its steps and the
    // actions they name (a copy each: a unit has its own action control, as every SFC of
    // CODESYS/TwinCAT has), on the instance's variables. SFC actions and actions of other
    // instances that its steps name become calls (Compiler::callable_association).
    model::Pou unit;
    unit.name = type.name;
    unit.kind = model::PouKind::FunctionBlock;
    unit.variables = type.variables;
    unit.where = a.where;
    unit.charts.push_back(type.charts[static_cast<std::size_t>(ci)]);
    auto& chart = unit.charts.back();
    chart.parent_action.clear();
    std::set<std::string> named;
    for (const auto& as : type.associations) {
      const bool here =
          as.chart.empty() ? chart.step_index(as.step) >= 0 : model::iequals(as.chart, chart.name);
      if (!here) continue;
      if (const auto* d = driving_association(type, as.action)) {
        error(as.where, "step '" + as.step + "' of SFC action '" + a.name + "' names SFC action '" +
                            as.action + "', which step '" + d->step + "' of the SFC body of " +
                            type.name + " runs as its nested chart: " + nested_and_called);
        continue;
      }
      unit.associations.push_back(as);
      named.insert(model::to_upper(as.action));
    }
    for (const auto& b : type.actions)
      if (b.kind != model::ActionBodyKind::Chart && named.count(model::to_upper(b.name)))
        unit.actions.push_back(b);
    synthetic_pous.push_back(std::move(unit));
    PouScope sc;
    sc.pou = &synthetic_pous.back();
    sc.index = static_cast<std::uint32_t>(scopes.size());
    sc.name = scopes[inst].name + "." + a.name;
    sc.alias = scopes[inst].alias + "." + a.name;
    sc.instance = true;
    sc.unit = true;
    sc.owner = inst;
    sc.names = scopes[inst].names;
    units[{inst, model::to_upper(a.name)}] = sc.index;
    scopes.push_back(std::move(sc));
  }
}

std::optional<std::uint32_t> Compiler::unit_named(const PouScope& sc,
                                                  const std::string& target) const {
  if (sc.function) return std::nullopt;
  const auto parts = model::split_path(target);
  if (parts.size() == 1) {
    const auto up = model::to_upper(target);
    if (sc.names.count(up)) return std::nullopt;
    const auto it = units.find({sc.unit ? sc.owner : sc.index, up});
    return it == units.end() ? std::nullopt : std::optional<std::uint32_t>(it->second);
  }
  std::size_t used = 0;
  const auto si = path_scope(sc, parts, used);
  if (used == 0 || used + 1 != parts.size() || !scopes[si].instance) return std::nullopt;
  const auto it = units.find({si, model::to_upper(parts.back())});
  return it == units.end() ? std::nullopt : std::optional<std::uint32_t>(it->second);
}

bool Compiler::callable_association(const PouScope& sc, const std::string& action) const {
  if (unit_named(sc, action)) return true;
  const auto parts = model::split_path(action);
  if (parts.size() < 2 || sc.function) return false;
  std::size_t used = 0;
  const auto si = path_scope(sc, parts, used);
  if (used == 0 || used + 1 != parts.size() || !scopes[si].instance) return false;
  const auto* act = scopes[si].pou->find_action(parts.back());
  return act && act->kind == model::ActionBodyKind::Statements;
}

void Compiler::reject_call_cycles() {
  // Units call units (a step naming another SFC action, an action calling `ACT();`): a cycle
  // of calls would run forever in one scan (CODESYS overflows its stack), so it is refused.
  std::vector<std::vector<std::uint32_t>> callees(p.pous.size());
  std::function<void(Block, std::vector<std::uint32_t>&)> calls = [&](Block b, auto& out) {
    for (std::uint32_t i = 0; i < b.count; ++i) {
      const Stmt& st = p.stmts[p.block_items[b.first + i]];
      if (st.op == SOp::Call) out.push_back(st.target);
      for (std::uint32_t a = 0; a < st.arm_count; ++a)
        calls(st.op == SOp::Case ? p.case_arms[st.arm_first + a].body
                                 : p.if_arms[st.arm_first + a].body,
              out);
      calls(st.else_body, out);
      calls(st.init, out);
      calls(st.body, out);
      calls(st.step, out);
    }
  };
  for (std::uint32_t pi = 0; pi < p.pous.size(); ++pi) calls(p.pous[pi].body, callees[pi]);
  for (const auto& a : p.actions) calls(a.body, callees[a.pou]);
  std::vector<int> mark(p.pous.size(), 0);
  std::vector<std::uint32_t> path;
  std::function<bool(std::uint32_t)> visit = [&](std::uint32_t pi) {
    if (mark[pi] == 2) return false;
    path.push_back(pi);
    if (mark[pi] == 1) {
      std::string chain;
      for (auto it = std::find(path.begin(), path.end(), pi); it != path.end(); ++it)
        chain += (chain.empty() ? "" : " -> ") + p.pous[*it].name;
      error(scopes[pi].pou->where, "'" + p.pous[pi].name + "' calls itself (" + chain +
                                       "): a cycle of calls within one scan is not modelled");
      return true;
    }
    mark[pi] = 1;
    for (auto c : callees[pi])
      if (visit(c)) return true;
    mark[pi] = 2;
    path.pop_back();
    return false;
  };
  for (std::uint32_t pi = 0; pi < p.pous.size(); ++pi) {
    path.clear();
    if (visit(pi)) return;
  }
}

}  // namespace sfcv::semantics::iec::detail

// The IEC compiler's SFC actions called by name (TwinCAT, CODESYS): a function block whose body
// is not SFC but whose actions are runs each SFC action as a unit, one cycle of its chart per
// call (docs/semantics.md 1.3b). A unit is an instance Pou: the machine and the circuit run it
// with their instance call (body, flags, actions, transitions, next configuration, commit).

#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

bool Compiler::runs_sfc_actions_as_units(const model::Pou& type) {
  if (type.kind != model::PouKind::FunctionBlock) return false;
  for (const auto& ch : type.charts)
    if (ch.parent_action.empty()) return false;  // an SFC body: its steps activate the actions
  for (const auto& a : type.actions)
    if (a.kind == model::ActionBodyKind::Chart) return true;
  return false;
}

const model::Pou* Compiler::instance_view(const model::Pou* type) {
  if (!type || !runs_sfc_actions_as_units(*type)) return type;
  auto [it, fresh] = instance_views.try_emplace(type, nullptr);
  if (fresh) {
    model::Pou view = *type;
    view.charts.clear();
    view.associations.clear();
    std::erase_if(view.actions,
                  [](const model::Action& a) { return a.kind == model::ActionBodyKind::Chart; });
    synthetic_pous.push_back(std::move(view));
    it->second = &synthetic_pous.back();
  }
  return it->second;
}

void Compiler::make_units(std::uint32_t inst, const model::Pou& type) {
  if (!runs_sfc_actions_as_units(type)) return;
  for (const auto& a : type.actions) {
    if (a.kind != model::ActionBodyKind::Chart) continue;
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

#include "model/compare.hpp"

#include <algorithm>
#include <iterator>
#include <map>
#include <set>

#include "model/names.hpp"

namespace sfcv::model {

namespace {

using Diff = std::optional<std::string>;

std::string q(std::string_view s) {
  return "'" + std::string(s) + "'";
}

// Charts are identified across projects by role: the body of an action, the POU's only
// top-level chart, or a named top-level chart (partial grafcets).
std::string chart_key(const Pou& pou, std::size_t index) {
  const Chart& c = pou.charts[index];
  if (!c.parent_action.empty()) return "action " + to_upper(c.parent_action);
  const auto top = std::count_if(pou.charts.begin(), pou.charts.end(),
                                 [](const Chart& x) { return x.parent_action.empty(); });
  return top == 1 ? std::string("body") : "chart " + to_upper(c.name);
}

std::string chart_key(const Pou& pou, std::string_view chart_name) {
  const int i = pou.chart_index(chart_name);
  return i < 0 ? "unknown chart " + to_upper(chart_name)
               : chart_key(pou, static_cast<std::size_t>(i));
}

bool same_type(const Type& a, const Type& b) {
  return a.kind == b.kind && a.fb == b.fb &&
         (a.kind != TypeKind::Int || (a.lo == b.lo && a.hi == b.hi));
}

std::string step_signature(const Step& s) {
  std::string sig = to_upper(s.name) + (s.initial ? " (initial)" : "");
  if (s.kind == StepKind::MacroStep) sig += " macro-step expanded by " + to_upper(s.expansion);
  if (s.kind == StepKind::Enclosing) {
    sig += " enclosing";
    for (const auto& e : s.enclosed) sig += " " + to_upper(e);
  }
  return sig;
}

std::vector<std::string> sorted_upper(const std::vector<std::string>& v) {
  std::vector<std::string> r;
  for (const auto& s : v) r.push_back(to_upper(s));
  std::sort(r.begin(), r.end());
  return r;
}

std::string describe(const Transition& t) {
  std::string s = "transition";
  if (!t.name.empty()) s += " " + q(t.name);
  auto list = [](const std::vector<std::string>& v) {
    std::string r;
    for (const auto& x : v) r += (r.empty() ? "" : ", ") + x;
    return v.size() == 1 ? r : "(" + r + ")";
  };
  return s + " FROM " + list(t.sources) + " TO " + list(t.targets) + " := " + to_st(t.guard);
}

bool same_transition(const Transition& a, const Transition& b) {
  if (sorted_upper(a.sources) != sorted_upper(b.sources)) return false;
  if (sorted_upper(a.targets) != sorted_upper(b.targets)) return false;
  if (a.priority != b.priority || !equal(a.guard, b.guard)) return false;
  return a.name.empty() || b.name.empty() || iequals(a.name, b.name);
}

bool shares_source(const Transition& a, const Transition& b) {
  for (const auto& s : a.sources)
    for (const auto& t : b.sources)
      if (iequals(s, t)) return true;
  return false;
}

Diff compare_charts(const Chart& a, const Chart& b) {
  std::vector<std::string> sa, sb;
  for (const auto& s : a.steps) sa.push_back(step_signature(s));
  for (const auto& s : b.steps) sb.push_back(step_signature(s));
  std::sort(sa.begin(), sa.end());
  std::sort(sb.begin(), sb.end());
  if (sa != sb) {
    std::vector<std::string> only_a, only_b;
    std::set_difference(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(only_a));
    std::set_difference(sb.begin(), sb.end(), sa.begin(), sa.end(), std::back_inserter(only_b));
    if (!only_a.empty()) return "step " + only_a.front() + " only in the first";
    return "step " + only_b.front() + " only in the second";
  }
  if (a.transitions.size() != b.transitions.size())
    return std::to_string(a.transitions.size()) + " transitions against " +
           std::to_string(b.transitions.size());
  // Match each transition of `a` to an unused equal one of `b`.
  std::vector<int> match(a.transitions.size(), -1);
  std::vector<bool> used(b.transitions.size(), false);
  for (std::size_t i = 0; i < a.transitions.size(); ++i) {
    for (std::size_t j = 0; j < b.transitions.size() && match[i] < 0; ++j)
      if (!used[j] && same_transition(a.transitions[i], b.transitions[j])) {
        match[i] = static_cast<int>(j);
        used[j] = true;
      }
    if (match[i] < 0) return describe(a.transitions[i]) + " only in the first";
  }
  // Document order decides between transitions leaving the same step; it must agree.
  auto before = [](const Chart& c, std::size_t x, std::size_t y) {
    const auto& tx = c.transitions[x];
    const auto& ty = c.transitions[y];
    return tx.order != ty.order ? tx.order < ty.order : x < y;
  };
  for (std::size_t i = 0; i < a.transitions.size(); ++i)
    for (std::size_t k = i + 1; k < a.transitions.size(); ++k) {
      if (!shares_source(a.transitions[i], a.transitions[k])) continue;
      const auto bi = static_cast<std::size_t>(match[i]), bk = static_cast<std::size_t>(match[k]);
      if (before(a, i, k) != before(b, bi, bk))
        return "order of " + describe(a.transitions[i]) + " and " + describe(a.transitions[k]);
    }
  return std::nullopt;
}

std::string describe(const ActionAssociation& x) {
  std::string s = x.action + "(" + std::string(to_string(x.qualifier));
  if (x.duration_ms) s += ", " + std::to_string(*x.duration_ms) + " ms";
  if (!x.duration_variable.empty()) s += ", " + x.duration_variable;
  if (!x.indicator.empty()) s += ", " + x.indicator;
  if (x.condition) s += " if " + to_st(x.condition);
  if (x.step_action) s += ", step action";
  return s + ")";
}

bool same_association(const ActionAssociation& a, const ActionAssociation& b) {
  return iequals(a.action, b.action) && a.qualifier == b.qualifier &&
         a.step_action == b.step_action && a.duration_ms == b.duration_ms &&
         iequals(a.duration_variable, b.duration_variable) && iequals(a.indicator, b.indicator) &&
         equal(a.condition, b.condition);
}

Diff compare_associations(const Pou& a, const Pou& b) {
  using Key = std::pair<std::string, std::string>;
  std::map<Key, std::vector<const ActionAssociation*>> ga, gb;
  for (const auto& x : a.associations) ga[{chart_key(a, x.chart), to_upper(x.step)}].push_back(&x);
  for (const auto& x : b.associations) gb[{chart_key(b, x.chart), to_upper(x.step)}].push_back(&x);
  std::set<Key> keys;
  for (const auto& kv : ga) keys.insert(kv.first);
  for (const auto& kv : gb) keys.insert(kv.first);
  static const std::vector<const ActionAssociation*> none;
  for (const auto& key : keys) {
    const auto ia = ga.find(key), ib = gb.find(key);
    const auto& la = ia == ga.end() ? none : ia->second;
    const auto& lb = ib == gb.end() ? none : ib->second;
    const std::string where = "step " + key.second + " (" + key.first + ")";
    for (std::size_t i = 0; i < std::max(la.size(), lb.size()); ++i) {
      if (i >= la.size())
        return where + ": association " + describe(*lb[i]) + " only in the second";
      if (i >= lb.size()) return where + ": association " + describe(*la[i]) + " only in the first";
      if (!same_association(*la[i], *lb[i]))
        return where + ": association " + describe(*la[i]) + " against " + describe(*lb[i]);
    }
  }
  return std::nullopt;
}

Diff compare_pous(const Pou& a, const Pou& b) {
  if (a.kind != b.kind) return std::string("kind differs");
  // Variables.
  if (a.variables.size() != b.variables.size())
    return std::to_string(a.variables.size()) + " variables against " +
           std::to_string(b.variables.size());
  for (const auto& va : a.variables) {
    const Variable* vb = b.find_variable(va.name);
    if (!vb) return "variable " + q(va.name) + " only in the first";
    if (va.direction != vb->direction) return "variable " + q(va.name) + ": direction differs";
    if (!same_type(va.type, vb->type))
      return "variable " + q(va.name) + ": type " + va.type.name + " against " + vb->type.name;
    if (va.initial != vb->initial) return "variable " + q(va.name) + ": initial value differs";
    if (!iequals(va.address, vb->address)) return "variable " + q(va.name) + ": address differs";
  }
  if (!equal(a.body, b.body)) return std::string("ST body differs");
  if (a.body_unsupported != b.body_unsupported) return std::string("body modelled in only one");
  // Charts.
  if (a.charts.size() != b.charts.size())
    return std::to_string(a.charts.size()) + " charts against " + std::to_string(b.charts.size());
  for (std::size_t i = 0; i < a.charts.size(); ++i) {
    const std::string key = chart_key(a, i);
    std::optional<std::size_t> j;
    for (std::size_t k = 0; k < b.charts.size() && !j; ++k)
      if (chart_key(b, k) == key) j = k;
    if (!j) return key + " only in the first";
    if (auto d = compare_charts(a.charts[i], b.charts[*j])) return key + ": " + *d;
  }
  // Actions.
  if (a.actions.size() != b.actions.size())
    return std::to_string(a.actions.size()) + " actions against " +
           std::to_string(b.actions.size());
  for (const auto& xa : a.actions) {
    const Action* xb = b.find_action(xa.name);
    if (!xb) return "action " + q(xa.name) + " only in the first";
    if (xa.kind != xb->kind) return "action " + q(xa.name) + ": kind differs";
    if (xa.body_unsupported != xb->body_unsupported)
      return "action " + q(xa.name) + ": body modelled in only one";
    if (xa.kind == ActionBodyKind::Variable && !iequals(xa.variable, xb->variable))
      return "action " + q(xa.name) + ": variable differs";
    if (xa.kind == ActionBodyKind::Statements && !equal(xa.body, xb->body))
      return "action " + q(xa.name) + ": body differs";
    if (xa.kind == ActionBodyKind::Chart) {
      const auto ok = [](const Pou& p, int c) {
        return c >= 0 && static_cast<std::size_t>(c) < p.charts.size();
      };
      if (!ok(a, xa.chart) || !ok(b, xb->chart) ||
          chart_key(a, static_cast<std::size_t>(xa.chart)) !=
              chart_key(b, static_cast<std::size_t>(xb->chart)))
        return "action " + q(xa.name) + ": nested chart differs";
    }
  }
  if (auto d = compare_associations(a, b)) return *d;
  // Grafcet extras, in order.
  if (a.stored_actions.size() != b.stored_actions.size())
    return std::string("number of stored actions differs");
  for (std::size_t i = 0; i < a.stored_actions.size(); ++i) {
    const auto& x = a.stored_actions[i];
    const auto& y = b.stored_actions[i];
    if (chart_key(a, x.chart) != chart_key(b, y.chart) || !iequals(x.step, y.step) ||
        x.when != y.when || !equal(x.event, y.event) || !iequals(x.variable, y.variable) ||
        !equal(x.value, y.value))
      return "stored action " + std::to_string(i + 1) + " on step " + q(x.step) + " differs";
  }
  if (a.forcing_orders.size() != b.forcing_orders.size())
    return std::string("number of forcing orders differs");
  for (std::size_t i = 0; i < a.forcing_orders.size(); ++i) {
    const auto& x = a.forcing_orders[i];
    const auto& y = b.forcing_orders[i];
    if (chart_key(a, x.chart) != chart_key(b, y.chart) || !iequals(x.step, y.step) ||
        chart_key(a, x.target) != chart_key(b, y.target) || x.kind != y.kind ||
        sorted_upper(x.situation) != sorted_upper(y.situation))
      return "forcing order " + std::to_string(i + 1) + " on step " + q(x.step) + " differs";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> first_difference(const Project& a, const Project& b) {
  if (a.dialect != b.dialect) return std::string("dialects differ");
  if (a.pous.size() != b.pous.size())
    return std::to_string(a.pous.size()) + " POUs against " + std::to_string(b.pous.size());
  for (const auto& pa : a.pous) {
    const Pou* pb = b.find_pou(pa.name);
    if (!pb) return "POU " + q(pa.name) + " only in the first";
    if (auto d = compare_pous(pa, *pb)) return "POU " + q(pa.name) + ": " + *d;
  }
  return std::nullopt;
}

}  // namespace sfcv::model

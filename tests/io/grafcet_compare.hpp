#pragma once
// Structural comparison of two Grafcet projects for the round-trip tests (source locations and
// source_format aside). Returns a description of the first difference, empty when equal.

#include <string>
#include <vector>

#include "model/chart.hpp"
#include "model/expr.hpp"

namespace sfcv::test {

inline std::string grafcet_difference(const model::Project& a, const model::Project& b) {
  using model::to_st;
  auto str_list = [](const std::vector<std::string>& v) {
    std::string s = "{";
    for (const auto& x : v) s += x + ",";
    return s + "}";
  };
#define SFCV_DIFF(cond, what) \
  if (!(cond)) return std::string(what)
  SFCV_DIFF(a.name == b.name, "project name " + a.name + " vs " + b.name);
  SFCV_DIFF(a.dialect == b.dialect, "dialect");
  SFCV_DIFF(a.pous.size() == b.pous.size(), "number of POUs");
  for (std::size_t p = 0; p < a.pous.size(); ++p) {
    const auto& x = a.pous[p];
    const auto& y = b.pous[p];
    SFCV_DIFF(x.name == y.name && x.kind == y.kind, "POU " + x.name + " vs " + y.name);
    SFCV_DIFF(x.variables.size() == y.variables.size(), "number of variables");
    for (std::size_t i = 0; i < x.variables.size(); ++i) {
      const auto& u = x.variables[i];
      const auto& v = y.variables[i];
      SFCV_DIFF(u.name == v.name && u.direction == v.direction && u.type == v.type &&
                    u.initial == v.initial,
                "variable " + u.name + " vs " + v.name);
    }
    SFCV_DIFF(x.charts.size() == y.charts.size(), "number of charts");
    for (std::size_t c = 0; c < x.charts.size(); ++c) {
      const auto& u = x.charts[c];
      const auto& v = y.charts[c];
      SFCV_DIFF(u.name == v.name && u.parent_action == v.parent_action &&
                    u.macro_entry == v.macro_entry && u.macro_exit == v.macro_exit,
                "chart " + u.name + " vs " + v.name);
      SFCV_DIFF(u.steps.size() == v.steps.size(), "number of steps of " + u.name);
      for (std::size_t i = 0; i < u.steps.size(); ++i) {
        const auto& s = u.steps[i];
        const auto& t = v.steps[i];
        SFCV_DIFF(s.name == t.name && s.initial == t.initial && s.kind == t.kind &&
                      s.expansion == t.expansion && s.enclosed == t.enclosed &&
                      s.activation_link == t.activation_link,
                  "step " + u.name + "/" + s.name + " vs " + t.name);
      }
      SFCV_DIFF(u.transitions.size() == v.transitions.size(), "number of transitions of " + u.name);
      for (std::size_t i = 0; i < u.transitions.size(); ++i) {
        const auto& s = u.transitions[i];
        const auto& t = v.transitions[i];
        SFCV_DIFF(s.name == t.name && s.sources == t.sources && s.targets == t.targets &&
                      s.priority == t.priority && s.order == t.order,
                  "transition " + u.name + "/" + s.name + " " + str_list(s.sources) + "->" +
                      str_list(s.targets) + " vs " + t.name + " " + str_list(t.sources) + "->" +
                      str_list(t.targets));
        SFCV_DIFF(model::equal(s.guard, t.guard), "guard of " + u.name + "/" + s.name + ": " +
                                                      to_st(s.guard) + " vs " + to_st(t.guard));
      }
    }
    SFCV_DIFF(x.actions.size() == y.actions.size(), "number of actions");
    for (std::size_t i = 0; i < x.actions.size(); ++i)
      SFCV_DIFF(x.actions[i].name == y.actions[i].name && x.actions[i].kind == y.actions[i].kind &&
                    x.actions[i].variable == y.actions[i].variable,
                "action " + x.actions[i].name + " vs " + y.actions[i].name);
    SFCV_DIFF(x.associations.size() == y.associations.size(), "number of action associations");
    for (std::size_t i = 0; i < x.associations.size(); ++i) {
      const auto& s = x.associations[i];
      const auto& t = y.associations[i];
      SFCV_DIFF(s.chart == t.chart && s.step == t.step && s.action == t.action &&
                    s.qualifier == t.qualifier && s.duration_ms == t.duration_ms &&
                    s.indicator == t.indicator && model::equal(s.condition, t.condition),
                "action association " + s.chart + "/" + s.step + ":" + s.action + " if " +
                    (s.condition ? to_st(s.condition) : "-") + " vs " + t.chart + "/" + t.step +
                    ":" + t.action + " if " + (t.condition ? to_st(t.condition) : "-"));
    }
    SFCV_DIFF(x.stored_actions.size() == y.stored_actions.size(), "number of stored actions");
    for (std::size_t i = 0; i < x.stored_actions.size(); ++i) {
      const auto& s = x.stored_actions[i];
      const auto& t = y.stored_actions[i];
      SFCV_DIFF(s.chart == t.chart && s.step == t.step && s.when == t.when &&
                    model::equal(s.event, t.event) && s.variable == t.variable &&
                    model::equal(s.value, t.value),
                "stored action " + s.chart + "/" + s.step + ":" + s.variable +
                    ":=" + to_st(s.value) + " vs " + t.chart + "/" + t.step + ":" + t.variable +
                    ":=" + to_st(t.value));
    }
    SFCV_DIFF(x.forcing_orders.size() == y.forcing_orders.size(), "number of forcing orders");
    for (std::size_t i = 0; i < x.forcing_orders.size(); ++i) {
      const auto& s = x.forcing_orders[i];
      const auto& t = y.forcing_orders[i];
      SFCV_DIFF(s.chart == t.chart && s.step == t.step && s.target == t.target &&
                    s.kind == t.kind && s.situation == t.situation,
                "forcing order of " + s.chart + "/" + s.step);
    }
  }
#undef SFCV_DIFF
  return {};
}

}  // namespace sfcv::test

#include "model/validate.hpp"

// The validator's driver and its per-POU look-ups; the checks of each concept are in
// validate_{chart,hierarchy,actions,types,statements}.cpp (model/detail/validator.hpp).

#include <algorithm>
#include <array>
#include <cctype>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/detail/validator.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/networks.hpp"

namespace sfcv::model {

namespace detail {

Diagnostics Validator::run() {
  // An empty file (or one of comments only) is no model: nothing could be checked in it.
  // A Grafcet needs a step; an IEC 61131-3 POU without steps is a program that runs its body
  // (possibly empty) every cycle.
  bool any_program = project_.dialect != Dialect::Grafcet && !project_.pous.empty();
  for (const auto& pou : project_.pous) any_program = any_program || pou.has_sfc();
  if (!any_program)
    error(project_.where,
          project_.dialect == Dialect::Grafcet
              ? "the model has no chart (no step in any partial grafcet): nothing to check"
              : "the model has no chart and no POU: nothing to check");
  check_duplicates(project_.pous, "POU", project_.where);
  for (const auto& pou : project_.pous) check_pou(pou);
  std::stable_sort(out_.begin(), out_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.where.file != b.where.file) return a.where.file < b.where.file;
    if (a.where.line != b.where.line) return a.where.line < b.where.line;
    return a.where.column < b.where.column;
  });
  return std::move(out_);
}

int Validator::step_index(const Chart& chart, std::string_view name) const {
  poll_.tick_or_throw("validating the model");
  auto [it, fresh] = step_indices_.try_emplace(&chart);
  if (fresh)
    for (std::size_t i = 0; i < chart.steps.size(); ++i)
      it->second.try_emplace(to_upper(chart.steps[i].name), static_cast<int>(i));
  const auto found = it->second.find(to_upper(std::string(name)));
  return found == it->second.end() ? -1 : found->second;
}

void Validator::check_pou(const Pou& pou) {
  pou_ = &pou;
  chart_by_name_.clear();
  for (std::size_t i = 0; i < pou.charts.size(); ++i)
    chart_by_name_.emplace(to_upper(pou.charts[i].name), static_cast<int>(i));
  outside_warned_.clear();
  check_duplicates(pou.variables, "variable", pou.where);
  check_duplicates(pou.actions, "action", pou.where);
  const auto activated = charts_activated_by_grafcet_orders();
  for (std::size_t c = 0; c < pou.charts.size(); ++c)
    check_chart(pou.charts[c], activated.count(c) > 0);
  check_hierarchy();
  for (const auto& a : pou.actions) check_action(a);
  for (const auto& as : pou.associations) check_association(as);
  for (const auto& sa : pou.stored_actions) check_stored_action(sa);
  for (const auto& fo : pou.forcing_orders) check_forcing_order(fo);
  check_statements(pou.body, pou.where);
}

bool Validator::step_exists(std::string_view name) const {
  for (const auto& c : pou_->charts)
    if (has_step(c, name)) return true;
  return false;
}

const Chart* Validator::chart_of(const std::string& chart_name, const std::string& step,
                                 const SourceLocation& where, std::string_view what) {
  if (const Chart* c = find_chart(chart_name)) {
    if (!has_step(*c, step))
      error(where, std::string(what) + " names undeclared step " + quoted(step) +
                       (chart_name.empty() ? std::string() : " of chart " + quoted(chart_name)));
    return c;
  }
  if (chart_name.empty()) {
    const Chart* found = nullptr;
    int count = 0;
    for (const auto& c : pou_->charts)
      if (has_step(c, step)) {
        found = &c;
        ++count;
      }
    if (count == 1) return found;
    error(where, std::string(what) + " names " +
                     (count == 0 ? "undeclared step " : "ambiguous step ") + quoted(step));
    return nullptr;
  }
  error(where, std::string(what) + " names undeclared chart " + quoted(chart_name));
  return nullptr;
}

std::set<std::size_t> Validator::charts_activated_by_grafcet_orders() const {
  std::set<std::size_t> result;
  auto add = [&](const std::string& name) {
    const int i = chart_index(name);
    if (i >= 0) result.insert(static_cast<std::size_t>(i));
  };
  for (const auto& c : pou_->charts)
    for (const auto& s : c.steps) {
      if (s.kind == StepKind::MacroStep) add(s.expansion);
      if (s.kind == StepKind::Enclosing)
        for (const auto& e : s.enclosed) add(e);
    }
  for (const auto& fo : pou_->forcing_orders) add(fo.target);
  return result;
}

}  // namespace detail

Diagnostics validate(const Project& project, const Budget* budget) {
  return detail::Validator(project, budget).run();
}

}  // namespace sfcv::model

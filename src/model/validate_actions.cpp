// Validation of actions and what drives them: action bodies, associations and their
// qualifiers, driven variables, Grafcet stored actions and forcing orders.

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

namespace sfcv::model::detail {

void Validator::check_action(const Action& a) {
  const auto& here = at(a.where, pou_->where);
  switch (a.kind) {
    case ActionBodyKind::Variable:
      check_driven_variable(a.variable, here, "action " + quoted(a.name));
      break;
    case ActionBodyKind::Statements:
      check_statements(a.body, here);
      break;
    case ActionBodyKind::Chart:
      if (a.chart < 0 || static_cast<std::size_t>(a.chart) >= pou_->charts.size())
        error(here, "action " + quoted(a.name) + " has no chart body");
      break;
  }
}

void Validator::check_driven_variable(const std::string& name, const SourceLocation& here,
                                      const std::string& who) {
  const Variable* v = pou_->find_variable(name);
  if (!v) {
    error(here, who + " drives undeclared variable " + quoted(name));
    return;
  }
  if (v->type.kind != TypeKind::Bool)
    error(here,
          who + " drives variable " + quoted(name) + " of type " + v->type.name + ", not BOOL");
  else if (v->direction == VarDirection::Input)
    write_to_input(here, who + " drives input variable " + quoted(name));
}

void Validator::write_to_input(const SourceLocation& here, const std::string& what) {
  if (grafcet())
    error(here, what + " (inputs are read-only)");
  else
    warning(here, what + " (IEC 61131-3 inputs are read-only; CODESYS and TwinCAT accept it)");
}

void Validator::outside_model(const SourceLocation& here, const std::string& full,
                              const std::string& base) {
  if (!outside_warned_.insert(to_upper(full)).second) return;
  warning(here, quoted(full) + " refers to " + quoted(base) +
                    ", which this model does not declare (a global variable list or an "
                    "instance of a type sfcv does not model?): its value is unknown to sfcv");
}

void Validator::undeclared_action(const std::string& action, const SourceLocation& here,
                                  const std::string& who) {
  const auto dot = action.rfind('.');
  if (dot != std::string::npos) {
    const std::string owner = action.substr(0, dot);
    const std::string first = owner.substr(0, owner.find('.'));
    if (!pou_->find_variable(first)) {
      if (!outside_warned_.insert(to_upper(action)).second) return;
      warning(here, who + " activates action " + quoted(action) + " of " + quoted(owner) +
                        ", which this model does not declare (an instance of a type sfcv "
                        "does not model?): the action is not modelled");
      return;
    }
    // `inst.ACT` (TwinCAT, CODESYS): the step calls action ACT of the instance while the
    // association is active.
    bool unknown_type = false;
    const Pou* type = instance_type(owner, unknown_type);
    if (unknown_type) return;  // the compiler reports the missing type
    if (type && type->find_action(action.substr(dot + 1))) return;
    if (type) {
      error(here, who + " names action " + quoted(action) + ", but function block " + type->name +
                      " has no action " + quoted(action.substr(dot + 1)));
      return;
    }
  }
  error(here, who + " names undeclared action " + quoted(action));
}

void Validator::check_association(const ActionAssociation& as) {
  const auto& here = at(as.where, pou_->where);
  chart_of(as.chart, as.step, here, "action association");
  const std::string who = "step " + quoted(as.step);
  if (!pou_->find_action(as.action)) {
    // An action may be a Boolean variable used directly.
    if (pou_->find_variable(as.action))
      check_driven_variable(as.action, here, who);
    else
      undeclared_action(as.action, here, who);
  }
  if (is_timed(as.qualifier)) {
    if (!as.duration_ms && as.duration_variable.empty())
      error(here, "qualifier " + std::string(to_string(as.qualifier)) + " of action " +
                      quoted(as.action) + " needs a duration");
  }
  if (!as.duration_variable.empty()) {
    const Variable* v = pou_->find_variable(as.duration_variable);
    if (!v)
      error(here, "undeclared duration variable " + quoted(as.duration_variable));
    else if (v->type.kind != TypeKind::Time)
      error(here, "duration variable " + quoted(as.duration_variable) + " has type " +
                      v->type.name + ", not TIME");
  }
  if (!as.indicator.empty() && !pou_->find_variable(as.indicator))
    error(here, "undeclared indicator variable " + quoted(as.indicator));
  if (as.condition) expect_bool(as.condition, here, "the assignment condition");
}

void Validator::check_stored_action(const StoredAction& sa) {
  const auto& here = at(sa.where, pou_->where);
  chart_of(sa.chart, sa.step, here, "stored action");
  if (sa.when == StoredWhen::Event) {
    if (!sa.event)
      error(here, "stored action on event has no event");
    else
      expect_bool(sa.event, here, "the event");
  }
  const Variable* v = pou_->find_variable(sa.variable);
  if (!v) {
    error(here, "stored action on undeclared variable " + quoted(sa.variable));
    return;
  }
  if (v->direction == VarDirection::Input)
    write_to_input(here, "stored action assigns input variable " + quoted(sa.variable));
  // Once per variable, at its first stored action.
  const bool first_stored =
      &sa ==
      &*std::find_if(pou_->stored_actions.begin(), pou_->stored_actions.end(),
                     [&](const StoredAction& x) { return iequals(x.variable, sa.variable); });
  const bool continuous = std::any_of(
      pou_->associations.begin(), pou_->associations.end(),
      [&](const auto& as) { return iequals(pou_->assigned_variable(as), sa.variable); });
  if (first_stored && continuous)
    warning(here, "variable " + quoted(sa.variable) +
                      " is written by both continuous and stored actions: IEC 60848 gives a "
                      "variable one mode; sfcv reads it as 1 when either gives 1, and "
                      "output-conflicts reports where the two disagree");
  const auto target = value_type(v->type);
  if (!target) {
    error(here, "stored action assigns function block instance " + quoted(sa.variable));
    return;
  }
  if (!sa.value) {
    error(here, "stored action on " + quoted(sa.variable) + " has no value");
    return;
  }
  // Grafcet writes x := 1 / x := 0 for Boolean outputs: Ty::Bit fits BOOL.
  const Ty value = type_of(*sa.value, here);
  if (clash(value, *target))
    error(at(sa.value->where, here), "stored action assigns a " + ty_name(value) + " value to " +
                                         ty_name(*target) + " variable " + quoted(sa.variable));
}

void Validator::check_forcing_order(const ForcingOrder& fo) {
  const auto& here = at(fo.where, pou_->where);
  chart_of(fo.chart, fo.step, here, "forcing order");
  const Chart* target = find_chart(fo.target);
  if (!target) {
    error(here, "forcing order names undeclared partial grafcet " + quoted(fo.target));
    return;
  }
  if (fo.kind != ForcingKind::Situation) return;
  for (const auto& s : fo.situation)
    if (!has_step(*target, s))
      error(here, "forcing order names step " + quoted(s) + ", which partial grafcet " +
                      quoted(fo.target) + " does not declare");
}

}  // namespace sfcv::model::detail

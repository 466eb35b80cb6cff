// Validation of statements: assignment targets and function block calls in ST bodies.

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

std::optional<Ty> Validator::assignable(const std::string& target, const SourceLocation& here) {
  const auto dot = target.find('.');
  const std::string name = target.substr(0, dot);
  const Variable* v = pou_->find_variable(name);
  if (dot == std::string::npos) {
    if (!v) {
      error(here, "assignment to undeclared variable " + quoted(target));
      return std::nullopt;
    }
    if (v->direction == VarDirection::Input)
      write_to_input(here, "assignment to input variable " + quoted(target));
    if (auto t = value_type(v->type)) return t;
    error(here, "assignment to function block instance " + quoted(target));
    return std::nullopt;
  }
  const std::string member = target.substr(dot + 1);
  if (v && v->type.kind == TypeKind::FunctionBlock) {
    const auto m = fb_member(v->type.fb, member);
    if (!m) {
      error(here, "function block " + v->type.name + " has no member " + quoted(member));
      return std::nullopt;
    }
    if (!m->input) {
      error(here, "assignment to output " + quoted(target) + " of a function block instance");
      return std::nullopt;
    }
    return m->type;
  }
  if (v && v->type.kind == TypeKind::Int && all_digits(member)) {
    if (v->direction == VarDirection::Input)
      write_to_input(here, "assignment to input variable " + quoted(name));
    return Ty::Bool;
  }
  if (!v && step_exists(name)) {
    error(here, "assignment to step flag " + quoted(target) + " (step flags are read-only)");
    return std::nullopt;
  }
  if (!v && !pou_->find_action(name) && !project_.find_pou(name)) {
    outside_model(here, target, name);
    return std::nullopt;
  }
  error(here, "assignment to unknown " + quoted(target));
  return std::nullopt;
}

void Validator::check_statements(const StmtList& body, const SourceLocation& fallback) {
  for (const auto& sp : body) {
    if (!sp) continue;
    const Stmt& s = *sp;
    const auto& here = at(s.where, fallback);
    switch (s.kind) {
      case StmtKind::Assign: {
        const auto target = assignable(s.target, here);
        const Ty value = s.value ? type_of(*s.value, here) : Ty::Unknown;
        if (target && clash(value, *target))
          error(here, "assignment of a " + ty_name(value) + " value to " + ty_name(*target) + " " +
                          quoted(s.target));
        break;
      }
      case StmtKind::If:
        for (const auto& c : s.conditions) expect_bool(c, here, "the IF condition");
        for (const auto& b : s.bodies) check_statements(b, here);
        check_statements(s.else_body, here);
        break;
      case StmtKind::Case: {
        const Ty sel = s.value ? type_of(*s.value, here) : Ty::Unknown;
        if (clash(sel, Ty::Int))
          error(here, "CASE selector has type " + ty_name(sel) + ", expected an integer");
        for (const auto& b : s.bodies) check_statements(b, here);
        check_statements(s.else_body, here);
        break;
      }
      case StmtKind::FbCall:
        check_fb_call(s, here);
        break;
      case StmtKind::For: {
        const auto target = assignable(s.target, here);
        if (target && clash(*target, Ty::Int))
          error(here, "FOR control variable " + quoted(s.target) + " is not an integer");
        for (const auto* e : {&s.value, &s.limit, &s.step})
          if (*e && clash(type_of(**e, here), Ty::Int))
            error(here, "FOR bound " + quoted(to_st(*e)) + " is not an integer");
        for (const auto& b : s.bodies) check_statements(b, here);
        break;
      }
      case StmtKind::While:
      case StmtKind::Repeat:
        for (const auto& c : s.conditions)
          expect_bool(c, here,
                      s.kind == StmtKind::While ? "the WHILE condition" : "the UNTIL condition");
        for (const auto& b : s.bodies) check_statements(b, here);
        break;
      case StmtKind::Exit:
      case StmtKind::Continue:
      case StmtKind::Return:
        break;
    }
  }
}

void Validator::check_fb_call(const Stmt& s, const SourceLocation& here) {
  const Variable* v = pou_->find_variable(s.target);
  // `ACT();`: a call of an action of the POU (IEC 61131-3 lets a body call its actions).
  if (!v && s.arguments.empty() && pou_->find_action(s.target)) return;
  if (!v) {
    error(here, "call of undeclared function block instance " + quoted(s.target));
    return;
  }
  if (v->type.kind != TypeKind::FunctionBlock) {
    error(here, "call of " + quoted(s.target) + ", which is a " + v->type.name +
                    " variable, not a function block instance");
    return;
  }
  for (const auto& [param, value] : s.arguments) {
    const auto m = fb_member(v->type.fb, param);
    if (!m) {
      error(here, "function block " + v->type.name + " has no parameter " + quoted(param));
      continue;
    }
    if (!value) continue;
    const Ty t = type_of(*value, here);
    if (clash(t, m->type))
      error(at(value->where, here), "parameter " + param + " of " + v->type.name + " expects " +
                                        ty_name(m->type) + ", got " + ty_name(t));
  }
}

}  // namespace sfcv::model::detail

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
  // `s.x`, `a[2].y`: an element of a structure or array is a variable of that name.
  const Variable* element = pou_->find_variable(target);
  if (!element && !grafcet()) element = project_global(target);
  const auto dot = element ? std::string::npos : target.find('.');
  const std::string name = target.substr(0, dot);
  const Variable* v = element ? element : pou_->find_variable(name);
  if (!v && dot == std::string::npos && !grafcet()) v = project_global(name);
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
  if (v && v->type.kind == TypeKind::FunctionBlock && v->type.fb == StandardFb::None) {
    // `inst.x := v`, `a.b.x := v`: a variable of a user function block instance.
    const Ty t = resolve_path(split_path(target), *pou_, true, here, target);
    if (t == Ty::Unknown) return std::nullopt;
    return t;
  }
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
  if (!v && !pou_->find_action(name) && project_.find_pou(name)) {
    // `GVL.x := v`, `Main.x := v`: a variable of a global list or of another program.
    const Ty t = resolve_path(split_path(target), *pou_, true, here, target);
    if (t == Ty::Unknown) return std::nullopt;
    return t;
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

const Pou* Validator::instance_type(const std::string& owner, bool& unknown_type) const {
  unknown_type = false;
  const Pou* type = nullptr;
  const Pou* scope = pou_;
  std::size_t start = 0;
  // TwinCAT's absolute instance path `MAIN.XPPU.Crane.ACT_x()`, `MAIN.xPPU()`: from the
  // program it names.
  const auto first = owner.substr(0, owner.find('.'));
  if (!pou_->find_variable(first))
    if (const Pou* program = project_.find_pou(first);
        program && program->kind == PouKind::Program) {
      if (first.size() == owner.size()) return program;
      scope = program;
      start = first.size() + 1;
    }
  for (std::size_t from = start; scope;) {
    const auto d = owner.find('.', from);
    const Variable* v =
        scope->find_variable(owner.substr(from, d == std::string::npos ? d : d - from));
    if (!v || v->type.kind != TypeKind::FunctionBlock || v->type.fb != StandardFb::None)
      return nullptr;
    type = project_.find_pou(v->type.name);
    if (!type) {
      unknown_type = true;
      return nullptr;
    }
    scope = type;
    if (d == std::string::npos) break;
    from = d + 1;
  }
  return type;
}

const Variable* Validator::project_global(std::string_view name) const {
  for (const auto& q : project_.pous)
    for (const auto& v : q.variables)
      if (v.direction == VarDirection::Global && iequals(v.name, name)) return &v;
  return nullptr;
}

void Validator::check_fb_call(const Stmt& s, const SourceLocation& here) {
  if (const auto dot = s.target.rfind('.'); dot != std::string::npos) {
    // `inst.ACT();`: an action of a user function block instance (`a.b.ACT()` nested).
    const std::string owner = s.target.substr(0, dot), action = s.target.substr(dot + 1);
    bool unknown_type = false;
    const Pou* type = instance_type(owner, unknown_type);
    if (unknown_type) return;  // a type this model does not hold: the compiler reports it
    if (!type) {
      error(here, "call of " + quoted(s.target) + ": " + quoted(owner) +
                      " is not an instance of a user function block of this model");
      return;
    }
    if (const Variable* inner = type->find_variable(action);
        inner && inner->type.kind == TypeKind::FunctionBlock) {
      return;  // `a.b(...)`: a call of a nested instance, checked by the compiler
    }
    if (!s.outputs.empty())
      error(here, "call of action " + quoted(s.target) + " with an output binding '=>'");
    else if (!type->find_action(action))
      error(here, "function block " + type->name + " has no action " + quoted(action));
    else if (const auto io =
                 std::find_if(type->variables.begin(), type->variables.end(),
                              [](const Variable& m) { return m.direction == VarDirection::InOut; });
             io != type->variables.end())
      // Its VAR_IN_OUT would refer to the variable of the last call, which sfcv does not keep.
      error(here, "call of action " + quoted(s.target) + ": function block " + type->name +
                      " has the VAR_IN_OUT " + quoted(io->name) +
                      ", and actions of such instances are not modelled");
    // Inputs passed to an action call (CODESYS, TwinCAT: `inst.ACT(SFCReset := TRUE)`) are
    // assigned to the instance's VAR_INPUTs before the action runs: checked as an instance call.
    for (const auto& [param, value] : s.arguments) {
      const Variable* m = type->find_variable(param);
      if (!m || m->direction != VarDirection::Input)
        error(here, "function block " + type->name + " has no input " + quoted(param));
    }
    return;
  }
  const Variable* v = pou_->find_variable(s.target);
  // `ACT();`: a call of an action of the POU (IEC 61131-3 lets a body call its actions).
  if (!v && s.arguments.empty() && pou_->find_action(s.target)) return;
  if (!v) {
    // A user function called as a statement (`F(x := a, q => z);`): its inputs and outputs
    // are checked where it is compiled, as in an assignment `y := F(...)`.
    if (const Pou* callee = project_.find_pou(s.target);
        callee && callee->kind == PouKind::Function)
      return;
    error(here, "call of undeclared function block instance " + quoted(s.target));
    return;
  }
  if (v->type.kind != TypeKind::FunctionBlock) {
    error(here, "call of " + quoted(s.target) + ", which is a " + v->type.name +
                    " variable, not a function block instance");
    return;
  }
  if (v->type.fb == StandardFb::None) {  // a user function block: its own declarations
    const Pou* type = project_.find_pou(v->type.name);
    if (!type) return;  // the compiler reports the missing type
    for (const auto& [param, value] : s.arguments) {
      const Variable* m = type->find_variable(param);
      const bool in_out = m && m->direction == VarDirection::InOut;
      if (!m || (m->direction != VarDirection::Input && !in_out)) {
        error(here, "function block " + type->name + " has no input " + quoted(param));
        continue;
      }
      if (!value) continue;
      if (in_out) {
        // Passed by reference: the call reads and writes the variable itself (docs/semantics.md
        // 1.3c), so it must be one.
        if (value->kind != ExprKind::Name && value->kind != ExprKind::Member) {
          error(at(value->where, here), "VAR_IN_OUT " + param + " of " + type->name +
                                            " is bound to '" + to_st(*value) +
                                            "', which is no variable");
          continue;
        }
        assignable(value->kind == ExprKind::Name ? value->name : value->name + "." + value->member,
                   here);
      }
      const auto want = value_type(m->type);
      const Ty t = type_of(*value, here);
      if (want && clash(t, *want))
        error(at(value->where, here), "parameter " + param + " of " + type->name + " expects " +
                                          ty_name(*want) + ", got " + ty_name(t));
    }
    for (const auto& [out, var] : s.outputs) {
      const Variable* m = type->find_variable(out);
      if (!m || m->direction != VarDirection::Output)
        error(here, "function block " + type->name + " has no output " + quoted(out));
      else
        assignable(var, here);
    }
    return;
  }
  // `Q => y` (IEC 61131-3 formal call with output assignment): y := inst.Q after the call.
  for (const auto& [out, var] : s.outputs) {
    const auto m = fb_member(v->type.fb, out);
    if (!m || m->input) {
      error(here, "function block " + v->type.name + " has no output " + quoted(out));
      continue;
    }
    assignable(var, here);
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

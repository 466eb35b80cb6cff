// The IEC compiler's statements: ST bodies (assignments, IF, CASE, loops, action calls) into
// Program blocks.

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

Block Compiler::block(const PouScope& sc, const model::StmtList& body,
                      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& input_copies) {
  std::vector<std::uint32_t> items;
  for (const auto& [field, input] : input_copies) {
    Stmt copy;
    copy.op = SOp::Assign;
    copy.where = sc.pou->where.str();
    copy.target = field;
    Node n;
    n.op = Op::Input;
    n.a = input;
    copy.expr = node(n);
    p.stmts.push_back(copy);
    items.push_back(static_cast<std::uint32_t>(p.stmts.size() - 1));
  }
  for (const auto& s : body) items.push_back(stmt(sc, *s));
  Block b;
  b.first = static_cast<std::uint32_t>(p.block_items.size());
  b.count = static_cast<std::uint32_t>(items.size());
  p.block_items.insert(p.block_items.end(), items.begin(), items.end());
  return b;
}

// `F(x := a, q => z);`: the call compiled as the right side of an assignment without a target
// (so its `=>` outputs are bound exactly as in `y := F(x := a, q => z);`), its value dropped.
void Compiler::function_statement(const PouScope& sc, const model::Stmt& s, Stmt& out) {
  std::vector<std::string> names;
  std::vector<model::ExprPtr> args;
  for (const auto& [name, value] : s.arguments) {
    names.push_back(name);
    args.push_back(value);
  }
  model::Stmt as_assignment;
  as_assignment.where = s.where;
  as_assignment.value =
      model::make_formal_call(s.target, std::move(names), std::move(args), s.where);
  as_assignment.outputs = s.outputs;
  out.op = SOp::Eval;
  VT t;
  assignment_with_outputs = &as_assignment;
  out.expr = expr(sc, *as_assignment.value, -1, t);
  assignment_with_outputs = nullptr;
  outputs_taken_by = nullptr;  // it pointed at the local statement
}

std::uint32_t Compiler::stmt(const PouScope& sc, const model::Stmt& s) {
  reading(sc, s.where);
  Stmt out;
  out.where = s.where.str();
  switch (s.kind) {
    case model::StmtKind::Assign: {
      out.op = SOp::Assign;
      std::optional<Ref> found;
      if (auto it = sc.names.find(model::to_upper(s.target)); it != sc.names.end())
        found = it->second;
      else
        found = global_ref(model::to_upper(s.target));  // an unqualified global
      VT t;
      assignment_with_outputs = &s;
      out.expr = s.value ? expr(sc, *s.value, -1, t) : constant(0);
      assignment_with_outputs = nullptr;
      if (!s.outputs.empty() && outputs_taken_by != &s)
        error(s.where, "output arguments '=>' in '" + s.target +
                           " := " + (s.value ? model::to_st(*s.value) : std::string()) +
                           "': only a call of a user FUNCTION binds outputs");
      if (s.target.find('.') != std::string::npos && !found) {
        // `inst.x := v`, `a.b.x := v`, `Main.x := v` (`s.x` of a structure is a variable).
        if (const auto r = dotted(sc, s.target, s.where)) {
          if (r->kind != Ref::Field) {
            error(s.where, "assignment to '" + s.target + "', which is an input");
          } else {
            out.target = r->index;
            if (r->is_bool && s.value) t = bool_if_literal(*s.value, t);
            if ((t == VT::Bool) != r->is_bool)
              error(s.where, "type mismatch in the assignment to '" + s.target + "'");
          }
        }
      } else if (!found) {
        error(s.where, "assignment to unknown variable '" + s.target + "'");
      } else if (found->kind != Ref::Field) {
        error(s.where, "assignment to '" + s.target + "', which is " +
                           (found->kind == Ref::Input ? "an input" : "a function block instance"));
      } else {
        out.target = found->index;
        if (field_is_bool[out.target] && s.value) t = bool_if_literal(*s.value, t);
        if ((t == VT::Bool) != static_cast<bool>(field_is_bool[out.target]))
          error(s.where, "type mismatch in the assignment to '" + s.target + "'");
      }
      break;
    }
    case model::StmtKind::If: {
      out.op = SOp::If;
      std::vector<IfArm> arms;
      for (std::size_t i = 0; i < s.conditions.size(); ++i)
        arms.push_back(IfArm{bool_expr(sc, s.conditions[i], -1, s.where, "condition"),
                             block(sc, s.bodies[i])});
      out.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
      out.arm_count = static_cast<std::uint32_t>(arms.size());
      p.if_arms.insert(p.if_arms.end(), arms.begin(), arms.end());
      out.else_body = block(sc, s.else_body);
      break;
    }
    case model::StmtKind::Case: {
      out.op = SOp::Case;
      VT t;
      out.expr = s.value ? expr(sc, *s.value, -1, t) : constant(0);
      std::vector<CaseArm> arms;
      for (std::size_t i = 0; i < s.labels.size(); ++i) {
        CaseArm arm;
        arm.label_first = static_cast<std::uint32_t>(p.case_labels.size());
        arm.label_count = static_cast<std::uint32_t>(s.labels[i].size());
        p.case_labels.insert(p.case_labels.end(), s.labels[i].begin(), s.labels[i].end());
        arm.body = block(sc, s.bodies[i]);
        arms.push_back(arm);
      }
      out.arm_first = static_cast<std::uint32_t>(p.case_arms.size());
      out.arm_count = static_cast<std::uint32_t>(arms.size());
      p.case_arms.insert(p.case_arms.end(), arms.begin(), arms.end());
      out.else_body = block(sc, s.else_body);
      break;
    }
    case model::StmtKind::FbCall:
      if (s.target.find('.') != std::string::npos) {
        // `inst.ACT();`: the instance's action ACT (ST/FBD/LD body) runs at that point, on the
        // instance's variables (TwinCAT calls actions of instances this way).
        const auto parts = model::split_path(s.target);
        std::size_t used = 0;
        const auto si = path_scope(sc, parts, used);
        if (used + 1 == parts.size()) {
          // `a.b(...)`: a call of the nested instance b of a.
          const auto& names = scopes[si].names;
          if (auto it = names.find(model::to_upper(parts.back()));
              it != names.end() && it->second.kind == Ref::Instance) {
            instance_call(sc, s, it->second.index, out);
            break;
          }
        }
        if (const auto unit = unit_named(sc, s.target)) {
          // `inst.ACT(...)` of an SFC action run as a unit: one cycle of its chart.
          instance_call(sc, s, *unit, out);
          break;
        }
        const model::Action* act = nullptr;
        if (used + 1 == parts.size() && scopes[si].instance)
          act = scopes[si].pou->find_action(parts.back());
        out.op = SOp::If;
        if (!act) {
          error(s.where, "call of '" + s.target + "': not an action of a function block instance");
          break;
        }
        if (si != sc.owner && refuse_in_out_action(si, s)) break;
        if (act->kind != model::ActionBodyKind::Statements || act->body_unsupported) {
          error(s.where, act->body_unsupported
                             ? "call of action '" + s.target + "': its body is not modelled"
                             : sfc_action_call_error(*scopes[si].pou, *act, s.target));
          break;
        }
        const auto key = scopes[si].name + "." + model::to_upper(act->name);
        if (!inlining.insert(key).second) {
          error(s.where, "action '" + s.target + "' calls itself (recursion)");
          break;
        }
        const Block body = block(scopes[si], act->body);
        inlining.erase(key);
        if (!s.arguments.empty()) {
          // `inst.ACT(a := x)`: the instance's inputs are assigned, then the action runs.
          instance_call(sc, s, si, out, &body);
          break;
        }
        out.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
        out.arm_count = 1;
        p.if_arms.push_back(IfArm{constant(1), body});
        out.else_body = block(sc, {});
        break;
      }
      if (const auto unit = unit_named(sc, s.target)) {
        // `ACT();` in the body or an action of an instance whose SFC actions are units.
        instance_call(sc, s, *unit, out);
        break;
      }
      if (const auto* act = called_action(sc, s)) {
        // `ACT();` runs the action's statements at that point of the body (IEC 61131-3
        // allows calling an action of the same POU): an IF TRUE around them.
        out.op = SOp::If;
        if (act->kind != model::ActionBodyKind::Statements || act->body_unsupported) {
          const auto& owner = sc.unit ? *scopes[sc.owner].pou : *sc.pou;
          error(s.where, act->body_unsupported ? "call of action '" + act->name + "' of " +
                                                     sc.pou->name + ": its body is not modelled"
                                               : sfc_action_call_error(owner, *act, act->name));
          break;
        }
        if (!inlining.insert(model::to_upper(act->name)).second) {
          error(s.where, "action '" + act->name + "' calls itself (recursion)");
          break;
        }
        IfArm arm{constant(1), block(sc, act->body)};
        inlining.erase(model::to_upper(act->name));
        out.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
        out.arm_count = 1;
        p.if_arms.push_back(arm);
        out.else_body = block(sc, {});
        break;
      }
      if (auto it = sc.names.find(model::to_upper(s.target));
          it != sc.names.end() && it->second.kind == Ref::Instance) {
        instance_call(sc, s, it->second.index, out);
        break;
      }
      if (const auto* f = project.find_pou(s.target);
          f && f->kind == model::PouKind::Function && !sc.names.count(model::to_upper(s.target))) {
        function_statement(sc, s, out);
        break;
      }
      if (!s.outputs.empty()) {
        // A standard FB's `Q => y`: the call, then `y := inst.Q`, in one IF TRUE (the
        // statements made here are kept with the compiler: the program refers to them).
        model::StmtList expanded;
        auto call = std::make_shared<model::Stmt>(s);
        call->outputs.clear();
        expanded.push_back(std::move(call));
        for (const auto& [output, variable] : s.outputs)
          expanded.push_back(
              model::make_assign(variable, model::make_member(s.target, output, s.where), s.where));
        const auto& kept = expanded_calls.emplace_back(std::move(expanded));
        out.op = SOp::If;
        IfArm arm{constant(1), block(sc, kept)};
        out.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
        out.arm_count = 1;
        p.if_arms.push_back(arm);
        out.else_body = block(sc, {});
        break;
      }
      out.op = SOp::FbCall;
      fb_call(sc, s, out);
      break;
    case model::StmtKind::For:
    case model::StmtKind::While:
    case model::StmtKind::Repeat:
      loop(sc, s, out);
      break;
    case model::StmtKind::Exit:
    case model::StmtKind::Continue:
      out.op = s.kind == model::StmtKind::Exit ? SOp::Exit : SOp::Continue;
      if (loop_depth == 0)
        error(s.where, std::string(s.kind == model::StmtKind::Exit ? "EXIT" : "CONTINUE") +
                           " outside a loop");
      break;
    case model::StmtKind::Return:
      out.op = SOp::Return;
      if (!inlining.empty()) error(s.where, "RETURN in an action called from ST is not modelled");
      break;
  }
  p.stmts.push_back(out);
  return static_cast<std::uint32_t>(p.stmts.size() - 1);
}

void Compiler::loop(const PouScope& sc, const model::Stmt& s, Stmt& out) {
  out.op = SOp::Loop;
  ++loop_depth;
  out.body = block(sc, s.bodies.empty() ? model::StmtList{} : s.bodies[0]);
  --loop_depth;
  if (s.kind != model::StmtKind::For) {
    out.expr = bool_expr(sc, s.conditions.empty() ? nullptr : s.conditions[0], -1, s.where,
                         s.kind == model::StmtKind::While ? "WHILE condition" : "UNTIL condition");
    out.test_after = s.kind == model::StmtKind::Repeat;
    out.init = block(sc, {});
    out.step = block(sc, {});
    return;
  }
  // FOR i := a TO b BY c: i := a; WHILE (c > 0 ? i <= b : i >= b) DO body; i := i + c.
  // The TO bound is evaluated before each iteration; BY must be a non-zero constant.
  auto it = sc.names.find(model::to_upper(s.target));
  if (it == sc.names.end() || it->second.kind != Ref::Field || it->second.is_bool) {
    error(s.where, "FOR control variable '" + s.target + "' is not an integer variable of " +
                       sc.pou->name + " (inputs cannot be assigned)");
    out.expr = constant(0);
    return;
  }
  const std::int64_t by = s.step ? literal(*s.step).value_or(0) : 1;
  if (by == 0) {
    error(s.step ? (s.step->where.known() ? s.step->where : s.where) : s.where,
          "FOR loop: BY must be a non-zero integer constant");
    out.expr = constant(0);
    return;
  }
  const auto from = s.value ? literal(*s.value) : std::nullopt;
  const auto to = s.limit ? literal(*s.limit) : std::nullopt;
  if (from && to) {
    std::int64_t span = 0;
    const bool huge = __builtin_sub_overflow(*to, *from, &span) ||
                      span == std::numeric_limits<std::int64_t>::min();
    const auto count = huge                               ? kMaxLoopIterations + 1
                       : (by > 0 ? span >= 0 : span <= 0) ? span / by + 1
                                                          : 0;
    if (count > kMaxLoopIterations)
      error(s.where, "FOR loop runs " + (huge ? std::string("over 2^63") : std::to_string(count)) +
                         " iterations, more than the limit of " +
                         std::to_string(kMaxLoopIterations) + " sfcv unrolls");
  }
  const auto i = model::make_name(s.target, s.where);
  const auto by_expr = model::make_int(by < 0 ? -by : by, s.where);
  out.init = block(sc, {model::make_assign(s.target, s.value, s.where)});
  out.step = block(
      sc, {model::make_assign(
              s.target, model::make_binary(by > 0 ? ExprKind::Add : ExprKind::Sub, i, by_expr),
              s.where)});
  const auto cond = model::make_binary(by > 0 ? ExprKind::Le : ExprKind::Ge, i, s.limit, s.where);
  out.expr = bool_expr(sc, cond, -1, s.where, "FOR bound");
}

const model::Action* Compiler::called_action(const PouScope& sc, const model::Stmt& s) const {
  if (!s.arguments.empty() || sc.names.count(model::to_upper(s.target))) return nullptr;
  if (const auto* a = sc.pou->find_action(s.target)) return a;
  // A unit holds only the actions its steps name; the body of one may call any other.
  return sc.unit ? scopes[sc.owner].pou->find_action(s.target) : nullptr;
}

}  // namespace sfcv::semantics::iec::detail

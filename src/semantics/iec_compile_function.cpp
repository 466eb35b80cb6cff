// The IEC compiler's user FUNCTIONs (IEC 61131-3 2.5.1) written in ST: a function is compiled
// once, at its first call, into a Program::Function whose body is an ordinary Block of the
// function's own fields; each call is an Op::Call node, so a call may stand in any expression
// (bodies, conditions of IF and loops, transition guards) and both the machine and the circuit
// run the body at that point with their own statement rules.

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

std::optional<std::uint32_t> Compiler::function(const model::Pou& f,
                                                const model::SourceLocation& call) {
  const auto up = model::to_upper(f.name);
  if (const auto at = std::find(calling.begin(), calling.end(), &f); at != calling.end()) {
    std::string chain;
    for (auto it = at; it != calling.end(); ++it) chain += (*it)->name + " -> ";
    error(call, "function '" + f.name + "' calls itself (" + chain + f.name +
                    "): recursion is not modelled");
    return std::nullopt;
  }
  if (const auto it = functions.find(up); it != functions.end()) return it->second;
  if (calling.size() >= kMaxFunctionDepth) {
    error(call, "call of function '" + f.name + "' nested deeper than " +
                    std::to_string(kMaxFunctionDepth) + " function calls");
    return std::nullopt;
  }
  functions[up] = std::nullopt;  // refused until it compiles

  const bool was_ok = ok;
  ok = true;
  reject_foreign({&f});
  if (f.has_sfc() || !f.actions.empty())
    error(f.where, "function '" + f.name + "' has steps or actions (not IEC 61131-3)");
  if (!ok) {
    ok = false;
    return std::nullopt;
  }
  PouScope sc;
  sc.pou = &f;
  sc.name = f.name;
  sc.function = true;
  Function fn;
  fn.name = f.name;
  fn.where = "function " + f.name + " (" + f.where.str() + ")";
  bool has_result = false;
  for (const auto& v : f.variables) {
    const auto what = "'" + v.name + "' of function " + f.name;
    if (v.type.kind == TypeKind::FunctionBlock) {
      error(v.where, "function block instance " + what +
                         ": a function keeps no state between calls (use a FUNCTION_BLOCK)");
      continue;
    }
    const bool result =
        v.direction == model::VarDirection::Output && model::iequals(v.name, f.name);
    const auto var = model::to_upper(v.name);
    if (v.direction == model::VarDirection::External) {
      // The global of that name, read and written in place like the caller's own.
      if (const auto g = global_ref(var); g && g->is_bool == (v.type.kind == TypeKind::Bool))
        sc.names[var] = *g;
      else
        error(v.where, "VAR_EXTERNAL " + what + ": no VAR_GLOBAL of that name and type");
      continue;
    }
    const bool output = v.direction == model::VarDirection::Output && !result;
    const bool in_out = v.direction == model::VarDirection::InOut;
    if (v.direction != model::VarDirection::Input && v.direction != model::VarDirection::Local &&
        !result && !output && !in_out) {
      error(v.where, "VAR_GLOBAL " + what +
                         " is not modelled (only VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR and "
                         "VAR_TEMP)");
      continue;
    }
    // Every variable starts each call from its initial value: the function has no memory.
    const auto t = value_type(v.type);
    std::int64_t init = v.initial.value_or(0);
    if (!v.initial && (0 < t.lo || 0 > t.hi)) init = t.lo;
    if (init < t.lo || init > t.hi) {
      error(v.where, "initial value of " + what + " is outside its type's range");
      init = t.lo;
    }
    const bool is_bool = t.kind == TypeKind::Bool;
    const auto field =
        add_field(f.name + "." + v.name, FieldKind::Variable, t.lo, t.hi, init, is_bool);
    sc.names[var] = Ref{Ref::Field, field, is_bool};
    fn.fields.push_back(field);
    // A VAR_IN_OUT is an input copied in, and copied back after the body (like an output).
    if (v.direction == model::VarDirection::Input || in_out) fn.inputs.push_back(field);
    if (output) function_outputs[up][var] = field;
    if (result) {
      fn.result = field;
      has_result = true;
    }
  }
  if (!has_result) error(f.where, "function '" + f.name + "' has no result of a modelled type");
  if (!ok) {
    ok = false;
    return std::nullopt;
  }
  ok = was_ok;
  const auto index = static_cast<std::uint32_t>(p.functions.size());
  p.functions.push_back(std::move(fn));
  // The body is compiled once, outside any loop of the caller (EXIT in it is an error there).
  calling.push_back(&f);
  const int depth = loop_depth;
  loop_depth = 0;
  const Block body = block(sc, f.body);
  loop_depth = depth;
  calling.pop_back();
  p.functions[index].body = body;
  functions[up] = index;
  return index;
}

std::uint32_t Compiler::function_call(const PouScope& sc, const model::Expr& e, const model::Pou& f,
                                      int context, VT& type) {
  // The `=>` outputs of the assignment whose whole right side this call is, taken before
  // anything else compiles: the function's body may hold such assignments too.
  const model::Stmt* binding = assignment_with_outputs && assignment_with_outputs->value.get() == &e
                                   ? std::exchange(assignment_with_outputs, nullptr)
                                   : nullptr;
  if (binding) outputs_taken_by = binding;
  // The declared result type, also after a refusal (no second error about the same call).
  const auto* declared = f.find_variable(f.name);
  type = declared && declared->type.kind == TypeKind::Bool ? VT::Bool : VT::Int;
  const auto index = function(f, e.where);
  if (!index) return constant(0);
  std::vector<const model::Variable*> inputs;  // VAR_INPUT and VAR_IN_OUT, as fn.inputs
  for (const auto& v : f.variables)
    if (v.direction == model::VarDirection::Input || v.direction == model::VarDirection::InOut)
      inputs.push_back(&v);
  // Copied: compiling an argument may compile another function (and grow p.functions).
  const auto fields = p.functions[*index].inputs;
  type = field_is_bool[p.functions[*index].result] ? VT::Bool : VT::Int;
  auto fail = [&](const model::SourceLocation& where, const std::string& why) {
    error(where.known() ? where : e.where, "'" + model::to_st(e) + "': " + why);
    return constant(0);
  };
  // The argument of each input, in declaration order; a formal call may leave an input out,
  // which then has its initial value (IEC 61131-3 2.5.1.1).
  std::vector<const model::Expr*> given(inputs.size(), nullptr);
  if (e.arg_names.empty()) {
    if (e.args.size() != inputs.size())
      return fail(e.where, "function " + f.name + " has " + std::to_string(inputs.size()) +
                               " input(s), the call gives " + std::to_string(e.args.size()));
    for (std::size_t i = 0; i < inputs.size(); ++i) given[i] = e.args[i].get();
  } else {
    for (std::size_t a = 0; a < e.args.size(); ++a) {
      const auto& name = e.arg_names[a];
      const auto at = std::find_if(inputs.begin(), inputs.end(), [&](const model::Variable* v) {
        return model::iequals(v->name, name);
      });
      if (at == inputs.end())
        return fail(e.args[a]->where, "function " + f.name + " has no input '" + name + "'");
      const auto i = static_cast<std::size_t>(at - inputs.begin());
      if (given[i]) return fail(e.args[a]->where, "input '" + name + "' is given twice");
      given[i] = e.args[a].get();
    }
  }
  std::vector<std::uint32_t> kids;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto field = fields[i];
    if (!given[i]) {
      kids.push_back(constant(p.initial[field]));
      continue;
    }
    VT t;
    kids.push_back(expr(sc, *given[i], context, t));
    if (field_is_bool[field]) t = bool_if_literal(*given[i], t);
    if ((t == VT::Bool) != static_cast<bool>(field_is_bool[field]))
      fail(given[i]->where,
           "input '" + inputs[i]->name + "' of function " + f.name + " has the wrong type");
  }
  Node n;
  n.op = Op::Call;
  n.a = *index;
  // `y := F(io := v)`: v copied into io before the body (above, as an input) and back after it.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> copies;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (inputs[i]->direction == model::VarDirection::InOut)
      if (const auto dst = function_in_out(sc, e, f, *inputs[i], given[i], binding, copies))
        copies.emplace_back(fields[i], dst->index);
  if (binding && (!binding->outputs.empty() || !copies.empty())) {
    // `y := F(x, q => z)`: q copied into z after the body (docs/semantics.md 1.9.1).
    const auto& s = *binding;
    const auto& outputs = function_outputs[model::to_upper(f.name)];
    for (const auto& [output, var] : s.outputs) {
      const auto it = outputs.find(model::to_upper(output));
      if (it == outputs.end()) {
        fail(e.where, "function " + f.name + " has no VAR_OUTPUT '" + output + "'");
        continue;
      }
      if (model::iequals(var, s.target)) {
        fail(e.where, "output " + output + " is bound to '" + var +
                          "', which the assignment writes too (which one wins is not defined)");
        continue;
      }
      if (const auto dst = output_binding(sc, output, var, field_is_bool[it->second], e.where))
        copies.emplace_back(it->second, dst->index);
    }
    p.call_output_copies.push_back(std::move(copies));
    n.k = static_cast<std::int64_t>(p.call_output_copies.size());
  }
  return node(n, std::move(kids));
}

std::optional<Ref> Compiler::function_in_out(
    const PouScope& sc, const model::Expr& call, const model::Pou& f, const model::Variable& param,
    const model::Expr* value, const model::Stmt* binding,
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& bound) {
  const auto what = "VAR_IN_OUT '" + param.name + "' of function " + f.name;
  const auto where = value && value->where.known() ? value->where : call.where;
  auto refuse = [&](const std::string& why) {
    error(where, "'" + model::to_st(call) + "': " + what + " " + why);
    return std::nullopt;
  };
  if (!value) return refuse("is not bound (IEC 61131-3 requires it)");
  // The copy back needs one place after the body: the end of the assignment or statement.
  if (!binding)
    return refuse(
        "is bound only by a call that is the whole right side of an assignment or a statement");
  if (value->kind != model::ExprKind::Name && value->kind != model::ExprKind::Member)
    return refuse("is bound to '" + model::to_st(*value) + "', which is no variable");
  const std::string var =
      value->kind == model::ExprKind::Member ? value->name + "." + value->member : value->name;
  const auto ref = variable_ref(sc, var, where, what + " bound to unknown variable '" + var + "'");
  if (!ref) return std::nullopt;
  if (ref->kind != Ref::Field)
    return refuse("is bound to '" + var + "', which is " +
                  (ref->kind == Ref::Input ? "an input" : "a function block instance"));
  if (ref->is_bool != (param.type.kind == TypeKind::Bool))
    return refuse("is bound to '" + var + "', of another type");
  // The copy in and back is the call by reference only if, during the call, nothing reaches
  // the variable but the parameter (docs/semantics.md 1.9.1): refuse every way it could.
  const auto alias = [&](const std::string& why) {
    return refuse("is bound to '" + var + "', " + why +
                  " (the call by reference is modelled only without aliases)");
  };
  if (model::iequals(var, binding->target)) return alias("which the assignment writes too");
  for (const auto& [field, other] : bound)
    if (other == ref->index) return alias("which another VAR_IN_OUT of the call binds");
  for (const auto& [output, other] : binding->outputs)
    if (model::iequals(other, var)) return alias("which an output of the call is bound to");
  const auto& mentioned = names_mentioned(f);
  for (const auto& [name, field] : global_fields)
    if (field == ref->index && mentioned.count(name))
      return alias("a global variable that " + f.name + " names");
  for (const auto& pou : project.pous)
    if (pou.kind == model::PouKind::Program && mentioned.count(model::to_upper(pou.name)))
      return alias("and " + f.name + " names variables of program " + pou.name);
  return ref;
}

}  // namespace sfcv::semantics::iec::detail

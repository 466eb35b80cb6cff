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
    if (v.direction != model::VarDirection::Input && v.direction != model::VarDirection::Local &&
        !result && !output) {
      error(v.where,
            std::string(v.direction == model::VarDirection::InOut ? "VAR_IN_OUT" : "VAR_GLOBAL") +
                " " + what + " is not modelled (only VAR_INPUT, VAR_OUTPUT, VAR and VAR_TEMP)");
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
    if (v.direction == model::VarDirection::Input) fn.inputs.push_back(field);
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
  std::vector<const model::Variable*> inputs;
  for (const auto& v : f.variables)
    if (v.direction == model::VarDirection::Input) inputs.push_back(&v);
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
  if (binding) {
    // `y := F(x, q => z)`: q copied into z after the body (docs/semantics.md 1.9.1).
    const auto& s = *binding;
    const auto& outputs = function_outputs[model::to_upper(f.name)];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> copies;
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

}  // namespace sfcv::semantics::iec::detail

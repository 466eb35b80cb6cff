// The IEC compiler's user function block instances: each instance is a scope (and a Pou of the
// Program) with its own fields, standard FB instances, nested instances and copy of the FB's
// charts and actions; a call `inst(a := x, q => y);` assigns the inputs, runs one cycle of the
// instance (Call) and copies the outputs; `inst.x` names the instance's variables.

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

void Compiler::instantiate(std::uint32_t parent, const model::Variable& v, int depth,
                           std::vector<std::string>& types) {
  const std::string parent_name = scopes[parent].name;
  const model::Pou* type = project.find_pou(v.type.name);
  if (!type || type->kind != model::PouKind::FunctionBlock) {
    error(v.where, "'" + v.name + "' of " + parent_name + " has type '" + v.type.name +
                       "', which is no FUNCTION_BLOCK of this project (and no standard one)");
    return;
  }
  const auto up_type = model::to_upper(type->name);
  if (std::find(types.begin(), types.end(), up_type) != types.end()) {
    error(v.where, "instance '" + v.name + "' of " + type->name + " in " + parent_name +
                       ": function block " + type->name +
                       " contains an instance of itself (recursion is not modelled)");
    return;
  }
  if (depth > kMaxInstanceDepth) {
    error(v.where, "instance '" + v.name + "' of " + type->name + " in " + parent_name +
                       " is nested deeper than " + std::to_string(kMaxInstanceDepth) +
                       " function block instances");
    return;
  }
  reject_foreign({type});  // what it writes: collected with every POU (variables())

  const auto si = static_cast<std::uint32_t>(scopes.size());
  {
    PouScope sc;
    sc.pou = instance_view(type);
    sc.index = si;
    sc.owner = si;
    sc.name = parent_name + "." + v.name;
    sc.alias = scopes[parent].instance ? scopes[parent].alias + "." + v.name : v.name;
    sc.instance = true;
    scopes.push_back(std::move(sc));
  }
  scopes[parent].names[model::to_upper(v.name)] = Ref{Ref::Instance, si, false};
  p.has_instances = true;
  types.push_back(up_type);
  for (const auto& w : type->variables) {
    const auto up = model::to_upper(w.name);
    if (w.type.kind == TypeKind::FunctionBlock) {
      if (w.type.fb == StandardFb::None)
        instantiate(si, w, depth + 1, types);
      else
        make_fb(si, w);
      continue;
    }
    switch (w.direction) {
      case model::VarDirection::InOut:
        // A field of the instance that each call loads from the variable it binds and copies
        // back after the instance ran (docs/semantics.md 1.3c).
        scopes[si].in_outs.push_back(w.name);
        break;
      case model::VarDirection::External:
        // VAR_EXTERNAL: the global of that name, shared with everyone.
        if (const auto g = global_ref(up); g && g->is_bool == (w.type.kind == TypeKind::Bool)) {
          scopes[si].names[up] = *g;
        } else {
          error(w.where, "VAR_EXTERNAL '" + w.name + "' of function block " + type->name +
                             ": no VAR_GLOBAL of that name and type in the project");
        }
        continue;
      case model::VarDirection::Global:
        error(w.where, "VAR_GLOBAL '" + w.name + "' declared inside function block " + type->name +
                           " (not modelled)");
        continue;
      default:
        break;
    }
    const auto t = value_type(w.type);
    if (w.direction != model::VarDirection::Input && w.address.rfind("%I", 0) == 0) {
      // `x AT %I*` (TwinCAT, CODESYS): the I/O configuration maps it to a sensor, so it is an
      // input of the plant, one per instance; code that writes it sees its write until the
      // instance's next cycle reads the input again (as for a program's %I variable).
      const std::string display = scopes[si].name + "." + w.name;
      const auto in = add_input(display, t, false);
      if (!written.count(up_type + "|" + up)) {
        scopes[si].names[up] = Ref{Ref::Input, in, t.kind == TypeKind::Bool};
        continue;
      }
      const auto f = add_field(display, FieldKind::Variable, t.lo, t.hi,
                               std::clamp<std::int64_t>(0, t.lo, t.hi), t.kind == TypeKind::Bool);
      scopes[si].names[up] = Ref{Ref::Field, f, t.kind == TypeKind::Bool};
      scopes[si].input_copies.emplace_back(f, in);
      continue;
    }
    // Every other variable (VAR_INPUT, VAR_OUTPUT, VAR, VAR_TEMP) is a field of the instance:
    // its inputs are set by the caller, not read from the plant.

    std::int64_t init = w.initial.value_or(0);
    if (!w.initial && (0 < t.lo || 0 > t.hi)) init = t.lo;
    if (init < t.lo || init > t.hi) {
      error(w.where, "initial value of '" + w.name + "' is outside its type's range");
      init = t.lo;
    }
    const auto& sc = scopes[si];
    const std::string display = sc.name + "." + w.name;
    const bool is_bool = t.kind == TypeKind::Bool;
    if (is_free(sc, w)) {  // no POU of the run writes it: any value each cycle (1.8)
      scopes[si].names[up] = Ref{Ref::Input, add_input(display, t, false), is_bool};
      continue;
    }
    const auto f = add_field(display, FieldKind::Variable, t.lo, t.hi, init, is_bool);
    declared_fields.push_back({f, si, &w});
    scopes[si].names[up] = Ref{Ref::Field, f, is_bool};
    Observable o;
    o.name = display;
    o.aliases = {scopes[si].alias + "." + w.name};
    o.kind = ObservableKind::Variable;
    o.type = t;
    o.is_output = false;
    p.observables.push_back(std::move(o));
    p.observable_refs.push_back(ObservableRef{ObservableKind::Variable, f});
  }
  make_units(si, *type);
  types.pop_back();
}

std::uint32_t Compiler::path_scope(const PouScope& sc, const std::vector<std::string>& parts,
                                   std::size_t& used) const {
  used = 0;
  std::uint32_t cur = sc.index;
  if (sc.function) return cur;  // a function names only its own variables
  if (parts.size() >= 2 && !sc.names.count(model::to_upper(parts[0]))) {
    // `Main.x`: a variable of a program of the same cycle.
    for (const auto& other : scopes)
      if (!other.instance && model::iequals(other.pou->name, parts[0])) {
        cur = other.index;
        used = 1;
        break;
      }
  }
  while (used + 1 < parts.size()) {
    const auto& names = scopes[cur].names;
    auto it = names.find(model::to_upper(parts[used]));
    if (it == names.end() || it->second.kind != Ref::Instance) break;
    cur = it->second.index;
    ++used;
  }
  return cur;
}

std::optional<Ref> Compiler::dotted(const PouScope& sc, const std::string& path,
                                    const model::SourceLocation& where) {
  const auto parts = model::split_path(path);
  std::size_t used = 0;
  const auto si = path_scope(sc, parts, used);
  if (used == 0 || used + 1 != parts.size()) {
    error(where, "'" + path + "' names no variable sfcv models (not a variable of a function " +
                     "block instance or of a program of this project)");
    return std::nullopt;
  }
  const auto& names = scopes[si].names;
  auto it = names.find(model::to_upper(parts.back()));
  if (it == names.end()) {
    error(where, "'" + path + "': " + scopes[si].name + " has no variable '" + parts.back() + "'");
    return std::nullopt;
  }
  if (it->second.kind == Ref::Instance || it->second.kind == Ref::FbInst) {
    error(where, "'" + path + "' is a function block instance, not a variable");
    return std::nullopt;
  }
  if (refuse_in_out_member(sc, si, parts.back(), path, where)) return std::nullopt;
  return it->second;
}

void Compiler::instance_call(const PouScope& sc, const model::Stmt& s, std::uint32_t inst,
                             Stmt& out, const Block* inline_body) {
  // An IF TRUE around: the input assignments, the Call, the output copies.
  const auto& callee = scopes[inst];
  std::vector<std::uint32_t> items;
  auto push = [&](Stmt st) {
    p.stmts.push_back(std::move(st));
    items.push_back(static_cast<std::uint32_t>(p.stmts.size() - 1));
  };
  // VAR_IN_OUT: (field of the instance, the variable bound), copied back after the call.
  std::vector<std::pair<std::uint32_t, Ref>> copy_back;
  if (callee.unit && sc.owner != callee.owner && refuse_in_out_action(inst, s)) return;
  for (const auto& name : callee.in_outs)
    if (std::none_of(s.arguments.begin(), s.arguments.end(),
                     [&](const auto& a) { return model::iequals(a.first, name) && a.second; }))
      error(s.where, "the call of '" + s.target + "' does not bind its VAR_IN_OUT '" + name +
                         "' (IEC 61131-3 requires it at every call)");
  for (const auto& [param, value] : s.arguments) {
    const auto* var = callee.pou->find_variable(param);
    auto it = callee.names.find(model::to_upper(param));
    const bool in_out = var && var->direction == model::VarDirection::InOut;
    if (!var || (var->direction != model::VarDirection::Input && !in_out) ||
        it == callee.names.end() || it->second.kind != Ref::Field) {
      error(s.where, "'" + s.target + "' (" + callee.pou->name + ") has no input '" + param + "'");
      continue;
    }
    if (in_out && value) {
      if (auto bound = in_out_variable(sc, s, inst, param, *value, copy_back))
        copy_back.emplace_back(it->second.index, *bound);
      else
        continue;
    }
    Stmt a;
    a.op = SOp::Assign;
    a.where = s.where.str();
    a.target = it->second.index;
    VT t;
    a.expr = value ? expr(sc, *value, -1, t) : constant(0);
    if (value && it->second.is_bool) t = bool_if_literal(*value, t);
    if ((t == VT::Bool) != it->second.is_bool)
      error(value && value->where.known() ? value->where : s.where,
            "input " + param + " of '" + s.target + "' has the wrong type");
    push(std::move(a));
  }
  Stmt call;
  call.where = s.where.str();
  if (inline_body) {
    call.op = SOp::If;
    call.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
    call.arm_count = 1;
    p.if_arms.push_back(IfArm{constant(1), *inline_body});
  } else {
    call.op = SOp::Call;
    call.target = inst;
  }
  push(std::move(call));
  // Copied back before the outputs: `inst(io := x, q => x)` leaves q in x, as the call by
  // reference does.
  for (const auto& [field, bound] : copy_back) {
    Stmt a;
    a.op = SOp::Assign;
    a.where = s.where.str();
    a.target = bound.index;
    Node n;
    n.op = Op::Field;
    n.a = field;
    a.expr = node(n);
    push(std::move(a));
  }
  for (const auto& [output, var] : s.outputs) {
    const auto* decl = callee.pou->find_variable(output);
    auto it = callee.names.find(model::to_upper(output));
    // (An output that the instance never writes may be a free input, docs/semantics.md 1.8.)
    if (!decl || decl->direction != model::VarDirection::Output || it == callee.names.end() ||
        (it->second.kind != Ref::Field && it->second.kind != Ref::Input)) {
      error(s.where,
            "'" + s.target + "' (" + callee.pou->name + ") has no output '" + output + "'");
      continue;
    }
    const auto dst = output_binding(sc, output, var, it->second.is_bool, s.where);
    if (!dst) continue;
    Stmt a;
    a.op = SOp::Assign;
    a.where = s.where.str();
    a.target = dst->index;
    Node n;
    n.op = it->second.kind == Ref::Field ? Op::Field : Op::Input;
    n.a = it->second.index;
    a.expr = node(n);
    push(std::move(a));
  }
  Block b;
  b.first = static_cast<std::uint32_t>(p.block_items.size());
  b.count = static_cast<std::uint32_t>(items.size());
  p.block_items.insert(p.block_items.end(), items.begin(), items.end());
  out.op = SOp::If;
  out.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
  out.arm_count = 1;
  p.if_arms.push_back(IfArm{constant(1), b});
  out.else_body = Block{};
}

std::optional<Ref> Compiler::variable_ref(const PouScope& sc, const std::string& var,
                                          const model::SourceLocation& where,
                                          const std::string& unknown) {
  if (var.find('.') != std::string::npos) return dotted(sc, var, where);
  if (auto d = sc.names.find(model::to_upper(var)); d != sc.names.end()) return d->second;
  if (auto g = global_ref(model::to_upper(var))) return g;
  error(where, unknown);
  return std::nullopt;
}

std::optional<Ref> Compiler::output_binding(const PouScope& sc, const std::string& output,
                                            const std::string& var, bool is_bool,
                                            const model::SourceLocation& where) {
  const auto dst = variable_ref(sc, var, where, "output binding to unknown variable '" + var + "'");
  if (!dst) return std::nullopt;
  if (dst->kind != Ref::Field) {
    error(where, "output binding to '" + var + "', which is " +
                     (dst->kind == Ref::Input ? "an input" : "a function block instance"));
    return std::nullopt;
  }
  if (dst->is_bool != is_bool) {
    error(where, "type mismatch in the output binding " + output + " => " + var);
    return std::nullopt;
  }
  return dst;
}

const std::set<std::string>& Compiler::names_mentioned(const model::Pou& type) {
  const auto key = model::to_upper(type.name);
  if (auto it = mentioned_by_type.find(key); it != mentioned_by_type.end()) return it->second;
  auto& names = mentioned_by_type[key];  // empty while it is filled: recursion stops here
  std::set<std::string> found;
  auto path = [&](const std::string& text) {
    for (const auto& part : model::split_path(text)) found.insert(model::to_upper(part));
  };
  // What a called user function names, the caller names too (it runs inside the call).
  auto called = [&](const std::string& name) {
    if (const auto* f = project.find_pou(name); f && f->kind == model::PouKind::Function) {
      const auto& more = names_mentioned(*f);
      found.insert(more.begin(), more.end());
    }
  };
  std::function<void(const model::Expr&)> expr = [&](const model::Expr& e) {
    if (e.kind == model::ExprKind::Name || e.kind == model::ExprKind::Member ||
        e.kind == model::ExprKind::Index)
      path(e.name);
    if (e.kind == model::ExprKind::Call) called(e.name);
    for (const auto& a : e.args)
      if (a) expr(*a);
  };
  std::function<void(const model::StmtList&)> body = [&](const model::StmtList& list) {
    for (const auto& st : list) {
      path(st->target);
      if (st->kind == model::StmtKind::FbCall) called(st->target);
      for (const auto* e : {&st->value, &st->limit, &st->step})
        if (*e) expr(**e);
      for (const auto& c : st->conditions) expr(*c);
      for (const auto& i : st->target_indices) expr(*i);
      for (const auto& [param, value] : st->arguments)
        if (value) expr(*value);
      for (const auto& [output, variable] : st->outputs) path(variable);
      for (const auto& b : st->bodies) body(b);
      body(st->else_body);
    }
  };
  body(type.body);
  for (const auto& a : type.actions) body(a.body);
  for (const auto& c : type.charts)
    for (const auto& t : c.transitions) expr(*t.guard);
  for (const auto& as : type.associations) path(as.action);
  for (const auto& v : type.variables) {
    found.insert(model::to_upper(v.name));
    if (v.type.kind == TypeKind::FunctionBlock && v.type.fb == StandardFb::None)
      if (const auto* inner = project.find_pou(v.type.name)) {
        const auto& more = names_mentioned(*inner);
        found.insert(more.begin(), more.end());
      }
  }
  names = std::move(found);
  return names;
}

bool Compiler::refuse_in_out_member(const PouScope& sc, std::uint32_t si, const std::string& name,
                                    const std::string& path, const model::SourceLocation& where) {
  if (si == sc.owner || std::none_of(scopes[si].in_outs.begin(), scopes[si].in_outs.end(),
                                     [&](const auto& n) { return model::iequals(n, name); }))
    return false;
  // By reference, it is whatever variable the running call binds: outside a call, none.
  error(where, "'" + path + "' is a VAR_IN_OUT of " + scopes[si].pou->name +
                   ", which only the instance itself reads and writes");
  return true;
}

bool Compiler::refuse_in_out_action(std::uint32_t inst, const model::Stmt& s) {
  const auto& owner = scopes[scopes[inst].unit ? scopes[inst].owner : inst];
  if (owner.in_outs.empty()) return false;
  // Its VAR_IN_OUT would refer to the variable of the last call, which is not kept.
  error(s.where, "call of '" + s.target + "': " + owner.pou->name + " has the VAR_IN_OUT '" +
                     owner.in_outs.front() +
                     "', and actions of such instances run from outside are not modelled");
  return true;
}

std::optional<Ref> Compiler::in_out_variable(
    const PouScope& sc, const model::Stmt& s, std::uint32_t inst, const std::string& param,
    const model::Expr& value, const std::vector<std::pair<std::uint32_t, Ref>>& bound) {
  const auto& callee = scopes[inst];
  const std::string var =
      value.kind == model::ExprKind::Member ? value.name + "." + value.member : value.name;
  const auto where = value.where.known() ? value.where : s.where;
  if (value.kind != model::ExprKind::Name && value.kind != model::ExprKind::Member) {
    error(where, "VAR_IN_OUT " + param + " of '" + s.target + "' is bound to '" +
                     model::to_st(value) + "', which is no variable");
    return std::nullopt;
  }
  const auto ref = variable_ref(sc, var, where,
                                "VAR_IN_OUT " + param + " bound to unknown variable '" + var + "'");
  if (!ref) return std::nullopt;
  if (ref->kind != Ref::Field) {
    error(where, "VAR_IN_OUT " + param + " of '" + s.target + "' is bound to '" + var +
                     "', which is " +
                     (ref->kind == Ref::Input ? "an input" : "a function block instance"));
    return std::nullopt;
  }
  if (ref->is_bool != callee.names.at(model::to_upper(param)).is_bool) {
    error(where, "VAR_IN_OUT " + param + " of '" + s.target + "' is bound to '" + var +
                     "', of another type");
    return std::nullopt;
  }
  // The copy in and back is the call by reference only if, during the call, nothing reaches
  // the variable but the parameter (docs/semantics.md 1.3c): refuse every way it could.
  auto alias = [&](const std::string& why) {
    error(where, "VAR_IN_OUT " + param + " of '" + s.target + "' is bound to '" + var + "', " +
                     why + " (the call by reference is modelled only without aliases)");
    return std::nullopt;
  };
  for (const auto& [field, other] : bound)
    if (other.index == ref->index) return alias("which another VAR_IN_OUT of the call binds");
  const auto parts = model::split_path(var);
  if (parts.size() > 1 && model::iequals(parts.front(), s.target))
    return alias("a variable of the instance itself");
  const auto& mentioned = names_mentioned(*callee.pou);
  for (const auto& [name, field] : global_fields)
    if (field == ref->index && mentioned.count(name))
      return alias("a global variable that " + callee.pou->name + " names");
  for (const auto& pou : project.pous)
    if (pou.kind == model::PouKind::Program && mentioned.count(model::to_upper(pou.name)))
      return alias("and " + callee.pou->name + " names variables of program " + pou.name);
  return ref;
}

void Compiler::instance_commits() {
  for (std::uint32_t pi = 0; pi < p.pous.size(); ++pi) {
    auto& pou = p.pous[pi];
    if (!pou.instance) continue;
    for (auto c : pou.charts)
      for (auto s : p.charts[c].steps) {
        const auto& st = p.steps[s];
        pou.commit.push_back(st.ready);
        if (st.t_field != kNone) pou.commit.push_back(static_cast<std::uint32_t>(st.t_field));
      }
    for (const auto& a : p.actions) {
      if (a.pou != pi) continue;
      pou.commit.push_back(a.active);
      if (a.stored != kNone) pou.commit.push_back(static_cast<std::uint32_t>(a.stored));
      if (a.final_call != kNone) pou.commit.push_back(static_cast<std::uint32_t>(a.final_call));
      for (auto x : a.assocs) {
        const auto& as = p.assocs[x];
        if (as.latch != kNone) pou.commit.push_back(static_cast<std::uint32_t>(as.latch));
        if (as.timer != kNone)
          pou.commit.push_back(p.timers[static_cast<std::size_t>(as.timer)].field);
      }
    }
  }
}

}  // namespace sfcv::semantics::iec::detail

// Compiles a model::Project into the flat Program the IEC 61131-3 machine runs: selects the
// POUs, connects their variables, lays out the state, resolves names and compiles guards and
// action bodies. Anything the semantics cannot model faithfully is an Error diagnostic. The
// concept-specific parts are in iec_compile_{expr,stmt,fb,chart}.cpp
// (semantics/detail/iec_compiler.hpp).

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "model/errors.hpp"
#include "model/names.hpp"
#include "model/suggest.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec {

namespace detail {

void Compiler::error(const model::SourceLocation& where, std::string msg) {
  diags.push_back({model::Severity::Error, where, std::move(msg)});
  ok = false;
}

void Compiler::warning(const model::SourceLocation& where, std::string msg) {
  diags.push_back({model::Severity::Warning, where, std::move(msg)});
}

void Compiler::poll_deadline() {
  if ((++polls & 1023U) != 0 || !p.options.deadline) return;
  if (std::chrono::steady_clock::now() > *p.options.deadline)
    throw LimitReached(Limit::Time, "time limit reached while building the system");
}

std::uint32_t Compiler::add_field(std::string name, FieldKind kind, std::int64_t lo,
                                  std::int64_t hi, std::int64_t init, bool is_bool) {
  const auto f = p.layout.add_field(name, kind, lo, hi);
  p.field_lo.push_back(lo);
  p.field_hi.push_back(hi);
  p.initial.push_back(init);
  p.field_names.push_back(std::move(name));
  field_is_bool.push_back(is_bool);
  return f;
}

std::uint32_t Compiler::add_input(std::string name, model::Type type, bool pseudo) {
  p.inputs.push_back(InputVariable{std::move(name), std::move(type), pseudo});
  return static_cast<std::uint32_t>(p.inputs.size() - 1);
}

std::vector<const model::Pou*> Compiler::select() {
  std::vector<const model::Pou*> out;
  if (!p.options.pous.empty()) {
    for (const auto& name : p.options.pous) {
      const auto* pou = project.find_pou(name);
      if (!pou) {
        std::string avail;
        std::vector<std::string> names;
        for (const auto& q : project.pous) {
          avail += (avail.empty() ? "" : ", ") + q.name;
          names.push_back(q.name);
        }
        const auto guess = model::closest_name(name, names);
        error(project.where, "no POU named '" + name + "'" +
                                 (guess.empty() ? " (the model has: " + avail + ")"
                                                : ": did you mean '" + guess + "'?"));
        continue;
      }
      if (pou->kind == model::PouKind::Function) {
        error(project.where, "'" + name + "' is a FUNCTION: it runs where a program calls it");
        continue;
      }
      out.push_back(pou);
    }
    return out;
  }
  // Without --pou: every PROGRAM in document order (a PLC task runs its programs one after
  // another in one cycle), when all of them can be modelled; else, as before, the one POU
  // with an SFC body (a function block then runs alone, its inputs free).
  // The POU whose body sfcv does not model among `q` and the function block types it
  // instantiates, recursively (null: none).
  std::set<const model::Pou*> visited;
  std::function<const model::Pou*(const model::Pou&)> unmodelled = [&](const model::Pou& q) {
    if (!visited.insert(&q).second) return static_cast<const model::Pou*>(nullptr);
    if (q.body_unsupported) return &q;
    for (const auto& v : q.variables) {
      if (v.type.kind != model::TypeKind::FunctionBlock || v.type.fb != model::StandardFb::None)
        continue;
      if (const auto* type = project.find_pou(v.type.name))
        if (const auto* found = unmodelled(*type)) return found;
    }
    return static_cast<const model::Pou*>(nullptr);
  };
  std::vector<const model::Pou*> programs, sfc_programs, sfc_others;
  std::vector<std::pair<const model::Pou*, const model::Pou*>> not_run;  // program, why
  for (const auto& q : project.pous) {
    const bool runs = q.has_sfc() || !q.body.empty() || q.body_unsupported;
    if (q.kind == model::PouKind::Program && runs) {
      programs.push_back(&q);
      visited.clear();
      if (const auto* why = unmodelled(q)) not_run.emplace_back(&q, why);
    }
    if (q.has_sfc()) (q.kind == model::PouKind::Program ? sfc_programs : sfc_others).push_back(&q);
  }
  if (!programs.empty() && not_run.empty()) return programs;
  const auto& cands = sfc_programs.empty() ? sfc_others : sfc_programs;
  if (cands.size() == 1) {
    for (const auto& [q, why] : not_run)
      diags.push_back({model::Severity::Note, q->where,
                       "program '" + q->name + "' is not run (" +
                           (why == q ? std::string("its body is not modelled")
                                     : "it runs an instance of '" + why->name +
                                           "', whose body is not modelled") +
                           "); '" + cands.front()->name + "' runs alone"});
    return {cands.front()};
  }
  if (cands.empty()) {
    std::string list;
    for (const auto* q : programs) {
      list += (list.empty() ? "" : ", ") + q->name;
      // The importer's reason, so that the error says what to change even under --quiet.
      if (q->body_unsupported && !q->unsupported_reason.empty())
        list += " [" + q->unsupported_reason + "]";
    }
    error(project.where, programs.empty()
                             ? "the model has no PROGRAM and no POU with an SFC body: choose the "
                               "POU(s) to run with --pou"
                             : "no program can be run (" + list +
                                   ": a body sfcv does not model); choose other POU(s) with --pou");
  } else {
    std::string list, why_not;
    for (const auto* q : cands) list += (list.empty() ? "" : ", ") + q->name;
    // The program(s) the project would run, and why they cannot (xPPU 17: MAIN's body was
    // not modelled), so that the user fixes that rather than picking a POU blindly.
    for (const auto& [q, why] : not_run)
      why_not +=
          "program '" + q->name + "' cannot be run (" +
          (why == q
               ? "its body is not modelled" +
                     (q->unsupported_reason.empty() ? std::string() : ": " + q->unsupported_reason)
               : "it runs an instance of '" + why->name + "', whose body is not modelled") +
          "); ";
    error(project.where, why_not + "several POUs have an SFC body (" + list +
                             "): choose the one(s) to run with --pou");
  }
  return out;
}

bool Compiler::is_global_list(const model::Pou& pou) {
  if (pou.kind != model::PouKind::Program || !pou.body.empty() || !pou.charts.empty() ||
      !pou.actions.empty() || pou.body_unsupported || pou.variables.empty())
    return false;
  return std::all_of(pou.variables.begin(), pou.variables.end(), [](const model::Variable& v) {
    return v.direction == model::VarDirection::Global;
  });
}

std::optional<Ref> Compiler::global_ref(const std::string& upper_name) const {
  auto it = global_fields.find(upper_name);
  if (it == global_fields.end()) {
    const auto in = global_inputs.find(upper_name);
    if (in == global_inputs.end()) return std::nullopt;
    return Ref{Ref::Input, in->second, p.inputs[in->second].type.kind == TypeKind::Bool};
  }
  return Ref{Ref::Field, it->second, static_cast<bool>(field_is_bool[it->second])};
}

model::Type Compiler::value_type(const model::Type& t) {
  if (t.kind == TypeKind::Time) return model::Type::integer("TIME", t.lo, t.hi);
  return t;
}

void Compiler::collect_written(const model::StmtList& body, const std::string& pou) {
  // `x.m := ...` and `inst(Q => x.m)` write member m of another instance: "*|M" marks m
  // written in every POU.
  auto write = [&](const std::string& target) {
    const auto up = model::to_upper(target);
    written.insert(pou + "|" + up);
    if (const auto dot = up.rfind('.'); dot != std::string::npos)
      written.insert("*|" + up.substr(dot + 1));
  };
  for (const auto& s : body) {
    if (s->kind == model::StmtKind::Assign || s->kind == model::StmtKind::For) write(s->target);
    for (const auto& [output, variable] : s->outputs) write(variable);
    // A variable bound to a VAR_IN_OUT is written back after the call.
    for (const auto& variable : model::in_out_bindings(&project, pou, *s)) write(variable);
    for (const auto& b : s->bodies) collect_written(b, pou);
    collect_written(s->else_body, pou);
  }
}

std::optional<std::int64_t> Compiler::constant_variable(const model::Pou& pou,
                                                        const std::string& name) {
  const auto* var = pou.find_variable(name);
  // A located variable (AT %I..., %M...; an HMI variable) is set from outside the program.
  if (!var || !var->address.empty() ||
      (var->direction != model::VarDirection::Local &&
       var->direction != model::VarDirection::Output))
    return std::nullopt;
  const auto up = model::to_upper(var->name);
  if (written.count(model::to_upper(pou.name) + "|" + up) || written.count("*|" + up))
    return std::nullopt;
  // Not free even when nothing writes it (1.8): a duration must be a constant.
  durations.insert(model::to_upper(pou.name) + "|" + up);
  return var->initial.value_or(0);
}

std::string Compiler::free_key(const std::string& scope, const std::string& var) {
  return model::to_upper(scope) + "|" + model::to_upper(var);
}

bool Compiler::is_free(const PouScope& sc, const model::Variable& v) const {
  return !free_variables.empty() && free_variables.count(free_key(sc.name, v.name)) > 0;
}

std::vector<UnwrittenVariable> Compiler::unwritten(std::vector<std::string>& keys) const {
  // Every write of the compiled run: assignments (output bindings, VAR_IN_OUT copies back and
  // FOR counters are assignments too), action variables, function outputs bound with `=>`.
  std::vector<std::uint8_t> written_field(p.initial.size(), 0);
  for (const auto& st : p.stmts)
    if (st.op == SOp::Assign && st.target < written_field.size()) written_field[st.target] = 1;
  for (const auto& a : p.actions)
    if (a.variable != kNone) written_field[static_cast<std::size_t>(a.variable)] = 1;
  for (const auto& copies : p.call_output_copies)
    for (const auto& [from, to] : copies) written_field[to] = 1;
  std::vector<UnwrittenVariable> out;
  for (const auto& d : declared_fields) {
    const auto& v = *d.var;
    const auto read = first_read.find(d.field);
    if (written_field[d.field] || read == first_read.end() || v.constant ||
        v.address.rfind("%Q", 0) == 0 ||
        durations.count(free_key(scopes[d.scope].pou->name, v.name)))
      continue;
    // An SFC flag (1.3a) that no POU sets is an operator's command the program does not give:
    // free, a reset at any cycle would make every deadlock and return check hold through it.
    const auto up = model::to_upper(v.name);
    // (The type as declared: an instance running its SFC actions as units has no chart itself.)
    const auto* type = project.find_pou(scopes[d.scope].pou->name);
    if ((type ? type : scopes[d.scope].pou)->has_sfc() && (up == "SFCINIT" || up == "SFCRESET"))
      continue;
    UnwrittenVariable u;
    u.name = p.field_names[d.field];
    u.type = value_type(v.type);
    u.declared = v.where;
    u.read_in = read->second.scope;
    u.read_at = read->second.where;
    out.push_back(std::move(u));
    keys.push_back(free_key(scopes[d.scope].name, v.name));
  }
  return out;
}

void Compiler::variables(const std::vector<const model::Pou*>& pous) {
  // Providers: outputs and globals, by name, for connecting other POUs' inputs.
  std::map<std::string, std::pair<std::uint32_t, Ref>> providers;  // name -> (pou, variable)
  auto& globals = global_fields;                                   // name -> field
  std::map<std::string, int> name_count;
  auto is_input = [](const model::Variable& v) {
    return v.direction == model::VarDirection::Input ||
           (v.direction == model::VarDirection::Local && v.address.rfind("%I", 0) == 0);
  };
  auto is_output = [](const model::Variable& v) {
    return v.direction == model::VarDirection::Output || v.address.rfind("%Q", 0) == 0;
  };
  // Names of the fields (inputs and connected inputs make none): unique ones display bare.
  for (const auto* pou : pous)
    for (const auto& v : pou->variables)
      if (v.type.kind != TypeKind::FunctionBlock && !is_input(v))
        ++name_count[model::to_upper(v.name)];
      else if (v.type.kind != TypeKind::FunctionBlock)
        input_names.insert(model::to_upper(v.name));
  for (std::uint32_t pi = 0; pi < pous.size(); ++pi) {
    PouScope sc;
    sc.pou = pous[pi];
    sc.index = pi;
    sc.owner = pi;
    sc.name = pous[pi]->name;
    scopes.push_back(std::move(sc));
  }
  // Every POU of the project (the selected ones, the FB types, the uncalled ones): a write
  // `x.m` in any of them changes member m.
  for (const auto& pou : project.pous) {
    const auto up = model::to_upper(pou.name);
    collect_written(pou.body, up);
    for (const auto& a : pou.actions) collect_written(a.body, up);
  }
  // Pass 1: state variables (non-inputs). Instances of user function blocks add scopes, so
  // the scope is found by index each time.
  for (std::uint32_t pi = 0; pi < pous.size(); ++pi) {
    const auto& pou = *pous[pi];
    for (const auto& v : pou.variables) {
      const auto up = model::to_upper(v.name);
      if (v.type.kind == TypeKind::FunctionBlock) {
        if (v.type.fb == StandardFb::None) {
          std::vector<std::string> types{model::to_upper(pou.name)};
          instantiate(pi, v, 1, types);
        } else {
          make_fb(pi, v);
        }
        continue;
      }
      auto& sc = scopes[pi];
      if (is_input(v)) continue;
      if (v.direction == model::VarDirection::InOut) {
        error(v.where, "VAR_IN_OUT '" + v.name + "' of " + pou.name +
                           ": in/out parameters are not supported by the scan-cycle semantics");
        continue;
      }
      const bool shared = v.direction == model::VarDirection::Global ||
                          v.direction == model::VarDirection::External;
      if (shared) {
        if (auto it = globals.find(up); it != globals.end()) {
          sc.names[up] = Ref{Ref::Field, it->second, v.type.kind == TypeKind::Bool};
          continue;
        }
        if (auto it = global_inputs.find(up); it != global_inputs.end()) {
          sc.names[up] = Ref{Ref::Input, it->second, v.type.kind == TypeKind::Bool};
          continue;
        }
      }
      const auto t = value_type(v.type);
      if (is_free(sc, v)) {
        // No POU of the run writes it: an input, any value of its type each cycle (1.8). Named
        // as its field would be, unless an input of the run has that name.
        const bool unique = (name_count[up] == 1 || shared) && !input_names.count(up);
        const auto in = add_input(unique ? v.name : pou.name + "." + v.name, t, false);
        const Ref r{Ref::Input, in, t.kind == TypeKind::Bool};
        sc.names[up] = r;
        if (shared) global_inputs[up] = in;
        if (is_output(v) || shared) providers.emplace(up, std::make_pair(pi, r));
        continue;
      }
      std::int64_t init = v.initial.value_or(0);
      if (!v.initial && (0 < t.lo || 0 > t.hi)) init = t.lo;
      if (init < t.lo || init > t.hi) {
        error(v.where, "initial value of '" + v.name + "' is outside its type's range");
        init = t.lo;
      }
      const bool unique = name_count[up] == 1 || shared;
      const std::string display = unique ? v.name : pou.name + "." + v.name;
      const auto f =
          add_field(display, FieldKind::Variable, t.lo, t.hi, init, t.kind == TypeKind::Bool);
      sc.names[up] = Ref{Ref::Field, f, t.kind == TypeKind::Bool};
      declared_fields.push_back({f, pi, &v});
      if (shared) globals[up] = f;
      if (is_output(v) || shared)
        providers.emplace(up, std::make_pair(pi, Ref{Ref::Field, f, t.kind == TypeKind::Bool}));
      Observable o;
      o.name = display;
      o.aliases = {pou.name + "." + v.name};
      if (unique) o.aliases.push_back(v.name);
      o.kind = ObservableKind::Variable;
      o.type = t;
      o.is_output = is_output(v);
      p.observables.push_back(std::move(o));
      p.observable_refs.push_back(ObservableRef{ObservableKind::Variable, f});
    }
  }
  // Pass 2: inputs, connected to another POU's output of the same name, else free.
  for (std::uint32_t pi = 0; pi < pous.size(); ++pi) {
    auto& sc = scopes[pi];
    for (const auto& v : pous[pi]->variables) {
      if (v.type.kind == TypeKind::FunctionBlock || !is_input(v)) continue;
      const auto up = model::to_upper(v.name);
      if (auto it = providers.find(up); it != providers.end() && it->second.first != pi) {
        sc.names[up] =
            Ref{it->second.second.kind, it->second.second.index, v.type.kind == TypeKind::Bool};
        continue;
      }
      auto it = inputs_by_name.find(up);
      if (it == inputs_by_name.end())
        it = inputs_by_name.emplace(up, add_input(v.name, value_type(v.type), false)).first;
      if (written.count(model::to_upper(pous[pi]->name) + "|" + up)) {
        // A PLC reads its inputs into memory at the start of a cycle, and code may overwrite
        // that memory (a %I variable, or a function block's VAR_INPUT that CODESYS code sets
        // itself): the write is seen until the next cycle reads the input again.
        const auto t = value_type(v.type);
        const bool is_bool = t.kind == TypeKind::Bool;
        const auto f =
            add_field(v.name, FieldKind::Variable, t.lo, t.hi,
                      v.initial.value_or(std::clamp<std::int64_t>(0, t.lo, t.hi)), is_bool);
        sc.names[up] = Ref{Ref::Field, f, is_bool};
        sc.input_copies.emplace_back(f, it->second);
        Observable o;
        o.name = v.name;
        o.aliases = {pous[pi]->name + "." + v.name};
        o.kind = ObservableKind::Variable;
        o.type = t;
        p.observables.push_back(std::move(o));
        p.observable_refs.push_back(ObservableRef{ObservableKind::Variable, f});
        continue;
      }
      sc.names[up] = Ref{Ref::Input, it->second, v.type.kind == TypeKind::Bool};
    }
  }
}

void Compiler::reject_foreign(const std::vector<const model::Pou*>& pous) {
  if (project.dialect == model::Dialect::Grafcet)
    error(project.where,
          "this is a Grafcet (IEC 60848) model; the IEC 61131-3 scan-cycle "
          "semantics does not apply to it");
  for (const auto* pou : pous) {
    if (pou->body_unsupported)
      error(pou->where, "POU '" + pou->name + "': its " + pou->unsupported_language +
                            " body is not modelled (" + pou->unsupported_reason + ")");
    for (const auto& sa : pou->stored_actions)
      error(sa.where, "Grafcet stored action on activation/deactivation/event in " + pou->name +
                          " is not IEC 61131-3");
    for (const auto& fo : pou->forcing_orders)
      error(fo.where, "Grafcet forcing order in " + pou->name + " is not IEC 61131-3");
    for (const auto& as : pou->associations)
      if (as.condition)
        error(as.where, "action block with an assignment condition (Grafcet) in " + pou->name);
    std::set<std::string> vars;
    for (const auto& v : pou->variables)
      if (!vars.insert(model::to_upper(v.name)).second)
        error(v.where, "variable '" + v.name + "' is declared twice in " + pou->name);
    for (const auto& ch : pou->charts) {
      std::set<std::string> steps;
      for (const auto& st : ch.steps)
        if (!steps.insert(model::to_upper(st.name)).second)
          error(st.where, "step '" + st.name + "' is declared twice in chart '" + ch.name + "'");
    }
  }
}

bool Compiler::run() {
  auto pous = select();
  if (!ok) return false;
  // Global variable lists first, so that their declarations (initial values) define the
  // globals that programs and instances name.
  std::vector<const model::Pou*> lists;
  for (const auto& q : project.pous)
    if (is_global_list(q) && std::find(pous.begin(), pous.end(), &q) == pous.end())
      lists.push_back(&q);
  first_program = static_cast<std::uint32_t>(lists.size());
  pous.insert(pous.begin(), lists.begin(), lists.end());
  reject_foreign(pous);
  if (!ok) return false;
  variables(pous);
  if (!ok) return false;
  structure();
  actions_and_transitions();
  final_calls();
  finish_timers();
  timer_reads();
  orders();
  for (const auto& a : p.options.assumptions)
    if (a)
      p.assumptions.push_back(
          bool_expr(scopes[std::min<std::size_t>(first_program, scopes.size() - 1)], a, -1,
                    a->where, "assumption"));
  timer_snapshots();
  step_timers();
  sfc_flags();
  reject_call_cycles();
  instance_commits();
  step_observables();
  // A program without steps may keep no state at all (it only maps inputs to outputs of
  // dropped types); the engines store states as words, so give it one constant bit.
  if (p.layout.fields().empty()) add_field("(no state)", FieldKind::Variable, 0, 1, 0, true);
  // Steps first in the observable list reads best in traces.
  std::vector<std::size_t> idx(p.observables.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](auto a, auto b) {
    return static_cast<int>(p.observables[a].kind) < static_cast<int>(p.observables[b].kind);
  });
  std::vector<Observable> obs;
  std::vector<ObservableRef> refs;
  for (auto i : idx) {
    obs.push_back(p.observables[i]);
    refs.push_back(p.observable_refs[i]);
  }
  p.observables = std::move(obs);
  p.observable_refs = std::move(refs);
  name_boolean_action_activities();
  return ok;
}

// A Boolean action of an instance is named like the variable it drives ("Main.Lift.Extend"):
// two observables, which differ where the action does not write its variable every cycle
// (TwinCAT's reading, docs/semantics.md 1.4a). The variable keeps the name, as the instance's
// alias "Lift.Extend" already resolved; the activity is "Main.Lift.Extend.A", IEC 61131-3's
// name for an action's activity flag. Before, the full name meant the action and the alias the
// variable, so that one property read two ways.
void Compiler::name_boolean_action_activities() {
  std::unordered_set<std::string> taken;
  for (const auto& o : p.observables)
    if (o.kind != ObservableKind::Action) taken.insert(model::to_upper(o.name));
  for (auto& o : p.observables) {
    if (o.kind != ObservableKind::Action || !taken.count(model::to_upper(o.name))) continue;
    o.name += ".A";
    // Its bare alias ("Extend") is the variable's name inside the instance: only "Extend.A"
    // stays.
    std::erase_if(o.aliases, [](const std::string& a) {
      return a.size() < 2 || model::to_upper(a.substr(a.size() - 2)) != ".A";
    });
  }
}

}  // namespace detail

bool compile(const model::Project& project, const Iec61131Options& options, Program& program,
             model::Diagnostics& diagnostics) {
  program.options = options;
  if (program.options.cycle_ms <= 0) program.options.cycle_ms = 1;
  std::vector<UnwrittenVariable> unwritten;
  std::vector<std::string> keys;
  {
    detail::Compiler c(project, program, diagnostics);
    if (!c.run()) return false;
    unwritten = c.unwritten(keys);
  }
  if (unwritten.empty()) return true;
  if (options.unwritten == UnwrittenMode::Free) {
    // Compiled again with those variables as inputs: every use of them (a comparison that splits
    // an integer input, a global, an instance's variable) is then an input's, as for VAR_INPUT.
    Program freed;
    freed.options = program.options;
    model::Diagnostics again;  // the first pass reported the rest
    detail::Compiler c(project, freed, again);
    c.free_variables.insert(keys.begin(), keys.end());
    if (!c.run()) {
      for (auto& d : again)
        if (d.severity == model::Severity::Error) diagnostics.push_back(std::move(d));
      return false;
    }
    program = std::move(freed);
  }
  for (auto& u : unwritten) u.free = options.unwritten == UnwrittenMode::Free;
  diagnostics.push_back({model::Severity::Note, project.where, unwritten_note(unwritten)});
  program.unwritten = std::move(unwritten);
  return true;
}

}  // namespace sfcv::semantics::iec

// The product of two IEC 61131-3 projects for `sfcv equiv` (equivalence.hpp): the two sides
// renamed apart, their inputs joined by name, and an observer program that flags differences.

#include "semantics/equivalence.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

#include "model/compare.hpp"
#include "model/errors.hpp"
#include "model/names.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::semantics {

namespace {

// ------------------------------------------------------------------------------- renaming

/// What to rename in the code of a POU: one variable (a path head: `x`, `x.m`, `x[1]`) and
/// user functions or function block types by name.
struct Renaming {
  std::string from, to;                     ///< variable; empty: none
  std::map<std::string, std::string> pous;  ///< upper-case old name -> new name
  std::set<std::string>* seen = nullptr;    ///< collects the POU names looked up (upper case)
};

std::string rename_head(const std::string& path, const Renaming& r) {
  if (r.from.empty() || path.size() < r.from.size()) return path;
  if (!model::iequals(std::string_view(path).substr(0, r.from.size()), r.from)) return path;
  if (path.size() == r.from.size()) return r.to;
  const char next = path[r.from.size()];
  if (next != '.' && next != '[') return path;
  return r.to + path.substr(r.from.size());
}

std::string rename_pou(const std::string& name, const Renaming& r) {
  if (r.seen) r.seen->insert(model::to_upper(name));
  const auto it = r.pous.find(model::to_upper(name));
  return it == r.pous.end() ? name : it->second;
}

model::ExprPtr rename(const model::ExprPtr& e, const Renaming& r) {
  if (!e) return e;
  auto copy = std::make_shared<model::Expr>(*e);
  switch (e->kind) {
    case model::ExprKind::Name:
    case model::ExprKind::Member:
    case model::ExprKind::Index:
      copy->name = rename_head(e->name, r);
      break;
    case model::ExprKind::Call:
      copy->name = rename_pou(e->name, r);
      break;
    default:
      break;
  }
  for (auto& a : copy->args) a = rename(a, r);
  return copy;
}

model::StmtList rename(const model::StmtList& body, const Renaming& r);

model::StmtPtr rename(const model::StmtPtr& s, const Renaming& r) {
  if (!s) return s;
  auto copy = std::make_shared<model::Stmt>(*s);
  if (s->kind == model::StmtKind::FbCall) (void)rename_pou(s->target, r);
  copy->target = rename_head(s->target, r);
  copy->value = rename(s->value, r);
  for (auto& c : copy->conditions) c = rename(c, r);
  for (auto& b : copy->bodies) b = rename(b, r);
  copy->else_body = rename(s->else_body, r);
  for (auto& a : copy->arguments) a.second = rename(a.second, r);
  for (auto& o : copy->outputs) o.second = rename_head(o.second, r);
  copy->limit = rename(s->limit, r);
  copy->step = rename(s->step, r);
  for (auto& i : copy->target_indices) i = rename(i, r);
  return copy;
}

model::StmtList rename(const model::StmtList& body, const Renaming& r) {
  model::StmtList out;
  out.reserve(body.size());
  for (const auto& s : body) out.push_back(rename(s, r));
  return out;
}

/// Renames in the code of `pou` (bodies, guards, associations, instance types).
void rename_in_pou(model::Pou& pou, const Renaming& r) {
  pou.body = rename(pou.body, r);
  for (auto& a : pou.actions) {
    a.body = rename(a.body, r);
    a.variable = rename_head(a.variable, r);
  }
  for (auto& c : pou.charts)
    for (auto& t : c.transitions) t.guard = rename(t.guard, r);
  for (auto& as : pou.associations) {
    as.condition = rename(as.condition, r);
    as.duration_variable = rename_head(as.duration_variable, r);
    as.indicator = rename_head(as.indicator, r);
  }
  for (auto& v : pou.variables) {
    if (!r.from.empty() && model::iequals(v.name, r.from)) v.name = r.to;
    v.type.name = rename_pou(v.type.name, r);
  }
}

// ------------------------------------------------------------------------------- one side

/// One side as it runs alone: its programs, free program variables, initial values.
struct Side {
  const char* label;   ///< "OLD", "NEW"
  const char* prefix;  ///< "Old_", "New_"
  model::Project project;
  TransitionSystemPtr system;
  std::vector<std::string> programs;  ///< run order, names in the project
  std::vector<StateWord> initial;     ///< the first initial state
};

class FirstState : public SuccessorSink {
 public:
  void successor(const Successor& s) override {
    ++count;
    if (!state.empty()) return;
    state.assign(s.target.begin(), s.target.end());
  }
  std::vector<StateWord> state;
  std::size_t count = 0;
};

std::string diagnostics_text(const model::Diagnostics& diags) {
  std::string text;
  for (const auto& d : diags)
    if (d.severity == model::Severity::Error) text += "\n  " + d.str();
  return text;
}

void build_alone(Side& side, const Iec61131Options& options) {
  if (side.project.dialect != model::Dialect::Iec61131)
    throw UnsupportedConstruct(std::string("sfcv equiv: ") + side.label +
                               " is a Grafcet (IEC 60848): one of its evolutions is an input "
                               "event followed by transient evolutions to a stable situation, "
                               "one of a PLC's a scan crossing one transition per chart; no "
                               "cycle-by-cycle correspondence between them is sound, so equiv "
                               "compares IEC 61131-3 programs only (docs/equivalence.md, "
                               "\"Grafcet against IEC 61131-3 code\")");
  model::Diagnostics diags;
  side.system = make_iec61131_system(side.project, options, diags);
  if (!side.system)
    throw InputError(std::string("sfcv equiv: ") + side.label +
                     " cannot be run:" + diagnostics_text(diags));
  for (const auto& inst : side.system->pou_instances())
    if (model::iequals(inst.path, inst.pou)) side.programs.push_back(inst.pou);
  FirstState first;
  side.system->initial_states(first);
  // The observer's first comparison is of the two initial situations: it needs one on each side.
  if (first.count != 1)
    throw UnsupportedConstruct(std::string("sfcv equiv: ") + side.label + " has " +
                               std::to_string(first.count) +
                               " initial situations; equiv compares programs with one");
  side.initial = std::move(first.state);
}

model::Pou* find_pou(model::Project& p, std::string_view name) {
  for (auto& pou : p.pous)
    if (model::iequals(pou.name, name)) return &pou;
  return nullptr;
}

model::Variable* find_var(model::Pou& pou, std::string_view name) {
  for (auto& v : pou.variables)
    if (model::iequals(v.name, name)) return &v;
  return nullptr;
}

bool is_input(const model::Variable& v) {
  return v.direction == model::VarDirection::Input;
}

/// Program variables that no POU of the run writes and that are free inputs: they become
/// VAR_INPUTs so that the two sides share them by name.
void free_variables_to_inputs(Side& side, const std::vector<ComparedSignal>& compared,
                              const EquivalenceOptions::Map* map, std::vector<std::string>& notes) {
  for (auto u : unwritten_variables(*side.system)) {
    if (!u.free) continue;
    // NEW's names as the product has them after --map.
    if (map)
      for (const auto& [old_name, new_name] : *map) {
        if (model::iequals(u.name, new_name)) u.name = old_name;
        const auto dot = u.name.rfind('.');
        if (dot != std::string::npos && model::iequals(u.name.substr(dot + 1), new_name))
          u.name = u.name.substr(0, dot + 1) + old_name;
      }
    bool shared = false;
    for (const auto& prog : side.programs) {
      auto* pou = find_pou(side.project, prog);
      for (auto& v : pou->variables) {
        if (v.direction == model::VarDirection::Global ||
            v.direction == model::VarDirection::External)
          continue;
        if (!model::iequals(u.name, v.name) && !model::iequals(u.name, prog + "." + v.name))
          continue;
        // A compared signal that its side never writes stays that side's own free value.
        const auto ref = side.prefix + prog + "." + v.name;
        if (std::any_of(compared.begin(), compared.end(), [&](const ComparedSignal& c) {
              return model::iequals(c.old_ref, ref) || model::iequals(c.new_ref, ref);
            })) {
          notes.push_back(std::string(side.label) + " never writes the compared " + v.name +
                          ": it is free there (any value each cycle)");
          shared = true;
          continue;
        }
        v.direction = model::VarDirection::Input;
        shared = true;
      }
    }
    // An instance's or a global's free variable stays one input per side: the two sides may
    // read different values there, and a difference found through it names it in the trace.
    if (!shared)
      notes.push_back(std::string(side.label) + "'s " + u.name +
                      " is free (no POU writes it) and not shared with the other side");
  }
}

struct Located {
  std::string program;  ///< name in the side's project
  model::Variable* variable = nullptr;
  /// The variable's path in its program: its name, or `inst.q` for a member of an instance.
  std::string path;
};

/// A program variable of the side named `name` or `Program.name`; nullopt when none.
std::optional<Located> locate(Side& side, const std::string& name) {
  std::optional<Located> found;
  for (const auto& prog : side.programs) {
    auto* pou = find_pou(side.project, prog);
    for (auto& v : pou->variables)
      if (model::iequals(v.name, name) || model::iequals(prog + "." + v.name, name)) {
        if (found)
          throw InputError(std::string("sfcv equiv: '") + name + "' is ambiguous in " + side.label +
                           " (programs " + found->program + " and " + prog +
                           "); name it Program.variable");
        found = Located{prog, &v, v.name};
      }
  }
  return found;
}

/// A variable of a function block instance of the side's programs: `inst.q` (`inst.sub.q`
/// through nested instances) or `Program.inst.q`; nullopt when `name` is not such a path. The
/// members of standard function blocks are refused (their fields are the semantics' own).
std::optional<Located> locate_member(Side& side, const std::string& name) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto dot = name.find('.', start);
    parts.push_back(name.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (parts.size() < 2) return std::nullopt;
  std::optional<Located> found;
  for (const auto& prog : side.programs) {
    // With or without the program's name in front.
    for (std::size_t first : {std::size_t{0}, std::size_t{1}}) {
      if (first == 1 && !model::iequals(parts[0], prog)) continue;
      if (parts.size() - first < 2) continue;
      model::Pou* pou = find_pou(side.project, prog);
      model::Variable* v = nullptr;
      std::string path;
      for (std::size_t k = first; k < parts.size() && pou; ++k) {
        v = find_var(*pou, parts[k]);
        if (!v) break;
        path += (path.empty() ? "" : ".") + v->name;
        if (k + 1 == parts.size()) break;
        if (v->type.kind != model::TypeKind::FunctionBlock) {
          v = nullptr;
          break;
        }
        if (v->type.fb != model::StandardFb::None)
          throw UsageError(std::string("sfcv equiv: '") + name + "' is a member of the standard " +
                           v->type.name + " instance " + v->name + " in " + side.label +
                           "; compare a variable it drives");
        pou = find_pou(side.project, v->type.name);
        if (!pou) v = nullptr;
      }
      if (!v || path.empty() || path.find('.') == std::string::npos) continue;
      if (found && !model::iequals(found->program, prog))
        throw InputError(std::string("sfcv equiv: '") + name + "' is ambiguous in " + side.label +
                         " (programs " + found->program + " and " + prog + "); name it Program." +
                         name);
      found = Located{prog, v, path};
    }
  }
  return found;
}

/// A program variable (locate) or a member of an instance (locate_member).
std::optional<Located> locate_signal(Side& side, const std::string& name) {
  if (name.find('.') != std::string::npos)
    if (auto m = locate_member(side, name)) return m;
  return locate(side, name);
}

bool is_member_path(const std::string& name) {
  return name.find('.') != std::string::npos;
}

bool same_type(const model::Type& a, const model::Type& b) {
  return a.kind == b.kind && a.lo == b.lo && a.hi == b.hi && a.fb == b.fb;
}

std::string type_text(const model::Type& t) {
  return t.name;
}

// ------------------------------------------------------------------------------- the product

void apply_map(Side& new_side, Side& old_side, const EquivalenceOptions& options) {
  for (const auto& [old_name, new_name] : options.map) {
    if (is_member_path(old_name) || is_member_path(new_name)) {
      // A member of an instance is compared where it is (choose_signals pairs the two paths):
      // the type it belongs to may be shared by both sides, so nothing is renamed.
      const auto o = locate_signal(old_side, old_name);
      const auto n = locate_signal(new_side, new_name);
      if (!o || !n)
        throw UsageError("sfcv equiv --map " + old_name + "=" + new_name + ": " +
                         (!o ? "OLD" : "NEW") + " has no variable '" + (!o ? old_name : new_name) +
                         "' in its programs or their instances");
      continue;
    }
    if (!locate(old_side, old_name))
      throw UsageError("sfcv equiv --map " + old_name + "=" + new_name + ": OLD has no variable '" +
                       old_name + "' in its programs");
    const auto at = locate(new_side, new_name);
    if (!at)
      throw UsageError("sfcv equiv --map " + old_name + "=" + new_name + ": NEW has no variable '" +
                       new_name + "' in its programs");
    if (model::iequals(old_name, new_name)) continue;
    auto* pou = find_pou(new_side.project, at->program);
    if (find_var(*pou, old_name))
      throw UsageError("sfcv equiv --map " + old_name + "=" + new_name + ": NEW's " + at->program +
                       " already has a variable '" + old_name + "'");
    Renaming r;
    r.from = new_name;
    r.to = old_name;
    rename_in_pou(*pou, r);
  }
}

bool is_global_list(const model::Pou& pou) {
  return !pou.variables.empty() &&
         std::all_of(pou.variables.begin(), pou.variables.end(),
                     [](const auto& v) { return v.direction == model::VarDirection::Global; });
}

std::set<std::string> global_names(const model::Project& p) {
  std::set<std::string> out;
  for (const auto& pou : p.pous)
    for (const auto& v : pou.variables)
      if (v.direction == model::VarDirection::Global) out.insert(model::to_upper(v.name));
  return out;
}

/// The names of the POUs `pou` may use: its instances' types, the functions it calls (and,
/// conservatively, every call target).
std::set<std::string> referenced_pous(const model::Pou& pou) {
  std::set<std::string> seen;
  Renaming r;
  r.seen = &seen;
  model::Pou copy = pou;
  rename_in_pou(copy, r);
  return seen;
}

bool same_pou(const model::Pou& a, const model::Pou& b) {
  // first_difference ignores type names; an instance of another type is another POU.
  for (const auto& v : a.variables) {
    const auto* w = b.find_variable(v.name);
    if (w && !model::iequals(v.type.name, w->type.name)) return false;
  }
  model::Project pa, pb;
  pa.pous.push_back(a);
  pb.pous.push_back(b);
  return !model::first_difference(pa, pb).has_value();
}

/// Copies both sides into one project: programs prefixed, other POUs shared when equal, NEW's
/// renamed `New_<name>` (with every use in NEW) when they differ.
void merge_pous(Side& old_side, Side& new_side, EquivalenceProduct& out) {
  for (const auto& g : global_names(old_side.project))
    if (global_names(new_side.project).count(g))
      throw UnsupportedConstruct(
          "sfcv equiv: both programs declare the global variable '" + g +
          "'; a global is one field shared by every POU, so the two sides cannot be kept apart "
          "(rename it in one of them)");
  std::set<std::string> taken;
  for (const auto& pou : old_side.project.pous) taken.insert(model::to_upper(pou.name));
  for (const auto& pou : new_side.project.pous) taken.insert(model::to_upper(pou.name));
  auto fresh = [&taken](const std::string& name) {
    if (taken.count(model::to_upper(name)))
      throw UnsupportedConstruct("sfcv equiv: the product needs the POU name '" + name +
                                 "', which one of the programs already uses");
    taken.insert(model::to_upper(name));
    return name;
  };
  auto is_run = [](const Side& s, const std::string& name) {
    return std::any_of(s.programs.begin(), s.programs.end(),
                       [&](const auto& p) { return model::iequals(p, name); });
  };
  Renaming new_renames;
  std::vector<model::Pou> new_pous;
  for (auto& pou : old_side.project.pous)
    if (is_run(old_side, pou.name)) pou.name = fresh(old_side.prefix + pou.name);
  // NEW's POUs that OLD also declares: shared when equal and everything they use is shared
  // too (a fixpoint: an equal block using a changed function must run NEW's function).
  std::set<std::string> differing;
  for (const auto& pou : new_side.project.pous) {
    if (is_run(new_side, pou.name)) continue;
    const auto* twin = old_side.project.find_pou(pou.name);
    if (twin && !same_pou(*twin, pou)) differing.insert(model::to_upper(pou.name));
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& pou : new_side.project.pous) {
      const auto key = model::to_upper(pou.name);
      if (is_run(new_side, pou.name) || differing.count(key) ||
          !old_side.project.find_pou(pou.name))
        continue;
      for (const auto& used : referenced_pous(pou))
        if (differing.count(used)) {
          differing.insert(key);
          grew = true;
          break;
        }
    }
  }
  for (auto& pou : new_side.project.pous) {
    if (is_run(new_side, pou.name)) {
      pou.name = fresh(new_side.prefix + pou.name);
      new_pous.push_back(pou);
      continue;
    }
    if (!old_side.project.find_pou(pou.name)) {
      new_pous.push_back(pou);
      continue;
    }
    if (!differing.count(model::to_upper(pou.name))) continue;
    if (is_global_list(pou))
      throw UnsupportedConstruct("sfcv equiv: both programs have a global variable list '" +
                                 pou.name + "', and they differ");
    const std::string renamed = fresh(new_side.prefix + pou.name);
    new_renames.pous[model::to_upper(pou.name)] = renamed;
    out.notes.push_back("NEW's " + pou.name + " differs from OLD's: it runs as " + renamed);
    pou.name = renamed;
    new_pous.push_back(pou);
  }
  // In the order of each side's scan cycle.
  for (const auto& p : old_side.programs) out.old_programs.push_back(old_side.prefix + p);
  for (const auto& p : new_side.programs) out.new_programs.push_back(new_side.prefix + p);
  if (!new_renames.pous.empty())
    for (auto& pou : new_pous) rename_in_pou(pou, new_renames);
  out.project.pous = old_side.project.pous;
  for (auto& pou : new_pous) out.project.pous.push_back(std::move(pou));
}

bool is_output(const model::Variable& v) {
  return v.direction == model::VarDirection::Output ||
         (v.address.size() > 1 && (v.address[1] == 'Q' || v.address[1] == 'q'));
}

/// The inputs of a side: name (upper case) -> variable, over its programs.
std::map<std::string, const model::Variable*> side_inputs(Side& side) {
  std::map<std::string, const model::Variable*> out;
  for (const auto& prog : side.programs)
    for (const auto& v : find_pou(side.project, prog)->variables)
      if (is_input(v)) out.emplace(model::to_upper(v.name), &v);
  return out;
}

void check_inputs(Side& old_side, Side& new_side, EquivalenceProduct& out) {
  const auto old_in = side_inputs(old_side), new_in = side_inputs(new_side);
  for (const auto& [key, v] : old_in)
    if (!new_in.count(key))
      out.notes.push_back("OLD's input " + v->name +
                          " is not an input of NEW: each side reads its own (--map " + v->name +
                          "=...)");
  for (const auto& [key, v] : new_in)
    if (!old_in.count(key))
      out.notes.push_back("NEW's input " + v->name +
                          " is not an input of OLD: each side reads its own");
  for (const auto& [key, v] : old_in) {
    const auto it = new_in.find(key);
    if (it == new_in.end()) continue;
    if (!same_type(v->type, it->second->type))
      throw InputError("sfcv equiv: the input '" + v->name + "' is " + type_text(v->type) +
                       " in OLD and " + type_text(it->second->type) +
                       " in NEW; both programs must read the same inputs (--map pairs others)");
    out.shared_inputs.push_back(v->name);
  }
  // An input of one side with the name of an output of the other would read that output
  // (docs/semantics.md 1.8, plant models): the sides would no longer be apart.
  auto clash = [](Side& reader, Side& writer,
                  const std::map<std::string, const model::Variable*>& inputs) {
    for (const auto& prog : writer.programs)
      for (const auto& v : find_pou(writer.project, prog)->variables)
        if (is_output(v) && inputs.count(model::to_upper(v.name)))
          throw InputError(std::string("sfcv equiv: '") + v.name + "' is an input of " +
                           reader.label + " but an output of " + writer.label + "'s " + prog +
                           "; rename one of them");
  };
  clash(old_side, new_side, old_in);
  clash(new_side, old_side, new_in);
}

std::string sanitize(const std::string& name) {
  std::string s;
  for (const char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return s;
}

std::string mapped_name(const EquivalenceOptions& o, const std::string& old_name) {
  for (const auto& [a, b] : o.map)
    if (model::iequals(a, old_name)) return b;
  return old_name;
}

bool listed(const std::vector<std::string>& list, const std::string& name,
            const std::string& program) {
  return std::any_of(list.begin(), list.end(), [&](const auto& n) {
    return model::iequals(n, name) || model::iequals(n, program + "." + name);
  });
}

/// The signal's value in the side's initial situation; a variable the state does not hold (one
/// nothing writes) has its declared initial value there.
/// `var` as the side alone names it, `declared` as the product does (after --map).
std::int64_t initial_value(Side& side, const std::string& program, const std::string& var,
                           const std::string& declared) {
  if (const auto index = find_observable(*side.system, program + "." + var))
    return side.system->observe(side.initial, *index);
  const model::Variable* v = find_var(*find_pou(side.project, program), declared);
  if (!v && is_member_path(var))
    if (const auto m = locate_member(side, program + "." + var)) v = m->variable;
  if (!v) throw InternalError("sfcv equiv: no variable " + program + "." + var);
  return std::clamp<std::int64_t>(v->initial.value_or(0), v->type.lo, v->type.hi);
}

/// Pairs the signals to compare. Names are resolved on the sides before the product's renaming
/// (side.programs are the original names).
void choose_signals(Side& old_side, Side& new_side, const EquivalenceOptions& o,
                    EquivalenceProduct& out) {
  std::vector<std::pair<std::string, bool>> wanted;  // OLD's name, internal
  if (o.outputs.empty()) {
    for (const auto& prog : old_side.programs)
      for (const auto& v : find_pou(old_side.project, prog)->variables)
        if (is_output(v) && !listed(o.ignore, v.name, prog)) {
          if (!locate(new_side, v.name)) {
            out.notes.push_back("OLD's output " + v.name + " has no counterpart in NEW (--map " +
                                v.name + "=...): not compared");
            continue;
          }
          wanted.emplace_back(v.name, false);
        }
    for (const auto& prog : new_side.programs)
      for (const auto& v : find_pou(new_side.project, prog)->variables)
        if (is_output(v) && !locate(old_side, v.name))
          out.notes.push_back("NEW's output " + v.name +
                              " has no counterpart in OLD: not compared");
  } else {
    for (const auto& n : o.outputs)
      if (!listed(o.ignore, n, "")) wanted.emplace_back(n, false);
  }
  for (const auto& n : o.compare) wanted.emplace_back(n, true);

  std::set<std::string> seen;
  for (const auto& [name, internal] : wanted) {
    const auto old_at = locate_signal(old_side, name);
    if (!old_at)
      throw UsageError("sfcv equiv: OLD's programs have no variable '" + name +
                       "' to compare (neither a program variable nor a member `inst.q` of an "
                       "instance)");
    if (listed(o.ignore, old_at->path, old_at->program)) continue;
    // apply_map gave NEW's program variable OLD's name already; a member of an instance is
    // paired by its --map entry (by the whole path, or the program-qualified one), else by its
    // own path.
    const bool member = is_member_path(old_at->path);
    std::string new_name = mapped_name(o, member ? old_at->path : old_at->variable->name);
    if (member && new_name == old_at->path) {
      const auto qualified = old_at->program + "." + old_at->path;
      if (const auto m = mapped_name(o, qualified); m != qualified) new_name = m;
    }
    const auto new_at =
        member ? locate_signal(new_side, new_name) : locate(new_side, old_at->variable->name);
    if (!new_at)
      throw UsageError("sfcv equiv: NEW's programs have no variable '" + new_name +
                       "' to compare with OLD's '" + name + "' (--map " + name + "=...)");
    const auto& ot = old_at->variable->type;
    const auto& nt = new_at->variable->type;
    if (ot.kind == model::TypeKind::FunctionBlock || nt.kind == model::TypeKind::FunctionBlock)
      throw UsageError("sfcv equiv: '" + name + "' is a function block instance, not a value");
    if ((ot.kind == model::TypeKind::Bool) != (nt.kind == model::TypeKind::Bool))
      throw InputError("sfcv equiv: '" + name + "' is " + type_text(ot) + " in OLD and " +
                       type_text(nt) + " in NEW");
    if (!seen.insert(model::to_upper(old_at->program + "." + old_at->path)).second) continue;
    ComparedSignal s;
    s.name = old_at->path;
    s.new_name = member ? new_at->path : new_name;
    s.old_ref = old_side.prefix + old_at->program + "." + old_at->path;
    // --map renamed NEW's program variable to OLD's name in the product; an instance member
    // keeps NEW's path.
    s.new_ref = new_side.prefix + new_at->program + "." + (member ? new_at->path : old_at->path);
    s.type = ot;
    s.new_type = nt;
    s.internal = internal;
    out.compared.push_back(std::move(s));
  }
  if (out.compared.empty())
    throw UsageError(
        "sfcv equiv: nothing to compare (the programs share no output; name the signals with "
        "--outputs a,b or --compare x)");
}

model::ExprPtr var_ref(const std::string& path) {
  // `Old_Main.inst.q` as the parser reads it: the member after the last dot.
  const auto dot = path.rfind('.');
  return model::make_member(path.substr(0, dot), path.substr(dot + 1));
}

/// `a <> b` for the signal's type (XOR for BOOL).
model::ExprPtr differ(const ComparedSignal& s, model::ExprPtr a, model::ExprPtr b) {
  const auto kind =
      s.type.kind == model::TypeKind::Bool ? model::ExprKind::Xor : model::ExprKind::Ne;
  return model::make_binary(kind, std::move(a), std::move(b));
}

/// The observer: runs last in the cycle. differs_s := new <> old AND new <> h1 ... AND new <> hN,
/// where h_d holds OLD's value d cycles back (shifted after the comparison).
model::Pou observer(EquivalenceProduct& out, std::uint32_t within,
                    const std::vector<std::pair<std::int64_t, std::int64_t>>& initial) {
  model::Pou pou;
  pou.name = kEquivObserver;
  pou.kind = model::PouKind::Program;
  std::set<std::string> used;
  for (std::size_t i = 0; i < out.compared.size(); ++i) {
    auto& s = out.compared[i];
    std::string base = sanitize(s.name);
    while (!used.insert(model::to_upper(base)).second) base += "_";
    s.differs = std::string(kEquivObserver) + ".differs_" + base;
    model::Variable flag;
    flag.name = "differs_" + base;
    flag.type = model::Type::boolean();
    flag.initial = initial[i].first != initial[i].second;
    pou.variables.push_back(flag);
    // Copies of both values first: the comparison reads them, and traces show them.
    s.old_seen = std::string(kEquivObserver) + ".old_" + base;
    s.new_seen = std::string(kEquivObserver) + ".new_" + base;
    // Each copy has its side's type: a value outside the other side's range must show as a
    // difference, not raise a range error that ends the run.
    for (const auto& [name, ref, init, type] :
         {std::tuple{"old_" + base, s.old_ref, initial[i].first, s.type},
          std::tuple{"new_" + base, s.new_ref, initial[i].second, s.new_type}}) {
      model::Variable copy;
      copy.name = name;
      copy.type = type;
      copy.initial = init;
      pou.variables.push_back(copy);
      pou.body.push_back(model::make_assign(name, var_ref(ref)));
    }
    const auto old_value = model::make_name("old_" + base);
    const auto new_value = model::make_name("new_" + base);
    model::ExprPtr cond = differ(s, new_value, old_value);
    std::vector<std::string> history;
    for (std::uint32_t d = 1; d <= within; ++d) {
      model::Variable h;
      h.name = "h" + std::to_string(d) + "_" + base;
      h.type = s.type;
      h.initial = initial[i].first;
      pou.variables.push_back(h);
      history.push_back(h.name);
      cond = model::make_nary(model::ExprKind::And,
                              {cond, differ(s, new_value, model::make_name(h.name))});
    }
    pou.body.push_back(model::make_assign("differs_" + base, cond));
    for (std::size_t d = history.size(); d-- > 0;)
      pou.body.push_back(model::make_assign(
          history[d], d == 0 ? var_ref(s.old_ref) : model::make_name(history[d - 1])));
  }
  return pou;
}

}  // namespace

EquivalenceProduct make_equivalence_product(const model::Project& old_project,
                                            const model::Project& new_project,
                                            const EquivalenceOptions& options) {
  if (!options.semantics.pous.empty())
    throw UsageError("sfcv equiv: --pou is not supported; each side runs its programs");
  Side old_side{"OLD", kEquivOldPrefix, old_project, nullptr, {}, {}};
  Side new_side{"NEW", kEquivNewPrefix, new_project, nullptr, {}, {}};
  build_alone(old_side, options.semantics);
  build_alone(new_side, options.semantics);
  EquivalenceProduct out;
  out.project.name = "equiv";
  out.project.dialect = model::Dialect::Iec61131;
  out.project.source_format = "equiv";
  out.project.data_types_lowered = old_project.data_types_lowered || new_project.data_types_lowered;
  apply_map(new_side, old_side, options);
  choose_signals(old_side, new_side, options, out);
  free_variables_to_inputs(old_side, out.compared, nullptr, out.notes);
  free_variables_to_inputs(new_side, out.compared, &options.map, out.notes);
  check_inputs(old_side, new_side, out);
  std::vector<std::pair<std::int64_t, std::int64_t>> initial;
  for (const auto& s : out.compared) {
    const auto program_of = [](const std::string& ref, const char* prefix) {
      return ref.substr(std::string(prefix).size(), ref.find('.') - std::string(prefix).size());
    };
    initial.emplace_back(
        initial_value(old_side, program_of(s.old_ref, kEquivOldPrefix), s.name, s.name),
        initial_value(new_side, program_of(s.new_ref, kEquivNewPrefix), s.new_name, s.name));
  }
  merge_pous(old_side, new_side, out);
  out.project.pous.push_back(observer(out, options.within, initial));
  out.options = options.semantics;
  out.options.pous = out.old_programs;
  out.options.pous.insert(out.options.pous.end(), out.new_programs.begin(), out.new_programs.end());
  out.options.pous.push_back(kEquivObserver);
  return out;
}

std::string abstract_time_note(const TransitionSystem& product) {
  std::size_t count = 0;
  for (const auto& in : product.inputs())
    if (in.pseudo && (in.name.rfind("timeout:", 0) == 0 || in.name.rfind("elapse:", 0) == 0))
      ++count;
  if (!count) return {};
  return std::to_string(count) +
         " timers or step times run on abstract time: each side's expire independently, so a "
         "difference may come from time alone (the trace shows timeout:...); --time discrete "
         "--cycle ... compares them in real cycles";
}

}  // namespace sfcv::semantics

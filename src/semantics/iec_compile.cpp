// Compiles a model::Project into the flat Program the IEC 61131-3 machine runs: selects the
// POUs, connects their variables, lays out the state, resolves names and compiles guards and
// action bodies. Anything the semantics cannot model faithfully is an Error diagnostic.

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "model/names.hpp"
#include "semantics/iec_program.hpp"

namespace sfcv::semantics::iec {

namespace {

using model::ExprKind;
using model::Qualifier;
using model::StandardFb;
using model::TypeKind;

struct Ref {
  enum Kind { Field, Input, FbInst } kind = Field;
  std::uint32_t index = 0;
  bool is_bool = true;
};

struct PouScope {
  const model::Pou* pou = nullptr;
  std::uint32_t index = 0;
  std::map<std::string, Ref> names;                // upper-case variable names
  std::vector<std::uint32_t> chart_ids;            // global chart index per pou chart
  std::map<std::string, std::uint32_t> actions;    // upper name -> global action index
  // Inputs the POU's own code writes: a field holds the program's copy, loaded from the input
  // at the start of the POU's cycle (field, input).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> input_copies;
};

enum class VT { Bool, Int };

struct Compiler {
  Compiler(const model::Project& pr, Program& prog, model::Diagnostics& d)
      : project(pr), p(prog), diags(d) {}
  const model::Project& project;
  Program& p;
  model::Diagnostics& diags;
  bool ok = true;
  std::vector<PouScope> scopes;
  std::map<std::string, std::uint32_t> inputs_by_name;
  std::vector<std::uint8_t> field_is_bool;
  std::set<std::string> written;  // "POU|VAR" upper-case: variables some statement assigns
  std::set<std::string> inlining;  // upper-case actions whose call is being compiled
  std::map<std::uint32_t, model::SourceLocation> omitted_pt;  // FB index -> a call without PT
  std::set<std::uint32_t> called_timers;                      // FB indices of called timers
  // Step .T: constants compared with, and nodes to patch once regions are known.
  std::map<std::uint32_t, std::set<std::int64_t>> t_keys;  // step -> keys (2c or 2c+1)
  std::vector<std::uint32_t> t_nodes;

  void error(const model::SourceLocation& where, std::string msg) {
    diags.push_back({model::Severity::Error, where, std::move(msg)});
    ok = false;
  }

  std::uint32_t add_field(std::string name, FieldKind kind, std::int64_t lo, std::int64_t hi,
                          std::int64_t init, bool is_bool) {
    const auto f = p.layout.add_field(name, kind, lo, hi);
    p.field_lo.push_back(lo);
    p.field_hi.push_back(hi);
    p.initial.push_back(init);
    p.field_names.push_back(std::move(name));
    field_is_bool.push_back(is_bool);
    return f;
  }

  std::uint32_t add_input(std::string name, model::Type type, bool pseudo) {
    p.inputs.push_back(InputVariable{std::move(name), std::move(type), pseudo});
    return static_cast<std::uint32_t>(p.inputs.size() - 1);
  }

  // ---------------------------------------------------------------------- POU selection
  std::vector<const model::Pou*> select() {
    std::vector<const model::Pou*> out;
    if (!p.options.pous.empty()) {
      for (const auto& name : p.options.pous) {
        const auto* pou = project.find_pou(name);
        if (!pou) {
          std::string avail;
          for (const auto& q : project.pous) avail += (avail.empty() ? "" : ", ") + q.name;
          error(project.where, "no POU named '" + name + "' (the model has: " + avail + ")");
          continue;
        }
        out.push_back(pou);
      }
      return out;
    }
    // Without --pou: every PROGRAM in document order (a PLC task runs its programs one after
    // another in one cycle), when all of them can be modelled; else, as before, the one POU
    // with an SFC body (a function block then runs alone, its inputs free).
    std::vector<const model::Pou*> programs, sfc_programs, sfc_others;
    bool programs_modelled = true;
    for (const auto& q : project.pous) {
      const bool runs = q.has_sfc() || !q.body.empty() || q.body_unsupported;
      if (q.kind == model::PouKind::Program && runs) {
        programs.push_back(&q);
        programs_modelled = programs_modelled && !q.body_unsupported;
      }
      if (q.has_sfc()) (q.kind == model::PouKind::Program ? sfc_programs : sfc_others).push_back(&q);
    }
    if (!programs.empty() && programs_modelled) return programs;
    const auto& cands = sfc_programs.empty() ? sfc_others : sfc_programs;
    if (cands.size() == 1) {
      for (const auto* q : programs)
        if (q->body_unsupported)
          diags.push_back({model::Severity::Note, q->where,
                           "program '" + q->name + "' is not run (its body is not modelled); '" +
                               cands.front()->name + "' runs alone"});
      return {cands.front()};
    }
    if (cands.empty()) {
      std::string list;
      for (const auto* q : programs) list += (list.empty() ? "" : ", ") + q->name;
      error(project.where, programs.empty()
                               ? "the model has no PROGRAM and no POU with an SFC body: choose the "
                                 "POU(s) to run with --pou"
                               : "no program can be run (" + list +
                                     ": a body sfcv does not model); choose other POU(s) with --pou");
    } else {
      std::string list;
      for (const auto* q : cands) list += (list.empty() ? "" : ", ") + q->name;
      error(project.where, "several POUs have an SFC body (" + list +
                               "): choose the one(s) to run with --pou");
    }
    return out;
  }

  // ------------------------------------------------------------------------- variables
  static model::Type value_type(const model::Type& t) {
    if (t.kind == TypeKind::Time) return model::Type::integer("TIME", t.lo, t.hi);
    return t;
  }

  void collect_written(const model::StmtList& body, const std::string& pou) {
    for (const auto& s : body) {
      if (s->kind == model::StmtKind::Assign) written.insert(pou + "|" + model::to_upper(s->target));
      for (const auto& b : s->bodies) collect_written(b, pou);
      collect_written(s->else_body, pou);
    }
  }

  void variables(const std::vector<const model::Pou*>& pous) {
    // Providers: outputs and globals, by name, for connecting other POUs' inputs.
    std::map<std::string, std::pair<std::uint32_t, std::uint32_t>> providers;  // name -> (pou, var)
    std::map<std::string, std::uint32_t> globals;                              // name -> field
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
        if (v.type.kind != TypeKind::FunctionBlock && !is_input(v)) ++name_count[model::to_upper(v.name)];
    for (std::uint32_t pi = 0; pi < pous.size(); ++pi) {
      PouScope sc;
      sc.pou = pous[pi];
      sc.index = pi;
      scopes.push_back(std::move(sc));
      const auto up = model::to_upper(pous[pi]->name);
      collect_written(pous[pi]->body, up);
      for (const auto& a : pous[pi]->actions) collect_written(a.body, up);
    }
    // Pass 1: state variables (non-inputs).
    for (std::uint32_t pi = 0; pi < pous.size(); ++pi) {
      const auto& pou = *pous[pi];
      auto& sc = scopes[pi];
      for (const auto& v : pou.variables) {
        const auto up = model::to_upper(v.name);
        if (v.type.kind == TypeKind::FunctionBlock) {
          make_fb(pi, v);
          continue;
        }
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
        }
        const auto t = value_type(v.type);
        std::int64_t init = v.initial.value_or(0);
        if (!v.initial && (0 < t.lo || 0 > t.hi)) init = t.lo;
        if (init < t.lo || init > t.hi) {
          error(v.where, "initial value of '" + v.name + "' is outside its type's range");
          init = t.lo;
        }
        const bool unique = name_count[up] == 1 || shared;
        const std::string display = unique ? v.name : pou.name + "." + v.name;
        const auto f = add_field(display, FieldKind::Variable, t.lo, t.hi, init,
                                 t.kind == TypeKind::Bool);
        sc.names[up] = Ref{Ref::Field, f, t.kind == TypeKind::Bool};
        if (shared) globals[up] = f;
        if (is_output(v) || shared) providers.emplace(up, std::make_pair(pi, f));
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
          sc.names[up] = Ref{Ref::Field, it->second.second, v.type.kind == TypeKind::Bool};
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
          const auto f = add_field(v.name, FieldKind::Variable, t.lo, t.hi,
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

  void make_fb(std::uint32_t pi, const model::Variable& v) {
    const auto& pou = *scopes[pi].pou;
    Fb fb;
    fb.name = pou.name + "." + v.name;
    fb.kind = v.type.fb;
    fb.pou = pi;
    switch (fb.kind) {
      case StandardFb::R_TRIG: case StandardFb::F_TRIG:
        fb.mem = static_cast<std::int32_t>(add_field(fb.name + ".M", FieldKind::FbState, 0, 1, 0, true));
        break;
      case StandardFb::CTU: case StandardFb::CTD:
        fb.mem = static_cast<std::int32_t>(add_field(fb.name + ".M", FieldKind::FbState, 0, 1, 0, true));
        fb.cv = static_cast<std::int32_t>(add_field(fb.name + ".CV", FieldKind::FbState, -32768, 32767, 0, false));
        break;
      case StandardFb::TP:
        fb.mem = static_cast<std::int32_t>(add_field(fb.name + ".IN", FieldKind::FbState, 0, 1, 0, true));
        break;
      case StandardFb::None:
        error(v.where, "'" + v.name + "' is an instance of an unsupported function block");
        return;
      default:
        break;
    }
    fb.q = static_cast<std::int32_t>(add_field(
        fb.name + (fb.kind == StandardFb::SR || fb.kind == StandardFb::RS ? ".Q1" : ".Q"),
        FieldKind::FbState, 0, 1, 0, true));
    p.fbs.push_back(fb);
    scopes[pi].names[model::to_upper(v.name)] =
        Ref{Ref::FbInst, static_cast<std::uint32_t>(p.fbs.size() - 1), false};
  }

  // ---------------------------------------------------------------------- expressions
  std::uint32_t node(Node n, std::vector<std::uint32_t> kids = {}) {
    n.first = static_cast<std::uint32_t>(p.kids.size());
    n.count = static_cast<std::uint32_t>(kids.size());
    p.kids.insert(p.kids.end(), kids.begin(), kids.end());
    p.nodes.push_back(n);
    return static_cast<std::uint32_t>(p.nodes.size() - 1);
  }
  std::uint32_t constant(std::int64_t k) {
    Node n;
    n.op = Op::Const;
    n.k = k;
    return node(n);
  }

  static std::optional<std::int64_t> literal(const model::Expr& e) {
    switch (e.kind) {
      case ExprKind::BoolConst: case ExprKind::IntConst: case ExprKind::TimeConst: return e.value;
      case ExprKind::Neg:
        if (auto v = literal(*e.args[0]); v && *v != std::numeric_limits<std::int64_t>::min())
          return -*v;
        return std::nullopt;
      default: return std::nullopt;
    }
  }

  // A step named `name` in the POU, preferring chart `context` (-1: none).
  std::optional<std::uint32_t> find_step(const PouScope& sc, std::string_view name, int context,
                                         const model::SourceLocation& where, bool report) {
    std::vector<std::uint32_t> hits;
    for (auto c : sc.chart_ids)
      for (auto s : p.charts[c].steps)
        if (model::iequals(p.steps[s].short_name, name)) {
          if (context >= 0 && c == static_cast<std::uint32_t>(context)) return s;
          hits.push_back(s);
        }
    if (hits.size() == 1) return hits.front();
    if (hits.size() > 1 && report) {
      std::string list;
      for (auto h : hits) list += " " + p.steps[h].name;
      error(where, "step name '" + std::string(name) + "' is ambiguous here:" + list);
    }
    return std::nullopt;
  }

  static Op op_of(ExprKind k) {
    switch (k) {
      case ExprKind::Not: return Op::Not;
      case ExprKind::Neg: return Op::Neg;
      case ExprKind::And: return Op::And;
      case ExprKind::Or: return Op::Or;
      case ExprKind::Xor: return Op::Xor;
      case ExprKind::Add: return Op::Add;
      case ExprKind::Sub: return Op::Sub;
      case ExprKind::Mul: return Op::Mul;
      case ExprKind::Div: return Op::Div;
      case ExprKind::Mod: return Op::Mod;
      case ExprKind::Eq: return Op::Eq;
      case ExprKind::Ne: return Op::Ne;
      case ExprKind::Lt: return Op::Lt;
      case ExprKind::Le: return Op::Le;
      case ExprKind::Gt: return Op::Gt;
      default: return Op::Ge;
    }
  }
  static Op flip(Op c) {
    switch (c) {
      case Op::Lt: return Op::Gt;
      case Op::Le: return Op::Ge;
      case Op::Gt: return Op::Lt;
      case Op::Ge: return Op::Le;
      default: return c;
    }
  }

  bool is_step_t(const PouScope& sc, const model::Expr& e, int context) {
    return e.kind == ExprKind::Member && model::iequals(e.member, "T") &&
           find_step(sc, e.name, context, e.where, false).has_value();
  }

  std::uint32_t compare(const PouScope& sc, const model::Expr& e, int context, VT& type) {
    type = VT::Bool;
    Op cmp = op_of(e.kind);
    const model::Expr* lhs = e.args[0].get();
    const model::Expr* rhs = e.args[1].get();
    // Step .T against a constant (the only use of .T sfcv supports: it keeps the state finite).
    if (is_step_t(sc, *rhs, context) && !is_step_t(sc, *lhs, context)) {
      std::swap(lhs, rhs);
      cmp = flip(cmp);
    }
    if (is_step_t(sc, *lhs, context)) {
      const auto k = literal(*rhs);
      const auto step = *find_step(sc, lhs->name, context, lhs->where, true);
      if (!k) {
        error(e.where, "'" + model::to_st(e) + "': a step's .T can only be compared with a constant");
        return constant(0);
      }
      if (p.options.time == TimeMode::Discrete) {
        auto& keys = t_keys[step];
        keys.insert(*k);
        Node n;
        n.op = Op::StepT;
        n.a = step;
        const auto t = node(n);
        return node(Node{cmp, Op::Eq, false, 0, 0, 0, 0}, {t, constant(*k)});
      }
      if (cmp == Op::Eq || cmp == Op::Ne) {
        error(e.where, "'" + model::to_st(e) + "': in abstract time a step's .T can only be compared "
                       "with <, <=, >, >= (use --time discrete for = and <>)");
        return constant(0);
      }
      // Region keys: "T >= c" passes key 2c; "T > c" passes key 2c+1.
      const std::int64_t key = (cmp == Op::Ge || cmp == Op::Lt) ? 2 * *k : 2 * *k + 1;
      const bool negate = cmp == Op::Lt || cmp == Op::Le;
      if (key <= 0) return constant(negate ? 0 : 1);  // T >= 0 always holds
      t_keys[step].insert(key);
      Node n;
      n.op = Op::StepTCmp;
      n.a = step;
      n.k = key;  // patched into a region index later
      n.negate = negate;
      const auto id = node(n);
      t_nodes.push_back(id);
      return id;
    }
    // An integer input against a constant: the successor function splits its interval.
    auto int_input = [&](const model::Expr& x) {
      if (x.kind != ExprKind::Name) return false;
      auto it = sc.names.find(model::to_upper(x.name));
      return it != sc.names.end() && it->second.kind == Ref::Input && !it->second.is_bool;
    };
    if (!int_input(*lhs) && int_input(*rhs)) {
      std::swap(lhs, rhs);
      cmp = flip(cmp);
    }
    if (lhs->kind == ExprKind::Name) {
      auto it = sc.names.find(model::to_upper(lhs->name));
      const auto k = literal(*rhs);
      if (it != sc.names.end() && it->second.kind == Ref::Input && !it->second.is_bool) {
        Node n;
        n.cmp = cmp;
        n.a = it->second.index;
        if (k) {
          n.op = Op::InputCmp;
          n.k = *k;
          return node(n);
        }
        // Against an expression: its value in this run is the split point.
        VT ot;
        const auto other = expr(sc, *rhs, context, ot);
        if (ot != VT::Int) error(e.where, "'" + model::to_st(e) + "' compares a number with a BOOL");
        n.op = Op::InputCmpExpr;
        return node(n, {other});
      }
    }
    VT lt, rt;
    const auto a = expr(sc, *e.args[0], context, lt);
    const auto b = expr(sc, *e.args[1], context, rt);
    if (lt == VT::Bool) rt = bool_if_literal(*e.args[1], rt);
    if (rt == VT::Bool) lt = bool_if_literal(*e.args[0], lt);
    if (lt != rt) error(e.where, "'" + model::to_st(e) + "' compares a BOOL with a number");
    else if (lt == VT::Bool && cmp != Op::Eq && cmp != Op::Ne)
      error(e.where, "'" + model::to_st(e) + "': ordering comparison of BOOL values");
    return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, {a, b});
  }

  // IEC 61131-3 (2.2.1): Boolean data may be written as the integer literals 0 and 1
  // (Beremiz exports `ORANGE_LIGHT := 1;`). Called only where a BOOL is expected.
  static VT bool_if_literal(const model::Expr& e, VT t) {
    return t == VT::Int && e.kind == ExprKind::IntConst && (e.value == 0 || e.value == 1) ? VT::Bool : t;
  }

  std::uint32_t expr(const PouScope& sc, const model::Expr& e, int context, VT& type) {
    switch (e.kind) {
      case ExprKind::BoolConst: type = VT::Bool; return constant(e.value);
      case ExprKind::IntConst: case ExprKind::TimeConst: type = VT::Int; return constant(e.value);
      case ExprKind::Name: {
        if (auto it = sc.names.find(model::to_upper(e.name)); it != sc.names.end()) {
          const auto& r = it->second;
          if (r.kind == Ref::FbInst) {
            error(e.where, "'" + e.name + "' is a function block instance; use one of its outputs");
            type = VT::Bool;
            return constant(0);
          }
          type = r.is_bool ? VT::Bool : VT::Int;
          Node n;
          n.op = r.kind == Ref::Field ? Op::Field : Op::Input;
          n.a = r.index;
          return node(n);
        }
        if (auto s = find_step(sc, e.name, context, e.where, true)) {
          type = VT::Bool;
          Node n;
          n.op = Op::StepX;
          n.a = *s;
          return node(n);
        }
        error(e.where, "unknown name '" + e.name + "' in " + sc.pou->name);
        type = VT::Bool;
        return constant(0);
      }
      case ExprKind::Member: return member(sc, e, context, type);
      case ExprKind::Not: case ExprKind::Neg: {
        VT t;
        const auto a = expr(sc, *e.args[0], context, t);
        if (e.kind == ExprKind::Not) t = bool_if_literal(*e.args[0], t);
        if (e.kind == ExprKind::Not && t != VT::Bool)
          error(e.where, "'" + model::to_st(e) + "': bitwise NOT on integers is not supported");
        if (e.kind == ExprKind::Neg && t != VT::Int) error(e.where, "'" + model::to_st(e) + "': negation of a BOOL");
        type = t;
        return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, {a});
      }
      case ExprKind::And: case ExprKind::Or: case ExprKind::Xor: {
        std::vector<std::uint32_t> kids;
        for (const auto& a : e.args) {
          VT t;
          kids.push_back(expr(sc, *a, context, t));
          if (bool_if_literal(*a, t) != VT::Bool)
            error(a->where.known() ? a->where : e.where,
                  "'" + model::to_st(e) + "': bitwise AND/OR/XOR on integers is not supported");
        }
        type = VT::Bool;
        return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, std::move(kids));
      }
      case ExprKind::Add: case ExprKind::Sub: case ExprKind::Mul: case ExprKind::Div: case ExprKind::Mod: {
        VT a, b;
        const auto x = expr(sc, *e.args[0], context, a);
        const auto y = expr(sc, *e.args[1], context, b);
        if (a != VT::Int || b != VT::Int) error(e.where, "'" + model::to_st(e) + "': arithmetic on BOOL");
        type = VT::Int;
        return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, {x, y});
      }
      case ExprKind::Eq: case ExprKind::Ne: case ExprKind::Lt: case ExprKind::Le: case ExprKind::Gt: case ExprKind::Ge:
        return compare(sc, e, context, type);
      case ExprKind::Rising: case ExprKind::Falling: case ExprKind::Delay:
        error(e.where, "'" + model::to_st(e) + "' is Grafcet syntax, not IEC 61131-3 (use R_TRIG/F_TRIG, TON)");
        type = VT::Bool;
        return constant(0);
    }
    type = VT::Bool;
    return constant(0);
  }

  std::uint32_t member(const PouScope& sc, const model::Expr& e, int context, VT& type) {
    const auto mem = model::to_upper(e.member);
    type = VT::Bool;
    if (auto it = sc.names.find(model::to_upper(e.name)); it != sc.names.end() && it->second.kind == Ref::FbInst) {
      const auto& fb = p.fbs[it->second.index];
      const bool timer = fb.kind == StandardFb::TON || fb.kind == StandardFb::TOF || fb.kind == StandardFb::TP;
      const bool counter = fb.kind == StandardFb::CTU || fb.kind == StandardFb::CTD;
      const bool q1 = fb.kind == StandardFb::SR || fb.kind == StandardFb::RS;
      if ((mem == "Q" && !q1) || (mem == "Q1" && q1)) {
        Node n;
        n.op = Op::Field;
        n.a = static_cast<std::uint32_t>(fb.q);
        return node(n);
      }
      if (mem == "CV" && counter) {
        type = VT::Int;
        Node n;
        n.op = Op::Field;
        n.a = static_cast<std::uint32_t>(fb.cv);
        return node(n);
      }
      if (mem == "ET" && timer) {
        if (p.options.time == TimeMode::Abstract) {
          error(e.where, "'" + model::to_st(e) + "': a timer's ET has no value in abstract time "
                         "(use --time discrete)");
          return constant(0);
        }
        type = VT::Int;
        Node n;
        n.op = Op::TimerET;
        n.a = it->second.index;
        return node(n);
      }
      error(e.where, "'" + model::to_st(e) + "': " + std::string(model::to_string(fb.kind)) +
                         " has no output " + e.member + " sfcv supports");
      return constant(0);
    }
    if (mem == "X") {
      if (auto s = find_step(sc, e.name, context, e.where, true)) {
        Node n;
        n.op = Op::StepX;
        n.a = *s;
        return node(n);
      }
    }
    if (mem == "T" && find_step(sc, e.name, context, e.where, false)) {
      error(e.where, "'" + model::to_st(e) + "': a step's .T can only be compared with a constant");
      return constant(0);
    }
    if (mem == "A" || mem == "Q") {
      if (auto it = sc.actions.find(model::to_upper(e.name)); it != sc.actions.end()) {
        Node n;
        n.op = Op::Field;
        n.a = p.actions[it->second].active;
        return node(n);
      }
    }
    error(e.where, "unknown name '" + e.name + "." + e.member + "' in " + sc.pou->name);
    return constant(0);
  }

  std::uint32_t bool_expr(const PouScope& sc, const model::ExprPtr& e, int context,
                          const model::SourceLocation& where, const char* what) {
    if (!e) return constant(1);
    VT t;
    const auto n = expr(sc, *e, context, t);
    if (bool_if_literal(*e, t) != VT::Bool) error(e->where.known() ? e->where : where, std::string(what) + " '" + model::to_st(e) + "' is not Boolean");
    return n;
  }

  // ------------------------------------------------------------------------ statements
  Block block(const PouScope& sc, const model::StmtList& body,
              const std::vector<std::pair<std::uint32_t, std::uint32_t>>& input_copies = {}) {
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

  std::uint32_t stmt(const PouScope& sc, const model::Stmt& s) {
    Stmt out;
    out.where = s.where.str();
    switch (s.kind) {
      case model::StmtKind::Assign: {
        out.op = SOp::Assign;
        auto it = sc.names.find(model::to_upper(s.target));
        VT t;
        out.expr = s.value ? expr(sc, *s.value, -1, t) : constant(0);
        if (it == sc.names.end()) {
          error(s.where, "assignment to unknown variable '" + s.target + "'");
        } else if (it->second.kind != Ref::Field) {
          error(s.where, "assignment to '" + s.target + "', which is " +
                             (it->second.kind == Ref::Input ? "an input" : "a function block instance"));
        } else {
          out.target = it->second.index;
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
          arms.push_back(IfArm{bool_expr(sc, s.conditions[i], -1, s.where, "condition"), block(sc, s.bodies[i])});
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
        if (const auto* act = called_action(sc, s)) {
          // `ACT();` runs the action's statements at that point of the body (IEC 61131-3
          // allows calling an action of the same POU): an IF TRUE around them.
          out.op = SOp::If;
          if (act->kind != model::ActionBodyKind::Statements || act->body_unsupported) {
            error(s.where, "call of action '" + act->name + "' of " + sc.pou->name + ": " +
                               (act->body_unsupported ? "its body is not modelled"
                                                      : "only actions with an ST/FBD/LD body can be called"));
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
        out.op = SOp::FbCall;
        fb_call(sc, s, out);
        break;
    }
    p.stmts.push_back(out);
    return static_cast<std::uint32_t>(p.stmts.size() - 1);
  }

  /// The action of the POU a call statement `NAME();` names (no variable of that name).
  const model::Action* called_action(const PouScope& sc, const model::Stmt& s) const {
    if (!s.arguments.empty() || sc.names.count(model::to_upper(s.target))) return nullptr;
    return sc.pou->find_action(s.target);
  }

  void fb_call(const PouScope& sc, const model::Stmt& s, Stmt& out) {
    auto it = sc.names.find(model::to_upper(s.target));
    if (it == sc.names.end() || it->second.kind != Ref::FbInst) {
      error(s.where, "call of '" + s.target + "', which is not an instance of a standard function "
                     "block (instances of user function blocks are not modelled; check the function "
                     "block's own POU with --pou)");
      return;
    }
    out.target = it->second.index;
    auto& fb = p.fbs[out.target];
    std::vector<std::string> params;
    switch (fb.kind) {
      case StandardFb::R_TRIG: case StandardFb::F_TRIG: params = {"CLK"}; break;
      case StandardFb::SR: params = {"S1", "R"}; break;
      case StandardFb::RS: params = {"S", "R1"}; break;
      case StandardFb::TON: case StandardFb::TOF: case StandardFb::TP: params = {"IN", "PT"}; break;
      case StandardFb::CTU: params = {"CU", "R", "PV"}; break;
      case StandardFb::CTD: params = {"CD", "LD", "PV"}; break;
      default: return;
    }
    std::vector<std::int32_t> nodes(params.size(), kNone);
    // CODESYS's reset idiom `T(IN := FALSE, PT := T#0MS)` beside `T(IN := x, PT := T#5S)`: a
    // TON with IN = FALSE is idle whatever PT is (Q = FALSE, ET = 0), so the PT of such a call
    // is not one of the instance's PT values. (TOF and TP do use PT while IN is FALSE.)
    bool pt_irrelevant = false;
    if (fb.kind == StandardFb::TON)
      for (const auto& [name, value] : s.arguments)
        if (model::iequals(name, "IN") && value && literal(*value) == 0) pt_irrelevant = true;
    bool pt_given = false;
    for (const auto& [written_name, value] : s.arguments) {
      auto up = model::to_upper(written_name);
      // CODESYS and TwinCAT name the counters' reset/load inputs RESET and LOAD (IEC: R, LD).
      if (fb.kind == StandardFb::CTU && up == "RESET") up = "R";
      if (fb.kind == StandardFb::CTD && up == "LOAD") up = "LD";
      const auto& name = written_name;
      auto pos = std::find(params.begin(), params.end(), up);
      if (pos == params.end()) {
        error(s.where, "'" + s.target + "' (" + std::string(model::to_string(fb.kind)) +
                           ") has no input '" + name + "'");
        continue;
      }
      const auto i = static_cast<std::size_t>(pos - params.begin());
      if (up == "PT" && pt_irrelevant) continue;
      if (up == "PT") {
        pt_given = true;
        std::optional<std::int64_t> pt = literal(*value);
        if (!pt && value->kind == ExprKind::Name) {
          const auto* var = sc.pou->find_variable(value->name);
          if (var && !written.count(model::to_upper(sc.pou->name) + "|" + model::to_upper(var->name)) &&
              var->direction != model::VarDirection::Input)
            pt = var->initial.value_or(0);
        }
        if (!pt) {
          error(value->where.known() ? value->where : s.where,
                "PT of '" + s.target + "' must be a constant (a literal or a variable no statement writes)");
          continue;
        }
        // Abstract time only distinguishes PT = 0 (at once) from PT > 0 (some later cycle), so
        // calls with different positive PTs (CODESYS's PPU) share one timer; discrete time
        // counts cycles and needs one PT.
        const bool same_abstract = p.options.time == TimeMode::Abstract && (fb.pt_ms > 0) == (*pt > 0);
        if (fb.pt_set && fb.pt_ms != *pt && !same_abstract) {
          error(s.where, "'" + s.target + "' is called with different PT values" +
                             std::string(p.options.time == TimeMode::Abstract
                                             ? " (zero and positive)"
                                             : "; discrete time needs one (--time abstract accepts several positive ones)"));
          continue;
        }
        if (fb.pt_set) continue;
        fb.pt_ms = *pt;
        fb.pt_set = true;
        continue;
      }
      VT t;
      nodes[i] = static_cast<std::int32_t>(expr(sc, *value, -1, t));
      const bool want_int = up == "PV";
      if (!want_int) t = bool_if_literal(*value, t);
      if ((t == VT::Int) != want_int)
        error(value->where.known() ? value->where : s.where,
              "input " + name + " of '" + s.target + "' has the wrong type");
    }
    for (std::size_t i = 0; i < params.size(); ++i)
      if (nodes[i] == kNone && params[i] != "PT")
        error(s.where, "call of '" + s.target + "' must give " + params[i] +
                           " (sfcv does not keep function block inputs between calls)");
    if (params.size() == 2 && params[1] == "PT") {
      // A call without PT keeps the PT of the previous call, T#0s before any (TwinCAT code
      // often gives none): decided once every call is compiled (finish_timers).
      if (!pt_given && !pt_irrelevant) omitted_pt.emplace(out.target, s.where);
      called_timers.insert(out.target);
      if (fb.pt_set && fb.timer == kNone) fb.timer = make_timer(fb.name, fb.pt_ms, fb.name);
    }
    out.arg1 = nodes[0];
    if (nodes.size() > 1) out.arg2 = nodes[1];
    if (nodes.size() > 2) out.arg3 = nodes[2];
  }

  /// Timers some call leaves without PT: sound only when no call gives a PT other than T#0s
  /// (then PT is T#0s throughout); timers only called with IN = FALSE get T#0s too.
  void finish_timers() {
    for (const auto& [index, where] : omitted_pt) {
      auto& fb = p.fbs[index];
      if (fb.pt_set && fb.pt_ms != 0) {
        error(where, "a call of '" + fb.name + "' gives no PT while another gives " +
                         std::to_string(fb.pt_ms) + " ms: PT is then T#0s or that value depending "
                         "on the order of the calls; give PT in every call");
        continue;
      }
      fb.pt_ms = 0;
      fb.pt_set = true;
    }
    for (const auto index : called_timers) {
      auto& fb = p.fbs[index];
      if (fb.timer != kNone) continue;
      if (!fb.pt_set) {  // never called, or only with IN = FALSE
        fb.pt_ms = 0;
        fb.pt_set = true;
      }
      fb.timer = make_timer(fb.name, fb.pt_ms, fb.name);
    }
  }

  std::int32_t make_timer(const std::string& field_name, std::int64_t d, const std::string& timeout_name) {
    Timer t;
    t.duration_ms = d;
    if (p.options.time == TimeMode::Abstract) {
      t.max_value = 2;
      t.timeout_input = static_cast<std::int32_t>(add_input("timeout:" + timeout_name, model::Type::boolean(), true));
    } else {
      const auto c = std::max<std::int64_t>(p.options.cycle_ms, 1);
      t.max_value = 1 + (d <= 0 ? 0 : (d + c - 1) / c);
    }
    t.field = add_field(field_name, FieldKind::Timer, 0, t.max_value, 0, false);
    p.timers.push_back(t);
    return static_cast<std::int32_t>(p.timers.size() - 1);
  }

  // ----------------------------------------------------------------- charts and actions
  void structure() {
    // Steps and charts.
    for (auto& sc : scopes) {
      const auto& pou = *sc.pou;
      Pou cp;
      cp.name = pou.name;
      for (std::size_t ci = 0; ci < pou.charts.size(); ++ci) {
        const auto& ch = pou.charts[ci];
        Chart c;
        c.pou = sc.index;
        const auto cid = static_cast<std::uint32_t>(p.charts.size());
        sc.chart_ids.push_back(cid);
        cp.charts.push_back(cid);
        bool has_initial = false;
        for (const auto& st : ch.steps) {
          if (st.kind != model::StepKind::Normal)
            error(st.where, "step '" + st.name + "' is a Grafcet macro/enclosing step, not IEC 61131-3");
          Step s;
          s.short_name = st.name;
          s.name = pou.name + "." + (ch.parent_action.empty() ? "" : ch.parent_action + ".") + st.name;
          s.chart = cid;
          s.initial = st.initial;
          has_initial |= st.initial;
          s.ready = add_field(s.name, FieldKind::StepReady, 0, 1, 0, true);
          c.steps.push_back(static_cast<std::uint32_t>(p.steps.size()));
          p.steps.push_back(std::move(s));
        }
        if (!has_initial) error(ch.where, "chart '" + ch.name + "' of " + pou.name + " has no initial step");
        p.charts.push_back(std::move(c));
      }
      p.pous.push_back(std::move(cp));
    }
    // Actions.
    for (auto& sc : scopes) {
      const auto& pou = *sc.pou;
      for (const auto& a : pou.actions) add_action(sc, a.name, a.kind, a.where);
    }
    // Nested charts: their parent actions.
    for (auto& sc : scopes) {
      const auto& pou = *sc.pou;
      for (std::size_t ci = 0; ci < pou.charts.size(); ++ci) {
        const auto& ch = pou.charts[ci];
        if (ch.parent_action.empty()) continue;
        const auto* act = pou.find_action(ch.parent_action);
        auto it = sc.actions.find(model::to_upper(ch.parent_action));
        if (!act || it == sc.actions.end() || act->kind != model::ActionBodyKind::Chart) {
          error(ch.where, "chart '" + ch.name + "' is the body of '" + ch.parent_action +
                              "', which is not an SFC action of " + pou.name);
          continue;
        }
        p.charts[sc.chart_ids[ci]].parent_action = static_cast<std::int32_t>(it->second);
      }
    }
  }

  std::uint32_t add_action(PouScope& sc, const std::string& name, model::ActionBodyKind kind,
                           const model::SourceLocation& where) {
    const auto up = model::to_upper(name);
    if (auto it = sc.actions.find(up); it != sc.actions.end()) {
      error(where, "action '" + name + "' is declared twice in " + sc.pou->name);
      return it->second;
    }
    Action a;
    a.name = sc.pou->name + "." + name;
    a.pou = sc.index;
    a.kind = kind;
    a.active = add_field(a.name, FieldKind::ActionActive, 0, 1, 0, true);
    p.actions.push_back(std::move(a));
    const auto id = static_cast<std::uint32_t>(p.actions.size() - 1);
    sc.actions[up] = id;
    Observable o;
    o.name = p.actions[id].name;
    o.aliases = {name, name + ".A"};
    o.kind = ObservableKind::Action;
    o.type = model::Type::boolean();
    p.observables.push_back(std::move(o));
    p.observable_refs.push_back(ObservableRef{ObservableKind::Action, id});
    return id;
  }

  void actions_and_transitions() {
    for (auto& sc : scopes) {
      const auto& pou = *sc.pou;
      auto& cp = p.pous[sc.index];
      cp.body = block(sc, pou.body, sc.input_copies);
      // Action bodies.
      for (const auto& a : pou.actions) {
        auto& ca = p.actions[sc.actions[model::to_upper(a.name)]];
        if (a.kind == model::ActionBodyKind::Statements) {
          ca.body = block(sc, a.body);
        } else if (a.kind == model::ActionBodyKind::Variable) {
          auto it = sc.names.find(model::to_upper(a.variable));
          if (it == sc.names.end() || it->second.kind != Ref::Field || !it->second.is_bool)
            error(a.where, "action '" + a.name + "' names '" + a.variable +
                               "', which is not a Boolean variable sfcv can write");
          else
            ca.variable = static_cast<std::int32_t>(it->second.index);
        }
      }
      // Associations.
      for (const auto& as : pou.associations) {
        std::optional<std::uint32_t> step;
        if (!as.chart.empty()) {
          const int ci = pou.chart_index(as.chart);
          if (ci < 0) {
            error(as.where, "unknown chart '" + as.chart + "'");
            continue;
          }
          const int si = pou.charts[static_cast<std::size_t>(ci)].step_index(as.step);
          if (si >= 0) step = p.charts[sc.chart_ids[static_cast<std::size_t>(ci)]].steps[static_cast<std::size_t>(si)];
        } else {
          step = find_step(sc, as.step, -1, as.where, true);
        }
        if (!step) {
          error(as.where, "action block of unknown step '" + as.step + "'");
          continue;
        }
        auto it = sc.actions.find(model::to_upper(as.action));
        if (it == sc.actions.end()) {
          // An action block may name a Boolean variable directly.
          auto v = sc.names.find(model::to_upper(as.action));
          if (v == sc.names.end() || v->second.kind != Ref::Field || !v->second.is_bool) {
            error(as.where, "action block names '" + as.action +
                                "', which is neither an action nor a Boolean variable of " + pou.name);
            continue;
          }
          const auto id = add_action(sc, as.action, model::ActionBodyKind::Variable, as.where);
          p.actions[id].variable = static_cast<std::int32_t>(v->second.index);
          it = sc.actions.find(model::to_upper(as.action));
        }
        if (const auto* ma = pou.find_action(as.action); ma && ma->body_unsupported) {
          error(as.where, "step '" + as.step + "' activates action '" + ma->name +
                              "', whose body sfcv does not model (" + ma->unsupported_reason + ")");
          continue;
        }
        Assoc ca;
        ca.step = *step;
        ca.action = it->second;
        ca.q = as.qualifier;
        if (as.qualifier == Qualifier::DL) {
          error(as.where, "qualifier DL is not defined by IEC 61131-3 (use D, L, SD, DS or SL)");
          continue;
        }
        if (model::is_timed(as.qualifier)) {
          std::optional<std::int64_t> d = as.duration_ms;
          if (!d && !as.duration_variable.empty()) {
            const auto* var = pou.find_variable(as.duration_variable);
            if (var && !written.count(model::to_upper(pou.name) + "|" + model::to_upper(var->name)))
              d = var->initial.value_or(0);
          }
          if (!d) {
            error(as.where, "qualifier " + std::string(model::to_string(as.qualifier)) +
                                " needs a constant duration");
            continue;
          }
          const std::string nm = p.steps[*step].name + "." + as.action + "." +
                                 std::string(model::to_string(as.qualifier));
          ca.timer = make_timer(nm, *d, nm);
          if (as.qualifier == Qualifier::SD || as.qualifier == Qualifier::SL)
            ca.latch = static_cast<std::int32_t>(add_field(nm + ".set", FieldKind::ActionStored, 0, 1, 0, true));
        }
        auto& act = p.actions[ca.action];
        if ((as.qualifier == Qualifier::S || as.qualifier == Qualifier::DS) && act.stored == kNone)
          act.stored = static_cast<std::int32_t>(add_field(act.name + ".stored", FieldKind::ActionStored, 0, 1, 0, true));
        p.assocs.push_back(ca);
        act.assocs.push_back(static_cast<std::uint32_t>(p.assocs.size() - 1));
      }
      // Transitions.
      for (std::size_t ci = 0; ci < pou.charts.size(); ++ci) {
        const auto& ch = pou.charts[ci];
        const auto cid = sc.chart_ids[ci];
        // Indexed once per chart: Chart::step_index per transition is quadratic on long charts.
        std::unordered_map<std::string, int> step_of;
        for (std::size_t i = 0; i < ch.steps.size(); ++i)
          step_of.try_emplace(model::to_upper(ch.steps[i].name), static_cast<int>(i));
        for (const auto& t : ch.transitions) {
          Transition ct;
          ct.chart = cid;
          bool good = true;
          auto resolve = [&](const std::vector<std::string>& names, std::vector<std::uint32_t>& out) {
            for (const auto& n : names) {
              const auto found = step_of.find(model::to_upper(n));
              const int si = found == step_of.end() ? -1 : found->second;
              if (si < 0) {
                error(t.where, "transition refers to unknown step '" + n + "' of chart '" + ch.name + "'");
                good = false;
              } else {
                out.push_back(p.charts[cid].steps[static_cast<std::size_t>(si)]);
              }
            }
          };
          resolve(t.sources, ct.sources);
          resolve(t.targets, ct.targets);
          if (ct.sources.empty() || ct.targets.empty()) {
            if (good) error(t.where, "transition without source or target step");
            continue;
          }
          ct.guard = bool_expr(sc, t.guard, static_cast<int>(cid), t.where, "transition condition");
          ct.rank = (static_cast<std::int64_t>(t.priority.value_or(std::numeric_limits<int>::max())) << 32) +
                    t.order;
          ct.index = static_cast<std::uint32_t>(p.transitions.size());
          TransitionInfo info;
          const std::string prefix = pou.name + (ch.parent_action.empty() ? "" : "." + ch.parent_action);
          if (!t.name.empty()) {
            info.name = prefix + "." + t.name;
          } else {
            std::string src, dst;
            for (auto s : t.sources) src += (src.empty() ? "" : ", ") + s;
            for (auto s : t.targets) dst += (dst.empty() ? "" : ", ") + s;
            info.name = prefix + ": " + src + " -> " + dst;
          }
          info.pou = pou.name;
          info.chart = ch.name;
          info.where = t.where;
          p.transition_infos.push_back(std::move(info));
          p.transitions.push_back(std::move(ct));
        }
      }
    }
    // Per chart: priority order, or the groups of alternatives for PriorityMode::None.
    for (std::uint32_t ti = 0; ti < p.transitions.size(); ++ti) p.charts[p.transitions[ti].chart].ordered.push_back(ti);
    for (auto& c : p.charts) {
      std::stable_sort(c.ordered.begin(), c.ordered.end(), [&](auto a, auto b) {
        return p.transitions[a].rank < p.transitions[b].rank;
      });
      if (p.options.priority != PriorityMode::None) continue;
      std::vector<std::uint8_t> grouped(p.transitions.size());
      // Document order within the group.
      std::vector<std::uint32_t> doc = c.ordered;
      std::stable_sort(doc.begin(), doc.end(), [&](auto a, auto b) {
        return (p.transitions[a].rank & 0xffffffff) < (p.transitions[b].rank & 0xffffffff);
      });
      for (auto s : c.steps) {
        std::vector<std::uint32_t> out;
        for (auto ti : doc)
          if (std::find(p.transitions[ti].sources.begin(), p.transitions[ti].sources.end(), s) !=
              p.transitions[ti].sources.end())
            out.push_back(ti);
        if (out.size() < 2) continue;
        bool simple = true;
        for (auto ti : out)
          if (p.transitions[ti].sources.size() != 1) {
            error(p.transition_infos[ti].where,
                  "with --priority none, transition '" + p.transition_infos[ti].name +
                      "' synchronises several steps and conflicts with another transition leaving '" +
                      p.steps[s].short_name + "'; sfcv cannot model this conflict faithfully");
            simple = false;
          }
        if (!simple) continue;
        AltGroup g;
        g.step = s;
        g.transitions = out;
        g.choice_input = add_input("choice:" + p.steps[s].name,
                                   model::Type::integer("INT", 0, static_cast<std::int64_t>(out.size()) - 1), true);
        for (auto ti : out) grouped[ti] = 1;
        c.groups.push_back(std::move(g));
      }
      for (auto ti : doc)
        if (!grouped[ti]) c.singles.push_back(ti);
    }
  }

  void orders() {
    for (auto& sc : scopes) {
      auto& cp = p.pous[sc.index];
      std::vector<std::uint32_t> acts;
      for (const auto& [up, id] : sc.actions) acts.push_back(id);
      std::sort(acts.begin(), acts.end());  // creation order = declaration order
      cp.exec_order = acts;
      if (p.options.action_order == ActionOrder::Alphabetical)
        std::stable_sort(cp.exec_order.begin(), cp.exec_order.end(), [&](auto a, auto b) {
          return model::to_upper(p.actions[a].name) < model::to_upper(p.actions[b].name);
        });
      // Topological order: an action after the actions holding the charts of its steps.
      std::vector<int> mark(p.actions.size(), 0);
      std::function<void(std::uint32_t)> visit = [&](std::uint32_t a) {
        if (mark[a] == 2) return;
        if (mark[a] == 1) {
          error(sc.pou->where, "action '" + p.actions[a].name +
                                   "' is associated with a step of a chart it (indirectly) holds");
          return;
        }
        mark[a] = 1;
        for (auto x : p.actions[a].assocs) {
          const auto pa = p.charts[p.steps[p.assocs[x].step].chart].parent_action;
          if (pa != kNone) visit(static_cast<std::uint32_t>(pa));
        }
        mark[a] = 2;
        cp.topo_order.push_back(a);
      };
      for (auto a : acts) visit(a);
    }
  }

  void step_timers() {
    const auto cycle = std::max<std::int64_t>(p.options.cycle_ms, 1);
    for (auto& [step, keys] : t_keys) {
      auto& s = p.steps[step];
      if (p.options.time == TimeMode::Discrete) {
        const auto mx = std::max<std::int64_t>(*keys.rbegin(), 0);
        s.t_max = mx / cycle + 1;
        s.t_field = static_cast<std::int32_t>(add_field(s.name + ".T", FieldKind::Timer, 0, s.t_max, 0, false));
      } else {
        s.thresholds.assign(keys.begin(), keys.end());
        const auto top = static_cast<std::int64_t>(s.thresholds.size());
        s.t_field = static_cast<std::int32_t>(add_field(s.name + ".T", FieldKind::Timer, 0, top, 0, false));
        s.elapse_input = static_cast<std::int32_t>(
            add_input("elapse:" + s.name, model::Type::integer("INT", 0, top), true));
      }
    }
    for (auto n : t_nodes) {
      auto& node = p.nodes[n];
      const auto& th = p.steps[node.a].thresholds;
      node.k = (std::lower_bound(th.begin(), th.end(), node.k) - th.begin()) + 1;
    }
  }

  void step_observables() {
    for (std::uint32_t i = 0; i < p.steps.size(); ++i) {
      const auto& s = p.steps[i];
      Observable o;
      o.name = s.name;
      o.aliases = {s.short_name, s.short_name + ".X", s.name + ".X"};
      o.kind = ObservableKind::Step;
      o.type = model::Type::boolean();
      p.observables.push_back(std::move(o));
      p.observable_refs.push_back(ObservableRef{ObservableKind::Step, i});
    }
  }

  /// Grafcet-only content and duplicates the IEC semantics would otherwise silently merge.
  void reject_foreign(const std::vector<const model::Pou*>& pous) {
    if (project.dialect == model::Dialect::Grafcet)
      error(project.where, "this is a Grafcet (IEC 60848) model; the IEC 61131-3 scan-cycle "
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

  bool run() {
    const auto pous = select();
    if (!ok) return false;
    reject_foreign(pous);
    if (!ok) return false;
    variables(pous);
    structure();
    actions_and_transitions();
    finish_timers();
    orders();
    for (const auto& a : p.options.assumptions)
      if (a) p.assumptions.push_back(bool_expr(scopes.front(), a, -1, a->where, "assumption"));
    step_timers();
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
    return ok;
  }
};

}  // namespace

bool compile(const model::Project& project, const Iec61131Options& options, Program& program,
             model::Diagnostics& diagnostics) {
  program.options = options;
  if (program.options.cycle_ms <= 0) program.options.cycle_ms = 1;
  Compiler c(project, program, diagnostics);
  return c.run();
}

}  // namespace sfcv::semantics::iec

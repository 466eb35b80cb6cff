// The IEC compiler's expressions: guards, conditions and right-hand sides into Program nodes,
// with step .T comparisons, member access and the integer/Boolean typing of the scan cycle.

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

std::uint32_t Compiler::node(Node n, std::vector<std::uint32_t> kids) {
  n.first = static_cast<std::uint32_t>(p.kids.size());
  n.count = static_cast<std::uint32_t>(kids.size());
  p.kids.insert(p.kids.end(), kids.begin(), kids.end());
  p.nodes.push_back(n);
  if (n.op == Op::Field && !first_read.count(n.a)) first_read.emplace(n.a, reading_at);
  return static_cast<std::uint32_t>(p.nodes.size() - 1);
}

std::uint32_t Compiler::constant(std::int64_t k) {
  Node n;
  n.op = Op::Const;
  n.k = k;
  return node(n);
}

std::optional<std::int64_t> Compiler::literal(const model::Expr& e) {
  switch (e.kind) {
    case ExprKind::BoolConst:
    case ExprKind::IntConst:
    case ExprKind::TimeConst:
      return e.value;
    case ExprKind::Neg:
      if (auto v = literal(*e.args[0]); v && *v != std::numeric_limits<std::int64_t>::min())
        return -*v;
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

std::optional<std::uint32_t> Compiler::find_step(const PouScope& sc, std::string_view name,
                                                 int context, const model::SourceLocation& where,
                                                 bool report) {
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

Op Compiler::op_of(ExprKind k) {
  switch (k) {
    case ExprKind::Not:
      return Op::Not;
    case ExprKind::Neg:
      return Op::Neg;
    case ExprKind::And:
      return Op::And;
    case ExprKind::Or:
      return Op::Or;
    case ExprKind::Xor:
      return Op::Xor;
    case ExprKind::Add:
      return Op::Add;
    case ExprKind::Sub:
      return Op::Sub;
    case ExprKind::Mul:
      return Op::Mul;
    case ExprKind::Div:
      return Op::Div;
    case ExprKind::Mod:
      return Op::Mod;
    case ExprKind::Eq:
      return Op::Eq;
    case ExprKind::Ne:
      return Op::Ne;
    case ExprKind::Lt:
      return Op::Lt;
    case ExprKind::Le:
      return Op::Le;
    case ExprKind::Gt:
      return Op::Gt;
    default:
      return Op::Ge;
  }
}

Op Compiler::flip(Op c) {
  switch (c) {
    case Op::Lt:
      return Op::Gt;
    case Op::Le:
      return Op::Ge;
    case Op::Gt:
      return Op::Lt;
    case Op::Ge:
      return Op::Le;
    default:
      return c;
  }
}

bool Compiler::is_step_t(const PouScope& sc, const model::Expr& e, int context) {
  return e.kind == ExprKind::Member && model::iequals(e.member, "T") &&
         find_step(sc, e.name, context, e.where, false).has_value();
}

std::uint32_t Compiler::compare(const PouScope& sc, const model::Expr& e, int context, VT& type) {
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
      error(e.where, "'" + model::to_st(e) +
                         "': in abstract time a step's .T can only be compared "
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
  // (A name of the scope, or an unqualified global: a free one is an input, 1.8.)
  auto int_input = [&](const model::Expr& x) -> std::optional<Ref> {
    if (x.kind != ExprKind::Name) return std::nullopt;
    const auto up = model::to_upper(x.name);
    auto it = sc.names.find(up);
    const auto r = it != sc.names.end() ? std::optional<Ref>(it->second) : global_ref(up);
    if (r && r->kind == Ref::Input && !r->is_bool) return r;
    return std::nullopt;
  };
  if (!int_input(*lhs) && int_input(*rhs)) {
    std::swap(lhs, rhs);
    cmp = flip(cmp);
  }
  if (lhs->kind == ExprKind::Name) {
    const auto in = int_input(*lhs);
    const auto k = literal(*rhs);
    if (in) {
      Node n;
      n.cmp = cmp;
      n.a = in->index;
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
  // `NOT x >= k` with an integer x is `(NOT x) >= k` (NOT binds tighter than a comparison,
  // IEC 61131-3 table of ST operators): read so, but say so, as `NOT (x >= k)` is often meant.
  for (std::size_t i = 0; i < 2; ++i)
    if (e.args[i]->kind == ExprKind::Not && (i == 0 ? lt : rt) == VT::Int) {
      model::Expr meant = e;
      meant.args[i] = e.args[i]->args[0];
      diags.push_back({model::Severity::Warning, e.where,
                       "'" + model::to_st(e) + "' compares the bitwise complement of " +
                           model::to_st(*meant.args[i]) +
                           " (NOT binds tighter than a comparison in IEC 61131-3); write NOT (" +
                           model::to_st(meant) + ") if the negated comparison is meant"});
    }
  if (lt != rt)
    error(e.where, "'" + model::to_st(e) + "' compares a BOOL with a number");
  else if (lt == VT::Bool && cmp != Op::Eq && cmp != Op::Ne)
    error(e.where, "'" + model::to_st(e) + "': ordering comparison of BOOL values");
  return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, {a, b});
}

VT Compiler::bool_if_literal(const model::Expr& e, VT t) {
  return t == VT::Int && e.kind == ExprKind::IntConst && (e.value == 0 || e.value == 1) ? VT::Bool
                                                                                        : t;
}

std::uint32_t Compiler::expr(const PouScope& sc, const model::Expr& e, int context, VT& type) {
  reading(sc, e.where);
  switch (e.kind) {
    case ExprKind::BoolConst:
      type = VT::Bool;
      return constant(e.value);
    case ExprKind::IntConst:
    case ExprKind::TimeConst:
      type = VT::Int;
      return constant(e.value);
    case ExprKind::UnmodelledConst:
      error(e.where, "unsupported: literal " + e.name);
      type = VT::Int;
      return constant(0);
    case ExprKind::StringConst:  // lowered by the readers (model::lower_data_types)
    case ExprKind::Index:
      error(e.where, "unsupported: '" + model::to_st(e) + "' (not lowered)");
      type = VT::Int;
      return constant(0);
    case ExprKind::Name: {
      std::optional<Ref> found;
      if (auto it = sc.names.find(model::to_upper(e.name)); it != sc.names.end())
        found = it->second;
      else
        found = global_ref(model::to_upper(e.name));  // an unqualified global
      if (found) {
        const auto& r = *found;
        if (r.kind == Ref::FbInst || r.kind == Ref::Instance) {
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
      if (const auto dot = e.name.rfind('.'); dot != std::string::npos) {
        // A chain kept as one name (`GVL.IsSFCResetting` in a TwinCAT condition network):
        // the member chain it is.
        const auto m = model::make_member(e.name.substr(0, dot), e.name.substr(dot + 1), e.where);
        return member(sc, *m, context, type);
      }
      error(e.where, "unknown name '" + e.name + "' in " + sc.pou->name);
      type = VT::Bool;
      return constant(0);
    }
    case ExprKind::Member:
      if (is_bit_access(e)) return bit_access(sc, e, context, type);
      return member(sc, e, context, type);
    case ExprKind::Call:
      return call(sc, e, context, type);
    case ExprKind::Not:
    case ExprKind::Neg: {
      if (e.kind == ExprKind::Not && bit_width(sc, *e.args[0]) > 0)
        return bitwise(sc, e, context, type);
      VT t;
      const auto a = expr(sc, *e.args[0], context, t);
      if (e.kind == ExprKind::Not) t = bool_if_literal(*e.args[0], t);
      if (e.kind == ExprKind::Not && t != VT::Bool) return integer_not(e, a, type);
      if (e.kind == ExprKind::Neg && t != VT::Int)
        error(e.where, "'" + model::to_st(e) + "': negation of a BOOL");
      type = t;
      return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, {a});
    }
    case ExprKind::And:
    case ExprKind::Or:
    case ExprKind::Xor: {
      if (std::any_of(e.args.begin(), e.args.end(),
                      [&](const model::ExprPtr& a) { return bit_width(sc, *a) > 0; }))
        return bitwise(sc, e, context, type);
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
    case ExprKind::Add:
    case ExprKind::Sub:
    case ExprKind::Mul:
    case ExprKind::Div:
    case ExprKind::Mod: {
      VT a, b;
      const auto x = expr(sc, *e.args[0], context, a);
      const auto y = expr(sc, *e.args[1], context, b);
      if (a != VT::Int || b != VT::Int)
        error(e.where, "'" + model::to_st(e) + "': arithmetic on BOOL");
      type = VT::Int;
      return node(Node{op_of(e.kind), Op::Eq, false, 0, 0, 0, 0}, {x, y});
    }
    case ExprKind::Eq:
    case ExprKind::Ne:
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge:
      return compare(sc, e, context, type);
    case ExprKind::Rising:
    case ExprKind::Falling:
    case ExprKind::Delay:
      error(e.where, "'" + model::to_st(e) +
                         "' is Grafcet syntax, not IEC 61131-3 (use R_TRIG/F_TRIG, TON)");
      type = VT::Bool;
      return constant(0);
  }
  type = VT::Bool;
  return constant(0);
}

std::uint32_t Compiler::member(const PouScope& sc, const model::Expr& e, int context, VT& type) {
  reading(sc, e.where);
  const auto mem = model::to_upper(e.member);
  type = VT::Bool;
  {
    // `inst.x`, `a.b.x`, `Main.x`, `inst.timer.Q`, `inst.Step.X`: resolved in the scope of the
    // instance (or program) the leading parts name.
    auto parts = model::split_path(e.name);
    parts.push_back(e.member);
    std::size_t used = 0;
    const auto si = path_scope(sc, parts, used);
    if (used > 0) {
      const auto& inner = scopes[si];
      if (used + 1 == parts.size()) {
        auto it = inner.names.find(model::to_upper(parts.back()));
        if (refuse_in_out_member(sc, si, parts.back(), model::to_st(e), e.where)) {
          if (it != inner.names.end()) type = it->second.is_bool ? VT::Bool : VT::Int;
          return constant(0);
        }
        if (it != inner.names.end() &&
            (it->second.kind == Ref::Field || it->second.kind == Ref::Input)) {
          type = it->second.is_bool ? VT::Bool : VT::Int;
          Node n;
          n.op = it->second.kind == Ref::Field ? Op::Field : Op::Input;
          n.a = it->second.index;
          return node(n);
        }
        if (it == inner.names.end() && find_step(inner, parts.back(), -1, e.where, false)) {
          Node n;  // `inst.Step`: the step's activity
          n.op = Op::StepX;
          n.a = *find_step(inner, parts.back(), -1, e.where, true);
          return node(n);
        }
        error(e.where, "'" + model::to_st(e) + "': " + inner.name + " has no variable '" +
                           parts.back() + "' sfcv models");
        return constant(0);
      }
      if (used + 2 == parts.size()) {
        model::Expr rest = e;
        rest.name = parts[used];
        rest.member = parts.back();
        return member(inner, rest, -1, type);
      }
      error(e.where, "'" + model::to_st(e) + "' names nothing sfcv models");
      return constant(0);
    }
  }
  if (auto it = sc.names.find(model::to_upper(e.name));
      it != sc.names.end() && it->second.kind == Ref::FbInst) {
    const auto& fb = p.fbs[it->second.index];
    const bool timer =
        fb.kind == StandardFb::TON || fb.kind == StandardFb::TOF || fb.kind == StandardFb::TP;
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
    if (mem == "PT" && timer) {
      type = VT::Int;
      return timer_read(it->second.index, false, e);
    }
    if (mem == "ET" && timer) {
      if (p.options.time == TimeMode::Abstract) {
        type = VT::Int;
        return timer_read(it->second.index, true, e);
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
  // `Main.x` of a program this run does not include (a TwinCAT FB reading MAIN's variables,
  // checked alone with --pou).
  if (const auto* program = project.find_pou(e.name);
      program && program->kind == model::PouKind::Program && program->find_variable(e.member)) {
    error(e.where, "'" + e.name + "." + e.member + "' in " + sc.pou->name +
                       " is a variable of program " + program->name +
                       ", which this run does not include: check the whole project (without "
                       "--pou), where " +
                       program->name + " runs the instances that need it");
    return constant(0);
  }
  error(e.where, "unknown name '" + e.name + "." + e.member + "' in " + sc.pou->name);
  return constant(0);
}

std::optional<std::pair<std::int64_t, std::int64_t>> Compiler::int_range(std::uint32_t n) const {
  const Node& x = p.nodes[n];
  if (x.op == Op::Field) return std::make_pair(p.field_lo[x.a], p.field_hi[x.a]);
  if (x.op == Op::Input) return std::make_pair(p.inputs[x.a].type.lo, p.inputs[x.a].type.hi);
  if (x.op == Op::Call) {
    const auto r = p.functions[x.a].result;
    return std::make_pair(p.field_lo[r], p.field_hi[r]);
  }
  // IEC 61131-3 arithmetic keeps its operands' (common) type: the first typed operand's.
  if (x.op == Op::Add || x.op == Op::Sub || x.op == Op::Mul || x.op == Op::Div || x.op == Op::Mod ||
      x.op == Op::Neg)
    for (std::uint32_t i = 0; i < x.count; ++i)
      if (auto r = int_range(p.kids[x.first + i])) return r;
  return std::nullopt;
}

// IEC 61131-3 NOT on an integer is the bitwise complement at the width of its type: in two's
// complement ~x = -1 - x for SINT..LINT, and 2^w - 1 - x for USINT..UDINT (the BYTE..DWORD
// ranges go through bitwise()). Written as a subtraction it needs no new operator in the
// machine, the circuit or the exports, and never leaves the type's range.
std::uint32_t Compiler::integer_not(const model::Expr& e, std::uint32_t operand, VT& type) {
  type = VT::Int;
  // A range below 0 is a signed type or a subrange of one, whatever its width; an unsigned
  // value needs its width: the type's full range, or an input's declared type name.
  std::optional<std::int64_t> all_ones;
  if (const auto r = int_range(operand)) {
    const auto [lo, hi] = *r;
    if (lo < 0) all_ones = -1;
    for (const std::int64_t top : {255LL, 65535LL, 4294967295LL})
      if (lo == 0 && hi == top) all_ones = top;
  }
  if (const Node& x = p.nodes[operand]; !all_ones && x.op == Op::Input) {
    const auto name = model::to_upper(p.inputs[x.a].type.name);
    if (name == "SINT" || name == "INT" || name == "DINT" || name == "LINT") all_ones = -1;
    if (name == "USINT") all_ones = 255;
    if (name == "UINT") all_ones = 65535;
    if (name == "UDINT") all_ones = 4294967295LL;
  }
  if (!all_ones) {
    error(e.where, "'" + model::to_st(e) +
                       "': bitwise NOT needs an operand whose type sfcv knows to be one of "
                       "SINT, INT, DINT, LINT, USINT, UINT, UDINT (a variable, input or "
                       "function result of that type; ULINT, typed literals and subranges of "
                       "variables of unsigned types are not modelled)");
    return constant(0);
  }
  return node(Node{Op::Sub, Op::Eq, false, 0, 0, 0, 0}, {constant(*all_ones), operand});
}

std::uint32_t Compiler::bool_expr(const PouScope& sc, const model::ExprPtr& e, int context,
                                  const model::SourceLocation& where, const char* what) {
  if (!e) return constant(1);
  VT t;
  const auto n = expr(sc, *e, context, t);
  if (bool_if_literal(*e, t) != VT::Bool)
    error(e->where.known() ? e->where : where,
          std::string(what) + " '" + model::to_st(e) + "' is not Boolean");
  return n;
}

}  // namespace sfcv::semantics::iec::detail

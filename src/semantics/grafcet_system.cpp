#include "semantics/grafcet_system.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <unordered_map>

#include "model/errors.hpp"
#include "model/names.hpp"
#include "semantics/detail/grafcet_system_impl.hpp"

namespace sfcv::semantics {

namespace grafcet {

using model::ExprKind;

// ------------------------------------------------------------------------------- compilation

int GrafcetSystem::find_step(const std::string& pou, std::string_view name) const {
  // Indexed: every identifier of every receptivity is looked up here.
  const auto it = step_index_.find(model::to_upper(pou) + "." + model::to_upper(std::string(name)));
  if (it == step_index_.end()) return -1;
  return it->second.count == 1 ? it->second.step : -2;
}

int GrafcetSystem::steps_named(std::string_view name) const {
  const auto it = step_name_count_.find(model::to_upper(name));
  return it == step_name_count_.end() ? 0 : it->second;
}

int GrafcetSystem::find_chart(const std::string& pou, std::string_view name) const {
  // Indexed: a chain of 10,000 nested macro-steps looks up 10,000 expansions.
  const auto it =
      chart_index_.find(model::to_upper(pou) + "." + model::to_upper(std::string(name)));
  return it == chart_index_.end() ? -1 : it->second;
}

int GrafcetSystem::input_index(const model::Pou& pou, const std::string& name) {
  const std::string key = model::to_upper(pou.name) + "." + model::to_upper(name);
  if (auto it = input_by_name_.find(key); it != input_by_name_.end()) return it->second;
  GInput in;
  const model::Variable* v = pou.find_variable(name);
  in.name = v ? v->name : name;
  in.order = static_cast<int>(pou.variables.size() + gin_.size());
  for (std::size_t i = 0; i < pou.variables.size(); ++i)
    if (&pou.variables[i] == v) in.order = static_cast<int>(i);
  in.type = v ? v->type : model::Type::boolean();
  if (in.type.kind == model::TypeKind::Time) in.type.kind = model::TypeKind::Int;
  gin_.push_back(in);
  const int id = static_cast<int>(gin_.size() - 1);
  input_by_name_[key] = id;
  return id;
}

bool GrafcetSystem::constant_value(const model::Expr& e, std::int64_t& v) const {
  switch (e.kind) {
    case ExprKind::IntConst:
    case ExprKind::TimeConst:
    case ExprKind::BoolConst:
      v = e.value;
      return true;
    case ExprKind::Neg:
      if (!constant_value(*e.args[0], v)) return false;
      v = -v;
      return true;
    default:
      return false;
  }
}

bool GrafcetSystem::compile(const model::Pou& pou, const model::Expr& e, CExpr& out,
                            bool under_edge) {
  auto resolve_step = [&](const std::string& name, CExpr& o) {
    const int s = find_step(pou.name, name);
    if (s == -2) {
      error(e.where, "ambiguous step name '" + name + "': several partial grafcets have it");
      return false;
    }
    if (s < 0) return false;
    o.op = Op::Step;
    o.ref = s;
    return true;
  };
  switch (e.kind) {
    case ExprKind::BoolConst:
    case ExprKind::IntConst:
    case ExprKind::TimeConst:
      out.op = Op::Const;
      out.value = e.value;
      return true;
    case ExprKind::Name: {
      const std::string key = model::to_upper(pou.name) + "." + model::to_upper(e.name);
      if (auto it = var_index_.find(key); it != var_index_.end()) {
        out.op = Op::Var;
        out.ref = it->second;
        return true;
      }
      const model::Variable* var = pou.find_variable(e.name);
      // A step variable: "X12" names step "12" unless a variable is called X12.
      if (!var && e.name.size() > 1 && (e.name[0] == 'X' || e.name[0] == 'x')) {
        if (resolve_step(e.name.substr(1), out)) return true;
        if (!ok_) return false;
      }
      if (!var && find_step(pou.name, e.name) >= 0) {
        error(e.where, "'" + e.name + "' is a step: write X" + e.name + " for its activity");
        return false;
      }
      if (var && var->type.kind == model::TypeKind::FunctionBlock) {
        error(e.where, "function block instance '" + e.name + "' is not part of Grafcet");
        return false;
      }
      out.op = Op::Input;
      out.ref = input_index(pou, e.name);
      if (under_edge) gin_[out.ref].edge = true;
      if (!var && !pou.variables.empty())
        diags_.push_back({model::Severity::Note, e.where,
                          "'" + e.name + "' is not declared: read as a Boolean input"});
      return true;
    }
    case ExprKind::Member: {
      if (model::iequals(e.member, "X") && resolve_step(e.name, out)) return true;
      if (!ok_) return false;
      const int chart = find_chart(pou.name, e.name);
      if (chart >= 0) {
        for (int s : charts_[chart].steps) {
          const auto& n = steps_[s].name;
          if (model::iequals(n, e.member) ||
              (e.member.size() > 1 && model::iequals(n, std::string_view(e.member).substr(1)))) {
            out.op = Op::Step;
            out.ref = s;
            return true;
          }
        }
      }
      error(e.where, "unknown step '" + e.name + "." + e.member + "'");
      return false;
    }
    case ExprKind::Delay: {
      CExpr inner;
      if (!compile(pou, *e.args[0], inner, under_edge) || !int_inputs_ok(inner, e)) return false;
      if (e.value < 0 || e.value2 < 0) {
        error(e.where, "negative delay");
        return false;
      }
      int id = -1;
      for (std::size_t i = 0; i < delays_.size(); ++i)
        if (delays_[i].t1 == e.value && delays_[i].t2 == e.value2 &&
            model::equal(delays_[i].source, e.args[0]))
          id = static_cast<int>(i);
      if (id < 0) {
        GDelay d;
        d.expr = std::move(inner);
        d.source = e.args[0];
        d.t1 = e.value;
        d.t2 = e.value2;
        delays_.push_back(std::move(d));
        id = static_cast<int>(delays_.size() - 1);
      }
      out.op = Op::Delay;
      out.ref = id;
      return true;
    }
    case ExprKind::Eq:
    case ExprKind::Ne:
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge: {
      static const std::map<ExprKind, Op> ops{{ExprKind::Eq, Op::Eq}, {ExprKind::Ne, Op::Ne},
                                              {ExprKind::Lt, Op::Lt}, {ExprKind::Le, Op::Le},
                                              {ExprKind::Gt, Op::Gt}, {ExprKind::Ge, Op::Ge}};
      Op op = ops.at(e.kind);
      CExpr l, r;
      if (!compile(pou, *e.args[0], l, under_edge) || !compile(pou, *e.args[1], r, under_edge))
        return false;
      auto is_int_input = [this](const CExpr& x) {
        return x.op == Op::Input && gin_[x.ref].type.kind == model::TypeKind::Int;
      };
      if (is_int_input(r) && !is_int_input(l)) {  // put the input on the left
        std::swap(l, r);
        static const std::map<Op, Op> mirror{{Op::Eq, Op::Eq}, {Op::Ne, Op::Ne}, {Op::Lt, Op::Gt},
                                             {Op::Le, Op::Ge}, {Op::Gt, Op::Lt}, {Op::Ge, Op::Le}};
        op = mirror.at(op);
      }
      if (is_int_input(l) && r.op == Op::Const) {
        const std::int64_t c = r.value;
        auto& th = gin_[l.ref].thresholds;
        // Values < c / >= c behave alike for Lt and Ge; Le, Gt split at c + 1; Eq, Ne at both.
        if (op == Op::Lt || op == Op::Ge || op == Op::Eq || op == Op::Ne) th.push_back(c);
        if (op == Op::Le || op == Op::Gt || op == Op::Eq || op == Op::Ne) th.push_back(c + 1);
        out.op = op;
        out.args = {std::move(l), std::move(r)};
        return true;
      }
      out.op = op;
      out.args = {std::move(l), std::move(r)};
      return true;
    }
    default:
      break;
  }
  // Operators with sub-expressions.
  static const std::map<ExprKind, Op> ops{
      {ExprKind::Not, Op::Not}, {ExprKind::Neg, Op::Neg},     {ExprKind::And, Op::And},
      {ExprKind::Or, Op::Or},   {ExprKind::Xor, Op::Xor},     {ExprKind::Add, Op::Add},
      {ExprKind::Sub, Op::Sub}, {ExprKind::Mul, Op::Mul},     {ExprKind::Div, Op::Div},
      {ExprKind::Mod, Op::Mod}, {ExprKind::Rising, Op::Rise}, {ExprKind::Falling, Op::Fall}};
  const auto it = ops.find(e.kind);
  if (it == ops.end()) {
    error(e.where, "expression not supported by the Grafcet semantics: " + model::to_st(e));
    return false;
  }
  out.op = it->second;
  const bool edge = under_edge || e.kind == ExprKind::Rising || e.kind == ExprKind::Falling;
  for (const auto& a : e.args) {
    CExpr c;
    if (!compile(pou, *a, c, edge)) return false;
    out.args.push_back(std::move(c));
  }
  return true;
}

bool GrafcetSystem::compile_top(const model::Pou& pou, const model::Expr& e, CExpr& out) {
  if (!compile(pou, e, out, false)) return false;
  if (out.op == Op::Input && gin_[out.ref].type.kind == model::TypeKind::Int) {
    error(e.where, "integer input '" + gin_[out.ref].name + "' used as a Boolean");
    return false;
  }
  return int_inputs_ok(out, e);
}

bool GrafcetSystem::int_inputs_ok(const CExpr& e, const model::Expr& where) {
  const bool comparison = e.op == Op::Eq || e.op == Op::Ne || e.op == Op::Lt || e.op == Op::Le ||
                          e.op == Op::Gt || e.op == Op::Ge;
  for (std::size_t i = 0; i < e.args.size(); ++i) {
    const auto& a = e.args[i];
    if (a.op == Op::Input && gin_[a.ref].type.kind == model::TypeKind::Int) {
      if (comparison && i == 0 && e.args[1].op == Op::Const) continue;  // regions (2.9)
      const bool integer_context = comparison || e.op == Op::Add || e.op == Op::Sub ||
                                   e.op == Op::Mul || e.op == Op::Div || e.op == Op::Mod ||
                                   e.op == Op::Neg;
      if (!integer_context) {
        error(where.where,
              "integer input '" + gin_[a.ref].name + "' used as a Boolean: " + model::to_st(where));
        return false;
      }
      // Compared with another value or computed with: its exact value, one region per value.
      auto& in = gin_[a.ref];
      if (in.type.hi - in.type.lo + 1 > kMaxExactInputValues) {
        error(where.where, "integer input '" + in.name + "' in " + model::to_st(where) +
                               ": compared with a non-constant or computed with, it needs its "
                               "exact value, and its range " +
                               std::to_string(in.type.lo) + ".." + std::to_string(in.type.hi) +
                               " has more than " + std::to_string(kMaxExactInputValues) +
                               " values (give it a subrange type)");
        return false;
      }
      in.exact = true;
      continue;
    }
    if (!int_inputs_ok(a, where)) return false;
  }
  return true;
}

namespace {
void remap_inputs(CExpr& e, const std::vector<int>& to) {
  if (e.op == Op::Input) e.ref = to[static_cast<std::size_t>(e.ref)];
  for (auto& a : e.args) remap_inputs(a, to);
}
}  // namespace

void GrafcetSystem::finish_inputs() {
  // Inputs in declaration order, so that conditions read the same whatever the chart order.
  std::vector<int> perm(gin_.size());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>(i);
  std::stable_sort(perm.begin(), perm.end(),
                   [this](int x, int y) { return gin_[x].order < gin_[y].order; });
  std::vector<int> to(gin_.size());
  std::vector<GInput> sorted;
  for (std::size_t i = 0; i < perm.size(); ++i) {
    to[static_cast<std::size_t>(perm[i])] = static_cast<int>(i);
    sorted.push_back(gin_[static_cast<std::size_t>(perm[i])]);
  }
  gin_ = std::move(sorted);
  for (auto& t : trans_) remap_inputs(t.guard, to);
  for (auto& a : stored_) {
    remap_inputs(a.event, to);
    remap_inputs(a.value, to);
  }
  for (auto& c : continuous_) remap_inputs(c.condition, to);
  for (auto& d : delays_) remap_inputs(d.expr, to);
  for (auto& [name, id] : input_by_name_) id = to[static_cast<std::size_t>(id)];
  for (auto& in : gin_) {
    if (in.type.kind != model::TypeKind::Int) continue;
    auto& th = in.thresholds;
    if (in.exact)
      for (std::int64_t x = in.type.lo + 1; x <= in.type.hi; ++x) th.push_back(x);
    std::sort(th.begin(), th.end());
    th.erase(std::unique(th.begin(), th.end()), th.end());
    in.region_lo = {in.type.lo};
    for (auto t : th)
      if (t > in.type.lo && t <= in.type.hi) in.region_lo.push_back(t);
  }
}

// ------------------------------------------------------------------------------- evaluation

bool GrafcetSystem::active(StateView s, int step) const {
  const auto& gs = steps_[step];
  if (gs.field >= 0) return layout_.get(s, static_cast<std::uint32_t>(gs.field)) != 0;
  for (int f : gs.derived_from)
    if (layout_.get(s, static_cast<std::uint32_t>(f))) return true;
  return false;
}

std::int64_t GrafcetSystem::value_of(StateView s, int var) const {
  const auto& gv = vars_[static_cast<std::size_t>(var)];
  const auto x = layout_.get(s, static_cast<std::uint32_t>(gv.field));
  if (!gv.mixed()) return x;
  return (x | layout_.get(s, static_cast<std::uint32_t>(gv.memory_field))) != 0 ? 1 : 0;
}

Val GrafcetSystem::eval(const CExpr& e, const Ctx& c) const {
  switch (e.op) {
    case Op::Const:
      return {true, e.value};
    case Op::Input: {
      const auto i = static_cast<std::size_t>(e.ref);
      if (!c.in->known[i]) {
        if (c.wanted < 0) c.wanted = e.ref;
        return {false, 0};
      }
      const auto v = c.in->val[i];
      return {true, gin_[i].type.kind == model::TypeKind::Int
                        ? gin_[i].region_lo[static_cast<std::size_t>(v)]
                        : v};
    }
    case Op::Step:
      return {true, active(c.cur, e.ref) ? 1 : 0};
    case Op::Var:
      return {true, value_of(c.cur, e.ref)};
    case Op::Delay: {
      const auto ph = layout_.get(c.cur, static_cast<std::uint32_t>(delays_[e.ref].field));
      return {true, ph >= 2 ? 1 : 0};
    }
    case Op::Not: {
      const Val a = eval(e.args[0], c);
      return {a.known, a.v ? 0 : 1};
    }
    case Op::Neg: {
      const Val a = eval(e.args[0], c);
      return {a.known, -a.v};
    }
    case Op::And:
    case Op::Or: {
      const bool dominant = e.op == Op::Or;  // the value that decides alone
      bool unknown = false;
      for (const auto& a : e.args) {
        const Val x = eval(a, c);
        if (x.known && (x.v != 0) == dominant) return {true, dominant ? 1 : 0};
        if (!x.known) unknown = true;
      }
      return {!unknown, dominant ? 0 : 1};
    }
    case Op::Xor: {
      std::int64_t r = 0;
      for (const auto& a : e.args) {
        const Val x = eval(a, c);
        if (!x.known) return {false, 0};
        r ^= (x.v != 0);
      }
      return {true, r};
    }
    case Op::Rise:
    case Op::Fall: {
      // Where the current and previous situations are one (the "before" side of an enclosing
      // edge), nothing changes: every edge is false. Said first, so that nested edges
      // (RE RE ... RE a) cost one evaluation per level instead of doubling at each.
      if (c.cur.data() == c.prev.data() && c.in == c.prev_in) return {true, 0};
      const Val now = eval(e.args[0], c);
      Ctx before{c.prev, c.prev_in, c.prev, c.prev_in};
      const Val was = eval(e.args[0], before);
      if (before.wanted >= 0 && c.wanted < 0) c.wanted = before.wanted;
      const bool want_now = e.op == Op::Rise;
      if ((now.known && (now.v != 0) != want_now) || (was.known && (was.v != 0) == want_now))
        return {true, 0};
      if (!now.known || !was.known) return {false, 0};
      return {true, 1};
    }
    default:
      break;
  }
  const Val a = eval(e.args[0], c);
  const Val b = eval(e.args[1], c);
  if (!a.known || !b.known) return {false, 0};
  switch (e.op) {
    case Op::Add:
      return {true, a.v + b.v};
    case Op::Sub:
      return {true, a.v - b.v};
    case Op::Mul:
      return {true, a.v * b.v};
    case Op::Div:
      return {true, b.v == 0 ? 0 : a.v / b.v};
    case Op::Mod:
      return {true, b.v == 0 ? 0 : a.v % b.v};
    case Op::Eq:
      return {true, a.v == b.v};
    case Op::Ne:
      return {true, a.v != b.v};
    case Op::Lt:
      return {true, a.v < b.v};
    case Op::Le:
      return {true, a.v <= b.v};
    case Op::Gt:
      return {true, a.v > b.v};
    case Op::Ge:
      return {true, a.v >= b.v};
    default:
      return {false, 0};
  }
}

std::int64_t GrafcetSystem::region_of(std::size_t input, std::int64_t value) const {
  const auto& in = gin_[input];
  if (in.type.kind != model::TypeKind::Int || in.pseudo) return value;
  const auto& lo = in.region_lo;
  const auto above = std::upper_bound(lo.begin(), lo.end(), value);
  return above == lo.begin() ? 0 : std::distance(lo.begin(), above) - 1;
}

Partial GrafcetSystem::inputs_of(StateView s) const {
  Partial p;
  p.val.assign(gin_.size(), 0);
  p.known.assign(gin_.size(), 0);
  for (std::size_t i = 0; i < gin_.size(); ++i) {
    if (gin_[i].field < 0) continue;
    p.val[i] = layout_.get(s, static_cast<std::uint32_t>(gin_[i].field));
    p.known[i] = 1;
  }
  return p;
}

InputCube GrafcetSystem::cube_of(const Partial& p) const {
  InputCube cube;
  for (std::size_t i = 0; i < gin_.size(); ++i) {
    if (!p.known[i]) continue;
    InputLiteral l;
    l.input = static_cast<std::uint32_t>(i);
    if (gin_[i].type.kind == model::TypeKind::Int && !gin_[i].pseudo) {
      l.lo = gin_[i].region_lo[static_cast<std::size_t>(p.val[i])];
      l.hi = gin_[i].region_hi(p.val[i]);
    } else {
      l.lo = l.hi = p.val[i];
    }
    cube.literals.push_back(l);
  }
  return cube;
}

bool GrafcetSystem::enters_at(int step, bool at_start) const {
  const auto& gs = steps_[step];
  const auto& gc = charts_[gs.chart];
  // At start a grafcet takes its initial steps; when its enclosing step is activated, its
  // activation-linked ones. Each falls back on the other mark when the chart has none of its
  // own (a file marking the entry of an enclosed grafcet initial; an enclosed grafcet with
  // only linked steps under an initial enclosing step). A top-level grafcet has no enclosing
  // step: only its initial steps.
  if (at_start) return gc.has_initial || gc.top_level ? gs.initial : gs.linked;
  return gc.has_linked ? gs.linked : gs.initial;
}

int GrafcetSystem::set_active(std::vector<StateWord>& s, int step) const {
  const auto& gs = steps_[step];
  const int id = gs.field >= 0 ? step : gs.entry;
  layout_.set(s, static_cast<std::uint32_t>(steps_[id].field), 1);
  return id;
}

void GrafcetSystem::init_chart(std::vector<StateWord>& s, int chart) const {
  for (int id : charts_[chart].steps) {
    if (!enters_at(id, true)) continue;
    // The enclosing steps of the initial situation are activated at start (2.2).
    for (int c : steps_[set_active(s, id)].enclosed) init_chart(s, c);
  }
}

void GrafcetSystem::activate_enclosed(std::vector<StateWord>& s, int enclosing_step) const {
  for (int c : steps_[enclosing_step].enclosed)
    for (int id : charts_[c].steps)
      if (enters_at(id, false)) activate_enclosed(s, set_active(s, id));
}

void GrafcetSystem::clear_chart(std::vector<StateWord>& s, int chart, bool enclosed) const {
  for (int id : charts_[chart].steps) {
    const auto& gs = steps_[id];
    if (gs.field >= 0) layout_.set(s, static_cast<std::uint32_t>(gs.field), 0);
    if (gs.expansion >= 0) clear_chart(s, gs.expansion, enclosed);
    if (enclosed)
      for (int c : gs.enclosed) clear_chart(s, c);
  }
}

GrafcetSystem::Status GrafcetSystem::evolve(StateView source, const Partial& v, bool initial,
                                            Result& r) const {
  // Stored inputs must be known: the target remembers them.
  for (std::size_t i = 0; i < gin_.size(); ++i)
    if (gin_[i].field >= 0 && !v.known[i]) {
      r.split = static_cast<int>(i);
      return Status::Split;
    }
  const Partial prev_inputs = initial ? v : inputs_of(source);
  std::vector<StateWord> cur(source.begin(), source.end());
  for (std::size_t i = 0; i < gin_.size(); ++i)
    if (gin_[i].field >= 0) layout_.set(cur, static_cast<std::uint32_t>(gin_[i].field), v.val[i]);
  // Elapse of running delays (pseudo-inputs): before the evolution the event triggers.
  if (!initial) {
    for (const auto& d : delays_) {
      const auto ph = layout_.get(cur, static_cast<std::uint32_t>(d.field));
      if (ph != 1 && ph != 3) continue;
      const auto p = static_cast<std::size_t>(d.pseudo);
      if (!v.known[p]) {
        r.split = d.pseudo;
        return Status::Split;
      }
      if (v.val[p]) layout_.set(cur, static_cast<std::uint32_t>(d.field), ph == 1 ? 2 : 0);
    }
  }
  std::vector<StateWord> prev(source.begin(), source.end());
  const Partial* prev_in = &prev_inputs;
  std::vector<std::vector<StateWord>> trajectory{cur};
  std::map<std::vector<StateWord>, std::size_t> seen;  // (prev, cur) -> index in trajectory
  r.fired.clear();
  r.entered.clear();
  // The step bits of every situation of the run, ORed (Successor::entered).
  std::vector<StateWord> crossed(step_mask_.size(), 0);

  std::vector<int> forced(charts_.size(), -1);
  std::vector<std::uint32_t> cleared;
  std::vector<const GStored*> events;
  for (std::size_t k = 0;; ++k) {
    // Every 8 iterations: one iteration evaluates every transition of the chart (milliseconds on
    // a chart of 300,000 steps), a clock read costs tens of nanoseconds.
    if (options_.deadline && (k & 7U) == 7U &&
        std::chrono::steady_clock::now() > *options_.deadline)
      throw LimitReached(Limit::Time, "time limit reached during a transient evolution");
    for (std::size_t w = 0; w < crossed.size(); ++w) crossed[w] |= cur[w] & step_mask_[w];
    const Ctx ctx{cur, &v, prev, prev_in};
    auto need_split = [&](const Ctx& c) {
      r.split = c.wanted;
      return Status::Split;
    };
    // Forcing orders of the active steps: the forced partial grafcets do not evolve.
    std::fill(forced.begin(), forced.end(), -1);
    for (std::size_t f = 0; f < forces_.size(); ++f) {
      const auto& fo = forces_[f];
      if (!active(cur, fo.step)) continue;
      auto& slot = forced[static_cast<std::size_t>(fo.chart)];
      if (slot >= 0) {
        const auto& other = forces_[static_cast<std::size_t>(slot)];
        if (other.kind != fo.kind || other.situation != fo.situation) {
          r.anomaly.kind = Anomaly::Kind::RangeError;
          r.anomaly.message = "conflicting forcing orders on partial grafcet " +
                              charts_[fo.chart].name + " (from steps " + steps_[other.step].name +
                              " and " + steps_[fo.step].name + ")";
          r.anomaly.condition.cubes = {cube_of(v)};
          return Status::Anomaly;
        }
      }
      slot = static_cast<int>(f);
    }
    // Clearable transitions: enabled (upstream steps active) and receptivity true.
    cleared.clear();
    for (std::size_t t = 0; t < trans_.size(); ++t) {
      const auto& gt = trans_[t];
      if (forced[static_cast<std::size_t>(gt.chart)] >= 0) continue;
      bool enabled = true;
      for (int f : gt.need)
        if (!layout_.get(cur, static_cast<std::uint32_t>(f))) enabled = false;
      if (!enabled) continue;
      const Val g = eval(gt.guard, ctx);
      if (!g.known) return need_split(ctx);
      if (g.v) cleared.push_back(static_cast<std::uint32_t>(t));
    }
    events.clear();
    for (const auto& sa : stored_) {
      if (sa.when != model::StoredWhen::Event || !active(cur, sa.step)) continue;
      const Val e = eval(sa.event, ctx);
      if (!e.known) return need_split(ctx);
      if (e.v) events.push_back(&sa);
    }
    // Simultaneous clearing: deactivate every upstream step, then activate every downstream
    // step, so that a step both deactivated and activated stays active.
    std::vector<StateWord> next = cur;
    for (auto t : cleared)
      for (int f : trans_[t].need) layout_.set(next, static_cast<std::uint32_t>(f), 0);
    for (auto t : cleared)
      for (int f : trans_[t].act) layout_.set(next, static_cast<std::uint32_t>(f), 1);
    // A forcing order sets the forced grafcet's own steps; its enclosing steps then follow the
    // rules below like any other (activated: their enclosed grafcets enter, 2.12).
    for (std::size_t c = 0; c < charts_.size(); ++c) {
      if (forced[c] < 0) continue;
      const auto& fo = forces_[static_cast<std::size_t>(forced[c])];
      if (fo.kind == model::ForcingKind::Current) continue;
      clear_chart(next, static_cast<int>(c), false);
      if (fo.kind == model::ForcingKind::Initial)
        for (int s : charts_[c].steps)
          if (steps_[s].initial) set_active(next, s);
      for (int s : fo.situation) set_active(next, s);
    }
    // Enclosing steps: an activated one activates the enclosed partial grafcets' linked steps
    // (initial steps for a grafcet without any), an inactive one deactivates every step they
    // enclose.
    for (int e : enclosing_)
      if (!active(cur, e) && active(next, e)) activate_enclosed(next, e);
    for (bool changed = true; changed;) {
      changed = false;
      for (int e : enclosing_) {
        if (active(next, e)) continue;
        for (int c : steps_[e].enclosed)
          for (int s : charts_[c].steps)
            if (steps_[s].field >= 0 &&
                layout_.get(next, static_cast<std::uint32_t>(steps_[s].field))) {
              clear_chart(next, c);
              changed = true;
            }
      }
    }
    // Stored actions: on deactivation, on activation, then on event (later ones win).
    std::vector<std::pair<int, std::int64_t>> writes;
    for (int pass = 0; pass < 2; ++pass)
      for (const auto& sa : stored_) {
        const auto when =
            pass == 0 ? model::StoredWhen::Deactivation : model::StoredWhen::Activation;
        if (sa.when != when) continue;
        const bool was = active(cur, sa.step), is = active(next, sa.step);
        if (pass == 0 ? !(was && !is) : !(!was && is)) continue;
        const Val x = eval(sa.value, ctx);
        if (!x.known) return need_split(ctx);
        writes.emplace_back(sa.var, x.v);
      }
    for (const auto* sa : events) {
      const Val x = eval(sa->value, ctx);
      if (!x.known) return need_split(ctx);
      writes.emplace_back(sa->var, x.v);
    }
    for (const auto& [var, value] : writes) {
      const auto& gv = vars_[static_cast<std::size_t>(var)];
      std::int64_t val = value;
      if (gv.type.kind == model::TypeKind::Bool) val = value != 0;
      if (gv.type.kind == model::TypeKind::Int && (val < gv.type.lo || val > gv.type.hi)) {
        r.anomaly.kind = Anomaly::Kind::RangeError;
        r.anomaly.message = "stored action sets " + gv.name + " to " + std::to_string(val) +
                            ", outside its range [" + std::to_string(gv.type.lo) + ", " +
                            std::to_string(gv.type.hi) + "]";
        r.anomaly.condition.cubes = {cube_of(v)};
        return Status::Anomaly;
      }
      layout_.set(next, static_cast<std::uint32_t>(gv.stored_field()), val);
    }
    // Delay phases follow their expression in the new situation.
    {
      const Ctx after{next, &v, cur, &v};
      for (const auto& d : delays_) {
        const auto f = static_cast<std::uint32_t>(d.field);
        const auto ph = layout_.get(next, f);
        const Val x = eval(d.expr, after);
        if (!x.known) return need_split(after);
        std::int64_t np = ph;
        if (x.v)
          np = ph == 0 ? (d.t1 > 0 ? 1 : 2) : (ph == 3 ? 2 : ph);
        else
          np = ph == 2 ? (d.t2 > 0 ? 3 : 0) : (ph == 1 ? 0 : ph);
        layout_.set(next, f, np);
      }
    }
    r.fired.insert(r.fired.end(), cleared.begin(), cleared.end());
    if (next == cur) break;  // stable
    prev = std::move(cur);
    prev_in = &v;
    cur = std::move(next);
    std::vector<StateWord> key = prev;
    key.insert(key.end(), cur.begin(), cur.end());
    const auto [it, fresh] = seen.emplace(std::move(key), trajectory.size());
    // A bound of the semantics, not a finding: the evolutions have not repeated yet, so they
    // may still stabilise (exactly max_transient_steps evolutions that do stabilise pass).
    if (fresh && k >= options_.max_transient_steps)
      throw LimitReached(Limit::Enumeration,
                         "no stable situation after " +
                             std::to_string(options_.max_transient_steps) +
                             " transient evolutions (the bound max_transient_steps) and no "
                             "repeated situation: the evolutions may still stabilise, so this "
                             "is not reported as an instability (the bdd, ic3 and bmc engines "
                             "have no such bound)");
    if (!fresh) {
      // Evolutions are deterministic under fixed inputs: a repeated (previous, current) pair
      // repeats forever.
      r.anomaly.kind = Anomaly::Kind::Instability;
      r.anomaly.condition.cubes = {cube_of(v)};
      r.anomaly.cycle.assign(trajectory.begin() + static_cast<std::ptrdiff_t>(it->second),
                             trajectory.end());
      r.anomaly.message = "instability: the transient evolutions cycle through " +
                          std::to_string(r.anomaly.cycle.size()) +
                          " situations and never reach a stable one";
      return Status::Anomaly;
    }
    trajectory.push_back(cur);
  }
  // Continuous actions are emitted in the stable situation only.
  {
    const Ctx ctx{cur, &v, cur, &v};
    for (const auto& gv : vars_)
      if (gv.continuous) layout_.set(cur, static_cast<std::uint32_t>(gv.field), 0);
    for (const auto& ca : continuous_) {
      if (!active(cur, ca.step)) continue;
      if (ca.has_condition) {
        const Val x = eval(ca.condition, ctx);
        if (!x.known) {
          r.split = ctx.wanted;
          return Status::Split;
        }
        if (!x.v) continue;
      }
      layout_.set(cur, static_cast<std::uint32_t>(vars_[static_cast<std::size_t>(ca.var)].field),
                  1);
    }
  }
  std::sort(r.fired.begin(), r.fired.end());
  r.fired.erase(std::unique(r.fired.begin(), r.fired.end()), r.fired.end());
  // Steps active in a situation of the run but in neither its source nor its target: what a
  // transition entered and the same evolution left (2.5), or an enclosing step's deactivation
  // emptied (2.12 c) is not here, as no situation holds it.
  for (std::size_t w = 0; w < crossed.size(); ++w) {
    StateWord only = crossed[w] & ~cur[w];
    if (!initial) only &= ~source[w];
    for (; only != 0; only &= only - 1)
      r.entered.push_back(
          step_field_at_bit_[w * 64 + static_cast<std::size_t>(std::countr_zero(only))]);
  }
  r.target = std::move(cur);
  return Status::Stable;
}

void GrafcetSystem::emit(StateView source, const Partial& v, const Result& r,
                         SuccessorSink& sink) const {
  const bool back =
      !source.empty() && std::equal(r.target.begin(), r.target.end(), source.begin(), source.end());
  // Back to the source: stutter is implicit (no edge), but what the run fired or crossed on
  // the way is still told.
  if (back && r.fired.empty() && r.entered.empty()) return;
  const InputCondition cond{{cube_of(v)}};
  const Successor out{StateView(r.target), cond, r.fired, r.entered};
  if (back)
    sink.returning(out);
  else
    sink.successor(out);
}

/// Splits the partial valuation on demand: each leaf decides the whole evolution, so the
/// number of evolutions computed follows the inputs that matter, not 2^inputs.
void GrafcetSystem::explore(StateView source, Partial start, bool initial, SuccessorSink& sink,
                            std::uint64_t* leaves) const {
  std::vector<Partial> work{std::move(start)};
  Result r;
  while (!work.empty()) {
    Partial p = std::move(work.back());
    work.pop_back();
    r.split = -1;
    const auto status = evolve(source, p, initial, r);
    // A state whose evolutions split on many inputs is wide: the engine may stop it (the
    // probe of --engine auto hands such charts to the symbolic engines), as for IEC 61131-3.
    if (leaves && status != Status::Split && (++*leaves & 4095U) == 0)
      sink.valuations(*leaves, work.capacity() * sizeof(Partial) +
                                   work.size() * gin_.size() * (sizeof(std::int64_t) + 1));
    switch (status) {
      case Status::Stable:
        emit(initial ? StateView{} : source, p, r, sink);
        break;
      case Status::Anomaly:
        sink.anomaly(r.anomaly);
        r.anomaly = {};
        break;
      case Status::Split: {
        const auto i = static_cast<std::size_t>(r.split);
        const auto n = gin_[i].regions();
        if (const auto* only = sink.only_valuation()) {  // the one region the sink wants
          Partial q = std::move(p);
          q.known[i] = 1;
          q.val[i] = region_of(i, (*only)[i]);
          work.push_back(std::move(q));
          break;
        }
        for (std::int64_t x = n - 1; x >= 0; --x) {
          Partial q = p;
          q.known[i] = 1;
          q.val[i] = x;
          work.push_back(std::move(q));
        }
        break;
      }
    }
  }
}

void GrafcetSystem::initial_states(SuccessorSink& sink) const {
  Partial p;
  p.val.assign(gin_.size(), 0);
  p.known.assign(gin_.size(), 0);
  // Pseudo-inputs play no role at the start: no delay is running yet.
  for (std::size_t i = 0; i < gin_.size(); ++i)
    if (gin_[i].pseudo) p.known[i] = 1;
  explore(initial_template_, p, true, sink, nullptr);
}

/// Knuth's estimate of the leaves of the tree initial_states() walks (each leaf one initial
/// situation, or an anomaly): random descents from the root, each multiplying the branching
/// factors it meets; their mean is an unbiased estimate of the leaf count. A fixed seed keeps
/// it deterministic; the cost is kSamples descents of at most one split per input.
std::optional<double> GrafcetSystem::estimate_initial_states() const {
  constexpr int kSamples = 64;
  std::uint64_t seed = 0x9E3779B97F4A7C15ULL;
  auto next = [&seed] {
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    return seed;
  };
  Partial root;
  root.val.assign(gin_.size(), 0);
  root.known.assign(gin_.size(), 0);
  for (std::size_t i = 0; i < gin_.size(); ++i)
    if (gin_[i].pseudo) root.known[i] = 1;
  double total = 0;
  Result r;
  for (int k = 0; k < kSamples; ++k) {
    Partial p = root;
    double weight = 1;
    // At most one split per input: a descent ends at a leaf within gin_.size() + 1 evolutions.
    for (std::size_t guard = 0; guard <= gin_.size(); ++guard) {
      r.split = -1;
      if (evolve(initial_template_, p, true, r) != Status::Split) break;
      r.anomaly = {};
      const auto i = static_cast<std::size_t>(r.split);
      const auto n = gin_[i].regions();
      weight *= static_cast<double>(n);
      p.known[i] = 1;
      p.val[i] = static_cast<std::int64_t>(next() % static_cast<std::uint64_t>(n));
    }
    total += weight;
  }
  return total / kSamples;
}

void GrafcetSystem::successors(StateView stored_state, SuccessorSink& sink) const {
  // The sink may store new states and move the memory `stored_state` points into: work on a copy.
  const std::vector<StateWord> copy(stored_state.begin(), stored_state.end());
  const StateView state(copy);
  std::uint64_t leaves = 0;
  if (!options_.single_input_change) {
    Partial p;
    p.val.assign(gin_.size(), 0);
    p.known.assign(gin_.size(), 0);
    explore(state, p, false, sink, &leaves);
    return;
  }
  // One event at a time: an input takes another value, or a running delay elapses.
  const Partial base = [&] {
    Partial p = inputs_of(state);
    for (std::size_t i = 0; i < gin_.size(); ++i)
      if (gin_[i].pseudo) {
        const auto ph =
            layout_.get(state, static_cast<std::uint32_t>(delays_[gin_[i].delay].field));
        p.known[i] = ph == 1 || ph == 3;  // only a running delay's pseudo-input is constrained
        p.val[i] = 0;
      }
    return p;
  }();
  for (std::size_t i = 0; i < gin_.size(); ++i) {
    if (gin_[i].pseudo) {
      if (!base.known[i]) continue;
      Partial p = base;
      p.val[i] = 1;
      explore(state, p, false, sink, &leaves);
      continue;
    }
    for (std::int64_t x = 0; x < gin_[i].regions(); ++x) {
      if (x == base.val[i]) continue;
      Partial p = base;
      p.val[i] = x;
      explore(state, p, false, sink, &leaves);
    }
  }
}

std::int64_t GrafcetSystem::observe(StateView state, std::uint32_t index) const {
  const auto& o = obs_info_[index];
  switch (o.ref) {
    case ObsRef::Step:
      return active(state, o.index) ? 1 : 0;
    case ObsRef::Variable:
      return value_of(state, o.index);
    case ObsRef::Input: {
      const auto& in = gin_[static_cast<std::size_t>(o.index)];
      const auto v = layout_.get(state, static_cast<std::uint32_t>(in.field));
      return in.type.kind == model::TypeKind::Int ? in.region_lo[static_cast<std::size_t>(v)] : v;
    }
  }
  return 0;
}

std::string GrafcetSystem::describe(StateView state) const {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < steps_.size(); ++i)
    if (active(state, static_cast<int>(i))) {
      const auto& n = steps_[i].name;
      names.push_back(steps_named(n) > 1 ? charts_[steps_[i].chart].name + "." + n : n);
    }
  std::sort(names.begin(), names.end(), numeric_less);
  std::string out = "{";
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? "," : "") + names[i];
  out += "}";
  for (std::size_t i = 0; i < vars_.size(); ++i) {
    const auto& v = vars_[i];
    const auto x = value_of(state, static_cast<int>(i));
    if (v.type.kind == model::TypeKind::Bool) {
      if (x) out += " " + v.name;
    } else {
      out += " " + v.name + "=" + std::to_string(x);
    }
  }
  return out;
}

}  // namespace grafcet

TransitionSystemPtr make_grafcet_system(const model::Project& project,
                                        const GrafcetOptions& options,
                                        model::Diagnostics& diagnostics) {
  auto ts = std::make_unique<grafcet::GrafcetSystem>(project, options, diagnostics);
  if (!ts->ok()) return nullptr;
  return ts;
}

}  // namespace sfcv::semantics

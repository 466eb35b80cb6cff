// GrafcetSystem::evolve (grafcet_system.cpp) executed symbolically, one evolution at a time: the
// functions below follow it statement by statement (forcing orders, clearing, enclosing steps,
// stored actions, delay phases), so that the two can be compared line by line. Values are
// 64-bit two's-complement bit vectors (the explicit system computes in int64).

#include "semantics/grafcet_circuit.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <set>
#include <stdexcept>

#include "semantics/detail/grafcet_system_impl.hpp"
#include "semantics/history_system.hpp"

namespace sfcv::semantics {
namespace grafcet {

namespace {
constexpr std::uint32_t kWidth = 64;
using Value = BitVector;
using State = std::vector<BitVector>;  ///< per layout field: its encoded bits (empty: absent)
}  // namespace

class CircuitBuilder {
 public:
  CircuitBuilder(const GrafcetSystem& s, GrafcetCircuit& out) : s_(s), c_(out), aig_(out.aig) {}

  void build();

 private:
  struct Ctx {
    const State* cur;
    const State* prev;
  };

  // ------------------------------------------------------------------------ values
  Value constant(std::int64_t k) const { return bv_constant(k, kWidth); }
  Value from_bool(AigLit b) const {
    Value v = bv_constant(0, kWidth);
    v[0] = b;
    return v;
  }
  AigLit truth(const Value& v) { return aig_.make_or(std::vector<AigLit>(v.begin(), v.end())); }
  static std::optional<std::int64_t> as_constant(const Value& v) {
    std::uint64_t r = 0;
    for (std::uint32_t i = 0; i < kWidth; ++i) {
      if (v[i] == Aig::kTrue)
        r |= 1ULL << i;
      else if (v[i] != Aig::kFalse)
        return std::nullopt;
    }
    return static_cast<std::int64_t>(r);
  }
  const StateField& field(int f) const { return s_.layout_.fields()[static_cast<std::size_t>(f)]; }
  Value decode(const State& st, int f) {
    const auto& bits = st[static_cast<std::size_t>(f)];
    if (bits.empty()) throw std::logic_error("grafcet circuit: field read outside its context");
    return bv_add(aig_, bv_resize(bits, kWidth, false), constant(field(f).lo));
  }
  /// Variable `var`'s value: either field when both kinds of action write it (Boolean).
  Value variable(const State& st, int var) {
    const auto& gv = s_.vars_[static_cast<std::size_t>(var)];
    if (!gv.mixed()) return decode(st, gv.field);
    return from_bool(aig_.make_or(bit(st, gv.field), bit(st, gv.memory_field)));
  }
  BitVector encode(const Value& v, int f) {
    const Value shifted = bv_sub(aig_, v, constant(field(f).lo));
    return BitVector(shifted.begin(), shifted.begin() + field(f).width);
  }
  AigLit bit(const State& st, int f) {
    const auto& bits = st[static_cast<std::size_t>(f)];
    if (bits.empty()) throw std::logic_error("grafcet circuit: field read outside its context");
    return bits[0];
  }
  State mux(AigLit c, const State& t, const State& e) {
    State r = e;
    for (std::size_t f = 0; f < r.size(); ++f)
      if (!t[f].empty()) r[f] = bv_mux(aig_, c, t[f], e[f]);
    return r;
  }
  AigLit equal_bits(const BitVector& a, const BitVector& b) {
    AigLit r = Aig::kTrue;
    for (std::size_t k = 0; k < a.size(); ++k) r = aig_.make_and(r, aig_.make_xnor(a[k], b[k]));
    return r;
  }
  AigLit equals_constant(const BitVector& bits, std::uint64_t k) {
    AigLit r = Aig::kTrue;
    for (std::size_t i = 0; i < bits.size(); ++i)
      r = aig_.make_and(r, ((k >> i) & 1U) ? bits[i] : Aig::make_not(bits[i]));
    return r;
  }

  // ------------------------------------------------------------------------- state
  AigLit active(const State& st, int step) {
    const auto& gs = s_.steps_[static_cast<std::size_t>(step)];
    if (gs.field >= 0) return bit(st, gs.field);
    AigLit r = Aig::kFalse;
    for (int f : gs.derived_from) r = aig_.make_or(r, bit(st, f));
    return r;
  }
  void set_bit(State& st, int f, AigLit v) { st[static_cast<std::size_t>(f)] = {v}; }
  int set_active(State& st, int step) {
    const auto& gs = s_.steps_[static_cast<std::size_t>(step)];
    const int id = gs.field >= 0 ? step : gs.entry;
    set_bit(st, s_.steps_[static_cast<std::size_t>(id)].field, Aig::kTrue);
    return id;
  }
  /// GrafcetSystem::activate_enclosed: the linked steps (else initial ones) of the enclosed
  /// grafcets, recursively.
  void activate_enclosed(State& st, int enclosing_step) {
    for (int c : s_.steps_[static_cast<std::size_t>(enclosing_step)].enclosed)
      for (int id : s_.charts_[static_cast<std::size_t>(c)].steps)
        if (s_.enters_at(id, false)) activate_enclosed(st, set_active(st, id));
  }
  void clear_chart(State& st, int chart, bool enclosed = true) {
    for (int id : s_.charts_[static_cast<std::size_t>(chart)].steps) {
      const auto& gs = s_.steps_[static_cast<std::size_t>(id)];
      if (gs.field >= 0) set_bit(st, gs.field, Aig::kFalse);
      if (gs.expansion >= 0) clear_chart(st, gs.expansion, enclosed);
      if (enclosed)
        for (int c : gs.enclosed) clear_chart(st, c);
    }
  }

  // ------------------------------------------------------------------- inputs
  /// Region index (encoded as the InputMemory field) of input i read from the circuit inputs.
  BitVector region_from_inputs(std::size_t i) {
    const auto& in = s_.gin_[i];
    if (in.type.kind != model::TypeKind::Int || in.pseudo) return {c_.input_bits[i][0]};
    const Value v = input_value_[i];
    const auto regions = static_cast<std::uint64_t>(in.regions());
    const std::uint32_t width =
        regions <= 1 ? 1 : static_cast<std::uint32_t>(std::bit_width(regions - 1));
    BitVector idx = bv_constant(0, width);
    for (std::size_t r = 1; r < in.region_lo.size(); ++r)
      idx = bv_mux(aig_, aig_.make_not(bv_less_signed(aig_, v, constant(in.region_lo[r]))),
                   bv_constant(static_cast<std::int64_t>(r), width), idx);
    return idx;
  }
  /// The region index of input i in context `st`: its memory when stored, else the inputs.
  BitVector region_in(const State& st, std::size_t i) {
    const auto& in = s_.gin_[i];
    if (in.field >= 0) {
      const auto& bits = st[static_cast<std::size_t>(in.field)];
      if (bits.empty()) throw std::logic_error("grafcet circuit: input memory outside its context");
      return bits;
    }
    return regions_[i];
  }

  // ------------------------------------------------------------------ expressions
  Value eval(const CExpr& e, const Ctx& c);
  AigLit eval_truth(const CExpr& e, const Ctx& c) { return truth(eval(e, c)); }
  void collect_edge_fields(const CExpr& e, bool under_edge, std::set<int>& out) const;

  // ------------------------------------------------------------------ evolution
  State evolve(const State& cur, const State& prev, AigLit& error, std::vector<AigLit>& cleared);

  const GrafcetSystem& s_;
  GrafcetCircuit& c_;
  Aig& aig_;
  std::vector<Value> input_value_;  ///< per input: its value from the circuit inputs
  std::vector<BitVector> regions_;  ///< per input: region index from the circuit inputs
};

void CircuitBuilder::collect_edge_fields(const CExpr& e, bool under_edge,
                                         std::set<int>& out) const {
  if (under_edge) {
    switch (e.op) {
      case Op::Step: {
        const auto& gs = s_.steps_[static_cast<std::size_t>(e.ref)];
        if (gs.field >= 0) out.insert(gs.field);
        for (int f : gs.derived_from) out.insert(f);
        break;
      }
      case Op::Var: {
        const auto& gv = s_.vars_[static_cast<std::size_t>(e.ref)];
        out.insert(gv.field);
        if (gv.mixed()) out.insert(gv.memory_field);
        break;
      }
      case Op::Delay:
        out.insert(s_.delays_[static_cast<std::size_t>(e.ref)].field);
        break;
      case Op::Input:
        if (s_.gin_[static_cast<std::size_t>(e.ref)].field >= 0)
          out.insert(s_.gin_[static_cast<std::size_t>(e.ref)].field);
        break;
      default:
        break;
    }
  }
  const bool edge = under_edge || e.op == Op::Rise || e.op == Op::Fall;
  for (const auto& a : e.args) collect_edge_fields(a, edge, out);
}

Value CircuitBuilder::eval(const CExpr& e, const Ctx& c) {
  switch (e.op) {
    case Op::Const:
      return constant(e.value);
    case Op::Input: {
      const auto i = static_cast<std::size_t>(e.ref);
      const auto& in = s_.gin_[i];
      if (in.type.kind == model::TypeKind::Int) {
        // An exact input (one region per value, GrafcetSystem::int_inputs_ok): lo + index.
        if (!in.exact)
          throw CircuitUnsupported("integer input '" + in.name + "' outside a comparison");
        BitVector index = region_in(*c.cur, i);
        index.resize(kWidth, Aig::kFalse);  // unsigned: zero-extended
        return bv_add(aig_, index, constant(in.type.lo));
      }
      return from_bool(region_in(*c.cur, i)[0]);
    }
    case Op::Step:
      return from_bool(active(*c.cur, e.ref));
    case Op::Var:
      return variable(*c.cur, e.ref);
    case Op::Delay: {
      const auto& bits =
          (*c.cur)[static_cast<std::size_t>(s_.delays_[static_cast<std::size_t>(e.ref)].field)];
      if (bits.size() < 2)
        throw std::logic_error("grafcet circuit: delay phase outside its context");
      return from_bool(bits[1]);  // phase 2 (on) or 3 (falling wait)
    }
    case Op::Not:
      return from_bool(aig_.make_not(eval_truth(e.args[0], c)));
    case Op::Neg:
      return bv_neg(aig_, eval(e.args[0], c));
    case Op::And:
    case Op::Or: {
      std::vector<AigLit> parts;
      for (const auto& a : e.args) parts.push_back(eval_truth(a, c));
      return from_bool(e.op == Op::And ? aig_.make_and(parts) : aig_.make_or(parts));
    }
    case Op::Xor: {
      AigLit r = Aig::kFalse;
      for (const auto& a : e.args) r = aig_.make_xor(r, eval_truth(a, c));
      return from_bool(r);
    }
    case Op::Rise:
    case Op::Fall: {
      // The previous situation seen from itself: no edge (and no doubling when edges nest).
      if (c.cur == c.prev) return from_bool(Aig::kFalse);
      const AigLit now = eval_truth(e.args[0], c);
      const AigLit was = eval_truth(e.args[0], Ctx{c.prev, c.prev});
      return from_bool(e.op == Op::Rise ? aig_.make_and(now, aig_.make_not(was))
                                        : aig_.make_and(aig_.make_not(now), was));
    }
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge: {
      const auto& l = e.args[0];
      if (l.op == Op::Input && e.args[1].op == Op::Const &&
          s_.gin_[static_cast<std::size_t>(l.ref)].type.kind == model::TypeKind::Int) {
        // Only comparisons with a constant (GrafcetSystem::int_inputs_ok): constant on each
        // region, so a table over the region index.
        const auto i = static_cast<std::size_t>(l.ref);
        const auto& in = s_.gin_[i];
        const std::int64_t k = e.args[1].value;
        const BitVector idx = region_in(*c.cur, i);
        AigLit r = Aig::kFalse;
        for (std::size_t reg = 0; reg < in.region_lo.size(); ++reg) {
          const std::int64_t v = in.region_lo[reg];
          bool holds = false;
          switch (e.op) {
            case Op::Eq:
              holds = v == k;
              break;
            case Op::Ne:
              holds = v != k;
              break;
            case Op::Lt:
              holds = v < k;
              break;
            case Op::Le:
              holds = v <= k;
              break;
            case Op::Gt:
              holds = v > k;
              break;
            default:
              holds = v >= k;
              break;
          }
          if (holds) r = aig_.make_or(r, equals_constant(idx, reg));
        }
        return from_bool(r);
      }
      const Value a = eval(e.args[0], c), b = eval(e.args[1], c);
      AigLit r = Aig::kFalse;
      switch (e.op) {
        case Op::Eq:
          r = bv_equal(aig_, a, b);
          break;
        case Op::Ne:
          r = aig_.make_not(bv_equal(aig_, a, b));
          break;
        case Op::Lt:
          r = bv_less_signed(aig_, a, b);
          break;
        case Op::Le:
          r = aig_.make_not(bv_less_signed(aig_, b, a));
          break;
        case Op::Gt:
          r = bv_less_signed(aig_, b, a);
          break;
        default:
          r = aig_.make_not(bv_less_signed(aig_, a, b));
          break;
      }
      return from_bool(r);
    }
    case Op::Add:
      return bv_add(aig_, eval(e.args[0], c), eval(e.args[1], c));
    case Op::Sub:
      return bv_sub(aig_, eval(e.args[0], c), eval(e.args[1], c));
    case Op::Mul: {
      Value a = eval(e.args[0], c), b = eval(e.args[1], c);
      auto ka = as_constant(a), kb = as_constant(b);
      if (ka && kb)
        return constant(static_cast<std::int64_t>(static_cast<std::uint64_t>(*ka) *
                                                  static_cast<std::uint64_t>(*kb)));
      if (ka) {
        std::swap(a, b);
        std::swap(ka, kb);
      }
      if (!kb) throw CircuitUnsupported("a product of two variables in a Grafcet expression");
      // Shift and add, wrapping at 64 bits.
      auto m = static_cast<std::uint64_t>(*kb);
      Value acc = constant(0), shifted = a;
      while (m) {
        if (m & 1U) acc = bv_add(aig_, acc, shifted);
        m >>= 1;
        Value doubled(kWidth);
        doubled[0] = Aig::kFalse;
        for (std::uint32_t i = 1; i < kWidth; ++i) doubled[i] = shifted[i - 1];
        shifted = doubled;
      }
      return acc;
    }
    case Op::Div:
    case Op::Mod: {
      const Value a = eval(e.args[0], c), b = eval(e.args[1], c);
      const auto ka = as_constant(a), kb = as_constant(b);
      if (!ka || !kb)
        throw CircuitUnsupported("a division or modulo of variables in a Grafcet expression");
      if (*kb == 0) return constant(0);
      return constant(e.op == Op::Div ? *ka / *kb : *ka % *kb);
    }
  }
  throw CircuitUnsupported("an expression the Grafcet circuit does not know");
}

State CircuitBuilder::evolve(const State& cur, const State& prev, AigLit& error,
                             std::vector<AigLit>& cleared) {
  const Ctx ctx{&cur, &prev};
  error = Aig::kFalse;
  // Forcing orders of the active steps; two active orders with different effects conflict.
  const auto& forces = s_.forces_;
  std::vector<AigLit> order_active(forces.size());
  std::vector<AigLit> forced(s_.charts_.size(), Aig::kFalse);
  for (std::size_t f = 0; f < forces.size(); ++f) {
    order_active[f] = active(cur, forces[f].step);
    auto& slot = forced[static_cast<std::size_t>(forces[f].chart)];
    for (std::size_t g = 0; g < f; ++g)
      if (forces[g].chart == forces[f].chart &&
          (forces[g].kind != forces[f].kind || forces[g].situation != forces[f].situation))
        error = aig_.make_or(error, aig_.make_and(order_active[g], order_active[f]));
    slot = aig_.make_or(slot, order_active[f]);
  }
  // Clearable transitions.
  cleared.assign(s_.trans_.size(), Aig::kFalse);
  for (std::size_t t = 0; t < s_.trans_.size(); ++t) {
    const auto& gt = s_.trans_[t];
    AigLit en = aig_.make_not(forced[static_cast<std::size_t>(gt.chart)]);
    for (int f : gt.need) en = aig_.make_and(en, bit(cur, f));
    cleared[t] = aig_.make_and(en, eval_truth(gt.guard, ctx));
  }
  std::vector<AigLit> event_fires(s_.stored_.size(), Aig::kFalse);
  for (std::size_t a = 0; a < s_.stored_.size(); ++a) {
    const auto& sa = s_.stored_[a];
    if (sa.when != model::StoredWhen::Event) continue;
    event_fires[a] = aig_.make_and(active(cur, sa.step), eval_truth(sa.event, ctx));
  }
  // Simultaneous clearing: deactivate every upstream step, then activate every downstream one.
  State next = cur;
  for (std::size_t t = 0; t < s_.trans_.size(); ++t)
    for (int f : s_.trans_[t].need)
      set_bit(next, f, aig_.make_and(bit(next, f), aig_.make_not(cleared[t])));
  for (std::size_t t = 0; t < s_.trans_.size(); ++t)
    for (int f : s_.trans_[t].act) set_bit(next, f, aig_.make_or(bit(next, f), cleared[t]));
  // Forced partial grafcets, in chart order; the last active order on a chart applies.
  for (std::size_t c = 0; c < s_.charts_.size(); ++c) {
    const State base = next;
    for (std::size_t f = 0; f < forces.size(); ++f) {
      const auto& fo = forces[f];
      if (static_cast<std::size_t>(fo.chart) != c) continue;
      State applied = base;
      if (fo.kind != model::ForcingKind::Current) {
        clear_chart(applied, static_cast<int>(c), false);
        if (fo.kind == model::ForcingKind::Initial)
          for (int st : s_.charts_[c].steps)
            if (s_.steps_[static_cast<std::size_t>(st)].initial) set_active(applied, st);
        for (int st : fo.situation) set_active(applied, st);
      }
      next = mux(order_active[f], applied, next);
    }
  }
  // Enclosing steps: activation activates the enclosed grafcets' linked steps (initial ones for
  // a grafcet without any); an inactive enclosing step clears the enclosed grafcets that still
  // have an active step (to a fixpoint).
  for (int e : s_.enclosing_) {
    const AigLit activated = aig_.make_and(aig_.make_not(active(cur, e)), active(next, e));
    State with = next;
    activate_enclosed(with, e);
    next = mux(activated, with, next);
  }
  std::size_t passes = 1;
  for (int e : s_.enclosing_) passes += s_.steps_[static_cast<std::size_t>(e)].enclosed.size();
  for (std::size_t pass = 0; pass < passes && !s_.enclosing_.empty(); ++pass)
    for (int e : s_.enclosing_) {
      const AigLit inactive = aig_.make_not(active(next, e));
      for (int c : s_.steps_[static_cast<std::size_t>(e)].enclosed) {
        AigLit any = Aig::kFalse;
        for (int st : s_.charts_[static_cast<std::size_t>(c)].steps)
          if (s_.steps_[static_cast<std::size_t>(st)].field >= 0)
            any = aig_.make_or(any, bit(next, s_.steps_[static_cast<std::size_t>(st)].field));
        State without = next;
        clear_chart(without, c);
        next = mux(aig_.make_and(inactive, any), without, next);
      }
    }
  // Stored actions: on deactivation, on activation, then on event; later writes win, each is
  // range-checked.
  struct Write {
    AigLit when;
    int var;
    Value value;
  };
  std::vector<Write> writes;
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& sa : s_.stored_) {
      const auto when = pass == 0 ? model::StoredWhen::Deactivation : model::StoredWhen::Activation;
      if (sa.when != when) continue;
      const AigLit was = active(cur, sa.step), is = active(next, sa.step);
      const AigLit cond =
          pass == 0 ? aig_.make_and(was, aig_.make_not(is)) : aig_.make_and(aig_.make_not(was), is);
      writes.push_back({cond, sa.var, eval(sa.value, ctx)});
    }
  for (std::size_t a = 0; a < s_.stored_.size(); ++a)
    if (s_.stored_[a].when == model::StoredWhen::Event)
      writes.push_back({event_fires[a], s_.stored_[a].var, eval(s_.stored_[a].value, ctx)});
  for (const auto& w : writes) {
    const auto& gv = s_.vars_[static_cast<std::size_t>(w.var)];
    Value v = w.value;
    if (gv.type.kind == model::TypeKind::Bool) {
      v = from_bool(truth(v));
    } else if (gv.type.kind == model::TypeKind::Int) {
      const AigLit out = aig_.make_or(bv_less_signed(aig_, v, constant(gv.type.lo)),
                                      bv_less_signed(aig_, constant(gv.type.hi), v));
      error = aig_.make_or(error, aig_.make_and(w.when, out));
    }
    auto& bits = next[static_cast<std::size_t>(gv.stored_field())];
    bits = bv_mux(aig_, w.when, encode(v, gv.stored_field()), bits);
  }
  // Delay phases follow their expression in the new situation (edges relative to `cur`, with
  // the same inputs), one delay after the other.
  for (const auto& d : s_.delays_) {
    const auto f = static_cast<std::size_t>(d.field);
    const State after = next;
    const AigLit x = eval_truth(d.expr, Ctx{&after, &cur});
    const BitVector ph = next[f];
    auto is = [&](std::uint64_t k) { return equals_constant(ph, k); };
    auto k2 = [](std::int64_t k) { return bv_constant(k, 2); };
    const BitVector on = bv_mux(aig_, is(0), k2(d.t1 > 0 ? 1 : 2), bv_mux(aig_, is(3), k2(2), ph));
    const BitVector off = bv_mux(aig_, is(2), k2(d.t2 > 0 ? 3 : 0), bv_mux(aig_, is(1), k2(0), ph));
    next[f] = bv_mux(aig_, x, on, off);
  }
  return next;
}

void CircuitBuilder::build() {
  const auto& layout = s_.layout_;
  const auto& fields = layout.fields();
  const StateView tmpl(s_.initial_template_);
  // State latches.
  State cur(fields.size());
  c_.field_latches.resize(fields.size());
  for (std::uint32_t f = 0; f < fields.size(); ++f) {
    const auto init = static_cast<std::uint64_t>(layout.get(tmpl, f) - fields[f].lo);
    for (std::uint32_t k = 0; k < fields[f].width; ++k) {
      c_.field_latches[f].push_back(static_cast<std::uint32_t>(aig_.latches().size()));
      cur[f].push_back(aig_.add_latch(
          fields[f].name + (fields[f].width > 1 ? "[" + std::to_string(k) + "]" : ""),
          ((init >> k) & 1U) != 0));
    }
  }
  c_.num_state_latches = aig_.latches().size();
  // Prev latches: the fields read under an edge.
  std::set<int> edge_fields;
  for (const auto& t : s_.trans_) collect_edge_fields(t.guard, false, edge_fields);
  for (const auto& a : s_.stored_) {
    collect_edge_fields(a.event, false, edge_fields);
    collect_edge_fields(a.value, false, edge_fields);
  }
  for (const auto& ca : s_.continuous_) collect_edge_fields(ca.condition, false, edge_fields);
  for (const auto& d : s_.delays_) collect_edge_fields(d.expr, false, edge_fields);
  State prev(fields.size());
  for (int f : edge_fields)
    for (std::size_t k = 0; k < cur[static_cast<std::size_t>(f)].size(); ++k) {
      const auto l = c_.field_latches[static_cast<std::size_t>(f)][k];
      c_.prev_of.push_back(l);
      prev[static_cast<std::size_t>(f)].push_back(aig_.add_latch("prev " + aig_.latches()[l].name));
    }
  // Circuit inputs (value - lo for integers), in range.
  AigLit allowed = Aig::kTrue;
  for (std::size_t i = 0; i < s_.gin_.size(); ++i) {
    const auto& in = s_.gin_[i];
    const bool integer = in.type.kind == model::TypeKind::Int && !in.pseudo;
    const std::int64_t lo = integer ? in.type.lo : 0, hi = integer ? in.type.hi : 1;
    const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    const std::uint32_t width = span == 0 ? 1 : static_cast<std::uint32_t>(std::bit_width(span));
    BitVector bits;
    for (std::uint32_t k = 0; k < width; ++k) {
      const AigLit l =
          aig_.add_input(s_.input_vars_[i].name + (width > 1 ? "[" + std::to_string(k) + "]" : ""));
      if (!in.pseudo && in.field < 0) c_.kept_inputs.push_back(aig_.nodes()[Aig::node_of(l)].index);
      bits.push_back(l);
    }
    const Value encoded = bv_resize(bits, kWidth, false);
    if (width < 64)
      allowed = aig_.make_and(
          allowed, aig_.make_not(bv_less_unsigned(
                       aig_, bv_constant(static_cast<std::int64_t>(span), kWidth), encoded)));
    c_.input_bits.push_back(bits);
    input_value_.push_back(bv_add(aig_, encoded, constant(lo)));
  }
  for (std::size_t i = 0; i < s_.gin_.size(); ++i) regions_.push_back(region_from_inputs(i));
  c_.allowed = allowed;

  // One evolution.
  AigLit error = Aig::kFalse;
  std::vector<AigLit> cleared;
  const State next = evolve(cur, prev, error, cleared);
  c_.range_error = error;
  c_.fired = cleared;
  AigLit stable = Aig::kTrue;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    stable = aig_.make_and(stable, equal_bits(next[f], cur[f]));
    for (std::size_t k = 0; k < next[f].size(); ++k)
      aig_.set_next(c_.field_latches[f][k], next[f][k]);
  }
  c_.stable = stable;
  for (std::size_t k = 0; k < c_.prev_of.size(); ++k)
    aig_.set_next(static_cast<std::uint32_t>(c_.num_state_latches + k),
                  aig_.latches()[c_.prev_of[k]].current);

  // The first situation of an event, read on the source: new input memory, elapsed delays.
  State start = cur, initial(fields.size());
  for (std::uint32_t f = 0; f < fields.size(); ++f) {
    const auto init = static_cast<std::uint64_t>(layout.get(tmpl, f) - fields[f].lo);
    for (std::uint32_t k = 0; k < fields[f].width; ++k)
      initial[f].push_back(((init >> k) & 1U) ? Aig::kTrue : Aig::kFalse);
  }
  std::vector<AigLit> changed;
  for (std::size_t i = 0; i < s_.gin_.size(); ++i) {
    const auto& in = s_.gin_[i];
    if (in.field < 0) continue;
    const auto f = static_cast<std::size_t>(in.field);
    BitVector reg = regions_[i];
    reg.resize(fields[f].width, Aig::kFalse);
    changed.push_back(aig_.make_not(equal_bits(reg, cur[f])));
    start[f] = reg;
    initial[f] = reg;
  }
  std::vector<AigLit> elapse, pseudo_bits;
  AigLit pseudo_ok = Aig::kTrue, no_pseudo = Aig::kTrue;
  for (const auto& d : s_.delays_) {
    if (d.pseudo < 0) continue;
    const auto f = static_cast<std::size_t>(d.field);
    const AigLit e = c_.input_bits[static_cast<std::size_t>(d.pseudo)][0];
    const AigLit p1 = equals_constant(cur[f], 1), p3 = equals_constant(cur[f], 3);
    start[f] = bv_mux(aig_, aig_.make_and(e, p1), bv_constant(2, 2),
                      bv_mux(aig_, aig_.make_and(e, p3), bv_constant(0, 2), cur[f]));
    pseudo_bits.push_back(e);
    pseudo_ok = aig_.make_and(pseudo_ok, aig_.make_implies(e, aig_.make_or(p1, p3)));
    no_pseudo = aig_.make_and(no_pseudo, aig_.make_not(e));
  }
  auto exactly_one = [&](const std::vector<AigLit>& xs) {
    AigLit none = Aig::kTrue, one = Aig::kFalse;
    for (auto x : xs) {
      one = aig_.make_or(aig_.make_and(one, aig_.make_not(x)), aig_.make_and(none, x));
      none = aig_.make_and(none, aig_.make_not(x));
    }
    return one;
  };
  if (s_.options_.single_input_change) {
    AigLit none_changed = Aig::kTrue;
    for (auto x : changed) none_changed = aig_.make_and(none_changed, aig_.make_not(x));
    c_.event = aig_.make_or(
        aig_.make_and(exactly_one(changed), no_pseudo),
        aig_.make_and(none_changed, aig_.make_and(exactly_one(pseudo_bits), pseudo_ok)));
  } else {
    c_.event = pseudo_ok;
  }
  c_.event = aig_.make_and(c_.event, allowed);
  c_.initial_event = aig_.make_and(no_pseudo, allowed);
  for (std::size_t f = 0; f < fields.size(); ++f) {
    for (auto l : start[f]) c_.start_next.push_back(l);
    for (auto l : initial[f]) c_.initial_next.push_back(l);
  }

  // The emitted stable situation: continuous outputs of the active steps (edges are false).
  State fin = cur;
  for (const auto& gv : s_.vars_)
    if (gv.continuous) set_bit(fin, gv.field, Aig::kFalse);
  for (const auto& ca : s_.continuous_) {
    AigLit on = active(cur, ca.step);
    if (ca.has_condition) on = aig_.make_and(on, eval_truth(ca.condition, Ctx{&cur, &cur}));
    const int f = s_.vars_[static_cast<std::size_t>(ca.var)].field;
    set_bit(fin, f, aig_.make_or(bit(fin, f), on));
  }
  for (std::size_t f = 0; f < fields.size(); ++f)
    for (auto l : fin[f]) c_.final_next.push_back(l);

  // Valid encodings: every field within its range.
  AigLit valid = Aig::kTrue;
  auto within = [&](int f, std::int64_t hi) {
    const Value v = decode(cur, f);
    valid = aig_.make_and(valid, aig_.make_not(bv_less_signed(aig_, constant(hi), v)));
  };
  for (const auto& gv : s_.vars_)
    if (gv.type.kind == model::TypeKind::Int) within(gv.field, gv.type.hi);
  for (const auto& in : s_.gin_)
    if (in.field >= 0) within(in.field, in.regions() - 1);
  c_.valid = valid;
  c_.max_transient_steps = s_.options_.max_transient_steps;

  // Observables, as observe() computes them.
  for (const auto& o : s_.obs_info_) {
    switch (o.ref) {
      case ObsRef::Step:
        c_.observable_bits.push_back({active(cur, o.index)});
        c_.observable_lo.push_back(0);
        break;
      case ObsRef::Variable: {
        const int f = s_.vars_[static_cast<std::size_t>(o.index)].field;
        if (s_.vars_[static_cast<std::size_t>(o.index)].mixed()) {
          c_.observable_bits.push_back({truth(variable(cur, o.index))});
          c_.observable_lo.push_back(0);
          break;
        }
        c_.observable_bits.push_back(cur[static_cast<std::size_t>(f)]);
        c_.observable_lo.push_back(fields[static_cast<std::size_t>(f)].lo);
        break;
      }
      case ObsRef::Input: {
        const auto& in = s_.gin_[static_cast<std::size_t>(o.index)];
        const auto& mem = cur[static_cast<std::size_t>(in.field)];
        if (in.type.kind != model::TypeKind::Int) {
          c_.observable_bits.push_back(mem);
          c_.observable_lo.push_back(0);
          break;
        }
        Value v = constant(0);
        for (std::size_t r = 0; r < in.region_lo.size(); ++r)
          v = bv_mux(aig_, equals_constant(mem, r), constant(in.region_lo[r]), v);
        c_.observable_bits.push_back(v);
        c_.observable_lo.push_back(0);
        break;
      }
    }
  }
}

}  // namespace grafcet

GrafcetCircuit build_grafcet_circuit(const TransitionSystem& ts, std::optional<Deadline> deadline,
                                     std::uint64_t max_memory_bytes) {
  if (as_history(ts))
    throw CircuitUnsupported(
        "prev(), rise() and fall() in a property: the Grafcet circuit does "
        "not keep previous situations yet (use --engine explicit)");
  const auto* sys = dynamic_cast<const grafcet::GrafcetSystem*>(&ts);
  if (!sys) throw std::invalid_argument("build_grafcet_circuit: not a Grafcet system");
  GrafcetCircuit c;
  c.aig.set_deadline(deadline);
  c.aig.set_memory_limit(max_memory_bytes);
  grafcet::CircuitBuilder builder(*sys, c);
  builder.build();
  c.aig.set_deadline(std::nullopt);
  c.aig.set_memory_limit(0);
  return c;
}

}  // namespace sfcv::semantics

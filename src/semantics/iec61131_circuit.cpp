// The scan cycle of iec_cycle.cpp / iec_machine.cpp, executed symbolically: every value is a
// 64-bit two's-complement bit vector over the Aig (the explicit machine computes in int64), every
// branch of the cycle is taken under its path condition, and a range error anywhere on a path
// raises range_error under that path. The structure follows the explicit machine function by
// function so that the two can be compared line by line.

#include "semantics/iec61131_circuit.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <optional>

#include "semantics/detail/iec_program.hpp"
#include "semantics/detail/iec_system_impl.hpp"
#include "semantics/history_system.hpp"

namespace sfcv::semantics {

namespace iec {
namespace {

constexpr std::uint32_t kWidth = 64;
using Value = BitVector;  // kWidth bits, signed

class SymbolicMachine {
 public:
  SymbolicMachine(const Program& p, TransitionCircuit& out) : p_(p), c_(out), aig_(out.aig) {}

  void build(StateView initial_state);

 private:
  // -------------------------------------------------------------------------- values
  Value constant(std::int64_t k) const { return bv_constant(k, kWidth); }
  Value from_bool(AigLit b) const {
    Value v = bv_constant(0, kWidth);
    v[0] = b;
    return v;
  }
  AigLit truth(const Value& v) { return aig_.make_or(std::vector<AigLit>(v.begin(), v.end())); }
  AigLit equal(const Value& a, const Value& b) { return bv_equal(aig_, a, b); }
  AigLit less(const Value& a, const Value& b) { return bv_less_signed(aig_, a, b); }
  Value mux(AigLit c, const Value& t, const Value& e) { return bv_mux(aig_, c, t, e); }
  Value min(const Value& a, const Value& b) { return mux(less(a, b), a, b); }
  Value max(const Value& a, const Value& b) { return mux(less(a, b), b, a); }

  /// a + b, raising a range error on signed 64-bit overflow (as __builtin_add_overflow).
  Value add(const Value& a, const Value& b, AigLit guard) {
    Value r = bv_add(aig_, a, b);
    const AigLit sa = a.back(), sb = b.back(), sr = r.back();
    // Overflow: both operands have the same sign and the result the other one.
    raise(guard, aig_.make_and(aig_.make_xnor(sa, sb), aig_.make_xor(sa, sr)));
    return r;
  }
  Value sub(const Value& a, const Value& b, AigLit guard) {
    Value r = bv_sub(aig_, a, b);
    const AigLit sa = a.back(), sb = b.back(), sr = r.back();
    raise(guard, aig_.make_and(aig_.make_xor(sa, sb), aig_.make_xor(sa, sr)));
    return r;
  }
  Value neg(const Value& a, AigLit guard) {
    raise(guard, equal(a, constant(std::numeric_limits<std::int64_t>::min())));
    return bv_neg(aig_, a);
  }
  /// a * k for a constant k, by shifts and adds with overflow checks.
  Value mul_constant(const Value& a, std::int64_t k, AigLit guard) {
    if (k == 0) return constant(0);
    if (k == std::numeric_limits<std::int64_t>::min())
      throw CircuitUnsupported("multiplication by the smallest 64-bit integer");
    const bool negative = k < 0;
    auto magnitude = static_cast<std::uint64_t>(negative ? -k : k);
    Value acc = constant(0);
    Value shifted = a;
    while (magnitude) {
      if (magnitude & 1U) acc = add(acc, shifted, guard);
      magnitude >>= 1;
      if (magnitude) {
        // shifted * 2 overflows when its two top bits differ.
        raise(guard, aig_.make_xor(shifted[kWidth - 1], shifted[kWidth - 2]));
        Value doubled(kWidth);
        doubled[0] = Aig::kFalse;
        for (std::uint32_t i = 1; i < kWidth; ++i) doubled[i] = shifted[i - 1];
        shifted = doubled;
      }
    }
    return negative ? neg(acc, guard) : acc;
  }
  /// x / k or x MOD k for a constant k, truncating toward zero as int64 does (the remainder
  /// has the dividend's sign): restoring long division of |x| by |k|, then the signs. It runs
  /// on the bits x really has: a small-range value's upper bits are copies of its sign, so |x|
  /// fits in w bits and the division takes w rounds of w + 1 bits, not 64 of 64.
  Value div_mod_constant(const Value& x, std::int64_t k, bool want_quotient, AigLit guard) {
    if (k == 0) {
      raise(guard, Aig::kTrue);
      return constant(0);
    }
    if (k == -1) return want_quotient ? neg(x, guard) : constant(0);
    const AigLit negative = x[kWidth - 1];
    std::uint32_t w = kWidth;  // x[w - 1 .. 63] are all the sign
    while (w > 1 && x[w - 2] == negative) --w;
    const auto divisor = k < 0 ? static_cast<std::uint64_t>(0) - static_cast<std::uint64_t>(k)
                               : static_cast<std::uint64_t>(k);
    if (w < kWidth && divisor >= (std::uint64_t{1} << w))  // |x| <= 2^(w-1) < divisor
      return want_quotient ? constant(0) : x;
    // |x| as w unsigned bits (2^63 for the minimum), and the divisor in w + 1 bits.
    const Value full = mux(negative, bv_neg(aig_, x), x);
    const Value magnitude(full.begin(), full.begin() + w);
    BitVector d(w + 1, Aig::kFalse);
    for (std::uint32_t b = 0; b < std::min<std::uint32_t>(w + 1, 64); ++b)
      if ((divisor >> b) & 1U) d[b] = Aig::kTrue;
    Value quotient = constant(0);
    BitVector rest(w + 1, Aig::kFalse);
    for (std::uint32_t i = w; i-- > 0;) {
      // rest < divisor and rest < 2^w, so 2 * rest + 1 fits in w + 1 bits.
      BitVector shifted(w + 1);
      shifted[0] = magnitude[i];
      for (std::uint32_t b = 1; b <= w; ++b) shifted[b] = rest[b - 1];
      const AigLit fits = aig_.make_not(bv_less_unsigned(aig_, shifted, d));
      rest = bv_mux(aig_, fits, bv_sub(aig_, shifted, d), shifted);
      quotient[i] = fits;
    }
    if (want_quotient) {
      const AigLit flip = k < 0 ? aig_.make_not(negative) : negative;
      return mux(flip, bv_neg(aig_, quotient), quotient);
    }
    Value remainder = constant(0);
    for (std::uint32_t b = 0; b < w; ++b) remainder[b] = rest[b];
    return mux(negative, bv_neg(aig_, remainder), remainder);
  }
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

  AigLit compare(Op cmp, const Value& x, const Value& k) {
    switch (cmp) {
      case Op::Eq:
        return equal(x, k);
      case Op::Ne:
        return aig_.make_not(equal(x, k));
      case Op::Lt:
        return less(x, k);
      case Op::Le:
        return aig_.make_not(less(k, x));
      case Op::Gt:
        return less(k, x);
      default:
        return aig_.make_not(less(x, k));
    }
  }

  void raise(AigLit guard, AigLit condition) {
    c_.range_error =
        aig_.make_or(c_.range_error, aig_.make_and(outer_, aig_.make_and(guard, condition)));
  }

  // ------------------------------------------------------------------------- state
  Value decode(const BitVector& encoded, std::int64_t lo) {
    return bv_add(aig_, bv_resize(encoded, kWidth, false), constant(lo));
  }
  BitVector encode(const Value& v, std::uint32_t field) {
    const auto& f = p_.layout.fields()[field];
    const Value shifted = bv_sub(aig_, v, constant(f.lo));
    return BitVector(shifted.begin(), shifted.begin() + f.width);
  }
  Value input_value(std::uint32_t input) { return input_values_[input]; }

  AigLit cur_truth(std::uint32_t f) { return truth(cur_[f]); }
  AigLit nxt_truth(std::uint32_t f) { return truth(nxt_[f]); }

  AigLit chart_active_cur(std::uint32_t chart) {
    const auto pa = p_.charts[chart].parent_action;
    return pa == kNone ? Aig::kTrue : cur_truth(p_.actions[static_cast<std::size_t>(pa)].active);
  }
  AigLit step_active_cur(std::uint32_t step) {
    const auto& s = p_.steps[step];
    return aig_.make_and(cur_truth(s.ready), chart_active_cur(s.chart));
  }
  AigLit step_active_next(std::uint32_t step) {
    const auto& s = p_.steps[step];
    const auto pa = p_.charts[s.chart].parent_action;
    const AigLit parent =
        pa == kNone ? Aig::kTrue : nxt_truth(p_.actions[static_cast<std::size_t>(pa)].active);
    return aig_.make_and(nxt_truth(s.ready), parent);
  }

  // ------------------------------------------------------------------ expressions
  Value eval(std::uint32_t index, AigLit guard);
  AigLit eval_truth(std::uint32_t index, AigLit guard) { return truth(eval(index, guard)); }

  // ------------------------------------------------------------------- statements
  void assign(std::uint32_t field, const Value& v, AigLit guard) {
    const auto lo = p_.field_lo[field], hi = p_.field_hi[field];
    raise(guard, aig_.make_or(less(v, constant(lo)), less(constant(hi), v)));
    // Where no range error is raised, v lies in [lo, hi], so its upper bits are known: FALSE
    // when lo >= 0, else copies of bit b - 1. Storing them as such costs no gate and lets later
    // operations (comparisons, a division by a constant) see how few bits the value has.
    Value canonical;
    if (lo >= 0) {
      const auto b = static_cast<std::uint32_t>(std::bit_width(static_cast<std::uint64_t>(hi)));
      canonical.assign(v.begin(), v.begin() + b);
      canonical.resize(kWidth, Aig::kFalse);
    } else {
      std::uint32_t b = 1;
      while (b < kWidth &&
             (lo < -(std::int64_t{1} << (b - 1)) || hi > (std::int64_t{1} << (b - 1)) - 1))
        ++b;
      canonical.assign(v.begin(), v.begin() + b);
      canonical.resize(kWidth, v[b - 1]);
    }
    nxt_[field] = mux(guard, canonical, nxt_[field]);
  }
  void set(std::uint32_t field, const Value& v, AigLit guard) {
    nxt_[field] = mux(guard, v, nxt_[field]);
  }
  void set_bool(std::uint32_t field, AigLit b, AigLit guard) { set(field, from_bool(b), guard); }
  /// Statements run on the paths of `guard` where no EXIT, CONTINUE or RETURN was taken.
  void exec_block(Block b, AigLit guard) {
    for (std::uint32_t i = 0; i < b.count; ++i)
      exec_stmt(p_.stmts[p_.block_items[b.first + i]],
                aig_.make_and(guard, aig_.make_not(aig_.make_or(left_loop_, returned_))));
  }
  /// A top-level body (a POU's or an action's): RETURN ends it.
  // A body (a POU's, an action's, or a called instance's inside its caller's) leaves by RETURN
  // on its own paths only: the caller's RETURN and loop exits are kept across it.
  void exec_body(Block b, AigLit guard) {
    const AigLit returned = returned_, left_loop = left_loop_, exit = exit_;
    returned_ = left_loop_ = exit_ = Aig::kFalse;
    exec_block(b, guard);
    returned_ = returned;
    left_loop_ = left_loop;
    exit_ = exit;
  }
  void exec_stmt(const Stmt& s, AigLit guard);
  void exec_loop(const Stmt& s, AigLit guard);
  Value bit_op(const Node& n, const std::uint32_t* kid, AigLit guard);
  Value call_function(const Node& n, const std::uint32_t* kid, AigLit guard);
  void fb_call(const Stmt& s, AigLit guard);

  // ----------------------------------------------------------------------- timers
  AigLit timer_expired(const Timer& t, const Value& v) {
    if (p_.options.time == TimeMode::Abstract) return equal(v, constant(2));
    // (v - 1) * cycle >= duration, v != 0  <=>  v >= max(1, 1 + ceil(duration / cycle))
    const std::int64_t c = p_.options.cycle_ms;
    const std::int64_t d = t.duration_ms;
    const std::int64_t need = d <= 0 ? 1 : 1 + (d + c - 1) / c;
    return aig_.make_not(less(v, constant(need)));
  }
  std::size_t timer_index(const Timer& t) const {
    return static_cast<std::size_t>(&t - p_.timers.data());
  }
  Value timer_next(const Timer& t, AigLit run, AigLit restart) {
    const Value v = nxt_[t.field];
    const AigLit idle = equal(v, constant(0));
    Value running;
    if (p_.options.time == TimeMode::Abstract) {
      const Value start = constant(t.duration_ms <= 0 ? 2 : 1);
      const AigLit timeout = truth(input_value(static_cast<std::uint32_t>(t.timeout_input)));
      Value advanced =
          mux(equal(v, constant(2)), constant(2), mux(timeout, constant(2), constant(1)));
      // Started in this cycle (a second call): no time has passed yet (Machine::timer_next).
      if (t.clocked) advanced = mux(started_[timer_index(t)], v, advanced);
      running = mux(aig_.make_or(idle, restart), start, advanced);
    } else {
      // A clocked timer's field already holds this cycle's age (advance_clock).
      const Value bumped = t.clocked ? v : min(bv_add(aig_, v, constant(1)), constant(t.max_value));
      running = mux(aig_.make_or(idle, restart), constant(1), bumped);
    }
    return mux(run, running, constant(0));
  }
  /// Abstract time: a clocked timer started on the paths of `when`.
  void note_start(const Timer& t, AigLit when) {
    if (p_.options.time != TimeMode::Abstract) return;
    auto& s = started_[timer_index(t)];
    s = aig_.make_or(s, when);
  }
  /// A new cycle's clock (Machine::advance_clock).
  void advance_clock() {
    started_.assign(p_.timers.size(), Aig::kFalse);
    step_started_.assign(p_.steps.size(), Aig::kFalse);
    if (p_.options.time != TimeMode::Discrete) return;
    for (const auto& t : p_.timers) {
      if (!t.clocked) continue;
      const Value& v = cur_[t.field];
      nxt_[t.field] = mux(equal(v, constant(0)), constant(0),
                          min(bv_add(aig_, v, constant(1)), constant(t.max_value)));
    }
    for (std::uint32_t s = 0; s < p_.steps.size(); ++s)
      if (clocked_step(s)) nxt_[static_cast<std::uint32_t>(p_.steps[s].t_field)] = aged_step(s);
  }
  bool clocked_step(std::uint32_t s) const {
    return p_.steps[s].clocked && p_.steps[s].t_field != kNone;
  }
  /// Discrete time: a clocked step's .T one cycle older if the step was active (Machine::age_step).
  Value aged_step(std::uint32_t s) {
    const auto& st = p_.steps[s];
    const Value& v = cur_[static_cast<std::uint32_t>(st.t_field)];
    return mux(step_active_cur(s), min(bv_add(aig_, v, constant(1)), constant(st.t_max)), v);
  }
  /// A qualifier's timer; a clocked one notes its start (abstract time, Machine::timer_next).
  Value qualifier_timer(const Timer& t, AigLit run, AigLit restart, AigLit guard) {
    if (t.clocked) {
      const AigLit starts = aig_.make_or(equal(nxt_[t.field], constant(0)), restart);
      note_start(t, aig_.make_and(guard, aig_.make_and(run, starts)));
    }
    return timer_next(t, run, restart);
  }
  void snapshot_et(const Fb& fb, const Timer& t, AigLit guard) {
    if (fb.et != kNone) set(static_cast<std::uint32_t>(fb.et), nxt_[t.field], guard);
  }

  // -------------------------------------------------------------------- the cycle
  /// `guard`: the path condition of a called instance's cycle (a Call under an IF); a program
  /// runs under the inputs' constraint only, and its state updates are unconditional.
  void cycle_pou(const Pou& pou, AigLit guard);
  void run_slot(const Pou& pou, std::size_t i, AigLit run);
  void call_instance(const Pou& pou, AigLit guard);
  void fire_chart(const Chart& c, AigLit guard);
  void fire(const Transition& t, AigLit when);
  void update_pou(const Pou& pou, AigLit guard);
  void step_times(const Pou& pou, AigLit guard);

  const Program& p_;
  TransitionCircuit& c_;
  Aig& aig_;
  std::vector<Value> cur_, nxt_, input_values_;
  std::vector<std::int64_t> initial_values_;  ///< per field: what SFCInit/SFCReset restore
  std::vector<AigLit> consumed_, entered_, left_;
  std::vector<AigLit> started_;       ///< per timer: started in this cycle (abstract time)
  std::vector<AigLit> step_started_;  ///< per step: entered in this cycle (abstract time)
  // Paths (under the current loop) that took EXIT or CONTINUE, and paths that took RETURN.
  AigLit left_loop_ = Aig::kFalse, exit_ = Aig::kFalse, returned_ = Aig::kFalse;
  // Range errors are raised only under this condition: inside a loop, the loop's guard.
  AigLit outer_ = Aig::kTrue;
};

Value SymbolicMachine::eval(std::uint32_t index, AigLit guard) {
  const Node& n = p_.nodes[index];
  const std::uint32_t* kid = p_.kids.data() + n.first;
  switch (n.op) {
    case Op::Const:
      return constant(n.k);
    case Op::Field:
      return nxt_[n.a];
    case Op::Input:
      return input_value(n.a);
    case Op::InputCmp:
      return from_bool(compare(n.cmp, input_value(n.a), constant(n.k)));
    case Op::InputCmpExpr: {
      const Value k = eval(kid[0], guard);
      return from_bool(compare(n.cmp, input_value(n.a), k));
    }
    case Op::StepX:
      return from_bool(step_active_cur(n.a));
    case Op::StepT: {
      const auto& s = p_.steps[n.a];
      const Value t =
          mul_constant(cur_[static_cast<std::size_t>(s.t_field)], p_.options.cycle_ms, guard);
      return mux(cur_truth(s.ready), t, constant(0));
    }
    case Op::StepTCmp: {
      const auto& s = p_.steps[n.a];
      const AigLit r =
          aig_.make_not(less(cur_[static_cast<std::size_t>(s.t_field)], constant(n.k)));
      return from_bool(n.negate ? aig_.make_not(r) : r);
    }
    case Op::TimerQ:
      return nxt_[static_cast<std::size_t>(p_.fbs[n.a].q)];
    case Op::TimerET: {
      const auto& fb = p_.fbs[n.a];
      if (fb.et == kNone) return constant(0);  // never called
      const Value v = nxt_[static_cast<std::size_t>(fb.et)];
      const Value elapsed = mul_constant(bv_sub(aig_, v, constant(1)), p_.options.cycle_ms, guard);
      return mux(equal(v, constant(0)), constant(0), min(elapsed, constant(fb.pt_ms)));
    }
    case Op::Not:
      return from_bool(aig_.make_not(eval_truth(kid[0], guard)));
    case Op::Neg:
      return neg(eval(kid[0], guard), guard);
    case Op::And: {
      // Short-circuit as the explicit machine: kid i is evaluated only if kids before it held.
      AigLit all = Aig::kTrue;
      for (std::uint32_t i = 0; i < n.count; ++i)
        all = aig_.make_and(all, eval_truth(kid[i], aig_.make_and(guard, all)));
      return from_bool(all);
    }
    case Op::Or: {
      AigLit any = Aig::kFalse;
      for (std::uint32_t i = 0; i < n.count; ++i)
        any = aig_.make_or(any, eval_truth(kid[i], aig_.make_and(guard, aig_.make_not(any))));
      return from_bool(any);
    }
    case Op::Xor: {
      AigLit r = Aig::kFalse;
      for (std::uint32_t i = 0; i < n.count; ++i) r = aig_.make_xor(r, eval_truth(kid[i], guard));
      return from_bool(r);
    }
    case Op::Add: {
      const Value x = eval(kid[0], guard);
      return add(x, eval(kid[1], guard), guard);
    }
    case Op::Sub: {
      const Value x = eval(kid[0], guard);
      return sub(x, eval(kid[1], guard), guard);
    }
    case Op::Mul: {
      const Value x = eval(kid[0], guard);
      const Value y = eval(kid[1], guard);
      if (auto k = as_constant(y)) return mul_constant(x, *k, guard);
      if (auto k = as_constant(x)) return mul_constant(y, *k, guard);
      throw CircuitUnsupported("a product of two variables");
    }
    case Op::Div:
    case Op::Mod: {
      const Value x = eval(kid[0], guard);
      const Value y = eval(kid[1], guard);
      const auto kx = as_constant(x), ky = as_constant(y);
      if (kx && ky) {
        if (*ky == 0 || (*kx == std::numeric_limits<std::int64_t>::min() && *ky == -1)) {
          raise(guard, Aig::kTrue);
          return constant(0);
        }
        return constant(n.op == Op::Div ? *kx / *ky : *kx % *ky);
      }
      if (ky) return div_mod_constant(x, *ky, n.op == Op::Div, guard);
      throw CircuitUnsupported(n.op == Op::Div ? "a division of variables" : "a MOD of variables");
    }
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge: {
      const Value x = eval(kid[0], guard);
      const Value y = eval(kid[1], guard);
      return from_bool(compare(n.op, x, y));
    }
    case Op::Ite: {
      const AigLit c = eval_truth(kid[0], guard);
      const Value t = eval(kid[1], aig_.make_and(guard, c));
      return mux(c, t, eval(kid[2], aig_.make_and(guard, aig_.make_not(c))));
    }
    case Op::RangeCheck: {
      const Value v = eval(kid[0], guard);
      const Value lo = eval(kid[1], guard), hi = eval(kid[2], guard);
      raise(guard, aig_.make_or(less(v, lo), less(hi, v)));
      return v;
    }
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor: {
      Value r = eval(kid[0], guard);
      for (std::uint32_t i = 1; i < n.count; ++i) {
        const Value v = eval(kid[i], guard);
        for (std::uint32_t b = 0; b < kWidth; ++b)
          r[b] = n.op == Op::BitAnd  ? aig_.make_and(r[b], v[b])
                 : n.op == Op::BitOr ? aig_.make_or(r[b], v[b])
                                     : aig_.make_xor(r[b], v[b]);
      }
      return r;
    }
    case Op::BitNot:
    case Op::Shl:
    case Op::Shr:
    case Op::Rol:
    case Op::Ror:
      return bit_op(n, kid, guard);
    case Op::Call:
      return call_function(n, kid, guard);
  }
  return constant(0);
}

void SymbolicMachine::exec_stmt(const Stmt& s, AigLit guard) {
  switch (s.op) {
    case SOp::Assign:
      assign(s.target, eval(s.expr, guard), guard);
      return;
    case SOp::Eval:
      eval(s.expr, guard);
      return;
    case SOp::If: {
      AigLit rest = guard;
      for (std::uint32_t i = 0; i < s.arm_count; ++i) {
        const auto& arm = p_.if_arms[s.arm_first + i];
        const AigLit c = eval_truth(arm.cond, rest);
        exec_block(arm.body, aig_.make_and(rest, c));
        rest = aig_.make_and(rest, aig_.make_not(c));
      }
      exec_block(s.else_body, rest);
      return;
    }
    case SOp::Case: {
      const Value sel = eval(s.expr, guard);
      AigLit rest = guard;
      for (std::uint32_t i = 0; i < s.arm_count; ++i) {
        const auto& arm = p_.case_arms[s.arm_first + i];
        AigLit match = Aig::kFalse;
        for (std::uint32_t l = 0; l < arm.label_count; ++l) {
          const auto& lab = p_.case_labels[arm.label_first + l];
          match = aig_.make_or(match, aig_.make_and(aig_.make_not(less(sel, constant(lab.lo))),
                                                    aig_.make_not(less(constant(lab.hi), sel))));
        }
        exec_block(arm.body, aig_.make_and(rest, match));
        rest = aig_.make_and(rest, aig_.make_not(match));
      }
      exec_block(s.else_body, rest);
      return;
    }
    case SOp::FbCall:
      fb_call(s, guard);
      return;
    case SOp::Loop:
      exec_loop(s, guard);
      return;
    case SOp::Exit:
      exit_ = aig_.make_or(exit_, guard);
      left_loop_ = aig_.make_or(left_loop_, guard);
      return;
    case SOp::Continue:
      left_loop_ = aig_.make_or(left_loop_, guard);
      return;
    case SOp::Return:
      returned_ = aig_.make_or(returned_, guard);
      return;
    case SOp::Call:
      call_instance(p_.pous[s.target], guard);
      return;
  }
}

// A loop is unrolled on a "live" copy of the variables: their values on the paths where the
// loop has gone on so far, computed as if the statement runs; so a loop with constant bounds
// folds to its exact number of iterations (even under a bound that depends on an input). The
// values of the paths that leave (the condition fails, EXIT, RETURN, UNTIL holds) are collected
// in `result`, merged back under `guard` at the end. Range errors inside are raised only on the
// paths still in the loop (outer_). Past kMaxLoopIterations the paths still going raise a
// range error (the explicit machine answers unknown for a loop that does not repeat).
void SymbolicMachine::exec_loop(const Stmt& s, AigLit guard) {
  const auto saved = nxt_;
  const AigLit saved_outer = outer_, saved_left = left_loop_, saved_exit = exit_,
               saved_return = returned_;
  const AigLit base = aig_.make_and(outer_, guard);
  outer_ = base;
  left_loop_ = exit_ = returned_ = Aig::kFalse;
  exec_block(s.init, Aig::kTrue);
  auto result = nxt_;
  auto leave = [&](AigLit when) {
    if (when == Aig::kFalse) return;
    for (std::size_t f = 0; f < nxt_.size(); ++f) result[f] = mux(when, nxt_[f], result[f]);
  };
  AigLit going = Aig::kTrue, returned_any = Aig::kFalse;
  // The explicit machine's repeat test (Machine::exec_loop): snapshots of the variables at
  // iterations 64, 128, 256, 512; a path whose variables equal the last snapshot at the start
  // of a later iteration never ends (a range error) and leaves the loop's paths.
  std::vector<Value> mark;
  std::int64_t mark_at = 64;
  for (std::int64_t n = 0;; ++n) {
    outer_ = aig_.make_and(base, going);
    if (!s.test_after) {
      const AigLit c = eval_truth(s.expr, Aig::kTrue);
      leave(aig_.make_and(going, aig_.make_not(c)));
      going = aig_.make_and(going, c);
    }
    if (going == Aig::kFalse) break;
    outer_ = aig_.make_and(base, going);
    if (n >= 64) {
      if (n == mark_at) {
        mark = nxt_;
        mark_at *= 2;
      } else {
        AigLit same = Aig::kTrue;
        for (std::size_t f = 0; f < nxt_.size() && same != Aig::kFalse; ++f)
          if (nxt_[f] != mark[f]) same = aig_.make_and(same, equal(nxt_[f], mark[f]));
        raise(same, Aig::kTrue);
        going = aig_.make_and(going, aig_.make_not(same));
        if (going == Aig::kFalse) break;
        outer_ = aig_.make_and(base, going);
      }
    }
    if (n == kMaxLoopIterations) {
      // The paths still going have not repeated: the loop may still end, a limit of sfcv and
      // not a finding (docs/semantics.md 1.9.1). They have no successor (range_error) and are
      // marked as loop_limit, which every engine answers as unknown.
      raise(going, Aig::kTrue);
      c_.loop_limit = aig_.make_or(c_.loop_limit, outer_);
      const std::string at = "at " + s.where;
      if (c_.loop_limit_where.find(at) == std::string::npos)
        c_.loop_limit_where += (c_.loop_limit_where.empty() ? "" : ", ") + at;
      break;
    }
    left_loop_ = exit_ = returned_ = Aig::kFalse;
    exec_block(s.body, Aig::kTrue);
    const AigLit out = aig_.make_and(going, aig_.make_or(exit_, returned_));
    returned_any = aig_.make_or(returned_any, aig_.make_and(going, returned_));
    leave(out);
    going = aig_.make_and(going, aig_.make_not(aig_.make_or(exit_, returned_)));
    left_loop_ = exit_ = returned_ = Aig::kFalse;
    outer_ = aig_.make_and(base, going);
    exec_block(s.step, Aig::kTrue);
    if (s.test_after) {
      const AigLit u = eval_truth(s.expr, Aig::kTrue);
      leave(aig_.make_and(going, u));
      going = aig_.make_and(going, aig_.make_not(u));
      if (going == Aig::kFalse) break;
    }
  }
  for (std::size_t f = 0; f < nxt_.size(); ++f) nxt_[f] = mux(guard, result[f], saved[f]);
  outer_ = saved_outer;
  left_loop_ = saved_left;
  exit_ = saved_exit;
  returned_ = aig_.make_or(saved_return, aig_.make_and(guard, returned_any));
}

// A call of a user function runs its body under the call's path condition, as the machine
// does at that point of the expression; its variables hold constants before and after.
Value SymbolicMachine::call_function(const Node& n, const std::uint32_t* kid, AigLit guard) {
  const Function& fn = p_.functions[n.a];
  std::vector<Value> args;
  args.reserve(n.count);
  for (std::uint32_t i = 0; i < n.count; ++i) args.push_back(eval(kid[i], guard));
  for (auto f : fn.fields) nxt_[f] = constant(p_.initial[f]);
  for (std::uint32_t i = 0; i < n.count; ++i) assign(fn.inputs[i], args[i], guard);
  exec_body(fn.body, guard);
  const Value result = nxt_[fn.result];
  if (n.k > 0)
    for (const auto& [from, to] : p_.call_output_copies[static_cast<std::size_t>(n.k - 1)])
      assign(to, nxt_[from], guard);
  for (auto f : fn.fields) nxt_[f] = constant(p_.initial[f]);
  return result;
}

Value SymbolicMachine::bit_op(const Node& n, const std::uint32_t* kid, AigLit guard) {
  const auto width = static_cast<std::uint32_t>(n.k);
  Value x = eval(kid[0], guard);
  for (std::uint32_t i = width; i < kWidth; ++i) x[i] = Aig::kFalse;
  if (n.op == Op::BitNot) {
    for (std::uint32_t i = 0; i < width; ++i) x[i] = aig_.make_not(x[i]);
    return x;
  }
  const Value by = eval(kid[1], guard);
  const bool shift = n.op == Op::Shl || n.op == Op::Shr;
  // x moved by a constant count c >= 0 (a rotation's count already below the width).
  auto moved = [&](std::uint64_t c) {
    Value r = constant(0);
    if (shift) {
      if (c >= width) return r;
      const auto s = static_cast<std::uint32_t>(c);
      for (std::uint32_t i = 0; i < width; ++i) {
        if (n.op == Op::Shl && i >= s) r[i] = x[i - s];
        if (n.op == Op::Shr && i + s < width) r[i] = x[i + s];
      }
      return r;
    }
    const auto s = static_cast<std::uint32_t>(c % width);
    const auto left = n.op == Op::Rol ? s : (width - s) % width;
    for (std::uint32_t i = 0; i < width; ++i) r[(i + left) % width] = x[i];
    return r;
  };
  if (const auto k = as_constant(by)) {
    if (*k < 0) {
      raise(guard, Aig::kTrue);
      return constant(0);
    }
    return moved(static_cast<std::uint64_t>(*k));
  }
  // A variable count: a negative one is a range error, as in the machine; then one result per
  // count that can make a difference (0 .. width - 1; a shift by more gives 0, a rotation
  // takes the count modulo the width), chosen by the count.
  raise(guard, by[kWidth - 1]);
  const Value count = shift ? by : div_mod_constant(by, width, false, guard);
  Value r = shift ? constant(0) : moved(0);
  for (std::uint32_t c = 0; c < width; ++c) r = mux(equal(count, constant(c)), moved(c), r);
  return r;
}

void SymbolicMachine::fb_call(const Stmt& s, AigLit guard) {
  const Fb& fb = p_.fbs[s.target];
  auto arg = [&](std::int32_t node) {
    return node == kNone ? constant(0) : eval(static_cast<std::uint32_t>(node), guard);
  };
  auto field = [](std::int32_t f) { return static_cast<std::uint32_t>(f); };
  const auto q = field(fb.q);
  switch (fb.kind) {
    case model::StandardFb::R_TRIG:
    case model::StandardFb::F_TRIG: {
      const AigLit clk = truth(arg(s.arg1));
      const AigLit mem = nxt_truth(field(fb.mem));
      if (fb.kind == model::StandardFb::R_TRIG) {
        set_bool(q, aig_.make_and(clk, aig_.make_not(mem)), guard);
        set_bool(field(fb.mem), clk, guard);
      } else {
        set_bool(q, aig_.make_and(aig_.make_not(clk), aig_.make_not(mem)), guard);
        set_bool(field(fb.mem), aig_.make_not(clk), guard);
      }
      return;
    }
    case model::StandardFb::SR: {
      const AigLit s1 = truth(arg(s.arg1)), r = truth(arg(s.arg2));
      set_bool(q, aig_.make_or(s1, aig_.make_and(aig_.make_not(r), nxt_truth(q))), guard);
      return;
    }
    case model::StandardFb::RS: {
      const AigLit st = truth(arg(s.arg1)), r1 = truth(arg(s.arg2));
      set_bool(q, aig_.make_and(aig_.make_not(r1), aig_.make_or(st, nxt_truth(q))), guard);
      return;
    }
    case model::StandardFb::CTU:
    case model::StandardFb::CTD: {
      const bool up = fb.kind == model::StandardFb::CTU;
      const AigLit edge_in = truth(arg(s.arg1)), other = truth(arg(s.arg2));
      const Value pv = arg(s.arg3);
      const AigLit rise = aig_.make_and(edge_in, aig_.make_not(nxt_truth(field(fb.mem))));
      set_bool(field(fb.mem), edge_in, guard);
      const auto cvf = field(fb.cv);
      const Value cv = nxt_[cvf];
      Value next_cv;
      if (up) {
        const AigLit can = aig_.make_and(rise, less(cv, constant(p_.field_hi[cvf])));
        next_cv = mux(other, constant(0), mux(can, bv_add(aig_, cv, constant(1)), cv));
      } else {
        raise(aig_.make_and(guard, other), aig_.make_or(less(pv, constant(p_.field_lo[cvf])),
                                                        less(constant(p_.field_hi[cvf]), pv)));
        const AigLit can = aig_.make_and(rise, less(constant(p_.field_lo[cvf]), cv));
        next_cv = mux(other, pv, mux(can, bv_sub(aig_, cv, constant(1)), cv));
      }
      set(cvf, next_cv, guard);
      set_bool(q, up ? aig_.make_not(less(next_cv, pv)) : aig_.make_not(less(constant(0), next_cv)),
               guard);
      return;
    }
    case model::StandardFb::TON: {
      const AigLit in = truth(arg(s.arg1));
      const auto& t = p_.timers[static_cast<std::size_t>(fb.timer)];
      note_start(t, aig_.make_and(guard, aig_.make_and(in, equal(nxt_[t.field], constant(0)))));
      const Value v = timer_next(t, in, Aig::kFalse);
      set(t.field, v, guard);
      set_bool(q, s.pt_zero ? in : aig_.make_and(in, timer_expired(t, v)), guard);
      snapshot_et(fb, t, guard);
      return;
    }
    case model::StandardFb::TOF: {
      const AigLit in = truth(arg(s.arg1));
      const auto& t = p_.timers[static_cast<std::size_t>(fb.timer)];
      const AigLit was =
          aig_.make_or(nxt_truth(q), aig_.make_not(equal(nxt_[t.field], constant(0))));
      const Value v = timer_next(t, Aig::kTrue, Aig::kFalse);
      const AigLit off_running = aig_.make_and(aig_.make_not(in), was);
      note_start(
          t, aig_.make_and(guard, aig_.make_and(off_running, equal(nxt_[t.field], constant(0)))));
      // IN: reset the timer, Q = 1; not IN and running: advance; otherwise unchanged.
      set(t.field, mux(in, constant(0), mux(off_running, v, nxt_[t.field])), guard);
      set_bool(q, aig_.make_or(in, aig_.make_and(off_running, aig_.make_not(timer_expired(t, v)))),
               aig_.make_and(guard, aig_.make_or(in, off_running)));
      snapshot_et(fb, t, guard);
      return;
    }
    case model::StandardFb::TP: {
      const AigLit in = truth(arg(s.arg1));
      const auto& t = p_.timers[static_cast<std::size_t>(fb.timer)];
      const AigLit last_in = nxt_truth(field(fb.mem));
      set_bool(field(fb.mem), in, guard);
      const AigLit idle = equal(nxt_[t.field], constant(0));
      const AigLit start = aig_.make_and(idle, aig_.make_and(in, aig_.make_not(last_in)));
      // Starting: restart the timer; running: advance it. Both end at 0 when done and IN is off.
      const Value started = timer_next(t, Aig::kTrue, Aig::kTrue);
      const Value advanced = timer_next(t, Aig::kTrue, Aig::kFalse);
      const Value v = mux(idle, started, advanced);
      const AigLit done = timer_expired(t, v);
      const AigLit q_running = aig_.make_not(done);
      const AigLit clear = aig_.make_and(done, aig_.make_not(in));
      const AigLit moving = aig_.make_or(start, aig_.make_not(idle));
      set(t.field, mux(moving, mux(clear, constant(0), v), nxt_[t.field]), guard);
      set_bool(q, aig_.make_and(moving, q_running), guard);
      note_start(t, aig_.make_and(guard, start));
      snapshot_et(fb, t, guard);
      return;
    }
    case model::StandardFb::None:
      return;
  }
}

void SymbolicMachine::fire(const Transition& t, AigLit when) {
  for (auto s : t.sources) {
    consumed_[s] = aig_.make_or(consumed_[s], when);
    left_[s] = aig_.make_or(left_[s], when);
  }
  for (auto s : t.targets) entered_[s] = aig_.make_or(entered_[s], when);
  c_.fired[t.index] = aig_.make_or(c_.fired[t.index], when);
}

void SymbolicMachine::fire_chart(const Chart& c, AigLit guard) {
  auto can_fire = [&](const Transition& t) {
    AigLit can = Aig::kTrue;
    for (auto s : t.sources)
      can = aig_.make_and(can, aig_.make_and(aig_.make_not(consumed_[s]), step_active_cur(s)));
    return can;
  };
  auto fire_if_enabled = [&](std::uint32_t ti) {
    const auto& t = p_.transitions[ti];
    const AigLit can = aig_.make_and(guard, can_fire(t));
    fire(t, aig_.make_and(can, eval_truth(t.guard, can)));
  };
  if (p_.options.priority == PriorityMode::Standard) {
    for (auto ti : c.ordered) fire_if_enabled(ti);
    return;
  }
  for (const auto& g : c.groups) {
    const AigLit active = aig_.make_and(guard, step_active_cur(g.step));
    // Every guard of the group is evaluated; the choice input picks among the enabled ones
    // (0 = the first in document order; values past the last enabled pick the last).
    std::vector<AigLit> enabled;
    for (auto ti : g.transitions) enabled.push_back(eval_truth(p_.transitions[ti].guard, active));
    const Value choice = input_value(g.choice_input);
    Value count = constant(0);
    std::vector<Value> rank;
    for (auto e : enabled) {
      rank.push_back(count);
      count = bv_add(aig_, count, from_bool(e));
    }
    const Value last = bv_sub(aig_, count, constant(1));
    const Value pick = min(max(choice, constant(0)), last);
    for (std::size_t j = 0; j < enabled.size(); ++j)
      fire(p_.transitions[g.transitions[j]],
           aig_.make_and(active, aig_.make_and(enabled[j], equal(rank[j], pick))));
  }
  for (auto ti : c.singles) fire_if_enabled(ti);
}

void SymbolicMachine::update_pou(const Pou& pou, AigLit guard) {
  const AigLit g = pou.instance ? guard : Aig::kTrue;
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) {
      const auto& st = p_.steps[s];
      set_bool(
          st.ready,
          aig_.make_or(aig_.make_and(cur_truth(st.ready), aig_.make_not(left_[s])), entered_[s]),
          g);
    }
  for (auto ai : pou.topo_order) {
    const auto& a = p_.actions[ai];
    AigLit reset = Aig::kFalse;
    for (auto x : a.assocs)
      if (p_.assocs[x].q == model::Qualifier::R)
        reset = aig_.make_or(reset, step_active_next(p_.assocs[x].step));
    AigLit act = Aig::kFalse, set_flag = Aig::kFalse;
    for (auto x : a.assocs) {
      const auto& as = p_.assocs[x];
      const auto& st = p_.steps[as.step];
      const AigLit sa = step_active_next(as.step);
      const Timer* t = as.timer == kNone ? nullptr : &p_.timers[static_cast<std::size_t>(as.timer)];
      const AigLit entered = entered_[as.step];
      switch (as.q) {
        case model::Qualifier::N:
          act = aig_.make_or(act, sa);
          break;
        case model::Qualifier::S:
          act = aig_.make_or(act, sa);
          set_flag = aig_.make_or(set_flag, sa);
          break;
        case model::Qualifier::R:
          break;
        case model::Qualifier::P:
        case model::Qualifier::P1:
          act = aig_.make_or(
              act, aig_.make_and(aig_.make_not(cur_truth(st.ready)), nxt_truth(st.ready)));
          break;
        case model::Qualifier::P0:
          act = aig_.make_or(
              act, aig_.make_and(cur_truth(st.ready), aig_.make_not(nxt_truth(st.ready))));
          break;
        case model::Qualifier::L: {
          const Value v = qualifier_timer(*t, sa, entered, g);
          set(t->field, v, g);
          act = aig_.make_or(act, aig_.make_and(sa, aig_.make_not(timer_expired(*t, v))));
          break;
        }
        case model::Qualifier::D: {
          const Value v = qualifier_timer(*t, sa, entered, g);
          set(t->field, v, g);
          act = aig_.make_or(act, aig_.make_and(sa, timer_expired(*t, v)));
          break;
        }
        case model::Qualifier::DS: {
          const Value v = qualifier_timer(*t, sa, entered, g);
          set(t->field, v, g);
          const AigLit fire_now = aig_.make_and(sa, timer_expired(*t, v));
          set_flag = aig_.make_or(set_flag, fire_now);
          act = aig_.make_or(act, fire_now);
          break;
        }
        case model::Qualifier::SD: {
          const auto latch = static_cast<std::uint32_t>(as.latch);
          const AigLit l = aig_.make_and(aig_.make_or(cur_truth(latch), sa), aig_.make_not(reset));
          set_bool(latch, l, g);
          const Value v = qualifier_timer(*t, l, Aig::kFalse, g);
          set(t->field, v, g);
          act = aig_.make_or(act, aig_.make_and(l, timer_expired(*t, v)));
          break;
        }
        case model::Qualifier::SL: {
          const auto latch = static_cast<std::uint32_t>(as.latch);
          const AigLit rising =
              aig_.make_and(sa, aig_.make_or(aig_.make_not(step_active_cur(as.step)), entered));
          const AigLit expired_before = timer_expired(*t, cur_[t->field]);
          const AigLit l = aig_.make_and(
              aig_.make_or(aig_.make_and(cur_truth(latch), aig_.make_not(expired_before)), rising),
              aig_.make_not(reset));
          set_bool(latch, l, g);
          const Value v = qualifier_timer(*t, l, rising, g);
          set(t->field, v, g);
          act = aig_.make_or(act, aig_.make_and(l, aig_.make_not(timer_expired(*t, v))));
          break;
        }
        case model::Qualifier::DL:
          break;  // rejected by the compiler
      }
    }
    AigLit stored = Aig::kFalse;
    if (a.stored != kNone) {
      const auto f = static_cast<std::uint32_t>(a.stored);
      stored = aig_.make_and(aig_.make_or(set_flag, cur_truth(f)), aig_.make_not(reset));
      set_bool(f, stored, g);
    }
    const AigLit active = aig_.make_and(aig_.make_or(act, stored), aig_.make_not(reset));
    if (a.final_call != kNone)
      set_bool(static_cast<std::uint32_t>(a.final_call),
               aig_.make_and(cur_truth(a.active), aig_.make_not(active)), g);
    // Machine::update_pou: under the vendor dialects only an active or deactivated action writes.
    if (a.variable != kNone)
      set_bool(static_cast<std::uint32_t>(a.variable), active,
               p_.vendor_final_calls() ? aig_.make_and(g, aig_.make_or(active, cur_truth(a.active)))
                                       : g);
    set_bool(a.active, active, g);
  }
  step_times(pou, g);
}

void SymbolicMachine::step_times(const Pou& pou, AigLit guard) {
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) {
      const auto& st = p_.steps[s];
      if (st.t_field == kNone) continue;
      const auto f = static_cast<std::uint32_t>(st.t_field);
      const AigLit restart = aig_.make_or(aig_.make_not(nxt_truth(st.ready)), entered_[s]);
      const AigLit advance = aig_.make_and(step_active_next(s), step_active_cur(s));
      const Value v = cur_[f];
      Value advanced;
      if (p_.options.time == TimeMode::Discrete) {
        // An instance's step: the clock aged .T already (Machine::update_pou).
        advanced = st.clocked ? nxt_[f] : min(bv_add(aig_, v, constant(1)), constant(st.t_max));
      } else {
        const Value top = constant(static_cast<std::int64_t>(st.thresholds.size()));
        const Value moved =
            max(v, min(input_value(static_cast<std::uint32_t>(st.elapse_input)), top));
        advanced = mux(less(v, top), moved, v);
        // Entered at an earlier call of this cycle: no time has passed since.
        if (st.clocked) advanced = mux(step_started_[s], nxt_[f], advanced);
      }
      // Suspended: frozen; an instance's step undoes the clock's aging.
      const Value held = st.clocked ? v : nxt_[f];
      if (st.clocked)
        step_started_[s] = aig_.make_or(step_started_[s], aig_.make_and(guard, entered_[s]));
      nxt_[f] = mux(guard, mux(restart, constant(0), mux(advance, advanced, held)), nxt_[f]);
    }
}

void SymbolicMachine::cycle_pou(const Pou& pou, AigLit guard) {
  exec_body(pou.body, guard);
  // SFCInit/SFCReset (Machine::sfc_flags): the charts restart from their initial situation;
  // under SFCInit they stay there, running no action.
  AigLit init = Aig::kFalse;
  if (pou.sfc_init != kNone || pou.sfc_reset != kNone) {
    if (pou.sfc_init != kNone)
      init = aig_.make_and(guard, eval_truth(static_cast<std::uint32_t>(pou.sfc_init), guard));
    AigLit reset = init;
    if (pou.sfc_reset != kNone)
      reset = aig_.make_or(
          reset,
          aig_.make_and(guard, eval_truth(static_cast<std::uint32_t>(pou.sfc_reset), guard)));
    for (auto f : pou.chart_fields) {
      const Value v = constant(initial_values_[f]);
      cur_[f] = mux(reset, v, cur_[f]);
      nxt_[f] = mux(reset, v, nxt_[f]);
    }
    // A reset chart ages as a program's does in its reset cycle (Machine::sfc_flags).
    if (p_.options.time == TimeMode::Discrete) {
      const AigLit reset_only = aig_.make_and(reset, aig_.make_not(init));
      for (auto c : pou.charts)
        for (auto s : p_.charts[c].steps)
          if (clocked_step(s)) {
            const auto f = static_cast<std::uint32_t>(p_.steps[s].t_field);
            nxt_[f] = mux(reset_only, aged_step(s), nxt_[f]);
          }
    }
  }
  const AigLit run = aig_.make_and(guard, aig_.make_not(init));
  // Machine::cycle_pou: the vendor dialects' final calls first.
  for (auto a : pou.exec_order) {
    const auto& act = p_.actions[a];
    if (act.final_call != kNone)
      exec_body(act.body,
                aig_.make_and(run, cur_truth(static_cast<std::uint32_t>(act.final_call))));
  }
  for (std::size_t i = 0; i < pou.exec_order.size(); ++i) {
    if (!pou.exec_group.empty() && pou.exec_group[i] != kNone) {
      run_slot(pou, i, run);
      continue;
    }
    const auto& act = p_.actions[pou.exec_order[i]];
    if (act.kind == model::ActionBodyKind::Statements)
      exec_body(act.body, aig_.make_and(run, cur_truth(act.active)));
  }
  for (auto c : pou.charts) fire_chart(p_.charts[c], aig_.make_and(run, chart_active_cur(c)));
  if (init == Aig::kFalse) {
    update_pou(pou, guard);
    return;
  }
  std::vector<Value> held;
  for (auto f : pou.chart_fields) held.push_back(nxt_[f]);
  update_pou(pou, run);
  for (std::size_t i = 0; i < held.size(); ++i)
    nxt_[pou.chart_fields[i]] = mux(init, held[i], nxt_[pou.chart_fields[i]]);
}

void SymbolicMachine::run_slot(const Pou& pou, std::size_t i, AigLit run) {
  // Machine::run_ordered_actions: the slot runs the member that the order picked by the
  // group's input puts there (the input's range is constrained to the orders).
  const auto& g = pou.order_groups[static_cast<std::size_t>(pou.exec_group[i])];
  const auto slot = static_cast<std::size_t>(pou.exec_slot[i]);
  const Value choice = input_value(g.choice_input);
  for (auto a : g.members) {
    AigLit here = Aig::kFalse;
    for (std::size_t l = 0; l < g.orders.size(); ++l)
      if (g.orders[l][slot] == a)
        here = aig_.make_or(here, equal(choice, constant(static_cast<std::int64_t>(l))));
    const auto& act = p_.actions[a];
    if (here != Aig::kFalse && act.kind == model::ActionBodyKind::Statements)
      exec_body(act.body, aig_.make_and(run, aig_.make_and(here, cur_truth(act.active))));
  }
}

void SymbolicMachine::call_instance(const Pou& pou, AigLit guard) {
  cycle_pou(pou, guard);
  // Only where the call happens: a call not made leaves cur_ as the last call left it, while
  // the clock has aged nxt_ (Machine::call_instance commits only when called).
  for (auto f : pou.commit) cur_[f] = mux(guard, nxt_[f], cur_[f]);
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) consumed_[s] = entered_[s] = left_[s] = Aig::kFalse;
}

void SymbolicMachine::build(StateView initial_state) {
  const auto& fields = p_.layout.fields();
  // Latches: one per field bit, initialised from the explicit initial configuration.
  c_.field_latches.resize(fields.size());
  cur_.resize(fields.size());
  initial_values_.resize(fields.size());
  for (std::uint32_t f = 0; f < fields.size(); ++f) {
    initial_values_[f] = p_.layout.get(initial_state, f);
    // In unsigned arithmetic: a field of the whole 64-bit range (lo = INT64_MIN) overflows
    // the signed difference.
    const auto init =
        static_cast<std::uint64_t>(initial_values_[f]) - static_cast<std::uint64_t>(fields[f].lo);
    BitVector bits;
    for (std::uint32_t k = 0; k < fields[f].width; ++k) {
      c_.field_latches[f].push_back(static_cast<std::uint32_t>(aig_.latches().size()));
      bits.push_back(aig_.add_latch(
          fields[f].name + (fields[f].width > 1 ? "[" + std::to_string(k) + "]" : ""),
          ((init >> k) & 1U) != 0));
    }
    cur_[f] = decode(bits, fields[f].lo);
  }
  // Inputs: their bits, constrained to the type's range.
  AigLit allowed = Aig::kTrue;
  for (const auto& in : p_.inputs) {
    const std::int64_t lo = in.type.kind == model::TypeKind::Bool ? 0 : in.type.lo;
    const std::int64_t hi = in.type.kind == model::TypeKind::Bool ? 1 : in.type.hi;
    const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    const std::uint32_t width = span == 0 ? 1 : static_cast<std::uint32_t>(std::bit_width(span));
    BitVector bits;
    for (std::uint32_t k = 0; k < width; ++k)
      bits.push_back(aig_.add_input(in.name + (width > 1 ? "[" + std::to_string(k) + "]" : "")));
    const BitVector encoded = bv_resize(bits, kWidth, false);
    if (width < 64)
      allowed = aig_.make_and(
          allowed, aig_.make_not(bv_less_unsigned(
                       aig_, bv_constant(static_cast<std::int64_t>(span), kWidth), encoded)));
    c_.input_bits.push_back(bits);
    input_values_.push_back(decode(bits, lo));
  }
  consumed_.assign(p_.steps.size(), Aig::kFalse);
  entered_.assign(p_.steps.size(), Aig::kFalse);
  left_.assign(p_.steps.size(), Aig::kFalse);
  c_.fired.assign(p_.transition_infos.size(), Aig::kFalse);

  // The cycle: assumptions on the new inputs and the current state, then the POUs in order.
  nxt_ = cur_;
  advance_clock();
  AigLit assumed = Aig::kTrue;
  for (auto a : p_.assumptions) assumed = aig_.make_and(assumed, eval_truth(a, assumed));
  c_.allowed = aig_.make_and(allowed, assumed);
  const std::vector<Value> latched = cur_;  // SFCInit/SFCReset and instance calls rewrite cur_
  for (const auto& pou : p_.pous)
    if (!pou.instance) cycle_pou(pou, c_.allowed);
  cur_ = latched;
  c_.range_error = aig_.make_and(c_.range_error, c_.allowed);
  c_.loop_limit = aig_.make_and(c_.loop_limit, c_.allowed);

  for (std::uint32_t f = 0; f < fields.size(); ++f) {
    const BitVector next = encode(nxt_[f], f);
    for (std::uint32_t k = 0; k < fields[f].width; ++k)
      aig_.set_next(c_.field_latches[f][k], next[k]);
  }

  // Observables, as observe() computes them from a state.
  for (const auto& r : p_.observable_refs) {
    switch (r.kind) {
      case ObservableKind::Step: {
        const auto& s = p_.steps[r.a];
        const auto pa = p_.charts[s.chart].parent_action;
        AigLit v = cur_truth(s.ready);
        if (pa != kNone)
          v = aig_.make_and(v, cur_truth(p_.actions[static_cast<std::size_t>(pa)].active));
        c_.observable_bits.push_back({v});
        c_.observable_lo.push_back(0);
        break;
      }
      case ObservableKind::Action:
        c_.observable_bits.push_back({cur_truth(p_.actions[r.a].active)});
        c_.observable_lo.push_back(0);
        break;
      case ObservableKind::Variable: {
        BitVector bits;
        for (auto l : c_.field_latches[r.a]) bits.push_back(aig_.latches()[l].current);
        c_.observable_bits.push_back(bits);
        c_.observable_lo.push_back(fields[r.a].lo);
        break;
      }
    }
  }
}

}  // namespace
}  // namespace iec

namespace {

/// The base circuit of a HistorySystem plus one latch per bit of each history field: a
/// recorded input's next value is the input, a previous value's is the observable now.
TransitionCircuit extend_with_history(const HistorySystem& h, TransitionCircuit c) {
  Aig& aig = c.aig;
  const auto& fields = h.layout().fields();
  auto add_field_latches = [&](std::uint32_t f, const BitVector& next,
                               const std::vector<bool>& init) {
    if (c.field_latches.size() <= f) c.field_latches.resize(f + 1);
    BitVector current;
    for (std::uint32_t k = 0; k < fields[f].width; ++k) {
      const auto lit = aig.add_latch(fields[f].name + "[" + std::to_string(k) + "]", init[k]);
      const auto index = static_cast<std::uint32_t>(aig.latches().size() - 1);
      aig.set_next(index, next[k]);
      c.field_latches[f].push_back(index);
      current.push_back(lit);
    }
    return current;
  };
  for (std::size_t k = 0; k < h.request().inputs.size(); ++k) {
    const auto& in = c.input_bits[h.request().inputs[k]];
    c.observable_bits.push_back(add_field_latches(h.input_field(k), {in[0]}, {false}));
    c.observable_lo.push_back(0);
  }
  // Initial values: the observable in the initial latch values (observables of the scan
  // cycle read latches only), so that prev(x) = x in the initial state.
  auto initial_value = [&](const BitVector& bits) {
    std::vector<bool> latches;
    for (const auto& l : aig.latches()) latches.push_back(l.initial);
    const auto values = aig.evaluate(std::vector<bool>(aig.inputs().size(), false), latches);
    std::vector<bool> out;
    for (auto b : bits) out.push_back(Aig::value_of(values, b));
    return out;
  };
  for (std::size_t k = 0; k < h.request().previous.size(); ++k) {
    const auto j = h.request().previous[k];
    const auto f = h.previous_field(k);
    if (c.observable_lo[j] != fields[f].lo)
      throw CircuitUnsupported("prev(" + h.observables()[j].name +
                               "): its encoding differs from "
                               "its type's range");
    const BitVector now = bv_resize(c.observable_bits[j], fields[f].width, false);
    c.observable_bits.push_back(add_field_latches(f, now, initial_value(now)));
    c.observable_lo.push_back(fields[f].lo);
  }
  return c;
}

}  // namespace

TransitionCircuit build_iec61131_circuit(const TransitionSystem& ts,
                                         std::optional<Deadline> deadline,
                                         std::uint64_t max_memory_bytes) {
  if (const auto* h = as_history(ts)) {
    if (h->kind() != SemanticsKind::Iec61131)
      throw std::invalid_argument("build_iec61131_circuit: not an IEC 61131-3 system");
    return extend_with_history(*h, build_iec61131_circuit(h->base(), deadline, max_memory_bytes));
  }
  const auto* sys = dynamic_cast<const iec::Iec61131System*>(&ts);
  if (!sys) throw std::invalid_argument("build_iec61131_circuit: not an IEC 61131-3 system");
  struct Initial final : SuccessorSink {
    std::vector<StateWord> state;
    void successor(const Successor& s) override { state.assign(s.target.begin(), s.target.end()); }
  } initial;
  ts.initial_states(initial);
  TransitionCircuit c;
  c.aig.set_deadline(deadline);
  c.aig.set_memory_limit(max_memory_bytes);
  iec::SymbolicMachine machine(sys->program(), c);
  machine.build(initial.state);
  c.aig.set_deadline(std::nullopt);
  c.aig.set_memory_limit(0);
  return c;
}

std::vector<StateWord> state_from_latches(const TransitionSystem& ts, const TransitionCircuit& c,
                                          const std::vector<bool>& latches) {
  const auto& layout = ts.layout();
  std::vector<StateWord> s(layout.words(), 0);
  for (std::uint32_t f = 0; f < c.field_latches.size(); ++f) {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < c.field_latches[f].size(); ++k)
      if (latches[c.field_latches[f][k]]) v |= 1ULL << k;
    layout.set(s, f,
               static_cast<std::int64_t>(static_cast<std::uint64_t>(layout.fields()[f].lo) + v));
  }
  return s;
}

std::vector<std::int64_t> inputs_from_bits(const TransitionSystem& ts, const TransitionCircuit& c,
                                           const std::vector<bool>& bits) {
  std::vector<std::int64_t> values;
  for (std::size_t i = 0; i < c.input_bits.size(); ++i) {
    const auto& t = ts.inputs()[i].type;
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < c.input_bits[i].size(); ++k) {
      const auto& node = c.aig.nodes()[Aig::node_of(c.input_bits[i][k])];
      if (bits[node.index]) v |= 1ULL << k;
    }
    const std::int64_t lo = t.kind == model::TypeKind::Bool ? 0 : t.lo;
    values.push_back(static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + v));
  }
  return values;
}

}  // namespace sfcv::semantics

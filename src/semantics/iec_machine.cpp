// The IEC 61131-3 machine, part 1: expression evaluation and the lazy input decisions that let
// successors() explore only the inputs a cycle actually reads (docs/semantics.md, "Successors").

#include <algorithm>
#include <array>
#include <limits>

#include "semantics/detail/iec_program.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::semantics::iec {

namespace {
const std::string kNowhere;
}

Machine::Machine(const Program& p)
    : p_(p),
      cur_(p.field_lo.size()),
      nxt_(p.field_lo.size()),
      in_lo_(p.inputs.size()),
      in_hi_(p.inputs.size()),
      consumed_(p.steps.size()),
      entered_(p.steps.size()),
      left_(p.steps.size()),
      reset_(p.actions.size()),
      started_(p.timers.size()),
      step_started_(p.steps.size()) {
  for (std::uint32_t i = 0; i < p.timers.size(); ++i)
    if (p.timers[i].clocked) clocked_.push_back(i);
  for (std::uint32_t i = 0; i < p.steps.size(); ++i)
    if (p.steps[i].clocked && p.steps[i].t_field != kNone) clocked_steps_.push_back(i);
  for (std::size_t i = 0; i < p.inputs.size(); ++i) {
    in_lo_[i] = p.inputs[i].type.lo;
    in_hi_[i] = p.inputs[i].type.hi;
  }
  touched_.reserve(p.inputs.size());
  trail_.reserve(64);
  fired_.reserve(p.transitions.size());
  enabled_scratch_.reserve(16);
  for (const auto& pou : p.pous) has_flags_ |= pou.sfc_init != kNone || pou.sfc_reset != kNone;
  if (has_flags_) {
    initial_configuration();
    reset_values_ = nxt_;
  }
}

void Machine::load(StateView state) {
  for (std::uint32_t f = 0; f < cur_.size(); ++f) cur_[f] = p_.layout.get(state, f);
  if (has_flags_ || p_.has_instances) loaded_ = cur_;
  cur_dirty_ = false;
}

void Machine::pack(MutableStateView out) const {
  std::fill(out.begin(), out.end(), StateWord{0});
  for (std::uint32_t f = 0; f < nxt_.size(); ++f) p_.layout.set(out, f, nxt_[f]);
}

void Machine::cube(InputCube& out) const {
  out.literals.clear();
  for (auto i : touched_) out.literals.push_back(InputLiteral{i, in_lo_[i], in_hi_[i]});
  std::sort(out.literals.begin(), out.literals.end(),
            [](const InputLiteral& a, const InputLiteral& b) { return a.input < b.input; });
}

bool Machine::next_leaf() {
  while (!trail_.empty()) {
    auto& d = trail_.back();
    if (d.alt + 1 < d.n) {
      ++d.alt;
      return true;
    }
    trail_.pop_back();
  }
  return false;
}

std::uint32_t Machine::decide(std::uint32_t input, std::uint32_t n) {
  std::uint32_t alt = 0;
  if (pos_ < trail_.size()) {
    alt = trail_[pos_].alt;
  } else {
    trail_.push_back(Decision{input, 0, n});
  }
  ++pos_;
  return alt;
}

void Machine::touch(std::uint32_t input, std::int64_t lo, std::int64_t hi) {
  const auto& t = p_.inputs[input].type;
  if (in_lo_[input] == t.lo && in_hi_[input] == t.hi) touched_.push_back(input);
  in_lo_[input] = lo;
  in_hi_[input] = hi;
}

std::int64_t Machine::read_input(std::uint32_t input) {
  const auto lo = in_lo_[input], hi = in_hi_[input];
  if (fixed_ || lo == hi) return lo;
  const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  if (span >= static_cast<std::uint64_t>(kMaxEnumeratedValues))
    throw SemanticsLimitError("input '" + p_.inputs[input].name +
                              "' is used as a value (copied or "
                              "in arithmetic) and would have to be enumerated over " +
                              std::to_string(lo) + ".." + std::to_string(hi) + " (more than " +
                              std::to_string(kMaxEnumeratedValues) +
                              " values); constrain it with an assumption or a subrange type");
  const auto alt = decide(input, static_cast<std::uint32_t>(span + 1));
  touch(input, lo + alt, lo + alt);
  return lo + alt;
}

namespace {
bool compare(Op cmp, std::int64_t x, std::int64_t k) {
  switch (cmp) {
    case Op::Eq:
      return x == k;
    case Op::Ne:
      return x != k;
    case Op::Lt:
      return x < k;
    case Op::Le:
      return x <= k;
    case Op::Gt:
      return x > k;
    default:
      return x >= k;
  }
}
}  // namespace

bool Machine::input_cmp(std::uint32_t input, Op cmp, std::int64_t k) {
  const auto lo = in_lo_[input], hi = in_hi_[input];
  if (fixed_ || lo == hi) return compare(cmp, lo, k);
  // The comparison cuts [lo, hi] into at most three pieces on which it is constant.
  std::array<std::pair<std::int64_t, std::int64_t>, 3> pieces{};
  std::uint32_t n = 0;
  auto add = [&](std::int64_t a, std::int64_t b) {
    a = std::max(a, lo);
    b = std::min(b, hi);
    if (a <= b) pieces[n++] = {a, b};
  };
  const auto mn = std::numeric_limits<std::int64_t>::min(),
             mx = std::numeric_limits<std::int64_t>::max();
  switch (cmp) {
    case Op::Lt:
    case Op::Ge:
      add(mn, k == mn ? mn : k - 1);
      if (k == mn) n = 0;
      add(k, mx);
      break;
    case Op::Le:
    case Op::Gt:
      add(mn, k);
      if (k != mx) add(k + 1, mx);
      break;
    default:
      if (k != mn) add(mn, k - 1);
      add(k, k);
      if (k != mx) add(k + 1, mx);
      break;
  }
  if (n <= 1) return compare(cmp, lo, k);
  const auto alt = decide(input, n);
  touch(input, pieces[alt].first, pieces[alt].second);
  return compare(cmp, pieces[alt].first, k);
}

std::int64_t Machine::arith(Op op, std::int64_t x, std::int64_t y) const {
  std::int64_t r = 0;
  switch (op) {
    case Op::Add:
      if (__builtin_add_overflow(x, y, &r)) throw RangeAbort{"integer overflow in +", &kNowhere};
      return r;
    case Op::Sub:
      if (__builtin_sub_overflow(x, y, &r)) throw RangeAbort{"integer overflow in -", &kNowhere};
      return r;
    case Op::Mul:
      if (__builtin_mul_overflow(x, y, &r)) throw RangeAbort{"integer overflow in *", &kNowhere};
      return r;
    case Op::Div:
    case Op::Mod:
      if (y == 0) throw RangeAbort{"division by zero", &kNowhere};
      if (x == std::numeric_limits<std::int64_t>::min() && y == -1)
        throw RangeAbort{"integer overflow in /", &kNowhere};
      return op == Op::Div ? x / y : x % y;
    default:
      return 0;
  }
}

bool Machine::chart_active_cur(std::uint32_t chart) const {
  const auto pa = p_.charts[chart].parent_action;
  return pa == kNone || cur_[p_.actions[static_cast<std::size_t>(pa)].active] != 0;
}

bool Machine::step_active_cur(std::uint32_t step) const {
  const auto& s = p_.steps[step];
  return cur_[s.ready] != 0 && chart_active_cur(s.chart);
}

bool Machine::step_active_next(std::uint32_t step) const {
  const auto& s = p_.steps[step];
  if (nxt_[s.ready] == 0) return false;
  const auto pa = p_.charts[s.chart].parent_action;
  return pa == kNone || nxt_[p_.actions[static_cast<std::size_t>(pa)].active] != 0;
}

std::int64_t Machine::bit_op(const Node& n, const std::uint32_t* kid) {
  const auto width = static_cast<std::uint32_t>(n.k);  // 1..64
  const std::uint64_t mask = width >= 64 ? ~0ULL : ((1ULL << width) - 1);
  const auto x = static_cast<std::uint64_t>(eval(kid[0])) & mask;
  if (n.op == Op::BitNot) return static_cast<std::int64_t>(~x & mask);
  const auto by = eval(kid[1]);
  if (by < 0) throw RangeAbort{"negative shift or rotation count", &kNowhere};
  std::uint64_t r = 0;
  if (n.op == Op::Shl || n.op == Op::Shr) {
    if (by < static_cast<std::int64_t>(width)) r = n.op == Op::Shl ? (x << by) & mask : x >> by;
  } else {
    const auto s = static_cast<std::uint32_t>(by % width);
    const auto left = n.op == Op::Rol ? s : (width - s) % width;
    r = left == 0 ? x : ((x << left) | (x >> (width - left))) & mask;
  }
  return static_cast<std::int64_t>(r);
}

std::int64_t Machine::eval(std::uint32_t index) {
  const Node& n = p_.nodes[index];
  const std::uint32_t* kid = p_.kids.data() + n.first;
  switch (n.op) {
    case Op::Const:
      return n.k;
    case Op::Field:
      return nxt_[n.a];
    case Op::Input:
      return read_input(n.a);
    case Op::InputCmp:
      return input_cmp(n.a, n.cmp, n.k);
    case Op::InputCmpExpr: {
      const auto k = eval(kid[0]);
      return input_cmp(n.a, n.cmp, k);
    }
    case Op::StepX:
      return step_active_cur(n.a);
    case Op::StepT: {
      const auto& s = p_.steps[n.a];
      return step_active_cur(n.a) || cur_[s.ready]
                 ? cur_[static_cast<std::size_t>(s.t_field)] * p_.options.cycle_ms
                 : 0;
    }
    case Op::StepTCmp: {
      const auto& s = p_.steps[n.a];
      const bool r = cur_[static_cast<std::size_t>(s.t_field)] >= n.k;
      return n.negate ? !r : r;
    }
    case Op::TimerQ:
      return nxt_[static_cast<std::size_t>(p_.fbs[n.a].q)];
    case Op::TimerET: {
      // ET as the last call left it (the timer's own field ages between calls).
      const auto& fb = p_.fbs[n.a];
      if (fb.et == kNone) return 0;  // never called
      const auto v = nxt_[static_cast<std::size_t>(fb.et)];
      return v == 0 ? 0 : std::min((v - 1) * p_.options.cycle_ms, fb.pt_ms);
    }
    case Op::Not:
      return !eval(kid[0]);
    case Op::Neg: {
      const auto v = eval(kid[0]);
      if (v == std::numeric_limits<std::int64_t>::min())
        throw RangeAbort{"integer overflow in -", &kNowhere};
      return -v;
    }
    case Op::And:
      for (std::uint32_t i = 0; i < n.count; ++i)
        if (!eval(kid[i])) return 0;
      return 1;
    case Op::Or:
      for (std::uint32_t i = 0; i < n.count; ++i)
        if (eval(kid[i])) return 1;
      return 0;
    case Op::Xor: {
      std::int64_t r = 0;
      for (std::uint32_t i = 0; i < n.count; ++i) r ^= (eval(kid[i]) != 0);
      return r;
    }
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod: {
      const auto x = eval(kid[0]);
      return arith(n.op, x, eval(kid[1]));
    }
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge: {
      const auto x = eval(kid[0]);
      return compare(n.op, x, eval(kid[1]));
    }
    case Op::Ite:
      return eval(kid[0]) ? eval(kid[1]) : eval(kid[2]);
    case Op::RangeCheck: {
      const auto v = eval(kid[0]);
      if (v < eval(kid[1]) || v > eval(kid[2]))
        throw RangeAbort{"value out of the range of the function's result type", &kNowhere};
      return v;
    }
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor: {
      auto r = static_cast<std::uint64_t>(eval(kid[0]));
      for (std::uint32_t i = 1; i < n.count; ++i) {
        const auto v = static_cast<std::uint64_t>(eval(kid[i]));
        r = n.op == Op::BitAnd ? (r & v) : n.op == Op::BitOr ? (r | v) : (r ^ v);
      }
      return static_cast<std::int64_t>(r);
    }
    case Op::BitNot:
    case Op::Shl:
    case Op::Shr:
    case Op::Rol:
    case Op::Ror:
      return bit_op(n, kid);
    case Op::Call:
      return call_function(n, kid);
  }
  return 0;
}

}  // namespace sfcv::semantics::iec

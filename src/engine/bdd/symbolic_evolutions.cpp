// The evolutions relation over (current, next) variables and the helpers the symbolic query
// evaluator needs (engine/bdd/symbolic_query_evaluator.hpp). Kept apart from
// symbolic_system.cpp, which builds the relation itself.

#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/bdd/symbolic_system.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;
using Bdd = bdd::Bdd;

Bdd SymbolicSystem::evolutions(const Bdd& from, const Bdd& on_inputs) const {
  // exists i. from(x) & on_inputs(x, i) & T(x, i, x'), conjoining the clusters in order; an
  // input is quantified after the last cluster that reads it (the pre-image schedule without
  // its next variables, which stay).
  const Relation& r = relation();
  Bdd acc = (from & on_inputs).exist(r.pre_quantify_first);
  for (std::size_t k = 0; k < r.clusters.size(); ++k)
    acc = acc.and_exist(r.clusters[k], r.pre_quantify_after[k].exist(next_cube_));
  // An input that `on_inputs` reads but no cluster does is still free here.
  return acc.exist(input_cube_);
}

Bdd SymbolicSystem::evolutions_only_under(const Bdd& pairs, const Bdd& on_inputs) const {
  return pairs & !evolutions(sources(pairs), !on_inputs);
}

Bdd SymbolicSystem::fires_any_under_inputs() {
  Bdd any = Bdd::constant(false);
  for (const auto lit : circuit_.fired) any = any | node_bdd(lit);
  return any;
}

Bdd SymbolicSystem::to_next(const Bdd& states) const {
  return states.replace(*current_to_next_);
}
Bdd SymbolicSystem::to_current(const Bdd& on_next) const {
  return on_next.replace(*next_to_current_);
}
Bdd SymbolicSystem::sources(const Bdd& pairs) const {
  return pairs.exist(next_cube_);
}
Bdd SymbolicSystem::targets(const Bdd& pairs) const {
  return to_current(pairs.exist(current_cube_));
}

double SymbolicSystem::count_pairs(const Bdd& pairs) const {
  if (pairs.is_false()) return 0;
  return std::round(std::exp2(pairs.sat_count_log2(current_cube_ & next_cube_)));
}

bool SymbolicSystem::depends_on_inputs(const Bdd& f) const {
  return f.exist(input_cube_) != f;
}

Bdd SymbolicSystem::observable_nonzero(std::uint32_t o) {
  const auto& bits = circuit_.observable_bits[o];
  if (bits.size() == 1 && circuit_.observable_lo[o] == 0) return node_bdd(bits[0]);
  return !field_value_equals(o, 0);
}

Bdd SymbolicSystem::field_nonzero(std::uint32_t f) {
  const auto& latches = circuit_.field_latches[f];
  // Zero is stored as (0 - lo); a field whose range excludes zero is never zero.
  const auto zero = std::uint64_t{0} - static_cast<std::uint64_t>(ts_.layout().fields()[f].lo);
  if (ts_.layout().fields()[f].lo > 0 || (latches.size() < 64 && (zero >> latches.size()) != 0))
    return Bdd::constant(true);
  Bdd is_zero = Bdd::constant(true);
  for (std::size_t k = 0; k < latches.size(); ++k) {
    const Bdd b = node_bdd(circuit_.aig.latches()[latches[k]].current);
    is_zero = is_zero & (((zero >> k) & 1U) ? b : !b);
  }
  return !is_zero;
}

namespace {

/// The 64-bit value of an integer-valued signal (Const, Input, Observable) in the circuit.
semantics::BitVector signal_value(semantics::Aig& aig, const semantics::TransitionCircuit& c,
                                  const semantics::TransitionSystem& ts, const logic::Signal& s) {
  using logic::Signal;
  switch (s.op) {
    case Signal::Op::Const:
      return semantics::bv_constant(s.value, 64);
    case Signal::Op::Input:
      return semantics::bv_add(aig, semantics::bv_resize(c.input_bits[s.index], 64, false),
                               semantics::bv_constant(ts.inputs()[s.index].type.lo, 64));
    case Signal::Op::Observable:
      return semantics::bv_add(aig, semantics::bv_resize(c.observable_bits[s.index], 64, false),
                               semantics::bv_constant(c.observable_lo[s.index], 64));
    default:
      break;
  }
  throw std::invalid_argument("SymbolicSystem::signal: not an integer expression");
}

}  // namespace

Bdd SymbolicSystem::signal(const logic::Signal& s, const std::vector<std::uint32_t>& slots) {
  using logic::Signal;
  switch (s.op) {
    case Signal::Op::Const:
      return Bdd::constant(s.value != 0);
    case Signal::Op::Input:
      // A Boolean input is one circuit bit; an integer one is only ever compared (Cmp).
      if (ts_.inputs()[s.index].type.kind != model::TypeKind::Bool)
        throw std::invalid_argument("SymbolicSystem::signal: integer input used as a Boolean");
      return node_bdd(circuit_.input_bits[s.index].at(0));
    case Signal::Op::Observable:
      return observable_nonzero(s.index);
    case Signal::Op::StepVar:
      return observable_nonzero(slots.at(s.index));
    case Signal::Op::Not:
      return !signal(s.args[0], slots);
    case Signal::Op::And:
      return signal(s.args[0], slots) & signal(s.args[1], slots);
    case Signal::Op::Or:
      return signal(s.args[0], slots) | signal(s.args[1], slots);
    case Signal::Op::Cmp: {
      if (!s.args[0].is_int) {
        // Booleans compare as truth values.
        const Bdd eq = signal(s.args[0], slots).iff(signal(s.args[1], slots));
        switch (s.cmp) {
          case logic::CmpOp::Eq:
            return eq;
          case logic::CmpOp::Ne:
            return !eq;
          default:
            throw std::invalid_argument("SymbolicSystem::signal: ordering of Booleans");
        }
      }
      Aig& aig = circuit_.aig;
      const auto a = signal_value(aig, circuit_, ts_, s.args[0]);
      const auto b = signal_value(aig, circuit_, ts_, s.args[1]);
      AigLit r = Aig::kFalse;
      switch (s.cmp) {
        case logic::CmpOp::Eq:
          r = semantics::bv_equal(aig, a, b);
          break;
        case logic::CmpOp::Ne:
          r = Aig::make_not(semantics::bv_equal(aig, a, b));
          break;
        case logic::CmpOp::Lt:
          r = semantics::bv_less_signed(aig, a, b);
          break;
        case logic::CmpOp::Le:
          r = Aig::make_not(semantics::bv_less_signed(aig, b, a));
          break;
        case logic::CmpOp::Gt:
          r = semantics::bv_less_signed(aig, b, a);
          break;
        case logic::CmpOp::Ge:
          r = Aig::make_not(semantics::bv_less_signed(aig, a, b));
          break;
      }
      memo_.resize(aig.nodes().size());
      memo_set_.resize(aig.nodes().size(), false);
      return node_bdd(r);
    }
  }
  throw std::invalid_argument("SymbolicSystem::signal: unknown operator");
}

std::vector<std::vector<semantics::StateWord>> SymbolicSystem::enumerate(
    const Bdd& states, std::uint64_t limit) const {
  std::vector<std::vector<semantics::StateWord>> out;
  Bdd rest = states;
  while (!rest.is_false()) {
    if (out.size() >= limit)
      throw std::length_error("more than " + std::to_string(limit) + " elements to list");
    out.push_back(pick(rest));
    rest = rest & !singleton(out.back());
  }
  return out;
}

Bdd SymbolicSystem::canonically_before(semantics::StateView state) const {
  // Built from the least significant position up: before(p) says "x < s on positions p..".
  const auto& layout = ts_.layout();
  Bdd before = Bdd::constant(false);
  for (std::size_t f = circuit_.field_latches.size(); f-- > 0;) {
    const auto v = static_cast<std::uint64_t>(layout.get(state, static_cast<std::uint32_t>(f)) -
                                              layout.fields()[f].lo);
    const auto& latches = circuit_.field_latches[f];
    for (std::size_t k = 0; k < latches.size(); ++k) {  // LSB first = least significant first
      const Bdd x = Bdd::variable(current_var_[latches[k]]);
      before = ((v >> k) & 1U) ? ((!x) | before) : ((!x) & before);
    }
  }
  return before;
}

}  // namespace sfcv::engine

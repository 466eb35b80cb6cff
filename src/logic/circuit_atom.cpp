#include "logic/circuit_atom.hpp"

#include <stdexcept>

namespace sfcv::logic {

using semantics::Aig;
using semantics::AigLit;

AigLit observable_equals(semantics::TransitionCircuit& circuit, std::uint32_t o,
                         std::int64_t value) {
  const auto& bits = circuit.observable_bits[o];
  const auto encoded = static_cast<std::uint64_t>(value - circuit.observable_lo[o]);
  if (value < circuit.observable_lo[o] || (bits.size() < 64 && (encoded >> bits.size()) != 0))
    return Aig::kFalse;
  std::vector<AigLit> lits;
  for (std::size_t k = 0; k < bits.size(); ++k)
    lits.push_back(((encoded >> k) & 1U) ? bits[k] : Aig::make_not(bits[k]));
  return circuit.aig.make_and(lits);
}

namespace {

using semantics::BitVector;
constexpr std::uint32_t kWidth = 64;

/// a * k by shifts and adds; exact because resolve() bounds the product within 64 bits.
BitVector times_constant(Aig& aig, const BitVector& a, std::int64_t k) {
  const bool negative = k < 0;
  auto m =
      negative ? std::uint64_t{0} - static_cast<std::uint64_t>(k) : static_cast<std::uint64_t>(k);
  BitVector acc = semantics::bv_constant(0, kWidth), shifted = a;
  while (m != 0) {
    if (m & 1U) acc = semantics::bv_add(aig, acc, shifted);
    m >>= 1;
    BitVector doubled(kWidth, Aig::kFalse);
    for (std::uint32_t i = 1; i < kWidth; ++i) doubled[i] = shifted[i - 1];
    shifted = std::move(doubled);
  }
  return negative ? semantics::bv_neg(aig, acc) : acc;
}

/// x / k or x MOD k (k != 0 constant), truncating toward zero, the remainder with x's sign:
/// long division of |x| by |k| on 64 bits, then the signs.
BitVector divide_constant(Aig& aig, const BitVector& x, std::int64_t k, bool quotient) {
  const AigLit negative = x[kWidth - 1];
  const BitVector magnitude = semantics::bv_mux(aig, negative, semantics::bv_neg(aig, x), x);
  const auto d64 =
      k < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(k) : static_cast<std::uint64_t>(k);
  // 65-bit unsigned arithmetic: the running remainder stays below |k| <= 2^63.
  BitVector d(kWidth + 1, Aig::kFalse), rest(kWidth + 1, Aig::kFalse);
  for (std::uint32_t b = 0; b < kWidth; ++b)
    if ((d64 >> b) & 1U) d[b] = Aig::kTrue;
  BitVector q(kWidth, Aig::kFalse);
  for (std::uint32_t i = kWidth; i-- > 0;) {
    BitVector shifted(kWidth + 1);
    shifted[0] = magnitude[i];
    for (std::uint32_t b = 1; b <= kWidth; ++b) shifted[b] = rest[b - 1];
    const AigLit fits = Aig::make_not(semantics::bv_less_unsigned(aig, shifted, d));
    rest = semantics::bv_mux(aig, fits, semantics::bv_sub(aig, shifted, d), shifted);
    q[i] = fits;
  }
  if (quotient) {
    const AigLit flip = k < 0 ? Aig::make_not(negative) : negative;
    return semantics::bv_mux(aig, flip, semantics::bv_neg(aig, q), q);
  }
  BitVector r(rest.begin(), rest.begin() + kWidth);
  return semantics::bv_mux(aig, negative, semantics::bv_neg(aig, r), r);
}

/// A resolved term as a 64-bit two's-complement vector (exact: resolve() bounds its range).
BitVector term_bits(semantics::TransitionCircuit& circuit, const Formula& t) {
  Aig& aig = circuit.aig;
  auto arg = [&](std::size_t i) { return term_bits(circuit, *t.args[i]); };
  switch (t.op) {
    case Op::Value: {
      const auto o = static_cast<std::uint32_t>(t.observable);
      return semantics::bv_add(aig, semantics::bv_resize(circuit.observable_bits[o], kWidth, false),
                               semantics::bv_constant(circuit.observable_lo[o], kWidth));
    }
    case Op::Number:
      return semantics::bv_constant(t.value, kWidth);
    case Op::Neg:
      return semantics::bv_neg(aig, arg(0));
    case Op::Add:
      return semantics::bv_add(aig, arg(0), arg(1));
    case Op::Sub:
      return semantics::bv_sub(aig, arg(0), arg(1));
    case Op::Mul:
      if (t.args[1]->op == Op::Number) return times_constant(aig, arg(0), t.args[1]->value);
      return times_constant(aig, arg(1), t.args[0]->value);
    case Op::Div:
    case Op::Mod:
      return divide_constant(aig, arg(0), t.args[1]->value, t.op == Op::Div);
    default:
      throw std::invalid_argument("circuit_literal: not a term: " + to_string(t));
  }
}

AigLit compare_bits(Aig& aig, CompareOp cmp, const BitVector& value, const BitVector& k) {
  switch (cmp) {
    case CompareOp::Eq:
      return semantics::bv_equal(aig, value, k);
    case CompareOp::Ne:
      return Aig::make_not(semantics::bv_equal(aig, value, k));
    case CompareOp::Lt:
      return semantics::bv_less_signed(aig, value, k);
    case CompareOp::Le:
      return Aig::make_not(semantics::bv_less_signed(aig, k, value));
    case CompareOp::Gt:
      return semantics::bv_less_signed(aig, k, value);
    case CompareOp::Ge:
      return Aig::make_not(semantics::bv_less_signed(aig, value, k));
  }
  return Aig::kFalse;
}

}  // namespace

AigLit circuit_literal(semantics::TransitionCircuit& circuit, const Formula& f) {
  Aig& aig = circuit.aig;
  switch (f.op) {
    case Op::True:
      return Aig::kTrue;
    case Op::False:
      return Aig::kFalse;
    case Op::Atom: {
      const auto o = static_cast<std::uint32_t>(f.observable);
      const auto& bits = circuit.observable_bits[o];
      if (bits.size() == 1 && circuit.observable_lo[o] == 0) return bits[0];
      // An integer used as a Boolean: true when non-zero.
      return Aig::make_not(observable_equals(circuit, o, 0));
    }
    case Op::Compare: {
      // value = lo + bits, compared with the constant as 64-bit integers in the circuit.
      const auto o = static_cast<std::uint32_t>(f.observable);
      const auto value =
          semantics::bv_add(aig, semantics::bv_resize(circuit.observable_bits[o], 64, false),
                            semantics::bv_constant(circuit.observable_lo[o], 64));
      const auto k = semantics::bv_constant(f.value, 64);
      switch (f.cmp) {
        case CompareOp::Eq:
          return semantics::bv_equal(aig, value, k);
        case CompareOp::Ne:
          return Aig::make_not(semantics::bv_equal(aig, value, k));
        case CompareOp::Lt:
          return semantics::bv_less_signed(aig, value, k);
        case CompareOp::Le:
          return Aig::make_not(semantics::bv_less_signed(aig, k, value));
        case CompareOp::Gt:
          return semantics::bv_less_signed(aig, k, value);
        case CompareOp::Ge:
          return Aig::make_not(semantics::bv_less_signed(aig, value, k));
      }
      return Aig::kFalse;
    }
    case Op::Relation:
      return compare_bits(aig, f.cmp, term_bits(circuit, *f.args[0]),
                          term_bits(circuit, *f.args[1]));
    case Op::Not:
      return Aig::make_not(circuit_literal(circuit, *f.args[0]));
    case Op::And:
      return aig.make_and(circuit_literal(circuit, *f.args[0]),
                          circuit_literal(circuit, *f.args[1]));
    case Op::Or:
      return aig.make_or(circuit_literal(circuit, *f.args[0]),
                         circuit_literal(circuit, *f.args[1]));
    case Op::Implies:
      return aig.make_implies(circuit_literal(circuit, *f.args[0]),
                              circuit_literal(circuit, *f.args[1]));
    case Op::Iff:
      return aig.make_xnor(circuit_literal(circuit, *f.args[0]),
                           circuit_literal(circuit, *f.args[1]));
    case Op::Xor:
      return aig.make_xor(circuit_literal(circuit, *f.args[0]),
                          circuit_literal(circuit, *f.args[1]));
    default:
      throw std::invalid_argument("circuit_literal: temporal operator");
  }
}

}  // namespace sfcv::logic

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

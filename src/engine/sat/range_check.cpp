#include "engine/sat/range_check.hpp"

#include "engine/sat/certificate.hpp"
#include "engine/sat/ic3.hpp"

namespace sfcv::engine::sat {

ReachQuery without_range_check(const ReachQuery& query, semantics::TransitionCircuit& circuit,
                               Deadline deadline) {
  using semantics::Aig;
  if (circuit.range_error == Aig::kFalse || query.aig != &circuit.aig ||
      query.step_ok != circuit.aig.make_and(circuit.allowed, Aig::make_not(circuit.range_error)))
    return query;
  ReachQuery probe = query;
  probe.targets = {circuit.aig.make_and(circuit.allowed, circuit.range_error)};
  Ic3Options options;
  options.deadline = deadline;
  const auto proof = ic3(probe, 0, options);
  if (proof.kind != ReachResult::Kind::Unreachable ||
      !recheck(probe, 0, proof.certificate, deadline).ok)
    return query;
  ReachQuery relaxed = query;
  relaxed.step_ok = circuit.allowed;
  return relaxed;
}

}  // namespace sfcv::engine::sat

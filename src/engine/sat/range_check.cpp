#include "engine/sat/range_check.hpp"

#include "engine/sat/certificate.hpp"
#include "engine/sat/ic3.hpp"

namespace sfcv::engine::sat {

ReachQuery without_range_check(const ReachQuery& query, semantics::TransitionCircuit& circuit,
                               Deadline deadline) {
  using semantics::Aig;
  if (circuit.range_error == Aig::kFalse || query.aig != &circuit.aig ||
      query.step_ok != circuit.step_ok())
    return query;
  ReachQuery probe = query;
  probe.targets = {circuit.range_error_step()};
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

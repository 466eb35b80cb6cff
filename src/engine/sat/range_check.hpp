#pragma once
// Leaving the range check out of a search's step relation when no reachable cycle raises a
// range error. A step of an IEC 61131-3 circuit is allowed when its inputs are (`allowed`) and
// it raises no range error; the range error reads every bounded variable, so it pulls all of
// them into every target's cone of influence. Once IC3 has proved that no allowed step from a
// reachable state raises one, both relations reach the same states (induction on the run), and
// the relaxed one leaves out of each target's cone the variables it does not read.

#include "engine/sat/reachability.hpp"
#include "engine/sat/sat_solver.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine::sat {

/// `query` (over `circuit.aig`, with step_ok = allowed & !range_error) with step_ok relaxed to
/// `circuit.allowed`, when IC3 proves within `deadline` that `allowed & range_error` is
/// unreachable and a fresh solver re-checks the proof; otherwise `query` unchanged. A proof
/// found on the relaxed query is an invariant of `query` too (closed under more steps, so
/// under fewer), and a run of the relaxed query is a run of `query`.
ReachQuery without_range_check(const ReachQuery& query, semantics::TransitionCircuit& circuit,
                               Deadline deadline);

}  // namespace sfcv::engine::sat

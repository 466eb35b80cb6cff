#pragma once
// From a transition system and the properties of a check to a CircuitExport (NuSMV, Cadence
// SMV, Promela) and an AIGER circuit, meaning exactly what sfcv's engines mean:
// - the circuit is semantics::build_iec61131_circuit (latches = the explicit state bits);
// - a cycle whose inputs violate the assumptions, or which raises a range error, has no
//   successor in sfcv: the export cuts it (constraint `allowed & !range_error`: NuSMV TRANS,
//   Cadence SMV assume, Promela end state). The state itself stays reachable and is checked;
// - a cycle whose ST loop meets the loop bound (TransitionCircuit::loop_limit: sfcv answers
//   unknown, the loop may still end) is not cut: it sets the latch `sfcv_loop_limit`, which
//   stays set, and every exported property fails once it is set (each invariant's bad state
//   is `sfcv_loop_limit | !p`, each CTL property is `AG !sfcv_loop_limit & (...)`), so that no
//   outside tool can prove a property that rests on the cut cycle; a violation whose trace
//   ends with the flag set is unknown (ends_in_loop_limit);
// - `AG p` with p propositional becomes a bad-state literal `!p` over the latches;
// - other CTL properties are kept as text for NuSMV / Cadence SMV only.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/external/circuit_export.hpp"
#include "logic/check_task.hpp"
#include "model/errors.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine {

/// What cannot be exported (Grafcet, an operation the circuit cannot express): the message
/// says what. Callers answer exit 2.
class ExportError : public UnsupportedConstruct {
 public:
  using UnsupportedConstruct::UnsupportedConstruct;
};

/// NuSMV / Cadence SMV (CTL text allowed) or a circuit checker (AIGER, Promela: invariants).
enum class ExportTarget { Smv, Circuit };

struct ExportRequest {
  ExportTarget target = ExportTarget::Smv;
  std::vector<logic::Property> properties;  ///< resolved against the system
  /// Add the reachability standard check: `EF X` per step for NuSMV / Cadence SMV, and the
  /// invariant `AG !X` ("X unreachable", violated = reachable) for AIGER / Promela.
  bool reachability = false;
  std::vector<std::string> header;  ///< first comment lines (source file, options)
};

struct ExportedModel {
  CircuitExport model;  ///< aig with constraint, bad literals, outputs; comments; CTL text
  semantics::TransitionCircuit circuit;  ///< for mapping counterexamples back
  /// Per bad literal of model.aig: the property it checks (index into request.properties), or
  /// -1 for a reachability invariant.
  std::vector<std::int32_t> bad_property;
  /// Per entry of model.ctl: the property (index into request.properties), -1 for reachability.
  std::vector<std::int32_t> ctl_property;
  /// Properties that are not invariants (only NuSMV / Cadence SMV can take them).
  std::vector<std::string> ctl_only;
  /// When a reachable cycle may meet the ST loop bound: the index in model.aig.latches() of
  /// the latch `sfcv_loop_limit` (set by such a cycle, then kept), else nullopt.
  std::optional<std::uint32_t> loop_limit_latch;
  /// NuSMV / Cadence SMV: the index in model.aig.bad() of the invariant `no_loop_limit`
  /// (AG !sfcv_loop_limit); when it is violated, every false verdict is unknown.
  std::optional<std::size_t> loop_limit_bad;
};

/// `AG p` with p propositional.
bool is_invariant(const logic::Formula& f);

/// Throws ExportError for Grafcet systems and for circuits sfcv cannot build.
ExportedModel build_export(const semantics::TransitionSystem& ts, const ExportRequest& request);

/// The circuit to write as AIGER and give to ABC: the cut constraint folded into a latch
/// `sfcv_valid` (initially 1, next = valid & constraint) and every bad literal b replaced by
/// `valid & b`. AIGER 1.9 constraints would also have to hold in the last frame, so a bad
/// state whose every input is cut (assumptions over the state, range errors) would be missed;
/// the latch keeps exactly sfcv's reachable states. Outputs are dropped (ABC would read them as
/// properties); at least one input is guaranteed (a dummy one when the chart has none).
semantics::Aig aiger_circuit(const CircuitExport& model);

/// Whether an outside counterexample whose cycles have the input frames `frames` (frames[k] =
/// circuit inputs of cycle k + 1, as for frames_to_inputs) ends in a state where the latch
/// `sfcv_loop_limit` is set: its violation rests on a cycle sfcv cannot finish, the verdict is
/// unknown (TransitionCircuit::loop_limit_message). False without such a latch.
bool ends_in_loop_limit(const ExportedModel& exported,
                        const std::vector<std::vector<bool>>& frames);

/// The input frames of an outside counterexample (frames[k] = circuit inputs of cycle k + 1)
/// as sfcv input valuations (`semantics::simulate`); extra (dummy) inputs are ignored.
std::vector<std::vector<std::int64_t>> frames_to_inputs(
    const semantics::TransitionSystem& ts, const semantics::TransitionCircuit& circuit,
    const std::vector<std::vector<bool>>& frames);

}  // namespace sfcv::engine

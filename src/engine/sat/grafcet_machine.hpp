#pragma once
// The Grafcet stable-situation relation as a circuit the SAT engines unroll
// (docs/engines.md, "Grafcet on the SAT engines"). The Grafcet circuit
// (semantics/grafcet_circuit.hpp) computes ONE transient evolution; a stable step is the
// closure of a sequence of them. The machine makes each of its steps one micro-step of that
// closure and records in a mode where it is:
//
//   Boot   (initially):  the initial valuation is read      -> Trans, N := initial_next(I)
//   Stable (N is a stable situation, the one the property reads):
//                        an input event I                    -> Trans, N := start_next(N, I)
//   Trans  (N is a transient situation):
//            range error / forcing conflict                  -> no step (the event has no end)
//            stable                                          -> Stable, N := final_next(N)
//            otherwise                                       -> Trans,  N := evolve(N, Q)
//
// Q copies the bits read under an edge (the previous situation), K holds the event's inputs
// that the evolutions read (they stay fixed during the event). An invariant p of the chart
// becomes the machine invariant "Stable -> p(N)": transient situations are never judged, as
// in the explicit and BDD engines. An event that never stabilises loops in Trans forever and
// so reaches no stable situation, as it has no successor in the explicit graph.

#include <cstdint>
#include <string>
#include <vector>

#include "semantics/grafcet_circuit.hpp"

namespace sfcv::engine::sat {

class GrafcetMachine {
 public:
  explicit GrafcetMachine(const semantics::GrafcetCircuit& circuit);

  const semantics::Aig& aig() const { return aig_; }
  semantics::AigLit step_ok() const { return step_ok_; }
  /// The mode literals over the machine's latches (exactly one holds).
  semantics::AigLit at_boot() const { return boot_; }
  semantics::AigLit at_stable() const { return stable_; }
  semantics::AigLit at_transient() const { return transient_; }
  /// at_stable() on a valuation of the machine's latches.
  bool is_stable(const std::vector<bool>& latches) const {
    return !latches[boot_latch_] && latches[stable_latch_];
  }
  /// "A stable situation where `circuit_lit` holds": a literal of the Grafcet circuit over its
  /// state latches (an observable, a property) read on the machine's situation N, in Stable.
  semantics::AigLit in_stable_situation(semantics::AigLit circuit_lit);
  /// "A stable situation reached by an event during which `lit` held in a situation the
  /// event crossed (the source excluded, the stable one included)": an observer latch, reset
  /// in Stable, accumulates `at_transient & lit` over the event's micro-steps. `lit` is a
  /// machine literal over N (e.g. in_situation()) or fired(). What the explicit engine reads
  /// on an edge of its graph, whose events end in a stable situation: a step crossed only
  /// during transient evolutions, a transition cleared (the start's stabilisation included).
  /// "The run's first stable situation": an initial situation, stabilised (a latch set once
  /// a stable situation has been left). Built on first use.
  semantics::AigLit at_initial_stable();
  /// For predicates the caller builds over the machine's latches (at_initial_stable, ...).
  semantics::Aig& mutable_aig() { return aig_; }
  /// With `also_stable`, `lit` holding in the stable situation itself counts too.
  semantics::AigLit seen_during_event(semantics::AigLit lit, std::string name, bool also_stable);
  /// "`lit` held in the stable situation the current event started from": an observer latch
  /// that copies `lit` (a machine literal over N) whenever the machine is in Stable and keeps
  /// it during the event's micro-steps (FALSE before the first stable situation).
  semantics::AigLit held_at_event_source(semantics::AigLit lit, std::string name);
  /// `circuit_lit` read on the machine's situation N (in any mode).
  semantics::AigLit in_situation(semantics::AigLit circuit_lit) {
    return translate(circuit_lit, on_n_);
  }
  /// "This transient micro-step raises a range error or a forcing conflict": the event has no
  /// end (docs/semantics.md 2.11, the instability check).
  semantics::AigLit at_anomaly() const { return anomaly_; }
  /// "The event's evolutions are back in a transient configuration they were in before": a
  /// lasso, so they never stabilise (the evolutions are deterministic under the event's kept
  /// inputs). A free input chooses the micro-step whose configuration (N and Q) shadow latches
  /// keep; the target is a later micro-step of the same event in that configuration. Built on
  /// first use.
  semantics::AigLit at_repeated_transient();
  /// The latches seen_during_event made. In a stable situation they describe the event that
  /// ended there: a search started in that situation clears them.
  const std::vector<std::uint32_t>& event_observer_latches() const { return observers_; }
  /// Per transition of the system: it is cleared by this micro-step (meaningful in Trans).
  const std::vector<semantics::AigLit>& fired() const { return fired_; }
  /// Machine latches [0, num_state_latches) are the circuit's state latches, same order.
  std::size_t num_state_latches() const { return circuit_.num_state_latches; }

 private:
  /// Copies the cone of `lit` from the circuit into the machine, with circuit latches and
  /// inputs replaced by `subst` (per circuit node; 0 = not yet translated for AND nodes).
  semantics::AigLit translate(semantics::AigLit lit, std::vector<semantics::AigLit>& memo);

  const semantics::GrafcetCircuit& circuit_;
  semantics::Aig aig_;
  std::vector<semantics::AigLit> on_n_, on_source_, on_boot_;  ///< translation memos
  semantics::AigLit boot_ = 0, stable_ = 0, transient_ = 0, step_ok_ = 0, initial_stable_ = 0;
  semantics::AigLit anomaly_ = 0, repeated_ = 0;
  std::size_t configuration_latches_ = 0;
  std::uint32_t boot_latch_ = 0, stable_latch_ = 0;  ///< N and Q: [0, configuration_latches_)
  std::vector<std::uint32_t> observers_;
  std::vector<semantics::AigLit> fired_;
};

}  // namespace sfcv::engine::sat

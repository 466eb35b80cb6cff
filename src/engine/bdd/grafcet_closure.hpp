#pragma once
// The Grafcet relation between stable situations, computed symbolically from the micro-step
// circuit (semantics/grafcet_circuit.hpp) as a least fixpoint of transient evolutions.
//
// A configuration of the closure is (C, N, Q, I): C the source stable situation, N the current
// transient situation, Q the previous one (only the bits read under an edge), I the inputs the
// evolutions read and the input memory does not hold (none under the single-input-change
// hypothesis). An event from C gives the first configuration (start_next); each evolution maps
// (N, Q) to (M, Q') = (next situation, N); a configuration is an end when it is stable without
// anomaly. Evolutions are deterministic, so a start either reaches exactly one end or runs into
// an anomaly: a range error / forcing conflict, or a cycle of transient situations that never
// stabilises (the instability of docs/semantics.md 2.11), found as the starts from which no end
// is reachable backwards.
//
// The relation R(C, N) relates C to the emitted situation of every end (continuous outputs
// computed), without stutter (the explicit graph omits edges to the source itself).

#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "engine/bdd/bdd_manager.hpp"
#include "semantics/grafcet_circuit.hpp"

namespace sfcv::engine {

struct GrafcetVariables {
  std::vector<int> c, n, m;  ///< per state latch: source, transient, next transient
  std::vector<int> q, qp;    ///< per prev latch: previous transient situation and its next copy
  std::vector<int> in;       ///< per circuit input
};

class GrafcetClosure {
 public:
  using Bdd = bdd::Bdd;
  /// `state_bdd(lit)`: the BDD of a circuit literal with state latches as C, prev latches as Q,
  /// inputs as I.
  GrafcetClosure(const semantics::GrafcetCircuit& circuit, GrafcetVariables vars,
                 const std::function<Bdd(semantics::AigLit)>& state_bdd, int cluster_nodes,
                 double timeout_seconds = 0);

  /// Initial stable situations (over C), and whether some initial valuation is anomalous.
  Bdd initial();
  bool initial_anomaly();
  /// Whether transition t is cleared while some initial valuation stabilises.
  bool fires_initially(std::uint32_t transition);
  bool initial_range_error();

  /// The sources the relation is computed from (preimage, has_successor, fires, anomalies): by
  /// default the reachable situations, computed on first use; the checker passes its reached
  /// set. Situations outside have no successor in that relation.
  void set_sources(const Bdd& sources);

  Bdd image(const Bdd& states);     ///< over C; exact (stutter removed)
  Bdd preimage(const Bdd& states);  ///< over C
  Bdd has_successor();
  /// Sources (over C) with an event whose run clears the transition and stabilises, in
  /// another situation or back in the source (no edge, but the transition fires: 2.5).
  Bdd fires(std::uint32_t transition);
  /// Sources (over C) where `step` (a predicate over C: a step's activity) does not hold,
  /// with an event whose run stabilises and has it hold in one of its situations (transient,
  /// or the stable end; docs/semantics.md 2.5).
  Bdd enters(const Bdd& step);
  /// Whether `step` holds in a situation of a run from an initial valuation that stabilises
  /// (the initial situation itself included).
  bool enters_initially(const Bdd& step);
  /// Sources (over C) with an edge that fires both transitions: some stable situation D is
  /// reached from C by a run that clears i and by a run that clears j (the explicit graph
  /// merges the events from C to D into one edge, its fired set the union of theirs).
  Bdd fires_on_one_edge(std::uint32_t i, std::uint32_t j);
  /// Sources (over C) with an event whose evolutions never stabilise / raise a range error.
  Bdd unstable_states();
  Bdd range_error_states();
  /// The circuit input valuations (over I) of the events from `from` that stabilise in `to`.
  Bdd inputs_between(const Bdd& from, const Bdd& to);
  /// The initial input valuations (over I) under which the initial situation stabilises in
  /// `to` (over C).
  Bdd initial_inputs(const Bdd& to);

 private:
  void check_time() const;  ///< throws bdd::BddError past the deadline
  Bdd micro_image(const Bdd& configs) const;
  Bdd micro_preimage(const Bdd& configs) const;
  Bdd forward(const Bdd& start) const;  ///< every configuration reached from `start`
  /// mu Z. targets | (within & continue & pre(Z))
  Bdd backward(const Bdd& targets, const Bdd& within) const;
  Bdd starts(const Bdd& sources, bool keep_all_inputs) const;
  Bdd initial_starts(bool keep_all_inputs) const;
  /// Ends of `reach` related to their emitted situation over N (Q and kept inputs quantified).
  Bdd emitted(const Bdd& ends) const;
  /// The inputs (over I) of the runs of `reach` whose end emits a situation of `to` (over C).
  Bdd inputs_ending_in(const Bdd& reach, const Bdd& to) const;
  void compute_relation();
  void compute_initial();

  const semantics::GrafcetCircuit& circuit_;
  GrafcetVariables v_;
  bool has_deadline_ = false;
  std::chrono::steady_clock::time_point deadline_;
  std::size_t num_state_ = 0;
  std::vector<Bdd> start_;    ///< per state latch, over C and I
  std::vector<Bdd> initial_;  ///< per state latch, over I
  std::vector<Bdd> final_;    ///< per state latch, over N and I
  std::vector<bool> final_changes_;
  std::vector<Bdd> cleared_;  ///< per transition, over N, Q, I
  Bdd event_, initial_event_, valid_, stable_, error_, continue_;
  Bdd c_cube_, n_cube_, q_cube_, dropped_inputs_cube_, all_inputs_cube_, kept_inputs_cube_;
  Bdd final_changed_n_cube_;
  std::unique_ptr<bdd::VarMap> m_to_n_, n_to_m_, c_to_n_, n_to_c_, final_m_to_n_;
  std::vector<Bdd> clusters_, quantify_after_, pre_quantify_after_;
  Bdd quantify_first_;

  bool have_relation_ = false, have_sources_ = false;
  Bdd sources_;
  Bdd reach_, ends_, ends_ne_, relation_, has_successor_, unstable_, range_;
  Bdd good_;  ///< configurations of reach_ whose run stabilises (its end stutters or not)
  std::vector<Bdd> fires_;
  std::vector<bool> fires_set_;
  std::vector<Bdd> edges_clearing_;  ///< per transition: R(C, N) of the runs that clear it
  std::vector<bool> edges_clearing_set_;
  bool have_initial_ = false;
  Bdd initial_set_;
  bool initial_anomaly_ = false, initial_range_ = false;
  Bdd initial_good_;  ///< initial configurations whose run stabilises
};

}  // namespace sfcv::engine

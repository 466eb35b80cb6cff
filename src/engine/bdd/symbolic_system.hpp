#pragma once
// A transition system's circuit (semantics::TransitionCircuit) as BDDs: the set of initial
// states, a partitioned transition relation with an early-quantification schedule (like SMV's
// `next(x) := f`, one conjunct per state bit, clustered), images and pre-images, and the sets a
// property talks about. Every BDD lives in the one global manager of bdd_manager.hpp.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "engine/bdd/bdd_manager.hpp"
#include "engine/bdd/reorder_mode.hpp"
#include "logic/formula.hpp"
#include "logic/query_compile.hpp"
#include "semantics/grafcet_circuit.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine {

struct SymbolicOptions {
  /// Initial node table, 0: sized from the circuit (make_symbolic_system). BuDDy grows it on
  /// demand, doubling; a preallocated 4M-node table cost every run 0.16 s and 220 MB.
  int nodes = 0;
  int cache = 0;              ///< operation cache entries, 0: a quarter of the table
  int cluster_nodes = 2'000;  ///< conjuncts are clustered up to about this many nodes
  /// Grafcet: the closure stops with LimitReached(Time) after this many seconds (0: no
  /// limit), so that a check with --timeout ends with unknown.
  double timeout_seconds = 0;
  /// The run's deadline (model::Budget): building the circuit stops there (LimitReached).
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// The system's BDDs and its transition relation are built by then or not at all
  /// (LimitReached(Time) saying so): the BDD engine's share of --engine auto's race, after
  /// which it leaves the cores to the SAT engines. None: the run's deadline only.
  std::optional<std::chrono::steady_clock::time_point> relation_deadline;
  /// The run's --memory: building the circuit stops past it (LimitReached(Memory)); 0: none.
  std::uint64_t max_circuit_bytes = 0;
  int max_nodes = 0;  ///< node table limit (0 = none): past it operations throw BddError
  ReorderMode reorder = ReorderMode::None;  ///< sifting of current/next pairs (reorder_mode.hpp)
};

class GrafcetClosure;

class SymbolicSystem {
 public:
  using Bdd = bdd::Bdd;

  SymbolicSystem(const semantics::TransitionSystem& ts, semantics::TransitionCircuit circuit,
                 const SymbolicOptions& options = {});
  /// Grafcet: the relation between stable situations, the closure of the transient evolutions
  /// of `circuit` (grafcet_closure.hpp). Same interface; image, preimage, fires, has_successor
  /// and inputs_between follow the explicit graph's edges (no stutter edges).
  SymbolicSystem(const semantics::TransitionSystem& ts, semantics::GrafcetCircuit circuit,
                 const SymbolicOptions& options = {});
  ~SymbolicSystem();
  SymbolicSystem(const SymbolicSystem&) = delete;
  SymbolicSystem& operator=(const SymbolicSystem&) = delete;

  const semantics::TransitionSystem& system() const { return ts_; }
  const semantics::TransitionCircuit& circuit() const { return circuit_; }

  const Bdd& initial() const { return initial_; }
  /// States with at least one allowed input that raises no range error.
  const Bdd& has_successor() const;
  /// States (current variables) where some allowed input raises a range error (Grafcet: an
  /// event whose evolutions raise a range error or a forcing conflict).
  const Bdd& range_error_states() const;
  /// IEC 61131-3: states where some allowed input runs an ST loop to the bound without its
  /// variables repeating (TransitionCircuit::loop_limit; false when no loop can); Grafcet: false.
  const Bdd& loop_limit_states() const { return loop_limit_states_; }
  /// Grafcet: states with an event whose transient evolutions never stabilise (empty for
  /// IEC 61131-3); initial_unstable(): some initial input valuation never stabilises, and
  /// initial_range_error(): some raises a range error.
  Bdd unstable_states() const;
  bool initial_unstable() const;
  /// Grafcet: transition t is cleared while an initial situation stabilises (IEC: false).
  bool fires_initially(std::uint32_t transition) const;
  bool initial_range_error() const;
  /// Grafcet: the situations whose successors preimage, has_successor, fires and the anomaly
  /// sets describe (the reached set); without it the system computes the reachable set itself.
  /// IEC 61131-3: preimage answers within `states` only, so that the CTL fixpoints work on
  /// the reached states instead of every valuation of the bits (measured: `EF S1` on
  /// `sfcv-gen random 60 --seed 1`, 3548 states, took 3.9 s over all valuations).
  void restrict_sources(const Bdd& states);
  /// How image computes: on the clustered relation, by simulating the circuit on every state
  /// of the set and every input valuation (bit-parallel; the successors' BDD is built from
  /// their sorted list), or by simulation when the set is small and near-explicit (a few states
  /// per BDD node, as random charts' sets are) and on the relation otherwise.
  enum class ImageMethod { Auto, Symbolic, Simulation };
  /// The successors of `states`. Simulation throws std::logic_error when the set or the
  /// inputs are too large to simulate (more than 12 inputs, a Grafcet, a set of 2^64 states).
  /// With `edges`: it receives the number of edges out of `states` (count_edges) when the
  /// image counted them at no cost (simulated, on the reached graph, or of the empty set),
  /// and nullopt otherwise. Auto images a subset of a closed reached set on the graph of its
  /// keys when step() kept them (preimage()).
  Bdd image(const Bdd& states, ImageMethod how = ImageMethod::Auto,
            std::optional<std::uint64_t>* edges = nullptr) const;
  /// The states with a successor in `states` (within restrict_sources()'s set). When step()
  /// kept that set's states as keys, on the graph of their successors (built once, by
  /// simulation), not on the relation.
  Bdd preimage(const Bdd& states) const;
  /// On the reached graph (preimage()), when the reached set is closed: the reached states
  /// from which (`backward`) or to which (forward) a path leads from or to a reached state of
  /// `seeds` with every other state of it in `through`, in one search instead of a fixpoint of
  /// pre-images or images. nullopt without a closed reached graph.
  std::optional<Bdd> reach_on_reached_graph(const Bdd& seeds, const Bdd& through,
                                            bool backward) const;
  /// One breadth-first step of reachability: the successors of `frontier` (the last ring)
  /// outside `reached`, their union with `reached`, and the edges out of `frontier` when the
  /// step counted them (simulated). From the first ring on (`frontier` == `reached`), while
  /// each step is fed the previous one's ring and reached set and every ring is simulated
  /// (image()'s choice), the reached states are also kept as keys: the next frontier's states
  /// are simulated from them, and only the new successors make the ring's BDD, with no walk of
  /// the frontier's BDD and no `& !reached`.
  struct Step {
    Bdd ring, reached;
    std::optional<std::uint64_t> edges;
  };
  Step step(const Bdd& frontier, const Bdd& reached) const;

  /// The states where a propositional formula over observables holds.
  Bdd atom(const logic::Formula& f);
  /// States where transition t fires under some allowed, error-free input.
  Bdd fires(std::uint32_t transition);
  /// Grafcet: states with an edge (events merged by target) that fires both transitions.
  Bdd fires_on_one_edge(std::uint32_t i, std::uint32_t j);
  /// States that fire at least one transition under some allowed, error-free input.
  Bdd fires_any();
  /// Grafcet: states where `step` (a state predicate: a step's activity) does not hold, with an
  /// event during whose evolutions it holds in some situation (GrafcetClosure::enters); IEC
  /// 61131-3: none.
  Bdd enters(const Bdd& step);
  /// Grafcet: `step` holds in a situation crossed while an initial situation stabilises.
  bool enters_initially(const Bdd& step) const;

  /// Number of states in `states` (exact below 2^64, else an approximation).
  double count(const Bdd& states) const;
  /// Number of states in `states`, exactly.
  logic::BigCount count_exact(const Bdd& states) const;
  /// How count_edges counts: on the relation (symbolic), by simulating the circuit on every
  /// state of the set and every input valuation (bit-parallel; when the set and the inputs are
  /// small), or whichever is expected to be cheaper.
  enum class EdgeCounting { Auto, Symbolic, Simulation };
  /// Number of pairs (s, s') with s in `from` and s' a successor of s: the explicit graph's
  /// edges (one per source and target), exactly; nullopt when the engine cannot count them
  /// (Grafcet; Simulation on a set or input count too large for it).
  std::optional<logic::BigCount> count_edges(const Bdd& from,
                                             EdgeCounting how = EdgeCounting::Auto) const;
  /// One concrete state of a non-empty set.
  std::vector<semantics::StateWord> pick(const Bdd& states) const;
  /// The singleton set of a concrete state.
  Bdd singleton(semantics::StateView state) const;

  /// Circuit input values (one bool per circuit input) that lead from `from` to `to` in one
  /// cycle, allowed and without range error; empty when there are none. Grafcet: those of an
  /// event that stabilises in `to`, keeping every input it can at its value in `near` (values
  /// of TransitionSystem::inputs(), the trace's previous row; empty: the lowest values) and
  /// every delay unelapsed, so that a trace changes one input per row under the
  /// single-input-change hypothesis (docs/semantics.md 2.15).
  std::vector<bool> inputs_between(semantics::StateView from, semantics::StateView to,
                                   const std::vector<std::int64_t>& near = {}) const;
  /// Grafcet: circuit input values of an initial input valuation under which the initial
  /// situation stabilises in `to`, as near `near` as inputs_between's; empty when there are
  /// none, and always for IEC 61131-3 (its initial state reads no input).
  std::vector<bool> initial_inputs(semantics::StateView to,
                                   const std::vector<std::int64_t>& near = {}) const;
  /// The transitions fired from `from` under circuit input values `inputs` (Grafcet: along the
  /// whole transient evolution), sorted.
  std::vector<std::uint32_t> fired_between(semantics::StateView from,
                                           const std::vector<bool>& inputs) const;

  std::size_t num_state_variables() const { return current_vars_.size(); }
  /// Whether the partitioned relation has been built (it is, on first use: relation()).
  bool has_relation() const { return relation_ != nullptr; }

  // Conflicts under --priority none (IEC 61131-3, the `conflicts` check): sets over the current
  // variables and the "plant" inputs, every input but the `choice:` pseudo-inputs
  // (conflict_ignored_inputs in standard_check_runner.hpp).

  /// The (x, plant inputs) of `states` under which two values of the choice inputs fire
  /// different sets of transitions (allowed and error-free both).
  Bdd choice_matters(const Bdd& states);
  /// One (x, plant inputs) valuation of a non-empty such set, as a minterm.
  Bdd pick_point(const Bdd& set);
  /// The (x, plant inputs) with a fired set (under some choice) that `point` has under no
  /// choice: those whose alternatives `point`'s do not cover.
  Bdd beyond_fired_sets_of(const Bdd& point);
  /// The states of `states` (over current variables) from which, under some plant inputs, two
  /// values of the `order:` inputs (docs/semantics.md 1.2a) give different next states (both
  /// allowed and error-free): the order-dependence check's candidates. IEC 61131-3 only.
  Bdd order_matters(const Bdd& states);
  /// The state of a point, over current variables.
  Bdd point_state(const Bdd& point) const { return point.exist(input_cube_); }

  // Evolutions, for the query language (symbolic_evolutions.cpp). An evolution is a pair
  // (x, x') over the current and next variables, as the explicit graph merges all inputs that
  // lead from x to x' into one edge.

  /// Pairs (x, x') with x in `from` such that some allowed, error-free input satisfying
  /// `on_inputs` (a BDD over current and input variables) leads from x to x' in one cycle.
  Bdd evolutions(const Bdd& from, const Bdd& on_inputs = Bdd::constant(true)) const;
  /// The pairs of `pairs` all of whose allowed, error-free inputs satisfy `on_inputs`.
  Bdd evolutions_only_under(const Bdd& pairs, const Bdd& on_inputs) const;
  /// Current and input valuations under which at least one transition fires.
  Bdd fires_any_under_inputs();
  Bdd to_next(const Bdd& states) const;      ///< current variables renamed to next ones
  Bdd to_current(const Bdd& on_next) const;  ///< next variables renamed to current ones
  Bdd sources(const Bdd& pairs) const;       ///< the x of the pairs
  Bdd targets(const Bdd& pairs) const;       ///< the x' of the pairs, over current variables
  /// Number of pairs (exact below 2^53).
  double count_pairs(const Bdd& pairs) const;
  /// Whether a BDD mentions circuit input variables.
  bool depends_on_inputs(const Bdd& f) const;
  /// States where an observable is non-zero (a step or action is active, a Boolean is true).
  Bdd observable_nonzero(std::uint32_t observable);
  /// States where layout field `field` holds a non-zero value (an action's stored flag).
  Bdd field_nonzero(std::uint32_t field);
  /// The current and input valuations where an input/output expression of a query holds;
  /// `slots` gives the step (observable) bound to each set-builder variable.
  Bdd signal(const logic::Signal& s, const std::vector<std::uint32_t>& slots);
  /// Every state of a set, in no particular order; throws std::length_error above `limit`.
  std::vector<std::vector<semantics::StateWord>> enumerate(const Bdd& states,
                                                           std::uint64_t limit) const;
  /// The states that come before `state` in the canonical order (layout fields in order, each
  /// compared by value), over current variables.
  Bdd canonically_before(semantics::StateView state) const;

 private:
  struct ReachedKeys;  // the reached states as keys (step()), defined in the .cpp
  Bdd node_bdd(semantics::AigLit lit) const;  ///< the BDD of an Aig literal (memoised per node)
  /// The partitioned relation: clusters of (next_l <-> f_l), with the variables each image,
  /// pre-image and edge count quantifies after each cluster. Built on first use: images by
  /// simulation need none, and on a small chart building it costs more than exploring.
  struct Relation {
    std::vector<Bdd> clusters;
    // Image: the current and input variables quantified before any cluster and after each.
    Bdd quantify_first;
    std::vector<Bdd> quantify_after;
    // Pre-image: the next variables a cluster defines and the inputs it is the last to read.
    Bdd pre_quantify_first;
    std::vector<Bdd> pre_quantify_after;
    // Edge counting: the inputs a cluster is the last to read.
    Bdd inputs_first;
    std::vector<Bdd> inputs_after;
  };
  const Relation& relation() const;
  const Relation& build_relation() const;  ///< relation()'s work, within its share of the time
  /// A set count_edges and image may simulate: an IEC 61131-3 system of at most 12 inputs, a
  /// set of fewer than 2^64 states costing at most `max_work` node words (and within a
  /// quarter of --memory), and when `near_explicit_only`, at most a few states per BDD node
  /// (where simulating is cheaper than conjoining the relation, whose intermediate products
  /// are near-explicit too). Its states and nodes; nullopt when it may not be simulated.
  struct SimulatedSet {
    std::uint64_t states = 0;
    int nodes = 0;
  };
  std::optional<SimulatedSet> simulation_of(const Bdd& from, std::uint64_t max_work,
                                            bool near_explicit_only) const;
  /// simulation_of()'s bounds on a set already measured.
  bool may_simulate(const SimulatedSet& set, std::uint64_t max_work, bool near_explicit_only) const;
  /// Whether small sets (under kMinSimulatedImageNodes nodes) are still simulated: before the
  /// relation is built, within a number of images and an amount of work.
  bool simulates_small_sets() const;
  /// image()'s choice for a set that may be simulated: whether to simulate it (counting a
  /// small one against the small-set budget).
  bool chooses_simulation(const SimulatedSet& set) const;
  /// step() with the reached states as keys; nullopt when the step is not simulated.
  std::optional<Step> simulated_step(const Bdd& frontier, const Bdd& reached) const;
  /// The reached states' keys with their successor graph (built on first use), when step()
  /// kept every state of restrict_sources()'s set; null otherwise.
  ReachedKeys* reached_graph() const;
  /// Which stored states a set (within the reached set) holds; nullopt when the set mentions
  /// other variables.
  std::optional<std::vector<bool>> reached_indices(const ReachedKeys& keys,
                                                   const Bdd& states) const;
  /// The BDD of the stored states `in` marks.
  Bdd bdd_of_reached(const ReachedKeys& keys, const std::vector<bool>& in) const;
  /// preimage() within the reached set, and image() of a subset of a closed reached set, on
  /// the reached graph; nullopt when there is none.
  std::optional<Bdd> preimage_on_reached_graph(const Bdd& states) const;
  std::optional<Bdd> image_on_reached_graph(const Bdd& states,
                                            std::optional<std::uint64_t>* edges) const;
  /// The latch values of a state.
  std::vector<bool> latches_of(semantics::StateView state) const;
  /// One valuation of `on_inputs` (over the input variables) as circuit input values: input
  /// by input, its value in `near` (lowest values when empty; 0 for pseudo-inputs) whenever
  /// the rest of the set allows it; empty when the set is.
  std::vector<bool> pick_inputs_near(Bdd on_inputs, const std::vector<std::int64_t>& near) const;
  bool simulates(const Bdd& from, std::uint64_t max_work, bool near_explicit_only) const;
  /// count_edges and image by simulation (after simulates()); nullopt when `from` mentions a
  /// variable other than the current ones. image_by_simulation counts in `tally` the states
  /// it simulated and their edges.
  struct SimulationTally {
    std::uint64_t states = 0, edges = 0;
  };
  std::optional<logic::BigCount> count_edges_by_simulation(const Bdd& from) const;
  std::optional<Bdd> image_by_simulation(const Bdd& from, SimulationTally& tally) const;
  Bdd symbolic_image(const Bdd& states) const;  ///< on the clustered relation
  void prepare_choice_cubes();
  Bdd field_value_equals(std::uint32_t observable, std::int64_t value);

  const semantics::TransitionSystem& ts_;
  semantics::TransitionCircuit circuit_;
  std::vector<int> input_var_;    ///< per circuit input
  std::vector<int> current_var_;  ///< per latch
  std::vector<int> next_var_;     ///< per latch
  std::vector<int> current_vars_;
  mutable std::vector<Bdd> memo_;  // node_bdd's memo: a cache, filled by const queries too
  mutable std::vector<bool> memo_set_;
  Bdd current_cube_, next_cube_, input_cube_;
  Bdd initial_, ok_, has_successor_, range_error_states_, loop_limit_states_;
  int cluster_nodes_;
  std::optional<std::chrono::steady_clock::time_point> relation_deadline_;
  mutable std::unique_ptr<Relation> relation_;         // relation(): null until first used
  mutable std::unique_ptr<ReachedKeys> reached_keys_;  // step(): the reached states as keys
  /// Images of small sets simulated before the relation was built, and their work
  /// (simulation_work_per_state units): image() stops past a number or an amount.
  mutable std::uint32_t small_images_simulated_ = 0;
  mutable std::uint64_t small_work_simulated_ = 0;
  std::uint64_t max_simulation_bytes_ = 0;  ///< successors a simulation holds (0: no limit)
  std::unique_ptr<bdd::VarMap> next_to_current_;
  std::unique_ptr<bdd::VarMap> current_to_next_;
  Bdd preimage_care_ = Bdd::constant(true);  ///< restrict_sources (IEC 61131-3)
  std::vector<Bdd> fires_;
  std::vector<bool> fires_set_;
  std::optional<Bdd> choice_cube_;  ///< the `choice:` input variables (prepare_choice_cubes)
  Bdd plant_cube_;                  ///< every other input variable
  std::optional<Bdd> order_cube_;   ///< the `order:` input variables (order_matters)
  // Grafcet mode.
  std::unique_ptr<semantics::GrafcetCircuit> grafcet_circuit_;
  std::unique_ptr<GrafcetClosure> grafcet_;
  mutable Bdd grafcet_has_successor_, grafcet_range_error_;
};

/// The symbolic system of `ts` by its semantics (IEC 61131-3 scan cycle or Grafcet stable
/// situations). Throws semantics::CircuitUnsupported for constructs the circuits cannot express.
std::unique_ptr<SymbolicSystem> make_symbolic_system(const semantics::TransitionSystem& ts,
                                                     const SymbolicOptions& options = {});

}  // namespace sfcv::engine

#pragma once
// The transition system every engine consumes (explicit, BDD, exports), for both semantics.
//
// States are packed bit vectors (StateLayout). From a state, successors come grouped by the
// condition on the inputs that leads to each: a semantics enumerates the sets of transitions
// that can fire together and the input condition of each, never all 2^inputs valuations.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/source_location.hpp"
#include "model/types.hpp"
#include "semantics/input_condition.hpp"
#include "semantics/state_layout.hpp"

namespace sfcv::semantics {

enum class SemanticsKind { Iec61131, Grafcet };
std::string_view to_string(SemanticsKind k);

/// Something a property can talk about: a step's activity, an action's activity, a variable.
enum class ObservableKind { Step, Action, Variable };

struct Observable {
  std::string name;                  ///< display name, unique: "MAIN.FILL_A", "V1", "X12"
  std::vector<std::string> aliases;  ///< other names a property may use: "FILL_A", "FILL_A.X"
  ObservableKind kind = ObservableKind::Variable;
  model::Type type;        ///< Bool for steps and actions
  bool is_output = false;  ///< an output of the chart (traces show these)
};

/// A chart transition, numbered across the whole system (for traces and dead-transition checks).
struct TransitionInfo {
  std::string name;  ///< "MAIN: S1 -> S2" when the chart does not name it
  std::string pou;
  std::string chart;
  model::SourceLocation where;
};

/// A POU as the system runs it: a program under its name, an instance of a function block type
/// under its path ("Main.v1"), whose steps and actions are named from that path; `pou` is its
/// POU in the project ("Valve"). `units`: the paths of its SFC actions run as units of their
/// own ("Main.v1.ACT_Init"), whose steps and action copies are named from those paths.
struct PouInstance {
  std::string path;
  std::string pou;
  std::vector<std::string> units;
};

/// A Boolean variable written by both continuous and stored actions (Grafcet, docs/semantics.md
/// 2.7): the layout field of its continuous assignation and that of the value the stored
/// actions keep; the variable reads 1 when either does.
struct MixedVariable {
  std::string name;
  std::uint32_t assigned_field = 0, stored_field = 0;
};

struct Successor {
  StateView target;
  const InputCondition& condition;       ///< inputs under which this evolution happens
  std::span<const std::uint32_t> fired;  ///< indices into transitions(), sorted
  /// Grafcet (docs/semantics.md 2.5): the layout fields of the steps active in some situation
  /// of this evolution (transient, or the stable one) but in neither its source nor its target,
  /// sorted. An initial evolution has no source: the steps of the initial situation left before
  /// it stabilises are here. Empty for IEC 61131-3.
  std::span<const std::uint32_t> entered = {};
};

/// A defect found while computing successors (e.g. a Grafcet instability: transient evolutions
/// that never reach a stable situation). The engine reports it; it never loops.
struct Anomaly {
  enum class Kind { Instability, RangeError } kind = Kind::Instability;
  std::string message;
  InputCondition condition;                   ///< inputs that trigger it
  std::vector<std::vector<StateWord>> cycle;  ///< the situations of the cycle (Instability)
};

class SuccessorSink {
 public:
  virtual ~SuccessorSink() = default;
  virtual void successor(const Successor& s) = 0;
  /// Grafcet: an evolution of the state that ends in the state itself, so no successor (2.1:
  /// stuttering is not an edge), but that clears s.fired or crosses s.entered on the way (an
  /// elapse that runs `2 -> 1 -> 2`). Called only when one of them is not empty.
  virtual void returning(const Successor&) {}
  virtual void anomaly(const Anomaly&) {}
  /// Called by a semantics that enumerates input valuations one by one (IEC 61131-3: the leaves
  /// of the scan cycle's input decisions) every so many of them, with the count for this state
  /// so far: the sink may throw (a limit of its engine, which the semantics cannot know) to stop
  /// the enumeration; the state then has no successors from this call. `held_bytes`: what the
  /// semantics holds for this state so far (the input conditions of its successors), for the
  /// engine's memory budget.
  virtual void valuations(std::uint64_t /*count*/, std::uint64_t /*held_bytes*/) {}
  /// A sink that wants only the successors under one full input valuation (indexed as
  /// inputs()): a semantics may skip the others (Grafcet: `sfcv simulate` on a chart whose
  /// start splits on 45 inputs walked all 2.7e12 initial situations to pick one).
  virtual const std::vector<std::int64_t>* only_valuation() const { return nullptr; }
};

class TransitionSystem {
 public:
  virtual ~TransitionSystem() = default;

  virtual SemanticsKind kind() const = 0;
  virtual const StateLayout& layout() const = 0;
  virtual const std::vector<InputVariable>& inputs() const = 0;
  virtual const std::vector<Observable>& observables() const = 0;
  virtual const std::vector<TransitionInfo>& transitions() const = 0;
  /// The POUs this system runs, each instance apart; empty where every POU of the project
  /// runs once, under its own name (Grafcet).
  virtual std::vector<PouInstance> pou_instances() const { return {}; }
  /// The variables written in both modes, each with its two fields; empty where there are none.
  virtual std::vector<MixedVariable> mixed_variables() const { return {}; }

  /// The initial states, each with the condition on the initial inputs that yields it.
  virtual void initial_states(SuccessorSink& sink) const = 0;
  /// An estimate of how many initial states initial_states() would enumerate, computed without
  /// enumerating them (a Grafcet's initial situations split on the initial inputs, up to
  /// millions); nullopt when the system does not estimate (few initial states). Deterministic.
  /// Only a forecast for choosing an engine (--engine auto), never used for a verdict.
  virtual std::optional<double> estimate_initial_states() const { return std::nullopt; }
  /// Every successor of `state`; the conditions of the successors partition the input
  /// valuations allowed by the assumptions (several may hold at once only when the semantics is
  /// nondeterministic, e.g. conflicts with no priority order).
  virtual void successors(StateView state, SuccessorSink& sink) const = 0;

  /// Value of observable `index` in `state` (0/1 for steps and actions).
  virtual std::int64_t observe(StateView state, std::uint32_t index) const = 0;
  /// The layout fields observe(state, index) reads: its value is a function of theirs alone.
  /// nullopt when the system does not say.
  virtual std::optional<std::vector<std::uint32_t>> observed_fields(std::uint32_t) const {
    return std::nullopt;
  }

  /// "{S1, S5} V1 V3" : active steps and true Boolean outputs, for traces and listings.
  virtual std::string describe(StateView state) const;

  /// The observable holding the previous value of observable `index` (prev(x) in a property),
  /// when the system keeps it (a HistorySystem, history_system.hpp); nullopt otherwise.
  virtual std::optional<std::uint32_t> previous_observable(std::uint32_t) const {
    return std::nullopt;
  }

 private:
  friend std::optional<std::uint32_t> find_observable(const TransitionSystem&, std::string_view,
                                                      std::string*);
  /// Observables by upper-case name and alias, built at the first look-up (find_observable),
  /// so that resolving every step of a 100,000-step chart is linear, not quadratic. A copy of
  /// the system starts without it; it is rebuilt when the observables have changed size.
  struct NameIndex;
  struct LazyNameIndex {
    LazyNameIndex();
    LazyNameIndex(const LazyNameIndex&);
    LazyNameIndex& operator=(const LazyNameIndex&);
    ~LazyNameIndex();
    std::mutex mutex;
    std::unique_ptr<const NameIndex> index;
  };
  mutable LazyNameIndex names_;
};

using TransitionSystemPtr = std::unique_ptr<TransitionSystem>;

/// Resolves a name used in a property ("FILL_A", "FILL_A.X", "X12", "MAIN.S1", "V1") to an
/// observable, case-insensitively, by name then aliases. Returns nullopt and sets `error` when it
/// is unknown or ambiguous (the message lists the candidates).
std::optional<std::uint32_t> find_observable(const TransitionSystem& ts, std::string_view name,
                                             std::string* error = nullptr);

}  // namespace sfcv::semantics

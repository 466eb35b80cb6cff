#pragma once
// Invariants (AG p, p propositional) decided on the fly, as Spin does: breadth-first search with
// parent pointers that stops at the first state violating every property it still has to
// decide, and keeps neither edges nor their labels (the conditions and fired transitions of the
// few edges on a counterexample are recomputed from their source state).
//
// Results equal those of the graph-based engine (explicit_model_checker.hpp): the same verdicts
// (a state limit aside), shortest counterexamples (the first violating state in BFS order,
// reached through its BFS parents), and the same state and edge counts whenever the whole space
// is explored. When the search stops early, the counts are those of the part explored. With the
// interpreted enumerator the BFS order is the graph's, and so are the counterexamples and the
// part a state limit explores; the compiled one orders a state's targets by input valuation, the
// interpreter by its input decisions, so where a cycle reads several inputs one after another
// (nested charts) the counterexample may end at another violating state of the same depth.

#include <cstdint>
#include <memory>
#include <vector>

#include "engine/explicit/state_codec.hpp"
#include "logic/check_result.hpp"
#include "logic/check_task.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::engine {

/// Distinct successor states of a state, without their conditions or fired transitions: what a
/// reachability search needs. The default enumerator asks TransitionSystem::successors; a
/// compiled one (compiled_successors.hpp) evaluates the scan cycle's circuit bit-parallel.
class TargetEnumerator {
 public:
  virtual ~TargetEnumerator() = default;
  /// Appends the successors of `state` to `out` (words_per_state words each, duplicates
  /// allowed); both in the stored form of codec().
  virtual void targets(semantics::StateView state, std::vector<semantics::StateWord>& out) = 0;
  /// The targets of `count` states packed one after another in `states`, in that order, as
  /// targets() gives them; after each state, the end of its targets in `out` is appended to
  /// `ends`. A compiled enumerator evaluates several states at once. When it throws, the
  /// states whose ends were appended are complete and the next one is the one that threw.
  virtual void targets_of(semantics::StateView states, std::uint32_t count,
                          std::vector<semantics::StateWord>& out, std::vector<std::uint32_t>& ends);
  /// An enumerator giving the same targets in the same order that may run on another thread
  /// beside this one; null when this one cannot (the interpreted system keeps its scratch
  /// state in the TransitionSystem).
  virtual std::unique_ptr<TargetEnumerator> clone() const { return nullptr; }
  /// The form of the states it reads and writes; null: as the system's layout packs them.
  virtual const StateCodec* codec() const { return nullptr; }
  /// The bytes the caller holds (the store, the parents): one state's enumeration may add to
  /// them only what the budget's memory leaves.
  void set_memory_in_use(std::uint64_t bytes) { memory_in_use_ = bytes; }

 protected:
  std::uint64_t memory_in_use_ = 0;
};

/// `limits` bounds the enumeration of one state: past its max_valuations, deadline, cancel or
/// memory (with set_memory_in_use()), targets() throws LimitReached (Valuations, Time,
/// Memory) and appends nothing.
std::unique_ptr<TargetEnumerator> make_interpreted_enumerator(const semantics::TransitionSystem& ts,
                                                              model::Budget limits = {});

/// Whether `task` asks only for invariants (every property AG p with p propositional, no
/// fairness, no standard check, no coverage), which check_invariants decides without the graph.
bool invariants_only(const logic::CheckTask& task);

/// Decides the invariants of `task` (precondition: invariants_only(task)) with `enumerator`
/// generating successors (null: the interpreted one). With `threads` > 1 and an enumerator
/// that clones, the other threads generate the successors of the next block of stored states
/// while this one stores a block's: states are still numbered and judged in BFS order on one
/// thread, so every count, verdict and counterexample equals the one-thread run.
logic::CheckReport check_invariants(const logic::CheckTask& task,
                                    TargetEnumerator* enumerator = nullptr, unsigned threads = 1);

}  // namespace sfcv::engine

#pragma once
// The reachable situations graph of a transition system, built explicitly by breadth-first
// search: for Grafcet its nodes are stable situations (seed 002's RSG), for IEC 61131-3 the
// configurations after each scan cycle. Edges carry the input condition that causes them and
// the transitions fired. BFS order makes parent pointers give shortest paths from the initial
// states, which counterexamples use.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/explicit/state_store.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::engine {

struct ExplorationProgress {
  std::uint64_t states = 0;
  std::uint64_t edges = 0;
  std::uint32_t depth = 0;
  double seconds = 0;
};

struct ExplorationOptions {
  std::uint64_t max_states = 0;  ///< 0 = unlimited
  double timeout_seconds = 0;    ///< 0 = unlimited
  /// The run's deadline (model::Budget), beside timeout_seconds: whichever comes first.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// model::Budget::cancel (may be null): raised, exploration stops as at the deadline.
  const std::atomic<bool>* cancel = nullptr;
  std::uint64_t max_memory_bytes = 0;  ///< 0 = unlimited; approximate (states + edges)
  /// model::Budget::max_valuations: input valuations one state's successors may take (0 =
  /// unlimited); past it the state stays unexpanded and the limit is "valuations".
  std::uint64_t max_valuations = 0;
  /// With a deadline: stop (limit "time") as soon as the states found but not yet expanded
  /// would take longer than the time left at the rate measured so far, so that an exploration
  /// that cannot finish hands over early (the probe of --engine auto) instead of at its deadline.
  bool forecast = false;
  bool keep_conditions = true;  ///< store each edge's input condition (RSG listing, traces)
  bool keep_fired = true;       ///< store each edge's fired transitions
  /// Called about every `progress_interval` states; may be empty.
  std::function<void(const ExplorationProgress&)> progress;
  std::uint64_t progress_interval = 1u << 16;
};

class ReachableSituationGraph {
 public:
  static constexpr std::uint32_t kNone = ~0U;

  explicit ReachableSituationGraph(const semantics::TransitionSystem& ts);

  const semantics::TransitionSystem& system() const { return *ts_; }
  const StateStore& states() const { return states_; }
  std::uint32_t num_states() const { return states_.size(); }
  std::uint64_t num_edges() const { return targets_.size(); }

  const std::vector<std::uint32_t>& initial_states() const { return initial_; }
  /// Condition on the initial inputs for initial state initial_states()[i].
  const semantics::InputCondition& initial_condition(std::size_t i) const {
    return conditions_[initial_condition_ids_[i]];
  }

  // Out-edges of state s are the edge ids [edges_begin(s), edges_end(s)); a state left
  // unexpanded by a limit has no known edges (an empty range).
  std::uint64_t edges_begin(std::uint32_t s) const {
    return s + 1 < offsets_.size() ? offsets_[s] : targets_.size();
  }
  std::uint64_t edges_end(std::uint32_t s) const {
    return s + 1 < offsets_.size() ? offsets_[s + 1] : targets_.size();
  }
  std::uint32_t target(std::uint64_t edge) const { return targets_[edge]; }
  /// Empty condition list when the graph was built without keep_conditions.
  const semantics::InputCondition& condition(std::uint64_t edge) const;
  std::span<const std::uint32_t> fired(std::uint64_t edge) const;
  bool has_conditions() const { return !edge_condition_ids_.empty() || targets_.empty(); }

  /// Whether a state was fully expanded (false only for the frontier left by a limit).
  bool expanded(std::uint32_t s) const { return s + 1 < offsets_.size(); }

  /// Shortest path (BFS) from an initial state to s: the edges taken, in order; the initial
  /// state is path_initial(s).
  std::vector<std::uint64_t> shortest_path_edges(std::uint32_t s) const;
  std::uint32_t path_initial(std::uint32_t s) const;
  /// Whether a BFS path to s is known: false only for a state first found while expanding the
  /// state a limit then left unexpanded (its edges, and so the path, were dropped).
  bool has_path(std::uint32_t s) const {
    return parent_edge_state_[s] != kNone ||
           std::find(initial_.begin(), initial_.end(), s) != initial_.end();
  }
  std::uint32_t depth(std::uint32_t s) const { return depth_[s]; }
  /// The source state of an edge (binary search on the offsets).
  std::uint32_t source(std::uint64_t edge) const;

  /// Predecessor lists, built on first use (backward CTL algorithms).
  const std::vector<std::uint64_t>& predecessor_offsets() const;
  const std::vector<std::uint64_t>& predecessor_edges() const;  ///< edge ids, grouped by target

  /// Transitions that fired on at least one edge (dead-transition check), by TS index.
  const std::vector<bool>& fired_somewhere() const { return fired_somewhere_; }
  /// Transitions cleared while an initial situation stabilised (Grafcet), by TS index.
  const std::vector<bool>& fired_initially() const { return fired_initially_; }

  // Grafcet, what the evolutions crossed (docs/semantics.md 2.5; semantics::Successor::entered):
  // records for the few states that have any, in state order.
  /// The states with steps crossed by one of their evolutions (edges, and evolutions back to
  /// the state itself) and active neither in the state nor at that evolution's end, and, for
  /// the i-th of them, those steps' layout fields (the union over its evolutions, sorted).
  const std::vector<std::uint32_t>& crossing_states() const { return crossing_states_; }
  std::span<const std::uint32_t> crossed(std::size_t i) const {
    return {crossed_.data() + crossed_offsets_[i], crossed_offsets_[i + 1] - crossed_offsets_[i]};
  }
  /// The states with an evolution back to themselves that clears transitions (no edge: 2.1),
  /// and, for the i-th of them, those transitions (sorted).
  const std::vector<std::uint32_t>& returning_states() const { return returning_states_; }
  std::span<const std::uint32_t> returning_fired(std::size_t i) const {
    return {returning_fired_.data() + returning_offsets_[i],
            returning_offsets_[i + 1] - returning_offsets_[i]};
  }
  /// The step fields active while an initial situation stabilised and not at its end (sorted).
  const std::vector<std::uint32_t>& entered_initially() const { return entered_initially_; }

  const std::vector<semantics::Anomaly>& anomalies() const { return anomalies_; }

  /// True when every reachable state was expanded; false when a limit stopped exploration.
  bool complete() const { return complete_; }
  /// Which limit stopped exploration ("states", "time", "memory"), empty when complete.
  const std::string& limit_reached() const { return limit_; }
  double build_seconds() const { return seconds_; }
  std::size_t memory_bytes() const;

 private:
  friend ReachableSituationGraph build_reachable_situation_graph(const semantics::TransitionSystem&,
                                                                 const ExplorationOptions&);
  std::uint32_t intern_condition(semantics::InputCondition c);

  const semantics::TransitionSystem* ts_;
  StateStore states_;
  std::vector<std::uint32_t> initial_;
  std::vector<std::uint32_t> initial_condition_ids_;
  std::vector<std::uint64_t> offsets_{0};
  std::vector<std::uint32_t> targets_;
  std::vector<std::uint32_t> edge_condition_ids_;
  std::vector<std::uint64_t> fired_offsets_{0};
  std::vector<std::uint32_t> fired_;
  std::vector<semantics::InputCondition> conditions_;
  std::uint64_t condition_bytes_ = 0;  ///< heap bytes of conditions_' cubes
  // Interning of conditions: open addressing over condition ids + 1 (0 = empty), grown at half
  // load, because a Grafcet start can bring millions of distinct conditions (corpus 22).
  std::vector<std::uint32_t> condition_table_;
  std::vector<std::uint64_t> condition_hashes_;   ///< per condition id
  std::vector<std::uint32_t> parent_edge_state_;  ///< BFS parent state (kNone for initial)
  std::vector<std::uint64_t> parent_edge_;        ///< BFS parent edge id
  std::vector<std::uint32_t> depth_;
  std::vector<bool> fired_somewhere_;
  std::vector<bool> fired_initially_;
  std::vector<std::uint32_t> crossing_states_, crossed_;
  std::vector<std::uint64_t> crossed_offsets_{0};
  std::vector<std::uint32_t> returning_states_, returning_fired_;
  std::vector<std::uint64_t> returning_offsets_{0};
  std::vector<std::uint32_t> entered_initially_;
  std::vector<semantics::Anomaly> anomalies_;
  mutable std::vector<std::uint64_t> pred_offsets_, pred_edges_;
  bool complete_ = false;
  std::string limit_;
  double seconds_ = 0;
};

/// Breadth-first exploration from the initial states. Stops at the first limit reached and then
/// reports complete() == false: a caller must answer "unknown", never "holds".
ReachableSituationGraph build_reachable_situation_graph(const semantics::TransitionSystem& ts,
                                                        const ExplorationOptions& options = {});

}  // namespace sfcv::engine

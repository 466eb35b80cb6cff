#include "engine/explicit/reachable_situation_graph.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_map>

#include "engine/auto_policy.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

using semantics::InputCondition;
using semantics::InputCube;

namespace {

std::uint64_t hash_condition(const InputCondition& c) {
  std::uint64_t h = 1469598103934665603ULL;
  auto add = [&h](std::uint64_t v) { h = (h ^ v) * 1099511628211ULL; };
  for (const auto& cube : c.cubes) {
    add(0xC0BE);
    for (const auto& l : cube.literals) {
      add(l.input);
      add(static_cast<std::uint64_t>(l.lo));
      add(static_cast<std::uint64_t>(l.hi));
    }
  }
  return h;
}

/// Successors of one state, merged by target before they are stored: one edge per
/// (source, target) pair, as in the seed's RSG, with the union of the conditions.
struct PendingEdge {
  std::uint32_t target;
  semantics::ConditionBuilder condition;
  std::vector<std::uint32_t> fired;
};

/// Thrown by the sink when a limit is reached in the middle of one state's successors (or of
/// the initial states): a semantics may enumerate very many of them in one call (a Grafcet
/// stabilised under every initial input valuation), so limits cannot wait for the next state.
struct StopExploring {
  const char* which;
};

/// `into` := into ∪ from (both sorted).
void merge(std::vector<std::uint32_t>& into, std::span<const std::uint32_t> from) {
  if (from.empty() || std::includes(into.begin(), into.end(), from.begin(), from.end())) return;
  std::vector<std::uint32_t> merged;
  std::set_union(into.begin(), into.end(), from.begin(), from.end(), std::back_inserter(merged));
  into = std::move(merged);
}

class Collector final : public semantics::SuccessorSink {
 public:
  Collector(StateStore& store, const ExplorationOptions& limits,
            std::chrono::steady_clock::time_point start)
      : store_(store), limits_(limits), start_(start) {}

  /// Before the successors of a state: `graph_bytes` is what the graph holds besides its store.
  void begin(std::uint64_t graph_bytes) {
    pending.clear();
    crossed.clear();
    returned.clear();
    pending_bytes_ = 0;
    graph_bytes_ = graph_bytes;
    ++generation_;
  }

  void successor(const semantics::Successor& s) override {
    if (limits_.max_states > 0 && store_.size() > limits_.max_states) throw StopExploring{"states"};
    // Polled by work, not by calls: one successor of a wide state may bring millions of cubes,
    // so the limits are read before they are copied.
    work_ += 1 + s.condition.cubes.size();
    if (work_ >= next_poll_) {
      next_poll_ = work_ + 1024;
      check_limits(s.condition.memory_bytes());
    }
    const std::uint32_t index = store_.insert(s.target).first;
    // Find this target's pending edge in O(1): a generation-stamped slot per state index.
    if (index >= stamp_.size()) {
      stamp_.resize(static_cast<std::size_t>(index) * 2 + 16, 0);
      slot_.resize(stamp_.size(), 0);
    }
    if (stamp_[index] != generation_) {
      stamp_[index] = generation_;
      slot_[index] = static_cast<std::uint32_t>(pending.size());
      pending.push_back({index, {}, {}});
    }
    merge(crossed, s.entered);
    PendingEdge& e = pending[slot_[index]];
    const auto before = e.condition.memory_bytes();
    e.condition.add(s.condition.cubes);
    pending_bytes_ += e.condition.memory_bytes() - before;
    if (e.fired.empty()) {
      e.fired.assign(s.fired.begin(), s.fired.end());
    } else if (!std::equal(e.fired.begin(), e.fired.end(), s.fired.begin(), s.fired.end())) {
      std::vector<std::uint32_t> merged;
      std::set_union(e.fired.begin(), e.fired.end(), s.fired.begin(), s.fired.end(),
                     std::back_inserter(merged));
      e.fired = std::move(merged);
    }
  }

  void anomaly(const semantics::Anomaly& a) override { anomalies.push_back(a); }
  void returning(const semantics::Successor& s) override {
    merge(crossed, s.entered);
    merge(returned, s.fired);
  }

  /// Inside one state's enumeration (the semantics calls it every few thousand valuations): the
  /// valuation bound, and the deadline, which successor() reads only once the state is done.
  void valuations(std::uint64_t count, std::uint64_t held_bytes) override {
    if (limits_.max_valuations > 0 && count > limits_.max_valuations)
      throw StopExploring{"valuations"};
    check_limits(held_bytes);
  }

  /// The time and memory limits, `more_bytes` about to be held besides the graph: throws
  /// StopExploring past one.
  void check_limits(std::uint64_t more_bytes) const {
    if ((limits_.timeout_seconds > 0 &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() >
             limits_.timeout_seconds) ||
        (limits_.deadline && std::chrono::steady_clock::now() > *limits_.deadline) ||
        (limits_.cancel && limits_.cancel->load(std::memory_order_relaxed)))
      throw StopExploring{"time"};
    if (over_memory(more_bytes)) throw StopExploring{"memory"};
  }

  std::vector<PendingEdge> pending;
  std::vector<semantics::Anomaly> anomalies;
  /// The state's evolutions: the steps they crossed (Successor::entered), and the transitions
  /// cleared by those back to the state itself; unions, sorted.
  std::vector<std::uint32_t> crossed, returned;
  std::uint64_t pending_bytes() const { return pending_bytes_; }

 private:
  /// The graph, the states stored since begin(), the edges pending and what the semantics holds
  /// for this state (`held_bytes`) against --memory.
  bool over_memory(std::uint64_t held_bytes) const {
    return limits_.max_memory_bytes > 0 &&
           graph_bytes_ + store_.memory_bytes() + pending_bytes_ + held_bytes >
               limits_.max_memory_bytes;
  }

  StateStore& store_;
  const ExplorationOptions& limits_;
  std::chrono::steady_clock::time_point start_;
  std::uint64_t work_ = 0, next_poll_ = 1024;
  std::uint64_t pending_bytes_ = 0, graph_bytes_ = 0;
  std::vector<std::uint32_t> stamp_, slot_;
  std::uint32_t generation_ = 0;
};

}  // namespace

ReachableSituationGraph::ReachableSituationGraph(const semantics::TransitionSystem& ts)
    : ts_(&ts),
      states_(ts.layout().words()),
      fired_somewhere_(ts.transitions().size(), false),
      fired_initially_(ts.transitions().size(), false) {}

std::uint32_t ReachableSituationGraph::intern_condition(InputCondition c) {
  if (2 * (conditions_.size() + 1) > condition_table_.size()) {
    std::vector<std::uint32_t> table(std::max<std::size_t>(1024, 2 * condition_table_.size()), 0);
    const std::size_t mask = table.size() - 1;
    for (std::uint32_t id = 0; id < conditions_.size(); ++id) {
      std::size_t i = condition_hashes_[id] & mask;
      while (table[i] != 0) i = (i + 1) & mask;
      table[i] = id + 1;
    }
    condition_table_ = std::move(table);
  }
  const std::uint64_t h = hash_condition(c);
  const std::size_t mask = condition_table_.size() - 1;
  std::size_t i = h & mask;
  for (; condition_table_[i] != 0; i = (i + 1) & mask) {
    const auto id = condition_table_[i] - 1;
    if (condition_hashes_[id] == h && conditions_[id].cubes == c.cubes) return id;
  }
  condition_bytes_ += c.memory_bytes();
  conditions_.push_back(std::move(c));
  condition_hashes_.push_back(h);
  const auto id = static_cast<std::uint32_t>(conditions_.size() - 1);
  condition_table_[i] = id + 1;
  return id;
}

const InputCondition& ReachableSituationGraph::condition(std::uint64_t edge) const {
  static const InputCondition unknown;
  if (edge >= edge_condition_ids_.size()) return unknown;
  return conditions_[edge_condition_ids_[edge]];
}

std::span<const std::uint32_t> ReachableSituationGraph::fired(std::uint64_t edge) const {
  if (edge + 1 >= fired_offsets_.size()) return {};
  return {fired_.data() + fired_offsets_[edge], fired_offsets_[edge + 1] - fired_offsets_[edge]};
}

std::uint32_t ReachableSituationGraph::source(std::uint64_t edge) const {
  const auto it = std::upper_bound(offsets_.begin(), offsets_.end(), edge);
  return static_cast<std::uint32_t>(it - offsets_.begin() - 1);
}

std::vector<std::uint64_t> ReachableSituationGraph::shortest_path_edges(std::uint32_t s) const {
  std::vector<std::uint64_t> path;
  while (parent_edge_state_[s] != kNone) {
    path.push_back(parent_edge_[s]);
    s = parent_edge_state_[s];
  }
  std::reverse(path.begin(), path.end());
  return path;
}

std::uint32_t ReachableSituationGraph::path_initial(std::uint32_t s) const {
  while (parent_edge_state_[s] != kNone) s = parent_edge_state_[s];
  return s;
}

const std::vector<std::uint64_t>& ReachableSituationGraph::predecessor_offsets() const {
  if (pred_offsets_.empty()) {
    const std::uint32_t n = num_states();
    pred_offsets_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (auto t : targets_) ++pred_offsets_[t + 1];
    for (std::uint32_t i = 0; i < n; ++i) pred_offsets_[i + 1] += pred_offsets_[i];
    pred_edges_.resize(targets_.size());
    std::vector<std::uint64_t> fill(pred_offsets_.begin(), pred_offsets_.end() - 1);
    for (std::uint64_t e = 0; e < targets_.size(); ++e) pred_edges_[fill[targets_[e]]++] = e;
  }
  return pred_offsets_;
}

const std::vector<std::uint64_t>& ReachableSituationGraph::predecessor_edges() const {
  predecessor_offsets();
  return pred_edges_;
}

std::size_t ReachableSituationGraph::memory_bytes() const {
  return states_.memory_bytes() + targets_.capacity() * 4 + offsets_.capacity() * 8 +
         edge_condition_ids_.capacity() * 4 + fired_offsets_.capacity() * 8 +
         fired_.capacity() * 4 + parent_edge_.capacity() * 8 + parent_edge_state_.capacity() * 4 +
         depth_.capacity() * 4 + condition_table_.capacity() * 4 +
         condition_hashes_.capacity() * 8 + conditions_.capacity() * sizeof(InputCondition) +
         condition_bytes_ +
         (crossing_states_.capacity() + crossed_.capacity() + returning_states_.capacity() +
          returning_fired_.capacity()) *
             4 +
         (crossed_offsets_.capacity() + returning_offsets_.capacity()) * 8;
}

ReachableSituationGraph build_reachable_situation_graph(const semantics::TransitionSystem& ts,
                                                        const ExplorationOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  ReachableSituationGraph g(ts);
  auto elapsed = [&start] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  // Initial states: merge the conditions of duplicates.
  {
    Collector init(g.states_, options, start);
    init.begin(0);
    try {
      ts.initial_states(init);
    } catch (const StopExploring& stop) {
      g.limit_ = stop.which;
    } catch (const LimitReached& stop) {
      if (stop.which() == Limit::Enumeration) throw;  // the caller says which input
      g.limit_ = to_string(stop.which());
    }
    for (auto& a : init.anomalies) g.anomalies_.push_back(std::move(a));
    g.entered_initially_ = std::move(init.crossed);
    for (auto& p : init.pending) {
      for (auto t : p.fired) g.fired_initially_[t] = true;
      g.initial_.push_back(p.target);
      g.initial_condition_ids_.push_back(g.intern_condition(std::move(p.condition).take()));
    }
    const auto n = g.states_.size();
    g.parent_edge_state_.assign(n, ReachableSituationGraph::kNone);
    g.parent_edge_.assign(n, 0);
    g.depth_.assign(n, 0);
  }

  Collector collect(g.states_, options, start);
  std::vector<semantics::StateWord> current;
  ExplorationProgress progress;
  std::uint64_t next_report = options.progress_interval;
  g.complete_ = g.limit_.empty();
  const std::uint32_t poll_mask = clock_poll_mask(ts.layout().words());
  const auto expand_start = Clock::now();
  for (std::uint32_t s = 0; g.complete_ && s < g.states_.size(); ++s) {
    if (options.forecast && options.deadline && (s & 15U) == 0 &&
        exploration_cannot_finish(
            s, g.states_.size(), std::chrono::duration<double>(Clock::now() - expand_start).count(),
            std::chrono::duration<double>(*options.deadline - Clock::now()).count())) {
      g.limit_ = "time";
      g.complete_ = false;
      break;
    }
    if ((s & poll_mask) == 0) {
      if ((options.timeout_seconds > 0 && elapsed() > options.timeout_seconds) ||
          (options.deadline && Clock::now() > *options.deadline) ||
          (options.cancel && options.cancel->load(std::memory_order_relaxed))) {
        g.limit_ = "time";
      } else if (options.max_memory_bytes > 0 && g.memory_bytes() > options.max_memory_bytes) {
        g.limit_ = "memory";
      }
      if (!g.limit_.empty()) {
        g.complete_ = false;
        break;
      }
    }
    if (options.max_states > 0 && g.states_.size() > options.max_states) {
      g.limit_ = "states";
      g.complete_ = false;
      break;
    }

    const std::uint32_t known = g.states_.size();
    collect.begin(g.memory_bytes() - g.states_.memory_bytes());
    // The sink inserts into the store, which may reallocate: the system must read a copy.
    const auto view = g.states_.at(s);
    current.assign(view.begin(), view.end());
    try {
      ts.successors(current, collect);
      // The last successors of a wide state may have taken long to merge: read the clock again
      // before they are stored.
      if (collect.pending_bytes() > (1U << 20)) collect.check_limits(0);
    } catch (const StopExploring& stop) {
      // State s stays unexpanded: the edges found so far are dropped with it.
      g.limit_ = stop.which;
      g.complete_ = false;
      break;
    } catch (const LimitReached& stop) {
      // The semantics' own poll of the deadline (a long transient evolution): the same.
      if (stop.which() == Limit::Enumeration) throw;
      g.limit_ = to_string(stop.which());
      g.complete_ = false;
      break;
    }
    // States numbered from `known` on were first reached from s: s is their BFS parent.
    g.parent_edge_state_.resize(g.states_.size(), ReachableSituationGraph::kNone);
    g.parent_edge_.resize(g.states_.size(), 0);
    g.depth_.resize(g.states_.size(), g.depth_[s] + 1);
    for (auto& a : collect.anomalies) g.anomalies_.push_back(std::move(a));
    collect.anomalies.clear();

    for (auto& p : collect.pending) {
      const std::uint64_t edge = g.targets_.size();
      g.targets_.push_back(p.target);
      if (options.keep_conditions)
        g.edge_condition_ids_.push_back(g.intern_condition(std::move(p.condition).take()));
      if (options.keep_fired) {
        g.fired_.insert(g.fired_.end(), p.fired.begin(), p.fired.end());
        g.fired_offsets_.push_back(g.fired_.size());
      }
      for (auto t : p.fired) g.fired_somewhere_[t] = true;
      if (p.target >= known) {
        g.parent_edge_state_[p.target] = s;
        g.parent_edge_[p.target] = edge;
      }
    }
    g.offsets_.push_back(g.targets_.size());
    if (!collect.crossed.empty()) {
      g.crossing_states_.push_back(s);
      g.crossed_.insert(g.crossed_.end(), collect.crossed.begin(), collect.crossed.end());
      g.crossed_offsets_.push_back(g.crossed_.size());
    }
    if (!collect.returned.empty()) {
      for (auto t : collect.returned) g.fired_somewhere_[t] = true;
      g.returning_states_.push_back(s);
      g.returning_fired_.insert(g.returning_fired_.end(), collect.returned.begin(),
                                collect.returned.end());
      g.returning_offsets_.push_back(g.returning_fired_.size());
    }

    progress.depth = g.depth_[s];
    if (options.progress && s + 1 >= next_report) {
      next_report += options.progress_interval;
      progress.states = g.states_.size();
      progress.edges = g.targets_.size();
      progress.seconds = elapsed();
      options.progress(progress);
    }
  }
  if (options.max_states > 0 && g.complete_ && g.states_.size() > options.max_states) {
    g.complete_ = false;
    g.limit_ = "states";
  }
  // States found but never expanded (frontier of a limit) still need parent entries.
  g.parent_edge_state_.resize(g.states_.size(), ReachableSituationGraph::kNone);
  g.parent_edge_.resize(g.states_.size(), 0);
  g.depth_.resize(g.states_.size(), 0);
  g.seconds_ = elapsed();
  return g;
}

}  // namespace sfcv::engine

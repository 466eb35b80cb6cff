#include "engine/bdd/symbolic_system.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "engine/bdd/grafcet_closure.hpp"
#include "engine/bdd/successor_simulator.hpp"
#include "engine/bdd/variable_order.hpp"
#include "engine/explicit/state_store.hpp"
#include "logic/circuit_atom.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;
using Bdd = bdd::Bdd;

namespace {

// Edges and images by simulation (count_edges_by_simulation, image_by_simulation): at most
// this many circuit inputs (4096 valuations a state), this much work (node words and
// successor bits, about a nanosecond each), and only on sets of at most this many states per
// BDD node.
constexpr std::size_t kMaxSimulatedInputs = 12;
constexpr std::uint64_t kSimulationWork = std::uint64_t{1} << 30;
constexpr std::uint64_t kSimulatedStatesPerNode = 8;
// Images by simulation, once the relation is built: only of sets of at least this many BDD
// nodes (image()).
constexpr int kMinSimulatedImageNodes = 256;
// Before the relation is built, at most this many images of smaller sets are simulated, for at
// most this much work in all (about 4 ms): a random chart's dozen rings then never need the
// relation (`random 60 --seed 2`: 7 ms of 60), a counter's thousands of rings of one state
// and a chart of 12 inputs (4096 valuations a state) do.
constexpr std::uint32_t kSmallImagesBeforeRelation = 64;
constexpr std::uint64_t kSmallWorkBeforeRelation = std::uint64_t{1} << 22;
// step() keeps at most this many reached states as keys (16 bytes or more each).
constexpr std::uint32_t kMaxReachedKeys = std::uint32_t{1} << 24;
// Simulations of many states read the clock (--timeout) after this many states.
constexpr std::uint32_t kStatesBetweenPolls = 256;
// Pre-images on the graph of the reached states: at most this many edges (4 bytes each).
constexpr std::size_t kMaxReachedGraphEdges = std::size_t{1} << 26;
// An image by simulation holds every distinct successor of the set (up to a word per 8 latch
// bits each): a quarter of the work bound keeps that under 64 MB.
constexpr std::uint64_t kSimulatedImageWork = kSimulationWork / 4;

/// The cost of simulating one state of `aig` in node words and successor bits (about a
/// nanosecond each).
std::uint64_t simulation_work_per_state(const Aig& aig) {
  const std::uint64_t valuations = std::uint64_t{1} << aig.inputs().size();
  return aig.nodes().size() * ((valuations + 63) / 64) + valuations * aig.latches().size();
}

// The node table a circuit starts with when the options leave it at 0: a few dozen BDD nodes
// per circuit node (the relation's conjuncts and the first rings fit without a resize),
// between 16 K and 1 M nodes.
bdd::ManagerOptions manager_options(const SymbolicOptions& o, const Aig& aig) {
  bdd::ManagerOptions m;
  m.nodes =
      o.nodes > 0
          ? o.nodes
          : static_cast<int>(std::clamp<std::size_t>(aig.nodes().size() * 32, 1 << 14, 1 << 20));
  m.cache = o.cache > 0 ? o.cache : std::max(1, m.nodes / 4);
  m.cache_ratio = 4;
  m.max_nodes = o.max_nodes;
  return m;
}

// Dynamic: the first pass when a collection leaves `first_pass_nodes` live nodes (or, for an
// IEC 61131-3 system once built, when an image blows up); then BuDDy sifts on its own whenever
// the live nodes have doubled.
void start_reordering(ReorderMode mode, int first_pass_nodes) {
  bdd::set_automatic_reordering(mode == ReorderMode::Dynamic ? kMaxAutomaticReorderings : 0,
                                kMinReorderGainPercent, first_pass_nodes);
}

int first_pass_nodes(const SymbolicOptions& o) {
  return o.nodes > 0 ? o.nodes : kFirstReorderNodes;
}

// An image whose intermediate products dwarf its operand and result: the static order fits
// the relation badly (parallel 32 --selector: 43 000 nodes between a 329-node frontier and a
// 1 743-node ring; random charts stay within 5 times).
void start_reordering_on_blowup(int peak, const Bdd& operand, const Bdd& result) {
  if (peak < kBlowupNodes) return;
  const int ends = std::max(operand.node_count(), result.node_count());
  if (peak >= kBlowupRatio * static_cast<std::int64_t>(ends)) bdd::start_automatic_reordering();
}

/// Runs `build` (the system's BDDs, its transition relation) by `share_end` when one is set:
/// past it, LimitReached(Time) saying that the BDD engine gave up its share of the race.
template <class Build>
decltype(auto) within_share(const std::optional<std::chrono::steady_clock::time_point>& share_end,
                            Build&& build) {
  if (!share_end) return build();
  const bdd::EarlierDeadlineScope scope(*share_end);
  try {
    return build();
  } catch (const LimitReached& e) {
    if (e.which() != Limit::Time || std::chrono::steady_clock::now() < *share_end) throw;
    throw LimitReached(Limit::Time,
                       "the transition relation was not built in the bdd engine's share of the "
                       "time; the bdd engine stopped, leaving the cores to ic3 and bmc");
  }
}

}  // namespace

struct SymbolicSystem::ReachedKeys {
  ReachedKeys(const semantics::TransitionCircuit& circuit, std::vector<std::uint32_t> ranks)
      : rank_of(ranks), sim(circuit, std::move(ranks)), store(sim.latch_words()) {}
  std::vector<std::uint32_t> rank_of;  ///< each latch's key bit (latch_ranks() when made)
  SuccessorSimulator sim;
  StateStore store;  ///< every reached state's key, in ring order: the frontier's are last
  std::uint32_t frontier_first = 0;
  Bdd reached, frontier;  ///< the sets the keys are
  // After exploration (preimage_on_reached_graph): the stored successors of state i are
  // successors[first_successor[i] .. first_successor[i + 1]).
  std::vector<std::uint64_t> first_successor;
  std::vector<std::uint32_t> successors;
  bool closed = false;  ///< every successor of a stored state is stored
  // The same edges reversed (reach_on_reached_graph, built on first use).
  std::vector<std::uint64_t> first_predecessor;
  std::vector<std::uint32_t> predecessors;
  /// The key of a state of latch values `x`.
  void key_of(const std::vector<bool>& x, std::vector<StateWord>& key) const {
    std::fill(key.begin(), key.end(), 0);
    for (std::size_t l = 0; l < x.size(); ++l)
      if (x[l]) set_key_bit(key.data(), rank_of[l]);
  }
  /// The latch values of the state of a key.
  void latches_of(const StateWord* key, std::vector<bool>& x) const {
    for (std::size_t l = 0; l < x.size(); ++l) x[l] = key_bit(key, rank_of[l]);
  }
};

SymbolicSystem::SymbolicSystem(const semantics::TransitionSystem& ts,
                               semantics::TransitionCircuit circuit, const SymbolicOptions& options)
    : ts_(ts), circuit_(std::move(circuit)) {
  bdd::start_manager(manager_options(options, circuit_.aig));
  bdd::reset_operation_caches();
  const Aig& aig = circuit_.aig;
  const std::size_t num_latches = aig.latches().size(), num_inputs = aig.inputs().size();
  const std::vector<std::uint32_t> best_order = force_order(aig);
  input_var_.assign(num_inputs, -1);
  current_var_.assign(num_latches, -1);
  next_var_.assign(num_latches, -1);
  int var = 0;
  for (auto u : best_order) {
    if (u < num_latches) {
      current_var_[u] = var++;
      next_var_[u] = var++;
    } else {
      input_var_[u - num_latches] = var++;
    }
  }
  bdd::ensure_variables(var);
  if (options.reorder != ReorderMode::None) {
    // Blocks before any reordering: a current/next pair moves as one, inputs alone.
    for (std::size_t l = 0; l < num_latches; ++l)
      bdd::add_variable_block(current_var_[l], next_var_[l]);
    for (int v : input_var_) bdd::add_variable_block(v, v);
    start_reordering(options.reorder, first_pass_nodes(options));
  }
  current_vars_ = current_var_;
  memo_.resize(aig.nodes().size());
  memo_set_.assign(aig.nodes().size(), false);
  current_cube_ = Bdd::cube(current_var_);
  next_cube_ = Bdd::cube(next_var_);
  input_cube_ = Bdd::cube(input_var_);

  initial_ = Bdd::constant(true);
  for (std::size_t l = 0; l < aig.latches().size(); ++l) {
    const Bdd v = Bdd::variable(current_var_[l]);
    initial_ = initial_ & (aig.latches()[l].initial ? v : !v);
  }
  ok_ = node_bdd(circuit_.allowed) & !node_bdd(circuit_.range_error);
  has_successor_ = ok_.exist(input_cube_);
  range_error_states_ =
      (node_bdd(circuit_.allowed) & node_bdd(circuit_.range_error)).exist(input_cube_);
  loop_limit_states_ = circuit_.loop_limit == Aig::kFalse
                           ? Bdd::constant(false)
                           : node_bdd(circuit_.loop_limit).exist(input_cube_);

  next_to_current_ = std::make_unique<bdd::VarMap>();
  current_to_next_ = std::make_unique<bdd::VarMap>();
  for (std::size_t l = 0; l < aig.latches().size(); ++l) {
    next_to_current_->rename(next_var_[l], current_var_[l]);
    current_to_next_->rename(current_var_[l], next_var_[l]);
  }
  fires_.resize(circuit_.fired.size());
  fires_set_.assign(circuit_.fired.size(), false);
  cluster_nodes_ = options.cluster_nodes;
  relation_deadline_ = options.relation_deadline;
  max_simulation_bytes_ = options.max_circuit_bytes / 4;
  // Automatic reordering waits for a full table; sift once for the relation, built now.
  if (options.reorder == ReorderMode::Once) {
    relation();
    bdd::reorder_now();
  }
  // Dynamic, from here on: when an image blows up (image(), preimage()). An explicit initial
  // table keeps BuDDy's rule (tests make small charts sift with it).
  if (options.reorder == ReorderMode::Dynamic && options.nodes == 0)
    bdd::delay_automatic_reordering(kLateReorderNodes);
}

SymbolicSystem::SymbolicSystem(const semantics::TransitionSystem& ts,
                               semantics::GrafcetCircuit circuit, const SymbolicOptions& options)
    : ts_(ts), circuit_(circuit) {
  bdd::start_manager(manager_options(options, circuit_.aig));
  bdd::reset_operation_caches();
  grafcet_circuit_ = std::make_unique<semantics::GrafcetCircuit>(std::move(circuit));
  const semantics::GrafcetCircuit& gc = *grafcet_circuit_;
  const Aig& aig = circuit_.aig;
  const std::size_t num_latches = aig.latches().size(), num_inputs = aig.inputs().size();
  const std::size_t num_state = gc.num_state_latches;
  // The FORCE order also ties each state latch to what its first value reads (an input memory
  // to its input, a delay phase to its elapse).
  std::vector<std::vector<std::uint32_t>> ties;
  {
    std::vector<bool> seen(aig.nodes().size());
    for (std::size_t l = 0; l < num_state; ++l) {
      std::fill(seen.begin(), seen.end(), false);
      std::vector<std::uint32_t> ins, lats;
      aig_support(aig, gc.start_next[l], seen, ins, lats);
      std::vector<std::uint32_t> tie{static_cast<std::uint32_t>(l)};
      for (auto x : lats)
        if (x != l) tie.push_back(x);
      for (auto i : ins) tie.push_back(static_cast<std::uint32_t>(num_latches + i));
      if (tie.size() > 1) ties.push_back(std::move(tie));
    }
  }
  const std::vector<std::uint32_t> order = force_order(aig, ties);
  GrafcetVariables v;
  v.c.assign(num_state, -1);
  v.n.assign(num_state, -1);
  v.m.assign(num_state, -1);
  v.q.assign(num_latches - num_state, -1);
  v.qp.assign(num_latches - num_state, -1);
  v.in.assign(num_inputs, -1);
  int var = 0;
  for (auto u : order) {
    if (u < num_state) {
      v.c[u] = var++;
      v.n[u] = var++;
      v.m[u] = var++;
    } else if (u < num_latches) {
      v.q[u - num_state] = var++;
      v.qp[u - num_state] = var++;
    } else {
      v.in[u - num_latches] = var++;
    }
  }
  bdd::ensure_variables(var);
  if (options.reorder != ReorderMode::None) {
    // Blocks before any reordering: a state latch's current, next and transient copies move as
    // one (they are consecutive), an output's pair too, inputs alone.
    for (std::size_t l = 0; l < num_state; ++l) bdd::add_variable_block(v.c[l], v.m[l]);
    for (std::size_t q = 0; q < v.q.size(); ++q) bdd::add_variable_block(v.q[q], v.qp[q]);
    for (int x : v.in) bdd::add_variable_block(x, x);
    start_reordering(options.reorder, first_pass_nodes(options));
  }
  input_var_ = v.in;
  current_var_ = v.c;
  next_var_ = v.n;
  current_var_.insert(current_var_.end(), v.q.begin(), v.q.end());
  next_var_.insert(next_var_.end(), v.qp.begin(), v.qp.end());
  current_vars_ = v.c;
  memo_.resize(aig.nodes().size());
  memo_set_.assign(aig.nodes().size(), false);
  current_cube_ = Bdd::cube(v.c);
  next_cube_ = Bdd::cube(v.n);
  input_cube_ = Bdd::cube(v.in);
  grafcet_ = std::make_unique<GrafcetClosure>(
      gc, std::move(v), [this](AigLit lit) { return node_bdd(lit); }, options.cluster_nodes,
      options.timeout_seconds);
  initial_ = grafcet_->initial();
  fires_.resize(circuit_.fired.size());
  fires_set_.assign(circuit_.fired.size(), false);
  if (options.reorder == ReorderMode::Once) bdd::reorder_now();
}

const SymbolicSystem::Relation& SymbolicSystem::relation() const {
  if (relation_) return *relation_;
  return within_share(relation_deadline_, [this]() -> const Relation& { return build_relation(); });
}

const SymbolicSystem::Relation& SymbolicSystem::build_relation() const {
  const Aig& aig = circuit_.aig;
  const std::size_t num_latches = aig.latches().size(), num_inputs = aig.inputs().size();
  auto built = std::make_unique<Relation>();
  Relation& r = *built;
  // Partitioned relation: one conjunct next_l <-> f_l per latch, clustered greedily in
  // variable order while small; then each current/input variable is quantified right after the last
  // cluster that mentions it.
  std::vector<Bdd> parts;
  std::vector<std::vector<bool>> part_support;
  std::vector<std::vector<int>> part_next_vars;  // next variables defined by each cluster
  const std::size_t num_vars = 2 * num_latches + num_inputs;
  {
    std::vector<bool> seen(aig.nodes().size());
    Bdd cluster = ok_;
    std::vector<bool> cluster_support(num_vars, false);
    std::vector<int> cluster_next;
    auto add_support = [&](AigLit lit, std::vector<bool>& into) {
      std::fill(seen.begin(), seen.end(), false);
      std::vector<std::uint32_t> ins, lats;
      aig_support(aig, lit, seen, ins, lats);
      for (auto i : ins) into[static_cast<std::size_t>(input_var_[i])] = true;
      for (auto l : lats) into[static_cast<std::size_t>(current_var_[l])] = true;
    };
    add_support(circuit_.allowed, cluster_support);
    add_support(circuit_.range_error, cluster_support);
    // Conjuncts in the variable order (measured against latch order: random 60 seed 1 from
    // 0.62 to 0.37 s, counter 16 from 0.70 to 0.45 s): a cluster then covers adjacent levels,
    // and a current bit is quantified once the clusters around its level are in.
    std::vector<std::size_t> latch_order(num_latches);
    for (std::size_t l = 0; l < num_latches; ++l) latch_order[l] = l;
    std::sort(latch_order.begin(), latch_order.end(),
              [&](auto a, auto b) { return current_var_[a] < current_var_[b]; });
    for (const std::size_t l : latch_order) {
      const Bdd conjunct = Bdd::variable(next_var_[l]).iff(node_bdd(aig.latches()[l].next));
      // A conjunct already past the bound starts a cluster of its own without trying the
      // product (xPPU scenario 2: 17.9 s for one product of 148,897 nodes that was dropped).
      const bool alone = static_cast<int>(conjunct.node_count()) > cluster_nodes_;
      const Bdd merged = alone ? conjunct : cluster & conjunct;
      if ((alone || merged.node_count() > cluster_nodes_) && !cluster.is_true()) {
        parts.push_back(cluster);
        part_support.push_back(cluster_support);
        part_next_vars.push_back(cluster_next);
        cluster = conjunct;
        cluster_support.assign(num_vars, false);
        cluster_next.clear();
      } else {
        cluster = merged;
      }
      cluster_next.push_back(next_var_[l]);
      add_support(aig.latches()[l].next, cluster_support);
    }
    parts.push_back(cluster);
    part_support.push_back(cluster_support);
    part_next_vars.push_back(cluster_next);
  }
  std::vector<int> last(num_vars, -1);
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (std::size_t v = 0; v < num_vars; ++v)
      if (part_support[k][v]) last[v] = static_cast<int>(k);
  std::vector<std::vector<int>> after(parts.size());
  std::vector<int> first;
  auto quantified = [&](int v) {
    return std::find(input_var_.begin(), input_var_.end(), v) != input_var_.end() ||
           std::find(current_var_.begin(), current_var_.end(), v) != current_var_.end();
  };
  for (std::size_t v = 0; v < num_vars; ++v) {
    if (!quantified(static_cast<int>(v))) continue;
    if (last[v] < 0)
      first.push_back(static_cast<int>(v));
    else
      after[static_cast<std::size_t>(last[v])].push_back(static_cast<int>(v));
  }
  // Pre-image: the next variables of a cluster and the inputs it is the last to read.
  std::vector<int> input_last(num_inputs, -1);
  for (std::size_t i = 0; i < num_inputs; ++i)
    input_last[i] = last[static_cast<std::size_t>(input_var_[i])];
  for (std::size_t k = 0; k < parts.size(); ++k) {
    std::vector<int> vs = part_next_vars[k];
    for (std::size_t i = 0; i < num_inputs; ++i)
      if (input_last[i] == static_cast<int>(k)) vs.push_back(input_var_[i]);
    r.pre_quantify_after.push_back(Bdd::cube(vs));
  }
  {
    std::vector<int> unused_inputs;
    for (std::size_t i = 0; i < num_inputs; ++i)
      if (input_last[i] < 0) unused_inputs.push_back(input_var_[i]);
    r.pre_quantify_first = Bdd::cube(unused_inputs);
    r.inputs_first = r.pre_quantify_first;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      std::vector<int> vs;
      for (std::size_t i = 0; i < num_inputs; ++i)
        if (input_last[i] == static_cast<int>(k)) vs.push_back(input_var_[i]);
      r.inputs_after.push_back(Bdd::cube(vs));
    }
  }
  r.clusters = std::move(parts);
  for (auto& vs : after) r.quantify_after.push_back(Bdd::cube(vs));
  r.quantify_first = Bdd::cube(first);

  relation_ = std::move(built);
  return *relation_;
}

SymbolicSystem::~SymbolicSystem() = default;

const Bdd& SymbolicSystem::has_successor() const {
  if (!grafcet_) return has_successor_;
  grafcet_has_successor_ = grafcet_->has_successor();
  return grafcet_has_successor_;
}

const Bdd& SymbolicSystem::range_error_states() const {
  if (!grafcet_) return range_error_states_;
  grafcet_range_error_ = grafcet_->range_error_states();
  return grafcet_range_error_;
}

Bdd SymbolicSystem::unstable_states() const {
  return grafcet_ ? grafcet_->unstable_states() : Bdd::constant(false);
}

bool SymbolicSystem::fires_initially(std::uint32_t transition) const {
  return grafcet_ && grafcet_->fires_initially(transition);
}

bool SymbolicSystem::initial_unstable() const {
  return grafcet_ && grafcet_->initial_anomaly() && !grafcet_->initial_range_error();
}

void SymbolicSystem::restrict_sources(const Bdd& states) {
  if (grafcet_)
    grafcet_->set_sources(states);
  else
    preimage_care_ = states;
}

bool SymbolicSystem::initial_range_error() const {
  return grafcet_ && grafcet_->initial_range_error();
}

std::vector<bool> SymbolicSystem::latches_of(semantics::StateView state) const {
  const auto& layout = ts_.layout();
  std::vector<bool> latches(circuit_.aig.latches().size());
  for (std::uint32_t f = 0; f < circuit_.field_latches.size(); ++f) {
    const auto v = static_cast<std::uint64_t>(layout.get(state, f) - layout.fields()[f].lo);
    for (std::size_t b = 0; b < circuit_.field_latches[f].size(); ++b)
      latches[circuit_.field_latches[f][b]] = ((v >> b) & 1U) != 0;
  }
  return latches;
}

std::vector<std::uint32_t> SymbolicSystem::fired_between(semantics::StateView from,
                                                         const std::vector<bool>& inputs) const {
  const Aig& aig = circuit_.aig;
  const std::vector<bool> latches = latches_of(from);
  std::vector<bool> on(circuit_.fired.size(), false);
  auto collect = [&](const std::vector<bool>& nodes) {
    for (std::size_t t = 0; t < circuit_.fired.size(); ++t)
      if (Aig::value_of(nodes, circuit_.fired[t])) on[t] = true;
  };
  if (!grafcet_) {
    collect(aig.evaluate(inputs, latches));
  } else {
    // Run the evolutions concretely: the first situation, then micro-steps until stable.
    const auto& gc = *grafcet_circuit_;
    const std::size_t n = gc.num_state_latches;
    std::vector<bool> nodes = aig.evaluate(inputs, latches);
    std::vector<bool> x(latches.size());
    for (std::size_t l = 0; l < n; ++l) x[l] = Aig::value_of(nodes, gc.start_next[l]);
    for (std::size_t p = 0; p < gc.prev_of.size(); ++p) x[n + p] = latches[gc.prev_of[p]];
    for (std::size_t k = 0; k <= gc.max_transient_steps; ++k) {
      nodes = aig.evaluate(inputs, x);
      if (Aig::value_of(nodes, gc.range_error)) break;
      collect(nodes);
      if (Aig::value_of(nodes, gc.stable)) break;
      std::vector<bool> y(x.size());
      for (std::size_t l = 0; l < n; ++l) y[l] = Aig::value_of(nodes, aig.latches()[l].next);
      for (std::size_t p = 0; p < gc.prev_of.size(); ++p) y[n + p] = x[gc.prev_of[p]];
      x = std::move(y);
    }
  }
  std::vector<std::uint32_t> fired;
  for (std::uint32_t t = 0; t < on.size(); ++t)
    if (on[t]) fired.push_back(t);
  return fired;
}

Bdd SymbolicSystem::node_bdd(AigLit lit) const {
  const Aig& aig = circuit_.aig;
  const auto root = Aig::node_of(lit);
  if (!memo_set_[root]) {
    // Iterative post-order: deep circuits would overflow a recursive walk.
    std::vector<std::uint32_t> stack{root};
    while (!stack.empty()) {
      const auto n = stack.back();
      if (memo_set_[n]) {
        stack.pop_back();
        continue;
      }
      const auto& node = aig.nodes()[n];
      switch (node.kind) {
        case Aig::NodeKind::Constant:
          memo_[n] = Bdd::constant(false);
          break;
        case Aig::NodeKind::Input:
          memo_[n] = Bdd::variable(input_var_[node.index]);
          break;
        case Aig::NodeKind::Latch:
          memo_[n] = Bdd::variable(current_var_[node.index]);
          break;
        case Aig::NodeKind::And: {
          const auto l = Aig::node_of(node.left), r = Aig::node_of(node.right);
          if (!memo_set_[l] || !memo_set_[r]) {
            if (!memo_set_[l]) stack.push_back(l);
            if (!memo_set_[r]) stack.push_back(r);
            continue;
          }
          const Bdd a = Aig::is_negated(node.left) ? !memo_[l] : memo_[l];
          const Bdd b = Aig::is_negated(node.right) ? !memo_[r] : memo_[r];
          memo_[n] = a & b;
          break;
        }
      }
      memo_set_[n] = true;
      stack.pop_back();
    }
  }
  return Aig::is_negated(lit) ? !memo_[root] : memo_[root];
}

std::optional<SymbolicSystem::SimulatedSet> SymbolicSystem::simulation_of(
    const Bdd& from, std::uint64_t max_work, bool near_explicit_only) const {
  if (grafcet_ || from.is_false() || circuit_.aig.inputs().size() > kMaxSimulatedInputs)
    return std::nullopt;
  SimulatedSet set;
  const auto states = from.sat_count_u64(current_vars_, &set.nodes);
  if (!states) return std::nullopt;
  set.states = *states;
  if (!may_simulate(set, max_work, near_explicit_only)) return std::nullopt;
  return set;
}

bool SymbolicSystem::may_simulate(const SimulatedSet& set, std::uint64_t max_work,
                                  bool near_explicit_only) const {
  const Aig& aig = circuit_.aig;
  if (grafcet_ || aig.inputs().size() > kMaxSimulatedInputs) return false;
  if (near_explicit_only &&
      set.states > kSimulatedStatesPerNode * static_cast<std::uint64_t>(std::max(1, set.nodes)))
    return false;
  if (set.states > max_work / std::max<std::uint64_t>(simulation_work_per_state(aig), 1))
    return false;
  // Under --memory, the successors a simulation holds (at most one key per state and input
  // valuation) stay within a quarter of it, as BuDDy's table does within the rest.
  const std::uint64_t key_bytes = 8 * ((aig.latches().size() + 63) / 64);
  return max_simulation_bytes_ == 0 ||
         set.states <= max_simulation_bytes_ / (key_bytes << aig.inputs().size());
}

bool SymbolicSystem::simulates(const Bdd& from, std::uint64_t max_work,
                               bool near_explicit_only) const {
  return simulation_of(from, max_work, near_explicit_only).has_value();
}

bool SymbolicSystem::simulates_small_sets() const {
  return !relation_ && small_images_simulated_ < kSmallImagesBeforeRelation &&
         small_work_simulated_ < kSmallWorkBeforeRelation;
}

bool SymbolicSystem::chooses_simulation(const SimulatedSet& set) const {
  // A set of many nodes is simulated. A small set's image on the relation costs microseconds,
  // less than setting up a simulation (`counter 16`, 131 069 rings of one state: 0.28 s on
  // the relation, 0.95 s simulated), but the relation must be built first, which costs more
  // than a small chart's whole exploration: before it exists, a few cheap small sets are
  // simulated too.
  if (set.nodes >= kMinSimulatedImageNodes) return true;
  const std::uint64_t work = set.states * simulation_work_per_state(circuit_.aig);
  if (!simulates_small_sets() || small_work_simulated_ + work > kSmallWorkBeforeRelation)
    return false;
  ++small_images_simulated_;
  small_work_simulated_ += work;
  return true;
}

Bdd SymbolicSystem::image(const Bdd& states, ImageMethod how,
                          std::optional<std::uint64_t>* edges) const {
  if (edges) edges->reset();
  SimulationTally tally;
  if (how == ImageMethod::Simulation) {
    if (states.is_false()) return states;
    std::optional<Bdd> result;
    if (simulates(states, ~std::uint64_t{0}, false)) result = image_by_simulation(states, tally);
    if (!result) throw std::logic_error("SymbolicSystem::image: the set cannot be simulated");
    if (edges) *edges = tally.edges;
    return *result;
  }
  if (states.is_false()) {
    if (edges) *edges = 0;
    return states;
  }
  if (how == ImageMethod::Auto && !grafcet_)
    if (auto on_graph = image_on_reached_graph(states, edges)) return *on_graph;
  // BuDDy counts a small set's nodes faster than simulation_of walks it (`counter 16`:
  // 131 069 rings of a few nodes).
  if (how == ImageMethod::Auto && !grafcet_ &&
      (simulates_small_sets() || states.node_count() >= kMinSimulatedImageNodes))
    if (const auto set = simulation_of(states, kSimulatedImageWork, true);
        set && chooses_simulation(*set))
      if (auto result = image_by_simulation(states, tally)) {
        if (edges) *edges = tally.edges;
        return *result;
      }
  return symbolic_image(states);
}

SymbolicSystem::Step SymbolicSystem::step(const Bdd& frontier, const Bdd& reached) const {
  if (auto simulated = simulated_step(frontier, reached)) return *std::move(simulated);
  reached_keys_.reset();  // the keys no longer follow the reached set
  Step s;
  s.ring = image(frontier, ImageMethod::Auto, &s.edges) & !reached;
  s.reached = reached | s.ring;
  return s;
}

std::optional<SymbolicSystem::Step> SymbolicSystem::simulated_step(const Bdd& frontier,
                                                                   const Bdd& reached) const {
  const std::size_t latches = current_var_.size();
  if (grafcet_ || latches == 0 || circuit_.aig.inputs().size() > kMaxSimulatedInputs ||
      frontier.is_false())
    return std::nullopt;
  // The keys start from the first ring, whose states are listed once; they are dropped for
  // good when a ring is not simulated, a reordering moves the levels or they grow too large.
  auto& keys = reached_keys_;
  if (keys && (keys->reached != reached || keys->frontier != frontier)) keys.reset();
  if (!keys && reached != frontier) return std::nullopt;
  std::vector<std::uint32_t> rank_of = latch_ranks(current_var_);
  if (keys && keys->rank_of != rank_of) {
    keys.reset();
    return std::nullopt;
  }
  // No bound on the work: the new successors go to the store at once, so a step holds no
  // more than the reached states, and a step of many states is exploration the relation
  // would do no faster (`random 60 --seed 2 --inputs 8`: rings of 20 000 states of 256
  // valuations each). A first ring is measured by simulation_of(), which checks the bounds.
  SimulatedSet set;
  if (keys) {
    set.states = keys->store.size() - keys->frontier_first;
    set.nodes = frontier.node_count();
    if (!may_simulate(set, ~std::uint64_t{0}, true)) return std::nullopt;
  } else if (const auto measured = simulation_of(frontier, ~std::uint64_t{0}, true)) {
    set = *measured;
  } else {
    return std::nullopt;
  }
  if (!chooses_simulation(set)) return std::nullopt;
  if (!keys) {
    keys = std::make_unique<ReachedKeys>(circuit_, rank_of);
    std::vector<StateWord> key(keys->sim.latch_words());
    const bool walked = frontier.for_each_assignment(current_var_, [&](const std::vector<bool>& x) {
      keys->key_of(x, key);
      keys->store.insert(key);
      return true;
    });
    if (!walked) {
      keys.reset();
      return std::nullopt;
    }
    keys->frontier_first = 0;
  }
  ReachedKeys& k = *keys;
  const std::uint32_t words = k.store.words_per_state();
  const std::uint32_t first = k.frontier_first, end = k.store.size();
  std::vector<bool> x(latches);
  Step s;
  std::uint64_t edges = 0;
  for (std::uint32_t i = first; i < end; ++i) {
    if ((i - first) % kStatesBetweenPolls == 0) {
      if (bdd::deadline_passed()) {
        keys.reset();  // half a step: the keys no longer are a reached set
        bdd::poll_deadline();
      }
      if (max_simulation_bytes_ > 0 && k.store.memory_bytes() > max_simulation_bytes_) {
        keys.reset();  // over --memory: the relation answers, or meets the limit
        return std::nullopt;
      }
    }
    // Decoded before the inserts below, which may move the store's array.
    k.latches_of(k.store.at(i).data(), x);
    const std::size_t count = k.sim.simulate(x);
    edges += count;
    for (std::size_t j = 0; j < count; ++j) k.store.insert(StateView(k.sim.successor(j), words));
  }
  const StateView added = k.store.range(end, k.store.size() - end);
  std::vector<std::uint64_t> ring_keys(added.begin(), added.end());
  const std::size_t count = sort_distinct_keys(ring_keys, words);
  s.ring = bdd_of_sorted_keys(ring_keys, count, words, var_at_rank(k.rank_of, current_var_));
  s.reached = reached | s.ring;
  s.edges = edges;
  k.reached = s.reached;
  k.frontier = s.ring;
  k.frontier_first = end;
  if (k.store.size() > kMaxReachedKeys ||
      (max_simulation_bytes_ > 0 && k.store.memory_bytes() > max_simulation_bytes_))
    keys.reset();
  return s;
}

SymbolicSystem::ReachedKeys* SymbolicSystem::reached_graph() const {
  auto& keys = reached_keys_;
  if (!keys || keys->reached != preimage_care_) return nullptr;
  ReachedKeys& k = *keys;
  if (!k.first_successor.empty()) return &k;
  // Each stored state's successors among the stored ones; the others lie outside the reached
  // set (exploration stopped early), where no pre-image looks and no image may be taken.
  const std::uint32_t n = k.store.size(), words = k.store.words_per_state();
  std::vector<bool> x(current_var_.size());
  k.first_successor.reserve(std::size_t{n} + 1);
  k.closed = true;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (i % kStatesBetweenPolls == 0 && bdd::deadline_passed()) {
      k.first_successor.clear();  // half a graph: built again on the next call
      k.successors.clear();
      bdd::poll_deadline();
    }
    k.first_successor.push_back(k.successors.size());
    k.latches_of(k.store.at(i).data(), x);
    const std::size_t count = k.sim.simulate(x);
    for (std::size_t j = 0; j < count; ++j) {
      const std::uint32_t target = k.store.find(StateView(k.sim.successor(j), words));
      if (target == StateStore::kAbsent)
        k.closed = false;
      else
        k.successors.push_back(target);
    }
    if (k.successors.size() > kMaxReachedGraphEdges ||
        (max_simulation_bytes_ > 0 &&
         k.store.memory_bytes() + 4 * k.successors.size() > max_simulation_bytes_)) {
      keys.reset();  // too large: images and pre-images on the relation
      return nullptr;
    }
  }
  k.first_successor.push_back(k.successors.size());
  return &k;
}

std::optional<std::vector<bool>> SymbolicSystem::reached_indices(const ReachedKeys& k,
                                                                 const Bdd& states) const {
  std::vector<bool> in(k.store.size(), false);
  std::vector<StateWord> key(k.store.words_per_state());
  const bool walked =
      (states & preimage_care_).for_each_assignment(current_var_, [&](const std::vector<bool>& x) {
        k.key_of(x, key);
        const std::uint32_t i = k.store.find(key);
        if (i != StateStore::kAbsent) in[i] = true;
        return i != StateStore::kAbsent;
      });
  if (!walked) return std::nullopt;
  return in;
}

Bdd SymbolicSystem::bdd_of_reached(const ReachedKeys& k, const std::vector<bool>& in) const {
  const std::uint32_t words = k.store.words_per_state();
  std::vector<std::uint64_t> keys;
  for (std::uint32_t i = 0; i < in.size(); ++i)
    if (in[i]) {
      const StateView key = k.store.at(i);
      keys.insert(keys.end(), key.begin(), key.end());
    }
  const std::size_t count = sort_distinct_keys(keys, words);
  return bdd_of_sorted_keys(keys, count, words, var_at_rank(k.rank_of, current_var_));
}

std::optional<Bdd> SymbolicSystem::preimage_on_reached_graph(const Bdd& states) const {
  const ReachedKeys* k = reached_graph();
  if (!k) return std::nullopt;
  const auto in = reached_indices(*k, states);
  if (!in) return std::nullopt;
  std::vector<bool> pre(in->size(), false);
  for (std::uint32_t i = 0; i < pre.size(); ++i)
    for (std::uint64_t e = k->first_successor[i]; e < k->first_successor[i + 1] && !pre[i]; ++e)
      pre[i] = (*in)[k->successors[e]];
  return bdd_of_reached(*k, pre);
}

std::optional<Bdd> SymbolicSystem::image_on_reached_graph(
    const Bdd& states, std::optional<std::uint64_t>* edges) const {
  const ReachedKeys* k = reached_graph();
  // Only within a closed reached set: every successor of its states is a stored one.
  if (!k || !k->closed || !(states & !preimage_care_).is_false()) return std::nullopt;
  const auto in = reached_indices(*k, states);
  if (!in) return std::nullopt;
  std::vector<bool> post(in->size(), false);
  std::uint64_t count = 0;
  for (std::uint32_t i = 0; i < post.size(); ++i)
    if ((*in)[i])
      for (std::uint64_t e = k->first_successor[i]; e < k->first_successor[i + 1]; ++e, ++count)
        post[k->successors[e]] = true;
  if (edges) *edges = count;
  return bdd_of_reached(*k, post);
}

std::optional<Bdd> SymbolicSystem::reach_on_reached_graph(const Bdd& seeds, const Bdd& through,
                                                          bool backward) const {
  ReachedKeys* k = reached_graph();
  if (!k || !k->closed) return std::nullopt;
  const std::uint32_t n = k->store.size();
  if (backward && k->first_predecessor.empty()) {
    std::vector<std::uint64_t> first(std::size_t{n} + 1, 0);
    for (const std::uint32_t target : k->successors) ++first[target + 1];
    for (std::uint32_t i = 0; i < n; ++i) first[i + 1] += first[i];
    std::vector<std::uint32_t> sources(k->successors.size());
    std::vector<std::uint64_t> next(first.begin(), first.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint64_t e = k->first_successor[i]; e < k->first_successor[i + 1]; ++e)
        sources[next[k->successors[e]]++] = i;
    k->first_predecessor = std::move(first);
    k->predecessors = std::move(sources);
  }
  auto reached = reached_indices(*k, seeds);
  if (!reached) return std::nullopt;
  std::optional<std::vector<bool>> allowed;
  if (!through.is_true()) {
    allowed = reached_indices(*k, through);
    if (!allowed) return std::nullopt;
  }
  const auto& first = backward ? k->first_predecessor : k->first_successor;
  const auto& edges = backward ? k->predecessors : k->successors;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t i = 0; i < n; ++i)
    if ((*reached)[i]) queue.push_back(i);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    if (head % (std::size_t{kStatesBetweenPolls} * 64) == 0) bdd::poll_deadline();
    const std::uint32_t v = queue[head];
    for (std::uint64_t e = first[v]; e < first[v + 1]; ++e) {
      const std::uint32_t u = edges[e];
      if ((*reached)[u] || (allowed && !(*allowed)[u])) continue;
      (*reached)[u] = true;
      queue.push_back(u);
    }
  }
  return bdd_of_reached(*k, *reached);
}

Bdd SymbolicSystem::symbolic_image(const Bdd& states) const {
  if (grafcet_) return grafcet_->image(states);
  const Relation& r = relation();
  Bdd acc = states.exist(r.quantify_first);
  const bool watch = bdd::automatic_reordering_waits();
  int peak = 0;
  for (std::size_t k = 0; k < r.clusters.size(); ++k) {
    acc = acc.and_exist(r.clusters[k], r.quantify_after[k]);
    if (watch) peak = std::max(peak, acc.node_count());
  }
  Bdd result = acc.replace(*next_to_current_);
  if (watch) start_reordering_on_blowup(peak, states, result);
  return result;
}

Bdd SymbolicSystem::preimage(const Bdd& states) const {
  if (grafcet_) return grafcet_->preimage(states);
  if (states.is_false()) return states;
  if (auto on_graph = preimage_on_reached_graph(states)) return *on_graph;
  // exists x', i. T(x, i, x') & S(x'), conjoining the clusters in order; ok_ (inputs allowed,
  // no range error) is part of the first cluster.
  const Relation& r = relation();
  Bdd acc = states.replace(*current_to_next_).exist(r.pre_quantify_first);
  const bool watch = bdd::automatic_reordering_waits();
  int peak = 0;
  for (std::size_t k = 0; k < r.clusters.size(); ++k) {
    acc = acc.and_exist(r.clusters[k], r.pre_quantify_after[k]);
    if (watch) peak = std::max(peak, acc.node_count());
  }
  Bdd result = acc & preimage_care_;
  if (watch) start_reordering_on_blowup(peak, states, result);
  return result;
}

std::vector<bool> SymbolicSystem::pick_inputs_near(Bdd on_inputs,
                                                   const std::vector<std::int64_t>& near) const {
  if (on_inputs.is_false()) return {};
  const auto& inputs = ts_.inputs();
  for (std::size_t i = 0; i < inputs.size() && i < circuit_.input_bits.size(); ++i) {
    const auto& t = inputs[i].type;
    const std::int64_t lo = t.kind == model::TypeKind::Bool ? 0 : t.lo;
    // A delay elapses only when the row says so: pseudo-inputs prefer their lowest value.
    const std::int64_t want = !inputs[i].pseudo && i < near.size() ? near[i] : lo;
    const auto encoded = static_cast<std::uint64_t>(want) - static_cast<std::uint64_t>(lo);
    Bdd same = Bdd::constant(true);
    for (std::size_t k = 0; k < circuit_.input_bits[i].size(); ++k) {
      const Bdd bit = node_bdd(circuit_.input_bits[i][k]);
      same = same & ((k < 64 && ((encoded >> k) & 1U)) ? bit : !bit);
    }
    const Bdd kept = on_inputs & same;
    if (!kept.is_false()) on_inputs = kept;
  }
  const Bdd one = on_inputs.sat_one(input_cube_);
  std::vector<bool> bits(input_var_.size());
  for (std::size_t i = 0; i < input_var_.size(); ++i)
    bits[i] = one.value_in_cube(input_var_[i]) == 1;
  return bits;
}

std::vector<bool> SymbolicSystem::initial_inputs(semantics::StateView to,
                                                 const std::vector<std::int64_t>& near) const {
  if (!grafcet_) return {};
  return pick_inputs_near(grafcet_->initial_inputs(singleton(to)), near);
}

std::vector<bool> SymbolicSystem::inputs_between(semantics::StateView from, semantics::StateView to,
                                                 const std::vector<std::int64_t>& near) const {
  if (grafcet_)
    return pick_inputs_near(grafcet_->inputs_between(singleton(from), singleton(to)), near);
  if (circuit_.aig.inputs().size() <= kMaxSimulatedInputs && !current_var_.empty()) {
    // Simulated: `from` under every input valuation, without the relation.
    std::vector<std::uint32_t> position(current_var_.size());
    std::iota(position.begin(), position.end(), 0U);
    SuccessorSimulator sim(circuit_, std::move(position));
    const std::vector<bool> target = latches_of(to);
    std::vector<std::uint64_t> key(sim.latch_words(), 0);
    for (std::uint32_t l = 0; l < target.size(); ++l)
      if (target[l]) set_key_bit(key.data(), l);
    const std::size_t count = sim.simulate(latches_of(from));
    for (std::size_t j = 0; j < count; ++j)
      if (std::equal(key.begin(), key.end(), sim.successor(j))) {
        std::vector<bool> bits(input_var_.size());
        for (std::size_t i = 0; i < bits.size(); ++i) bits[i] = ((sim.valuation(j) >> i) & 1U) != 0;
        return bits;
      }
    return {};
  }
  // T(from, i, to) over the inputs: every current and next variable is fixed, so each cluster
  // only shrinks the set of inputs.
  Bdd acc = singleton(from) & singleton(to).replace(*current_to_next_);
  for (const auto& c : relation().clusters) acc = acc & c;
  const Bdd on_inputs = acc.exist(current_cube_).exist(next_cube_);
  const Bdd one = on_inputs.sat_one(input_cube_);
  if (one.is_false()) return {};
  std::vector<bool> bits(input_var_.size());
  for (std::size_t i = 0; i < input_var_.size(); ++i)
    bits[i] = one.value_in_cube(input_var_[i]) == 1;
  return bits;
}

Bdd SymbolicSystem::field_value_equals(std::uint32_t o, std::int64_t value) {
  const auto& bits = circuit_.observable_bits[o];
  const auto encoded = static_cast<std::uint64_t>(value - circuit_.observable_lo[o]);
  if (value < circuit_.observable_lo[o] || (bits.size() < 64 && (encoded >> bits.size()) != 0))
    return Bdd::constant(false);
  Bdd r = Bdd::constant(true);
  for (std::size_t k = 0; k < bits.size(); ++k) {
    const Bdd b = node_bdd(bits[k]);
    r = r & (((encoded >> k) & 1U) ? b : !b);
  }
  return r;
}

Bdd SymbolicSystem::atom(const logic::Formula& f) {
  // The shared mapping to circuit literals (logic/circuit_atom.hpp), which the SAT engines use
  // too; comparisons may add nodes to the circuit.
  const AigLit lit = logic::circuit_literal(circuit_, f);
  memo_.resize(circuit_.aig.nodes().size());
  memo_set_.resize(circuit_.aig.nodes().size(), false);
  return node_bdd(lit);
}

Bdd SymbolicSystem::fires(std::uint32_t t) {
  if (grafcet_) return grafcet_->fires(t);
  if (!fires_set_[t]) {
    fires_[t] = (node_bdd(circuit_.fired[t]) & ok_).exist(input_cube_);
    fires_set_[t] = true;
  }
  return fires_[t];
}

Bdd SymbolicSystem::fires_on_one_edge(std::uint32_t i, std::uint32_t j) {
  if (!grafcet_) throw std::logic_error("fires_on_one_edge: Grafcet only");
  return grafcet_->fires_on_one_edge(i, j);
}

void SymbolicSystem::prepare_choice_cubes() {
  if (choice_cube_) return;
  if (grafcet_) throw std::logic_error("choice inputs: IEC 61131-3 only");
  std::vector<bool> is_choice(input_var_.size(), false);
  for (std::size_t i = 0; i < ts_.inputs().size(); ++i) {
    const auto& in = ts_.inputs()[i];
    if (!in.pseudo || !in.name.starts_with("choice:")) continue;
    for (auto bit : circuit_.input_bits[i]) {
      const Bdd v = node_bdd(bit);
      if (v.is_true() || v.is_false()) continue;
      for (std::size_t k = 0; k < input_var_.size(); ++k)
        if (input_var_[k] == v.top()) is_choice[k] = true;
    }
  }
  std::vector<int> choice, plant;
  for (std::size_t k = 0; k < input_var_.size(); ++k)
    (is_choice[k] ? choice : plant).push_back(input_var_[k]);
  choice_cube_ = Bdd::cube(choice);
  plant_cube_ = Bdd::cube(plant);
}

Bdd SymbolicSystem::choice_matters(const Bdd& states) {
  prepare_choice_cubes();
  const Bdd ok = ok_ & states;
  Bdd out = Bdd::constant(false);
  for (auto lit : circuit_.fired) {
    const Bdd f = node_bdd(lit);
    out = out | ((ok & f).exist(*choice_cube_) & (ok & !f).exist(*choice_cube_));
  }
  return out;
}

Bdd SymbolicSystem::order_matters(const Bdd& states) {
  if (grafcet_) throw std::logic_error("order inputs: IEC 61131-3 only");
  if (!order_cube_) {
    std::vector<int> order;
    for (std::size_t i = 0; i < ts_.inputs().size(); ++i) {
      const auto& in = ts_.inputs()[i];
      if (!in.pseudo || !in.name.starts_with("order:")) continue;
      for (auto bit : circuit_.input_bits[i]) {
        const Bdd v = node_bdd(bit);
        if (!v.is_true() && !v.is_false()) order.push_back(v.top());
      }
    }
    order_cube_ = Bdd::cube(order);
  }
  // A latch whose next value is 1 under one order and 0 under another, the state and the other
  // inputs fixed: the cycle's result depends on the order.
  const Bdd ok = ok_ & states;
  Bdd out = Bdd::constant(false);
  for (const auto& latch : circuit_.aig.latches()) {
    const Bdd f = node_bdd(latch.next);
    out = out | ((ok & f).exist(*order_cube_) & (ok & !f).exist(*order_cube_));
  }
  return out.exist(input_cube_);
}

Bdd SymbolicSystem::pick_point(const Bdd& set) {
  prepare_choice_cubes();
  return set.sat_one(current_cube_ & plant_cube_);
}

Bdd SymbolicSystem::beyond_fired_sets_of(const Bdd& point) {
  prepare_choice_cubes();
  Bdd rest = ok_ & point;
  Bdd outside = Bdd::constant(true);
  while (!rest.is_false()) {
    // One choice, then every choice with the same fired set.
    const Bdd one = rest.sat_one(*choice_cube_);
    Bdd same = Bdd::constant(true);
    for (auto lit : circuit_.fired) {
      const Bdd f = node_bdd(lit);
      same = same & ((f & one).is_false() ? !f : f);
    }
    rest = rest & !same;
    outside = outside & !same;
  }
  return (ok_ & outside).exist(*choice_cube_);
}

Bdd SymbolicSystem::enters(const Bdd& step) {
  return grafcet_ ? grafcet_->enters(step) : Bdd::constant(false);
}

bool SymbolicSystem::enters_initially(const Bdd& step) const {
  return grafcet_ && grafcet_->enters_initially(step);
}

Bdd SymbolicSystem::fires_any() {
  Bdd any = Bdd::constant(false);
  for (std::uint32_t t = 0; t < circuit_.fired.size(); ++t) any = any | fires(t);
  return any;
}

double SymbolicSystem::count(const Bdd& states) const {
  if (states.is_false()) return 0;
  if (const auto exact = states.sat_count_u64(current_vars_)) return static_cast<double>(*exact);
  return std::exp2(states.sat_count_log2(current_cube_));
}

logic::BigCount SymbolicSystem::count_exact(const Bdd& states) const {
  return states.sat_count_exact(current_vars_);
}

std::optional<logic::BigCount> SymbolicSystem::count_edges(const Bdd& from,
                                                           EdgeCounting how) const {
  // Grafcet: the closure computes images, never the pair relation; the count stays unknown
  // rather than wrong.
  if (grafcet_) return std::nullopt;
  if (from.is_false()) return logic::BigCount(0);
  if (how == EdgeCounting::Simulation)
    return simulates(from, ~std::uint64_t{0}, false) ? count_edges_by_simulation(from)
                                                     : std::nullopt;
  // A set with few BDD nodes per state (a counter's, the structured families') is counted on
  // the relation at almost no cost; one with about a node per state (random charts: 10 004
  // states in 23 442 nodes, whose pair relation has 295 000) by simulation, when small enough
  // (measured on `sfcv-gen random 60 --seed 2`: 0.78 s on the relation).
  if (how == EdgeCounting::Auto && simulates(from, kSimulationWork, true))
    if (auto edges = count_edges_by_simulation(from)) return edges;
  // exists i. T(x, i, x') & from(x), quantifying each input after the last cluster reading it.
  const Relation& r = relation();
  Bdd acc = from.exist(r.inputs_first);
  for (std::size_t k = 0; k < r.clusters.size(); ++k)
    acc = acc.and_exist(r.clusters[k], r.inputs_after[k]);
  std::vector<int> vars = current_var_;
  vars.insert(vars.end(), next_var_.begin(), next_var_.end());
  return acc.sat_count_exact(vars);
}

std::optional<logic::BigCount> SymbolicSystem::count_edges_by_simulation(const Bdd& from) const {
  std::vector<std::uint32_t> position(current_var_.size());
  std::iota(position.begin(), position.end(), 0U);
  SuccessorSimulator sim(circuit_, std::move(position));
  std::uint64_t edges = 0;
  const bool walked = from.for_each_assignment(current_var_, [&](const std::vector<bool>& x) {
    edges += sim.simulate(x);
    return true;
  });
  if (!walked) return std::nullopt;
  return logic::BigCount(edges);
}

std::optional<Bdd> SymbolicSystem::image_by_simulation(const Bdd& from,
                                                       SimulationTally& tally) const {
  std::vector<std::uint32_t> rank_of = latch_ranks(current_var_);
  const std::vector<int> var_of_rank = var_at_rank(rank_of, current_var_);
  SuccessorSimulator sim(circuit_, std::move(rank_of));
  const std::size_t key_words = sim.latch_words();
  std::vector<std::uint64_t> keys;
  const bool walked = from.for_each_assignment(current_var_, [&](const std::vector<bool>& x) {
    const std::size_t count = sim.simulate(x);
    for (std::size_t j = 0; j < count; ++j)
      keys.insert(keys.end(), sim.successor(j), sim.successor(j) + key_words);
    ++tally.states;
    tally.edges += count;
    return true;
  });
  if (!walked) return std::nullopt;
  const std::size_t count = sort_distinct_keys(keys, key_words);
  return bdd_of_sorted_keys(keys, count, key_words, var_of_rank);
}

std::vector<semantics::StateWord> SymbolicSystem::pick(const Bdd& states) const {
  const Bdd one = states.sat_one(current_cube_);
  if (one.is_false()) throw std::invalid_argument("SymbolicSystem::pick: empty set");
  std::vector<bool> latches(current_var_.size());
  for (std::size_t l = 0; l < current_var_.size(); ++l)
    latches[l] = one.value_in_cube(current_var_[l]) == 1;
  return semantics::state_from_latches(ts_, circuit_, latches);
}

Bdd SymbolicSystem::singleton(semantics::StateView state) const {
  const auto& layout = ts_.layout();
  Bdd r = Bdd::constant(true);
  for (std::uint32_t f = 0; f < circuit_.field_latches.size(); ++f) {
    const auto v = static_cast<std::uint64_t>(layout.get(state, f) - layout.fields()[f].lo);
    for (std::size_t k = 0; k < circuit_.field_latches[f].size(); ++k) {
      const Bdd b = Bdd::variable(current_var_[circuit_.field_latches[f][k]]);
      r = r & (((v >> k) & 1U) ? b : !b);
    }
  }
  return r;
}

std::unique_ptr<SymbolicSystem> make_symbolic_system(const semantics::TransitionSystem& ts,
                                                     const SymbolicOptions& options) {
  // Before any Bdd exists (a member's VarMap would start the manager with the default sizing).
  auto configure = [&options](const Aig& aig) {
    const auto m = manager_options(options, aig);
    bdd::configure_manager(m.nodes, m.cache, m.cache_ratio);
  };
  if (ts.kind() == semantics::SemanticsKind::Grafcet) {
    auto circuit =
        semantics::build_grafcet_circuit(ts, options.deadline, options.max_circuit_bytes);
    configure(circuit.aig);
    return std::make_unique<SymbolicSystem>(ts, std::move(circuit), options);
  }
  auto circuit = semantics::build_iec61131_circuit(ts, options.deadline, options.max_circuit_bytes);
  configure(circuit.aig);
  return within_share(options.relation_deadline, [&] {
    return std::make_unique<SymbolicSystem>(ts, std::move(circuit), options);
  });
}

}  // namespace sfcv::engine

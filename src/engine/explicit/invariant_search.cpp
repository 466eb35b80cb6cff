#include "engine/explicit/invariant_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

#include "engine/explicit/mapped_array.hpp"
#include "engine/explicit/state_store.hpp"
#include "logic/formula.hpp"

namespace sfcv::engine {

using logic::Op;
using semantics::StateView;
using semantics::StateWord;

void TargetEnumerator::targets_of(StateView states, std::uint32_t count,
                                  std::vector<StateWord>& out, std::vector<std::uint32_t>& ends) {
  const std::size_t words = count == 0 ? 0 : states.size() / count;
  for (std::uint32_t i = 0; i < count; ++i) {
    targets(states.subspan(i * words, words), out);
    ends.push_back(static_cast<std::uint32_t>(out.size()));
  }
}

namespace {

constexpr std::uint32_t kNoState = ~0U;

/// States enumerated together by the serial search: enough for a compiled enumerator to fill
/// its 64 lanes with several states, few enough that the work done past a stopping state is
/// small.
constexpr std::uint32_t kSerialChunkStates = 64;

class InterpretedEnumerator final : public TargetEnumerator, semantics::SuccessorSink {
 public:
  InterpretedEnumerator(const semantics::TransitionSystem& ts, model::Budget limits)
      : ts_(ts), limits_(std::move(limits)) {}
  void targets(StateView state, std::vector<StateWord>& out) override {
    // The search reads the clock every few hundred states, and the system every 4096 input
    // valuations: an interpreted state whose cycle runs a long ST loop once per valuation can
    // take 70 ms with fewer, and 901 of them ran 52 s past --timeout 10 (issue 53). A clock
    // read is nothing beside an interpreted cycle.
    limits_.check_time("computing the successors of one state");
    out_ = &out;
    const auto size = out.size();
    try {
      ts_.successors(state, *this);
    } catch (...) {
      out.resize(size);  // no partial successors of a state a limit stopped
      throw;
    }
  }

 private:
  void successor(const semantics::Successor& s) override {
    out_->insert(out_->end(), s.target.begin(), s.target.end());
  }
  // Inside one wide state: the valuation bound of --engine auto's probe, and the run's
  // deadline or cancel (the system reads only the deadline it was built with).
  void valuations(std::uint64_t count, std::uint64_t held_bytes) override {
    if (limits_.max_valuations > 0 && count > limits_.max_valuations)
      throw LimitReached(Limit::Valuations, "more than " + std::to_string(limits_.max_valuations) +
                                                " input valuations in the successors of one state");
    if (limits_.max_memory_bytes > 0 &&
        memory_in_use_ + held_bytes + out_->capacity() * sizeof(StateWord) >
            limits_.max_memory_bytes)
      throw LimitReached(Limit::Memory,
                         "memory limit reached while computing the successors of one state");
    limits_.check_time("computing the successors of one state");
  }
  const semantics::TransitionSystem& ts_;
  model::Budget limits_;  ///< a copy (the cancel flag is shared)
  std::vector<StateWord>* out_ = nullptr;
};

/// The label of the edge source -> `target` as the graph builder merges it: the cubes of every
/// successor reaching `target` (first occurrence order, no repeats) and the union of their fired
/// transitions.
class EdgeLabel final : public semantics::SuccessorSink {
 public:
  explicit EdgeLabel(StateView target) : target_(target) {}
  void successor(const semantics::Successor& s) override {
    if (!std::equal(s.target.begin(), s.target.end(), target_.begin(), target_.end())) return;
    builder_.add(s.condition.cubes);
    std::vector<std::uint32_t> merged;
    std::set_union(fired.begin(), fired.end(), s.fired.begin(), s.fired.end(),
                   std::back_inserter(merged));
    fired = std::move(merged);
  }
  const semantics::InputCondition& condition() const { return builder_.condition(); }
  std::vector<std::uint32_t> fired;

 private:
  StateView target_;
  semantics::ConditionBuilder builder_;
};

bool holds(const logic::Formula& f, const semantics::TransitionSystem& ts, StateView s) {
  const auto& a = f.args;
  switch (f.op) {
    case Op::True:
      return true;
    case Op::False:
      return false;
    case Op::Atom:
      return ts.observe(s, static_cast<std::uint32_t>(f.observable)) != 0;
    case Op::Compare:
      return logic::compare(f.cmp, ts.observe(s, static_cast<std::uint32_t>(f.observable)),
                            f.value);
    case Op::Relation:
      return logic::relation_holds(f, [&](std::uint32_t o) { return ts.observe(s, o); });
    case Op::Not:
      return !holds(*a[0], ts, s);
    case Op::And:
      return holds(*a[0], ts, s) && holds(*a[1], ts, s);
    case Op::Or:
      return holds(*a[0], ts, s) || holds(*a[1], ts, s);
    case Op::Implies:
      return !holds(*a[0], ts, s) || holds(*a[1], ts, s);
    case Op::Iff:
      return holds(*a[0], ts, s) == holds(*a[1], ts, s);
    case Op::Xor:
      return holds(*a[0], ts, s) != holds(*a[1], ts, s);
    default:
      return false;  // temporal: excluded by invariants_only
  }
}

/// The verdicts of an invariant's state formula, memoised on the few stored bits it reads: the
/// bits of the fields its observables read (TransitionSystem::observed_fields()), through the
/// codec. Its value is a function of those bits, so a new state is judged by a table look-up
/// and the semantics runs once per value of them.
class FormulaMemo {
 public:
  static constexpr std::uint32_t kMaxBits = 12;
  /// Unusable (every state judged by the semantics) when the system does not name the fields
  /// its observables read, or they span more than kMaxBits stored bits.
  FormulaMemo(const logic::Formula& f, const semantics::TransitionSystem& ts,
              const StateCodec* codec) {
    std::vector<std::uint32_t> bits;
    if (!collect_bits(f, ts, codec, bits)) return;
    std::sort(bits.begin(), bits.end());
    bits.erase(std::unique(bits.begin(), bits.end()), bits.end());
    if (bits.size() > kMaxBits) return;
    bits_ = std::move(bits);
    verdicts_.assign(std::size_t{1} << bits_.size(), kUnknown);
  }
  bool usable() const { return !verdicts_.empty(); }
  static constexpr std::uint8_t kUnknown = 0, kHolds = 1, kViolated = 2;
  /// The memoised verdict of the stored state `stored` (kUnknown the first time its bits are
  /// seen: set it then).
  std::uint8_t& verdict(const StateWord* stored) {
    std::size_t key = 0;
    for (std::size_t j = 0; j < bits_.size(); ++j)
      key |= static_cast<std::size_t>((stored[bits_[j] / 64] >> (bits_[j] % 64)) & 1U) << j;
    return verdicts_[key];
  }

 private:
  static bool collect_bits(const logic::Formula& f, const semantics::TransitionSystem& ts,
                           const StateCodec* codec, std::vector<std::uint32_t>& bits) {
    if (logic::names_observable(f.op)) {
      if (f.observable < 0) return false;
      const auto fields = ts.observed_fields(static_cast<std::uint32_t>(f.observable));
      if (!fields) return false;
      for (const auto field : *fields) {
        const auto& info = ts.layout().fields()[field];
        for (std::uint32_t b = info.offset; b < info.offset + info.width; ++b) {
          if (!codec) {
            bits.push_back(b);
            continue;
          }
          if (const auto stored = codec->stored_bit_of(b)) bits.push_back(*stored);
        }
        if (bits.size() > 4 * kMaxBits) return false;  // before the duplicates go: a bound
      }
    }
    for (const auto& a : f.args)
      if (!collect_bits(*a, ts, codec, bits)) return false;
    return true;
  }
  std::vector<std::uint32_t> bits_;  ///< the stored bits read, in key order
  std::vector<std::uint8_t> verdicts_;
};

/// The inputs of the initial situation `target`, picked as the graph-based engine picks them.
/// A Grafcet may have very many initial situations: the enumeration stops as soon as no later
/// one can change the pick, or once the budget has run out and some inputs lead to `target`
/// (a valid trace, if not the graph engine's exact pick).
std::vector<std::int64_t> initial_inputs(const semantics::TransitionSystem& ts, StateView target,
                                         const model::Budget& budget) {
  struct Stop {};
  class Picker final : public semantics::SuccessorSink {
   public:
    Picker(const semantics::TransitionSystem& sys, StateView t, const model::Budget& b)
        : picker(sys.inputs(), {}), target_(t), poll_(b, 64) {}
    void successor(const semantics::Successor& s) override {
      if (std::equal(s.target.begin(), s.target.end(), target_.begin(), target_.end())) {
        for (const auto& cube : s.condition.cubes) picker.add(cube);
        found_ = true;
      }
      if (picker.settled() || (found_ && poll_.tick())) throw Stop{};
    }
    logic::InputPicker picker;

   private:
    StateView target_;
    model::BudgetPoll poll_;
    bool found_ = false;
  } picker(ts, target, budget);
  try {
    ts.initial_states(picker);
  } catch (const Stop&) {
  }
  return picker.picker.pick();
}

/// The run from an initial state to `s` through BFS parents, with the inputs of each edge
/// picked as the graph-based engine picks them.
logic::Trace counterexample(const semantics::TransitionSystem& ts, const StateStore& store,
                            const StateCodec* codec, const MappedArray<std::uint32_t>& parent,
                            std::uint32_t s, const model::Budget& budget) {
  auto full = [&](std::uint32_t x) {
    const auto view = store.at(x);
    if (!codec) return std::vector<StateWord>(view.begin(), view.end());
    std::vector<StateWord> state(codec->full_words());
    codec->to_full(view.data(), state.data());
    return state;
  };
  std::vector<std::uint32_t> path;
  for (auto x = s; x != kNoState; x = parent[x]) path.push_back(x);
  std::reverse(path.begin(), path.end());
  logic::Trace trace;
  trace.kind = logic::TraceKind::Counterexample;
  std::vector<std::int64_t> previous;
  for (std::size_t i = 0; i < path.size(); ++i) {
    logic::TraceStep step;
    step.state = full(path[i]);
    if (i == 0) {
      step.inputs = initial_inputs(ts, step.state, budget);
    } else {
      EdgeLabel label(step.state);
      ts.successors(full(path[i - 1]), label);
      step.inputs = logic::pick_inputs(label.condition(), ts.inputs(), previous);
      step.fired = label.fired;
    }
    previous = step.inputs;
    trace.steps.push_back(std::move(step));
  }
  return trace;
}

/// Keeps the first occurrence of each of the `count` targets at `first` (`words` words each),
/// in their order, and returns how many remain: one edge per (source, target), as the graph.
/// `last_repeats`: whether the last target repeats an earlier one.
std::size_t keep_distinct_targets(StateWord* first, std::size_t count, std::uint32_t words,
                                  std::vector<std::uint32_t>& table, bool& last_repeats) {
  last_repeats = false;
  auto at = [&](std::size_t i) { return first + i * words; };
  auto same = [&](std::size_t i, std::size_t j) { return same_state(at(i), at(j), words); };
  std::size_t kept = 0;
  if (words == 1 && count > 8 && count <= 64) {
    // One-word targets (the common case of a compiled enumerator): the words themselves in a
    // 128-slot table on the stack, its occupancy in two words.
    StateWord keys[128];
    std::uint64_t used[2] = {0, 0};
    for (std::size_t i = 0; i < count; ++i) {
      const StateWord w = first[i];
      auto slot = static_cast<std::uint32_t>((w * 0x9e3779b97f4a7c15ULL) >> 57);
      bool seen = false;
      for (; (used[slot >> 6] >> (slot & 63U)) & 1U; slot = (slot + 1) & 127U)
        if (keys[slot] == w) {
          seen = true;
          break;
        }
      last_repeats = seen;
      if (seen) continue;
      keys[slot] = w;
      used[slot >> 6] |= std::uint64_t{1} << (slot & 63U);
      first[kept++] = w;
    }
    return kept;
  }
  if (count <= 16) {
    for (std::size_t i = 0; i < count; ++i) {
      bool seen = false;
      for (std::size_t j = 0; j < kept && !seen; ++j) seen = same(i, j);
      last_repeats = seen;
      if (seen) continue;
      if (kept != i) std::copy(at(i), at(i) + words, at(kept));
      ++kept;
    }
    return kept;
  }
  std::size_t size = 64;
  while (size < 2 * count) size *= 2;
  table.assign(size, 0);
  const std::size_t mask = size - 1;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (std::uint32_t w = 0; w < words; ++w) h = (h ^ at(i)[w]) * 0xbf58476d1ce4e5b9ULL;
    std::size_t slot = (h ^ (h >> 29)) & mask;
    bool seen = false;
    for (; table[slot] != 0; slot = (slot + 1) & mask)
      if (same(i, table[slot] - 1)) {
        seen = true;
        break;
      }
    last_repeats = seen;
    if (seen) continue;
    if (kept != i) std::copy(at(i), at(i) + words, at(kept));
    table[slot] = static_cast<std::uint32_t>(++kept);
  }
  return kept;
}

/// Keeps the distinct targets of each state (keep_distinct_targets), moved down in place:
/// `ends` (per state, the end of its targets in words) is updated and `repeats` gets, per state,
/// whether its last target repeated an earlier one.
void keep_distinct_targets_of_each(std::vector<StateWord>& targets,
                                   std::vector<std::uint32_t>& ends, std::uint32_t words,
                                   std::vector<std::uint32_t>& table,
                                   std::vector<std::uint8_t>& repeats) {
  std::uint32_t from = 0, kept = 0;
  for (auto& end : ends) {
    bool repeat = false;
    const auto count =
        keep_distinct_targets(targets.data() + from, (end - from) / words, words, table, repeat);
    repeats.push_back(repeat ? 1 : 0);
    if (kept != from) std::copy_n(targets.begin() + from, count * words, targets.begin() + kept);
    from = end;
    kept += static_cast<std::uint32_t>(count * words);
    end = kept;
  }
  targets.resize(kept);
}

/// The threads of the parallel search. A job runs on every worker at once, and on this thread
/// too when it joins to help, each with its own enumerator; it takes its share of the work
/// itself (from an atomic counter), so it is over once its work is taken and every thread has
/// left it.
class WorkerPool {
 public:
  using Job = std::function<void(TargetEnumerator&)>;

  WorkerPool(TargetEnumerator& own, unsigned threads) : own_(own) {
    for (unsigned t = 1; t < threads; ++t) {
      auto e = own.clone();
      if (!e) break;
      enumerators_.push_back(std::move(e));
    }
    // A thread the system cannot start (process table full) leaves fewer workers: the jobs take
    // their work from a shared counter, so results do not depend on how many started.
    for (auto& e : enumerators_) {
      try {
        workers_.emplace_back([this, en = e.get()] { work(*en); });
      } catch (const std::system_error&) {
        break;
      }
    }
    enumerators_.resize(workers_.size());
  }
  ~WorkerPool() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  bool parallel() const { return !workers_.empty(); }

  /// Starts `job` on the workers; join() ends it.
  void post(Job job) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      job_ = std::move(job);
      posted_ = true;
      error_ = nullptr;
      ++generation_;
    }
    wake_.notify_all();
  }
  /// Runs the posted job on this thread too (when `help`; otherwise its work must already be
  /// taken), waits until no worker is inside it, and rethrows what one of its runs threw.
  void join(bool help = true) {
    if (help) run(own_);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return active_ == 0; });
    posted_ = false;  // a worker waking late finds nothing to run
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }

 private:
  void work(TargetEnumerator& e) {
    std::unique_lock<std::mutex> lock(mutex_);
    std::uint64_t seen = 0;
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || (posted_ && generation_ != seen); });
      if (stop_) return;
      seen = generation_;
      ++active_;
      lock.unlock();
      run(e);
      lock.lock();
      if (--active_ == 0) done_.notify_all();
    }
  }
  void run(TargetEnumerator& e) {
    try {
      job_(e);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }

  TargetEnumerator& own_;
  std::vector<std::unique_ptr<TargetEnumerator>> enumerators_;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  Job job_;
  bool posted_ = false;
  std::uint64_t generation_ = 0;
  std::uint32_t active_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

/// What the serial search enumerates at once: the distinct targets of a run of stored states
/// (a chunk), and their hashes.
struct ChunkTargets {
  std::vector<StateWord> targets;     ///< each source's distinct targets, one after another
  std::vector<std::uint32_t> ends;    ///< per source, the end of its targets (in words)
  std::vector<std::uint8_t> repeats;  ///< per source, whether its last target repeated one
  std::vector<std::uint64_t> hashes;  ///< per target, its state_hash()
  std::vector<std::uint32_t> table;   ///< keep_distinct_targets()'s

  /// Enumerates the `count` states `sources` of `store`. A limit met inside the enumeration
  /// is returned (the sources in `ends` were enumerated before it), except Limit::Enumeration,
  /// which is rethrown.
  std::optional<Limit> enumerate(TargetEnumerator& e, const StateStore& store, StateView sources,
                                 std::uint32_t count) {
    const std::uint32_t words = store.words_per_state();
    targets.clear();
    ends.clear();
    repeats.clear();
    std::optional<Limit> stopped;
    try {
      e.targets_of(sources, count, targets, ends);
    } catch (const LimitReached& stop) {
      if (stop.which() == Limit::Enumeration) throw;
      stopped = stop.which();
    }
    keep_distinct_targets_of_each(targets, ends, words, table, repeats);
    hashes.resize(targets.size() / words);
    store.state_hashes(targets, hashes.size(), hashes.data());
    return stopped;
  }
};

/// The serial search on several threads: while this thread stores the targets of one block of
/// kStates sources, the workers enumerate the next block's chunks, whose sources are stored
/// already. The search itself is the one-thread search, so every count, verdict and trace is
/// its own: a chunk the workers did not enumerate (a limit, an error) is enumerated again on
/// this thread, where it meets the limit or the error as the one-thread search does.
///
/// The sources of a block do not move while the workers read them: before they start, the
/// store makes room for as many new states as the block being stored has targets.
class EnumerationAhead {
 public:
  static constexpr std::uint32_t kStates = 4096;

  /// Chunks of `chunk_states` sources, a power of two dividing kStates.
  EnumerationAhead(WorkerPool& pool, StateStore& store, std::uint32_t chunk_states)
      : pool_(pool), store_(store), chunk_states_(chunk_states), chunks_(kStates / chunk_states) {
    for (auto* set : {&current_, &next_}) set->chunks.resize(chunks_);
  }
  ~EnumerationAhead() {
    try {
      finish();
    } catch (...) {  // the job catches what an enumeration throws
    }
  }
  EnumerationAhead(const EnumerationAhead&) = delete;
  EnumerationAhead& operator=(const EnumerationAhead&) = delete;

  /// The search begins the block at `begin` (a multiple of kStates): takes the block the
  /// workers enumerated (enumerating with them the chunks they have not taken yet: storing may
  /// be the shorter half), enumerates it on every thread when they did not and it is stored, and
  /// starts the next block on the workers when its sources are stored and this block's are
  /// enumerated. `memory_in_use`: for their enumerators (set_memory_in_use()).
  void begin_block(std::uint32_t begin, std::uint64_t memory_in_use) {
    finish(true);
    std::swap(current_, next_);
    if (current_.begin != begin && std::uint64_t{begin} + kStates <= store_.size()) {
      post(current_, begin, memory_in_use);
      join(true);
    }
    if (current_.begin != begin) return;
    std::uint64_t targets = 0;
    for (const auto& c : current_.chunks) {
      if (!c.ready) return;  // its targets are not counted: the workers wait
      targets += c.hashes.size();
    }
    if (std::uint64_t{begin} + 2 * kStates > store_.size()) return;
    store_.reserve_states(targets);
    post(next_, begin + kStates, memory_in_use);
  }
  /// Hands over the chunk of sources starting at `from` when the workers enumerated it.
  bool take(std::uint32_t from, ChunkTargets& chunk) {
    if (from < current_.begin || from - current_.begin >= kStates ||
        (from - current_.begin) % chunk_states_ != 0)
      return false;
    auto& c = current_.chunks[(from - current_.begin) / chunk_states_];
    if (!c.ready) return false;
    c.ready = false;
    std::swap(chunk, static_cast<ChunkTargets&>(c));
    return true;
  }
  /// Waits for the workers' job to end (before the search ends, or begins their block),
  /// enumerating what they have not taken yet when `help`.
  void finish(bool help = false) {
    if (running_) join(help);
  }

 private:
  struct Chunk : ChunkTargets {
    bool ready = false;  ///< enumerated by a worker
  };
  struct Block {
    std::uint32_t begin = kNoState;
    std::vector<Chunk> chunks;
  };

  void post(Block& block, std::uint32_t begin, std::uint64_t memory_in_use) {
    block.begin = begin;
    for (auto& c : block.chunks) c.ready = false;
    next_chunk_.store(0);
    const StateView sources = store_.range(begin, kStates);
    const std::uint32_t words = store_.words_per_state();
    running_ = true;
    pool_.post([this, &block, sources, words, memory_in_use](TargetEnumerator& e) {
      e.set_memory_in_use(memory_in_use);
      for (;;) {
        const auto c = next_chunk_.fetch_add(1);
        if (c >= chunks_) break;
        auto& chunk = block.chunks[c];
        const StateView run(sources.data() + std::size_t{c} * chunk_states_ * words,
                            std::size_t{chunk_states_} * words);
        try {
          chunk.ready = !chunk.enumerate(e, store_, run, chunk_states_);
        } catch (...) {
          // Enumerated again on the search's thread, which meets the error itself.
        }
      }
    });
  }
  void join(bool help) {
    running_ = false;
    pool_.join(help);
  }

  WorkerPool& pool_;
  StateStore& store_;
  std::uint32_t chunk_states_;
  std::uint32_t chunks_;
  Block current_, next_;
  std::atomic<std::uint32_t> next_chunk_{0};
  bool running_ = false;
};

}  // namespace

std::unique_ptr<TargetEnumerator> make_interpreted_enumerator(const semantics::TransitionSystem& ts,
                                                              model::Budget limits) {
  return std::make_unique<InterpretedEnumerator>(ts, std::move(limits));
}

bool invariants_only(const logic::CheckTask& task) {
  if (!task.system || !task.checks.empty() || !task.fairness.empty() || task.properties.empty() ||
      task.coverage)
    return false;
  for (const auto& p : task.properties)
    if (p.formula->op != Op::AG || !logic::is_propositional(*p.formula->args[0])) return false;
  return true;
}

logic::CheckReport check_invariants(const logic::CheckTask& task, TargetEnumerator* enumerator,
                                    unsigned threads) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&start] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const auto& ts = *task.system;
  const auto& limits = task.limits;
  std::unique_ptr<TargetEnumerator> own;
  if (!enumerator) {
    own = make_interpreted_enumerator(ts, limits);
    enumerator = own.get();
  }

  // The stored form of the states (fewer words when some bits follow others): converted back
  // only to judge a new state and to rebuild a counterexample.
  const StateCodec* codec = enumerator->codec();
  std::vector<StateWord> full(codec ? codec->full_words() : 0), stored;
  const std::size_t n = task.properties.size();
  std::vector<std::uint32_t> violation(n, kNoState);  ///< first violating state per property
  std::vector<double> decided_at(n, 0);
  std::size_t open = n;
  // The search asks the store only whether a target is stored (a new state's index is the
  // store's size): one-word states may be held in the table's slots, in quotient form.
  const std::uint32_t stored_words = codec ? codec->stored_words() : ts.layout().words();
  const std::uint32_t stored_bits = codec ? codec->stored_bits() : ts.layout().bits();
  StateStore store(stored_words, StateStore::kTaggedStates,
                   stored_words == 1 ? std::max<std::uint32_t>(stored_bits, 1) : 0);
  if (codec) stored.resize(codec->stored_words());
  MappedArray<std::uint32_t> parent;  ///< per state: the state it was first reached from
  // Checks a newly stored state against every invariant still open.
  std::vector<std::size_t> just_violated;  ///< properties violated while expanding this state
  std::vector<FormulaMemo> memos;
  for (const auto& p : task.properties) memos.emplace_back(*p.formula->args[0], ts, codec);
  auto judge = [&](std::uint32_t s) {
    const auto stored_view = store.at(s);
    auto view = stored_view;
    bool converted = !codec;
    for (std::size_t i = 0; i < n; ++i) {
      if (violation[i] != kNoState) continue;
      std::uint8_t scratch = FormulaMemo::kUnknown;
      std::uint8_t& verdict = memos[i].usable() ? memos[i].verdict(stored_view.data()) : scratch;
      if (verdict == FormulaMemo::kUnknown) {
        if (!converted) {
          codec->to_full(stored_view.data(), full.data());
          view = full;
          converted = true;
        }
        verdict = holds(*task.properties[i].formula->args[0], ts, view) ? FormulaMemo::kHolds
                                                                        : FormulaMemo::kViolated;
      }
      if (verdict == FormulaMemo::kViolated) {
        violation[i] = s;
        decided_at[i] = elapsed();
        just_violated.push_back(i);
        --open;
      }
    }
  };

  // A Grafcet may start in very many situations (one per initial valuation): the state limit
  // and the deadline apply to them too, and stop the enumeration (corpus 22 under auto ran
  // minutes past --timeout, enumerating valuations after the limit).
  // Each new initial situation is judged at once: when every invariant is violated the rest
  // are not enumerated (corpus 22 violates AG !X2 in its first one, of about 2^40).
  struct StopInitial {};
  class Initial final : public semantics::SuccessorSink {
   public:
    Initial(StateStore& st, const model::Budget& b, std::function<bool(std::uint32_t)> judge,
            std::function<StateView(StateView)> stored_form)
        : store(st),
          max_states(b.max_states),
          poll(b, 64),
          judge_(std::move(judge)),
          stored_form_(std::move(stored_form)) {}
    void successor(const semantics::Successor& s) override {
      if (max_states > 0 && store.size() > max_states) {
        limit = "states";
        throw StopInitial{};
      }
      if (poll.tick()) {
        limit = "time";
        throw StopInitial{};
      }
      const auto [index, fresh] = store.insert(stored_form_(s.target));
      if (fresh && !judge_(index)) throw StopInitial{};
    }
    StateStore& store;
    std::uint64_t max_states;
    model::BudgetPoll poll;
    std::string limit;

   private:
    std::function<bool(std::uint32_t)> judge_;
    std::function<StateView(StateView)> stored_form_;
  } initial(
      store, limits,
      [&](std::uint32_t s) {
        judge(s);
        return open > 0;
      },
      [&](StateView state) {
        if (!codec) return state;
        // The compiled enumerator proved its codec on every initial state.
        if (!codec->to_stored(state.data(), stored.data()))
          throw std::logic_error("invariant search: an initial state outside the stored form");
        return StateView(stored);
      });
  try {
    ts.initial_states(initial);
  } catch (const StopInitial&) {
  }
  const std::uint32_t initial_count = store.size();
  parent.assign(initial_count, kNoState);

  std::string limit = initial.limit;
  std::uint64_t edges = 0;
  const std::uint32_t words = store.words_per_state();
  auto memory = [&] { return store.memory_bytes() + parent.resident_bytes(); };
  // BFS numbers states level by level: [level_begin, level_end) are the states at `level`.
  std::uint32_t level = 0, level_end = initial_count;
  const std::uint32_t poll_mask = clock_poll_mask(words);
  // Before state s is expanded: the level it starts, and the limits. False: stop before it.
  auto before = [&](std::uint32_t s) {
    if (s == level_end) {
      ++level;
      level_end = store.size();
    }
    if (limits.max_states > 0 && store.size() > limits.max_states) {
      limit = "states";
      return false;
    }
    if ((s & poll_mask) == 0 && s > 0) {
      if (limits.expired())
        limit = "time";
      else if (limits.max_memory_bytes > 0 && memory() > limits.max_memory_bytes)
        limit = "memory";
      if (!limit.empty()) return false;
      if (limits.progress && (s & 4095U) == 0) {
        logic::Progress p;
        p.states = store.size();
        p.edges = edges;
        p.depth = level;
        p.seconds = elapsed();
        p.phase = "explore (invariants)";
        limits.progress(p);
      }
    }
    return true;
  };
  // The serial search enumerates the stored states [chunk_begin, chunk_end) together: their
  // distinct targets (one edge per source and target, as the graph) are in `chunk`.
  ChunkTargets chunk;
  const auto& targets = chunk.targets;
  const auto& ends = chunk.ends;
  const auto& hashes = chunk.hashes;
  std::uint32_t chunk_begin = 0, chunk_end = 0;
  // Stores the targets [first, last) of state s and judges the new ones. False: a limit
  // stopped it. The look-ups of the chunk's later targets are started early.
  auto expand = [&](std::uint32_t s, std::size_t first, std::size_t last) {
    just_violated.clear();
    const std::uint64_t max_states = limits.max_states;
    // As the graph builder: no state is stored beyond the limit, and the state being expanded
    // when it is reached stays unexpanded.
    const std::uint32_t known = store.size();
    const std::uint64_t size_cap = max_states > 0 ? max_states + 1 : ~std::uint64_t{0};
    if (store.insert_new_states(targets.data(), hashes.data(), first, last, hashes.size(),
                                size_cap) < last)
      limit = "states";
    for (std::uint32_t t = known; t < store.size(); ++t) {
      parent.push_back(s);
      if (open > 0) judge(t);
    }
    // A repeated last target counts as a look-up past the limit, as in the graph builder.
    if (limit.empty() && max_states > 0 && store.size() > max_states &&
        chunk.repeats[s - chunk_begin] != 0)
      limit = "states";
    if (!limit.empty()) {
      // As in the graph, the state stays unexpanded and what it reached has no known path.
      for (auto i : just_violated) violation[i] = kNoState;
      open += just_violated.size();
      return false;
    }
    edges += last - first;
    return true;
  };
  // A chunk never crosses a clock poll, so the enumeration done between two reads of the
  // clock is what it was state by state.
  //
  // A limit inside one state's enumeration (a wide state past --engine auto's valuation bound,
  // or the deadline): that state stays unexpanded, as a state limit leaves it; the states of
  // its chunk before it are expanded first. An integer input too wide to enumerate
  // (Limit::Enumeration) still ends the run: the caller names it.
  std::uint32_t stopped_at = kNoState;  ///< the state whose enumeration threw
  Limit stopped_by = Limit::Time;
  WorkerPool pool(*enumerator, threads);
  // Chunks are aligned, so the workers of EnumerationAhead enumerate the chunks the search does.
  const std::uint32_t chunk_states = std::min(kSerialChunkStates, poll_mask + 1);
  std::optional<EnumerationAhead> ahead;  // ends its job before the pool ends
  auto enumerate = [&](std::uint32_t from) {
    chunk_begin = from;
    if (!ahead || !ahead->take(from, chunk)) {
      const auto end = static_cast<std::uint32_t>(
          std::min<std::uint64_t>(store.size(), (from | (chunk_states - 1)) + std::uint64_t{1}));
      if (limits.max_memory_bytes > 0) enumerator->set_memory_in_use(memory());
      if (const auto stop =
              chunk.enumerate(*enumerator, store, store.range(from, end - from), end - from)) {
        stopped_at = from + static_cast<std::uint32_t>(ends.size());
        stopped_by = *stop;
      }
    }
    chunk_end = from + static_cast<std::uint32_t>(ends.size());
    // The store starts its look-ups kLookAhead targets ahead: the first ones start here.
    for (std::size_t k = 0; k < std::min(StateStore::kLookAhead, hashes.size()); ++k)
      store.prefetch_slot(hashes[k]);
  };
  if (pool.parallel()) ahead.emplace(pool, store, chunk_states);
  std::uint32_t s = 0;
  for (; limit.empty() && open > 0 && s < store.size(); ++s) {
    if (!before(s)) break;
    if (ahead && s % EnumerationAhead::kStates == 0)
      ahead->begin_block(s, limits.max_memory_bytes > 0 ? memory() : 0);
    if (s >= chunk_end && s != stopped_at) enumerate(s);
    if (s == stopped_at) {
      limit = to_string(stopped_by);
      break;
    }
    const std::uint32_t from = s == chunk_begin ? 0 : ends[s - chunk_begin - 1];
    if (!expand(s, from / words, ends[s - chunk_begin] / words)) break;
  }
  ahead.reset();
  const bool complete = limit.empty() && s >= store.size();

  logic::CheckReport report;
  report.engine = "explicit";
  report.states = store.size();
  report.edges = edges;
  // The deepest state stored: the last one, one level below the one expanded when it was found.
  report.depth = store.size() > level_end ? level + 1 : level;
  report.complete = complete || open == 0;
  // Every invariant met a bad state before the search ended: the counts are those explored.
  report.stopped_early = !complete && limit.empty() && open == 0;
  report.limit = limit;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = task.properties[i];
    logic::PropertyResult r;
    r.name = p.name;
    r.formula = logic::to_string(p.formula);
    r.where = p.where;
    if (initial_count == 0) {
      r.verdict = logic::Verdict::Unknown;
      r.message =
          "no initial state: the assumptions exclude every initial situation, or none is stable "
          "(see the instability check)";
    } else if (violation[i] != kNoState) {
      r.verdict = logic::Verdict::Violated;
      r.trace = counterexample(ts, store, codec, parent, violation[i], limits);
      r.trace->marked = logic::atom_observables(*p.formula);
    } else if (complete) {
      r.verdict = logic::Verdict::Holds;
    } else {
      r.verdict = logic::Verdict::Unknown;
      r.message = "exploration stopped at the " + limit + " limit after " +
                  std::to_string(store.size()) + " states";
    }
    r.seconds = violation[i] != kNoState ? decided_at[i] : elapsed();
    report.results.push_back(std::move(r));
  }
  report.seconds = elapsed();
  return report;
}

}  // namespace sfcv::engine

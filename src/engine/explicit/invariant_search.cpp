#include "engine/explicit/invariant_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
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

constexpr std::uint32_t kNone = ~0U;

/// States enumerated together by the serial search: enough for a compiled enumerator to fill
/// its 64 lanes with several states, few enough that the work done past a stopping state is
/// small.
constexpr std::uint32_t kSerialChunkStates = 64;

/// How many targets ahead a store look-up is started: each misses the cache twice (its slot,
/// then the state the slot refers to), and the misses of several look-ups overlap.
constexpr std::uint32_t kAhead = StateStore::kLookAhead;

class InterpretedEnumerator final : public TargetEnumerator, semantics::SuccessorSink {
 public:
  InterpretedEnumerator(const semantics::TransitionSystem& ts, model::Budget limits)
      : ts_(ts), limits_(std::move(limits)) {}
  void targets(StateView state, std::vector<StateWord>& out) override {
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
    if (f.op == Op::Atom || f.op == Op::Compare) {
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
  for (auto x = s; x != kNone; x = parent[x]) path.push_back(x);
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

/// The threads of the parallel search. A job runs on this thread and on every worker at once,
/// each with its own enumerator, and takes its share of the work itself (from an atomic
/// counter), so it is over once its work is taken and every thread has left it.
class WorkerPool {
 public:
  using Job = std::function<void(TargetEnumerator&)>;

  WorkerPool(TargetEnumerator& own, unsigned threads) : own_(own) {
    for (unsigned t = 1; t < threads; ++t) {
      auto e = own.clone();
      if (!e) break;
      enumerators_.push_back(std::move(e));
    }
    for (auto& e : enumerators_) workers_.emplace_back([this, en = e.get()] { work(*en); });
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

/// A batch of stored states of the parallel search, expanded on every thread at once. A thread
/// takes kChunkStates sources at a time, enumerates their distinct targets and looks them up
/// while they are in its cache (a whole batch enumerated first and looked up afterwards cost
/// more per look-up: docs/benchmarks.md). A target not stored is staged by the first pair that
/// looks it up and claimed by the first pair in serial order that reaches it; the search
/// numbers the new states in claim order, which is the serial search's.
///
/// A pair's key is its chunk and its place among the chunk's targets, so keys follow the
/// serial order; a staged state's entry in the store is the key of the pair that staged it.
class ParallelBatch {
 public:
  static constexpr std::uint32_t kStates = 4096;
  static constexpr std::uint32_t kChunkStates = 64;
  struct Entry {
    std::uint32_t claim;  ///< the key of the first pair in serial order reaching the state
    std::uint32_t key;    ///< the key of the pair that staged it, whose words hold it
    std::uint32_t slot;
  };

  /// Expands the stored states [begin, end) on every thread of `pool`; afterwards entries()
  /// lists their new targets by claim. False when the store cannot stage them (more states
  /// than it numbers, a chunk of 2^24 targets, a slot its quotient form cannot record):
  /// nothing is staged then. An exception of an enumeration (a limit) is rethrown, with
  /// nothing staged.
  bool expand(WorkerPool& pool, StateStore& store, std::uint32_t begin, std::uint32_t end) {
    begin_ = begin;
    end_ = end;
    words_ = store.words_per_state();
    num_chunks_ = (end - begin + kChunkStates - 1) / kChunkStates;
    if (chunks_.size() < num_chunks_) chunks_.resize(num_chunks_);
    // Chunks prepare() enumerated for this batch are only staged.
    const std::uint32_t prepared = begin == prepared_begin_ ? prepared_chunks_ : 0;
    for (std::uint32_t c = prepared; c < num_chunks_; ++c) chunks_[c].enumerated = false;
    prepared_chunks_ = 0;
    unstageable_.store(false);
    if (!run(pool, store, room_for(begin, end))) {
      // More targets than the room made: stage them again in a table that holds them all.
      if (unstageable_.load() || !run(pool, store, pairs())) return false;
    }
    pairs_per_state_ = std::max<std::uint64_t>(pairs_per_state_, pairs() / (end - begin) + 1);
    for (auto& e : entries_) e.claim = claim_of(e.key);
    return true;
  }
  /// The batch's new states, in claim order once sort_entries() has run (after expand(), on
  /// one thread while the workers prepare the next batch).
  const std::vector<Entry>& entries() const { return entries_; }
  void sort_entries() {
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.claim < b.claim; });
  }
  /// Grows the store for the batch [begin, end) before expand() does, so that the table
  /// grows on this thread while the workers prepare the batch.
  void reserve_room(StateStore& store, std::uint32_t begin, std::uint32_t end) const {
    static_cast<void>(store.reserve_for_staging(room_for(begin, end)));
  }

  std::uint32_t end() const { return end_; }
  /// The keys of the pairs of source `s`: [first_key(s), end_key(s)), contiguous.
  std::uint32_t first_key(std::uint32_t s) const {
    const auto i = s - begin_;
    return i % kChunkStates == 0 ? key(i / kChunkStates, 0)
                                 : end_key_in_chunk(i / kChunkStates, i % kChunkStates - 1);
  }
  std::uint32_t end_key(std::uint32_t s) const {
    const auto i = s - begin_;
    return end_key_in_chunk(i / kChunkStates, i % kChunkStates);
  }
  /// Whether the last target the enumeration gave for source `s` repeats an earlier one.
  bool ends_with_repeat(std::uint32_t s) const {
    const auto i = s - begin_;
    return chunks_[i / kChunkStates].repeats[i % kChunkStates] != 0;
  }
  /// The words of the target of the pair of key `k`.
  const StateWord* target(std::uint32_t k) const {
    return chunks_[k >> kPairBits].targets.data() +
           static_cast<std::size_t>(k & kPairMask) * words_;
  }

 private:
  static constexpr std::uint32_t kPairBits = 24;
  static constexpr std::uint32_t kPairMask = (1U << kPairBits) - 1;
  // Keys stay below the staged bit of a slot.
  static_assert(kStates / kChunkStates <= (1U << (31 - kPairBits)));

  struct Chunk {
    bool enumerated = false;
    std::vector<StateWord> targets;
    std::vector<std::uint32_t> ends;    ///< per state: end of its targets in `targets`, in words
    std::vector<std::uint8_t> repeats;  ///< per state: its last target repeats an earlier one
    std::vector<std::uint32_t> table;   ///< scratch of keep_distinct_targets
    std::vector<std::uint32_t> claims;  ///< per pair that staged a state: its claim
  };
  static std::uint32_t key(std::uint32_t chunk, std::uint32_t pair) {
    return chunk << kPairBits | pair;
  }
  std::uint32_t end_key_in_chunk(std::uint32_t c, std::uint32_t i) const {
    return key(c, chunks_[c].ends[i] / words_);
  }
  std::uint32_t& claim_of(std::uint32_t k) { return chunks_[k >> kPairBits].claims[k & kPairMask]; }
  std::uint64_t pairs() const {
    std::uint64_t n = 0;
    for (std::uint32_t c = 0; c < num_chunks_; ++c) n += chunks_[c].targets.size() / words_;
    return n;
  }

  /// One pass over the chunks on every thread, after making room for `reserve` new states.
  /// False, with nothing staged, when their targets did not fit in the room (every chunk is
  /// enumerated then) or the store cannot number them.
  bool run(WorkerPool& pool, StateStore& store, std::uint64_t reserve) {
    entries_.clear();
    if (!store.reserve_for_staging(reserve)) {
      unstageable_.store(true);
      return false;
    }
    room_ = store.staging_room();
    used_.store(0);
    full_.store(false);
    range_.store(std::uint64_t{num_chunks_} << 32);
    arrivals_.store(0);
    pool.post([&](TargetEnumerator& e) { expand_chunks(e, store); });
    try {
      pool.join();
    } catch (...) {
      store.drop_staged();
      throw;
    }
    if (!full_.load()) return true;
    store.drop_staged();
    return false;
  }

  /// Enumerates chunk `c` of the batch at begin_, of `sources` sources in all.
  void enumerate_chunk(TargetEnumerator& e, const StateStore& store, std::uint32_t c,
                       std::uint32_t sources) {
    auto& chunk = chunks_[c];
    chunk.targets.clear();
    chunk.ends.clear();
    chunk.repeats.clear();
    const auto first = c * kChunkStates;
    const auto last = std::min(first + kChunkStates, sources);
    e.targets_of(store.range(begin_ + first, last - first), last - first, chunk.targets,
                 chunk.ends);
    keep_distinct_targets_of_each(chunk.targets, chunk.ends, words_, chunk.table, chunk.repeats);
    chunk.enumerated = true;
  }

 public:
  /// Starts enumerating, on the workers of `pool`, the whole chunks of the batch that will
  /// begin at `begin` whose sources lie below `stored` (stored already, so they do not move
  /// while the caller stores more: it reserved the room). Meanwhile the caller commits the
  /// batch before, and finish_preparing() ends the job; expand() then only stages those chunks.
  void prepare(WorkerPool& pool, const StateStore& store, std::uint32_t begin,
               std::uint32_t stored) {
    prepared_begin_ = begin;
    prepared_chunks_ = stored > begin ? std::min(stored - begin, kStates) / kChunkStates : 0;
    if (prepared_chunks_ == 0) return;
    begin_ = begin;
    words_ = store.words_per_state();
    if (chunks_.size() < prepared_chunks_) chunks_.resize(prepared_chunks_);
    for (std::uint32_t c = 0; c < prepared_chunks_; ++c) chunks_[c].enumerated = false;
    next_prepared_.store(0);
    preparing_ = true;
    pool.post([this, &store](TargetEnumerator& e) {
      for (;;) {
        const auto c = next_prepared_.fetch_add(1);
        if (c >= prepared_chunks_) break;
        enumerate_chunk(e, store, c, prepared_chunks_ * kChunkStates);
      }
    });
  }
  /// Ends prepare()'s job, taking a share of what is left. A limit met by an enumeration
  /// drops every prepared chunk: expand() enumerates them again, and meets it there.
  void finish_preparing(WorkerPool& pool) {
    if (!std::exchange(preparing_, false)) return;
    try {
      pool.join();
    } catch (const LimitReached&) {
      prepared_chunks_ = 0;
    }
  }

 private:
  void expand_chunks(TargetEnumerator& e, StateStore& store) {
    std::vector<std::uint64_t> hashes;
    std::vector<Entry> mine;
    const bool from_back = (arrivals_.fetch_add(1) & 1U) != 0;
    for (;;) {
      const auto c = take(from_back);
      if (c == kNone) break;
      auto& chunk = chunks_[c];
      if (!chunk.enumerated) enumerate_chunk(e, store, c, end_ - begin_);
      const std::size_t pairs = chunk.targets.size() / words_;
      if (pairs > kPairMask) unstageable_.store(true, std::memory_order_relaxed);
      // Past the room the table would fill: the rest is only enumerated, for a second run.
      if (unstageable_.load(std::memory_order_relaxed) || full_.load(std::memory_order_relaxed) ||
          used_.fetch_add(pairs) + pairs > room_) {
        full_.store(true, std::memory_order_relaxed);
        continue;
      }
      stage_chunk(c, store, hashes, mine);
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    entries_.insert(entries_.end(), mine.begin(), mine.end());
  }

  void stage_chunk(std::uint32_t c, StateStore& store, std::vector<std::uint64_t>& hashes,
                   std::vector<Entry>& mine) {
    auto& chunk = chunks_[c];
    const auto pairs = static_cast<std::uint32_t>(chunk.targets.size() / words_);
    chunk.claims.resize(pairs);
    hashes.resize(pairs);
    auto target_of = [&](std::uint32_t p) { return StateView(target(key(c, p)), words_); };
    for (std::uint32_t p = 0; p < pairs; ++p) hashes[p] = store.state_hash(target_of(p));
    auto words_of = [this](std::uint32_t k) { return target(k); };
    // As the serial search: the look-ups miss the cache, so the slot of the pair kAhead ahead,
    // and the state its slot refers to kAhead / 2 ahead, are loaded while this one is looked up.
    for (std::uint32_t p = 0; p < pairs; ++p) {
      if (p + kAhead < pairs) store.prefetch_slot(hashes[p + kAhead]);
      if (p + kAhead / 2 < pairs) store.prefetch_state(hashes[p + kAhead / 2]);
      const auto t = target_of(p);
      if (store.stored_before_staging(t, hashes[p])) continue;
      const auto k = key(c, p);
      // Written before stage() can publish pair p, read by the threads that find it there.
      std::atomic_ref<std::uint32_t>(chunk.claims[p]).store(k, std::memory_order_relaxed);
      const auto found = store.stage(t, hashes[p], k, words_of);
      if (found.no_room) {
        // The quotient form cannot record the slot (a probe too long, never seen at the
        // loads kept): nothing of the batch is kept, and the search goes on serially, where
        // the store leaves that form.
        unstageable_.store(true, std::memory_order_relaxed);
        full_.store(true, std::memory_order_relaxed);
        return;
      }
      if (found.stored) continue;
      if (found.first) {
        mine.push_back({0, k, found.slot});
        continue;
      }
      std::atomic_ref<std::uint32_t> claim(claim_of(found.entry));
      auto seen = claim.load(std::memory_order_relaxed);
      while (k < seen && !claim.compare_exchange_weak(seen, k, std::memory_order_relaxed)) {
      }
    }
  }

  /// The targets to make room for when expanding the sources [begin, end): as many per source
  /// as the most any batch gave so far.
  std::uint64_t room_for(std::uint32_t begin, std::uint32_t end) const {
    return std::uint64_t{end - begin} * pairs_per_state_;
  }

  std::uint32_t begin_ = 0, end_ = 0, words_ = 1;
  std::vector<Chunk> chunks_;
  std::uint32_t num_chunks_ = 0;
  std::uint64_t pairs_per_state_ = 16;  ///< the most per source of a batch so far, plus one
  std::uint32_t prepared_begin_ = kNone, prepared_chunks_ = 0;
  std::atomic<std::uint32_t> next_prepared_{0};
  bool preparing_ = false;
  std::vector<Entry> entries_;
  /// The chunks not taken yet, [low, high) as high << 32 | low: half the threads take them
  /// from the front, half from the back, so that each works on sources far from the others'.
  std::atomic<std::uint64_t> range_{0};
  std::atomic<std::uint32_t> arrivals_{0};
  std::uint32_t take(bool from_back) {
    auto r = range_.load(std::memory_order_relaxed);
    for (;;) {
      const auto low = static_cast<std::uint32_t>(r), high = static_cast<std::uint32_t>(r >> 32);
      if (low >= high) return kNone;
      const auto next = from_back ? (r - (std::uint64_t{1} << 32)) : r + 1;
      if (range_.compare_exchange_weak(r, next, std::memory_order_relaxed))
        return from_back ? high - 1 : low;
    }
  }
  std::uint64_t room_ = 0;              ///< how many pairs may stage states in this run
  std::atomic<std::uint64_t> used_{0};  ///< the pairs of the chunks staged so far
  std::atomic<bool> full_{false};       ///< a chunk did not fit in the room
  std::atomic<bool> unstageable_{false};
  std::mutex mutex_;
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
  std::vector<std::uint32_t> violation(n, kNone);  ///< first violating state per property
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
      if (violation[i] != kNone) continue;
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
  parent.assign(initial_count, kNone);

  std::string limit = initial.limit;
  std::uint64_t edges = 0;
  std::vector<StateWord> targets;
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
  // distinct targets (one edge per source and target, as the graph) are `targets`, the end of
  // each one's in `ends` (in words), whether its last target repeated an earlier one in
  // `repeats`, and each target's hash in `hashes`.
  std::vector<std::uint32_t> ends, table;
  std::vector<std::uint8_t> repeats;
  std::vector<std::uint64_t> hashes;
  std::uint32_t chunk_begin = 0, chunk_end = 0;
  // Stores the targets [first, last) of state s and judges the new ones. False: a limit
  // stopped it. The look-ups of the chunk's later targets are started early.
  auto expand = [&](std::uint32_t s, std::size_t first, std::size_t last) {
    just_violated.clear();
    const std::uint64_t max_states = limits.max_states;
    const std::size_t chunk_targets = hashes.size();
    if (words == 1) {
      // As the graph builder: no state is stored beyond the limit, and the state being expanded
      // when it is reached stays unexpanded.
      const std::uint32_t known = store.size();
      const std::uint64_t size_cap = max_states > 0 ? max_states + 1 : ~std::uint64_t{0};
      if (store.insert_new_words(targets.data(), hashes.data(), first, last, chunk_targets,
                                 size_cap) < last)
        limit = "states";
      for (std::uint32_t t = known; t < store.size(); ++t) {
        parent.push_back(s);
        if (open > 0) judge(t);
      }
    } else {
      for (std::size_t k = first; k < last; ++k) {
        if (k + kAhead < chunk_targets) store.prefetch_slot(hashes[k + kAhead]);
        if (k + kAhead / 2 < chunk_targets) store.prefetch_state(hashes[k + kAhead / 2]);
        if (max_states > 0 && store.size() > max_states) {
          limit = "states";
          break;
        }
        const auto t = store.insert_if_new(StateView(targets.data() + k * words, words), hashes[k]);
        if (t == StateStore::kAbsent) continue;
        parent.push_back(s);
        if (open > 0) judge(t);
      }
    }
    // A repeated last target counts as a look-up past the limit, as in the graph builder.
    if (limit.empty() && max_states > 0 && store.size() > max_states &&
        repeats[s - chunk_begin] != 0)
      limit = "states";
    if (!limit.empty()) {
      // As in the graph, the state stays unexpanded and what it reached has no known path.
      for (auto i : just_violated) violation[i] = kNone;
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
  std::uint32_t stopped_at = kNone;  ///< the state whose enumeration threw
  Limit stopped_by = Limit::Time;
  auto enumerate = [&](std::uint32_t from) {
    const auto end = static_cast<std::uint32_t>(
        std::min<std::uint64_t>({store.size(), std::uint64_t{from} + kSerialChunkStates,
                                 (std::uint64_t{from} | poll_mask) + 1}));
    targets.clear();
    ends.clear();
    chunk_begin = from;
    try {
      if (limits.max_memory_bytes > 0) enumerator->set_memory_in_use(memory());
      enumerator->targets_of(store.range(from, end - from), end - from, targets, ends);
    } catch (const LimitReached& stop) {
      if (stop.which() == Limit::Enumeration) throw;
      stopped_at = from + static_cast<std::uint32_t>(ends.size());
      stopped_by = stop.which();
    }
    chunk_end = from + static_cast<std::uint32_t>(ends.size());
    repeats.clear();
    keep_distinct_targets_of_each(targets, ends, words, table, repeats);
    hashes.resize(targets.size() / words);
    for (std::size_t k = 0; k < hashes.size(); ++k)
      hashes[k] = store.state_hash(StateView(targets.data() + k * words, words));
  };
  std::uint32_t s = 0;
  // Two batches: while this thread commits one, the workers enumerate the next one's sources.
  ParallelBatch batches[2];  // outlive the pool's workers
  unsigned current = 0;
  WorkerPool pool(*enumerator, threads);
  // A batch whose enumeration threw (a limit, on some thread) or that the store cannot stage:
  // the search goes on from its first state on this thread alone, so the state that stops it
  // is the one-thread search's.
  bool serial = !pool.parallel();
  if (!serial) {
    bool stopped = false;
    while (!stopped && s < store.size()) {
      auto& batch = batches[current];
      auto& next = batches[current ^ 1];
      current ^= 1;
      try {
        if (!batch.expand(pool, store, s, std::min(store.size(), s + ParallelBatch::kStates))) {
          serial = true;
          break;
        }
      } catch (const LimitReached& stop) {
        if (stop.which() == Limit::Enumeration) throw;
        serial = true;
        break;
      }
      // The batch's new states are numbered, stored and judged here, in the serial search's
      // order: source by source, each source's new states in the order of their first pairs.
      const auto& fresh = batch.entries();
      // The workers enumerate the next batch's stored sources meanwhile: they read the stored
      // states, which the room reserved keeps in place.
      store.reserve_states(fresh.size());
      next.prepare(pool, store, batch.end(), store.size());
      batch.sort_entries();
      std::size_t k = 0;
      for (; s < batch.end(); ++s) {
        if (!limit.empty() || open == 0 || !before(s)) {
          stopped = true;
          break;
        }
        const auto pairs_end = batch.end_key(s);
        just_violated.clear();
        for (; k < fresh.size() && fresh[k].claim < pairs_end; ++k) {
          const auto t =
              store.commit_staged(fresh[k].slot, StateView(batch.target(fresh[k].key), words));
          parent.push_back(s);
          if (open > 0) judge(t);
          // As expand(): the next target of this source, if any (a repeat counts), finds
          // the store past the limit.
          if (limits.max_states > 0 && store.size() > limits.max_states &&
              (fresh[k].claim + 1 < pairs_end || batch.ends_with_repeat(s))) {
            limit = "states";
            ++k;
            break;
          }
        }
        if (!limit.empty()) {
          for (auto i : just_violated) violation[i] = kNone;
          open += just_violated.size();
          stopped = true;
          break;
        }
        edges += pairs_end - batch.first_key(s);
      }
      if (k < fresh.size()) store.drop_staged();
      // Meanwhile too: the table grows for the next batch (it holds no staged state now).
      if (!stopped && s < store.size())
        next.reserve_room(store, s, std::min(store.size(), s + ParallelBatch::kStates));
      next.finish_preparing(pool);
    }
  }
  if (serial) {
    for (; limit.empty() && open > 0 && s < store.size(); ++s) {
      if (!before(s)) break;
      if (s >= chunk_end && s != stopped_at) enumerate(s);
      if (s == stopped_at) {
        limit = to_string(stopped_by);
        break;
      }
      const std::uint32_t from = s == chunk_begin ? 0 : ends[s - chunk_begin - 1];
      if (!expand(s, from / words, ends[s - chunk_begin] / words)) break;
    }
  }
  const bool complete = limit.empty() && s >= store.size();

  logic::CheckReport report;
  report.engine = "explicit";
  report.states = store.size();
  report.edges = edges;
  // The deepest state stored: the last one, one level below the one expanded when it was found.
  report.depth = store.size() > level_end ? level + 1 : level;
  report.complete = complete || open == 0;
  report.limit = limit;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = task.properties[i];
    logic::PropertyResult r;
    r.name = p.name;
    r.formula = logic::to_string(p.formula);
    r.where = p.where;
    if (initial_count == 0) {
      r.verdict = logic::Verdict::Unknown;
      r.message = "no initial state: the assumptions exclude every initial situation";
    } else if (violation[i] != kNone) {
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
    r.seconds = violation[i] != kNone ? decided_at[i] : elapsed();
    report.results.push_back(std::move(r));
  }
  report.seconds = elapsed();
  return report;
}

}  // namespace sfcv::engine

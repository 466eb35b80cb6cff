#include "engine/explicit/invariant_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

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
                            const std::vector<std::uint32_t>& parent, std::uint32_t s,
                            const model::Budget& budget) {
  std::vector<std::uint32_t> path;
  for (auto x = s; x != kNone; x = parent[x]) path.push_back(x);
  std::reverse(path.begin(), path.end());
  logic::Trace trace;
  trace.kind = logic::TraceKind::Counterexample;
  std::vector<std::int64_t> previous;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto view = store.at(path[i]);
    logic::TraceStep step;
    step.state.assign(view.begin(), view.end());
    if (i == 0) {
      step.inputs = initial_inputs(ts, step.state, budget);
    } else {
      EdgeLabel label(step.state);
      const auto from = store.at(path[i - 1]);
      const std::vector<StateWord> source(from.begin(), from.end());
      ts.successors(source, label);
      step.inputs = logic::pick_inputs(label.condition(), ts.inputs(), previous);
      step.fired = label.fired;
    }
    previous = step.inputs;
    trace.steps.push_back(std::move(step));
  }
  return trace;
}

/// Successor generation for batches of stored states on several threads. The search stores
/// and judges states on its own thread, in BFS order, from the targets computed here, so the
/// numbering and every result are those of the one-thread search; only the enumeration, two
/// thirds of the instructions of a compiled search, runs in parallel, and the next batch is
/// enumerated while the current one is stored.
class ParallelTargets {
 public:
  static constexpr std::uint32_t kBatchStates = 4096;
  static constexpr std::uint32_t kChunkStates = 64;

  /// The states [begin, end) of one batch, copied (the store grows while they are expanded),
  /// and their targets, chunk by chunk.
  class Batch {
   public:
    std::uint32_t begin() const { return begin_; }
    std::uint32_t end() const { return end_; }
    bool empty() const { return begin_ == end_; }
    /// The targets of state `s` of this batch: (first word, number of words).
    std::pair<const StateWord*, std::size_t> targets(std::uint32_t s) const {
      const auto i = s - begin_;
      const auto& c = chunks_[i / kChunkStates];
      const auto k = i % kChunkStates;
      const std::uint32_t from = k == 0 ? 0 : c.ends[k - 1];
      return {c.targets.data() + from, c.ends[k] - from};
    }

   private:
    friend class ParallelTargets;
    struct Chunk {
      std::vector<StateWord> targets;
      std::vector<std::uint32_t> ends;  ///< per state: end of its targets in `targets`
    };
    std::uint32_t begin_ = 0, end_ = 0;
    std::vector<StateWord> states_;
    std::vector<Chunk> chunks_;
    std::uint32_t num_chunks_ = 0;
    std::atomic<std::uint32_t> next_{0};  ///< the next chunk to take
    std::uint32_t completed_ = 0;         ///< guarded by the pool's mutex, as active_
    std::uint32_t active_ = 0;            ///< workers inside this batch
    std::exception_ptr error_;
  };

  ParallelTargets(TargetEnumerator& own, unsigned threads, std::uint32_t words)
      : own_(own), words_(words) {
    for (unsigned t = 1; t < threads; ++t) {
      auto e = own.clone();
      if (!e) break;
      enumerators_.push_back(std::move(e));
    }
    for (auto& e : enumerators_) workers_.emplace_back([this, en = e.get()] { work(*en); });
  }
  ~ParallelTargets() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }
  ParallelTargets(const ParallelTargets&) = delete;
  ParallelTargets& operator=(const ParallelTargets&) = delete;

  bool parallel() const { return !workers_.empty(); }

  /// Copies the states [begin, end) of `store` into `b` and lets the workers enumerate them.
  void start(Batch& b, const StateStore& store, std::uint32_t begin, std::uint32_t end) {
    b.begin_ = begin;
    b.end_ = end;
    b.states_.resize(static_cast<std::size_t>(end - begin) * words_);
    for (std::uint32_t s = begin; s < end; ++s) {
      const auto v = store.at(s);
      std::copy(v.begin(), v.end(),
                b.states_.begin() + static_cast<std::ptrdiff_t>(s - begin) * words_);
    }
    b.num_chunks_ = (end - begin + kChunkStates - 1) / kChunkStates;
    if (b.chunks_.size() < b.num_chunks_) b.chunks_.resize(b.num_chunks_);
    b.next_.store(0);
    b.completed_ = 0;
    b.error_ = nullptr;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      job_ = &b;
      ++generation_;
    }
    wake_.notify_all();
  }

  /// Enumerates what is left of `b` on this thread, waits for the workers, and rethrows what
  /// an enumeration threw.
  void finish(Batch& b) {
    run(b, own_);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return b.completed_ == b.num_chunks_ && b.active_ == 0; });
    if (job_ == &b) job_ = nullptr;
    if (b.error_) std::rethrow_exception(b.error_);
  }

  /// Stops handing out the chunks of `b` and waits until no worker is inside it.
  void abandon(Batch& b) {
    b.next_.store(b.num_chunks_);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return b.active_ == 0; });
    if (job_ == &b) job_ = nullptr;
  }

 private:
  void work(TargetEnumerator& e) {
    std::unique_lock<std::mutex> lock(mutex_);
    std::uint64_t seen = 0;
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || (job_ && generation_ != seen); });
      if (stop_) return;
      seen = generation_;
      Batch& b = *job_;
      ++b.active_;
      lock.unlock();
      run(b, e);
      lock.lock();
      --b.active_;
      done_.notify_all();
    }
  }

  void run(Batch& b, TargetEnumerator& e) {
    for (;;) {
      const auto c = b.next_.fetch_add(1);
      if (c >= b.num_chunks_) return;
      auto& chunk = b.chunks_[c];
      chunk.targets.clear();
      chunk.ends.clear();
      std::exception_ptr error;
      try {
        const auto first = c * kChunkStates;
        const auto last = std::min(first + kChunkStates, b.end_ - b.begin_);
        e.targets_of(StateView(b.states_.data() + static_cast<std::size_t>(first) * words_,
                               static_cast<std::size_t>(last - first) * words_),
                     last - first, chunk.targets, chunk.ends);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex_);
      if (error && !b.error_) b.error_ = error;
      if (++b.completed_ == b.num_chunks_) done_.notify_all();
    }
  }

  TargetEnumerator& own_;
  std::uint32_t words_;
  std::vector<std::unique_ptr<TargetEnumerator>> enumerators_;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  Batch* job_ = nullptr;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
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

  const std::size_t n = task.properties.size();
  std::vector<std::uint32_t> violation(n, kNone);  ///< first violating state per property
  std::vector<double> decided_at(n, 0);
  std::size_t open = n;
  StateStore store(ts.layout().words());
  std::vector<std::uint32_t> parent;
  // Checks a newly stored state against every invariant still open.
  std::vector<std::size_t> just_violated;  ///< properties violated while expanding this state
  auto judge = [&](std::uint32_t s) {
    const auto view = store.at(s);
    for (std::size_t i = 0; i < n; ++i)
      if (violation[i] == kNone && !holds(*task.properties[i].formula->args[0], ts, view)) {
        violation[i] = s;
        decided_at[i] = elapsed();
        just_violated.push_back(i);
        --open;
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
    Initial(StateStore& st, const model::Budget& b, std::function<bool(std::uint32_t)> judge)
        : store(st), max_states(b.max_states), poll(b, 64), judge_(std::move(judge)) {}
    void successor(const semantics::Successor& s) override {
      if (max_states > 0 && store.size() > max_states) {
        limit = "states";
        throw StopInitial{};
      }
      if (poll.tick()) {
        limit = "time";
        throw StopInitial{};
      }
      const auto [index, fresh] = store.insert(s.target);
      if (fresh && !judge_(index)) throw StopInitial{};
    }
    StateStore& store;
    std::uint64_t max_states;
    model::BudgetPoll poll;
    std::string limit;

   private:
    std::function<bool(std::uint32_t)> judge_;
  } initial(store, limits, [&](std::uint32_t s) {
    judge(s);
    return open > 0;
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
  std::vector<std::uint32_t> stamp;  ///< per state: 1 + the last source that reached it
  const std::uint32_t words = std::max<std::uint32_t>(ts.layout().words(), 1);
  auto memory = [&] { return store.memory_bytes() + (parent.capacity() + stamp.capacity()) * 4; };
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
  // Stores the targets of state s and judges the new ones. False: a limit stopped it.
  auto expand = [&](std::uint32_t s, const StateWord* found, std::size_t count) {
    std::uint64_t out_edges = 0;
    just_violated.clear();
    const std::uint64_t max_states = limits.max_states;
    for (std::size_t k = 0; k < count; k += words) {
      // As the graph builder: no state is stored beyond the limit, and the state being expanded
      // when it is reached stays unexpanded.
      if (max_states > 0 && store.size() > max_states) {
        limit = "states";
        break;
      }
      const auto [t, fresh] = store.insert(StateView(found + k, words));
      if (fresh) parent.push_back(s);
      if (t >= stamp.size()) stamp.resize(std::max<std::size_t>(t + 1, 2 * stamp.size()), 0);
      if (stamp[t] == s + 1) continue;  // the same target again: one edge per (source, target)
      stamp[t] = s + 1;
      ++out_edges;
      if (fresh && open > 0) judge(t);
    }
    if (!limit.empty()) {
      // As in the graph, the state stays unexpanded and what it reached has no known path.
      for (auto i : just_violated) violation[i] = kNone;
      open += just_violated.size();
      return false;
    }
    edges += out_edges;
    return true;
  };
  // The serial search enumerates the stored states [chunk_begin, chunk_end) together; `ends`
  // holds the end of each one's targets in `targets`. A chunk never crosses a clock poll, so
  // the enumeration done between two reads of the clock is what it was state by state.
  std::vector<std::uint32_t> ends;
  std::uint32_t chunk_begin = 0, chunk_end = 0;
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
  };
  std::uint32_t s = 0;
  ParallelTargets::Batch batches[2];  // outlive the pool's workers
  ParallelTargets pool(*enumerator, threads, words);
  // A batch whose enumeration threw (a limit, on some worker): the search goes on from its
  // first state on this thread alone, so the state that stops it is the one-thread search's.
  bool serial = !pool.parallel();
  if (!serial) {
    auto* cur = &batches[0];
    auto* next = &batches[1];
    auto batch_end = [&](std::uint32_t from) {
      return std::min<std::uint32_t>(store.size(), from + ParallelTargets::kBatchStates);
    };
    auto finished = [&](ParallelTargets::Batch& b) {
      try {
        pool.finish(b);
        return true;
      } catch (const LimitReached& stop) {
        if (stop.which() == Limit::Enumeration) throw;
        serial = true;
        s = b.begin();
        return false;
      }
    };
    pool.start(*cur, store, 0, batch_end(0));
    bool stopped = !finished(*cur);
    while (!stopped && !cur->empty()) {
      // The states already stored past this batch are enumerated while it is stored.
      pool.start(*next, store, cur->end(), batch_end(cur->end()));
      for (s = cur->begin(); s < cur->end(); ++s) {
        if (!limit.empty() || open == 0 || !before(s)) {
          stopped = true;
          break;
        }
        const auto [first, count] = cur->targets(s);
        if (!expand(s, first, count)) {
          stopped = true;
          break;
        }
      }
      if (stopped) {
        pool.abandon(*next);
        break;
      }
      if (!finished(*next)) break;
      if (next->empty()) {
        pool.start(*next, store, cur->end(), batch_end(cur->end()));
        if (!finished(*next)) break;
      }
      std::swap(cur, next);
    }
    if (!stopped && !serial) s = store.size();
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
      if (!expand(s, targets.data() + from, ends[s - chunk_begin] - from)) break;
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
      r.trace = counterexample(ts, store, parent, violation[i], limits);
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

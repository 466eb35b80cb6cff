// Explicit exploration on the parallel-branch family (sfcv-gen parallel N --selector: 2^N + 1
// states, N successors per state), against naive breadth-first searches over std::unordered_set
// measured in the same run, plus the state hash set alone.
//
//   Explore/N          sfcv's explorer (build_reachable_situation_graph, no conditions kept)
//   NaiveBfsSameTs/N   the same successor function, states in std::unordered_set<std::string>
//   NaiveToggles/N     N Boolean toggles as a bit mask in std::unordered_set<uint64_t> (the
//                      issue's "naive C++ BFS" baseline: no chart semantics at all)
//   Successors/N       successor generation alone, over the first 4096 states
//   StateStore/N       StateStore::insert of 2^N distinct one-word states
//   UnorderedSet/N     std::unordered_set<uint64_t>::insert of the same states
// Counters: items_per_second is states per second (successors per second for Successors).

#include <benchmark/benchmark.h>

#include <deque>
#include <string>
#include <unordered_set>
#include <vector>

#include "chart_families.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "engine/explicit/state_store.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_system.hpp"

namespace {

using namespace sfcv;

semantics::TransitionSystemPtr parallel_system(std::uint32_t n) {
  static std::deque<model::Project> keep;  // the system refers to its project (stable addresses)
  auto loaded = io::load_iec_text(bench::parallel_branches_iec(n, true), "parallel.st");
  if (!loaded.project) throw std::runtime_error("parallel family does not load");
  keep.push_back(std::move(*loaded.project));
  model::Diagnostics d;
  auto ts = semantics::make_iec61131_system(keep.back(), semantics::Iec61131Options{}, d);
  if (!ts) throw std::runtime_error("parallel family has no IEC system");
  return ts;
}

class Collect : public semantics::SuccessorSink {
 public:
  std::vector<std::vector<semantics::StateWord>> targets;
  void successor(const semantics::Successor& s) override {
    targets.emplace_back(s.target.begin(), s.target.end());
  }
};

class Count : public semantics::SuccessorSink {
 public:
  std::uint64_t n = 0;
  void successor(const semantics::Successor& s) override {
    n += s.target.size();  // touch the state
  }
};

void Explore(benchmark::State& state) {
  const auto ts = parallel_system(static_cast<std::uint32_t>(state.range(0)));
  engine::ExplorationOptions o;
  o.keep_conditions = false;
  o.keep_fired = false;
  std::uint64_t states = 0;
  for (auto _ : state) {
    const auto g = engine::build_reachable_situation_graph(*ts, o);
    states += g.num_states();
    benchmark::DoNotOptimize(g.num_edges());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(states));
}

std::string key(semantics::StateView s) {
  return {reinterpret_cast<const char*>(s.data()), s.size() * sizeof(semantics::StateWord)};
}

void NaiveBfsSameTs(benchmark::State& state) {
  const auto ts = parallel_system(static_cast<std::uint32_t>(state.range(0)));
  std::uint64_t states = 0;
  for (auto _ : state) {
    std::unordered_set<std::string> seen;
    std::deque<std::vector<semantics::StateWord>> queue;
    Collect c;
    ts->initial_states(c);
    for (auto& s : c.targets)
      if (seen.insert(key(s)).second) queue.push_back(std::move(s));
    while (!queue.empty()) {
      Collect next;
      ts->successors(queue.front(), next);
      queue.pop_front();
      for (auto& s : next.targets)
        if (seen.insert(key(s)).second) queue.push_back(std::move(s));
    }
    states += seen.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(states));
}

void NaiveToggles(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  std::uint64_t states = 0;
  for (auto _ : state) {
    std::unordered_set<std::uint64_t> seen{0};
    std::deque<std::uint64_t> queue{0};
    while (!queue.empty()) {
      const auto s = queue.front();
      queue.pop_front();
      for (std::uint32_t i = 0; i < n; ++i) {
        const auto t = s ^ (std::uint64_t{1} << i);
        if (seen.insert(t).second) queue.push_back(t);
      }
    }
    states += seen.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(states));
}

void Successors(benchmark::State& state) {
  const auto ts = parallel_system(static_cast<std::uint32_t>(state.range(0)));
  engine::ExplorationOptions o;
  o.max_states = 4096;
  const auto g = engine::build_reachable_situation_graph(*ts, o);
  Count c;
  std::uint64_t calls = 0;
  for (auto _ : state) {
    for (std::uint32_t s = 0; s < g.num_states(); ++s) ts->successors(g.states().at(s), c);
    calls += g.num_states();
  }
  benchmark::DoNotOptimize(c.n);
  state.counters["states_expanded_per_s"] =
      benchmark::Counter(static_cast<double>(calls), benchmark::Counter::kIsRate);
}

std::vector<std::uint64_t> scrambled(std::uint32_t n) {
  std::vector<std::uint64_t> v(std::size_t{1} << n);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = (i * 0x9E3779B97F4A7C15ULL) | 1;
  return v;
}

void StateStoreInsert(benchmark::State& state) {
  const auto values = scrambled(static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) {
    engine::StateStore store(1);
    for (auto v : values) store.insert(semantics::StateView(&v, 1));
    benchmark::DoNotOptimize(store.size());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * values.size()));
}

void UnorderedSetInsert(benchmark::State& state) {
  const auto values = scrambled(static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) {
    std::unordered_set<std::uint64_t> set;
    for (auto v : values) set.insert(v);
    benchmark::DoNotOptimize(set.size());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * values.size()));
}

}  // namespace

BENCHMARK(Explore)->Arg(12)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(NaiveBfsSameTs)->Arg(12)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(NaiveToggles)->Arg(12)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(Successors)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(StateStoreInsert)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(UnorderedSetInsert)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

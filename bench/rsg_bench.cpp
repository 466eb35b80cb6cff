// RSG construction speed on a scalable grafcet family: N independent two-step loops, loop i
// being A_i --x_i--> B_i --!x_i--> A_i on its own input. Under the single-input-change rule its
// RSG has 2^N situations and N * 2^N evolutions. A second family adds inputs that nothing reads:
// the cost must not depend on them.

#include <benchmark/benchmark.h>

#include "engine/explicit/reachable_situation_graph.hpp"
#include "model/chart.hpp"
#include "semantics/grafcet_system.hpp"

namespace {

using namespace sfcv;

model::Project loops(int n, int unused_inputs) {
  model::Project p;
  p.dialect = model::Dialect::Grafcet;
  p.pous.emplace_back();
  auto& pou = p.pous.back();
  pou.name = "LOOPS";
  for (int i = 0; i < n; ++i) {
    const std::string x = "x" + std::to_string(i);
    pou.variables.push_back({x,
                             model::VarDirection::Input,
                             model::Type::boolean(),
                             std::nullopt,
                             "",
                             {},
                             {},
                             {},
                             false});
    model::Chart c;
    c.name = "G" + std::to_string(i);
    model::Step a, b;
    a.name = "A" + std::to_string(i);
    a.initial = true;
    b.name = "B" + std::to_string(i);
    c.steps = {a, b};
    model::Transition t1, t2;
    t1.sources = {a.name};
    t1.targets = {b.name};
    t1.guard = model::make_name(x);
    t2.sources = {b.name};
    t2.targets = {a.name};
    t2.guard = model::make_unary(model::ExprKind::Not, model::make_name(x));
    c.transitions = {t1, t2};
    pou.charts.push_back(c);
  }
  for (int u = 0; u < unused_inputs; ++u)
    pou.variables.push_back({"u" + std::to_string(u),
                             model::VarDirection::Input,
                             model::Type::boolean(),
                             std::nullopt,
                             "",
                             {},
                             {},
                             {}});
  return p;
}

void run(benchmark::State& state, int n, int unused) {
  const auto project = loops(n, unused);
  model::Diagnostics d;
  const auto ts = semantics::make_grafcet_system(project, {}, d);
  std::uint64_t situations = 0, evolutions = 0;
  for (auto _ : state) {
    const auto g = engine::build_reachable_situation_graph(*ts);
    situations += g.num_states();
    evolutions += g.num_edges();
    benchmark::DoNotOptimize(g.num_edges());
  }
  state.counters["situations"] =
      static_cast<double>(situations) / static_cast<double>(state.iterations());
  state.counters["evolutions"] =
      static_cast<double>(evolutions) / static_cast<double>(state.iterations());
  state.counters["situations/s"] =
      benchmark::Counter(static_cast<double>(situations), benchmark::Counter::kIsRate);
}

void BM_RsgIndependentLoops(benchmark::State& state) {
  run(state, static_cast<int>(state.range(0)), 0);
}
BENCHMARK(BM_RsgIndependentLoops)->DenseRange(4, 14, 2)->Unit(benchmark::kMillisecond);

void BM_RsgUnusedInputs(benchmark::State& state) {
  run(state, 8, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_RsgUnusedInputs)->Arg(0)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

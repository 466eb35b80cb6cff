// The BDD image on the parallel-branch family with free inputs (sfcv-gen parallel N: 2^N + 1
// reachable states, 2^N successors each): one image of the full reachable set, and the whole
// least fixpoint from the initial states (what `sfcv check --engine bdd` does for AG p).
//
//   ImageOfReachable/N   image(R) with R the reachable set
//   Reachability/N       R = mu Z. I | image(Z), breadth-first (N + 2 images)
// Counter: states (the size of R, from the BDD).

#include <benchmark/benchmark.h>

#include <deque>

#include "chart_families.hpp"
#include "engine/bdd/symbolic_system.hpp"
#include "io/load.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"

namespace {

using namespace sfcv;
using engine::SymbolicSystem;

struct Model {
  model::Project project;
  semantics::TransitionSystemPtr ts;
  std::unique_ptr<SymbolicSystem> sys;
};

Model& parallel_model(std::uint32_t n) {
  static std::deque<Model> models;  // stable addresses: systems refer to their project
  auto loaded = io::load_iec_text(bench::parallel_branches_iec(n, false), "parallel.st");
  if (!loaded.project) throw std::runtime_error("parallel family does not load");
  auto& m = models.emplace_back();
  m.project = std::move(*loaded.project);
  model::Diagnostics d;
  m.ts = semantics::make_iec61131_system(m.project, semantics::Iec61131Options{}, d);
  if (!m.ts) throw std::runtime_error("parallel family has no IEC system");
  m.sys = std::make_unique<SymbolicSystem>(*m.ts, semantics::build_iec61131_circuit(*m.ts));
  return m;
}

SymbolicSystem::Bdd reachable(const SymbolicSystem& sys) {
  auto r = sys.initial();
  auto frontier = r;
  while (!frontier.is_false()) {
    const auto next = sys.image(frontier);
    frontier = next & !r;
    r = r | next;
  }
  return r;
}

void ImageOfReachable(benchmark::State& state) {
  auto& m = parallel_model(static_cast<std::uint32_t>(state.range(0)));
  const auto r = reachable(*m.sys);
  for (auto _ : state) benchmark::DoNotOptimize(m.sys->image(r));
  state.counters["states"] = m.sys->count(r);
}

void Reachability(benchmark::State& state) {
  auto& m = parallel_model(static_cast<std::uint32_t>(state.range(0)));
  double states = 0;
  for (auto _ : state) states = m.sys->count(reachable(*m.sys));
  state.counters["states"] = states;
}

}  // namespace

BENCHMARK(ImageOfReachable)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK(Reachability)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

// Successor generation of the IEC 61131-3 semantics on generated charts with 8 and 64 Boolean
// inputs. Enumerating valuations would cost 2^64; the lazy decisions cost what the enabled
// guards read: time per call grows linearly with the chart, never with 2^inputs.
//
//   Alternatives/N : one step with N alternative branches, branch i guarded by input i
//                    (N + 1 successors).
//   Conjunction/N  : one transition guarded by i0 AND ... AND i(N-1) (2 successors, N + 1 cubes).
//   Ring/N         : N steps in a loop, step k left on input k; N inputs, 2 successors per state.

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "model/chart.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"

namespace {

using namespace sfcv;

enum class Shape { Alternatives, Conjunction, Ring };

model::Project make_chart(Shape shape, int n) {
  model::Pou pou;
  pou.name = "MAIN";
  for (int i = 0; i < n; ++i)
    pou.variables.push_back(model::Variable{"i" + std::to_string(i),
                                            model::VarDirection::Input,
                                            model::Type::boolean(),
                                            std::nullopt,
                                            "",
                                            {},
                                            {},
                                            {}});
  model::Chart c;
  c.name = "MAIN";
  auto step = [&](std::string name, bool initial) {
    model::Step s;
    s.name = std::move(name);
    s.initial = initial;
    c.steps.push_back(s);
  };
  auto trans = [&](std::string from, std::string to, model::ExprPtr guard) {
    model::Transition t;
    t.sources = {std::move(from)};
    t.targets = {std::move(to)};
    t.guard = std::move(guard);
    t.order = static_cast<int>(c.transitions.size());
    c.transitions.push_back(t);
  };
  auto in = [](int i) { return model::make_name("i" + std::to_string(i)); };
  switch (shape) {
    case Shape::Alternatives:
      step("S", true);
      for (int i = 0; i < n; ++i) {
        step("T" + std::to_string(i), false);
        trans("S", "T" + std::to_string(i), in(i));
        trans("T" + std::to_string(i), "S", model::make_bool(true));
      }
      break;
    case Shape::Conjunction: {
      step("S", true);
      step("T", false);
      std::vector<model::ExprPtr> args;
      for (int i = 0; i < n; ++i) args.push_back(in(i));
      trans("S", "T", model::make_nary(model::ExprKind::And, args));
      trans("T", "S", model::make_bool(true));
      break;
    }
    case Shape::Ring:
      for (int i = 0; i < n; ++i) step("R" + std::to_string(i), i == 0);
      for (int i = 0; i < n; ++i)
        trans("R" + std::to_string(i), "R" + std::to_string((i + 1) % n), in(i));
      break;
  }
  pou.charts.push_back(std::move(c));
  model::Project p;
  p.pous.push_back(std::move(pou));
  return p;
}

struct Count : semantics::SuccessorSink {
  std::size_t successors = 0, cubes = 0;
  void successor(const semantics::Successor& s) override {
    ++successors;
    cubes += s.condition.cubes.size();
  }
};

void run(benchmark::State& state, Shape shape) {
  const int n = static_cast<int>(state.range(0));
  const auto project = make_chart(shape, n);
  model::Diagnostics d;
  auto ts = semantics::make_iec61131_system(project, {}, d);
  if (!ts) {
    state.SkipWithError("chart did not compile");
    return;
  }
  const auto s0 = semantics::first_initial_state(*ts);
  Count c;
  for (auto _ : state) {
    c = Count{};
    ts->successors(s0, c);
    benchmark::DoNotOptimize(c.successors);
  }
  state.counters["inputs"] = static_cast<double>(ts->inputs().size());
  state.counters["successors"] = static_cast<double>(c.successors);
  state.counters["cubes"] = static_cast<double>(c.cubes);
}

void BM_Alternatives(benchmark::State& s) {
  run(s, Shape::Alternatives);
}
void BM_Conjunction(benchmark::State& s) {
  run(s, Shape::Conjunction);
}
void BM_Ring(benchmark::State& s) {
  run(s, Shape::Ring);
}

BENCHMARK(BM_Alternatives)->Arg(8)->Arg(64);
BENCHMARK(BM_Conjunction)->Arg(8)->Arg(64);
BENCHMARK(BM_Ring)->Arg(8)->Arg(64);

}  // namespace

BENCHMARK_MAIN();

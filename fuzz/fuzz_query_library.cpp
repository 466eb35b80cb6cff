// libFuzzer harness: a query library and a query (the input split at the first line "%%"),
// compiled against the pistons' Grafcet and evaluated on its situation graph. The library's
// definitions are inlined by the compiler: this is where `def`/`let` chains once expanded
// exponentially (docs/reliability.md), so the harness runs the expansion, not only the parser.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <string_view>

#include "engine/explicit/query_evaluator.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "io/load.hpp"
#include "logic/query_compile.hpp"
#include "semantics/grafcet_system.hpp"

namespace {

// Two partial grafcets with step variables, an edge, inputs and outputs: every sort a query has.
constexpr std::string_view kPistons = R"(project pistons;
input start, out1, in1, out2, in2;
output O1, I1, O2, I2;
grafcet piston1 {
  step 10 initial; step 11, 12, 13;
  transition 1: 10 -> 11 when RE start & in1 & in2;
  transition 2: 11 -> 12 when out1;
  transition 3: 12 -> 13 when in1;
  transition 4: 13 -> 10 when X23;
  action 11: O1; action 12: I1;
}
grafcet piston2 {
  step 20 initial; step 21, 22, 23;
  transition 5: 20 -> 21 when X13;
  transition 6: 21 -> 22 when out2;
  transition 7: 22 -> 23 when in2;
  transition 8: 23 -> 20 when X10;
  action 21: O2; action 22: I2;
}
)";

struct Fixture {
  sfcv::semantics::TransitionSystemPtr ts;
  std::unique_ptr<sfcv::engine::ReachableSituationGraph> graph;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    auto loaded = sfcv::io::load_g7(kPistons, "pistons.g7", nullptr);
    sfcv::model::Diagnostics d;
    x.ts = sfcv::semantics::make_grafcet_system(*loaded.project, {}, d);
    x.graph = std::make_unique<sfcv::engine::ReachableSituationGraph>(
        sfcv::engine::build_reachable_situation_graph(*x.ts, {}));
    return x;
  }();
  return f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto split = text.find("\n%%\n");
  const auto library_text =
      split == std::string_view::npos ? std::string_view{} : text.substr(0, split);
  const auto query_text = split == std::string_view::npos ? text : text.substr(split + 4);
  const auto& f = fixture();
  try {
    sfcv::logic::QueryLibrary library;
    library.add_text(library_text, "fuzz.sfql");
    const auto compiled = sfcv::logic::compile_query(query_text, library, *f.ts, "fuzz");
    sfcv::engine::QueryEvaluator evaluator(*f.graph);
    (void)evaluator.evaluate(compiled);
  } catch (const std::exception&) {
    // A reported error (parse, sort, expansion bound), not a crash.
  }
  return 0;
}

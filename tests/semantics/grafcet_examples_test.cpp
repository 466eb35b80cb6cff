// The Grafcet semantics on files: the pallet-transfer example of seed 002 (examples/) and the
// AGRAFE corpus files 24 and 26 (through SFCV_CORPUS only).

#include <gtest/gtest.h>

#include "io/load.hpp"
#include "support/grafcet_builder.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

BuiltRsg build_file(const std::string& path, semantics::GrafcetOptions o = {}) {
  auto loaded = io::load_file(path);
  for (const auto& d : loaded.diagnostics) EXPECT_NE(d.severity, model::Severity::Error) << d.str();
  if (!loaded.project) throw std::runtime_error("not loaded: " + path);
  static std::vector<model::Project> keep;  // the system refers to names only; keep it alive anyway
  keep.push_back(std::move(*loaded.project));
  return build_rsg(keep.back(), o);
}

// Seed 002: the flawed grafcet reaches the collision situation {1,10,20,25,31,40} (a pallet
// running on the main line, X10, while another exits onto it, X25); the fix (/X9 added to
// transition 15) removes every situation with X10 and X25. Sizes: see docs/examples.md.
TEST(GrafcetExamples, PalletTransferCollisionAndFix) {
  const auto flawed = build_file(source_path("examples/pallet_transfer/pallet_transfer.g7"));
  EXPECT_TRUE(flawed.graph.complete());
  EXPECT_TRUE(flawed.graph.anomalies().empty());
  EXPECT_GT(count_states(flawed, {"X1", "X10", "X20", "X25", "X31", "X40"}), 0u);
  EXPECT_GT(count_states(flawed, {"X10", "X25"}), 0u);
  EXPECT_EQ(flawed.graph.num_states(), 9192u);
  EXPECT_EQ(flawed.graph.num_edges(), 55152u);

  const auto fixed = build_file(source_path("examples/pallet_transfer/pallet_transfer_fixed.g7"));
  EXPECT_TRUE(fixed.graph.complete());
  EXPECT_TRUE(fixed.graph.anomalies().empty());
  EXPECT_EQ(count_states(fixed, {"X10", "X25"}), 0u);
  EXPECT_EQ(fixed.graph.num_states(), 8272u);
  EXPECT_EQ(fixed.graph.num_edges(), 49632u);
}

TEST(GrafcetExamples, Corpus24ExclusiveSelectionBuildsAnRsg) {
  SFCV_REQUIRE_CORPUS(corpus);
  for (bool single : {true, false}) {
    semantics::GrafcetOptions o;
    o.single_input_change = single;
    const auto r = build_file((corpus / "24_agrafe_exclusive_selection.grafcet").string(), o);
    EXPECT_TRUE(r.graph.complete());
    EXPECT_TRUE(r.graph.anomalies().empty());
    EXPECT_GT(r.graph.num_states(), 0u);
    // Step 1 selects one of its sequences at once: it is never a stable situation.
    EXPECT_EQ(count_states(r, {"X1"}), 0u);
  }
}

// 1 --TRUE--> 2 --k < 1--> 3 and 4 --TRUE--> 5 with k := 1 on the activation of 5: both initial
// steps are left at once, 5 sets k before 2 is stable, so step 3 is never reached.
TEST(GrafcetExamples, Corpus26HasAnUnreachableStep) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto r = build_file((corpus / "26_agrafe_step_reachability3.grafcet").string());
  EXPECT_TRUE(r.graph.complete());
  EXPECT_EQ(r.graph.num_states(), 1u);
  EXPECT_EQ(r.system->describe(r.graph.states().at(0)), "{2,5} k=1");
  std::vector<std::string> never;
  for (std::uint32_t i = 0; i < r.system->observables().size(); ++i) {
    const auto& o = r.system->observables()[i];
    if (o.kind != semantics::ObservableKind::Step) continue;
    bool seen = false;
    for (std::uint32_t s = 0; s < r.graph.num_states(); ++s)
      seen = seen || r.system->observe(r.graph.states().at(s), i);
    if (!seen) never.push_back(o.name);
  }
  // 1 and 4 are left during the initial stabilisation; 3 is never active at all.
  EXPECT_EQ(never, (std::vector<std::string>{"X1", "X3", "X4"}));
}

}  // namespace
}  // namespace sfcv::test

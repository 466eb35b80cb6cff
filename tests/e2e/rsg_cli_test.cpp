// End-to-end: sfcv rsg on small .g7 documents (summary, listing, dot, json, anomalies, limits).

#include <nlohmann/json.hpp>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::source_path;
using sfcv::test::write_temp;

const char* kToggle = R"(project toggle;
input a;
output y;
grafcet G {
  step 1 initial;
  step 2;
  transition 1: 1 -> 2 when a;
  transition 2: 2 -> 1 when !a;
  action 2: y;
}
)";

const char* kUnstable = R"(project unstable;
input a;
grafcet G {
  step 1 initial;
  step 2;
  transition 1: 1 -> 2 when a;
  transition 2: 2 -> 1 when a;
}
)";

TEST(RsgCli, SummaryAndListing) {
  const auto path = write_temp(kToggle, ".g7");
  const auto r = run_sfcv("rsg --list " + path);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("semantics: grafcet (IEC 60848, single input change)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("situations: 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("evolutions: 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("build time:"), std::string::npos);
  EXPECT_NE(r.out.find("{1} --[a]--> s1 {2} / y"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{2} --[!a]--> s0 {1}"), std::string::npos) << r.out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The grouped graph's situation nodes ("  g3 [id=\"sg3\", ..."; edges are \"se0\").
std::size_t situation_nodes(const std::string& dot) {
  return count(dot, " [id=\"sg");
}

TEST(RsgCli, DotAndJson) {
  const auto path = write_temp(kToggle, ".g7");
  // Every stable situation, its edges labelled with their input conditions.
  const auto dot = run_sfcv("rsg --dot-states - " + path);
  EXPECT_EQ(dot.exit_code, 0);
  EXPECT_NE(dot.out.find("digraph rsg"), std::string::npos);
  EXPECT_NE(dot.out.find("label=\"a\""), std::string::npos) << dot.out;
  const auto js = run_sfcv("rsg --json " + path);
  ASSERT_EQ(js.exit_code, 0) << js.err;
  const auto j = nlohmann::json::parse(js.out);
  EXPECT_EQ(j["semantics"], "grafcet");
  EXPECT_EQ(j["states"].size(), 2u);
  EXPECT_EQ(j["edges"].size(), 2u);
  EXPECT_EQ(j["edges"][0]["condition"], "a");
}

// The pistons' RSG has 96 stable situations in 5 step situations: --dot draws 5 nodes (the
// 96-node graph took graphviz minutes), and a cap says what it left out.
TEST(RsgCli, DotGroupsByStepSituationWithACap) {
  const auto pistons = source_path("examples/pistons/pistons.g7");
  const auto r = run_sfcv("rsg --dot - " + pistons);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("digraph rsg {", 0), 0u) << r.out;  // the graph alone, for a pipe into dot
  EXPECT_EQ(situation_nodes(r.out), 5u) << r.out;
  EXPECT_NE(r.out.find("label=\"{X10, X20}\\n32 stable situations\", peripheries=2"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("g1 -> g3 [id=\"se4\", label=\"(2) X11 -> X12\\l\"]"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("left out"), std::string::npos) << r.err;

  const auto cut = run_sfcv("rsg --dot - --max-nodes 2 " + pistons);
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  EXPECT_EQ(situation_nodes(cut.out), 2u) << cut.out;
  EXPECT_NE(cut.out.find("3 more step situations"), std::string::npos) << cut.out;
  EXPECT_NE(
      cut.err.find("sfcv rsg --dot: 2 of 5 step situations are drawn (the first 2 "
                   "breadth-first), 3 left out; --max-nodes N draws N, --max-nodes 0 every one"),
      std::string::npos)
      << cut.err;
}

TEST(RsgCli, InstabilityIsAnErrorWithItsCycle) {
  const auto path = write_temp(kUnstable, ".g7");
  const auto r = run_sfcv("rsg " + path);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(path + ": error: instability"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cycle: {2} -> {1} -> {2}"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("inputs: a"), std::string::npos) << r.err;
}

TEST(RsgCli, MultiInputChangeAndLimits) {
  const auto pallet = source_path("examples/pallet_transfer/pallet_transfer.g7");
  const auto multi = run_sfcv("rsg --multi-input-change " + pallet);
  EXPECT_EQ(multi.exit_code, 0);
  EXPECT_NE(multi.out.find("multiple input changes"), std::string::npos);
  const auto limited = run_sfcv("rsg --max-states 100 " + pallet);
  EXPECT_EQ(limited.exit_code, 3);
  EXPECT_NE(limited.out.find("unknown"), std::string::npos) << limited.out;
}

TEST(RsgCli, UnknownSemanticsIsBadUsage) {
  const auto path = write_temp(kToggle, ".g7");
  EXPECT_EQ(run_sfcv("rsg --semantics petri " + path).exit_code, 2);
}

}  // namespace

namespace {

// Corpus 22 stabilises its initial situation under every input valuation: hundreds of thousands
// of initial situations, each with its own condition. A time limit must end the run with
// "unknown" (exit 3), in rsg and in check; interning the conditions in a fixed-size table used to
// make it quadratic and ignore the limit.
TEST(RsgCorpus, TimeLimitEndsTheExplosiveQualityControlPlant) {
  SFCV_REQUIRE_CORPUS(corpus);
  const std::string path =
      "'" + (corpus / "22_agrafe_quality_control_plant.grafcet").string() + "'";
  const auto rsg = run_sfcv("rsg " + path + " --timeout 2");
  EXPECT_EQ(rsg.exit_code, 3) << rsg.out << rsg.err;
  EXPECT_NE(rsg.out.find("time limit"), std::string::npos) << rsg.out;
  const auto check =
      run_sfcv("check " + path + " --engine explicit --timeout 2 --checks reachable --trace none");
  EXPECT_EQ(check.exit_code, 3) << check.out << check.err;
  EXPECT_NE(check.out.find("unknown"), std::string::npos) << check.out;
}

}  // namespace

namespace {

// Issue 53's minimal case (docs/semantics.md 2.12): G0 has no initial step, 10 is linked.
const char* kLinked = R"(project linked;
input a, b, c;
grafcet Main {
  step 1 initial;
  step 2 encloses G0;
  transition 1: 1 -> 2 when a;
  transition 2: 2 -> 1 when b;
}
grafcet G0 {
  step 10 linked;
  step 11;
  transition 3: 10 -> 11 when c;
  transition 4: 11 -> 10 when !c;
}
)";

// Every engine holds the linked step to the rule: AG (X2 -> X10 | X11) and EF X10 hold (before
// issue 53 both were violated). The SAT engines decide what they can and never say violated:
// kind and ic3 prove the invariant and EF p from each of the several initial situations (6
// here, one per stored input valuation; docs/engines.md "EF on Grafcet", it was "not checked",
// exit 3); BMC proves nothing: unknown (docs/semantics.md 3.7).
TEST(RsgCli, ActivationLinksOnEveryEngine) {
  const auto path = write_temp(kLinked, ".g7");
  for (const std::string engine : {"explicit", "bdd", "auto", "kind", "ic3", "bmc"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv("check " + path + " --engine " + engine +
                            " --ctl 'AG (X2 -> X10 | X11)' --ctl 'EF X10' --ctl 'EF (X2 & X11)'");
    EXPECT_EQ(r.out.find("violated"), std::string::npos) << r.out;
    EXPECT_EQ(r.exit_code, engine == "bmc" ? 3 : 0) << r.out << r.err;
    if (engine == "kind" || engine == "ic3") {
      EXPECT_NE(r.out.find("AG (X2 -> X10 | X11)  holds"), std::string::npos) << r.out;
    }
  }
  // With a and b both true, 1 --a--> 2 --b--> 1 never stabilises: instabilities, exit 1.
  const auto rsg = run_sfcv("rsg --list " + path);
  EXPECT_EQ(rsg.exit_code, 1) << rsg.err;
  EXPECT_NE(rsg.out.find("{2,10}"), std::string::npos) << rsg.out;
  EXPECT_NE(rsg.out.find("{2,11}"), std::string::npos) << rsg.out;
  const auto lint = run_sfcv("lint " + path);
  EXPECT_EQ(lint.out.find("no activation-linked step"), std::string::npos) << lint.out;
}

// A chain needing more transient evolutions than max_transient_steps (10000) is unknown, exit 3,
// with the bound named; not an instability (docs/semantics.md 2.11).
std::string chain_g7(int n) {
  std::string text = "project chain;\ninput a;\ngrafcet G {\n  step 0 initial;\n";
  for (int i = 1; i <= n; ++i) text += "  step " + std::to_string(i) + ";\n";
  text += "  transition 0 -> 1 when a;\n";
  for (int i = 1; i < n; ++i)
    text += "  transition " + std::to_string(i) + " -> " + std::to_string(i + 1) + ";\n";
  text += "  transition " + std::to_string(n) + " -> 0 when !a;\n}\n";
  return text;
}

TEST(RsgCli, TransientBoundIsUnknown) {
  const auto over = write_temp(chain_g7(10001), ".g7");
  const auto r = run_sfcv("check " + over + " --engine explicit --checks instability");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE((r.out + r.err).find("no stable situation after 10000 transient evolutions"),
            std::string::npos)
      << r.out << r.err;
  EXPECT_NE((r.out + r.err).find("max_transient_steps"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.out.find("violated"), std::string::npos) << r.out;
  // Exactly 10000 evolutions: stable, the instability check holds.
  const auto exact = write_temp(chain_g7(10000), ".g7");
  const auto e = run_sfcv("check " + exact + " --engine explicit --checks instability");
  EXPECT_EQ(e.exit_code, 0) << e.out << e.err;
}

}  // namespace

namespace {

// A linked step is crossed when its enclosing step is (docs/semantics.md 2.5, 2.12 a): at the
// start (AGRAFE's sitReachability4: 11 -> 12 -> 13 at once, 12 encloses G10 = {101*}) and after
// an event (2 is crossed when a rises, 10* with it). `reachable` holds on both engines; before,
// 101 and 10 were "never active".
TEST(RsgCli, ReachableCountsStepsEnteredWithTheirEnclosingStep) {
  const auto at_start = write_temp(R"(project start;
grafcet G1 {
  step 11 initial;
  step 12 encloses G10;
  step 13;
  transition 11: 11 -> 12;
  transition 12: 12 -> 13;
}
grafcet G10 {
  step 101 linked;
}
)",
                                   ".g7");
  const auto on_event = write_temp(R"(project event;
input a;
grafcet G1 {
  step 1 initial;
  step 2 encloses G0;
  step 3;
  transition 1: 1 -> 2 when a;
  transition 2: 2 -> 3;
  transition 3: 3 -> 1 when !a;
}
grafcet G0 {
  step 10 linked;
}
)",
                                   ".g7");
  for (const std::string engine : {"explicit", "bdd"}) {
    SCOPED_TRACE(engine);
    auto r = run_sfcv("check " + at_start + " --engine " + engine + " --checks reachable");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("3 only while the initial situation stabilises"), std::string::npos)
        << r.out;
    r = run_sfcv("check " + on_event + " --engine " + engine + " --checks reachable");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("2 only during transient evolutions"), std::string::npos) << r.out;
  }
}

}  // namespace

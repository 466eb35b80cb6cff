// The Grafcet standard checks `reachable` and `dead-transitions` on steps crossed only during
// transient evolutions (docs/semantics.md 2.5: "a step active only during the transient
// evolutions after an event, and a step active only while the initial situation stabilises (the
// initial steps, and those the start runs through), are reached"), on every engine: explicit,
// bdd, and the SAT engines' observers (docs/engines.md, "Grafcet on the SAT engines"). Each
// chart is the worked example of a disagreement of SatEngineAgreement.RandomGrafcets.

#include <gtest/gtest.h>

#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "semantics/grafcet_system.hpp"
#include "support/ctl_task.hpp"
#include "support/grafcet_builder.hpp"

namespace sfcv::engine {
namespace {

using test::GrafcetBuilder;

struct Built {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Built make(model::Project p) {
  Built b{std::move(p), nullptr};
  model::Diagnostics d;
  b.ts = semantics::make_grafcet_system(b.project, semantics::GrafcetOptions{}, d);
  for (const auto& x : d)
    if (x.severity == model::Severity::Error) ADD_FAILURE() << x.str();
  return b;
}

/// Every engine's report on `checks` (and `ctl`) of `b`: explicit, bdd, bmc, kind, ic3.
std::vector<std::pair<std::string, logic::CheckReport>> every_engine(
    const Built& b, const std::vector<logic::StandardCheck>& checks,
    const std::vector<std::string>& ctl = {}) {
  auto task = test::task_for(b.project, *b.ts, ctl, {});
  task.checks = checks;
  std::vector<std::pair<std::string, logic::CheckReport>> out;
  out.emplace_back("explicit", make_explicit_model_checker()->check(task));
  out.emplace_back("bdd", make_bdd_model_checker()->check(task));
  for (auto algorithm : {SatAlgorithm::Bmc, SatAlgorithm::KInduction, SatAlgorithm::Ic3}) {
    SatEngineOptions o;
    o.algorithm = algorithm;
    o.max_depth = 16;
    const auto checker = make_sat_model_checker(o);
    out.emplace_back(std::string(checker->name()), checker->check(task));
  }
  return out;
}

// A transition into macro-step M2 activates its entry step E2 (docs/semantics.md 2.12); with
// `E2 --1--> S2` the entry step is left in the next evolution, so E2 is crossed only during the
// transient evolutions after a rises, like a step entered by a transition: reached. (Seed 46:
// the explicit and BDD engines said "step XE2 is never active", as they counted only steps
// named as a transition's target, and the SAT engines' observers saw E2 active.)
TEST(GrafcetCrossedSteps, MacroStepEntryCrossedTransientlyIsReached) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("M2", false, model::StepKind::MacroStep, {"X2"});
  b.transition({"1"}, {"M2"}, test::v("a")).transition({"M2"}, {"1"}, test::not_(test::v("a")));
  b.chart("X2").step("E2").step("S2");
  b.transition({"E2"}, {"S2"}, test::lit(true));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] :
       every_engine(built, {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions},
                    {"AG !XE2"})) {
    SCOPED_TRACE(engine);
    ASSERT_EQ(r.results.size(), 3u);
    if (engine != "bmc") {  // BMC proves no invariant; transient situations are never judged
      EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds);
    }
    EXPECT_EQ(r.results[1].verdict, logic::Verdict::Holds) << r.results[1].message;
    EXPECT_TRUE(r.results[1].findings.empty());
    EXPECT_EQ(r.results[2].verdict, logic::Verdict::Holds) << r.results[2].message;
  }
}

// A forcing order activates the forced steps in the next evolution (2.12): 2 forces G2{22} and
// is entered when a rises, then left at once for 3 (`2 --1--> 3`), and G2, no longer forced,
// leaves 22 for 21 in the evolution after: 22 is active only during the transient evolutions
// after a rises, reached; `AG !X22` holds (transient situations are never judged).
TEST(GrafcetCrossedSteps, StepForcedTransientlyIsReached) {
  GrafcetBuilder b;
  b.input("a").chart("G1").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, test::v("a"))
      .transition({"2"}, {"3"}, test::lit(true))
      .transition({"3"}, {"1"}, test::not_(test::v("a")));
  b.forcing("2", "G2", model::ForcingKind::Situation, {"22"});
  b.chart("G2").step("21", true).step("22");
  b.transition({"22"}, {"21"}, test::lit(true));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] :
       every_engine(built, {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions},
                    {"AG !X22"})) {
    SCOPED_TRACE(engine);
    ASSERT_EQ(r.results.size(), 3u);
    if (engine != "bmc") {
      EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds);
    }
    EXPECT_EQ(r.results[1].verdict, logic::Verdict::Holds) << r.results[1].message;
    EXPECT_EQ(r.results[2].verdict, logic::Verdict::Holds) << r.results[2].message;
  }
}

// The initial steps are active in the initial situation before it stabilises (2.2, 2.5), also
// when a forcing order, not a transition, deactivates them: 1 --1--> 2 at start, 2 forces
// G2{22}, so 21 is active only then and `21 --X1 & X3--> 22` never fires. (Seed 69: the explicit
// and BDD engines counted only the steps of the transitions cleared at the start, and said "step
// X21 is never active".)
TEST(GrafcetCrossedSteps, InitialStepForcedAwayAtTheStartIsReached) {
  GrafcetBuilder b;
  b.input("a").chart("G1").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, test::lit(true))
      .transition({"2"}, {"3"}, test::v("a"))
      .transition({"3"}, {"2"}, test::not_(test::v("a")));
  b.forcing("2", "G2", model::ForcingKind::Situation, {"22"});
  b.chart("G2").step("21", true).step("22");
  b.transition({"21"}, {"22"}, test::and_(test::v("X1"), test::v("X3")));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(
           built, {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions})) {
    SCOPED_TRACE(engine);
    ASSERT_EQ(r.results.size(), 2u);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds) << r.results[0].message;
    if (engine == "explicit" || engine == "bdd") {
      EXPECT_NE(r.results[0].message.find("2 only while the initial situation stabilises"),
                std::string::npos)
          << r.results[0].message;
    }
    if (engine == "bmc") continue;  // proves nothing: the dead transition stays unknown
    EXPECT_EQ(r.results[1].verdict, logic::Verdict::Violated) << r.results[1].message;
    ASSERT_EQ(r.results[1].findings.size(), 1u);
    EXPECT_NE(r.results[1].findings[0].find("X21 -> X22"), std::string::npos)
        << r.results[1].findings[0];
  }
}

// No stable situation at all: `1 --1--> 2 --1--> 1` never stabilises under any input, so
// there is no initial state and nothing to judge: every engine answers unknown, never "step X1
// is never active" (seed 90: k-induction proved every step unreachable in the stable
// situations and reported them all).
TEST(GrafcetCrossedSteps, NoStableSituationIsUnknownNotAFinding) {
  GrafcetBuilder b;
  b.input("a").chart("G").step("1", true).step("2");
  b.transition({"1"}, {"2"}, test::lit(true)).transition({"2"}, {"1"}, test::lit(true));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(
           built, {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions})) {
    SCOPED_TRACE(engine);
    ASSERT_EQ(r.results.size(), 2u);
    for (const auto& x : r.results) {
      EXPECT_EQ(x.verdict, logic::Verdict::Unknown) << x.message;
      EXPECT_TRUE(x.findings.empty());
    }
  }
}

}  // namespace
}  // namespace sfcv::engine

namespace sfcv::engine {
namespace {

// A transition into a step of an enclosed grafcet that fires in the evolution that deactivates
// the enclosing step: the deactivation (docs/semantics.md 2.12 c) is applied after the clearing,
// so 31 is never active in any situation, transient or stable. `1 --a--> 3 --b--> 1`, 3 encloses
// G3 `32* --b--> 31`: a rise of b clears both. (Seed 383 with --multi-input-change: the SAT
// engines' observers say "step X31 is never active", which is right.)
Built enclosed_entered_as_its_enclosing_step_ends() {
  GrafcetBuilder b;
  b.input("a").input("b").chart("G1").step("1", true).step("3", false, model::StepKind::Enclosing,
                                                           {"G3"});
  b.transition({"1"}, {"3"}, test::v("a")).transition({"3"}, {"1"}, test::v("b"));
  b.chart("G3").step("31").step("32");
  b.transition({"32"}, {"31"}, test::v("b"));
  for (auto& c : b.pou().charts)
    if (c.name == "G3") c.steps[1].activation_link = true;
  return make(b.project());
}

TEST(GrafcetCrossedSteps, StepEnteredAsItsEnclosingStepEndsIsNeverActiveOnTheSatEngines) {
  const auto built = enclosed_entered_as_its_enclosing_step_ends();
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(built, {logic::StandardCheck::Reachable})) {
    if (engine != "ic3" && engine != "kind") continue;
    SCOPED_TRACE(engine);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Violated) << r.results[0].message;
    ASSERT_EQ(r.results[0].findings.size(), 1u);
    EXPECT_NE(r.results[0].findings[0].find("X31 is never active"), std::string::npos);
  }
}

// The explicit and BDD engines counted a step entered by a transition that fires as crossed, and
// said "reachable holds" here: a false "holds" (then, until they followed each evolution to its
// end, unknown). No engine may say it holds.
TEST(GrafcetCrossedSteps, StepEnteredAsItsEnclosingStepEndsIsNeverHeldReachable) {
  const auto built = enclosed_entered_as_its_enclosing_step_ends();
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(built, {logic::StandardCheck::Reachable})) {
    SCOPED_TRACE(engine);
    EXPECT_NE(r.results[0].verdict, logic::Verdict::Holds) << r.results[0].message;
  }
}

// The explicit and BDD engines follow each evolution to its end (the steps active in one of its
// situations, semantics::Successor::entered): 31 is in none, and every engine that decides
// says so. The clearing of 32 -> 31 still counts as firing: dead-transitions holds.
TEST(GrafcetCrossedSteps, StepEnteredAsItsEnclosingStepEndsIsNeverActiveEverywhere) {
  const auto built = enclosed_entered_as_its_enclosing_step_ends();
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(
           built, {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions})) {
    if (engine == "bmc") continue;
    SCOPED_TRACE(engine);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Violated) << r.results[0].message;
    EXPECT_EQ(r.results[0].findings, std::vector<std::string>{"step X31 is never active"});
    EXPECT_EQ(r.results[1].verdict, logic::Verdict::Holds) << r.results[1].message;
  }
}

// The same end through an input edge (seed 127 of SatEngineAgreement.RandomGrafcets): 5
// encloses G3 `31 --fall c--> 32`, `1 --rise a--> 5 --!c--> 1`. When c falls in {5,31} both
// transitions clear in the first evolution; the deactivation of 5 then empties G3 (2.12 c, applied
// after the clearing): 32 is active in no situation. Entering 5 with c false leaves it at once, G3
// in 31. reachable: "X32 is never active" on every engine that decides; 31 -> 32 fires.
TEST(GrafcetCrossedSteps, StepEnteredByAFallingEdgeThatEndsItsEnclosingStepIsNeverActive) {
  GrafcetBuilder b;
  b.input("a").input("c").chart("G1").step("1", true).step("5", false, model::StepKind::Enclosing,
                                                           {"G3"});
  b.transition({"1"}, {"5"}, test::rise(test::v("a")))
      .transition({"5"}, {"1"}, test::not_(test::v("c")));
  b.chart("G3").step("31", true).step("32");
  b.transition({"31"}, {"32"}, test::fall(test::v("c")));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(
           built, {logic::StandardCheck::Reachable, logic::StandardCheck::DeadTransitions})) {
    if (engine == "bmc") continue;
    SCOPED_TRACE(engine);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Violated) << r.results[0].message;
    EXPECT_EQ(r.results[0].findings, std::vector<std::string>{"step X32 is never active"});
    EXPECT_EQ(r.results[1].verdict, logic::Verdict::Holds) << r.results[1].message;
  }
}

// The control: the enclosing step is left one evolution later (`5 --X32--> 1`), so 32 is active
// in the transient situation {5,32} after c falls: reached, "only during transient evolutions".
TEST(GrafcetCrossedSteps, StepOfAnEnclosedGrafcetLeftOneEvolutionLaterIsReached) {
  GrafcetBuilder b;
  b.input("a").input("c").chart("G1").step("1", true).step("5", false, model::StepKind::Enclosing,
                                                           {"G3"});
  b.transition({"1"}, {"5"}, test::rise(test::v("a"))).transition({"5"}, {"1"}, test::v("X32"));
  b.chart("G3").step("31", true).step("32");
  b.transition({"31"}, {"32"}, test::fall(test::v("c")));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(built, {logic::StandardCheck::Reachable})) {
    if (engine == "bmc") continue;
    SCOPED_TRACE(engine);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds) << r.results[0].message;
    if (engine == "explicit" || engine == "bdd") {
      EXPECT_NE(r.results[0].message.find("1 only during transient evolutions"), std::string::npos)
          << r.results[0].message;
    }
  }
}

// A transition cleared only by evolutions that end where they started fires (2.5; seed 260):
// `1 --a--> 2 --1s/X2--> 1`, `2 --!a--> 3 --a--> 2`, so 2 is stable only under a. In {2} the
// elapse of the delay clears 2 -> 1, then 1 -> 2 under a, and the delay restarts: the same
// stable situation, so no edge (2.1), but 2 -> 1 fired. The explicit and BDD engines dropped
// such an evolution with what it fired and listed `X2 -> X1` as never firing; the SAT engines'
// observers see it.
TEST(GrafcetCrossedSteps, TransitionClearedOnAnEvolutionBackToItsSourceFires) {
  GrafcetBuilder b;
  b.input("a").chart("G1").step("1", true).step("2").step("3");
  b.transition({"1"}, {"2"}, test::v("a"))
      .transition({"2"}, {"1"}, model::make_delay(1000, test::v("X2"), 0))
      .transition({"2"}, {"3"}, test::not_(test::v("a")))
      .transition({"3"}, {"2"}, test::v("a"));
  const auto built = make(b.project());
  ASSERT_TRUE(built.ts);
  for (const auto& [engine, r] : every_engine(
           built, {logic::StandardCheck::DeadTransitions, logic::StandardCheck::Reachable})) {
    if (engine == "bmc") continue;
    SCOPED_TRACE(engine);
    EXPECT_EQ(r.results[0].verdict, logic::Verdict::Holds) << r.results[0].message;
    EXPECT_TRUE(r.results[0].findings.empty());
    EXPECT_EQ(r.results[1].verdict, logic::Verdict::Holds) << r.results[1].message;
  }
}

}  // namespace
}  // namespace sfcv::engine

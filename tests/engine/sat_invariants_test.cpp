// Invariants the SAT engines share between targets: Houdini's inductive subset of candidate
// clauses (engine/sat/houdini.hpp) and IC3 runs that assume an invariant already proved
// (Ic3Options::known_invariant), whose certificates must still be inductive alone.

#include <gtest/gtest.h>

#include <algorithm>

#include "engine/sat/certificate.hpp"
#include "engine/sat/houdini.hpp"
#include "engine/sat/ic3.hpp"
#include "semantics/aig.hpp"

namespace sfcv::engine::sat {
namespace {

using semantics::Aig;
using semantics::AigLit;

/// A ring of four steps s0 -> s1 -> s2 -> s3 -> s0 (s0 initial) that moves on input `go`, and
/// a latch p that follows s2 exactly (set with it, cleared with it): p and s2 are always active
/// together, every other pair never.
struct Ring {
  Aig aig;
  std::vector<AigLit> s;
  AigLit p = 0, go = 0;
  Ring() {
    go = aig.add_input("go");
    for (int i = 0; i < 4; ++i) s.push_back(aig.add_latch("s" + std::to_string(i), i == 0));
    p = aig.add_latch("p");
    const auto stay_or_come = [&](AigLit self, AigLit from) {
      return aig.make_or(aig.make_and(self, Aig::make_not(go)), aig.make_and(from, go));
    };
    for (std::uint32_t i = 0; i < 4; ++i) aig.set_next(i, stay_or_come(s[i], s[(i + 3) % 4]));
    aig.set_next(4, stay_or_come(p, s[1]));
  }
  ReachQuery query(AigLit target) const {
    ReachQuery q;
    q.aig = &aig;
    q.targets = {target};
    return q;
  }
};

LatchClause not_both(std::uint32_t a, std::uint32_t b) {
  return {{std::min(a, b), false}, {std::max(a, b), false}};
}

TEST(SatInvariants, HoudiniKeepsTheExclusionsThatHoldAndDropsTheOthers) {
  Ring ring;
  auto candidates = step_exclusion_candidates({{0, 1, 2, 3, 4}}, 1000);
  ASSERT_EQ(candidates.size(), 10U);
  candidates.push_back({{0, false}});  // "s0 is never active": false initially
  const auto kept = houdini(ring.query(Aig::kFalse), candidates, {});
  EXPECT_EQ(kept.size(), 9U);
  EXPECT_EQ(std::count(kept.begin(), kept.end(), not_both(2, 4)), 0);  // p and s2 together
  EXPECT_EQ(std::count(kept.begin(), kept.end(), LatchClause{{0, false}}), 0);
  for (std::uint32_t a = 0; a < 4; ++a)
    for (std::uint32_t b = a + 1; b < 4; ++b)
      EXPECT_EQ(std::count(kept.begin(), kept.end(), not_both(a, b)), 1) << a << " " << b;
  // The kept set is an inductive invariant: a fresh solver re-checks it against a target it
  // excludes.
  Certificate cert;
  cert.kind = Certificate::Kind::Invariant;
  cert.clauses = kept;
  Ring copy;
  EXPECT_TRUE(recheck(copy.query(copy.aig.make_and(copy.s[0], copy.s[2])), 0, cert).ok);
}

TEST(SatInvariants, HoudiniCapsTheCandidatesOfLargeCharts) {
  EXPECT_EQ(step_exclusion_candidates({{0, 1, 2, 3, 4}, {5, 6, 7}}, 1000).size(), 13U);
  EXPECT_EQ(step_exclusion_candidates({{0, 1, 2, 3, 4}, {5, 6, 7}}, 7).size(), 7U);
}

TEST(SatInvariants, Ic3AssumesAKnownInvariantAndItsCertificateStandsAlone) {
  Ring ring;
  const auto known =
      houdini(ring.query(Aig::kFalse), step_exclusion_candidates({{0, 1, 2, 3, 4}}, 1000), {});
  ASSERT_FALSE(known.empty());
  Ic3Options options;
  options.known_invariant = &known;
  // s0 and s2 together: unreachable, and the proof carries the invariant it assumed.
  const AigLit never = ring.aig.make_and(ring.s[0], ring.s[2]);
  const auto proof = ic3(ring.query(never), 0, options);
  ASSERT_EQ(proof.kind, ReachResult::Kind::Unreachable);
  for (const auto& c : known)
    EXPECT_EQ(std::count(proof.certificate.clauses.begin(), proof.certificate.clauses.end(), c), 1);
  EXPECT_TRUE(recheck(ring.query(never), 0, proof.certificate).ok);
  // p with s2: reached in two steps; the known invariant does not hide it.
  Ring again;
  const AigLit together = again.aig.make_and(again.p, again.s[2]);
  const auto run = ic3(again.query(together), 0, options);
  ASSERT_EQ(run.kind, ReachResult::Kind::Reached);
  EXPECT_EQ(run.depth, 2U);
}

TEST(SatInvariants, AFalseKnownInvariantFailsTheRecheckInsteadOfProvingAnything) {
  // The caller's promise broken (a clause that does not hold: "s1 is never active"): IC3 then
  // claims a proof, but the certificate it returns carries the clause and a fresh solver
  // refuses it, so no false "holds" can come of it (the engine re-checks every proof).
  Ring ring;
  const std::vector<LatchClause> wrong{{{1, false}}};
  Ic3Options options;
  options.known_invariant = &wrong;
  const AigLit s1 = ring.s[1];
  const auto r = ic3(ring.query(s1), 0, options);
  ASSERT_EQ(r.kind, ReachResult::Kind::Unreachable);
  const auto verdict = recheck(ring.query(s1), 0, r.certificate);
  EXPECT_FALSE(verdict.ok);
  EXPECT_EQ(verdict.failed, "consecution");
}

}  // namespace
}  // namespace sfcv::engine::sat

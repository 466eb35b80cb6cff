#pragma once
// What the SAT engines decide: can a run from the initial state reach a frame where `target`
// holds? A run takes a transition from (state, inputs) only where `step_ok` holds (the inputs
// are allowed and the cycle raises no range error); `target` is read over the state and the
// inputs of its frame. Every invariant-shaped question (AG p, EF p, a step reachable, a
// transition firable, a range error) is one such target.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "semantics/aig.hpp"

namespace sfcv::engine::sat {

class CutMapping;  // unrolling.hpp

struct ReachQuery {
  const semantics::Aig* aig = nullptr;
  semantics::AigLit step_ok = semantics::Aig::kTrue;
  std::vector<semantics::AigLit> targets;
  /// BMC, k-induction and IC3: a simplifying unrolling (unrolling.hpp). Off for the Grafcet
  /// machine: its traces read the inputs of every event frame, and the simplified encoding leaves
  /// inputs that the folded gates no longer read free in the model (a trace with two inputs
  /// changing at once, EveryTraceReplays grafcet seed 10).
  bool simplify = true;
  /// simplify: the cut of each gate, shared by the unrollings of `aig` that this query and its
  /// copies make (IC3 makes a solver per frame and one for lifting, per target); null: each
  /// makes its own.
  std::shared_ptr<CutMapping> cuts;
};

/// A clause over latches: latch index and the value that satisfies the literal.
struct LatchLiteral {
  std::uint32_t latch = 0;
  bool value = false;
  bool operator==(const LatchLiteral&) const = default;
  auto operator<=>(const LatchLiteral&) const = default;
};
using LatchClause = std::vector<LatchLiteral>;

/// Why a target is unreachable, in a form a fresh solver re-checks (certificate.hpp):
/// IC3's inductive invariant (a clause set over latches: it holds initially, is closed under
/// every transition and excludes the target), or k-induction's depth (no target within
/// depth - 1 steps, and no loop-free run of `depth` non-target frames reaches one).
struct Certificate {
  enum class Kind { None, Invariant, KInduction } kind = Kind::None;
  std::vector<LatchClause> clauses;  ///< Invariant
  std::uint32_t depth = 0;           ///< KInduction
};

struct ReachResult {
  enum class Kind { Reached, Unreachable, Unknown } kind = Kind::Unknown;
  /// Reached: circuit input values of frames 0..depth, a run from the initial state whose
  /// last frame satisfies the target (replay it with Aig::evaluate).
  std::vector<std::vector<bool>> inputs;
  std::uint32_t depth = 0;  ///< Reached: the run's length; Unknown: the bound reached
  Certificate certificate;  ///< Unreachable
  std::string why;          ///< Unknown: which limit
};

}  // namespace sfcv::engine::sat

#pragma once
// Tseitin encoding of an Aig into one solver, frame by frame and only on demand: asking for a
// literal at frame k encodes exactly its cone of influence there. Frames are linked by
// renaming: a latch at frame k+1 is the literal of its next-state function at frame k, so no
// equality clauses are needed. A latch at frame 0 is a fresh variable (constrained to its
// initial value when the unrolling starts in the initial state).
//
// Simplifying unrollings (BMC, k-induction) also fold constants (the initial state's values
// flow through the first frames as constants, no clauses) and hash AND gates on their solver
// literals across all frames (a gate whose inputs are the same literals as one encoded before,
// in any frame, is that gate): on bench/run's levels 8 the first frames cost no clauses and the
// frames where part of the state stays unchanged share their gates (docs/engines.md).

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "engine/sat/sat_solver.hpp"
#include "semantics/aig.hpp"

namespace sfcv::engine::sat {

class Unrolling {
 public:
  /// `from_initial`: latches at frame 0 take their initial values. `simplify`: fold constants
  /// and hash gates (a literal may then be the solver's true literal or its negation, and two
  /// nodes may share a literal); IC3 keeps one fresh variable per latch and gate.
  Unrolling(const semantics::Aig& aig, Solver& solver, bool from_initial, bool simplify = false);

  /// The solver literal of `lit` at `frame` (encodes its cone on first use).
  int literal(semantics::AigLit lit, std::size_t frame);
  /// The solver literal of latch `index` at `frame`.
  int latch(std::uint32_t index, std::size_t frame);
  /// The solver literal of input `index` at `frame`, or 0 when that input was never encoded
  /// there (it influences nothing asked so far: any value will do).
  int input_if_encoded(std::uint32_t index, std::size_t frame) const;
  /// The solver literal of `lit` at `frame` if it was encoded already, else 0 (asking for it
  /// would add clauses, which ends the solver's current model).
  int literal_if_encoded(semantics::AigLit lit, std::size_t frame) const;
  /// Circuit input values at `frame` in the solver's model (unencoded inputs are false).
  std::vector<bool> input_values(std::size_t frame) const;

  Solver& solver() { return solver_; }
  const semantics::Aig& aig() const { return aig_; }

 private:
  /// The literal of AND over `lits` (simplified and hashed when simplify_).
  int conjunction(std::vector<int> lits);
  /// The literal of (s ? a : b), simplified and hashed.
  int ite(int s, int a, int b);
  /// Simplify: the fan-in literals of the AND tree at And node `node` at `frame`: non-negated
  /// And inputs read by this tree alone (fanout 1) and not encoded yet are merged in.
  std::vector<semantics::AigLit> tree_leaves(std::uint32_t node, std::size_t frame);
  /// Simplify: node = !(s & a) & !(!s & b), both inner gates read by it alone: {s, a, b}.
  bool ite_shape(std::uint32_t node, semantics::AigLit& s, semantics::AigLit& a,
                 semantics::AigLit& b) const;

  const semantics::Aig& aig_;
  Solver& solver_;
  bool from_initial_;
  bool simplify_;
  /// simplify: the gate already encoded for each key (an AND's sorted literals, or 0 and an
  /// ITE's three).
  std::map<std::vector<int>, int> gates_;
  std::unordered_map<std::uint64_t, int> pairs_;  ///< simplify: two-input ANDs (most gates)
  std::vector<std::uint32_t> fanout_;  ///< simplify: readers of each node (gates and latches)
  std::vector<std::vector<int>> lit_of_node_;  ///< [frame][node]: its literal, 0 = none
};

/// Clauses saying that frames `a` and `b` differ on at least one of `latches` (simple-path
/// constraints of k-induction).
void add_frames_differ(Unrolling& frames, const std::vector<std::uint32_t>& latches, std::size_t a,
                       std::size_t b);

/// The latches in the cone of influence of `roots`: read by them, directly or through the
/// next-state functions of other latches in the cone (sorted).
std::vector<std::uint32_t> cone_latches(const semantics::Aig& aig,
                                        const std::vector<semantics::AigLit>& roots);

}  // namespace sfcv::engine::sat

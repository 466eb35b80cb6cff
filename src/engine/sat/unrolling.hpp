#pragma once
// Tseitin encoding of an Aig into one solver, frame by frame and only on demand: asking for a
// literal at frame k encodes exactly its cone of influence there. Frames are linked by
// renaming: a latch at frame k+1 is the literal of its next-state function at frame k, so no
// equality clauses are needed. A latch at frame 0 is a fresh variable (constrained to its
// initial value when the unrolling starts in the initial state).
//
// Simplifying unrollings (BMC, k-induction, IC3 on IEC 61131-3 charts) also fold constants (the
// initial state's values flow through the first frames as constants, no clauses) and hash gates on
// their solver literals across all frames (a gate whose inputs are the same literals as one encoded
// before, in any frame, is that gate): on bench/run's levels 8 the first frames cost no clauses and
// the frames where part of the state stays unchanged share their gates (docs/engines.md). They
// encode a gate with up to four inputs per solver variable, not one per AND node: each node
// takes the cut of its fan-in cone that costs the fewest clauses (priority cuts with area flow,
// as in Een, Mishchenko and Sorensson, "Applying logic synthesis for speeding up SAT", 2007),
// its clauses the irredundant covers of the cut's function and of its negation.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

#include "engine/sat/sat_solver.hpp"
#include "semantics/aig.hpp"

namespace sfcv::engine::sat {

/// The cut each And node of an Aig is encoded by in a simplifying unrolling: priority cuts of
/// up to four leaves, ranked by area flow in clauses, computed on first use with the node's
/// fan-in. A node's cuts depend on its fan-in cone alone, which never changes, so one mapping
/// serves every unrolling of its Aig (IC3's frame solvers, k-induction's step cases), also
/// after nodes are added (they count one reader each).
class CutMapping {
 public:
  /// A cut of an And node's fan-in cone: its leaves (node ids, ascending) and the node's
  /// value as a function of theirs (bit m: the value when leaf i has bit i of m).
  struct Cut {
    std::array<std::uint32_t, 4> leaves{};
    std::uint8_t size = 0;
    std::uint16_t truth = 0;
    float flow = 0;  ///< area flow: clauses of this cut and its share of the leaves' cones
  };

  explicit CutMapping(const semantics::Aig& aig);
  const semantics::Aig& aig() const { return aig_; }
  /// The chosen cut of And node `node`.
  const Cut& best(std::uint32_t node);
  /// The irredundant cover of `truth`: per cube, the bits of its literals' variables
  /// (low nibble) and their polarities (high nibble).
  const std::vector<std::uint8_t>& cover_of(std::uint16_t truth);

 private:
  void enumerate(std::uint32_t node);
  /// Clauses of the encoding of `truth` (its cover and its negation's): the cost of a cut.
  int clauses_of(std::uint16_t truth);

  const semantics::Aig& aig_;
  std::vector<std::uint32_t> fanout_;   ///< readers of each node (gates and latches)
  std::vector<std::vector<Cut>> cuts_;  ///< [node] its priority cuts, best first
  std::unordered_map<std::uint16_t, std::vector<std::uint8_t>> covers_;
};

class Unrolling {
 public:
  /// `from_initial`: latches at frame 0 take their initial values. `simplify`: fold constants
  /// and hash gates (a literal may then be the solver's true literal or its negation, and two
  /// nodes may share a literal); the plain one keeps a fresh variable per latch and gate (the
  /// Grafcet machine's engines, the certificate re-checks, Houdini, loop pumping).
  /// `mapping`: the cuts to share (made here when null or of another Aig).
  Unrolling(const semantics::Aig& aig, Solver& solver, bool from_initial, bool simplify = false,
            std::shared_ptr<CutMapping> mapping = nullptr);

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
  /// The literal of the function `truth` (a 4-input truth table) of `lits`, simplified and
  /// hashed: constants and repeated variables folded, ANDs (of literals, or negated) through
  /// conjunction.
  int gate(std::uint16_t truth, const std::vector<int>& lits);

  const semantics::Aig& aig_;
  Solver& solver_;
  bool from_initial_;
  bool simplify_;
  /// simplify: the gate already encoded for each key (an AND's sorted literals, or 0, the
  /// truth table and its sorted variables).
  std::map<std::vector<int>, int> gates_;
  std::unordered_map<std::uint64_t, int> pairs_;  ///< simplify: two-input ANDs (most gates)
  std::shared_ptr<CutMapping> mapping_;           ///< simplify: the cut of each gate
  std::vector<std::vector<int>> lit_of_node_;     ///< [frame][node]: its literal, 0 = none
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

#pragma once
// The circuit of an IEC 61131-3 system simulated on explicit states, for the BDD engine's
// images and edge counts of near-explicit sets (symbolic_system.hpp): the successors of a
// state under every input valuation at once, as keys of latch bits, and the BDD of a sorted
// list of such keys.

#include <cstdint>
#include <vector>

#include "engine/bdd/bdd_manager.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine {

/// The circuit simulated on one state under every input valuation at once (bit v of a node's
/// words is its value under valuation v, input i being bit i of v): the distinct successors
/// of a state, each a key of latch bits. Latch l is bit position[l] of a key, counted from the
/// top bit of its first word, so that keys compared word by word compare the latches in the
/// order of their positions.
class SuccessorSimulator {
 public:
  SuccessorSimulator(const semantics::TransitionCircuit& circuit,
                     std::vector<std::uint32_t> position);
  std::size_t latch_words() const { return latch_words_; }
  /// Simulates the state of latch values `x`; returns how many distinct successors it has
  /// (allowed, no range error). successor(j) is the j-th of them, in increasing key order.
  std::size_t simulate(const std::vector<bool>& x);
  /// The key of the j-th distinct successor of the last simulate(): latch_words() words.
  const std::uint64_t* successor(std::size_t j) const {
    return keys_.data() + static_cast<std::size_t>(order_[j]) * latch_words_;
  }
  /// An input valuation (bit i: input i) that leads to successor(j).
  std::uint32_t valuation(std::size_t j) const { return order_[j]; }

 private:
  std::uint64_t lit(semantics::AigLit l, std::size_t w) const {
    const std::uint64_t v = value_[semantics::Aig::node_of(l) * words_ + w];
    return semantics::Aig::is_negated(l) ? ~v : v;
  }

  std::vector<std::uint32_t> position_;
  const semantics::TransitionCircuit& circuit_;
  const semantics::Aig& aig_;
  std::size_t valuations_, words_, latch_words_;
  std::uint64_t used_;
  std::vector<std::uint64_t> value_;
  /// An AND gate with its operands' negations as masks: one branch-free line per gate.
  struct Gate {
    std::uint32_t out, left, right;
    std::uint64_t left_flip, right_flip;
  };
  std::vector<Gate> gates_;
  std::vector<std::uint32_t> latch_nodes_;
  std::vector<std::uint64_t> keys_, ok_;
  std::vector<std::uint32_t> order_;
};

/// Bit `position` of a key, counted from the top bit of its first word (the order in which
/// keys compared word by word compare their bits).
inline void set_key_bit(std::uint64_t* key, std::uint32_t position) {
  key[position / 64] |= std::uint64_t{1} << (63 - position % 64);
}
inline bool key_bit(const std::uint64_t* key, std::uint32_t position) {
  return ((key[position / 64] >> (63 - position % 64)) & 1U) != 0;
}

/// The rank of each latch among the latches sorted by the level of its current variable
/// (`current_var[l]`): the key bit a SuccessorSimulator gives it, so that sorted keys split by
/// the top variable first.
std::vector<std::uint32_t> latch_ranks(const std::vector<int>& current_var);

/// Each rank's current variable: the inverse of `rank_of` (latch_ranks()) over `current_var`.
std::vector<int> var_at_rank(const std::vector<std::uint32_t>& rank_of,
                             const std::vector<int>& current_var);

/// Sorts `keys` (records of `width` words, compared word by word) and keeps one of each;
/// returns how many are left.
std::size_t sort_distinct_keys(std::vector<std::uint64_t>& keys, std::size_t width);

/// The BDD of the first `count` keys of `keys` (records of `width` words, sorted and distinct;
/// bit r of a record, from the top, is the variable `var_at_rank[r]`, in level order).
bdd::Bdd bdd_of_sorted_keys(const std::vector<std::uint64_t>& keys, std::size_t count,
                            std::size_t width, const std::vector<int>& var_at_rank);

}  // namespace sfcv::engine

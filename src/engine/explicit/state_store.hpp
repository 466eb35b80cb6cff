#pragma once
// Open-addressing hash set of fixed-width packed states. States live contiguously in one vector
// (no per-state heap allocation) and are numbered in insertion order, so BFS numbering is the
// state index. A state of at most 64 bits is one word compared directly: 16 bytes per state at
// the table's half load (8 for the word, 8 for two slots).

#include <cstdint>
#include <utility>
#include <vector>

#include "semantics/state_layout.hpp"

namespace sfcv::engine {

using semantics::StateView;
using semantics::StateWord;

/// The mask of the state counter between two reads of the clock in an exploration loop: every
/// 1024 states of one word, down to every state for states of 1024 words or more (a chart of a
/// million steps costs milliseconds per state, and --timeout must still hold within a second).
inline std::uint32_t clock_poll_mask(std::uint32_t words_per_state) {
  std::uint32_t every = 1024;
  while (every > 1 && every * words_per_state > 1024) every /= 2;
  return every - 1;
}

class StateStore {
 public:
  explicit StateStore(std::uint32_t words_per_state);

  /// Inserts `state` unless present; returns its index and whether it was new.
  std::pair<std::uint32_t, bool> insert(StateView state);
  /// Index of `state`, or kAbsent.
  std::uint32_t find(StateView state) const;

  StateView at(std::uint32_t index) const {
    return {data_.data() + static_cast<std::size_t>(index) * words_, words_};
  }
  std::uint32_t size() const { return size_; }
  std::uint32_t words_per_state() const { return words_; }
  std::size_t memory_bytes() const;

  static constexpr std::uint32_t kAbsent = ~0U;

 private:
  std::uint64_t hash(StateView state) const;
  bool equal_at(std::uint32_t index, StateView state) const;
  std::pair<std::uint32_t, bool> insert_word(StateWord word);
  void grow();

  std::uint32_t words_;
  std::uint32_t size_ = 0;
  std::vector<StateWord> data_;
  std::vector<std::uint32_t> slots_;   ///< state index + 1; 0 = empty
  std::vector<std::uint32_t> hashes_;  ///< high bits of each state's hash, to skip most compares
                                       ///< (not kept for one-word states: compared directly)
};

}  // namespace sfcv::engine

#pragma once
// The stored form of a state when some of its bits are known to follow others. A search that
// keeps its states in this form stores fewer words per state (parallel 20 --selector: 82 state
// bits, 42 stored, one word instead of two), and converts back only where a state is read by the
// semantics: judging a property, rebuilding a counterexample.
//
// The codec only moves bits; which bits may be dropped is proved by whoever builds it (the
// compiled enumerator: latches with the same next-state literal, see compiled_successors.cpp).

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "semantics/state_layout.hpp"

namespace sfcv::engine {

class StateCodec {
 public:
  /// A bit of the full state that follows a stored bit: full = stored ^ negated.
  struct Follower {
    std::uint32_t stored_bit;
    std::uint32_t full_bit;
    bool negated;
  };

  StateCodec(std::uint32_t full_words, std::uint32_t stored_bits, std::vector<Follower> followers,
             std::vector<semantics::StateWord> constant)
      : full_words_(full_words),
        stored_bits_(stored_bits),
        stored_words_(std::max<std::uint32_t>(1, (stored_bits + 63) / 64)),
        followers_(std::move(followers)),
        constant_(std::move(constant)),
        follows_(full_words, 0) {
    for (const auto& f : followers_) follows_[f.full_bit / 64] |= mask(f.full_bit);
    // Judging a state converts it: per stored byte, the full bits of each of its 256 values,
    // while that table stays small (a loop over followers cost 200 ns per state at 82 bits).
    const std::size_t words = std::size_t{stored_words_} * 8 * 256 * full_words_;
    if (words > kMaxTableWords) return;
    by_byte_.assign(words, 0);
    for (const auto& f : followers_)
      for (std::uint32_t value = 0; value < 256; ++value)
        if ((((value >> (f.stored_bit % 8)) & 1U) != 0) != f.negated)
          by_byte_[(std::size_t{f.stored_bit / 8} * 256 + value) * full_words_ + f.full_bit / 64] |=
              mask(f.full_bit);
  }

  std::uint32_t full_words() const { return full_words_; }
  std::uint32_t stored_words() const { return stored_words_; }
  std::uint32_t stored_bits() const { return stored_bits_; }

  /// The stored bit a bit of the full state follows; nullopt when the full bit is a constant.
  std::optional<std::uint32_t> stored_bit_of(std::uint32_t full_bit) const {
    for (const auto& f : followers_)
      if (f.full_bit == full_bit) return f.stored_bit;
    return std::nullopt;
  }

  /// Writes the full state of `stored` to `full` (full_words() words).
  void to_full(const semantics::StateWord* stored, semantics::StateWord* full) const {
    for (std::uint32_t w = 0; w < full_words_; ++w) full[w] = constant_[w];
    if (by_byte_.empty()) {
      for (const auto& f : followers_)
        if (bit(stored, f.stored_bit) != f.negated) full[f.full_bit / 64] |= mask(f.full_bit);
      return;
    }
    const semantics::StateWord* entry = by_byte_.data();
    for (std::uint32_t b = 0; b < stored_words_ * 8; ++b, entry += 256 * full_words_) {
      const auto value = static_cast<std::uint32_t>(stored[b / 8] >> (8 * (b % 8))) & 0xFFU;
      const semantics::StateWord* bits = entry + value * full_words_;
      for (std::uint32_t w = 0; w < full_words_; ++w) full[w] |= bits[w];
    }
  }
  /// Writes the stored form of `full` to `stored` (stored_words() words); false when `full` is
  /// not a state of this form (a dropped bit does not follow its stored bit).
  bool to_stored(const semantics::StateWord* full, semantics::StateWord* stored) const {
    for (std::uint32_t w = 0; w < stored_words_; ++w) stored[w] = 0;
    for (std::uint32_t w = 0; w < full_words_; ++w)
      if ((full[w] & ~follows_[w]) != constant_[w]) return false;
    for (const auto& f : followers_)
      if (bit(full, f.full_bit) != f.negated) stored[f.stored_bit / 64] |= mask(f.stored_bit);
    for (const auto& f : followers_)
      if (bit(full, f.full_bit) != (bit(stored, f.stored_bit) != f.negated)) return false;
    return true;
  }

 private:
  static bool bit(const semantics::StateWord* s, std::uint32_t b) {
    return ((s[b / 64] >> (b % 64)) & 1U) != 0;
  }
  static semantics::StateWord mask(std::uint32_t b) { return semantics::StateWord{1} << (b % 64); }

  std::uint32_t full_words_, stored_bits_, stored_words_;
  std::vector<Follower> followers_;             ///< every full bit that is not constant
  std::vector<semantics::StateWord> constant_;  ///< the full bits that are always set
  std::vector<semantics::StateWord> follows_;   ///< the full bits some follower sets
  static constexpr std::size_t kMaxTableWords = std::size_t{1} << 15;  // 256 KB
  std::vector<semantics::StateWord> by_byte_;  ///< see the constructor; empty when too large
};

}  // namespace sfcv::engine

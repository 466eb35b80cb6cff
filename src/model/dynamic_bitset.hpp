#pragma once
// A fixed-size set of small integers (state, edge or step indices) stored as 64-bit words: the
// explicit evaluation of set queries is a sequence of whole-set operations on these.

#include <bit>
#include <cstdint>
#include <vector>

namespace sfcv::model {

class DynamicBitset {
 public:
  DynamicBitset() = default;
  explicit DynamicBitset(std::uint64_t size, bool value = false)
      : size_(size), words_((size + 63) / 64, value ? ~std::uint64_t{0} : 0) {
    trim();
  }

  std::uint64_t size() const { return size_; }
  bool test(std::uint64_t i) const { return (words_[i / 64] >> (i % 64)) & 1U; }
  void set(std::uint64_t i) { words_[i / 64] |= std::uint64_t{1} << (i % 64); }
  void reset(std::uint64_t i) { words_[i / 64] &= ~(std::uint64_t{1} << (i % 64)); }

  std::uint64_t count() const {
    std::uint64_t n = 0;
    for (auto w : words_) n += static_cast<std::uint64_t>(std::popcount(w));
    return n;
  }
  bool none() const {
    for (auto w : words_)
      if (w) return false;
    return true;
  }

  DynamicBitset& operator|=(const DynamicBitset& o) {
    for (std::size_t i = 0; i < words_.size(); ++i) words_[i] |= o.words_[i];
    return *this;
  }
  DynamicBitset& operator&=(const DynamicBitset& o) {
    for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= o.words_[i];
    return *this;
  }
  /// Removes the elements of `o`.
  DynamicBitset& subtract(const DynamicBitset& o) {
    for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= ~o.words_[i];
    return *this;
  }
  bool operator==(const DynamicBitset& o) const = default;

  /// Calls f(i) for each element, in increasing order.
  template <class F>
  void for_each(F&& f) const {
    for (std::size_t w = 0; w < words_.size(); ++w)
      for (auto bits = words_[w]; bits; bits &= bits - 1)
        f(static_cast<std::uint64_t>(w) * 64 + static_cast<std::uint64_t>(std::countr_zero(bits)));
  }

  std::vector<std::uint64_t> elements() const {
    std::vector<std::uint64_t> r;
    for_each([&](std::uint64_t i) { r.push_back(i); });
    return r;
  }

 private:
  void trim() {
    if (size_ % 64 && !words_.empty()) words_.back() &= (std::uint64_t{1} << (size_ % 64)) - 1;
  }

  std::uint64_t size_ = 0;
  std::vector<std::uint64_t> words_;
};

}  // namespace sfcv::model

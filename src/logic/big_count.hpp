#pragma once
// An exact count of states or edges: symbolic engines count sets far beyond 2^64 (tanks 24 has
// about 5 * 10^23 states), and a double or a 64-bit integer would print them rounded or as 0.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace sfcv::logic {

/// A non-negative integer of any size (only what counting needs: add, times 2^k, print).
class BigCount {
 public:
  BigCount() = default;
  BigCount(std::uint64_t value);  // NOLINT(google-explicit-constructor): counts are numbers

  BigCount& operator+=(const BigCount& other);
  /// *this times 2^bits.
  BigCount shifted_left(unsigned bits) const;

  /// The value when it fits in 64 bits.
  std::optional<std::uint64_t> to_u64() const;
  /// The nearest double (for limits and progress lines).
  double to_double() const;
  /// Decimal digits.
  std::string str() const;

  friend bool operator==(const BigCount&, const BigCount&) = default;
  friend std::ostream& operator<<(std::ostream& out, const BigCount& c) { return out << c.str(); }

 private:
  std::vector<std::uint32_t> limbs_;  ///< least significant first, no leading zero limbs
  void trim();
};

}  // namespace sfcv::logic

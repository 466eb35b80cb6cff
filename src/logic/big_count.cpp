#include "logic/big_count.hpp"

#include <algorithm>

namespace sfcv::logic {

BigCount::BigCount(std::uint64_t value) {
  while (value) {
    limbs_.push_back(static_cast<std::uint32_t>(value));
    value >>= 32;
  }
}

void BigCount::trim() {
  while (!limbs_.empty() && limbs_.back() == 0) limbs_.pop_back();
}

BigCount& BigCount::operator+=(const BigCount& other) {
  limbs_.resize(std::max(limbs_.size(), other.limbs_.size()) + 1, 0);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < limbs_.size(); ++i) {
    const std::uint64_t sum =
        carry + limbs_[i] + (i < other.limbs_.size() ? other.limbs_[i] : std::uint64_t{0});
    limbs_[i] = static_cast<std::uint32_t>(sum);
    carry = sum >> 32;
  }
  trim();
  return *this;
}

BigCount BigCount::shifted_left(unsigned bits) const {
  if (limbs_.empty()) return {};
  BigCount r;
  const unsigned whole = bits / 32, part = bits % 32;
  r.limbs_.assign(whole, 0);
  std::uint32_t carry = 0;
  for (auto limb : limbs_) {
    r.limbs_.push_back(part ? (limb << part) | carry : limb);
    carry = part ? limb >> (32 - part) : 0;
  }
  r.limbs_.push_back(carry);
  r.trim();
  return r;
}

std::optional<std::uint64_t> BigCount::to_u64() const {
  if (limbs_.size() > 2) return std::nullopt;
  std::uint64_t v = 0;
  for (std::size_t i = limbs_.size(); i-- > 0;) v = (v << 32) | limbs_[i];
  return v;
}

double BigCount::to_double() const {
  double v = 0;
  for (std::size_t i = limbs_.size(); i-- > 0;) v = v * 4294967296.0 + limbs_[i];
  return v;
}

std::string BigCount::str() const {
  if (limbs_.empty()) return "0";
  // Repeated division by 10^9, nine digits at a time.
  std::vector<std::uint32_t> n = limbs_;
  std::vector<std::uint32_t> chunks;
  while (!n.empty()) {
    std::uint64_t rem = 0;
    for (std::size_t i = n.size(); i-- > 0;) {
      const std::uint64_t cur = (rem << 32) | n[i];
      n[i] = static_cast<std::uint32_t>(cur / 1'000'000'000);
      rem = cur % 1'000'000'000;
    }
    chunks.push_back(static_cast<std::uint32_t>(rem));
    while (!n.empty() && n.back() == 0) n.pop_back();
  }
  std::string out = std::to_string(chunks.back());
  for (std::size_t i = chunks.size() - 1; i-- > 0;) {
    const std::string part = std::to_string(chunks[i]);
    out += std::string(9 - part.size(), '0') + part;
  }
  return out;
}

}  // namespace sfcv::logic

#include "semantics/state_layout.hpp"

#include <bit>
#include <stdexcept>

namespace sfcv::semantics {

std::uint32_t StateLayout::add_field(std::string name, FieldKind kind, std::int64_t lo,
                                     std::int64_t hi) {
  if (hi < lo) throw std::invalid_argument("StateLayout::add_field: empty range for " + name);
  const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  const auto width = span == 0 ? 1U : static_cast<std::uint32_t>(std::bit_width(span));
  // A field never straddles two words, so get/set stay one shift and one mask.
  if (bits_ / 64 != (bits_ + width - 1) / 64) bits_ = (bits_ / 64 + 1) * 64;
  fields_.push_back(StateField{std::move(name), kind, bits_, width, lo});
  bits_ += width;
  return static_cast<std::uint32_t>(fields_.size() - 1);
}

std::int64_t StateLayout::get(StateView state, std::uint32_t field) const {
  const auto& f = fields_[field];
  const std::uint64_t word = state[f.offset / 64] >> (f.offset % 64);
  const std::uint64_t mask = f.width == 64 ? ~0ULL : ((1ULL << f.width) - 1);
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(f.lo) + (word & mask));
}

void StateLayout::set(MutableStateView state, std::uint32_t field, std::int64_t value) const {
  const auto& f = fields_[field];
  const std::uint64_t mask = f.width == 64 ? ~0ULL : ((1ULL << f.width) - 1);
  const std::uint64_t encoded =
      (static_cast<std::uint64_t>(value) - static_cast<std::uint64_t>(f.lo)) & mask;
  auto& w = state[f.offset / 64];
  w = (w & ~(mask << (f.offset % 64))) | (encoded << (f.offset % 64));
}

}  // namespace sfcv::semantics

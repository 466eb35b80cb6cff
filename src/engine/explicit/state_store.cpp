#include "engine/explicit/state_store.hpp"

#include <algorithm>
#include <stdexcept>

namespace sfcv::engine {

StateStore::StateStore(std::uint32_t words_per_state)
    : words_(std::max<std::uint32_t>(words_per_state, 1)), slots_(1024, 0) {}

std::uint64_t StateStore::hash(StateView state) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::uint32_t i = 0; i < words_; ++i) h = mix(h ^ state[i]);
  return h;
}

bool StateStore::equal_at(std::uint32_t index, StateView state) const {
  const StateWord* p = data_.data() + static_cast<std::size_t>(index) * words_;
  return std::equal(p, p + words_, state.begin());
}

std::uint32_t StateStore::find(StateView state) const {
  const std::uint64_t h = hash(state);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = h & mask;; i = (i + 1) & mask) {
    const std::uint32_t s = slots_[i];
    if (s == 0) return kAbsent;
    if (words_ == 1
            ? data_[s - 1] == state[0]
            : hashes_[s - 1] == static_cast<std::uint32_t>(h >> 32) && equal_at(s - 1, state))
      return s - 1;
  }
}

std::pair<std::uint32_t, bool> StateStore::insert_wide(StateView state) {
  const std::uint64_t h = hash(state);
  const auto tag = static_cast<std::uint32_t>(h >> 32);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = h & mask;; i = (i + 1) & mask) {
    const std::uint32_t s = slots_[i];
    if (s == 0) {
      if (size_ == kAbsent - 1) throw std::length_error("StateStore: more than 2^32-2 states");
      data_.insert(data_.end(), state.begin(), state.begin() + words_);
      hashes_.push_back(tag);
      slots_[i] = ++size_;
      return {size_ - 1, true};
    }
    if (hashes_[s - 1] == tag && equal_at(s - 1, state)) return {s - 1, false};
  }
}

std::uint32_t StateStore::add_word(std::size_t slot, StateWord word) {
  if (size_ == kAbsent - 1) throw std::length_error("StateStore: more than 2^32-2 states");
  data_.push_back(word);
  slots_[slot] = ++size_;
  return size_ - 1;
}

void StateStore::grow() {
  std::vector<std::uint32_t> bigger(slots_.size() * 2, 0);
  const std::size_t mask = bigger.size() - 1;
  for (std::uint32_t idx = 0; idx < size_; ++idx) {
    const std::uint64_t h = hash(at(idx));
    std::size_t i = h & mask;
    while (bigger[i] != 0) i = (i + 1) & mask;
    bigger[i] = idx + 1;
  }
  slots_ = std::move(bigger);
}

std::size_t StateStore::memory_bytes() const {
  return data_.capacity() * sizeof(StateWord) + slots_.capacity() * sizeof(std::uint32_t) +
         hashes_.capacity() * sizeof(std::uint32_t);
}

}  // namespace sfcv::engine

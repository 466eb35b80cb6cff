#include "engine/explicit/state_store.hpp"

#include <algorithm>
#include <stdexcept>

namespace sfcv::engine {

StateStore::StateStore(std::uint32_t words_per_state, std::uint32_t tagged_states,
                       std::uint32_t membership_bits)
    : words_(std::max<std::uint32_t>(words_per_state, 1)),
      membership_(membership_bits > 0),
      state_bits_(std::min<std::uint32_t>(membership_bits, 64)),
      bits_mask_(state_bits_ >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << state_bits_) - 1),
      shift_{std::max<std::uint32_t>(1, state_bits_ * 30 / 64),
             std::max<std::uint32_t>(1, state_bits_ * 27 / 64),
             std::max<std::uint32_t>(1, state_bits_ * 31 / 64)},
      // A hash of b bits has its top 7 at b - 7: shifted to the tag's bits 24-30. Fewer than 31
      // bits: no tags (a narrow state leaves the indexed form at once).
      tag_shift_(membership_ ? (state_bits_ >= 31 ? state_bits_ - 31 : 0) : 33),
      tag_mask_(words_ == 1 && (!membership_ || state_bits_ >= 31) ? kTagBits : 0),
      tagged_states_(std::min(tagged_states, kTaggedStates)),
      slots_(1024, 0) {
  if (membership_ && words_ != 1)
    throw std::logic_error("StateStore: membership_bits is for one-word states only");
  rehash(slots_.size());  // takes the quotient form if it fits already
}

void StateStore::state_hashes(StateView states, std::size_t count, std::uint64_t* out) const {
  if (words_ != 1 || !membership_) {
    for (std::size_t k = 0; k < count; ++k) out[k] = state_hash(states.subspan(k * words_, words_));
    return;
  }
  const std::uint64_t mask = bits_mask_;
  const std::uint32_t shift0 = shift_[0], shift1 = shift_[1], shift2 = shift_[2];
  for (std::size_t k = 0; k < count; ++k)
    out[k] = mix_bits(states[k], mask, shift0, shift1, shift2);
}

void StateStore::throw_too_wide() {
  throw std::logic_error("StateStore: a state wider than the membership_bits it was promised");
}

std::uint64_t StateStore::hash(StateView state) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::uint32_t i = 0; i < words_; ++i) h = mix(h ^ state[i]);
  return h;
}

bool StateStore::equal_at(std::uint32_t index, StateView state) const {
  const StateWord* p = data_.data() + static_cast<std::size_t>(index) * words_;
  return same_state(p, state.data(), words_);
}

std::uint32_t StateStore::find(StateView state) const {
  if (membership_) throw std::logic_error("StateStore::find: only membership is asked");
  const std::uint64_t h = state_hash(state);
  if (words_ == 1) {
    const std::uint32_t s = slots_[probe_word(state[0], h)];
    return s == 0 ? kAbsent : index_of(s);
  }
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = h & mask;; i = (i + 1) & mask) {
    const std::uint32_t s = slots_[i];
    if (s == 0) return kAbsent;
    if (stored_at(s, i, state, h)) return s - 1;
  }
}

std::pair<std::uint32_t, bool> StateStore::insert_wide(StateView state, std::uint64_t h) {
  const auto tag = static_cast<std::uint32_t>(h >> 32);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = h & mask;; i = (i + 1) & mask) {
    const std::uint32_t s = slots_[i];
    if (s == 0) {
      if (size_ == kAbsent - 1) throw std::length_error("StateStore: more than 2^32-2 states");
      data_.append(state.data(), words_);
      hashes_.push_back(tag);
      slots_[i] = ++size_;
      return {size_ - 1, true};
    }
    if (stored_at(s, i, state, h)) return {s - 1, false};
  }
}

std::uint32_t StateStore::add_word(std::size_t slot, StateWord word, std::uint64_t hash) {
  if (size_ == kAbsent - 1) throw std::length_error("StateStore: more than 2^32-2 states");
  const std::uint32_t value = slot_of(size_, hash, slot);
  data_.push_back(word);
  slots_[slot] = value;
  return size_++;
}

std::size_t StateStore::insert_new_states(const StateWord* states, const std::uint64_t* hashes,
                                          std::size_t first, std::size_t last,
                                          std::size_t ahead_end, std::uint64_t size_cap) {
  std::size_t k = first;
  while (k < last) {
    if (size_ >= size_cap) return k;
    if (full_for_one_more()) grow();
    if (!quotient_) {
      // The indexed form: the slots refer to the stored states.
      if (k + kLookAhead < ahead_end) prefetch_slot(hashes[k + kLookAhead]);
      if (k + kLookAhead / 2 < ahead_end) prefetch_state(hashes[k + kLookAhead / 2]);
      static_cast<void>(insert_if_new(StateView(states + k * words_, words_), hashes[k]));
      ++k;
      continue;
    }
    // The quotient form (one-word states), until the table grows or a probe runs past the
    // farthest distance.
    std::uint32_t* const slots = slots_.data();
    const QuotientProbe probe = quotient_probe();
    // Each one-word state takes the next index, up to the last a slot may number.
    const std::uint64_t stop_at = std::min<std::uint64_t>(
        {size_cap, states_before_growth(slots_.size()), std::uint64_t{kAbsent} - 1});
    std::uint64_t size = size_;
    bool no_room = false;
    for (; k < last && size < stop_at; ++k) {
      if (k + kLookAhead < ahead_end)
        __builtin_prefetch(slots + probe.home(hashes[k + kLookAhead]));
      const std::uint64_t h = hashes[k];
      const std::size_t i = probe.slot(h);
      if (i == kNoRoom) {
        no_room = true;
        break;
      }
      if (slots[i] == 0) {
        slots[i] = probe.value(h, i);
        data_.push_back(states[k]);
        ++size;
      }
    }
    size_ = static_cast<std::uint32_t>(size);
    if (no_room) leave_quotient_form();
    if (size_ == kAbsent - 1 && k < last)
      throw std::length_error("StateStore: more than 2^32-2 states");
  }
  return k;
}

void StateStore::grow() {
  if (size_ == tag_limit()) {
    untag();  // more states than a tagged slot can number
    if (!full_for_one_more()) return;
  }
  rehash(slots_.size() * 2);
}

void StateStore::untag() {
  for (std::uint32_t& s : slots_)
    if (s != 0) s &= ~tag_mask_;
  tag_mask_ = 0;
}

void StateStore::leave_quotient_form() {
  left_quotient_ = true;
  rehash(slots_.size());
}

void StateStore::rehash(std::size_t slot_count) {
  std::vector<std::uint32_t> table(slot_count, 0);
  const std::size_t mask = table.size() - 1;
  slot_bits_ = static_cast<std::uint32_t>(__builtin_ctzll(slot_count));
  const bool was_quotient = quotient_;
  // The remainder and the distance in 32 bits.
  quotient_ = membership_ && !left_quotient_ && state_bits_ <= slot_bits_ + (32 - kDistanceBits);
  remainder_bits_ = quotient_ && state_bits_ > slot_bits_ ? state_bits_ - slot_bits_ : 0;
  if (quotient_)
    tag_mask_ = 0;
  else if (was_quotient)  // left: tags again while the indices fit beside them
    tag_mask_ = state_bits_ >= 31 && size_ < tagged_states_ ? kTagBits : 0;
  // Each insertion misses the cache: the slot of the state kAhead on is loaded meanwhile.
  constexpr std::uint32_t kAhead = 16;
  std::uint64_t ahead[kAhead];
  for (std::uint32_t idx = 0; idx < std::min(size_, kAhead); ++idx) {
    ahead[idx] = state_hash(at(idx));
    __builtin_prefetch(table.data() + (ahead[idx] & mask), 1);
  }
  for (std::uint32_t idx = 0; idx < size_; ++idx) {
    const std::uint64_t h = ahead[idx % kAhead];
    if (idx + kAhead < size_) {
      ahead[idx % kAhead] = state_hash(at(idx + kAhead));
      __builtin_prefetch(table.data() + (ahead[idx % kAhead] & mask), 1);
    }
    std::size_t i = h & mask;
    while (table[i] != 0) i = (i + 1) & mask;
    const std::uint32_t value = slot_of(idx, h, i);
    if (value == 0) {  // farther from home than a quotient records
      left_quotient_ = true;
      rehash(slot_count);
      return;
    }
    table[i] = value;
  }
  slots_ = std::move(table);
}

std::size_t StateStore::memory_bytes() const {
  return data_.resident_bytes() + slots_.capacity() * sizeof(std::uint32_t) +
         hashes_.resident_bytes();
}

}  // namespace sfcv::engine

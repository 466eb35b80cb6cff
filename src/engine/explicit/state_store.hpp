#pragma once
// Open-addressing hash set of fixed-width packed states. States live contiguously in one
// remapped array (no per-state heap allocation) and are numbered in insertion order, so BFS
// numbering is the state index. A state of at most 64 bits is one word compared directly: 8
// bytes for the word and 4 per slot, so 16 bytes per state at half load and 13.3 at three
// quarters, the load that tables of 2^22 slots and more reach before they grow
// (states_before_growth()). Below 2^24 states, a one-word state's slot also holds 7 bits of its
// hash: a probe passes a slot of another state without reading that state (a third of the
// look-ups probe past their first slot, each a cache miss).
//
// A store asked only whether a one-word state is stored (the invariant search: a new state's
// index is the size at its insertion) holds each state in its slot once the table is large
// enough (the quotient form): the hash is a bijection of the state's bits, its low bits give
// the state's home slot, and the slot keeps the rest and the distance from home. A look-up
// then reads one cache line, not two, and the table keeps its 4 bytes per slot.

#include <cstdint>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/explicit/mapped_array.hpp"
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

/// Whether the states at `a` and `b` of `words` words are equal. A plain loop: states are a few
/// words, where a call to memcmp costs more than the compare.
inline bool same_state(const StateWord* a, const StateWord* b, std::uint32_t words) {
  for (std::uint32_t i = 0; i < words; ++i)
    if (a[i] != b[i]) return false;
  return true;
}

class StateStore {
 public:
  static constexpr std::uint32_t kTaggedStates = (1U << 24) - 2;
  /// `tagged_states`: how many one-word states are stored with a tag in their slot (at most
  /// the 2^24 - 2 that the slot can number; fewer only to test the change of mode).
  /// `membership_bits` > 0: the states are one word of at most that many bits, and the store is
  /// never asked the index of a state stored before (find() is refused, insert() gives kAbsent
  /// for it), so it may hold them in quotient form. A wider state is then a logic error.
  explicit StateStore(std::uint32_t words_per_state, std::uint32_t tagged_states = kTaggedStates,
                      std::uint32_t membership_bits = 0);

  /// Inserts `state` unless present; returns its index and whether it was new (kAbsent for a
  /// state stored before, when only membership is asked).
  std::pair<std::uint32_t, bool> insert(StateView state) {
    if (membership_) {
      const auto index = insert_if_new(state, state_hash(state));
      return {index, index != kAbsent};
    }
    if (full_for_one_more()) grow();
    if (words_ != 1) return insert_wide(state, hash(state));
    const std::uint64_t h = hash_word(state[0]);
    const std::size_t i = probe_word(state[0], h);
    if (slots_[i] == 0) return {add_word(i, state[0], h), true};
    return {index_of(slots_[i]), false};
  }
  /// Inserts `state` unless present: its index when it is new, kAbsent when it was stored.
  /// `hash` is state_hash(state).
  [[gnu::always_inline]] std::uint32_t insert_if_new(StateView state, std::uint64_t hash) {
    if (full_for_one_more()) grow();
    if (words_ != 1) {
      const auto [index, fresh] = insert_wide(state, hash);
      return fresh ? index : kAbsent;
    }
    if (quotient_) {
      const std::size_t i = probe_quotient(hash);
      if (i != kNoRoom) return slots_[i] == 0 ? add_word(i, state[0], hash) : kAbsent;
      leave_quotient_form();  // its probe would pass the farthest distance a slot records
    }
    const std::size_t i = probe_word(state[0], hash);
    return slots_[i] == 0 ? add_word(i, state[0], hash) : kAbsent;
  }
  /// How many look-ups ahead insert_new_states() loads a slot: each misses the cache, and the
  /// misses of several look-ups overlap.
  static constexpr std::size_t kLookAhead = 32;
  /// The serial searches' insertion of one source's targets: inserts state k of `states`
  /// (packed, words_per_state() words each), of hash hashes[k] (state_hash()), for k from
  /// `first` on, in order, while the store holds fewer than `size_cap` states; the new ones
  /// take the next indices. Returns the first k not looked up: `last` when every one was.
  /// Loads the slot of hashes[k + kLookAhead] below `ahead_end` meanwhile. One call per source
  /// keeps the table's fields in registers, which a call per target reloads after each store
  /// to a slot.
  std::size_t insert_new_states(const StateWord* states, const std::uint64_t* hashes,
                                std::size_t first, std::size_t last, std::size_t ahead_end,
                                std::uint64_t size_cap);
  /// Index of `state`, or kAbsent. Refused when only membership is asked.
  std::uint32_t find(StateView state) const;
  /// Whether the slots hold the states (quotients), not their indices.
  bool quotient_form() const { return quotient_; }

  StateView at(std::uint32_t index) const {
    return {data_.data() + static_cast<std::size_t>(index) * words_, words_};
  }
  /// The states [first, first + count), packed one after another.
  StateView range(std::uint32_t first, std::uint32_t count) const {
    return {data_.data() + static_cast<std::size_t>(first) * words_,
            static_cast<std::size_t>(count) * words_};
  }
  std::uint32_t size() const { return size_; }
  std::uint32_t words_per_state() const { return words_; }
  std::size_t memory_bytes() const;

  static constexpr std::uint32_t kAbsent = ~0U;

  /// state_hash() of each of the `count` states packed in `states`, into `out`: one call for
  /// a chunk's targets keeps the hash's parameters in registers, which a call per state
  /// reloads after each store of a hash.
  void state_hashes(StateView states, std::size_t count, std::uint64_t* out) const;
  [[gnu::always_inline]] std::uint64_t state_hash(StateView state) const {
    if (words_ != 1) return hash(state);
    return membership_ ? mix_bits(state[0]) : hash_word(state[0]);
  }
  /// Hints that a look-up of a state of hash `hash` follows: loads its first slot.
  void prefetch_slot(std::uint64_t hash) const {
    __builtin_prefetch(slots_.data() + (hash & (slots_.size() - 1)));
  }
  /// Hints that a look-up of a state of hash `hash` follows soon (after prefetch_slot()): loads
  /// the stored state its first slot refers to.
  [[gnu::always_inline]] void prefetch_state(std::uint64_t hash) const {
    if (quotient_) return;  // the slot holds the state
    const std::uint32_t s = slots_[hash & (slots_.size() - 1)];
    if (s == 0 || (s & tag_mask_) != tag_of(hash)) return;
    __builtin_prefetch(data_.data() + static_cast<std::size_t>(index_of(s)) * words_);
    if (words_ > 1) __builtin_prefetch(hashes_.data() + index_of(s));
  }
  /// Room for `count` more states, so that those stored do not move while they are added
  /// (other threads may read them meanwhile).
  void reserve_states(std::uint64_t count) {
    data_.reserve(static_cast<std::size_t>((size_ + count) * words_));
    if (words_ > 1) hashes_.reserve(static_cast<std::size_t>(size_ + count));
  }

 private:
  std::uint64_t hash(StateView state) const;
  bool equal_at(std::uint32_t index, StateView state) const;
  /// Whether the value `s` of slot `i` holds `state`, of hash `hash`.
  bool stored_at(std::uint32_t s, std::size_t i, StateView state, std::uint64_t hash) const {
    if (quotient_) return s == quotient_at(hash, i);
    return words_ == 1
               ? (s & tag_mask_) == tag_of(hash) && data_[index_of(s)] == state[0]
               : hashes_[s - 1] == static_cast<std::uint32_t>(hash >> 32) && equal_at(s - 1, state);
  }
  // A one-word state is its own key: no stored hash, no call to compare. Inline: the search
  // looks up every edge's target. The slot of the one-word state `word` of hash `hash`: the
  // one that holds it, or the empty one where it goes. Linear probing,
  // read four slots at a time: the slots whose tag matches and the empty ones are found at
  // once, so a look-up takes one round (and one branch) where a slot at a time took several at
  // the load of three quarters.
  [[gnu::always_inline]] std::size_t probe_word(StateWord word, std::uint64_t hash) const {
    const std::size_t mask = slots_.size() - 1;  // a power of two of at least 16
    const std::uint32_t* slots = slots_.data();
    const StateWord* data = data_.data();
    const std::uint32_t tag = tag_of(hash);
    const std::size_t start = hash & mask;
    std::size_t group = start & ~kGroupMask;
    // Slots before the start belong to other probe paths.
    std::uint32_t on_path = ~std::uint32_t{0} << (start & kGroupMask);
    for (;;) {
      std::uint32_t empty, match;
      group_masks(slots + group, tag, empty, match);
      empty &= on_path;
      // Candidates before the path's first empty slot (an empty slot also matches tag 0).
      match &= on_path & ((empty & (0U - empty)) - 1U);
      for (; match != 0; match &= match - 1) {
        const std::size_t i = group + static_cast<std::size_t>(__builtin_ctz(match));
        if (data[index_of(slots[i])] == word) return i;
      }
      if (empty != 0) return group + static_cast<std::size_t>(__builtin_ctz(empty));
      group = (group + kGroupSlots) & mask;
      on_path = ~std::uint32_t{0};
    }
  }
  static constexpr std::size_t kGroupSlots = 4;
  static constexpr std::size_t kGroupMask = kGroupSlots - 1;
  /// Bit k of `empty` (`match`): slot k of the kGroupSlots at `group` is empty (carries the
  /// tag `tag`). Tags are compared in the indexed form only.
  void group_masks(const std::uint32_t* group, std::uint32_t tag, std::uint32_t& empty,
                   std::uint32_t& match) const {
#if defined(__SSE2__)
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(group));
    const __m128i masked = _mm_and_si128(v, _mm_set1_epi32(static_cast<int>(tag_mask_)));
    empty = static_cast<std::uint32_t>(
        _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(v, _mm_setzero_si128()))));
    match = static_cast<std::uint32_t>(_mm_movemask_ps(
        _mm_castsi128_ps(_mm_cmpeq_epi32(masked, _mm_set1_epi32(static_cast<int>(tag))))));
#else
    empty = match = 0;
    for (std::uint32_t k = 0; k < kGroupSlots; ++k) {
      empty |= static_cast<std::uint32_t>(group[k] == 0) << k;
      match |= static_cast<std::uint32_t>((group[k] & tag_mask_) == tag) << k;
    }
#endif
  }
  /// How many states the table holds before it grows: half its slots, and three quarters from
  /// 2^22 slots (16 MB) on. Each slot probed past the first costs a read of a stored state, but
  /// the grouped probe finds most within the first cache line, past a million states memory
  /// bounds the search, and the load of three quarters takes a state from 16 to 8 bytes of
  /// table just after a doubling (docs/benchmarks.md).
  std::size_t states_before_growth(std::size_t slot_count) const {
    return slot_count < kDenseTableSlots ? slot_count / 2 : slot_count / 4 * 3;
  }
  static constexpr std::size_t kDenseTableSlots = std::size_t{1} << 22;
  /// Whether one more state would fill the table past its load, or past the tagged states.
  bool full_for_one_more() const {
    return static_cast<std::size_t>(size_) + 1 > states_before_growth(slots_.size()) ||
           size_ == tag_limit();
  }
  std::uint32_t add_word(std::size_t slot, StateWord word, std::uint64_t hash);
  // Tagged slots (tag_mask_ != 0): bits 24 to 30 hold the top 7 bits of the state's hash, bits 0
  // to 23 its index + 1; bit 31 stays clear.
  static constexpr std::uint32_t kTagBits = 0x7F000000U;
  std::uint32_t tag_of(std::uint64_t hash) const {
    return static_cast<std::uint32_t>(hash >> tag_shift_) & tag_mask_;
  }
  std::uint32_t index_of(std::uint32_t slot) const {
    return (slot & ~tag_mask_) - 1;
  }
  /// The value of slot `i` for the state of index `index` and hash `hash`.
  std::uint32_t slot_of(std::uint32_t index, std::uint64_t hash, std::size_t i) const {
    return quotient_ ? quotient_at(hash, i) : tag_of(hash) | (index + 1);
  }

  // The quotient form. The hash of a state of b bits is a bijection onto b bits; a table of
  // 2^k slots takes its low k bits as the home slot, so the other b - k (the remainder) and
  // the slot's distance d from home give the state back. A stored slot holds the remainder,
  // and d + 1 above it: never 0. The form is taken once the remainder and kDistanceBits fit in
  // the slot's 32 bits; a probe farther than kMaxDistance from home (never seen at the loads
  // kept) leaves it for the indexed form, for good.
  static constexpr std::uint32_t kDistanceBits = 8;
  static constexpr std::uint32_t kMaxDistance = (1U << kDistanceBits) - 2;
  static constexpr std::size_t kNoRoom = ~std::size_t{0};
  /// The value slot `i` holds for the state of hash `hash`; 0 when the state cannot lie there.
  std::uint32_t quotient_at(std::uint64_t hash, std::size_t i) const {
    const std::size_t mask = (std::size_t{1} << slot_bits_) - 1;
    const std::size_t d = (i - hash) & mask;
    if (d > kMaxDistance) return 0;
    return static_cast<std::uint32_t>(hash >> slot_bits_) | static_cast<std::uint32_t>(d + 1)
                                                                << remainder_bits_;
  }
  /// Look-ups in a table of the quotient form, its fields in registers (a loop of look-ups
  /// keeps one). The first kGroupSlots slots of a path are compared at once (SSE2): a branch
  /// per slot on where a look-up ends mispredicted, and cost a fifth of the search's time
  /// (docs/benchmarks.md).
  class QuotientProbe {
   public:
    QuotientProbe(const std::uint32_t* slots, std::size_t slot_count, std::uint32_t slot_bits,
                  std::uint32_t remainder_bits)
        : slots_(slots),
          mask_(slot_count - 1),
          slot_bits_(slot_bits),
          step_(1U << remainder_bits)
#if defined(__SSE2__)
          ,
          // What a slot holds at distances 0 to 3 from home, above what it holds at home.
          distances_(_mm_set_epi32(static_cast<int>(3 * step_), static_cast<int>(2 * step_),
                                   static_cast<int>(step_), 0))
#endif
    {
    }
    /// The home slot of the state of hash `hash`.
    std::size_t home(std::uint64_t hash) const {
      return hash & mask_;
    }
    /// The value slot `i` holds for the state of hash `hash`, on its path at most kMaxDistance
    /// from home.
    std::uint32_t value(std::uint64_t hash, std::size_t i) const {
      return at_home(hash) + static_cast<std::uint32_t>((i - hash) & mask_) * step_;
    }
    /// The slot that holds the state of hash `hash`, the empty one where it goes, or kNoRoom
    /// when neither lies within kMaxDistance of its home.
    [[gnu::always_inline]] std::size_t slot(std::uint64_t hash) const {
      const std::size_t home_slot = home(hash);
      std::uint32_t expected = at_home(hash);
      std::size_t i = home_slot;
      std::uint32_t d = 0;
#if defined(__SSE2__)
      if (home_slot + kGroupSlots <= mask_ + 1) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(slots_ + home_slot));
        const __m128i want = _mm_add_epi32(_mm_set1_epi32(static_cast<int>(expected)), distances_);
        const auto ends = static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(
            _mm_or_si128(_mm_cmpeq_epi32(v, want), _mm_cmpeq_epi32(v, _mm_setzero_si128())))));
        if (ends != 0) return home_slot + static_cast<std::size_t>(__builtin_ctz(ends));
        d = kGroupSlots;
        i = (home_slot + kGroupSlots) & mask_;
        expected += kGroupSlots * step_;
      }
#endif
      for (std::uint32_t s = slots_[i]; s != expected && s != 0; s = slots_[i]) {
        if (d == kMaxDistance) return kNoRoom;
        ++d;
        i = (i + 1) & mask_;
        expected += step_;
      }
      return i;
    }

   private:
    /// The value of the state's slot at distance 0: its remainder, and 1 above it.
    std::uint32_t at_home(std::uint64_t hash) const {
      return static_cast<std::uint32_t>(hash >> slot_bits_) | step_;
    }
    const std::uint32_t* slots_;
    std::size_t mask_;
    std::uint32_t slot_bits_;
    std::uint32_t step_;
#if defined(__SSE2__)
    __m128i distances_;
#endif
  };
  QuotientProbe quotient_probe() const {
    return {slots_.data(), slots_.size(), slot_bits_, remainder_bits_};
  }
  /// The slot that holds the state of hash `hash`, the empty one where it goes, or kNoRoom
  /// when neither lies within kMaxDistance of its home.
  [[gnu::always_inline]] std::size_t probe_quotient(std::uint64_t hash) const {
    return quotient_probe().slot(hash);
  }
  void leave_quotient_form();
  /// A bijection of the words below 2^membership_bits: xor-shifts and odd multiplications
  /// (splitmix64's), each invertible modulo 2^b.
  [[gnu::always_inline]] std::uint64_t mix_bits(StateWord word) const {
    return mix_bits(word, bits_mask_, shift_[0], shift_[1], shift_[2]);
  }
  /// mix_bits() with its parameters given: a loop keeps them in registers.
  [[gnu::always_inline]] static std::uint64_t mix_bits(StateWord word, std::uint64_t mask,
                                                       std::uint32_t shift0, std::uint32_t shift1,
                                                       std::uint32_t shift2) {
    if ((word & ~mask) != 0) throw_too_wide();
    std::uint64_t h = word;
    h ^= h >> shift0;
    h = (h * 0xbf58476d1ce4e5b9ULL) & mask;
    h ^= h >> shift1;
    h = (h * 0x94d049bb133111ebULL) & mask;
    h ^= h >> shift2;
    return h;
  }
  [[noreturn]] static void throw_too_wide();
  std::pair<std::uint32_t, bool> insert_wide(StateView state, std::uint64_t hash);
  static std::uint64_t mix(std::uint64_t h) {
    // splitmix64 finaliser: cheap and good enough for packed bit vectors.
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return h;
  }
  static std::uint64_t hash_word(StateWord word) {
    return mix(0x9e3779b97f4a7c15ULL ^ word);
  }
  void grow();
  /// The size at which tagging stops (never reached when it has stopped).
  std::uint32_t tag_limit() const {
    return tag_mask_ ? tagged_states_ : kAbsent;
  }
  void rehash(std::size_t slot_count);
  /// Stops tagging one-word slots. In place: a slot's position depends on the hash, not the tag.
  void untag();

  std::uint32_t words_;
  bool membership_;        ///< only membership is asked (membership_bits > 0)
  bool quotient_ = false;  ///< the slots hold quotients
  bool left_quotient_ = false;
  std::uint32_t state_bits_;  ///< membership_bits
  std::uint64_t bits_mask_;
  std::uint32_t shift_[3];
  std::uint32_t slot_bits_ = 10;  ///< log2 of the slot count
  std::uint32_t remainder_bits_ = 0;
  std::uint32_t tag_shift_;  ///< the hash bits a tag takes: its top 7 (the tag is bits 24-30)
  std::uint32_t tag_mask_;   ///< kTagBits while one-word states are tagged, else 0
  std::uint32_t tagged_states_;
  std::uint32_t size_ = 0;
  MappedArray<StateWord> data_;
  std::vector<std::uint32_t> slots_;   ///< state index + 1; 0 = empty
  MappedArray<std::uint32_t> hashes_;  ///< high bits of each state's hash, to skip most compares
                                       ///< (not kept for one-word states: compared directly)
};

}  // namespace sfcv::engine

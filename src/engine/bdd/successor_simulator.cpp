#include "engine/bdd/successor_simulator.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;
using Bdd = bdd::Bdd;

SuccessorSimulator::SuccessorSimulator(const semantics::TransitionCircuit& circuit,
                                       std::vector<std::uint32_t> position)
    : position_(std::move(position)),
      circuit_(circuit),
      aig_(circuit.aig),
      valuations_(std::size_t{1} << aig_.inputs().size()),
      words_((valuations_ + 63) / 64),
      latch_words_((aig_.latches().size() + 63) / 64),
      used_(valuations_ >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << valuations_) - 1),
      value_(aig_.nodes().size() * words_, 0),
      latch_nodes_(aig_.latches().size()),
      keys_(valuations_ * latch_words_),
      ok_(words_),
      order_(valuations_) {
  for (std::size_t n = 0; n < aig_.nodes().size(); ++n) {
    const auto& node = aig_.nodes()[n];
    if (node.kind == Aig::NodeKind::And)
      gates_.push_back({static_cast<std::uint32_t>(n), Aig::node_of(node.left),
                        Aig::node_of(node.right), Aig::is_negated(node.left) ? ~0ULL : 0,
                        Aig::is_negated(node.right) ? ~0ULL : 0});
    if (node.kind == Aig::NodeKind::Latch) latch_nodes_[node.index] = static_cast<std::uint32_t>(n);
    if (node.kind != Aig::NodeKind::Input) continue;
    static constexpr std::uint64_t kPattern[6] = {0xAAAAAAAAAAAAAAAAULL, 0xCCCCCCCCCCCCCCCCULL,
                                                  0xF0F0F0F0F0F0F0F0ULL, 0xFF00FF00FF00FF00ULL,
                                                  0xFFFF0000FFFF0000ULL, 0xFFFFFFFF00000000ULL};
    for (std::size_t w = 0; w < words_; ++w)
      value_[n * words_ + w] = node.index < 6                        ? kPattern[node.index]
                               : ((w >> (node.index - 6)) & 1U) != 0 ? ~std::uint64_t{0}
                                                                     : 0;
  }
}

std::size_t SuccessorSimulator::simulate(const std::vector<bool>& x) {
  const std::size_t latches = aig_.latches().size();
  for (std::size_t l = 0; l < latches; ++l)
    std::fill_n(value_.begin() + static_cast<std::ptrdiff_t>(latch_nodes_[l] * words_), words_,
                x[l] ? ~std::uint64_t{0} : 0);
  std::uint64_t* value = value_.data();
  if (words_ == 1) {
    for (const auto& g : gates_)
      value[g.out] = (value[g.left] ^ g.left_flip) & (value[g.right] ^ g.right_flip);
  } else {
    for (const auto& g : gates_)
      for (std::size_t w = 0; w < words_; ++w)
        value[g.out * words_ + w] = (value[g.left * words_ + w] ^ g.left_flip) &
                                    (value[g.right * words_ + w] ^ g.right_flip);
  }
  for (std::size_t w = 0; w < words_; ++w)
    ok_[w] = lit(circuit_.allowed, w) & ~lit(circuit_.range_error, w) & used_;
  std::fill(keys_.begin(), keys_.end(), 0);
  for (std::size_t l = 0; l < latches; ++l) {
    const AigLit next = aig_.latches()[l].next;
    for (std::size_t w = 0; w < words_; ++w) {
      const std::uint64_t bits = lit(next, w) & ok_[w];
      for (std::uint64_t b = bits; b != 0; b &= b - 1) {
        const std::size_t v = w * 64 + static_cast<std::size_t>(std::countr_zero(b));
        set_key_bit(keys_.data() + v * latch_words_, position_[l]);
      }
    }
  }
  std::size_t count = 0;
  for (std::size_t w = 0; w < words_; ++w)
    for (std::uint64_t b = ok_[w]; b != 0; b &= b - 1)
      order_[count++] = static_cast<std::uint32_t>(w * 64 + std::countr_zero(b));
  auto key_less = [&](std::uint32_t a, std::uint32_t b) {
    return std::lexicographical_compare(
        keys_.begin() + a * latch_words_, keys_.begin() + (a + 1) * latch_words_,
        keys_.begin() + b * latch_words_, keys_.begin() + (b + 1) * latch_words_);
  };
  std::sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(count), key_less);
  std::size_t distinct = 0;
  for (std::size_t j = 0; j < count; ++j)
    if (j == 0 || key_less(order_[distinct - 1], order_[j])) order_[distinct++] = order_[j];
  return distinct;
}

std::vector<std::uint32_t> latch_ranks(const std::vector<int>& current_var) {
  const std::size_t latches = current_var.size();
  std::vector<std::uint32_t> by_level(latches), rank_of(latches);
  std::iota(by_level.begin(), by_level.end(), 0U);
  std::sort(by_level.begin(), by_level.end(), [&](std::uint32_t a, std::uint32_t b) {
    return bdd::level_of(current_var[a]) < bdd::level_of(current_var[b]);
  });
  for (std::uint32_t r = 0; r < latches; ++r) rank_of[by_level[r]] = r;
  return rank_of;
}

std::vector<int> var_at_rank(const std::vector<std::uint32_t>& rank_of,
                             const std::vector<int>& current_var) {
  std::vector<int> var(rank_of.size());
  for (std::size_t l = 0; l < rank_of.size(); ++l) var[rank_of[l]] = current_var[l];
  return var;
}

namespace {

/// Sorts `keys` (records of `width` words, compared word by word) and keeps one of each;
/// returns how many are left. Records of up to 4 words are sorted as values: comparing through
/// indices cost twice as much.
template <std::size_t Width>
std::size_t sort_distinct_records(std::vector<std::uint64_t>& keys) {
  using Record = std::array<std::uint64_t, Width>;
  std::vector<Record> records(keys.size() / Width);
  for (std::size_t k = 0; k < records.size(); ++k)
    std::copy_n(keys.begin() + static_cast<std::ptrdiff_t>(k * Width), Width, records[k].begin());
  std::sort(records.begin(), records.end());
  records.erase(std::unique(records.begin(), records.end()), records.end());
  keys.resize(records.size() * Width);
  for (std::size_t k = 0; k < records.size(); ++k)
    std::copy_n(records[k].begin(), Width, keys.begin() + static_cast<std::ptrdiff_t>(k * Width));
  return records.size();
}

}  // namespace

std::size_t sort_distinct_keys(std::vector<std::uint64_t>& keys, std::size_t width) {
  switch (width) {
    case 0:
      return keys.empty() ? 0 : 1;
    case 1:
      return sort_distinct_records<1>(keys);
    case 2:
      return sort_distinct_records<2>(keys);
    case 3:
      return sort_distinct_records<3>(keys);
    case 4:
      return sort_distinct_records<4>(keys);
    default:
      break;
  }
  const std::size_t count = keys.size() / width;
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0U);
  auto key_at = [&](std::uint32_t k) { return keys.begin() + k * width; };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::lexicographical_compare(key_at(a), key_at(a) + width, key_at(b), key_at(b) + width);
  });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](std::uint32_t a, std::uint32_t b) {
                            return std::equal(key_at(a), key_at(a) + width, key_at(b));
                          }),
              order.end());
  std::vector<std::uint64_t> sorted;
  sorted.reserve(order.size() * width);
  for (auto k : order) sorted.insert(sorted.end(), key_at(k), key_at(k) + width);
  keys.swap(sorted);
  return order.size();
}

Bdd bdd_of_sorted_keys(const std::vector<std::uint64_t>& keys, std::size_t count, std::size_t width,
                       const std::vector<int>& var_at_rank) {
  const std::size_t ranks = var_at_rank.size();
  auto bit = [&](std::size_t k, std::size_t r) {
    return ((keys[k * width + r / 64] >> (63 - r % 64)) & 1U) != 0;
  };
  // From the bottom: a node per distinct (rank, low, high), found in a local table first, so
  // BuDDy makes each node of the result once however many states share it (a trie of the
  // states would make a node per state and bit).
  std::vector<Bdd> nodes{Bdd::constant(false), Bdd::constant(true)};
  // The local table: open addressing over (rank, low, high), at most half full.
  struct Entry {
    std::uint32_t rank, low, high, id;  // id 0: empty (the constants are never entered)
  };
  std::vector<Entry> table(1024, Entry{0, 0, 0, 0});
  auto slot_of = [&](std::uint32_t rank, std::uint32_t low, std::uint32_t high) {
    std::uint64_t h = (std::uint64_t{rank} << 42) ^ (std::uint64_t{low} << 21) ^ high;
    h *= 0x9e3779b97f4a7c15ULL;
    const std::size_t mask = table.size() - 1;
    for (std::size_t i = (h >> 20) & mask;; i = (i + 1) & mask) {
      const Entry& e = table[i];
      if (e.id == 0 || (e.rank == rank && e.low == low && e.high == high)) return i;
    }
  };
  // The set of the sorted keys [first, last), which agree on every rank above `rank`.
  auto build = [&](auto& self, std::size_t first, std::size_t last,
                   std::uint32_t rank) -> std::uint32_t {
    if (first == last) return 0;
    if (rank == ranks) return 1;
    std::size_t split = first, above = last;  // the first key of [first, last) with the bit
    while (split < above) {
      const std::size_t mid = split + (above - split) / 2;
      if (bit(mid, rank))
        above = mid;
      else
        split = mid + 1;
    }
    const std::uint32_t low = self(self, first, split, rank + 1);
    const std::uint32_t high = self(self, split, last, rank + 1);
    if (low == high) return low;
    if (const Entry& e = table[slot_of(rank, low, high)]; e.id != 0) return e.id;
    nodes.push_back(Bdd::variable(var_at_rank[rank]).ite(nodes[high], nodes[low]));
    const auto id = static_cast<std::uint32_t>(nodes.size() - 1);
    if (2 * nodes.size() > table.size()) {
      std::vector<Entry> old(table.size() * 2, Entry{0, 0, 0, 0});
      old.swap(table);
      for (const Entry& e : old)
        if (e.id != 0) table[slot_of(e.rank, e.low, e.high)] = e;
    }
    table[slot_of(rank, low, high)] = Entry{rank, low, high, id};
    return id;
  };
  return nodes[build(build, 0, count, 0U)];
}

}  // namespace sfcv::engine

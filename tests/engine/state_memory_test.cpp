// The explicit search's per-state memory: the remapped arrays and the state table's load.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "engine/explicit/mapped_array.hpp"
#include "engine/explicit/state_store.hpp"

namespace sfcv::engine {
namespace {

TEST(MappedArray, KeepsItsValuesAcrossGrowthAppendAndMove) {
  MappedArray<std::uint64_t> a;
  EXPECT_TRUE(a.empty());
  EXPECT_EQ(a.resident_bytes(), 0u);
  // Past several remappings (the first mapping holds 512 values).
  for (std::uint64_t i = 0; i < 300000; ++i) a.push_back(i * 3);
  const std::vector<std::uint64_t> tail{7, 8, 9};
  a.append(tail.data(), tail.size());
  ASSERT_EQ(a.size(), 300003u);
  for (std::uint64_t i = 0; i < 300000; ++i) ASSERT_EQ(a[i], i * 3);
  EXPECT_EQ(a[300002], 9u);
  // Whole pages of what was written, not of the capacity.
  EXPECT_EQ(a.resident_bytes(), (300003 * 8 + 4095) / 4096 * 4096);

  MappedArray<std::uint64_t> b(std::move(a));
  EXPECT_EQ(b.size(), 300003u);
  EXPECT_EQ(b[299999], 299999u * 3);
  a = std::move(b);
  EXPECT_EQ(a.size(), 300003u);
  a.assign(5, 42);
  ASSERT_EQ(a.size(), 5u);
  for (auto v : a) EXPECT_EQ(v, 42u);

  MappedArray<std::uint32_t> small;
  small.assign(3, ~0U);
  small.push_back(1);
  EXPECT_EQ(small.size(), 4u);
  EXPECT_EQ(small[2], ~0U);
  EXPECT_EQ(small[3], 1u);
}

TEST(StateStore, FillsALargeTableToThreeQuarters) {
  // 3,000,000 one-word states: at half load they would need 2^23 slots (32 MB), at three
  // quarters 2^22 (16 MB). Every state must keep its index, through the grouped probe.
  constexpr std::uint64_t kStates = 3000000;
  StateStore store(1);
  auto word = [](std::uint64_t i) { return (i * 0x9e3779b97f4a7c15ULL) >> 3; };
  for (std::uint64_t i = 0; i < kStates; ++i) {
    const StateWord w[1] = {word(i)};
    ASSERT_EQ(store.insert(w), std::make_pair(static_cast<std::uint32_t>(i), true));
  }
  for (std::uint64_t i = 0; i < kStates; i += 7) {
    const StateWord w[1] = {word(i)};
    ASSERT_EQ(store.find(w), static_cast<std::uint32_t>(i));
  }
  const StateWord absent[1] = {word(kStates)};
  EXPECT_EQ(store.find(absent), StateStore::kAbsent);
  // 8 bytes of state and about 5.6 of table per state; at half load it would be 19.2.
  EXPECT_LE(store.memory_bytes(), kStates * 14);
}

}  // namespace
}  // namespace sfcv::engine

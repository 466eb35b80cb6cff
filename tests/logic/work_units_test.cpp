// The split of a check into shards (logic/work_units.hpp, docs/distributed.md): "I/N" is
// 1-based and checked; every unit goes to exactly one shard; the same units give the same
// split (N processes on N machines must agree without talking); the split balances the cost
// (longest processing time first).

#include "logic/work_units.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <set>

namespace {

using sfcv::logic::assign_shards;
using sfcv::logic::parse_shard;
using sfcv::logic::shard_units;
using sfcv::logic::ShardSpec;
using sfcv::logic::WorkUnit;

std::vector<WorkUnit> units_of_costs(const std::vector<std::uint64_t>& costs) {
  std::vector<WorkUnit> units;
  for (std::size_t i = 0; i < costs.size(); ++i)
    units.push_back({"property/" + std::to_string(i), "property", "p", i, costs[i]});
  return units;
}

TEST(WorkUnits, ParseShardIsOneBasedAndChecked) {
  std::string why;
  const auto s = parse_shard("2/4", &why);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->index, 2u);
  EXPECT_EQ(s->count, 4u);
  EXPECT_TRUE(parse_shard("1/1", &why));
  EXPECT_TRUE(parse_shard("4/4", &why));
  for (const char* bad :
       {"0/4", "5/4", "1/0", "x", "2", "/4", "2/", "2/4/1", "-1/4", "1.5/4", " 1/4"}) {
    EXPECT_FALSE(parse_shard(bad, &why)) << bad;
    EXPECT_NE(why.find(std::string("bad --shard '") + bad + "'"), std::string::npos) << why;
  }
  parse_shard("0/4", &why);
  EXPECT_NE(why.find("numbered from 1"), std::string::npos) << why;
  parse_shard("5/4", &why);
  EXPECT_NE(why.find("1/4 to 4/4"), std::string::npos) << why;
}

TEST(WorkUnits, EveryUnitInExactlyOneShard) {
  const auto units = units_of_costs({5, 3, 8, 1, 1, 2, 9, 4, 4, 7, 6});
  for (const std::uint32_t n : {1u, 2u, 4u, 7u, 20u}) {
    std::multiset<std::string> seen;
    for (std::uint32_t i = 1; i <= n; ++i)
      for (const auto& u : shard_units(units, ShardSpec{i, n})) seen.insert(u.id);
    EXPECT_EQ(seen.size(), units.size()) << n;
    for (const auto& u : units) EXPECT_EQ(seen.count(u.id), 1u) << u.id << " of " << n;
  }
}

TEST(WorkUnits, LongestFirstToTheLeastLoaded) {
  // Costs 9 8 7 6 5 4 3 over 3 shards: 9->A, 8->B, 7->C, 6->C (13), 5->B (13), 4->A (13),
  // 3->A (16, the first of the least loaded at 13): loads 16, 13, 13.
  const auto units = units_of_costs({3, 4, 5, 6, 7, 8, 9});
  const auto shard = assign_shards(units, 3);
  const std::vector<std::uint32_t> expected = {0, 0, 1, 2, 2, 1, 0};
  EXPECT_EQ(shard, expected);
  EXPECT_EQ(assign_shards(units, 3), shard);  // deterministic
  // Ties keep the units' order: equal costs go round the shards in order.
  EXPECT_EQ(assign_shards(units_of_costs({1, 1, 1, 1}), 2),
            (std::vector<std::uint32_t>{0, 1, 0, 1}));
}

TEST(WorkUnits, MoreShardsThanUnitsLeavesSomeEmpty) {
  const auto units = units_of_costs({2, 2});
  EXPECT_EQ(shard_units(units, ShardSpec{1, 7}).size(), 1u);
  EXPECT_EQ(shard_units(units, ShardSpec{2, 7}).size(), 1u);
  EXPECT_TRUE(shard_units(units, ShardSpec{7, 7}).empty());
}

}  // namespace

// The BDD facade's negation and if-then-else (engine/bdd/bdd_manager.cpp) against truth
// tables. Both avoid BuDDy's not_rec, whose apply-cache entries leave a field unwritten that
// apply_rec then reads (issue 53 item 10, docs/engines.md); the ctest valgrind_grafcet_bdd runs
// this test under valgrind too, beside `sfcv check --engine bdd` on pistons.g7, where the read
// showed (whether a given run meets it depends on cache collisions: this test alone did not).

#include "engine/bdd/bdd_manager.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace sfcv::engine::bdd {
namespace {

constexpr int kVars = 10;
using Table = std::vector<bool>;  // value per assignment, bit v of the index = variable v

Table table_of(const Bdd& f) {
  std::vector<int> vars;
  for (int v = 0; v < kVars; ++v) vars.push_back(v);
  Table t(std::size_t{1} << kVars, false);
  const bool ok = f.for_each_assignment(vars, [&](const std::vector<bool>& values) {
    std::size_t index = 0;
    for (int v = 0; v < kVars; ++v)
      if (values[static_cast<std::size_t>(v)]) index |= std::size_t{1} << v;
    t[index] = true;
    return true;
  });
  EXPECT_TRUE(ok);
  return t;
}

TEST(BddManager, NegationAndIteFollowTheirTruthTables) {
  std::mt19937_64 rng(53);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  ensure_variables(kVars);
  std::vector<Bdd> pool;
  std::vector<Table> tables;
  for (int k = 0; k < 48; ++k) {
    pool.push_back(Bdd::variable(k % kVars));
    tables.push_back(table_of(pool.back()));
  }
  const std::size_t size = std::size_t{1} << kVars;
  for (int it = 0; it < 3000; ++it) {
    const auto i = pick(pool.size()), j = pick(pool.size()), k = pick(pool.size());
    Bdd result;
    Table expected(size);
    const Bdd negated = !pool[i];
    switch (pick(5)) {
      case 0: {  // a negation, then a conjunction with the node or its negation
        const bool use_negation = pick(2) == 1;
        result = (use_negation ? negated : pool[i]) & pool[j];
        for (std::size_t x = 0; x < size; ++x)
          expected[x] = (use_negation ? !tables[i][x] : tables[i][x]) && tables[j][x];
        break;
      }
      case 1:
        result = negated | pool[j];
        for (std::size_t x = 0; x < size; ++x) expected[x] = !tables[i][x] || tables[j][x];
        break;
      case 2:
        result = pool[i].ite(pool[j], pool[k]);
        for (std::size_t x = 0; x < size; ++x)
          expected[x] = tables[i][x] ? tables[j][x] : tables[k][x];
        break;
      case 3:  // else = true, then = false: a negation
        result = pool[i].ite(Bdd::constant(false), Bdd::constant(true));
        for (std::size_t x = 0; x < size; ++x) expected[x] = !tables[i][x];
        break;
      default: {  // a variable above both branches, as successor_simulator builds nodes
        const int v = static_cast<int>(pick(kVars));
        const Bdd hi = pool[j].exist(Bdd::cube({v})), lo = pool[k].exist(Bdd::cube({v}));
        result = Bdd::variable(v).ite(hi, lo);
        const std::size_t bit = std::size_t{1} << v;
        for (std::size_t x = 0; x < size; ++x) {
          const auto& from = x & bit ? tables[j] : tables[k];  // exists v: either value of v
          expected[x] = from[x & ~bit] || from[x | bit];
        }
      }
    }
    // Reading a table back walks the BDD: every 16th result, and all of them at the end.
    if (it % 16 == 0) {
      ASSERT_EQ(table_of(result), expected) << "iteration " << it;
    }
    pool[i] = result;
    tables[i] = std::move(expected);
  }
  for (std::size_t i = 0; i < pool.size(); ++i) EXPECT_EQ(table_of(pool[i]), tables[i]) << i;
}

}  // namespace
}  // namespace sfcv::engine::bdd

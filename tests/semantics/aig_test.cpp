#include "semantics/aig.hpp"

#include <gtest/gtest.h>

#include <string>

#include "model/errors.hpp"

namespace sfcv::semantics {
namespace {

std::int64_t value(const Aig& aig, const std::vector<bool>& nodes, const BitVector& bv,
                   bool is_signed) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < bv.size(); ++i)
    if (Aig::value_of(nodes, bv[i])) v |= 1ULL << i;
  if (is_signed && !bv.empty() && (v >> (bv.size() - 1)) & 1U) v |= ~0ULL << bv.size();
  (void)aig;
  return static_cast<std::int64_t>(v);
}

// --memory while a circuit is built: the graph counts its bytes and stops past the limit.
TEST(Aig, MemoryLimitEndsTheBuildWithLimitReached) {
  Aig aig;
  std::vector<AigLit> in;
  for (int i = 0; i < 64; ++i) in.push_back(aig.add_input("i" + std::to_string(i)));
  aig.set_memory_limit(256 * 1024);
  bool stopped = false;
  try {
    AigLit acc = Aig::kTrue;
    for (std::uint32_t k = 0; k < 1'000'000; ++k)
      acc = aig.make_and(aig.make_xor(acc, in[k % 64]), in[(k * 7 + 3) % 64]);
  } catch (const LimitReached& e) {
    stopped = true;
    EXPECT_EQ(e.which(), Limit::Memory);
    EXPECT_NE(std::string(e.what()).find("memory limit reached while building the circuit"),
              std::string::npos);
  }
  EXPECT_TRUE(stopped);
  EXPECT_LT(aig.memory_bytes(), 4 * 256 * 1024);
  EXPECT_GT(aig.memory_bytes(), 256 * 1024);
  // Without a limit the same graph grows on.
  Aig unlimited;
  AigLit acc = Aig::kTrue;
  const auto a = unlimited.add_input("a"), b = unlimited.add_input("b");
  for (std::uint32_t k = 0; k < 10'000; ++k)
    acc = unlimited.make_and(unlimited.make_xor(acc, a), b);
  EXPECT_GT(unlimited.num_ands(), 20000U);
}

TEST(Aig, FoldsConstantsAndHashesStructure) {
  Aig aig;
  const auto a = aig.add_input("a"), b = aig.add_input("b");
  EXPECT_EQ(aig.make_and(a, Aig::kFalse), Aig::kFalse);
  EXPECT_EQ(aig.make_and(a, Aig::kTrue), a);
  EXPECT_EQ(aig.make_and(a, Aig::make_not(a)), Aig::kFalse);
  const auto ab = aig.make_and(a, b);
  EXPECT_EQ(aig.make_and(b, a), ab);
  EXPECT_EQ(aig.num_ands(), 1u);
}

TEST(Aig, EvaluatesLatchesAndGates) {
  Aig aig;
  const auto in = aig.add_input("in");
  const auto l = aig.add_latch("l", true);
  const auto x = aig.make_xor(in, l);
  for (bool vi : {false, true})
    for (bool vl : {false, true}) {
      const auto nodes = aig.evaluate({vi}, {vl});
      EXPECT_EQ(Aig::value_of(nodes, x), vi != vl);
      EXPECT_EQ(Aig::value_of(nodes, aig.make_ite(in, l, Aig::kTrue)), vi ? vl : true);
    }
}

// Exhaustive check of the 4-bit arithmetic against int arithmetic.
TEST(Aig, BitVectorArithmeticMatchesIntegers) {
  Aig aig;
  BitVector a, b;
  for (int i = 0; i < 4; ++i) a.push_back(aig.add_input("a" + std::to_string(i)));
  for (int i = 0; i < 4; ++i) b.push_back(aig.add_input("b" + std::to_string(i)));
  const auto sum = bv_add(aig, a, b), diff = bv_sub(aig, a, b);
  const auto eq = bv_equal(aig, a, b), lts = bv_less_signed(aig, a, b),
             ltu = bv_less_unsigned(aig, a, b);
  for (int x = 0; x < 16; ++x)
    for (int y = 0; y < 16; ++y) {
      std::vector<bool> in;
      for (int i = 0; i < 4; ++i) in.push_back((x >> i) & 1);
      for (int i = 0; i < 4; ++i) in.push_back((y >> i) & 1);
      const auto nodes = aig.evaluate(in, {});
      const int sx = x >= 8 ? x - 16 : x, sy = y >= 8 ? y - 16 : y;
      EXPECT_EQ(value(aig, nodes, sum, false), (x + y) & 15);
      EXPECT_EQ(value(aig, nodes, diff, false), (x - y) & 15);
      EXPECT_EQ(Aig::value_of(nodes, eq), x == y);
      EXPECT_EQ(Aig::value_of(nodes, ltu), x < y) << x << " " << y;
      EXPECT_EQ(Aig::value_of(nodes, lts), sx < sy) << sx << " " << sy;
    }
}

}  // namespace
}  // namespace sfcv::semantics

namespace sfcv::semantics {
namespace {

TEST(Aig, CofactorSubstitutesAConstant) {
  Aig aig;
  const auto a = aig.add_input("a"), b = aig.add_input("b");
  const auto q = aig.add_latch("q");
  const auto f = aig.make_or(aig.make_and(q, a), aig.make_and(Aig::make_not(q), b));
  EXPECT_EQ(aig.cofactor(f, q, true), a);
  EXPECT_EQ(aig.cofactor(f, q, false), b);
  EXPECT_EQ(aig.cofactor(Aig::make_not(f), q, true), Aig::make_not(a));
  EXPECT_EQ(aig.cofactor(f, a, true), aig.make_or(q, aig.make_and(Aig::make_not(q), b)));
}

}  // namespace
}  // namespace sfcv::semantics

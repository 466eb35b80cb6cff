// The benchmark families (bench/gen, the sfcv-gen binary) at small sizes: every generated file
// loads, has the structure we count by hand, and the engines find the state counts we count by
// hand (or, where a hand count is out of reach, the explicit and BDD engines agree).

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "support/generate.hpp"
#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::generate;
using sfcv::test::run_sfcv;

/// Whether this build's sfcv has the info command (it lands with the validate-info branch).
bool info_is_built() {
  const auto r = run_sfcv("info '" + generate("parallel 1", ".st") + "'");
  return r.err.find("not built yet") == std::string::npos;
}

/// `sfcv info --json`: total steps and transitions.
void expect_info(const std::string& file, std::size_t steps, std::size_t transitions) {
  const auto r = run_sfcv("info --json '" + file + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("steps").get<std::size_t>(), steps) << file;
  EXPECT_EQ(j.at("transitions").get<std::size_t>(), transitions) << file;
}

struct Graph {
  int exit_code = -1;
  std::string verdict;
  std::uint64_t states = 0, edges = 0;
};

Graph check(const std::string& file, const std::string& engine, const std::string& ctl) {
  const auto r = run_sfcv("check '" + file + "' --engine " + engine + " --checks none --ctl '" +
                          ctl + "' --json --quiet");
  Graph g;
  g.exit_code = r.exit_code;
  if (r.exit_code != 0 && r.exit_code != 1) {
    ADD_FAILURE() << "sfcv check " << file << " --engine " << engine << ": " << r.err;
    return g;
  }
  const auto j = nlohmann::json::parse(r.out);
  g.states = j.at("states").get<std::uint64_t>();
  if (j.contains("edges") && j["edges"].is_number()) g.edges = j["edges"].get<std::uint64_t>();
  g.verdict = j.at("properties").at(0).at("verdict").get<std::string>();
  return g;
}

/// `sfcv rsg` summary: (situations, distinct step situations, evolutions).
std::tuple<std::uint64_t, std::uint64_t, std::uint64_t> rsg(const std::string& file) {
  const auto r = run_sfcv("rsg '" + file + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  const std::regex sit(R"(situations: (\d+) \(distinct step situations: (\d+)\))");
  const std::regex evo(R"(evolutions: (\d+))");
  if (!std::regex_search(r.out, m, sit)) {
    ADD_FAILURE() << "no situation count in: " << r.out;
    return {};
  }
  const auto situations = std::stoull(m[1]), distinct = std::stoull(m[2]);
  if (!std::regex_search(r.out, m, evo)) {
    ADD_FAILURE() << "no evolution count in: " << r.out;
    return {};
  }
  return {situations, distinct, std::stoull(m[1])};
}

TEST(Families, ParallelSelectorHas2PowNPlus1States) {
  // Init, then the 2^3 combinations of A_i/B_i; sel picks the one branch that toggles.
  const auto f = generate("parallel 3 --selector", ".st");
  const auto ex = check(f, "explicit", "AG !(A0 & B0)");
  EXPECT_EQ(ex.states, 9u);
  EXPECT_EQ(ex.edges, 25u);  // Init -> all A; then sel in 0..2 toggles one of 3 branches
  EXPECT_EQ(ex.verdict, "holds");
  const auto bdd = check(f, "bdd", "AG !(A0 & B0)");
  EXPECT_EQ(bdd.states, 9u);
  EXPECT_EQ(bdd.verdict, "holds");
  // B0 & B1 & B2 is reachable: three toggles.
  EXPECT_EQ(check(f, "explicit", "AG !(B0 & B1 & B2)").verdict, "violated");
}

TEST(Families, ParallelFreeInputsHas2PowNPlus1States) {
  const auto f = generate("parallel 4", ".st");
  EXPECT_EQ(check(f, "explicit", "AG !(A0 & B0)").states, 17u);
  EXPECT_EQ(check(f, "bdd", "AG !(A0 & B0)").states, 17u);
}

TEST(Families, TanksFixedHoldsFlawedViolated) {
  for (const std::uint32_t n : {1u, 2u}) {
    const auto fixed = generate("tanks " + std::to_string(n), ".st");
    const auto flawed = generate("tanks " + std::to_string(n) + " --flawed", ".st");
    const std::string last = std::to_string(n - 1);
    const std::string prop = "AG !(V2_" + last + " & V4_" + last + ")";
    const auto ex = check(fixed, "explicit", prop);
    EXPECT_EQ(ex.verdict, "holds") << n;
    EXPECT_EQ(check(fixed, "bdd", prop).states, ex.states) << n;
    EXPECT_EQ(check(flawed, "explicit", prop).verdict, "violated") << n;
    EXPECT_EQ(check(flawed, "bdd", prop).verdict, "violated") << n;
  }
  // The reactors are independent: the state count of two is the product of one's, with the
  // shared Start state counted once.
  const auto one = check(generate("tanks 1", ".st"), "explicit", "AG !(V2_0 & V4_0)").states;
  const auto two = check(generate("tanks 2", ".st"), "explicit", "AG !(V2_0 & V4_0)").states;
  EXPECT_EQ(two, (one - 1) * (one - 1) + 1);
}

// Decimal digits of a * b (a test-side multiplication, independent of logic::BigCount).
std::string times(const std::string& a, std::uint64_t b) {
  std::string r;
  std::uint64_t carry = 0;  // b is small (a state count of one tank)
  for (std::size_t i = a.size(); i-- > 0;) {
    const std::uint64_t v = static_cast<std::uint64_t>(a[i] - '0') * b + carry;
    r.insert(r.begin(), static_cast<char>('0' + static_cast<int>(v % 10)));
    carry = v / 10;
  }
  for (; carry; carry /= 10)
    r.insert(r.begin(), static_cast<char>('0' + static_cast<int>(carry % 10)));
  const auto nz = r.find_first_not_of('0');
  return nz == std::string::npos ? "0" : r.substr(nz);
}

std::string plus_one(std::string a) {
  std::size_t i = a.size();
  while (i-- > 0 && a[i] == '9') a[i] = '0';
  if (i == std::string::npos) return "1" + a;
  ++a[i];
  return a;
}

// Past 2^64 the count is exact, in the text report and as a decimal string in JSON (it was 0).
TEST(Families, TanksCountsPastSixtyFourBitsAreExact) {
  const auto one = check(generate("tanks 1", ".st"), "explicit", "AG !(V2_0 & V4_0)").states;
  std::string expected = "1";
  for (int k = 0; k < 24; ++k) expected = times(expected, one - 1);
  ASSERT_GT(expected.size(), 20u);  // beyond 2^64 = 18446744073709551616
  expected = plus_one(expected);    // the shared Start state
  const auto file = generate("tanks 24", ".st");
  const auto r = run_sfcv("check '" + file +
                          "' --engine bdd --checks none --ctl 'AG !(V2_0 & V4_0)' --json --quiet");
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.at("states").is_string()) << j.at("states");
  EXPECT_EQ(j.at("states").get<std::string>(), expected);
  const auto text =
      run_sfcv("check '" + file + "' --engine bdd --checks none --ctl 'AG !(V2_0 & V4_0)' --quiet");
  // The text is for people: the exact count (in the JSON above) as two digits and a power of
  // ten (issue 48); the power of ten is the exact count's.
  EXPECT_NE(text.out.find("\u00b710^" + std::to_string(expected.size() - 1) + " states, "),
            std::string::npos)
      << text.out;
}

TEST(Families, NestedEnginesAgree) {
  for (const std::uint32_t n : {1u, 3u}) {
    const auto f = generate("nested " + std::to_string(n), ".st");
    const auto ex = check(f, "explicit", "AG !(L0_A & L0_B)");
    EXPECT_EQ(ex.verdict, "holds");
    EXPECT_EQ(check(f, "bdd", "AG !(L0_A & L0_B)").states, ex.states) << n;
  }
}

TEST(Families, RandomChartsLoadAndEnginesAgree) {
  for (const int seed : {1, 2, 3}) {
    const auto f = generate("random 20 --inputs 3 --seed " + std::to_string(seed), ".st");
    const auto ex = check(f, "explicit", "AG !(S1 & S2)");
    const auto bdd = check(f, "bdd", "AG !(S1 & S2)");
    EXPECT_EQ(bdd.verdict, ex.verdict) << seed;
    // A violated invariant stops both searches at the violation (explicit: the first violating
    // state; bdd: the first ring that meets one): the whole space is counted under a property
    // that is not an invariant.
    const auto ex_all = check(f, "explicit", "TRUE");
    const auto bdd_all = check(f, "bdd", "TRUE");
    EXPECT_GT(ex_all.states, 1u) << seed;
    EXPECT_EQ(bdd_all.states, ex_all.states) << seed;
  }
}

TEST(Families, TransferLineStepSituations) {
  // Station 1 alone: 10 (empty), 11 (machining), 13 (releasing); 12 is transient since the
  // last station releases at once (receptivity 1).
  const auto one = generate("transfer 1", ".g7");
  EXPECT_EQ(std::get<1>(rsg(one)), 3u);
  // Two stations: {10,11,12,13} x {20,21,23}, less {12,20} (c1, X20, fires at once).
  const auto two = generate("transfer 2", ".g7");
  EXPECT_EQ(std::get<1>(rsg(two)), 11u);
}

TEST(Families, TransferLineUnusedInputsDoNotChangeTheRsg) {
  const auto plain = rsg(generate("transfer 2", ".g7"));
  const auto spare = rsg(generate("transfer 2 --unused 8", ".g7"));
  EXPECT_EQ(std::get<0>(spare), std::get<0>(plain));
  EXPECT_EQ(std::get<1>(spare), std::get<1>(plain));
  EXPECT_EQ(std::get<2>(spare), std::get<2>(plain));
}

TEST(Families, EveryFamilyLoadsWithTheHandCountedStructure) {
  struct Case {
    std::string args, ext;
    std::size_t steps, transitions;
  };
  const std::vector<Case> cases = {
      {"parallel 3 --selector", ".st", 7, 7},  // Init + A_i, B_i; Init's divergence + 2 each
      {"parallel 4", ".st", 9, 9},
      {"tanks 1", ".st", 8, 8},  // Start + 7 steps, divergence + 7 transitions per reactor
      {"tanks 2 --flawed", ".st", 15, 15},
      {"nested 3", ".st", 8, 8},               // two steps and two transitions per level
      {"transfer 2 --unused 3", ".g7", 8, 8},  // four of each per station
  };
  const bool info = info_is_built();
  for (const auto& c : cases) {
    const auto f = generate(c.args, c.ext);
    const auto loaded = sfcv::io::load_file(f);
    ASSERT_TRUE(loaded.project) << c.args;
    std::size_t steps = 0, transitions = 0;
    for (const auto& pou : loaded.project->pous)
      for (const auto& chart : pou.charts) {
        steps += chart.steps.size();
        transitions += chart.transitions.size();
      }
    EXPECT_EQ(steps, c.steps) << c.args;
    EXPECT_EQ(transitions, c.transitions) << c.args;
    if (info) expect_info(f, c.steps, c.transitions);
  }
  const auto random = generate("random 20 --inputs 3 --seed 1", ".st");
  EXPECT_TRUE(sfcv::io::load_file(random).project);
  if (info) {
    EXPECT_EQ(run_sfcv("info --json '" + random + "'").exit_code, 0);
  }
  // sfcv info lands with the validate-info branch; until then only the library counts ran.
  if (!info) GTEST_SKIP() << "sfcv info is not built in this tree: library counts only";
}

}  // namespace

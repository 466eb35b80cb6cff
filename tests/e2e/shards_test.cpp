// sfcv check --shard I/N, sfcv plan and sfcv merge (docs/distributed.md), as separate processes
// the way a CI matrix or a Slurm array runs them: the merged report of N shards is the single
// run's, byte for byte once timings and dates are left out, for N = 1, 2, 4 and 7 (more shards
// than units leaves some empty); a missing or doubled shard, or one of another model, is exit 2;
// a swarm (--diversify, BMC depth ranges) finds a counterexample 62 cycles deep that its first
// shard alone does not reach.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "support/generate.hpp"
#include "support/sfcv_test.hpp"

namespace {

using nlohmann::json;
using sfcv::test::generate;
using sfcv::test::run_sfcv;
using sfcv::test::write_temp;

/// The JSON without what differs between two runs of the same question: timings and dates.
json without_timings(json j) {
  if (j.is_object()) {
    j.erase("seconds");
    j.erase("date");
    for (auto& [key, value] : j.items()) value = without_timings(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_timings(value);
  }
  return j;
}

/// Runs `check FILE ARGS --json --quiet --shard i/N` for each i, each in its own process;
/// returns the files of their results.
std::vector<std::string> run_shards(const std::string& check, int n,
                                    const std::string& extra = "") {
  std::vector<std::string> files;
  for (int i = 1; i <= n; ++i) {
    const auto r = run_sfcv(check + " --json --quiet --shard " + std::to_string(i) + "/" +
                            std::to_string(n) + extra);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 3) << r.err;
    files.push_back(write_temp(r.out, ".json"));
  }
  return files;
}

std::string joined(const std::vector<std::string>& files) {
  std::string out;
  for (const auto& f : files) out += " '" + f + "'";
  return out;
}

/// The single run of `check` (JSON without timings, exit code), once per command line.
const sfcv::test::RunResult& single_run(const std::string& check) {
  static std::map<std::string, sfcv::test::RunResult> runs;
  auto it = runs.find(check);
  if (it == runs.end()) {
    auto r = run_sfcv(check + " --json --quiet");
    if (r.exit_code == 0 || r.exit_code == 1) r.out = without_timings(json::parse(r.out)).dump(1);
    it = runs.emplace(check, std::move(r)).first;
  }
  return it->second;
}

/// The merge of N shards equals the single run (JSON, exit code).
void expect_merge_equals_single(const std::string& file, const std::string& args, int n) {
  const std::string check = "check '" + file + "' " + args;
  const auto& single = single_run(check);
  ASSERT_TRUE(single.exit_code == 0 || single.exit_code == 1) << single.err;
  SCOPED_TRACE(file + " " + args + ", " + std::to_string(n) + " shards");
  const auto merged = run_sfcv("merge" + joined(run_shards(check, n)) + " --json --quiet");
  EXPECT_EQ(merged.exit_code, single.exit_code) << merged.err;
  ASSERT_FALSE(merged.out.empty()) << merged.err;
  const auto got = json::parse(merged.out);
  EXPECT_FALSE(got.contains("shard"));
  EXPECT_EQ(without_timings(got).dump(1), single.out);
}

/// One input: a generated family (sfcv-gen arguments) or a corpus file, and check's arguments.
struct Input {
  const char* name;
  const char* generate;  ///< sfcv-gen arguments, or null for a corpus file
  const char* file;      ///< the generated file's suffix, or the corpus file
  const char* args;
};

const Input kInputs[] = {
    // Two violated invariants with traces, and every standard check.
    {"Tanks", "tanks 2 --flawed", ".st",
     "--ctl 'AG !(V2_0 & V4_0)' --ctl 'AG !(V1_1 & V3_1)' --checks all"},
    // Vacuity (AG (a -> f)), LTL with a lasso, a witness, the standard checks.
    {"Parallel", "parallel 3 --selector", ".st",
     "--checks all --ctl 'AG (Parallel.O0 -> EF !Parallel.O0)' --ltl 'G F Parallel.O1' --ctl "
     "'EF (Parallel.O0 & Parallel.O1 & Parallel.O2)'"},
    // Invariants alone: the explicit engine stops at the violations; the merge keeps the counts
    // of the shard that explored most, as the single run's.
    {"InvariantsOnTheFly", "tanks 2 --flawed", ".st",
     "--ctl 'AG !(V2_0 & V4_0)' --ctl 'AG !(V1_1 & V3_1)' --checks none"},
    {"Grafcet", "transfer 2", ".g7", ""},
    // One corpus file of each importer: PLCopen XML, IEC text, AGRAFE XMI (small for ASan).
    {"CorpusPlcopen", nullptr, "03_matiec_SFC_TEST_tc6v1.xml", ""},
    {"CorpusIecText", nullptr, "04_matiec_sfc_syntax.st", ""},
    {"CorpusAgrafe", nullptr, "24_agrafe_exclusive_selection.grafcet", ""},
};

class MergeAsOneRun : public ::testing::TestWithParam<std::tuple<Input, int>> {};

TEST_P(MergeAsOneRun, SameJsonAndExitCode) {
  const auto& [input, n] = GetParam();
  std::string file;
  if (input.generate) {
    static std::map<std::string, std::string> generated;  // one file per family and size
    auto& f = generated[input.generate];
    if (f.empty()) f = generate(input.generate, input.file);
    file = f;
  } else {
    SFCV_REQUIRE_CORPUS(corpus);
    file = (corpus / input.file).string();
  }
  expect_merge_equals_single(file, input.args, n);
}

INSTANTIATE_TEST_SUITE_P(Shards, MergeAsOneRun,
                         ::testing::Combine(::testing::ValuesIn(kInputs),
                                            ::testing::Values(1, 2, 4, 7)),
                         [](const ::testing::TestParamInfo<std::tuple<Input, int>>& p) {
                           return std::string(std::get<0>(p.param).name) + "_" +
                                  std::to_string(std::get<1>(p.param)) + "_shards";
                         });

TEST(Shards, PlanListsEveryUnitWithItsShard) {
  const auto file = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const auto r = run_sfcv("plan '" + file + "' --ctl 'AG !(V1 & V3)' --checks all --shard 1/3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto plan = json::parse(r.out);
  EXPECT_EQ(plan.at("shards"), 3);
  const auto& units = plan.at("units");
  ASSERT_GE(units.size(), 4u);
  EXPECT_EQ(units[0].at("id"), "property/0");
  EXPECT_EQ(units[1].at("id"), "check/reachable");
  std::uint64_t total = 0;
  std::vector<std::uint64_t> load(3, 0);
  for (const auto& u : units) {
    total += u.at("cost").get<std::uint64_t>();
    load.at(u.at("shard").get<std::size_t>() - 1) += u.at("cost").get<std::uint64_t>();
  }
  EXPECT_EQ(plan.at("total_cost"), total);
  for (const auto l : load) EXPECT_GT(l, 0u) << "a shard without work";
  // The same command line gives the same plan.
  EXPECT_EQ(run_sfcv("plan '" + file + "' --ctl 'AG !(V1 & V3)' --checks all --shard 1/3").out,
            r.out);
}

TEST(Shards, BadShardIsUsageError) {
  const auto file = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  for (const char* bad : {"0/4", "5/4", "x", "1/0", "1/", "-1/4"}) {
    const auto r = run_sfcv("check '" + file + "' --shard '" + bad + "'");
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("bad --shard '" + std::string(bad) + "'"), std::string::npos) << r.err;
  }
}

TEST(Shards, MissingDuplicateOrForeignShardIsRefused) {
  const auto file = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const std::string check = "check '" + file + "' --checks reachable,dead-transitions,reentry";
  const auto files = run_shards(check, 4);
  auto r = run_sfcv("merge '" + files[0] + "' '" + files[1] + "' '" + files[3] + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("shard 3/4 missing"), std::string::npos) << r.err;
  r = run_sfcv("merge" + joined(files) + " '" + files[1] + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("shard 2/4 given twice"), std::string::npos) << r.err;
  // A shard of another model (the same split): the input hashes differ.
  const auto other = run_shards(
      "check '" + generate("tanks 1", ".st") + "' --checks reachable,dead-transitions,reentry", 4);
  r = run_sfcv("merge '" + files[0] + "' '" + files[1] + "' '" + files[2] + "' '" + other[3] + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("another model"), std::string::npos) << r.err;
  // A plain check result is not a shard.
  const auto plain = write_temp(run_sfcv(check + " --json --quiet").out, ".json");
  r = run_sfcv("merge '" + plain + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no \"shard\""), std::string::npos) << r.err;
}

TEST(Shards, SwarmFindsDeepCounterexampleFirstShardAloneDoesNot) {
  // c counts up every second cycle: c = 31 first holds after 62 cycles. Over --depth 79 the
  // four shards try depths 0-19, 20-39, 40-59 and 60-79.
  const auto file = generate("counter 6", ".st");
  const std::string check =
      "check '" + file + "' --engine bmc --depth 79 --ctl 'AG Counter.c < 31'";
  const auto files = run_shards(check, 4, " --diversify");
  const auto first = json::parse(sfcv::test::read_file(files[0]));
  EXPECT_EQ(first.at("properties").at(0).at("verdict"), "unknown");
  const auto merged = run_sfcv("merge" + joined(files) + " --json --quiet");
  EXPECT_EQ(merged.exit_code, 1) << merged.err;
  const auto j = json::parse(merged.out);
  const auto& p = j.at("properties").at(0);
  EXPECT_EQ(p.at("verdict"), "violated");
  // A shortest run: 62 cycles after the initial state (the trace was replayed on the model).
  EXPECT_EQ(p.at("trace").at("steps").size(), 63u);
  // The merge of a swarm misses no shard either.
  EXPECT_EQ(run_sfcv("merge '" + files[0] + "' '" + files[1] + "'").exit_code, 2);
}

}  // namespace

// Inputs, prev(), rise() and fall() in properties, end to end on the seed's chemical plant
// (IEC 61131-3) and a Grafcet, on both engines, with counterexample replay.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

const std::string kPlant =
    "'" + std::string(SFCV_SOURCE_DIR) + "/examples/chemical_plant/chemical_plant.st'";

/// The report line of the property named `name` ("EF start  holds  0.001s").
std::string line_of(const std::string& out, const std::string& name) {
  for (std::size_t pos = 0; pos < out.size();) {
    const auto end = out.find('\n', pos);
    const auto line = out.substr(pos, end - pos);
    if (line.rfind(name + " ", 0) == 0) return line;
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return "";
}

bool verdict_is(const std::string& out, const std::string& name, const std::string& verdict) {
  return line_of(out, name).find(" " + verdict + " ") != std::string::npos;
}

class HistoryCheck : public ::testing::TestWithParam<const char*> {};

TEST_P(HistoryCheck, StartIsAnInputThatPropertiesCanName) {
  const std::string engine = GetParam();
  auto r = run_sfcv("check " + kPlant + " --engine " + engine + " --ctl 'EF start'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(verdict_is(r.out, "EF start", "holds")) << r.out;
  r = run_sfcv("check " + kPlant + " --engine " + engine + " --ctl 'AG !start'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(verdict_is(r.out, "AG !start", "violated")) << r.out;
}

TEST_P(HistoryCheck, PreviousValuesAndEdges) {
  const std::string engine = GetParam();
  // V1 opens on a rising edge of the chart's own output; it is never open before the start.
  auto r = run_sfcv("check " + kPlant + " --engine " + engine +
                    " --ctl 'EF rise(V1)' --ctl 'EF fall(V1)' --ctl 'AG (rise(V1) -> !prev(V1))'"
                    " --ctl 'AG (prev(V1) <-> V1)'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(verdict_is(r.out, "EF rise(V1)", "holds")) << r.out;
  EXPECT_NE(r.out.find("formula: EF (V1 & !prev(V1))"), std::string::npos) << r.out;
  EXPECT_TRUE(verdict_is(r.out, "EF fall(V1)", "holds")) << r.out;
  EXPECT_TRUE(verdict_is(r.out, "AG (rise(V1) -> !prev(V1))", "holds")) << r.out;
  EXPECT_TRUE(verdict_is(r.out, "AG (prev(V1) <-> V1)", "violated")) << r.out;
  // Rising edge of an input: start is pressed in some cycle after a cycle without it.
  r = run_sfcv("check " + kPlant + " --engine " + engine + " --ctl 'EF rise(start)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

INSTANTIATE_TEST_SUITE_P(Engines, HistoryCheck, ::testing::Values("explicit", "bdd"));

TEST(HistoryCheckCommand, CounterexampleWithAnInputReplays) {
  const auto csv = write_temp("", ".csv");
  auto r = run_sfcv("check " + kPlant + " --quiet --ctl 'AG !start' --trace csv --trace-file '" +
                    csv + "'");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  std::ifstream f(csv);
  std::vector<std::vector<std::string>> rows;  // header first, comment lines skipped
  for (std::string line; std::getline(f, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    rows.push_back(std::move(cells));
  }
  ASSERT_GE(rows.size(), 2u);
  const auto column = std::find(rows[0].begin(), rows[0].end(), "start") - rows[0].begin();
  ASSERT_LT(static_cast<std::size_t>(column), rows[0].size());
  // The last cycle of the counterexample reads start = 1.
  EXPECT_EQ(rows.back()[static_cast<std::size_t>(column)], "1");
  const auto sim = run_sfcv("simulate " + kPlant + " --inputs '" + csv + "'");
  EXPECT_EQ(sim.exit_code, 0) << sim.out << sim.err;
}

TEST(HistoryCheckCommand, StatesGrowOnlyWhenAPropertyNeedsHistory) {
  auto plain = run_sfcv("check " + kPlant + " --json --ctl 'EF V1'");
  auto with_input = run_sfcv("check " + kPlant + " --json --ctl 'EF (V1 & start)'");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(with_input.exit_code, 0) << with_input.err;
  const auto states = [](const std::string& json) {
    const auto k = json.find("\"states\": ");
    return std::stoull(json.substr(k + 10));
  };
  EXPECT_LT(states(plain.out), states(with_input.out));
}

TEST(HistoryCheckCommand, ErrorsAreLocated) {
  auto r = run_sfcv("check " + kPlant + " --ctl 'EF prev(EF V1)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("prev() takes a propositional formula"), std::string::npos) << r.err;
  r = run_sfcv("check " + kPlant + " --ctl 'EF V1' --assume 'rise(start)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not allowed in an assumption"), std::string::npos) << r.err;
}

TEST(HistoryCheckCommand, GrafcetInputsAreTheSituationsInputs) {
  const auto g7 = write_temp(R"(
    project g;
    input a, b;
    output Y;
    grafcet G {
      step 0 initial; step 1;
      transition t1: 0 -> 1 when a;
      transition t2: 1 -> 0 when b & !a;
      action 1: Y;
    }
  )",
                             ".g7");
  for (const char* engine : {"explicit", "bdd"}) {
    auto r =
        run_sfcv(std::string("check '") + g7 + "' --engine " + engine +
                 " --ctl 'AG (X1 -> Y)' --ctl 'EF (X1 & a)' --ctl 'AG (X0 -> !a)' --ctl 'AG !b'");
    EXPECT_EQ(r.exit_code, 1) << engine << r.out << r.err;
    EXPECT_TRUE(verdict_is(r.out, "EF (X1 & a)", "holds")) << r.out;
    EXPECT_TRUE(verdict_is(r.out, "AG (X0 -> !a)", "holds")) << r.out;
    EXPECT_TRUE(verdict_is(r.out, "AG !b", "violated")) << r.out;
  }
  // prev() on a Grafcet: the explicit engine keeps the previous stable situation.
  auto r = run_sfcv(std::string("check '") + g7 + "' --engine explicit --ctl 'AG (rise(X1) -> a)'");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_sfcv(std::string("check '") + g7 + "' --engine bdd --ctl 'AG (rise(X1) -> a)'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--engine explicit"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sfcv::test

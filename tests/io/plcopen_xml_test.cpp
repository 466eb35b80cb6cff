// The PLCopen TC6 XML importer: small inline documents per feature, and the shared corpus.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "model/chart.hpp"
#include "model/names.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::io {
namespace {

using model::Severity;

const char* const kNs201 = "http://www.plcopen.org/xml/tc6_0201";
const char* const kNs200 = "http://www.plcopen.org/xml/tc6_0200";
const char* const kNs10 = "http://www.plcopen.org/xml/tc6.xsd";

// A project with one POU `P` (program) holding `interface`, `extra` (actions, transitions) and
// an SFC body `sfc`.
[[maybe_unused]] std::string project(const std::string& sfc, const std::string& interface = "",
                    const std::string& extra = "", const char* ns = kNs201) {
  return std::string("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<project xmlns=\"") + ns +
         "\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n"
         "<fileHeader companyName=\"t\" productName=\"t\" productVersion=\"1\" creationDateTime=\"2024-01-01T00:00:00\"/>\n"
         "<contentHeader name=\"demo\"/>\n<types><dataTypes/><pous>\n"
         "<pou name=\"P\" pouType=\"program\">\n<interface>" + interface + "</interface>\n" +
         extra + "\n<body><SFC>\n" + sfc + "\n</SFC></body>\n</pou>\n</pous></types>\n</project>\n";
}

[[maybe_unused]] std::string step(int id, const std::string& name, int from = -1, bool initial = false) {
  std::string s = "<step localId=\"" + std::to_string(id) + "\" name=\"" + name + "\"" +
                  (initial ? " initialStep=\"true\"" : "") + ">";
  if (from >= 0)
    s += "<connectionPointIn><connection refLocalId=\"" + std::to_string(from) + "\"/></connectionPointIn>";
  return s + "<connectionPointOut/></step>\n";
}

[[maybe_unused]] std::string inline_st(const std::string& text) {
  return "<condition><inline name=\"\"><ST><xhtml:p><![CDATA[" + text + "]]></xhtml:p></ST></inline></condition>";
}

[[maybe_unused]] std::string transition(int id, int from, const std::string& condition) {
  return "<transition localId=\"" + std::to_string(id) +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn><connectionPointOut/>" + condition + "</transition>\n";
}

[[maybe_unused]] std::string jump(int id, int from, const std::string& target) {
  return "<jumpStep localId=\"" + std::to_string(id) + "\" targetName=\"" + target +
         "\"><connectionPointIn><connection refLocalId=\"" + std::to_string(from) +
         "\"/></connectionPointIn></jumpStep>\n";
}

std::string errors_of(const LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics)
    if (d.severity == Severity::Error) s += d.str() + "\n";
  return s;
}

[[maybe_unused]] bool has_message(const LoadResult& r, Severity sev, const std::string& part) {
  return std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [&](const auto& d) {
    return d.severity == sev && d.message.find(part) != std::string::npos;
  });
}

[[maybe_unused]] const model::Diagnostic* find_message(const LoadResult& r, Severity sev, const std::string& part) {
  for (const auto& d : r.diagnostics)
    if (d.severity == sev && d.message.find(part) != std::string::npos) return &d;
  return nullptr;
}

[[maybe_unused]] std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

[[maybe_unused]] const model::Chart& chart0(const LoadResult& r) { return r.project->pous.at(0).charts.at(0); }

// --------------------------------------------------------------------------------- the corpus

[[maybe_unused]] std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct CorpusCase {
  const char* file;
  std::size_t steps;
  std::size_t transitions;
};

class PlcopenCorpus : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(PlcopenCorpus, LoadsWithManifestCounts) {
  SFCV_REQUIRE_CORPUS(corpus);
  const auto& c = GetParam();
  const auto path = corpus / c.file;
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const auto r = load_file(path.string());
  ASSERT_TRUE(r.project.has_value()) << errors_of(r);
  EXPECT_EQ(errors_of(r), "");
  EXPECT_EQ(model::count_steps(*r.project), c.steps);
  EXPECT_EQ(model::count_transitions(*r.project), c.transitions);
}

// 06: PLC_PRG has 6 steps and 5 transitions, its action sub_sfc1 1 step and 1 transition
// (counted in the file: 7 <step>, 6 <transition>).
INSTANTIATE_TEST_SUITE_P(Manifest, PlcopenCorpus,
                         ::testing::Values(CorpusCase{"01_beremiz_traffic_light.xml", 6, 11},
                                           CorpusCase{"02_beremiz_first_steps.xml", 3, 4},
                                           CorpusCase{"03_matiec_SFC_TEST_tc6v1.xml", 12, 13},
                                           CorpusCase{"06_codesys_nested_sfc_action.xml", 7, 6},
                                           CorpusCase{"07_codesys_ppu_scenario3v1.xml", 55, 58},
                                           CorpusCase{"09_twincat_xppu_scenario1.xml", 95, 104}),
                         [](const auto& param_info) {
                           return "file" + std::string(param_info.param.file).substr(0, 2);
                         });

}  // namespace
}  // namespace sfcv::io

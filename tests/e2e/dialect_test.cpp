// --dialect end to end (docs/semantics.md 1.4a): a file CODESYS wrote is read in CODESYS's
// dialect by default, where an IEC action runs once more in the cycle after its step is left;
// --dialect iec reads it without, and says which final calls it leaves out; sfcv's export keeps
// the dialect; `sfcv info` and the JSON provenance say which one applied. The file is written
// here in the shape of a CODESYS export (tests/support/plcopen_text.hpp).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

// S1 -a-> S2 -b-> S1. S2's IEC action Look records whether S1 is active: never while S2 is, but
// in Look's final call, the cycle after S2 is left for S1, it is.
std::string final_call_chart() {
  return kPlcopenHeader + "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"a", "b"}) + plcopen_vars("outputVars", {"seen"}) +
         "</interface><actions><action name=\"Look\"><body>" +
         plcopen_st("IF S1.X THEN seen := TRUE; END_IF;") + "</body></action></actions>" +
         R"(<body><SFC>
<step localId="1" name="S1" initialStep="true"><connectionPointIn/><connectionPointOut/></step>
<transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
  <connectionPointOut/><condition><inline name="">)" +
         plcopen_st("a") + R"(</inline></condition></transition>
<step localId="3" name="S2"><connectionPointIn><connection refLocalId="2"/></connectionPointIn>
  <connectionPointOut/><connectionPointOutAction/></step>
<transition localId="4"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
  <connectionPointOut/><condition><inline name="">)" +
         plcopen_st("b") + R"(</inline></condition></transition>
<jumpStep localId="5" targetName="S1"><connectionPointIn><connection refLocalId="4"/>
  </connectionPointIn></jumpStep>
<actionBlock localId="6"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
  <action localId="7" qualifier="N"><reference name="Look"/></action></actionBlock>
</SFC></body></pou>
)" + kPlcopenFooter;
}

const char* kNeverSeen = " --checks none --ctl 'AG !seen'";

TEST(Dialect, ACodesysFileIsReadWithItsFinalCallsInEveryEngine) {
  const auto path = write_temp(final_call_chart(), ".xml");
  for (const char* engine : {"explicit", "bdd", "bmc", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv("check '" + path + "'" + kNeverSeen + " --engine " + engine);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    if (std::string(engine) == "bmc") continue;  // it proves nothing
    const auto iec =
        run_sfcv("check '" + path + "'" + kNeverSeen + " --dialect iec --engine " + engine);
    EXPECT_EQ(iec.exit_code, 0) << iec.out << iec.err;
    EXPECT_NE(iec.err.find("codesys runs each IEC action once more"), std::string::npos) << iec.err;
  }
  // The shortest run: enter S2, leave it, and the final call sees S1.
  const auto r = run_sfcv("check '" + path + "'" + kNeverSeen + " --trace json");
  EXPECT_NE(r.out.find("violated"), std::string::npos) << r.out;
  EXPECT_EQ(run_sfcv("check '" + path + "'" + kNeverSeen + " --dialect twincat").exit_code, 1);
  EXPECT_EQ(run_sfcv("check '" + path + "'" + kNeverSeen + " --dialect rockwell").exit_code, 0);
}

TEST(Dialect, TheDialectIsSaidAndKeptByTheExport) {
  const auto path = write_temp(final_call_chart(), ".xml");
  const auto info = run_sfcv("info '" + path + "'");
  EXPECT_NE(info.out.find("read in codesys's dialect"), std::string::npos) << info.out;
  const auto json = nlohmann::json::parse(run_sfcv("info --json '" + path + "'").out);
  EXPECT_EQ(json["vendor_dialect"], "codesys");
  const auto check = run_sfcv("check '" + path + "'" + kNeverSeen + " --json");
  const auto j = nlohmann::json::parse(check.out);
  EXPECT_EQ(j["provenance"]["settings"]["dialect"], "codesys") << check.out;
  const auto iec = nlohmann::json::parse(
      run_sfcv("check '" + path + "'" + kNeverSeen + " --json --dialect IEC").out);
  EXPECT_EQ(iec["provenance"]["settings"]["dialect"], "iec");
  // sfcv's PLCopen export is still CODESYS's model: the same verdict.
  const auto xml = run_sfcv("export '" + path + "' --to plcopen");
  ASSERT_EQ(xml.exit_code, 0) << xml.err;
  const auto exported = write_temp(xml.out, ".xml");
  EXPECT_EQ(run_sfcv("check '" + exported + "'" + kNeverSeen).exit_code, 1);
}

TEST(Dialect, EquivRunsBothSidesInOneDialect) {
  const auto path = write_temp(final_call_chart(), ".xml");
  auto other_text = final_call_chart();
  const std::string product = "productName=\"CODESYS\"";
  other_text.replace(other_text.find(product), product.size(), "productName=\"Beremiz\"");
  const auto other = write_temp(other_text, ".xml");
  // Two CODESYS files: CODESYS's dialect on both sides, equivalent.
  const auto same = run_sfcv("equiv '" + path + "' '" + path + "' --engine explicit");
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  // A CODESYS file against another tool's: which dialect is asked for.
  const auto mixed = run_sfcv("equiv '" + path + "' '" + other + "' --engine explicit");
  EXPECT_EQ(mixed.exit_code, 2) << mixed.out << mixed.err;
  EXPECT_NE(mixed.err.find("OLD is in codesys's dialect and NEW in iec's"), std::string::npos)
      << mixed.err;
  for (const char* d : {"codesys", "iec"}) {
    const auto r =
        run_sfcv("equiv '" + path + "' '" + other + "' --engine explicit --dialect " + d);
    EXPECT_EQ(r.exit_code, 0) << d << r.out << r.err;
  }
}

TEST(Dialect, BadValuesAndGrafcetsAreUsageErrors) {
  const auto path = write_temp(final_call_chart(), ".xml");
  const auto bad = run_sfcv("check '" + path + "'" + kNeverSeen + " --dialect beremiz");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad --dialect 'beremiz' (expected iec, codesys, twincat, siemens or "
                         "rockwell)"),
            std::string::npos)
      << bad.err;
  const auto g7 = source_path("examples/pistons/pistons.g7");
  const auto r = run_sfcv("check '" + g7 + "' --checks none --ctl 'AG TRUE' --dialect codesys");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--dialect apply to the IEC 61131-3 semantics only"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace sfcv::test

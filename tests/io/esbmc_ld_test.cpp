// ESBMC's LD benchmarks (`regression/ld/*.ld`, issue 45) are PLCopen-looking XML in a layout of
// their own: <pous> straight under <project>, networks as <rung> lists. sfcv does not read that
// layout; it refuses it by name, never as an empty program whose coils stay FALSE.

#include <gtest/gtest.h>

#include <string>

#include "io/load.hpp"

namespace sfcv::io {
namespace {

const std::string kHead =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n"
    "  <fileHeader companyName=\"x\" productVersion=\"1.0\" creationDateTime=\"2026-07-30\"/>\n"
    "  <contentHeader name=\"esd\"/>\n";

const std::string kPou =
    "<pou name=\"esd\" pouType=\"program\"><interface>"
    "<inputVars><variable name=\"a\"><type><BOOL/></type></variable></inputVars>"
    "<outputVars><variable name=\"q\"><type><BOOL/></type></variable></outputVars>"
    "</interface><body><LD>\n"
    "  <rung localId=\"1\"><contact variable=\"a\"/><coil kind=\"set\" variable=\"q\"/></rung>\n"
    "</LD></body></pou>";

std::string messages(const LoadResult& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += d.str() + "\n";
  return s;
}

bool has(const LoadResult& r, model::Severity sev, const std::string& part) {
  for (const auto& d : r.diagnostics)
    if (d.severity == sev && d.message.find(part) != std::string::npos) return true;
  return false;
}

TEST(EsbmcLd, PousDirectlyUnderProjectAreRefusedByName) {
  const auto r =
      load_plcopen_xml(kHead + "  <types/>\n  <pous>" + kPou + "</pous>\n</project>\n", "esd.ld");
  EXPECT_TRUE(has(r, model::Severity::Error,
                  "unsupported: <pous> directly under <project> (the layout of ESBMC's LD "
                  "benchmarks; PLCopen TC6 puts POUs in <types><pous>): not read"))
      << messages(r);
  EXPECT_FALSE(r.ok());
}

// A <rung> inside a TC6 <LD>: skipped, the body would have no statement and `AG !q` would hold.
TEST(EsbmcLd, ARungInsideTc6LdIsRefusedAtTheRung) {
  const auto r = load_plcopen_xml(
      kHead + "  <types><dataTypes/><pous>" + kPou + "</pous></types>\n</project>\n", "esd.ld");
  EXPECT_TRUE(has(r, model::Severity::Error,
                  "unsupported: <rung> (ESBMC's LD rung shorthand) is not a PLCopen TC6 element") ||
              has(r, model::Severity::Warning, "unsupported: <rung> (ESBMC's LD rung shorthand)"))
      << messages(r);
  if (r.ok()) {
    ASSERT_EQ(r.project->pous.size(), 1u);
    EXPECT_TRUE(r.project->pous[0].body_unsupported) << messages(r);
  }
}

}  // namespace
}  // namespace sfcv::io

// CODESYS/TwinCAT implicit SFC flags (docs/semantics.md, "Implicit SFC flags"): SFCInit and
// SFCReset reset the chart to its initial situation; the other vendor flags are refused.

#include <gtest/gtest.h>

#include "io/load.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/iec_builder.hpp"

namespace sfcv::test {
namespace {

semantics::TransitionSystemPtr build(const std::string& text, model::Diagnostics& diags) {
  auto loaded = io::load_iec_text(text, "flags.st");
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) return nullptr;
  return semantics::make_iec61131_system(*loaded.project, semantics::Iec61131Options{}, diags);
}

// S0 -go-> S1 -go-> S2; S1 sets `armed` (S), S2's P1 action counts. SFCReset/SFCInit inputs.
const char* kChart = R"(FUNCTION_BLOCK Seq
  VAR_INPUT go, SFCInit, SFCReset : BOOL; END_VAR
  VAR_OUTPUT lamp, armed : BOOL; END_VAR
  INITIAL_STEP S0 : Lamp(N); END_STEP
  STEP S1 : Arm(N); END_STEP
  STEP S2 : END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
  TRANSITION FROM S1 TO S2 := go; END_TRANSITION
  TRANSITION FROM S2 TO S0 := FALSE; END_TRANSITION
  ACTION Lamp : lamp := TRUE; END_ACTION
  ACTION Arm : armed := TRUE; lamp := FALSE; END_ACTION
END_FUNCTION_BLOCK
)";

TEST(Iec61131SfcFlags, ResetRestartsFromTheInitialStepAndEvolves) {
  model::Diagnostics diags;
  auto ts = build(kChart, diags);
  ASSERT_TRUE(ts);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"go", 1}}));
  ASSERT_TRUE(r.cycle({{"go", 1}}));
  EXPECT_EQ(r["S2"], 1);  // S2 -> S0 never fires: only a reset leaves S2
  ASSERT_TRUE(r.cycle({{"SFCReset", 1}}));
  EXPECT_EQ(r["S2"], 0);
  EXPECT_EQ(r["S0"], 1);
  EXPECT_EQ(r["Lamp"], 1);
  // Reset, then the cycle goes on: S0's action runs and S0 -go-> S1 fires in the same cycle.
  ASSERT_TRUE(r.cycle({{"SFCReset", 1}, {"go", 1}}));
  EXPECT_EQ(r["S1"], 1);
  EXPECT_EQ(r["lamp"], 1);
}

TEST(Iec61131SfcFlags, InitHeldFreezesTheChartAtItsInitialSituation) {
  model::Diagnostics diags;
  auto ts = build(kChart, diags);
  ASSERT_TRUE(ts);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"go", 1}}));
  ASSERT_TRUE(r.cycle());  // Arm runs
  EXPECT_EQ(r["S1"], 1);
  EXPECT_EQ(r["armed"], 1);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(r.cycle({{"SFCInit", 1}, {"go", 1}}));
    EXPECT_EQ(r["S0"], 1);
    EXPECT_EQ(r["S1"], 0);
    EXPECT_EQ(r["armed"], 1);  // variables keep their values: no action ran, none reset them
  }
  ASSERT_TRUE(r.cycle({{"go", 1}}));  // released: evolves again
  EXPECT_EQ(r["S1"], 1);
}

TEST(Iec61131SfcFlags, ActionSettingResetTakesEffectTheNextCycle) {
  model::Diagnostics diags;
  auto ts = build(R"(PROGRAM P
  VAR_INPUT go : BOOL; END_VAR
  VAR SFCReset : BOOL; END_VAR
  INITIAL_STEP S0 : Clear(N); END_STEP
  STEP S1 : Again(N); END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
  TRANSITION FROM S1 TO S0 := FALSE; END_TRANSITION
  ACTION Again : SFCReset := TRUE; END_ACTION
  ACTION Clear : SFCReset := FALSE; END_ACTION
END_PROGRAM
)",
                  diags);
  ASSERT_TRUE(ts);
  Runner r(*ts);
  ASSERT_TRUE(r.cycle({{"go", 1}}));
  EXPECT_EQ(r["S1"], 1);
  ASSERT_TRUE(r.cycle());  // Again runs: SFCReset TRUE from now on
  EXPECT_EQ(r["S1"], 1);
  ASSERT_TRUE(r.cycle());  // read after the body: reset, S0's Clear runs
  EXPECT_EQ(r["S0"], 1);
  EXPECT_EQ(r["SFCReset"], 0);
}

TEST(Iec61131SfcFlags, OtherVendorFlagsAreRefusedWithTheirLocation) {
  for (const char* flag : {"SFCPause", "SFCError", "SFCCurrentStep", "SFCErrorAnalyzation"}) {
    SCOPED_TRACE(flag);
    model::Diagnostics diags;
    auto ts = build(std::string("PROGRAM P\n  VAR go : BOOL;\n    ") + flag +
                        " : BOOL; END_VAR\n  INITIAL_STEP S0 : END_STEP\n  STEP S1 : END_STEP\n"
                        "  TRANSITION FROM S0 TO S1 := go; END_TRANSITION\n"
                        "  TRANSITION FROM S1 TO S0 := go; END_TRANSITION\nEND_PROGRAM\n",
                    diags);
    EXPECT_FALSE(ts);
    ASSERT_FALSE(diags.empty());
    EXPECT_NE(diags.front().message.find("implicit SFC flag"), std::string::npos)
        << diags.front().str();
    EXPECT_EQ(diags.front().where.line, 3) << diags.front().str();
  }
}

TEST(Iec61131SfcFlags, NonBooleanFlagIsRefused) {
  model::Diagnostics diags;
  auto ts = build(R"(PROGRAM P
  VAR go : BOOL; SFCReset : INT; END_VAR
  INITIAL_STEP S0 : END_STEP
  STEP S1 : END_STEP
  TRANSITION FROM S0 TO S1 := go; END_TRANSITION
  TRANSITION FROM S1 TO S0 := go; END_TRANSITION
END_PROGRAM
)",
                  diags);
  EXPECT_FALSE(ts);
  ASSERT_FALSE(diags.empty());
  EXPECT_NE(diags.front().message.find("must be a BOOL"), std::string::npos);
}

// A program without a chart may use the names freely.
TEST(Iec61131SfcFlags, NamesAreFreeWithoutAChart) {
  model::Diagnostics diags;
  auto ts = build(R"(PROGRAM P
  VAR_INPUT go : BOOL; END_VAR
  VAR_OUTPUT SFCPause : BOOL; END_VAR
  SFCPause := go;
END_PROGRAM
)",
                  diags);
  EXPECT_TRUE(ts);
}

}  // namespace
}  // namespace sfcv::test

#pragma once
// A Boolean action of a function block instance named like the variable it drives: the
// action `Extend` of `Cylinder` and its output `Extend` are two bits called
// "Main.Lift.Extend" (the activity and the value). The exports once gave them one identifier
// and one output, and the full name and the alias `Lift.Extend` once named different bits.

namespace sfcv::test {

/// The Boolean action alone drives `Extend`: the two bits are equal in every dialect.
inline constexpr const char* kCylinderChart = R"(
FUNCTION_BLOCK Cylinder
  VAR_INPUT Go : BOOL; END_VAR
  VAR_OUTPUT Extend : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Out: Extend(N); END_STEP
  TRANSITION FROM Idle TO Out := Go; END_TRANSITION
  TRANSITION FROM Out TO Idle := NOT Go; END_TRANSITION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT Button : BOOL; END_VAR
  VAR Lift : Cylinder; END_VAR
  Lift(Go := Button);
END_PROGRAM
)";

/// Hold also writes `Extend` in Idle, where the Boolean action does not run: under CODESYS's
/// and TwinCAT's reading the variable is then TRUE and the activity FALSE.
inline constexpr const char* kCylinderWithHoldChart = R"(
FUNCTION_BLOCK Cylinder
  VAR_INPUT Go : BOOL; Force : BOOL; END_VAR
  VAR_OUTPUT Extend : BOOL; END_VAR
  INITIAL_STEP Idle: Hold(N); END_STEP
  STEP Out: Extend(N); END_STEP
  ACTION Hold: IF Force THEN Extend := TRUE; END_IF; END_ACTION
  TRANSITION FROM Idle TO Out := Go; END_TRANSITION
  TRANSITION FROM Out TO Idle := NOT Go; END_TRANSITION
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_INPUT Button : BOOL; F : BOOL; END_VAR
  VAR Lift : Cylinder; END_VAR
  Lift(Go := Button, Force := F);
END_PROGRAM
)";

}  // namespace sfcv::test

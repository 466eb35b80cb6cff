#pragma once
// The set/reset chart of issue 47 (action orders), shared by its engine and CLI tests: Start sets
// the motor, Stop resets it; in Halt both run, so the motor after Halt depends on the order the
// two actions run in, and Halt returns to Idle at once.

namespace sfcv::test {

inline constexpr const char* kPressChart = R"(
PROGRAM Press
  VAR_INPUT go : BOOL; stop : BOOL; END_VAR
  VAR_OUTPUT motor : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Run: Start(N); END_STEP
  STEP Halt: Start(N); Stop(N); END_STEP
  TRANSITION FROM Idle TO Run := go; END_TRANSITION
  TRANSITION FROM Run TO Halt := stop; END_TRANSITION
  TRANSITION FROM Halt TO Idle := TRUE; END_TRANSITION
  ACTION Start: motor := TRUE; END_ACTION
  ACTION Stop: motor := FALSE; END_ACTION
END_PROGRAM
)";

}  // namespace sfcv::test

#pragma once
// The chart of issue 53's ST loop bound, shared by the export and confirmation tests: a cycle
// whose WHILE loop meets sfcv's bound (1000 iterations) has no successor in sfcv, which answers
// unknown; on a PLC the loop ends after 2000 iterations and sets bad, so no exported model may
// prove `AG !bad` by cutting that cycle.

namespace sfcv::test {

inline constexpr const char* kLoopLimitChart = R"(
PROGRAM Chart
  VAR_GLOBAL bad : BOOL; END_VAR
  INITIAL_STEP Idle: END_STEP
  STEP Done: END_STEP
  TRANSITION FROM Idle TO Done := bad; END_TRANSITION
END_PROGRAM
PROGRAM Loop
  VAR_INPUT go : BOOL; END_VAR
  VAR_EXTERNAL bad : BOOL; END_VAR
  VAR n : INT; END_VAR
  n := 0;
  WHILE go AND n < 2000 DO
    n := n + 1;
  END_WHILE;
  IF n >= 2000 THEN
    bad := TRUE;
  END_IF;
END_PROGRAM
)";

}  // namespace sfcv::test

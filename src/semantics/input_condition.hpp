#pragma once
// Conditions on the inputs: the label of a successor. A condition is a disjunction of cubes; a
// cube constrains some inputs (a Boolean input to one value, an integer input to an interval).
// Inputs a cube does not mention are free.

#include <cstdint>
#include <string>
#include <vector>

#include "model/types.hpp"

namespace sfcv::semantics {

struct InputVariable {
  std::string name;
  model::Type type;  ///< Bool or Int (its range bounds the values)
  /// Not a signal of the plant but a nondeterministic choice of the semantics made explicit
  /// (IEC: `timeout:<timer>` a running timer expires, `choice:<step>` which conflicting
  /// alternative fires, `elapse:<step>` how far a step's abstract .T advances). Engines treat it
  /// like any input; traces may hide it.
  bool pseudo = false;
};

struct InputLiteral {
  std::uint32_t input = 0;  ///< index into TransitionSystem::inputs()
  std::int64_t lo = 0;      ///< Bool: lo == hi == 0 or 1
  std::int64_t hi = 0;
  bool operator==(const InputLiteral&) const = default;
};

struct InputCube {
  std::vector<InputLiteral> literals;  ///< sorted by input, at most one per input; empty = true
  bool operator==(const InputCube&) const = default;
};

struct InputCondition {
  std::vector<InputCube> cubes;  ///< empty = false

  static InputCondition always() { return InputCondition{{InputCube{}}}; }
  bool is_false() const { return cubes.empty(); }
  bool is_true() const;

  /// One valuation inside the condition (free inputs take their lowest value, i.e. FALSE);
  /// values[i] is the value of input i. Precondition: !is_false().
  std::vector<std::int64_t> witness(const std::vector<InputVariable>& inputs) const;
  bool holds(const std::vector<std::int64_t>& valuation) const;

  /// "LIS1 & !LIS2 | i <= 562" (the RSG's notation: & | !, integer ranges as comparisons).
  std::string to_string(const std::vector<InputVariable>& inputs) const;
};

}  // namespace sfcv::semantics

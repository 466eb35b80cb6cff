#pragma once
// Conditions on the inputs: the label of a successor. A condition is a disjunction of cubes; a
// cube constrains some inputs (a Boolean input to one value, an integer input to an interval).
// Inputs a cube does not mention are free.

#include <cstdint>
#include <string>
#include <unordered_set>
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

  /// Approximate heap bytes of the cubes (the memory budget of one state's enumeration).
  std::uint64_t memory_bytes() const;
};

/// A condition built cube by cube without repeats, in first-occurrence order: a search while
/// it is small, then a hash of every cube, so that adding n cubes costs O(n) however they come
/// (a wide state may bring millions, in one successor or one per successor).
class ConditionBuilder {
 public:
  void add(const InputCube& cube);
  void add(const std::vector<InputCube>& cubes) {
    for (const auto& c : cubes) add(c);
  }
  const InputCondition& condition() const { return condition_; }
  InputCondition take() && { return std::move(condition_); }
  std::uint64_t memory_bytes() const { return condition_.memory_bytes() + hashes_.size() * 16; }

 private:
  InputCondition condition_;
  std::unordered_set<std::uint64_t> hashes_;  ///< of every cube, once past a few
};

}  // namespace sfcv::semantics

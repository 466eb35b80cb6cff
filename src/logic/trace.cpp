#include "logic/trace.hpp"

#include <algorithm>

namespace sfcv::logic {

InputPicker::InputPicker(const std::vector<semantics::InputVariable>& inputs,
                         const std::vector<std::int64_t>& previous)
    : base_(previous) {
  if (base_.size() != inputs.size()) {
    base_.assign(inputs.size(), 0);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      base_[i] = inputs[i].type.kind == model::TypeKind::Bool ? 0 : inputs[i].type.lo;
  }
}

void InputPicker::add(const semantics::InputCube& cube) {
  if (settled()) return;
  auto v = base_;
  std::size_t changes = 0;
  for (const auto& lit : cube.literals) {
    if (lit.input >= v.size()) continue;
    const auto clamped = std::clamp(v[lit.input], lit.lo, lit.hi);
    if (clamped != v[lit.input]) ++changes;
    v[lit.input] = clamped;
  }
  // The first cube with the fewest changes; one that holds at the base changes nothing.
  if (changes < best_changes_) {
    best_changes_ = changes;
    best_ = std::move(v);
  }
}

std::vector<std::int64_t> pick_inputs(const semantics::InputCondition& condition,
                                      const std::vector<semantics::InputVariable>& inputs,
                                      const std::vector<std::int64_t>& previous) {
  InputPicker picker(inputs, previous);
  for (const auto& cube : condition.cubes) picker.add(cube);
  return picker.pick();
}

}  // namespace sfcv::logic

#include "logic/trace.hpp"

#include <algorithm>

namespace sfcv::logic {

std::vector<std::int64_t> pick_inputs(const semantics::InputCondition& condition,
                                      const std::vector<semantics::InputVariable>& inputs,
                                      const std::vector<std::int64_t>& previous) {
  std::vector<std::int64_t> base = previous;
  if (base.size() != inputs.size()) {
    base.assign(inputs.size(), 0);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      base[i] = inputs[i].type.kind == model::TypeKind::Bool ? 0 : inputs[i].type.lo;
  }
  if (condition.cubes.empty() || condition.holds(base)) return base;
  std::vector<std::int64_t> best;
  std::size_t best_changes = ~std::size_t{0};
  for (const auto& cube : condition.cubes) {
    auto v = base;
    std::size_t changes = 0;
    for (const auto& lit : cube.literals) {
      if (lit.input >= v.size()) continue;
      const auto clamped = std::clamp(v[lit.input], lit.lo, lit.hi);
      if (clamped != v[lit.input]) ++changes;
      v[lit.input] = clamped;
    }
    if (changes < best_changes) {
      best_changes = changes;
      best = std::move(v);
    }
  }
  return best;
}

}  // namespace sfcv::logic

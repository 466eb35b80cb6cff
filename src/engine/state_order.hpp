#pragma once
// The canonical order of states that both query engines print in: layout fields in order, each
// compared by value. It does not depend on how a state was found (BFS numbering, BDD variable
// order), so the explicit and the symbolic engine list the same sets the same way.

#include "semantics/state_layout.hpp"

namespace sfcv::engine {

inline bool canonically_less(const semantics::StateLayout& layout, semantics::StateView a,
                             semantics::StateView b) {
  for (std::uint32_t f = 0; f < layout.fields().size(); ++f) {
    const auto va = layout.get(a, f), vb = layout.get(b, f);
    if (va != vb) return va < vb;
  }
  return false;
}

}  // namespace sfcv::engine

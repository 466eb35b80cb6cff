#pragma once
// One negation pushed inward through the CTL operators, used to explain why a formula fails
// (the counterexample of g is the witness of push_negation(g)) by every engine.

#include "logic/fwd.hpp"

namespace sfcv::logic {

/// Pushes one negation inward: !AG p -> EF !p, !AF p -> EG !p, !A[p U q] -> E[!q U !p & !q] |
/// EG !q, !(a & b) -> !a | !b, ... ; returns `f` negated one level deep.
FormulaPtr push_negation(const FormulaPtr& f);

}  // namespace sfcv::logic

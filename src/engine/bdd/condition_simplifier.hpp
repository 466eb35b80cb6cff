#pragma once
// Simplification of input conditions (RSG edge labels) into an irredundant sum of products,
// by the Minato-Morreale ISOP over BDDs.
//
// Boolean inputs are BDD variables. An integer literal (input in [lo, hi]) is an opaque atom:
// its own variable, with no knowledge of the other intervals of the same input. The result is
// therefore equivalent to the input condition (atom-level equivalence implies equivalence), but
// it only merges integer literals that are identical; a negated atom is written back as the one
// or two intervals of its complement.

#include <vector>

#include "semantics/input_condition.hpp"

namespace sfcv::engine {

semantics::InputCondition simplify(const semantics::InputCondition& condition,
                                   const std::vector<semantics::InputVariable>& inputs);

}  // namespace sfcv::engine

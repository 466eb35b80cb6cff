#pragma once
// Converts a propositional formula (an --assume or `assume` constraint) to the chart IR's
// expression, which the semantics resolves against its own scope (inputs, variables, steps).

#include "logic/fwd.hpp"
#include "model/expr.hpp"

namespace sfcv::logic {

/// `FILL_A.X` becomes a Member node, `level >= 3` a Ge node, `a -> b` becomes `NOT a OR b`,
/// `a <-> b` becomes `a = b`. Throws std::invalid_argument on a temporal operator.
model::ExprPtr to_expr(const Formula& f, const std::string& file = {});

}  // namespace sfcv::logic

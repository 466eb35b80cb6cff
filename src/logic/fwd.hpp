#pragma once
// Forward declarations of the property language: formulas are small immutable values shared
// between users (like spot::formula), passed as FormulaPtr.

#include <memory>

namespace sfcv::logic {

struct Formula;
using FormulaPtr = std::shared_ptr<const Formula>;

}  // namespace sfcv::logic

#pragma once
// One nesting limit for every parser and every recursive pass over expressions, statements and
// formulas. Real charts nest a few levels; the limit keeps recursion far from the end of the
// stack (also under AddressSanitizer, whose frames are several times larger), so that hostile
// input ends in a located error instead of a stack overflow.

#include <cstdint>

namespace sfcv::model {

/// The deepest nesting any parser accepts (parentheses, unary operators, nested statements,
/// and the height of the trees they build). Trees no deeper than this can be walked recursively.
inline constexpr int kMaxNesting = 200;

/// Counts the levels of a recursive descent. `NestingLevel level(depth);` enters one level and
/// leaves it on every exit path; `level.too_deep()` says the limit is passed (the caller reports
/// its located error).
class NestingLevel {
 public:
  explicit NestingLevel(int& depth) : depth_(depth) { ++depth_; }
  ~NestingLevel() { --depth_; }
  NestingLevel(const NestingLevel&) = delete;
  NestingLevel& operator=(const NestingLevel&) = delete;
  bool too_deep() const { return depth_ > kMaxNesting; }

 private:
  int& depth_;
};

}  // namespace sfcv::model

#pragma once
// Exit codes are a contract (README): 0 every property holds, 1 some property is violated,
// 2 bad usage or input, 3 unknown (a resource limit was reached).

#include <stdexcept>
#include <string>

namespace sfcv::cli {

enum ExitCode : int { kHolds = 0, kViolated = 1, kBadInput = 2, kUnknown = 3 };

/// Bad usage or input: the message is printed as is, exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sfcv::cli

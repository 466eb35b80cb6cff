#pragma once
// Exit codes are a contract (README): 0 every property holds, 1 some property is violated,
// 2 bad usage or input, 3 unknown (a resource limit was reached), 4 an internal error (a bug).
// The error kinds (model/errors.hpp) map to them in one place: run_with_exit_codes.

#include <functional>
#include <ostream>

#include "model/errors.hpp"

namespace sfcv::cli {

enum ExitCode : int { kHolds = 0, kViolated = 1, kBadInput = 2, kUnknown = 3, kInternalError = 4 };

// The CLI's own errors are the library's kinds: bad usage or input, exit code 2.
using sfcv::InputError;
using sfcv::UsageError;

/// Runs `command` and returns its exit code; an error it throws becomes its kind's exit code
/// (InputError, UnsupportedConstruct, UsageError: 2; LimitReached, out of memory: 3; any other
/// exception: 4, an internal error), with its message on `err`.
int run_with_exit_codes(const std::function<int()>& command, std::ostream& err);

}  // namespace sfcv::cli

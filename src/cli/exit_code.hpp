#pragma once
// Exit codes are a contract (README): 0 every property holds, 1 some property is violated,
// 2 bad usage or input, 3 unknown (a resource limit was reached), 4 an internal error (a bug).
// The error kinds (model/errors.hpp) map to them in one place: run_with_exit_codes.

#include <functional>
#include <ostream>
#include <string>

#include "model/errors.hpp"

namespace sfcv::cli {

enum ExitCode : int { kHolds = 0, kViolated = 1, kBadInput = 2, kUnknown = 3, kInternalError = 4 };

// The CLI's own errors are the library's kinds: bad usage or input, exit code 2.
using sfcv::InputError;
using sfcv::UsageError;

/// Runs `command` and returns its exit code; an error it throws becomes its kind's exit code
/// (InputError, UnsupportedConstruct, UsageError: 2; LimitReached, out of memory: 3; any other
/// exception: 4, an internal error), with its message on `err`.
/// With `json_out` (a command run with --json), the error is also written there as one JSON
/// object, so that standard output stays a JSON document (write_json_error).
int run_with_exit_codes(const std::function<int()>& command, std::ostream& err,
                        std::ostream* json_out = nullptr);

/// {"schema_version": "1.0", "error": {"kind": "input", "message": "..."}, "exit_code": 2}:
/// kind is usage, input, unsupported, limit, out-of-memory or internal
/// (share/sfcv/check-result.schema.json, docs/formats.md).
void write_json_error(std::ostream& out, const char* kind, const std::string& message,
                      int exit_code);

/// Whether the command line asks for JSON on standard output (a `--json` word).
bool wants_json(int argc, char** argv);

}  // namespace sfcv::cli

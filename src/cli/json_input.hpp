#pragma once
// JSON documents sfcv reads back (a saved `check --json` result, a `--trace json` trace), read
// through model::read_input_file's guards and parsed with a bounded depth: a 100,000-deep array
// in an extra field once crashed `sfcv report` in recursive printing.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace sfcv::cli {

/// Deeper than any document sfcv writes (traces and results nest fewer than ten levels).
inline constexpr std::size_t kMaxJsonDepth = 256;

/// The JSON document in `path`; InputError naming the file and `what` it was read as when it
/// cannot be read, is not JSON (`not_json` starts the message), or nests deeper than
/// kMaxJsonDepth.
nlohmann::json read_json_file(const std::string& path, const std::string& what,
                              const std::string& not_json);

}  // namespace sfcv::cli

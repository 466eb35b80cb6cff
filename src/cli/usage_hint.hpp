#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// "Did you mean" for the command line: CLI11 says "A subcommand is required" for `sfcv chek` and
// "not expected: --clt" for a misspelled option; this names the word and the closest known one.

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sfcv::cli {

/// A clearer message for a command line that CLI11 refused: an unknown subcommand or an unknown
/// long option, with the closest known name. None when the words are all known (CLI11's message
/// is then the right one). `args` are argv[1..].
std::optional<std::string> usage_hint(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace sfcv::cli

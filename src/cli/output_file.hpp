#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// Every file a subcommand writes (reports, traces, exports, graphs) goes through here, so that
// one set of rules holds for all of them (docs/reliability.md, "Output files"):
// - the paths are checked before the run (their directory exists and is writable, the path is
//   not a directory): a typo ends the run at once (exit 2), not after an hour of exploration;
// - a regular file is written to a temporary file in the same directory, then renamed over the
//   target: a reader (or a kill) never sees half a file, and an old report stays whole when
//   the run fails before writing;
// - every write, flush and close error is exit 2 naming the file; "-" is standard output, and
//   special files (/dev/stdout, /dev/full, a FIFO) are written directly, errors still checked.

#include <string>
#include <vector>

namespace sfcv::cli {

/// One output of a subcommand: the path given and the option that gave it ("--junit").
struct OutputPath {
  std::string path;  ///< empty: not requested
  std::string option;
};

/// Throws UsageError (exit 2) naming the option and the path when one requested output cannot
/// be written: its directory is missing or not writable, it is a directory, or two options name
/// the same file. Call before any long work.
void check_output_paths(const std::vector<OutputPath>& outputs);

/// Writes `text` to `out.path` (atomically for a regular file). Throws UsageError naming the
/// file and the option on any error; the target is then left as it was.
void write_output(const OutputPath& out, const std::string& text);

/// Flushes standard output; throws UsageError when a write to it failed (`> /dev/full`).
void flush_standard_output();

}  // namespace sfcv::cli

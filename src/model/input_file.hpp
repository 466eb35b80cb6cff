#pragma once
// Reading an input file (a model, a spec, a query library, a result JSON, a trace) with the
// guards every reader shares: a device such as /dev/zero, a directory or a socket is refused
// instead of read forever, and so is a file larger than kMaxInputBytes.

#include <cstddef>
#include <optional>
#include <string>

namespace sfcv::model {

/// The largest input sfcv reads: 1 GiB (the largest public SFC export found is 2.2 MB).
inline constexpr std::size_t kMaxInputBytes = std::size_t{1} << 30;

/// The whole content of `path`, a regular file or a pipe (`/dev/stdin`, a FIFO). Throws
/// InputError located at the path, saying what it was read as (`what`: "the model", "the spec
/// file"), when it cannot be opened, is not a file, or is larger than `max_bytes`.
std::string read_input_file(const std::string& path, const std::string& what,
                            std::size_t max_bytes = kMaxInputBytes);

/// As read_input_file, into `text`; a failure is returned as its reason (without the path).
std::optional<std::string> try_read_input_file(const std::string& path, const std::string& what,
                                               std::string& text,
                                               std::size_t max_bytes = kMaxInputBytes);

}  // namespace sfcv::model

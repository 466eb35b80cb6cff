#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// Files sfcv writes (SARIF, JSON, VCD, HTML, JUnit) given where a model is expected: read as IEC
// text they gave dozens of lexer errors. Their first bytes tell what they are.

#include <optional>
#include <string>
#include <string_view>

namespace sfcv::cli {

/// What the text is when it is a kind of file that is no model ("a SARIF log", "a VCD
/// waveform", ...), from its first bytes; none when it may be a model.
std::optional<std::string> foreign_file_kind(std::string_view head);

/// Throws InputError ("FILE: this is a SARIF log, not a model ...") when the file at `path` is
/// such a file; does nothing when it cannot be read (the loader reports that).
void refuse_foreign_file(const std::string& path);

}  // namespace sfcv::cli

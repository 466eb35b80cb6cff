#pragma once
// Findings and diagnostics for people (issue 48): a finding line ran 250-320 characters, an
// absolute path, line:col and a full XML path each. Without --verbose the text keeps the path
// relative to the working directory and line:col, and leaves the XML element path out (the
// POU and step are already named in words); --verbose keeps everything.

#include <string>
#include <string_view>

namespace sfcv::report {

/// `text` with each " (/project/...)" XML element path removed and each occurrence of the
/// folder `cwd` (an absolute path, without its final slash) made relative. An element path is
/// a parenthesised text that starts with "/project" or "/" followed by a letter and holds an
/// XPath; quotes inside it (names) are skipped as they are.
std::string concise_text(std::string_view text, std::string_view cwd);

/// The process's working directory (empty when unknown).
std::string working_directory();

}  // namespace sfcv::report

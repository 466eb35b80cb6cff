#pragma once
// Internal header of sfcv_report (only src/report includes it; cmake/CheckInternalHeaders.cmake).
// Escaping shared by the writers of markup: the HTML report, graphviz HTML-like labels.

#include <string>
#include <string_view>

namespace sfcv::report {

/// `<`, `>`, `&` and `"` as character references: safe in HTML text and attribute values.
std::string html_escape(std::string_view s);

/// `"` and `\` backslash-escaped: the inside of a quoted DOT string.
std::string dot_escape(std::string_view s);

}  // namespace sfcv::report

#pragma once
// Internal header of sfcv_report (only src/report includes it; cmake/CheckInternalHeaders.cmake).
// Escaping shared by the writers of markup: the HTML report, graphviz HTML-like labels.

#include <string>
#include <string_view>

namespace sfcv::report {

/// `<`, `>`, `&` and `"` as character references: safe in HTML text and attribute values (and
/// in graphviz HTML-like labels); control bytes other than tab, newline and carriage return,
/// which XML forbids (graphviz then refuses the label), become U+FFFD.
std::string html_escape(std::string_view s);

/// The inside of a quoted DOT string (every name in a DOT file goes through it): `"` and `\`
/// backslash-escaped, so a name can neither end the string nor start a DOT escape (`\l`,
/// `\N`), a newline as `\n` (a line break of the label), other control bytes as spaces.
std::string dot_escape(std::string_view s);

}  // namespace sfcv::report

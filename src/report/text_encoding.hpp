#pragma once
// Names are kept as the bytes of the input (a step name may be Latin-1, or any bytes) and are
// printed as valid UTF-8 by every report writer: each byte that is not part of a well-formed
// UTF-8 sequence becomes U+FFFD. JSON (which a reader must be able to parse), SARIF, the HTML
// page and the text report go through valid_utf8(); XML (JUnit) through xml_text(), which also
// replaces the characters XML 1.0 does not allow (control characters). docs/reliability.md.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace sfcv::report {

/// Whether `s` is well-formed UTF-8 (no overlong forms, no surrogates, at most U+10FFFF).
bool is_valid_utf8(std::string_view s);

/// `s` with each byte outside a well-formed UTF-8 sequence replaced by U+FFFD; valid text is
/// returned unchanged.
std::string valid_utf8(std::string_view s);

/// valid_utf8(s) with the characters XML 1.0 excludes (U+0000-U+001F but tab, line feed and
/// carriage return; U+FFFE, U+FFFF) replaced by U+FFFD too: text for an XML attribute or element.
std::string xml_text(std::string_view s);

/// Every string of `j`, object keys included, through valid_utf8(): a document nlohmann::json
/// can dump (it throws on invalid UTF-8) and any JSON reader can parse.
void make_valid_utf8(nlohmann::json& j);
void make_valid_utf8(nlohmann::ordered_json& j);

}  // namespace sfcv::report

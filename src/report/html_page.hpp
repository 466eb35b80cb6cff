#pragma once
// Internal header of sfcv_report (only src/report includes it; cmake/CheckInternalHeaders.cmake).
// The parts every HTML page of sfcv shares (check, query, equiv): the head with the style sheet,
// the section navigation, a verdict badge, and the layout probe the browser tests read.

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

namespace sfcv::report {

/// From <!DOCTYPE html> to <body>: the title, the viewport, the style sheet (report.css).
std::string html_page_head(const std::string& title);

/// A sticky bar of links to the page's sections: (anchor id, label) pairs.
std::string html_page_nav(const std::vector<std::pair<std::string, std::string>>& sections);

/// `<span class="verdict violated">violated</span>`; the class is the verdict with spaces and
/// slashes as dashes ("not checked" -> not-checked, "n/a" -> n-a).
std::string html_verdict(const std::string& verdict);

/// The string member `key` of an object of a JSON report (the pages are rendered from them), or
/// "" when it is missing or not a string.
std::string json_text(const nlohmann::json& object, const char* key);

/// The script of the pictures (#chart-svg, #situations-svg), after the page's own: they come fitted
/// to their boxes, a click toggles the natural size; a picture whose fitted text would be smaller
/// than 9 px (a wide chart on a phone) starts at its natural size, scrolled in its own box.
std::string html_pictures_script();

/// A script that, only when the URL hash holds `test` (`#trace=0&test`), measures the laid-out
/// page (horizontal overflow of the page, the chart's smallest text, small tap targets, where
/// the chart and the player sit) and writes it as JSON into <html data-sfcv-layout>, and posts
/// it to a parent frame: the browser tests' view of the page at a given width.
std::string html_layout_probe();

}  // namespace sfcv::report

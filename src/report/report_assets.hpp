#pragma once
// Internal header of sfcv_report (only src/report includes it; cmake/CheckInternalHeaders.cmake).
// The HTML report's script and style sheet (share/sfcv/report.js, report.css), compiled in.

#include <string_view>

namespace sfcv::report {

std::string_view report_script();
std::string_view report_style();

}  // namespace sfcv::report

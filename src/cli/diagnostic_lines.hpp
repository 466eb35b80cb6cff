#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// Warnings and notes printed before a run's output: corpus 01 printed 8 notes of 280 characters
// before every output. Without --verbose a warning or note has a relative path and line:col (no
// XML element path), a note's text is cut, and past a few notes the rest are counted; errors
// are always printed in full (they name the XML element).

#include <iosfwd>

#include "model/diagnostic.hpp"

namespace sfcv::cli {

/// Prints `diagnostics` on `err` as above; warnings and notes not at all when `quiet`.
void print_diagnostic_lines(const model::Diagnostics& diagnostics, bool quiet, std::ostream& err);

}  // namespace sfcv::cli

#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// The IEC 61131-3 semantics options as subcommands spell them (--priority, --time, --cycle):
// parsed once here for check, simulate, export and query. Bad values throw InputError (exit 2).

#include <cstdint>
#include <string>

#include "semantics/options.hpp"

namespace sfcv::cli {

/// "10ms", "1s", "250" (milliseconds); positive.
std::int64_t parse_cycle_ms(const std::string& text);
/// "standard" or "none".
semantics::PriorityMode parse_priority(const std::string& text);
/// "abstract" or "discrete".
semantics::TimeMode parse_time_mode(const std::string& text);
/// "free" or "keep" (--unwritten).
semantics::UnwrittenMode parse_unwritten(const std::string& text);

}  // namespace sfcv::cli

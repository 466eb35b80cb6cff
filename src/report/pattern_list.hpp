#pragma once
// The catalogue of requirement patterns as text, for `sfcv patterns`.

#include <string>
#include <vector>

#include "logic/pattern.hpp"

namespace sfcv::report {

/// One block per pattern: its syntax, its English and its CTL; then the scopes and bounds.
std::string pattern_list_text(const std::vector<logic::PatternInfo>& catalogue);

/// The catalogue as JSON, for tools that write requirements (`sfcv patterns --json`): per
/// pattern its name, parameters, English, CTL, whether it takes a scope or a bound, and the
/// PLCverif pattern ids and ESBMC-PLC kinds that --requirements maps onto it.
std::string pattern_list_json(const std::vector<logic::PatternInfo>& catalogue);

}  // namespace sfcv::report

#pragma once
// The catalogue of requirement patterns as text, for `sfcv patterns`.

#include <string>
#include <vector>

#include "logic/pattern.hpp"

namespace sfcv::report {

/// One block per pattern: its syntax, its English and its CTL; then the scopes and bounds.
std::string pattern_list_text(const std::vector<logic::PatternInfo>& catalogue);

}  // namespace sfcv::report

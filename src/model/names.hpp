#pragma once
// IEC 61131-3 identifiers are case-insensitive.

#include <string>
#include <string_view>

namespace sfcv::model {

bool iequals(std::string_view a, std::string_view b);
std::string to_upper(std::string_view s);

}  // namespace sfcv::model

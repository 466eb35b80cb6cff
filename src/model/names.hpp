#pragma once
// IEC 61131-3 identifiers are case-insensitive.

#include <string>
#include <string_view>
#include <vector>

namespace sfcv::model {

bool iequals(std::string_view a, std::string_view b);
std::string to_upper(std::string_view s);
/// The parts of a dotted name as written: "a.b.x" -> {"a", "b", "x"} (member chains of
/// instances, `GVL.x`, `Main.x`).
std::vector<std::string> split_path(std::string_view dotted);

}  // namespace sfcv::model

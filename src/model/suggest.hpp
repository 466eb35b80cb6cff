#pragma once
// "Did you mean": the known name closest to a misspelled one, for the messages of every layer
// (an unknown name in a property or a body, a --pou, a subcommand, an option).

#include <string>
#include <string_view>
#include <vector>

namespace sfcv::model {

/// The candidate closest to `name`, compared case-insensitively: first one whose last dotted
/// part is `name` ("S1" for "Main.S1"), else the one at the smallest edit distance (inserting,
/// deleting, replacing or swapping two neighbouring characters), if that distance is at most a
/// third of the longer name and at most 3 (a distant name is no help). Empty when none is close;
/// ties go to the first candidate.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

/// " (did you mean 'X'?)" for the closest name, or "" when none is close.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

/// The case-insensitive edit distance of a and b (optimal string alignment).
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace sfcv::model

#pragma once
// Printing a model as IEC 61131-3 textual SFC, such that load_iec_text of the result gives a
// structurally equal model (model::first_difference).

#include <string>

#include "model/chart.hpp"

namespace sfcv::io {

/// The project as IEC 61131-3 text (PROGRAM / FUNCTION_BLOCK, VAR sections, steps with their
/// action associations, transitions with priorities, actions with ST or nested SFC bodies).
/// Throws std::invalid_argument naming the construct for what IEC text cannot express: Grafcet
/// stored actions, forcing orders, macro/enclosing steps, edges and delays in expressions,
/// assignment conditions, FUNCTION POUs, actions whose body is not modelled, timed qualifiers
/// without a duration, associations to undeclared steps.
std::string write_iec_text(const model::Project& project);

}  // namespace sfcv::io

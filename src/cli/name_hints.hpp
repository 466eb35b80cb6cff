#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// A property naming a step or variable of a POU that the run leaves out (--pou, or a function
// block never instantiated) said only "unknown name": the name exists, the run does not hold it.

#include "model/chart.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::cli {

/// Completes each "unknown name 'X'" error without a suggestion when some POU of `project`
/// declares a step or variable X (its last dotted part): that POU is not part of the run.
void explain_left_out_names(model::Diagnostics& diagnostics, const model::Project& project);

}  // namespace sfcv::cli

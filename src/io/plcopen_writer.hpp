#pragma once
// Writing a model as a PLCopen TC6 XML v2.01 document (namespace tc6_0201), such that
// load_plcopen_xml of the result gives a structurally equal model (model::first_difference).

#include <string>

#include "model/chart.hpp"

namespace sfcv::io {

/// The project as PLCopen TC6 XML v2.01: POUs under types/pous with their variables, declared
/// actions (ST bodies, nested SFC bodies, or the text of a body sfcv does not model), SFC
/// bodies as graphs (steps, macro-steps, transitions with inline ST conditions, names and
/// priorities, selection and simultaneous divergences/convergences, jumps for back edges,
/// action blocks) and an SFC POU's ST body as a second body. Graphical positions are all 0.
/// Throws std::invalid_argument naming the construct for what the importer would not read
/// back the same: Grafcet projects (edges, delays, stored actions, forcing orders, macro-step
/// entry/exit, enclosing steps), transitions without source or target steps or to undeclared
/// steps, ST-only POU bodies, timed qualifiers without a duration, graphical bodies sfcv does
/// not model, associations to missing steps.
std::string write_plcopen_xml(const model::Project& project);

}  // namespace sfcv::io

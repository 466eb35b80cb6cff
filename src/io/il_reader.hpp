#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Instruction List (IEC 61131-3 2nd ed., 3.2) read as ST statements. Internal to src/io.

#include <optional>

#include "io/plcopen_xml_dom.hpp"
#include "model/statement.hpp"

namespace sfcv::io {

/// The statements an IL body executes, or nullopt with located errors in `problems`. The
/// current result is followed symbolically (no variable is added): each store assigns the
/// expression it holds, and a conditional jump becomes IF ... ELSE with the rest of the body
/// in both branches (forward jumps only; docs/semantics.md 1.9.2).
std::optional<model::StmtList> read_il_statements(const plcopen::BodyText& text,
                                                  model::Diagnostics& problems);

}  // namespace sfcv::io

#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// ST text found in PLCopen XML (conditions, action and transition bodies), handed to the ST
// parser with the location where the text starts. Internal to src/io.

#include <optional>

#include "io/plcopen_xml_dom.hpp"
#include "model/expr.hpp"
#include "model/statement.hpp"

namespace sfcv::io::plcopen {

/// An expression (a transition condition, an inVariable). Parse errors go to `problems`;
/// returns null then.
model::ExprPtr parse_expression_text(const BodyText& text, model::Diagnostics& problems);

/// A statement list. Parse errors go to `problems` (the caller decides their severity);
/// returns nullopt then.
std::optional<model::StmtList> parse_statements_text(const BodyText& text,
                                                     model::Diagnostics& problems);

}  // namespace sfcv::io::plcopen

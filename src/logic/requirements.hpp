#pragma once
// Requirement files written for other tools, read as sfcv's patterns (docs/properties.md,
// "Requirement files"):
//
// - PLCverif-style JSON: {"property_description": ..., "property": {"job_req": "pattern",
//   "pattern_id": "pattern-implication", "pattern_params": {"1": ..., "2": ...}}}, alone, in an
//   array, or in the "properties_to_be_validated" array of a task (the Agents4PLC benchmark);
// - ESBMC-PLC's YAML (esbmc docs/safe-ld-property-format.md): `properties:` entries with id,
//   kind (mutual_exclusion, invariant, absence, response, reachability), their fields,
//   description and justification.
//
// The format is detected by content (JSON starts with '{' or '['). Each requirement becomes a
// named property whose description is its English and whose justification is kept for reports.

#include <string>
#include <string_view>

#include "logic/pattern.hpp"
#include "logic/spec.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::logic {

struct ParsedRequirements {
  Spec spec;
  model::Diagnostics diagnostics;
  bool ok() const { return !model::has_errors(diagnostics); }
};

/// Parses a requirements file; errors (malformed file, unknown pattern id or kind, a missing
/// field, a bad expression) are diagnostics located in `file`.
ParsedRequirements parse_requirements(std::string_view text, const std::string& file,
                                      const PatternOptions& options = {});

/// The sfcv pattern of a PLCverif pattern id ("pattern-implication" -> "implies"), or empty.
std::string_view plcverif_pattern(std::string_view id);

}  // namespace sfcv::logic

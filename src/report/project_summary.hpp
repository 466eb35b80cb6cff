// What `sfcv info` prints: a project's POUs, charts, actions, variables and the variables the
// run reads that no POU writes (docs/semantics.md 1.8), as JSON (share/sfcv/info.schema.json)
// or text rendered from that JSON, so that the two never say different things.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "report/schema_versions.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::report {

/// `unwritten`: nullopt when it was not computed (the semantics cannot model the project, or a
/// limit was reached); a Grafcet has none (its variables are all inputs or outputs).
nlohmann::ordered_json project_summary_json(
    const std::string& file, const model::Project& project,
    const std::optional<std::vector<semantics::UnwrittenVariable>>& unwritten);

/// The text form. `stopped`: a limit left the unwritten variables out.
void print_project_summary(const nlohmann::ordered_json& summary, std::ostream& out, bool stopped);

/// What `sfcv lint --json` prints (share/sfcv/lint.schema.json): the diagnostics in order and
/// their counts.
nlohmann::ordered_json diagnostics_json(const model::Diagnostics& diagnostics, std::size_t errors,
                                        std::size_t warnings);

/// The text form: one line a diagnostic, then "N errors, M warnings".
void print_diagnostics(const model::Diagnostics& diagnostics, std::size_t errors,
                       std::size_t warnings, std::ostream& out);

}  // namespace sfcv::report

#pragma once
// Renders a CheckReport as SARIF 2.1.0, the format code-scanning views (GitHub, GitLab, VS Code
// SARIF viewer) read: one rule per standard check and per property, one result per violation
// (error) or unknown (warning), located in the model's source; a counterexample becomes related
// locations (the steps it visits) and a code flow (one location per situation).

#include <nlohmann/json.hpp>

#include "logic/check_result.hpp"
#include "model/chart.hpp"
#include "report/check_render.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

/// `project` (may be null) gives the steps' source locations.
nlohmann::json check_sarif(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                           const model::Project* project, const RenderOptions& options);

}  // namespace sfcv::report

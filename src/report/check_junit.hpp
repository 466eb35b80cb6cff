#pragma once
// Renders a CheckReport as JUnit XML, the report format CI servers (Jenkins, GitLab, GitHub
// test reporters) read: one test case per property or standard check. A violated property is a
// failure carrying its findings and counterexample; "unknown" is an error, never a pass, because
// a limit stopped the proof; a check the engine cannot evaluate is skipped with the reason.

#include <string>

#include "logic/check_result.hpp"
#include "report/check_render.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

std::string check_junit(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                        const RenderOptions& options);

}  // namespace sfcv::report

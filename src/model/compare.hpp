#pragma once
// Structural comparison of projects, for round-trip tests and for checking that two importers
// (e.g. PLCopen XML and its textual twin) give the same model.

#include <optional>
#include <string>

#include "model/chart.hpp"

namespace sfcv::model {

/// The first structural difference between `a` and `b`, described in words, or nullopt when they
/// are structurally equal. Ignored: source locations, the project name and source format, the
/// order of POUs, variables, steps and actions (matched by name, case-insensitively), the name
/// of a POU's only top-level chart, transition names when either side has none, and type names
/// (types compare by kind, range and FB). Transitions are matched by sources, targets, guard
/// (model::equal) and priority; their document order must agree between transitions that share
/// a source step. Associations compare in order per step. An action whose body is not modelled
/// (Action::body_unsupported) differs from one whose body is.
std::optional<std::string> first_difference(const Project& a, const Project& b);

}  // namespace sfcv::model

#pragma once
// Binds the atoms of a formula to the observables of a transition system
// (semantics::find_observable: case-insensitive, by name then aliases).

#include <string>

#include "logic/fwd.hpp"
#include "model/diagnostic.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

struct ResolvedFormula {
  FormulaPtr formula;  ///< null when some name could not be resolved
  model::Diagnostics diagnostics;
};

/// Resolves every Atom/Compare of `f`. Unknown or ambiguous names, integer variables used as
/// Booleans and inputs (which are not part of a state) are errors located at the atom, in
/// `source` (the file or option the formula came from).
ResolvedFormula resolve(const FormulaPtr& f, const semantics::TransitionSystem& ts,
                        const std::string& source);

}  // namespace sfcv::logic

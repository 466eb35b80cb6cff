#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// --action-order: declaration, alphabetical, unordered, or a FILE of pairs `A < B` (seed 000's
// partial order on actions, docs/semantics.md §1.2a).

#include <string>

#include "semantics/options.hpp"

namespace sfcv::cli {

/// Fills options.action_order (and action_pairs for a FILE). A bad line of the file throws
/// InputError at file:line:col; an unreadable file names it.
void parse_action_order(const std::string& value, semantics::Iec61131Options& options);

/// The pairs of an action order file's text (`A < B < C` per line, `#` or `//` comments);
/// `file` names it in locations.
std::vector<semantics::ActionPair> parse_action_pairs(const std::string& text,
                                                      const std::string& file);

}  // namespace sfcv::cli

#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Building one POU of a PLCopen TC6 document: what the SFC graph builder shares with the POU
// reader. Internal to src/io.

#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/plcopen_xml_dom.hpp"
#include "model/chart.hpp"

namespace sfcv::io::plcopen {

struct PouContext {
  XmlContext& ctx;
  pugi::xml_node pou_node;
  model::Pou& pou;
  /// pou/transitions/transition by upper-case name (conditions given by reference).
  std::map<std::string, pugi::xml_node> named_transitions;
  /// Guards of named transitions already read, by upper-case name.
  std::map<std::string, model::ExprPtr> transition_guards;
  /// FB calls needed by condition networks (LD/FBD logic wired to transitions).
  model::StmtList condition_calls;
  /// Inline action bodies read so far (they are named INLINE1, INLINE2, ...).
  int inline_actions = 0;
};

/// Reads `sfc` into a new chart of the POU (named `chart_name`, body of `parent_action` when
/// not empty), with its action associations and inline actions (named INLINE<k>, numbered in
/// document order over the POU, a suffix added if the name is taken); returns its index in
/// Pou::charts. Macro-step bodies become further charts.
int build_sfc_chart(PouContext& pc, pugi::xml_node sfc, const std::string& chart_name,
                    const std::string& parent_action);

/// A body in ST, FBD or LD as statements (the R_TRIG/F_TRIG instances of LD edge elements,
/// named with `edge_prefix`, are added to the POU's variables); nullopt with the reasons in
/// `problems` when it cannot be modelled (IL, unsupported constructs).
std::optional<model::StmtList> read_statement_body(PouContext& pc, pugi::xml_node language,
                                                   const std::string& edge_prefix,
                                                   model::Diagnostics& problems);

/// The user FUNCTIONs of `pous` whose ST body only assigns their own result and variables
/// (no VAR_IN_OUT, VAR_OUTPUT or VAR_EXTERNAL, no instance call) and calls only standard
/// functions and such functions: leaving out a call of one changes nothing but its value.
std::set<std::string> pure_functions(XmlContext& ctx, const std::vector<pugi::xml_node>& pous);

/// Leaves out of `body` each assignment to a variable of a type sfcv does not model
/// (XmlContext::unmodelled_variables) whose right side only computes the value, with a note
/// in `problems` for each.
void leave_out_unmodelled_writes(PouContext& pc, model::StmtList& body,
                                 model::Diagnostics& problems);

/// Adds to each error of `problems` about such a variable the type it was declared with.
void name_unmodelled_types(const PouContext& pc, model::Diagnostics& problems);

/// Sets `action`'s body from a language element (ST, FBD, LD; IL and others are not modelled).
/// A body that cannot be modelled does not block loading: a warning with the element path,
/// `body_unsupported` set and the reasons as notes.
void read_action_body(PouContext& pc, model::Action& action, pugi::xml_node language);

/// The first element child that is a body language (ST, IL, FBD, LD, SFC), skipping
/// documentation and addData.
pugi::xml_node body_language(pugi::xml_node body);

}  // namespace sfcv::io::plcopen

#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// FBD/LD networks of PLCopen XML as ST: the value on a wire as an expression (transition
// conditions wired to logic, transitions written in FBD/LD), and whole FBD/LD bodies as
// statements (actions). Internal to src/io.
//
// Functions (AND, OR, XOR, NOT, MOVE, comparisons, arithmetic) become expressions. A standard
// function block (TON, SR, R_TRIG, ...) becomes an FbCall statement, emitted before the first
// use of one of its outputs, which reads `instance.OUTPUT`; a feedback loop through an FB
// reads the output of the previous call, as PLCs do. Anything else is an "unsupported"
// diagnostic naming the block.
//
// A network is a DAG: an element whose output feeds several inputs is built once and shared
// (never unfolded into a tree, which doubles per level of sharing). In a body, a shared Boolean
// element becomes a hidden BOOL temporary assigned where the statement first needs it and
// reset at the end of the body, so it carries no state; other shared values stay shared
// expressions, and one that would still unfold past kMaxUnfoldedOperations is refused.

#include <cstdint>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/plcopen_xml_dom.hpp"
#include "model/chart.hpp"
#include "model/expr.hpp"
#include "model/statement.hpp"

namespace sfcv::io::plcopen {

class Network {
 public:
  /// `container`: the element holding the network (SFC, FBD, LD). Problems go to `problems`.
  /// `edge_prefix` names the R_TRIG/F_TRIG instances that LD edge contacts and coils need
  /// (`SFCV_EDGE_<prefix>_<localId>`); it must differ between the networks of one POU.
  /// `declared`: the POU's variables, to know which shared values are Boolean (may be null).
  Network(pugi::xml_node container, const XmlContext& ctx, model::Diagnostics& problems,
          std::string edge_prefix = "", const std::vector<model::Variable>* declared = nullptr);

  /// Operations an expression of the network may have once its sharing is unfolded by the
  /// consumers that read expressions as trees; more is refused as not modelled.
  static constexpr std::uint64_t kMaxUnfoldedOperations = 100000;

  /// input() for a value used as a whole (a transition condition): also checks its unfolded
  /// size. Null after a diagnostic.
  model::ExprPtr condition(pugi::xml_node connection_point_in);

  /// The value flowing into `connection_point_in` (several connections are LD parallel
  /// branches: OR). Null after a diagnostic.
  model::ExprPtr input(pugi::xml_node connection_point_in, pugi::xml_node owner = {});

  /// FB calls the values computed so far need, in call order; the list is emptied.
  model::StmtList take_calls();

  /// The R_TRIG/F_TRIG instances created for edge contacts and coils so far, and the hidden
  /// temporaries of shared elements, as local variables the caller adds to the POU; the list
  /// is emptied.
  std::vector<model::Variable> take_edge_instances();

  /// A whole FBD/LD body as statements: every output (outVariable, inOutVariable, coil) in
  /// execution order, FB calls before their first use. nullopt after a diagnostic.
  std::optional<model::StmtList> statements();

  /// Outputs (outVariable expression / coil variable) named `name`: the value driving it.
  /// Used for transitions written in FBD/LD. Null when absent (no diagnostic) or on error.
  model::ExprPtr output_named(std::string_view name, bool& found);
  /// The positions (in `at`, by localId) of the assigned inOutVariables that `output`'s input
  /// cone reads.
  std::vector<std::size_t> variables_read(pugi::xml_node output,
                                          const std::map<std::string, std::size_t>& at);
  /// Puts the output elements of a network without execution order in data-flow order; false
  /// (after an error) on a cycle.
  bool in_data_flow_order(std::vector<pugi::xml_node>& outputs);

 private:
  model::ExprPtr value(pugi::xml_node connection);
  model::ExprPtr node_value(pugi::xml_node node, const std::string& pin);
  model::ExprPtr block_value(pugi::xml_node block, const std::string& pin);
  /// The variable wired to the VAR_IN_OUT pin `pin` of `block` (a name or member), or null
  /// with a located error.
  model::ExprPtr in_out_variable(pugi::xml_node block, pugi::xml_node pin);
  model::ExprPtr text_value(pugi::xml_node holder, pugi::xml_node text_element);
  bool call_block(pugi::xml_node block);
  /// The localId of the function block (no instance) wired alone into `cpi`, else empty.
  std::string straight_function(pugi::xml_node cpi) const;
  /// The block's EN input (TRUE when not connected; null after a diagnostic).
  model::ExprPtr enable_of(pugi::xml_node block);
  /// `edge` ("rising"/"falling") of `value`, through a new R_TRIG/F_TRIG instance called first.
  model::ExprPtr edge_of(pugi::xml_node node, const std::string& edge, model::ExprPtr value);
  model::ExprPtr fail(pugi::xml_node node, std::string message);
  /// `v`, the value of an element that feeds several inputs, as the network shares it (a
  /// temporary in a body, when Boolean).
  model::ExprPtr shared(pugi::xml_node node, const std::string& pin, model::ExprPtr v);
  bool is_boolean(const model::Expr& e) const;
  /// The type of a variable of the POU or of the network (edge instance, temporary).
  std::optional<model::Type> declared_type(const std::string& name) const;
  /// False (after a located error at `at`) when `v` unfolds past kMaxUnfoldedOperations.
  bool within_unfolded_bound(const model::ExprPtr& v, pugi::xml_node at);

  const XmlContext& ctx_;
  model::Diagnostics& problems_;
  std::map<std::string, pugi::xml_node> by_id_;
  std::map<std::string, pugi::xml_node> connectors_;  ///< connector name -> element
  std::set<std::string> called_;                      ///< FB blocks (localId) already called
  std::set<std::string> visiting_;                    ///< localIds on the evaluation path
  std::set<std::string> evaluated_;                   ///< user function blocks (localId) read
  /// The function block (localId) whose result goes straight to the output being assigned:
  /// its EN may be connected, and guards that assignment (`enable_`, once read).
  std::string enabled_function_;
  model::ExprPtr enable_;
  model::StmtList calls_;
  std::vector<model::Variable> edge_instances_;
  std::set<std::string> edges_;  ///< edge instances already called (one per element)
  std::string edge_prefix_;
  std::map<std::string, model::Type> declared_types_;  ///< upper-case name -> type
  std::map<std::string, int> fan_out_;                 ///< localId -> connections reading it
  std::map<std::string, model::ExprPtr> memo_;  ///< "localId/pin" -> value of a shared element
  bool hoist_ = false;                          ///< in statements(): shared Booleans to temporaries
  std::vector<std::string> temporaries_;        ///< hidden temporaries, reset after the body
  pugi::xml_node container_;
};

/// The IF statement `IF cond THEN target := value; END_IF` (set/reset coils).
model::StmtPtr make_if_assign(model::ExprPtr cond, std::string target, model::ExprPtr value,
                              model::SourceLocation where);

}  // namespace sfcv::io::plcopen

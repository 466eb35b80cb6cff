#pragma once
// The chart IR: one model for IEC 61131-3 SFC and IEC 60848 Grafcet.
//
// A Project holds POUs. A POU holds variables, charts (SFC bodies / partial grafcets) and
// actions. Chart 0 of a POU is not special: `Chart::parent_action` tells whether a chart is a
// top-level body (empty) or the body of an action (a nested SFC, hierarchy). Step names are
// unique within one chart; other charts may reuse them (TwinCAT actions each have an "Init").

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/expr.hpp"
#include "model/source_location.hpp"
#include "model/statement.hpp"
#include "model/types.hpp"

namespace sfcv::model {

enum class Dialect { Iec61131, Grafcet };

// ---------------------------------------------------------------------------------- variables

enum class VarDirection { Input, Output, InOut, Local, Global, External };

/// One dimension of an ARRAY declaration: [lo..hi].
struct ArrayDimension {
  std::int64_t lo = 0, hi = 0;
  bool operator==(const ArrayDimension&) const = default;
};

struct Variable {
  std::string name;
  VarDirection direction = VarDirection::Local;
  Type type;
  std::optional<std::int64_t> initial;  ///< BOOL as 0/1, TIME in ms
  std::string address;                  ///< "%IX1" when declared with AT, else empty
  SourceLocation where;
  // As read, before model::lower_data_types replaces the variable by its elements:
  /// non-empty: an ARRAY of `type` with these dimensions.
  std::vector<ArrayDimension> dimensions;
  /// The initial value of an ARRAY, STRUCT or enumeration variable as written
  /// (`[1, 2(0)]`, `(x := 1)`, `Red`); null when none.
  ExprPtr declared_initial;
  /// Declared in a CONSTANT section (`VAR CONSTANT`, PLCopen `constant="true"`): no one may
  /// write it, so the semantics never reads it as an input (docs/semantics.md 1.8).
  bool constant = false;
};

// -------------------------------------------------------------------------- user data types

/// A TYPE declaration (PLCopen <dataType>). model::lower_data_types replaces every variable of
/// such a type by its elements (`s.x`, `a[2]`) and every enumerator by its value.
enum class DataTypeKind { Enumeration, Structure, Alias };

struct DataType {
  std::string name;
  DataTypeKind kind = DataTypeKind::Alias;
  /// Enumeration: the enumerators and their values, in declaration order.
  std::vector<std::pair<std::string, std::int64_t>> enumerators;
  /// Structure: the fields. Alias (`TYPE T : ARRAY[1..3] OF INT`, `TYPE T : INT(0..5)`): one
  /// field, unnamed, whose type (and dimensions) T stands for.
  std::vector<Variable> fields;
  SourceLocation where;
};

// ------------------------------------------------------------------------------ steps, transitions

enum class StepKind {
  Normal,
  MacroStep,  ///< Grafcet macro-step: `expansion` names the chart holding its expansion
  Enclosing,  ///< Grafcet enclosing step: `enclosed` names the partial grafcets it encloses
};

struct Step {
  std::string name;
  bool initial = false;
  StepKind kind = StepKind::Normal;
  std::string expansion;              ///< MacroStep: chart name of the expansion
  std::vector<std::string> enclosed;  ///< Enclosing: chart names enclosed
  /// Grafcet: a step of an enclosed partial grafcet that is activated when its enclosing step
  /// is activated (the step marked `*` in IEC 60848; AGRAFE's `activationLink`).
  bool activation_link = false;
  SourceLocation where;
};

struct Transition {
  std::string name;  ///< may be empty; Grafcet transitions are numbered
  /// Step names in the same chart, >= 1 for IEC 61131-3. A Grafcet source transition (IEC 60848)
  /// has no upstream step and a sink transition no downstream step: these may be empty.
  std::vector<std::string> sources;
  std::vector<std::string> targets;
  ExprPtr guard;                ///< never null (TRUE when absent)
  std::optional<int> priority;  ///< explicit (PRIORITY := n); smaller number = higher priority
  int order = 0;                ///< document order ("left to right") within the chart
  SourceLocation where;
};

// ------------------------------------------------------------------------------------- actions

enum class Qualifier { N, R, S, P, P0, P1, L, D, SD, DS, SL, DL };

std::string_view to_string(Qualifier q);
std::optional<Qualifier> parse_qualifier(std::string_view s);  ///< case-insensitive
bool is_timed(Qualifier q);                                    ///< L D SD DS SL DL

enum class ActionBodyKind {
  Variable,    ///< the action is a Boolean variable: it equals the action's activity
  Statements,  ///< an ST body
  Chart,       ///< a nested SFC: `chart` is the index of its chart in Pou::charts
};

struct Action {
  std::string name;
  ActionBodyKind kind = ActionBodyKind::Statements;
  std::string variable;  ///< kind Variable
  StmtList body;         ///< kind Statements
  int chart = -1;        ///< kind Chart
  SourceLocation where;
  /// The importer could not model the body (an unsupported construct in an exported ST/LD/IL
  /// body); `body` is empty and the semantics must refuse the action rather than run a no-op.
  bool body_unsupported = false;
  /// With body_unsupported: the body as written when it is text ("ST" or "IL" and its text),
  /// so that writers can give it back unchanged; both empty for graphical bodies.
  std::string unsupported_language;
  std::string unsupported_text;
  std::string unsupported_reason;  ///< with body_unsupported: why, for the semantics' error
};

/// A step's action block: (step, action, qualifier [, duration] [, indicator]).
/// For Grafcet continuous actions, the qualifier is N and `condition` is the optional
/// assignment condition.
struct ActionAssociation {
  std::string chart;  ///< chart of the step
  std::string step;
  std::string action;
  Qualifier qualifier = Qualifier::N;
  std::optional<std::int64_t> duration_ms;  ///< timed qualifiers with a literal duration
  std::string duration_variable;            ///< timed qualifiers with a TIME variable
  std::string indicator;
  ExprPtr condition;  ///< Grafcet assignment condition of a continuous action; null = none
  /// A CODESYS/TwinCAT step action (entry, main or exit, read as P1, N, P0), not an IEC action
  /// block: the vendors give it no final call and run it before the IEC actions
  /// (docs/semantics.md 1.4a).
  bool step_action = false;
  SourceLocation where;
};

// ----------------------------------------------------------------------------- Grafcet extras

/// IEC 60848 stored action: `variable := value` on activation of the step, on its
/// deactivation, or on an event (`event` true, evaluated while the step is active).
enum class StoredWhen { Activation, Deactivation, Event };

struct StoredAction {
  std::string chart;
  std::string step;
  StoredWhen when = StoredWhen::Activation;
  ExprPtr event;  ///< StoredWhen::Event: the event expression (usually an edge)
  std::string variable;
  ExprPtr value;  ///< 0/1 for Boolean outputs; an integer expression for internal counters
  SourceLocation where;
};

/// IEC 60848 forcing order G{...} held by a step on a partial grafcet.
enum class ForcingKind {
  Situation,  ///< G{1,5}: force exactly these steps
  Current,    ///< G{*}: freeze in the current situation
  Initial,    ///< G{INIT}: force the initial situation
  Empty,      ///< G{}: force the empty situation
};

struct ForcingOrder {
  std::string chart;   ///< chart of the forcing step
  std::string step;    ///< the step that holds the order
  std::string target;  ///< forced partial grafcet (a chart name)
  ForcingKind kind = ForcingKind::Situation;
  std::vector<std::string> situation;  ///< ForcingKind::Situation: steps of `target`
  SourceLocation where;
};

// ------------------------------------------------------------------------------- charts, POUs

struct Chart {
  std::string name;
  std::string parent_action;  ///< empty for a top-level body / partial grafcet
  /// Grafcet macro-step expansion: its entry step (E) and exit step (S); both empty for any
  /// other chart. The macro-step that owns the expansion names this chart in Step::expansion.
  std::string macro_entry;
  std::string macro_exit;
  std::vector<Step> steps;
  std::vector<Transition> transitions;
  SourceLocation where;
  /// IEC 61131-3 as CODESYS and TwinCAT run it: where a parallel branch of this chart ends in a
  /// jump (the convergence then waits for the other branches only); unknown when none does. The
  /// jump may leave two steps of one sequence active: steps are flags (docs/semantics.md 1.2b),
  /// so the parallel-structure check of validate() is not applied to such a chart.
  SourceLocation parallel_branch_jump;

  const Step* find_step(std::string_view step_name) const;
  int step_index(std::string_view step_name) const;  ///< -1 when absent
};

/// A Function's result is the Output variable named like the function (IEC 61131-3 2.5.1: the
/// name of a function is a variable of its body); the readers declare it.
enum class PouKind { Program, FunctionBlock, Function };

struct Pou {
  std::string name;
  PouKind kind = PouKind::Program;
  std::vector<Variable> variables;
  std::vector<Chart> charts;
  std::vector<Action> actions;
  std::vector<ActionAssociation> associations;
  std::vector<StoredAction> stored_actions;  ///< Grafcet
  std::vector<ForcingOrder> forcing_orders;  ///< Grafcet
  /// The POU's own body (ST, or FBD/LD read as statements), run every cycle before its charts;
  /// a POU without charts is a program whose body is the whole scan cycle.
  StmtList body;
  /// The importer could not model the body (IL, or an unsupported construct): `body` is empty
  /// and the semantics refuses to run the POU rather than run a no-op.
  bool body_unsupported = false;
  std::string unsupported_language;  ///< with body_unsupported: "ST", "IL", "FBD", "LD"
  std::string unsupported_text;      ///< the text (ST, IL) or the element as XML (FBD, LD)
  std::string unsupported_reason;    ///< the importer's first reason, with its location
  SourceLocation where;

  bool has_sfc() const { return !charts.empty(); }
  const Variable* find_variable(std::string_view var_name) const;
  const Action* find_action(std::string_view action_name) const;
  /// Grafcet: the variable a continuous action assigns, the named action's variable, or the
  /// association's own name when it names a variable directly (`X1 -> Y`).
  const std::string& assigned_variable(const ActionAssociation& as) const;
  const Chart* find_chart(std::string_view chart_name) const;
  int chart_index(std::string_view chart_name) const;  ///< -1 when absent
};

struct Project;

/// The vendor whose dialect of IEC 61131-3 a project's file is in (docs/semantics.md 1.4a):
/// Project::vendor, else "twincat" or "codesys" for their PLCopen exports (the fileHeader names
/// the tool) and native files, "siemens" for S7-GRAPH blocks, "rockwell" for L5X files, and ""
/// (plain IEC 61131-3) for anything else.
std::string vendor_of(const Project& project);

struct Project {
  std::string name;
  Dialect dialect = Dialect::Iec61131;
  std::string source_format;  ///< "plcopen-xml", "iec-text", "g7", "agrafe-xmi", ...
  /// The vendor whose dialect the file is in when its format does not say (sfcv's PLCopen
  /// export of a CODESYS project): "codesys", "twincat", ...; empty: from source_format
  /// (model::vendor_of).
  std::string vendor;
  std::vector<Pou> pous;
  /// User data types as read; after model::lower_data_types, kept for reference only.
  std::vector<DataType> data_types;
  /// lower_data_types replaced aggregates by their elements: the writers cannot give the
  /// declarations back as written, so they refuse to print such a project.
  bool data_types_lowered = false;
  SourceLocation where;

  const Pou* find_pou(std::string_view pou_name) const;
};

/// The variables (`x`, `a.b`) that the call `call` in POU `pou` binds to VAR_IN_OUTs of a
/// user function block instance (docs/semantics.md 1.3c) or of a user function called by an
/// assignment or as a statement (1.9.1): the call writes them back.
std::vector<std::string> in_out_bindings(const Project* project, std::string_view pou,
                                         const Stmt& call);

// Counting helpers (sfcv info, tests against the corpus MANIFEST).
/// An action associated with a step that is no action of the POU but one of its BOOL variables
/// is that variable (IEC 61131-3 Boolean action): adds such actions to `pou`.
void add_boolean_variable_actions(Pou& pou);

std::size_t count_steps(const Project& p);
std::size_t count_transitions(const Project& p);

}  // namespace sfcv::model

// The IEC 61131-3 compiler's shared state (internal to sfcv_semantics): one Compiler object
// turns a model::Project into the flat Program of semantics/detail/iec_program.hpp. Its member
// functions live in one file per concept: iec_compile.cpp (POU selection, variables, the driver),
// iec_compile_expr.cpp (expressions), iec_compile_stmt.cpp (statements),
// iec_compile_fb.cpp (standard function block instances: timers, counters, edges),
// iec_compile_instances.cpp (user function block instances), iec_compile_call.cpp and
// iec_compile_function.cpp (standard and user functions) and
// iec_compile_chart.cpp (steps, transitions, actions and their qualifiers).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "semantics/detail/iec_program.hpp"

namespace sfcv::semantics::iec::detail {
using model::ExprKind;
using model::Qualifier;
using model::StandardFb;
using model::TypeKind;

struct Ref {
  /// Instance: a user function block instance; index is its scope (= its Pou).
  enum Kind { Field, Input, FbInst, Instance } kind = Field;
  std::uint32_t index = 0;
  bool is_bool = true;
};

struct PouScope {
  const model::Pou* pou = nullptr;
  std::uint32_t index = 0;
  std::string name;   // the program "Main", or the instance path "Main.Crane"
  std::string alias;  // instances: the path below the program, "Crane" ("" for programs)
  bool instance = false;
  bool function = false;  // a user FUNCTION's body (names its own variables)
  // A called SFC action of an instance (Compiler::make_units): its own chart and action
  // control, on the variables of the instance scope `owner` (every other scope: itself).
  bool unit = false;
  std::uint32_t owner = 0;
  std::map<std::string, Ref> names;              // upper-case variable names
  std::vector<std::uint32_t> chart_ids;          // global chart index per pou chart
  std::map<std::string, std::uint32_t> actions;  // upper name -> global action index
  // Inputs the POU's own code writes: a field holds the program's copy, loaded from the input
  // at the start of the POU's cycle (field, input).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> input_copies;
  // Instances: the type's VAR_IN_OUTs, as declared (bound at each call, docs/semantics.md 1.3c).
  std::vector<std::string> in_outs;
};

enum class VT { Bool, Int };

struct Compiler {
  Compiler(const model::Project& pr, Program& prog, model::Diagnostics& d)
      : project(pr), p(prog), diags(d) {}
  const model::Project& project;
  Program& p;
  model::Diagnostics& diags;
  bool ok = true;
  std::vector<PouScope> scopes;
  std::map<std::string, std::uint32_t> inputs_by_name;
  std::vector<std::uint8_t> field_is_bool;
  std::set<std::string> written;  // "POU|VAR" upper-case: variables some statement assigns
  // VAR_GLOBAL fields by upper-case name: one field per global, shared by every POU and
  // instance that names it (VAR_EXTERNAL, unqualified, or `GVL.x`).
  std::map<std::string, std::uint32_t> global_fields;
  std::uint32_t first_program = 0;  // scopes before it are global variable lists
  std::set<std::string> inlining;   // upper-case actions whose call is being compiled
  // Standard FB calls with `=>` outputs, as the call and its assignments (iec_compile_stmt.cpp);
  // a deque, so that the statements stay where the compiled program saw them.
  std::deque<model::StmtList> expanded_calls;
  int loop_depth = 0;  // loops around the statement being compiled
  std::map<std::uint32_t, model::SourceLocation> omitted_pt;  // FB index -> a call without PT
  std::set<std::uint32_t> called_timers;                      // FB indices of called timers
  std::map<std::uint32_t, model::SourceLocation> zero_pt;     // TON index -> a PT := 0 call
  // Step .T: constants compared with, and nodes to patch once regions are known.
  std::map<std::uint32_t, std::set<std::int64_t>> t_keys;  // step -> keys (2c or 2c+1)
  std::vector<std::uint32_t> t_nodes;
  std::uint32_t polls = 0;  // calls of poll_deadline()

  void error(const model::SourceLocation& where, std::string msg);
  void warning(const model::SourceLocation& where, std::string msg);
  /// Once per step, transition or association compiled: past the run's deadline
  /// (Iec61131Options::deadline), throws LimitReached(Time).
  void poll_deadline();

  std::uint32_t add_field(std::string name, FieldKind kind, std::int64_t lo, std::int64_t hi,
                          std::int64_t init, bool is_bool);

  std::uint32_t add_input(std::string name, model::Type type, bool pseudo);

  // ---------------------------------------- variables no POU of the run writes (1.8)
  /// "SCOPE|VAR" (upper-case scope name, variable): read as inputs. compile() fills it for its
  /// second pass under UnwrittenMode::Free, with the unwritten variables of the first.
  std::set<std::string> free_variables;
  /// A declared variable held in a field: may be unwritten.
  struct Declared {
    std::uint32_t field = 0, scope = 0;
    const model::Variable* var = nullptr;
  };
  std::vector<Declared> declared_fields;
  /// Where the run first reads each field (the scope's name, the place): node() records it
  /// from the context that expr() and stmt() set.
  struct ReadAt {
    std::string scope;
    model::SourceLocation where;
  };
  std::unordered_map<std::uint32_t, ReadAt> first_read;
  ReadAt reading_at;
  void reading(const PouScope& sc, const model::SourceLocation& where) {
    if (!where.known()) return;
    reading_at.scope = sc.name;
    reading_at.where = where;
  }
  /// "POU|VAR": variables read as a constant duration (constant_variable): they keep their
  /// initial value, as sfcv needs constant durations (docs/semantics.md 1.6).
  std::set<std::string> durations;
  /// Upper-case names of the run's inputs (VAR_INPUT, %I): a free variable is not named alike.
  std::set<std::string> input_names;
  std::map<std::string, std::uint32_t> global_inputs;  ///< free VAR_GLOBALs by upper-case name
  static std::string free_key(const std::string& scope, const std::string& var);
  bool is_free(const PouScope& sc, const model::Variable& v) const;
  /// After run(): the declared variables that the run reads and nothing writes, and for each
  /// its key in free_variables.
  std::vector<UnwrittenVariable> unwritten(std::vector<std::string>& keys) const;

  // ---------------------------------------------------------------------- POU selection
  std::vector<const model::Pou*> select();
  /// A global variable list (a PLCopen/TwinCAT GVL read as a PROGRAM with only VAR_GLOBALs).
  static bool is_global_list(const model::Pou& pou);
  /// The field of global `name` (upper-case), if one is declared.
  std::optional<Ref> global_ref(const std::string& upper_name) const;

  // ------------------------------------------------------------------------- variables
  static model::Type value_type(const model::Type& t);

  void collect_written(const model::StmtList& body, const std::string& pou);
  /// The value of `pou`'s variable `name` when nothing can change it, to be read as a
  /// constant (PT of a timer, the duration of a timed qualifier): a VAR or VAR_OUTPUT with its
  /// initial value that no assignment, FOR loop or output binding `=> name` of `pou` writes,
  /// and no write `x.name` anywhere. An input, in/out, external, global or located (`AT %...`)
  /// variable is never constant (its caller, the plant or another POU sets it).
  std::optional<std::int64_t> constant_variable(const model::Pou& pou, const std::string& name);

  void variables(const std::vector<const model::Pou*>& pous);

  void make_fb(std::uint32_t pi, const model::Variable& v);

  // ---------------------------------------------------- user function block instances
  static constexpr int kMaxInstanceDepth = 8;
  /// Creates the scope (and so the Pou) of instance `v` of a user FB inside scope `parent`,
  /// with its own fields, standard FB instances and nested instances. `types`: the FB types
  /// being instantiated around it (recursion).
  void instantiate(std::uint32_t parent, const model::Variable& v, int depth,
                   std::vector<std::string>& types);
  /// The scope that the leading parts of a dotted path name (instances, nested instances, or a
  /// program of the project for `Main.x`); `used` is how many parts it took (0: none).
  std::uint32_t path_scope(const PouScope& sc, const std::vector<std::string>& parts,
                           std::size_t& used) const;
  /// The field of a dotted variable `inst.x`, `a.b.x`, `Main.x` (nullopt after an error).
  std::optional<Ref> dotted(const PouScope& sc, const std::string& path,
                            const model::SourceLocation& where);
  /// `inst(a := x, q => y);`: the input assignments, the Call, the output copies.
  /// `inline_body`: instead of the Call, an instance action's statements (`inst.ACT(a := x);`).
  /// Every name a function block type mentions, in its code and in the types of its
  /// instances, upper-case, each part of a dotted path apart (the VAR_IN_OUT alias check).
  /// The variable a call binds to the function's VAR_IN_OUT `param` (copied back after the
  /// body), or nullopt with an error: unbound, not a variable, or reachable another way.
  std::optional<Ref> function_in_out(
      const PouScope& sc, const model::Expr& call, const model::Pou& f,
      const model::Variable& param, const model::Expr* value, const model::Stmt* binding,
      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& bound);
  const std::set<std::string>& names_mentioned(const model::Pou& type);
  std::map<std::string, std::set<std::string>> mentioned_by_type;
  /// Refuses a call of an action of instance scope `inst` from outside it when its type has a
  /// VAR_IN_OUT (true: refused).
  bool refuse_in_out_action(std::uint32_t inst, const model::Stmt& s);
  /// Refuses `path`, naming VAR_IN_OUT `name` of instance scope `si` from scope `sc` outside
  /// it (true: refused).
  bool refuse_in_out_member(const PouScope& sc, std::uint32_t si, const std::string& name,
                            const std::string& path, const model::SourceLocation& where);
  /// The variable that `value` binds to VAR_IN_OUT `param` of instance scope `inst` in the
  /// call `s` (nullopt after an error); `bound`: the variables bound before it in the call.
  std::optional<Ref> in_out_variable(const PouScope& sc, const model::Stmt& s, std::uint32_t inst,
                                     const std::string& param, const model::Expr& value,
                                     const std::vector<std::pair<std::uint32_t, Ref>>& bound);
  /// What `var` (`x`, `a.b`, an unqualified global) names in scope `sc`; nullopt after an
  /// error (`unknown` when it names nothing).
  std::optional<Ref> variable_ref(const PouScope& sc, const std::string& var,
                                  const model::SourceLocation& where, const std::string& unknown);
  /// The field that `output => var` copies into, in scope `sc` (nullopt after an error).
  std::optional<Ref> output_binding(const PouScope& sc, const std::string& output,
                                    const std::string& var, bool is_bool,
                                    const model::SourceLocation& where);
  /// The `=>` outputs of the assignment being compiled, for the function call that is its
  /// whole right side (Compiler::function_call takes them).
  const model::Stmt* assignment_with_outputs = nullptr;
  const model::Stmt* outputs_taken_by = nullptr;  ///< the last assignment whose outputs a call took
  /// Per user function (upper-case name): its VAR_OUTPUT fields by upper-case name.
  std::map<std::string, std::map<std::string, std::uint32_t>> function_outputs;
  void instance_call(const PouScope& sc, const model::Stmt& s, std::uint32_t inst, Stmt& out,
                     const Block* inline_body = nullptr);
  /// Per instance Pou: the chart state fields a call commits.
  void instance_commits();

  // --------------------------------------- SFC actions called by name (TwinCAT, CODESYS)
  // A function block whose body is not SFC but whose actions are (the TwinCAT idiom: `ST`
  // body, SFC actions `ACT_Init`, `ACT_AutomaticExecute`) runs each SFC action as its own
  // chart, one cycle of it per call: `inst.ACT_Init();` in ST, or a step's association naming
  // `inst.ACT_Init` (the step calls it while the association is active). Each such action is a
  // *unit*: an instance Pou of its own, with the action's chart at top level and a private
  // action control for the actions its steps name, reading and writing the instance's
  // variables (docs/semantics.md 1.3b).
  static bool runs_sfc_actions_as_units(const model::Pou& type);
  /// An FB's SFC action runs as a unit unless the FB's SFC body drives it as a nested chart:
  /// a step of the body (or of a chart nested in it) names it (docs/semantics.md 1.3b).
  static bool is_unit_action(const model::Pou& type, const model::Action& a);
  /// The association of a step of `type`'s SFC body (or of a chart nested in it) that makes
  /// SFC action `action` a nested chart; null when none does.
  static const model::ActionAssociation* driving_association(const model::Pou& type,
                                                             const std::string& action);
  /// Why an SFC action both nested in the body and called by name is refused.
  static constexpr const char* nested_and_called =
      "one chart both evolving as a nested chart while that step is active (1.3) and run "
      "one more cycle at each call by name (1.3b) is not modelled";
  /// The error for a call of SFC action `act` of `type` (`target` as written), which is not a
  /// unit: the body's nested chart, or a program's SFC action.
  std::string sfc_action_call_error(const model::Pou& type, const model::Action& act,
                                    const std::string& target) const;
  /// The type as its instance scope sees it: without the SFC actions (they are units).
  const model::Pou* instance_view(const model::Pou* type);
  /// Creates the unit scopes of instance scope `inst` (after its variables).
  void make_units(std::uint32_t inst, const model::Pou& type);
  /// The unit a call target names from scope `sc` ("ACT", "inst.ACT", "a.b.ACT"), if any.
  std::optional<std::uint32_t> unit_named(const PouScope& sc, const std::string& target) const;
  /// An association naming no action of its scope that a call can run: `inst.ACT` (an action
  /// of an instance) or a unit of the scope's instance. Its action calls it while active.
  bool callable_association(const PouScope& sc, const std::string& action) const;
  /// A unit or instance that calls itself through other calls: a located error.
  void reject_call_cycles();
  std::deque<model::Pou> synthetic_pous;  // instance views and units (stable addresses)
  std::map<const model::Pou*, const model::Pou*> instance_views;
  std::map<std::pair<std::uint32_t, std::string>, std::uint32_t> units;  // (owner, ACTION)

  // ------------------------------------------------------------------- user functions
  /// Upper-case name -> index in Program::functions; nullopt when refused (reported once).
  std::map<std::string, std::optional<std::uint32_t>> functions;
  std::vector<const model::Pou*> calling;  // functions whose bodies are being compiled
  /// Functions calling functions: deeper chains are refused (they would only deepen the
  /// compiler's and the machine's recursion).
  static constexpr std::size_t kMaxFunctionDepth = 32;
  /// The compiled function `f` (compiled at its first call, at `call`), or nullopt after an
  /// error: recursion, or a part of the function sfcv does not model.
  std::optional<std::uint32_t> function(const model::Pou& f, const model::SourceLocation& call);
  /// `f(x, y)` or `f(a := x, b := y)` in an expression: an Op::Call node.
  std::uint32_t function_call(const PouScope& sc, const model::Expr& e, const model::Pou& f,
                              int context, VT& type);

  // ---------------------------------------------------------------------- expressions
  std::uint32_t node(Node n, std::vector<std::uint32_t> kids = {});
  std::uint32_t constant(std::int64_t k);

  static std::optional<std::int64_t> literal(const model::Expr& e);

  // A step named `name` in the POU, preferring chart `context` (-1: none).
  std::optional<std::uint32_t> find_step(const PouScope& sc, std::string_view name, int context,
                                         const model::SourceLocation& where, bool report);

  static Op op_of(ExprKind k);
  static Op flip(Op c);

  bool is_step_t(const PouScope& sc, const model::Expr& e, int context);

  std::uint32_t compare(const PouScope& sc, const model::Expr& e, int context, VT& type);

  // IEC 61131-3 (2.2.1): Boolean data may be written as the integer literals 0 and 1
  // (Beremiz exports `ORANGE_LIGHT := 1;`). Called only where a BOOL is expected.
  static VT bool_if_literal(const model::Expr& e, VT t);

  std::uint32_t expr(const PouScope& sc, const model::Expr& e, int context, VT& type);

  std::uint32_t member(const PouScope& sc, const model::Expr& e, int context, VT& type);
  /// The declared range of the integer that node `n` reads (a field, an input, a function's
  /// result); nullopt for any other node.
  std::optional<std::pair<std::int64_t, std::int64_t>> int_range(std::uint32_t n) const;
  /// `NOT x` on an integer `x` compiled as node `operand` (iec_compile_expr.cpp).
  std::uint32_t integer_not(const model::Expr& e, std::uint32_t operand, VT& type);

  // Standard functions, bit strings (iec_compile_call.cpp).
  std::uint32_t call(const PouScope& sc, const model::Expr& e, int context, VT& type);
  /// Bits of a bit-string expression (8, 16, 32); 0 for an integer literal; -1 for anything
  /// else (a signed integer, a BOOL, ...).
  int bit_width(const PouScope& sc, const model::Expr& e) const;
  std::uint32_t bitwise(const PouScope& sc, const model::Expr& e, int context, VT& type);
  std::uint32_t bit_access(const PouScope& sc, const model::Expr& e, int context, VT& type);
  static bool is_bit_access(const model::Expr& e);

  std::uint32_t bool_expr(const PouScope& sc, const model::ExprPtr& e, int context,
                          const model::SourceLocation& where, const char* what);

  // ------------------------------------------------------------------------ statements
  Block block(const PouScope& sc, const model::StmtList& body,
              const std::vector<std::pair<std::uint32_t, std::uint32_t>>& input_copies = {});

  void function_statement(const PouScope& sc, const model::Stmt& s, Stmt& out);
  std::uint32_t stmt(const PouScope& sc, const model::Stmt& s);
  /// FOR, WHILE, REPEAT into an SOp::Loop (iec_compile_stmt.cpp).
  void loop(const PouScope& sc, const model::Stmt& s, Stmt& out);

  /// The action of the POU a call statement `NAME();` names (no variable of that name).
  const model::Action* called_action(const PouScope& sc, const model::Stmt& s) const;

  void fb_call(const PouScope& sc, const model::Stmt& s, Stmt& out);

  /// Timers some call leaves without PT: sound only when no call gives a PT other than T#0s
  /// (then PT is T#0s throughout); timers only called with IN = FALSE get T#0s too.
  void finish_timers();

  std::int32_t make_timer(const std::string& field_name, std::int64_t d,
                          const std::string& timeout_name);

  /// Discrete time: a field holding ET at the last call for every timer instance whose ET some
  /// expression reads (after every expression is compiled).
  void timer_snapshots();

  /// Reads of a timer's PT (both time modes) and of its ET in abstract time: placeholder nodes
  /// that timer_reads() fills once every call is compiled (iec_compile_timer_reads.cpp).
  struct TimerRead {
    std::uint32_t node = 0, fb = 0;
    bool et = false;
    model::SourceLocation where;
  };
  std::vector<TimerRead> timer_reads_pending;
  bool timer_reads_done = false;
  std::uint32_t timer_read(std::uint32_t fb, bool et, const model::Expr& e);
  /// A field `<fb>.PT` holding the PT of the last call (T#0s before any), written by every call
  /// that gives one, and the abstract-time ET of docs/semantics.md 1.6 (before orders()).
  void timer_reads();

  // ----------------------------------------------------------------- charts and actions
  void structure();

  std::uint32_t add_action(PouScope& sc, const std::string& name, model::ActionBodyKind kind,
                           const model::SourceLocation& where);

  void actions_and_transitions();

  void orders();
  /// The vendor dialect's final calls (Action::final_call), or under another dialect a warning
  /// that a CODESYS/TwinCAT file's IEC actions lose theirs (docs/semantics.md 1.4a).
  void final_calls();
  /// Moves the step associations of IEC action `action` to a twin of it (same body).
  void step_action_twin(std::uint32_t action);
  /// ActionOrder::Vendor: step actions (exit, entry, main, by step), then IEC actions by name.
  void vendor_order(std::vector<std::uint32_t>& order) const;
  /// A partial action order (ActionOrder::Partial, Unordered) on one POU: base exec_order and
  /// the groups whose order a pseudo-input chooses (iec_compile_order.cpp). `pair_used` marks
  /// the user's pairs this POU's actions name (1 both, 2 one).
  void action_order(PouScope& sc, std::vector<std::uint32_t>& pair_used);

  void step_timers();

  void step_observables();
  void name_boolean_action_activities();

  /// CODESYS/TwinCAT implicit SFC flags: SFCInit and SFCReset attached to their compiled Pou,
  /// the other vendor flags refused (iec_compile_flags.cpp).
  void sfc_flags();

  /// Grafcet-only content and duplicates the IEC semantics would otherwise silently merge.
  void reject_foreign(const std::vector<const model::Pou*>& pous);

  bool run();
};

}  // namespace sfcv::semantics::iec::detail

#pragma once
// Internal to the IEC 61131-3 semantics: the chart compiled into flat arrays (expressions as
// node pools, statements as blocks), and the Machine that runs one scan cycle on them.
// Every piece of state is a field of the StateLayout; the machine keeps one int64 per field.

#include <cstdint>
#include <string>
#include <vector>

#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/input_condition.hpp"
#include "semantics/options.hpp"
#include "semantics/state_layout.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics::iec {

inline constexpr std::int32_t kNone = -1;

// ------------------------------------------------------------------------------ expressions

enum class Op : std::uint8_t {
  Const,         ///< k
  Field,         ///< value of field a (as the cycle's actions left it)
  Input,         ///< Boolean input a, or an integer input read as a value (enumerated)
  InputCmp,      ///< integer input a compared (cmp) with constant k: splits the input's interval
  InputCmpExpr,  ///< integer input a compared (cmp) with the value of child 0 (evaluated first)
  StepX,         ///< activity of step a in the current configuration
  StepT,         ///< discrete time: .T of step a in ms
  StepTCmp,      ///< abstract time: step a's .T region >= k (after `negate`)
  TimerQ,        ///< Q of timer FB a (its timer state)
  TimerET,       ///< discrete time: ET of timer FB a in ms
  Not,
  Neg,
  And,
  Or,
  Xor,
  Add,
  Sub,
  Mul,
  Div,
  Mod,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  Ite,         ///< children: condition, then, else (only the chosen branch is evaluated)
  RangeCheck,  ///< children: value, lo, hi (constants): the value, or a range error outside
  BitAnd,      ///< bit strings (unsigned, k bits wide): n-ary
  BitOr,
  BitXor,
  BitNot,  ///< k-bit complement of child 0
  Shl,     ///< child 0 << child 1, truncated to k bits; shifts >= k give 0
  Shr,
  Rol,  ///< rotations of a k-bit value by child 1 (mod k)
  Ror,
  Call,  ///< user FUNCTION a (Program::functions) on the children, one per VAR_INPUT; k > 0:
         ///< then Program::call_output_copies[k - 1] (`y := F(x, q => z)`)
};

/// The most iterations a loop may run in one execution of its statement (FOR, WHILE, REPEAT):
/// one more is a run-time range error, in the machine and the circuit alike (docs/semantics.md).
inline constexpr std::int64_t kMaxLoopIterations = 1000;

struct Node {
  Op op = Op::Const;
  Op cmp = Op::Eq;      ///< InputCmp
  bool negate = false;  ///< StepTCmp
  std::uint32_t a = 0;
  std::uint32_t first = 0;  ///< children in Program::kids
  std::uint32_t count = 0;
  std::int64_t k = 0;
};

// ------------------------------------------------------------------------------- statements

/// Call: one cycle of the user function block instance whose Pou is `target` (the inputs are
/// assigned before it and the `=>` outputs copied after it by ordinary Assign statements).
/// Eval: `expr` evaluated for its effects only, its value dropped (a user function called as a
/// statement, `F(x := a, q => z);`: the `=>` copies of its Call node are the effect).
enum class SOp : std::uint8_t {
  Assign,
  If,
  Case,
  FbCall,
  Loop,
  Exit,
  Continue,
  Return,
  Call,
  Eval
};

/// How control leaves a block: normally, or by EXIT, CONTINUE or RETURN.
enum class Flow : std::uint8_t { Normal, Exit, Continue, Return };

struct Block {
  std::uint32_t first = 0, count = 0;  ///< in Program::block_items
};

struct IfArm {
  std::uint32_t cond = 0;
  Block body;
};

struct CaseArm {
  std::uint32_t label_first = 0, label_count = 0;  ///< in Program::case_labels
  Block body;
};

struct Stmt {
  SOp op = SOp::Assign;
  std::uint32_t target = 0;  ///< Assign: field; FbCall: FB index; Call: Pou index
  std::uint32_t expr = 0;    ///< Assign: value; Case: selector
  std::uint32_t arm_first = 0, arm_count = 0;
  Block else_body;
  std::int32_t arg1 = kNone, arg2 = kNone, arg3 = kNone;  ///< FbCall: expression nodes
  std::string where;                                      ///< for range errors
  // Loop: `init` once, then while `expr` holds (checked after `body` when test_after, where
  // the loop ends when it holds: REPEAT ... UNTIL): body, then `step` (FOR's increment).
  Block init, body, step;
  bool test_after = false;
  /// FbCall of a TON with `PT := T#0ms` while other calls give a positive PT (TwinCAT xPPU):
  /// this call's Q is IN, the timer itself runs on as the other calls see it.
  bool pt_zero = false;
  /// FbCall of a timer: the PT this call gives (kPtNotGiven, or kPtNotConstant for the ignored
  /// PT of a TON called with IN := FALSE), for a program that reads the instance's PT.
  std::int64_t pt_ms = -1;
  static constexpr std::int64_t kPtNotGiven = -1, kPtNotConstant = -2;
};

/// A user FUNCTION written in ST (IEC 61131-3 2.5.1). Its variables are fields that hold their
/// initial values between calls (so they add no states): a call sets them to their initial
/// values, assigns the evaluated arguments to `inputs`, runs `body` (RETURN ends it) and reads
/// `result`, the variable named like the function; then they are reset.
struct Function {
  std::string name;
  std::vector<std::uint32_t> inputs;  ///< fields of the VAR_INPUTs, in declaration order
  std::vector<std::uint32_t> fields;  ///< every field of the function (inputs, temporaries)
  std::uint32_t result = 0;           ///< field
  Block body;
  std::string where;  ///< for range errors on the inputs
};

// ------------------------------------------------------------------------------------ timers

/// A timer in one field: 0 idle; abstract time 1 running, 2 expired; discrete time 1 + elapsed
/// cycles, saturated at 1 + ceil(d / cycle).
/// A clocked timer (a TON, TOF or TP instance) reads the cycle clock (docs/semantics.md §1.6):
/// in discrete time the cycle ages it before any code runs, whether or not it is called
/// (Machine::advance_clock), and its calls only start, stop and read it; in abstract time it
/// cannot expire in the cycle it started, however often it is called. So does a qualifier's
/// timer in a user FB instance; in a program it is aged by phase 4, once per cycle.
struct Timer {
  std::uint32_t field = 0;
  std::int64_t duration_ms = 0;
  std::int32_t timeout_input = kNone;  ///< abstract time
  std::int64_t max_value = 2;
  bool clocked = false;
};

struct Fb {
  std::string name;
  model::StandardFb kind = model::StandardFb::None;
  std::uint32_t pou = 0;
  std::int32_t q = kNone;      ///< Q / Q1 field
  std::int32_t mem = kNone;    ///< edge memory (R_TRIG, F_TRIG, CTU, CTD, TP's last IN)
  std::int32_t cv = kNone;     ///< counters
  std::int32_t timer = kNone;  ///< index into Program::timers
  std::int64_t pt_ms = -1;     ///< timers: constant PT
  bool pt_set = false;
  /// Discrete time, timers whose ET is read: the timer's value at the last call (its field's
  /// encoding), since ET changes only when the instance is called while its field ages.
  std::int32_t et = kNone;
};

// --------------------------------------------------------------------------- chart structure

struct Step {
  std::string name;  ///< "POU.STEP" or "POU.ACTION.STEP"
  std::string short_name;
  std::uint32_t chart = 0;
  std::uint32_t ready = 0;  ///< field
  bool initial = false;
  // .T: discrete: a counter of cycles in a field; abstract: a region index in a field.
  std::int32_t t_field = kNone;
  std::int64_t t_max = 0;                ///< discrete: saturation (cycles)
  std::vector<std::int64_t> thresholds;  ///< abstract: sorted region bounds (2*c, or 2*c+1 for c+)
  std::int32_t elapse_input = kNone;     ///< abstract
  /// A step of a user FB instance: its .T reads the cycle clock (docs/semantics.md §1.6), as
  /// TON does: discrete time ages it before any code runs while the step is active, whether or
  /// not the instance is called; a second call in the cycle does not age it again.
  bool clocked = false;
};

struct Transition {
  std::uint32_t chart = 0;
  std::vector<std::uint32_t> sources, targets;  ///< steps
  std::uint32_t guard = 0;
  std::int64_t rank = 0;    ///< priority key within the chart
  std::uint32_t index = 0;  ///< in TransitionSystem::transitions()
};

struct AltGroup {  ///< PriorityMode::None: the alternatives leaving one step
  std::uint32_t step = 0;
  std::vector<std::uint32_t> transitions;  ///< document order
  std::uint32_t choice_input = 0;
};

struct Chart {
  std::uint32_t pou = 0;
  std::int32_t parent_action = kNone;
  std::vector<std::uint32_t> steps;
  std::vector<std::uint32_t> ordered;  ///< transitions by priority (Standard) / order
  std::vector<AltGroup> groups;        ///< PriorityMode::None
  std::vector<std::uint32_t> singles;  ///< PriorityMode::None: not in a group
};

struct Assoc {
  std::uint32_t step = 0, action = 0;
  model::Qualifier q = model::Qualifier::N;
  std::int32_t timer = kNone;  ///< timed qualifiers
  std::int32_t latch = kNone;  ///< SD, SL: field
  bool step_action = false;    ///< a CODESYS/TwinCAT entry, main or exit action's
};

struct Action {
  std::string name;  ///< "POU.ACTION"
  std::uint32_t pou = 0;
  std::uint32_t active = 0;     ///< field
  std::int32_t stored = kNone;  ///< field
  model::ActionBodyKind kind = model::ActionBodyKind::Statements;
  std::int32_t variable = kNone;  ///< field of the Boolean variable
  /// VendorDialect Codesys/Twincat, an IEC action with a body: field "active in the last
  /// configuration and not in this one", the cycle of its final call (docs/semantics.md 1.4a)
  std::int32_t final_call = kNone;
  model::SourceLocation where;  ///< the action's declaration
  Block body;
  std::vector<std::uint32_t> assocs;
};

/// Actions of one POU that write a common variable (a connected group) and whose order the
/// action order leaves open (docs/semantics.md §1.2a). They run at `slots`, the positions of
/// exec_order they hold in the base order; the pseudo-input `choice_input` (`order:...`, an
/// enumeration naming each order) picks which of `orders` fills the slots in this cycle.
/// Members not active are skipped, so the machine decides only when two are active.
struct OrderGroup {
  std::vector<std::uint32_t> members;              ///< actions, in the base order
  std::vector<std::uint32_t> slots;                ///< positions in Pou::exec_order, ascending
  std::vector<std::vector<std::uint32_t>> orders;  ///< admissible orders; [0] the base order
  std::uint32_t choice_input = 0;
};

struct Pou {
  std::string name;  ///< a program "Main", or an instance of a user FB "Main.Crane"
  std::string type;  ///< the POU of the project it runs ("Main", "Crane")
  /// A called SFC action of an instance, run as its own unit ("Main.Crane.ACT_Init"): its
  /// steps, and its copies of the actions they name, are named under the action; `owner` is
  /// the instance's Pou.
  bool unit = false;
  std::uint32_t owner = 0;
  /// An instance of a user function block: the cycle does not run it; a Call statement of its
  /// caller does (each call is one cycle of the instance: body, chart evolution, actions).
  bool instance = false;
  /// Instances: the chart state fields (step readiness and .T, action activity and memories)
  /// that a call commits (cur := nxt), so that a second call in the same cycle evolves from
  /// the situation the first one left and later code reads the new activity.
  std::vector<std::uint32_t> commit;
  Block body;
  std::vector<std::uint32_t> charts;
  std::vector<std::uint32_t> exec_order;  ///< actions, in execution order
  std::vector<OrderGroup> order_groups;   ///< empty under a total action order
  /// Per position of exec_order: the group whose slot it is and the slot's index, or kNone.
  std::vector<std::int32_t> exec_group, exec_slot;
  std::vector<std::uint32_t> topo_order;  ///< actions, parents before nested ones
  /// CODESYS/TwinCAT implicit flags (nodes, read after the body): while TRUE, chart_fields take
  /// their initial values; under SFCInit the charts then neither run actions nor evolve.
  std::int32_t sfc_init = kNone, sfc_reset = kNone;
  std::vector<std::uint32_t> chart_fields;
};

struct ObservableRef {
  ObservableKind kind = ObservableKind::Variable;
  std::uint32_t a = 0;  ///< Step: step index; Action: action index; Variable: field
};

struct Program {
  Iec61131Options options;
  /// CODESYS's or TwinCAT's dialect (docs/semantics.md 1.4a): final calls, and a Boolean action
  /// writes its variable only while it runs and when it stops.
  bool vendor_final_calls() const {
    return options.dialect == VendorDialect::Codesys || options.dialect == VendorDialect::Twincat;
  }
  StateLayout layout;
  std::vector<std::int64_t> initial;  ///< per field
  std::vector<InputVariable> inputs;
  std::vector<Observable> observables;
  std::vector<ObservableRef> observable_refs;
  std::vector<TransitionInfo> transition_infos;

  std::vector<Node> nodes;
  std::vector<std::uint32_t> kids;
  std::vector<Stmt> stmts;
  std::vector<std::uint32_t> block_items;
  std::vector<IfArm> if_arms;
  std::vector<CaseArm> case_arms;
  std::vector<model::CaseLabel> case_labels;

  std::vector<Timer> timers;
  std::vector<Fb> fbs;
  std::vector<Step> steps;
  std::vector<Transition> transitions;
  std::vector<Chart> charts;
  std::vector<Assoc> assocs;
  std::vector<Action> actions;
  std::vector<Pou> pous;
  std::vector<Function> functions;
  /// Per call binding VAR_OUTPUTs with `=>`: (the function's output field, the caller's
  /// field), copied after the body, before the function's fields are reset.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> call_output_copies;
  std::vector<std::uint32_t> assumptions;        ///< nodes
  std::vector<std::int64_t> field_lo, field_hi;  ///< value range per field (range errors)
  std::vector<std::string> field_names;
  bool has_instances = false;
  /// The variables the run reads and no POU of it writes (inputs under UnwrittenMode::Free).
  std::vector<UnwrittenVariable> unwritten;
};

/// Compiles; returns false with Error diagnostics when something cannot be modelled faithfully.
bool compile(const model::Project& project, const Iec61131Options& options, Program& program,
             model::Diagnostics& diagnostics);

// ---------------------------------------------------------------------------------- machine

/// A range error (integer overflow, division by zero, out-of-range assignment): the run stops.
struct RangeAbort {
  const char* what;
  const std::string* where;
};

/// One decision on an input: which of `n` alternatives this leaf takes.
struct Decision {
  std::uint32_t input = 0;
  std::uint32_t alt = 0, n = 0;
};

class Machine {
 public:
  explicit Machine(const Program& p);

  /// Loads the current configuration.
  void load(StateView state);
  /// Runs one cycle under the decisions of the trail (extending it when the run reads an input
  /// not decided yet). Returns false when the assumptions exclude this leaf.
  bool run();
  /// Moves the trail to the next leaf; false when every leaf was visited.
  bool next_leaf();
  void reset_trail() { trail_.clear(); }
  /// The cube of the last run: inputs it constrained.
  void cube(InputCube& out) const;
  void pack(MutableStateView out) const;
  const std::vector<std::uint32_t>& fired() const { return fired_; }

  /// Simulation: runs with every input fixed (no decisions); false when an assumption fails.
  bool run_fixed(const std::vector<std::int64_t>& valuation);
  /// Writes the initial configuration.
  void initial(MutableStateView out);

  // Used by the evaluator.
  std::int64_t eval(std::uint32_t node);
  bool step_active_cur(std::uint32_t step) const;

 private:
  std::uint32_t decide(std::uint32_t input, std::uint32_t n);
  std::int64_t read_input(std::uint32_t input);
  bool input_cmp(std::uint32_t input, Op cmp, std::int64_t k);
  void touch(std::uint32_t input, std::int64_t lo, std::int64_t hi);
  std::int64_t arith(Op op, std::int64_t x, std::int64_t y) const;

  std::int64_t bit_op(const Node& n, const std::uint32_t* kid);
  std::int64_t call_function(const Node& n, const std::uint32_t* kid);
  Flow exec_block(Block b);
  Flow exec_loop(const Stmt& s);
  Flow exec_stmt(const Stmt& s);
  void fb_call(const Stmt& s);
  void assign(std::uint32_t field, std::int64_t v, const std::string& where);
  std::int64_t timer_next(const Timer& t, bool run, bool restart);
  bool timer_expired(const Timer& t, std::int64_t v) const;
  /// A new cycle's clock: ages every running clocked timer by one cycle (discrete time), forgets
  /// which started in the last cycle (abstract time).
  void advance_clock();
  /// After a call of a timer whose ET is read: ET now shows the call's reading of the clock.
  void snapshot_et(const Fb& fb, const Timer& t) {
    if (fb.et != kNone) nxt_[static_cast<std::uint32_t>(fb.et)] = nxt_[t.field];
  }
  /// Discrete time: a clocked step's .T one cycle older if the step was active (reads cur_).
  void age_step(std::uint32_t step);

  void cycle_pou(const Pou& pou);
  /// Phase 2 under a partial action order: each group's members in the order its input picks.
  void run_ordered_actions(const Pou& pou);
  std::uint32_t order_of(const OrderGroup& g);
  /// SFCInit/SFCReset read after the body: restores the POU's chart fields; true under SFCInit.
  bool sfc_flags(const Pou& pou);
  void initial_configuration();
  void call_instance(const Pou& pou);
  void fire_chart(const Chart& c);
  void fire(const Transition& t);
  void update_pou(const Pou& pou);
  bool chart_active_cur(std::uint32_t chart) const;
  bool step_active_next(std::uint32_t step) const;

  const Program& p_;
  std::vector<std::int64_t> cur_, nxt_;
  std::vector<std::int64_t> in_lo_, in_hi_;
  std::vector<std::uint32_t> touched_;
  std::vector<Decision> trail_;
  std::size_t pos_ = 0;
  bool fixed_ = false;
  std::vector<std::uint8_t> consumed_, entered_, left_;  ///< per step, this cycle
  std::vector<std::uint32_t> fired_;
  std::vector<std::uint32_t> enabled_scratch_;
  std::vector<std::uint8_t> reset_;           ///< per action
  std::vector<std::uint32_t> clocked_;        ///< timers that read the cycle clock
  std::vector<std::uint8_t> started_;         ///< per timer: started in this cycle (abstract time)
  std::vector<std::uint32_t> clocked_steps_;  ///< steps whose .T reads the cycle clock
  std::vector<std::uint8_t> step_started_;    ///< per step: entered in this cycle (abstract time)
  // SFCInit/SFCReset: the initial configuration they restore, and the loaded state (a flag
  // rewrites cur_ within a run; the next leaf starts again from the loaded state).
  bool has_flags_ = false, cur_dirty_ = false;
  std::vector<std::int64_t> reset_values_, loaded_;
};

}  // namespace sfcv::semantics::iec

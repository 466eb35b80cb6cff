#pragma once
// Internal: the compiled Grafcet model and the GrafcetSystem class (make_grafcet_system returns
// it). Shared with grafcet_circuit.cpp, which builds the micro-step circuit from the same model.

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/options.hpp"
#include "semantics/state_layout.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics::grafcet {

using model::ExprKind;

// ------------------------------------------------------------------------ compiled expressions

enum class Op : std::uint8_t {
  Const,
  Input,
  Step,
  Var,
  Delay,
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
  Rise,
  Fall,
};

/// An expression whose names are resolved to inputs, steps, memory fields and delays.
struct CExpr {
  Op op = Op::Const;
  std::int32_t ref = 0;
  std::int64_t value = 0;
  std::vector<CExpr> args;
};

/// Three-valued: unknown when it depends on an input the current partial valuation leaves free.
struct Val {
  bool known = true;
  std::int64_t v = 0;
};

/// A partial input valuation: val[i] is 0/1 for Boolean and pseudo inputs, the region index for
/// integer inputs.
struct Partial {
  std::vector<std::int64_t> val;
  std::vector<char> known;
};

struct GStep {
  std::string name;
  int chart = -1;
  model::StepKind kind = model::StepKind::Normal;
  bool initial = false;
  bool linked = false;            ///< IEC 60848 activation link (`*`, model::Step::activation_link)
  int field = -1;                 ///< -1 for a macro-step (derived activity)
  int expansion = -1;             ///< macro-step: chart id
  std::vector<int> enclosed;      ///< enclosing step: chart ids
  int entry = -1, exit = -1;      ///< macro-step: steps of the expansion
  std::vector<int> derived_from;  ///< macro-step: the fields whose OR is its activity
};

struct GChart {
  std::string name;
  std::string pou;
  std::vector<int> steps;
  bool top_level = true;     ///< neither enclosed nor an expansion
  bool has_linked = false;   ///< some step carries the activation link
  bool has_initial = false;  ///< some step is initial-marked
  /// Macro-step expansion: the entry and exit steps the file marks (model::Chart::macro_entry,
  /// macro_exit), empty when unmarked.
  std::string macro_entry, macro_exit;
};

struct GTrans {
  std::vector<int> need;  ///< fields that must be active (and are deactivated)
  std::vector<int> act;   ///< fields activated
  CExpr guard;
  int chart = -1;
};

struct GStored {
  int step = -1;
  model::StoredWhen when = model::StoredWhen::Activation;
  CExpr event;
  int var = -1;  ///< index into vars_
  CExpr value;
};

struct GForce {
  int step = -1;
  int chart = -1;
  model::ForcingKind kind = model::ForcingKind::Situation;
  std::vector<int> situation;  ///< step ids
};

struct GVar {
  std::string name;
  int field = -1;  ///< the value; when both kinds write it, the continuous assignation
  model::Type type;
  bool continuous = false;  ///< written by continuous actions
  bool stored = false;      ///< written by stored actions
  int memory_field = -1;    ///< both kinds: the stored value (docs/semantics.md 2.7)

  bool mixed() const { return continuous && stored; }
  /// The field stored actions write.
  int stored_field() const { return mixed() ? memory_field : field; }
};

struct GContinuous {
  int step = -1;
  int var = -1;
  bool has_condition = false;
  CExpr condition;
};

/// Largest range of an integer input whose exact value the system keeps (docs/semantics.md 2.9).
inline constexpr std::int64_t kMaxExactInputValues = 1024;

struct GInput {
  std::string name;
  model::Type type;
  std::vector<std::int64_t> thresholds;  ///< integer: the region boundaries
  std::vector<std::int64_t> region_lo;   ///< integer: first value of each region
  /// Integer, compared with a non-constant or used in arithmetic: one region per value (its
  /// value is then exact, not the region's representative).
  bool exact = false;
  bool edge = false;  ///< read under an edge
  int order = 0;      ///< declaration order (undeclared: after, by first use)
  bool pseudo = false;
  int delay = -1;  ///< pseudo: the delay it elapses
  int field = -1;  ///< InputMemory field, -1 when not stored

  std::int64_t regions() const {
    return type.kind == model::TypeKind::Int ? static_cast<std::int64_t>(region_lo.size()) : 2;
  }
  std::int64_t region_hi(std::int64_t r) const {
    return r + 1 < regions() ? region_lo[static_cast<std::size_t>(r + 1)] - 1 : type.hi;
  }
};

struct GDelay {
  CExpr expr;
  model::ExprPtr source;
  std::int64_t t1 = 0, t2 = 0;
  int field = -1;
  int pseudo = -1;
};

enum class ObsRef { Step, Variable, Input };
struct ObsInfo {
  ObsRef ref = ObsRef::Variable;
  int index = 0;  ///< into steps_, vars_ or gin_
};

inline bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

/// Step names in the usual order: numbers by value, then the others alphabetically.
inline bool numeric_less(const std::string& a, const std::string& b) {
  const bool da = all_digits(a), db = all_digits(b);
  if (da && db && a.size() != b.size()) return a.size() < b.size();
  if (da != db) return da;
  return a < b;
}

// ------------------------------------------------------------------------------- the system

class GrafcetSystem final : public TransitionSystem {
 public:
  GrafcetSystem(const model::Project& project, const GrafcetOptions& options,
                model::Diagnostics& diagnostics)
      : options_(options), diags_(diagnostics) {
    build(project);
  }

  bool ok() const { return ok_; }

  SemanticsKind kind() const override { return SemanticsKind::Grafcet; }
  const StateLayout& layout() const override { return layout_; }
  const std::vector<InputVariable>& inputs() const override { return input_vars_; }
  const std::vector<Observable>& observables() const override { return observables_; }
  const std::vector<TransitionInfo>& transitions() const override { return trans_info_; }
  std::vector<MixedVariable> mixed_variables() const override {
    std::vector<MixedVariable> out;
    for (const auto& v : vars_)
      if (v.mixed())
        out.push_back({v.name, static_cast<std::uint32_t>(v.field),
                       static_cast<std::uint32_t>(v.memory_field)});
    return out;
  }

  void initial_states(SuccessorSink& sink) const override;
  std::optional<double> estimate_initial_states() const override;
  void successors(StateView state, SuccessorSink& sink) const override;
  std::int64_t observe(StateView state, std::uint32_t index) const override;
  std::string describe(StateView state) const override;

 private:
  friend class CircuitBuilder;
  // ---- compilation (grafcet_build.cpp: build runs one function per group of IEC 60848 rules)
  void build(const model::Project& project);
  void build_charts(const model::Project& project);
  void build_enclosures_and_expansions(const model::Project& project);
  void build_expansion_entries_and_exits();
  void build_step_fields();
  void build_macro_step_activity();
  void build_variables(const model::Project& project);
  void build_variable_fields();
  void build_transitions(const model::Pou& pou, const model::Chart& chart, int chart_id);
  /// Once per step and transition built: past GrafcetOptions::deadline, throws
  /// LimitReached(Time) (a chart of a million steps takes seconds to build).
  void poll_build_deadline();
  int step_in(const model::Pou& pou, const std::string& chart, const std::string& step,
              const model::SourceLocation& where);
  void build_stored_actions(const model::Pou& pou);
  void build_continuous_actions(const model::Pou& pou);
  void build_forcing_orders(const model::Pou& pou);
  void build_inputs_and_delays();
  void build_observables(const model::Project& project);
  void build_initial_situation(const model::Project& project);
  void error(const model::SourceLocation& where, std::string message) {
    diags_.push_back({model::Severity::Error, where, std::move(message)});
    ok_ = false;
  }
  int find_step(const std::string& pou, std::string_view name) const;
  int find_chart(const std::string& pou, std::string_view name) const;
  int steps_named(std::string_view name) const;
  int input_index(const model::Pou& pou, const std::string& name);
  bool compile(const model::Pou& pou, const model::Expr& e, CExpr& out, bool under_edge);
  /// compile() then checks that integer inputs are only compared with constants.
  bool compile_top(const model::Pou& pou, const model::Expr& e, CExpr& out);
  bool int_inputs_ok(const CExpr& e, const model::Expr& where);
  bool constant_value(const model::Expr& e, std::int64_t& v) const;
  void finish_inputs();

  // ---- evaluation
  struct Ctx {
    StateView cur;
    const Partial* in;
    StateView prev;
    const Partial* prev_in;
    mutable int wanted = -1;  ///< first free input met
  };
  bool active(StateView s, int step) const;
  /// Variable `var`'s value: its field, or either field when both kinds of action write it.
  std::int64_t value_of(StateView s, int var) const;
  Val eval(const CExpr& e, const Ctx& c) const;
  Partial inputs_of(StateView s) const;
  /// The region (Partial::val) of input `input` that holds `value`.
  std::int64_t region_of(std::size_t input, std::int64_t value) const;
  InputCube cube_of(const Partial& p) const;

  enum class Status { Stable, Split, Anomaly };
  struct Result {
    std::vector<StateWord> target;
    std::vector<std::uint32_t> fired;
    std::vector<std::uint32_t> entered;  ///< Successor::entered
    int split = -1;
    Anomaly anomaly;
  };
  Status evolve(StateView source, const Partial& v, bool initial, Result& r) const;
  /// The initial situation of `chart` (docs/semantics.md 2.2): its initial steps; an enclosing
  /// step among them has its enclosed grafcets take their initial steps (linked ones when they
  /// have none), recursively.
  void init_chart(std::vector<StateWord>& s, int chart) const;
  /// Activation of an enclosing step (2.12): each enclosed grafcet takes its activation-linked
  /// steps (its initial steps when it has none), recursively for enclosing steps among them.
  void activate_enclosed(std::vector<StateWord>& s, int enclosing_step) const;
  /// The steps an enclosed chart takes when its enclosing step is activated, or at start.
  bool enters_at(int step, bool at_start) const;
  /// Deactivates every step of `chart` and of its macro-step expansions; with `enclosed`, of
  /// the grafcets its enclosing steps enclose too.
  void clear_chart(std::vector<StateWord>& s, int chart, bool enclosed = true) const;
  /// Sets step `step` active (a macro-step: its entry step); returns the step whose bit was set.
  int set_active(std::vector<StateWord>& s, int step) const;
  /// `leaves` counts the evolutions computed for one state (the engine's width bound reads it
  /// through SuccessorSink::valuations); null for the initial situations.
  void explore(StateView source, Partial start, bool initial, SuccessorSink& sink,
               std::uint64_t* leaves) const;
  void emit(StateView source, const Partial& v, const Result& r, SuccessorSink& sink) const;

  GrafcetOptions options_;
  model::Diagnostics& diags_;
  bool ok_ = true;
  std::uint32_t build_polls_ = 0;  ///< calls of poll_build_deadline()

  std::vector<GStep> steps_;
  std::vector<GChart> charts_;
  /// "POU.CHART" upper-cased -> index in charts_ (first of equal names), for find_chart.
  std::unordered_map<std::string, int> chart_index_;
  /// "POU.STEP" upper-cased -> the step and how many steps of the POU have that name.
  struct StepEntry {
    int step = -1, count = 0;
  };
  std::unordered_map<std::string, StepEntry> step_index_;
  /// Upper-cased step name -> how many steps, in every POU, have it (observable names).
  std::unordered_map<std::string, int> step_name_count_;
  std::vector<GTrans> trans_;
  std::vector<GStored> stored_;
  std::vector<GForce> forces_;
  std::vector<GVar> vars_;
  std::vector<GContinuous> continuous_;
  std::vector<GInput> gin_;
  std::vector<GDelay> delays_;
  std::vector<int> enclosing_;  ///< ids of enclosing steps
  /// The bits of the step fields, and the field of each such bit (Successor::entered).
  std::vector<StateWord> step_mask_;
  std::vector<std::uint32_t> step_field_at_bit_;

  std::map<std::string, int> var_index_;      ///< upper "POU.NAME" -> vars_
  std::map<std::string, int> input_by_name_;  ///< upper "POU.NAME" -> gin_

  StateLayout layout_;
  std::vector<InputVariable> input_vars_;
  std::vector<Observable> observables_;
  std::vector<ObsInfo> obs_info_;
  std::vector<TransitionInfo> trans_info_;
  std::vector<StateWord> initial_template_;
};

}  // namespace sfcv::semantics::grafcet

// The validator's shared state (internal to sfcv_model): one Validator object checks a
// Project for model::validate (model/validate.hpp). Its checks live in one file per concept:
// validate.cpp (the driver, POUs, step and chart look-ups), validate_chart.cpp (one chart's
// structure: initial steps, reachability, parallel branches), validate_hierarchy.cpp (charts
// nested in actions, enclosing and macro-steps), validate_actions.cpp (actions, associations,
// Grafcet stored actions and forcing orders), validate_types.cpp (expression types and name
// resolution) and validate_statements.cpp (assignments and function block calls).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/budget.hpp"
#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "model/names.hpp"

namespace sfcv::model::detail {

// ------------------------------------------------------------------------------- value types

/// What an expression evaluates to. `Unknown` follows an error already reported (or an
/// unresolvable part): it is compatible with everything so that one defect gives one diagnostic.
/// `Bit` is the literal 0 or 1, which IEC 61131-3 also accepts as a BOOL literal.
enum class Ty { Bool, Int, Time, Bit, Unknown };

std::string ty_name(Ty t);
std::optional<Ty> value_type(const Type& t);
bool clash(Ty a, Ty b);
/// `Bit` read as a number.
Ty numeric(Ty t);

/// The members of the standard function blocks (IEC 61131-3 table 2.5.2.3).
struct FbMember {
  Ty type;
  bool input;
};

std::optional<FbMember> fb_member(StandardFb fb, std::string_view member);
bool all_digits(std::string_view s);
const SourceLocation& at(const SourceLocation& own, const SourceLocation& fallback);
/// `loc` for a message about an element at `here`: "12:5" in the same file, else the full form.
std::string place(const SourceLocation& loc, const SourceLocation& here);
std::string quoted(std::string_view s);

class Validator {
 public:
  Validator(const Project& project, const Budget* budget)
      : project_(project), poll_(budget, 1024) {}

  Diagnostics run();

 private:
  const Project& project_;
  const Pou* pou_ = nullptr;
  /// The charts of pou_ by upper-cased name (the first of equal names, as Pou::chart_index):
  /// 10,000 nested macro-steps must not cost 10,000 linear searches.
  std::unordered_map<std::string, int> chart_by_name_;
  Diagnostics out_;
  std::set<std::string> outside_warned_;  ///< per POU: names already reported by outside_model
  /// The run's deadline, polled per step lookup (every transition and association makes one).
  mutable BudgetPoll poll_;

  /// Step indices by upper-case name (the first declaration), built once per chart: checks look
  /// steps up per transition and association, and a linear search each time is quadratic.
  mutable std::map<const Chart*, std::unordered_map<std::string, int>> step_indices_;

  bool grafcet() const { return project_.dialect == Dialect::Grafcet; }

  int step_index(const Chart& chart, std::string_view name) const;
  bool has_step(const Chart& chart, std::string_view name) const {
    return step_index(chart, name) >= 0;
  }

  void error(const SourceLocation& where, std::string message) {
    out_.push_back({Severity::Error, where, std::move(message)});
  }
  void warning(const SourceLocation& where, std::string message) {
    out_.push_back({Severity::Warning, where, std::move(message)});
  }

  /// Elements with the same name (case-insensitive): one error at each repetition.
  template <typename T>
  void check_duplicates(const std::vector<T>& items, std::string_view what,
                        const SourceLocation& fallback) {
    std::map<std::string, const T*> first;
    for (const auto& item : items) {
      poll_.tick_or_throw("validating the model");
      if (item.name.empty()) continue;
      auto [it, fresh] = first.emplace(to_upper(item.name), &item);
      if (fresh) continue;
      const auto& here = at(item.where, fallback);
      error(here, "duplicate " + std::string(what) + " " + quoted(item.name) +
                      (it->second->where.known()
                           ? " (first declared at " + place(it->second->where, here) + ")"
                           : std::string()));
    }
  }

  // ------------------------------------------------------------------------------- one POU

  void check_pou(const Pou& pou);

  bool step_exists(std::string_view name) const;

  /// The chart an association / stored action / forcing order names. An empty chart name is
  /// accepted when exactly one chart declares the step.
  const Chart* chart_of(const std::string& chart_name, const std::string& step,
                        const SourceLocation& where, std::string_view what);

  /// Grafcet charts whose steps can be activated by something else than their initial steps:
  /// enclosed partial grafcets, macro-step expansions and targets of forcing orders.
  std::set<std::size_t> charts_activated_by_grafcet_orders() const;

  // ------------------------------------------------------------------------------ one chart

  std::string chart_label(const Chart& chart) const;

  void check_chart(const Chart& chart, bool activated_otherwise);

  void check_step_kind(const Step& s, const SourceLocation& fallback);

  void check_initial_steps(const Chart& chart, bool activated_otherwise);

  /// Steps that no sequence of transitions reaches from the initial steps, reading the chart
  /// as a Petri net without guards: a transition can fire once all its source steps can be
  /// active, whatever the guards say.
  void check_reachability(const Chart& chart);

  // ---------------------------------------------------------------- parallel structure (IEC)
  //
  // The rule. Give every step a *token context*: the path of parallel branches it lies in,
  // from the outermost to the innermost, each branch being (simultaneous divergence, index of
  // the branch). Initial steps lie in no branch: context []. A transition carries its input
  // context to its targets:
  //   - one source step: the input context is that step's context;
  //   - several source steps (a simultaneous convergence): their contexts must be P+[(d,i)] for
  //     one prefix P and one divergence d, with the indices i covering each branch of d exactly
  //     once; the input context is then P. Otherwise the convergence joins branches of
  //     different divergences, or only some branches: an error ("unreachable" SFC: it waits for
  //     a token that never comes, or leaves tokens behind);
  //   - one target step gets the input context; with several targets (a simultaneous
  //     divergence d), target i gets input+[(d,i)].
  // Contexts are assigned breadth-first from the initial steps; each step must receive the
  // same context along every transition that reaches it. A transition that gives a step a
  // shorter context jumps out of a parallel branch ("unsafe" SFC: the branch's token escapes
  // and the convergence never completes, or a second token enters a sequence); a longer one
  // jumps into a branch from outside; any other difference connects two different branches.
  // A chart that passes keeps exactly one token per active sequence: every evolution moves a
  // token within its context, splits it into all branches, or joins all of them.
  // Applied to IEC 61131-3 only: IEC 60848 defines what activating an active step means.

  struct Branch {
    int divergence;  ///< transition index
    int index;       ///< branch number, in target order
    bool operator==(const Branch&) const = default;
  };
  using Context = std::vector<Branch>;

  std::string describe(const Context& ctx, const Chart& chart, const SourceLocation& here) const;

  std::vector<int> declared_steps(const Chart& chart, const std::vector<std::string>& names);

  void check_parallel_structure(const Chart& chart);

  Context input_context(const Chart& chart, const std::vector<int>& srcs,
                        const std::vector<std::vector<int>>& targets,
                        const std::vector<std::optional<Context>>& ctx, const SourceLocation& here);

  void report_context_clash(const Chart& chart, int ti, const Step& target, const Context& known,
                            const Context& out, const SourceLocation& here);

  // -------------------------------------------------------------------------------- hierarchy

  struct Edge {
    std::size_t to;
    const SourceLocation* where;
  };

  /// Hierarchy: a chart's step activates an action whose body is a chart, encloses a partial
  /// grafcet, or is a macro-step. A cycle would nest a chart in itself without end.
  void check_hierarchy();
  void check_activation_links();

  int chart_index(std::string_view name) const;
  const Chart* find_chart(std::string_view name) const;

  int chart_index_of_step(const std::string& chart_name, const std::string& step) const;

  // ---------------------------------------------------------------------- actions, associations

  void check_action(const Action& a);

  /// A Boolean variable that an action drives: declared, BOOL, not an input.
  void check_driven_variable(const std::string& name, const SourceLocation& here,
                             const std::string& who);

  /// IEC 61131-3 inputs are read-only, but CODESYS and TwinCAT let a POU write its own
  /// VAR_INPUTs (corpus 07, 09), so for IEC charts this is a warning. A Grafcet input comes from
  /// the plant: writing it is an error.
  void write_to_input(const SourceLocation& here, const std::string& what);

  /// A qualified name whose first part the model does not declare: a global variable list,
  /// an instance of a function block type sfcv does not model, ... Its value is unknown to sfcv:
  /// one warning per name and POU, not an error, so that such charts still load.
  void outside_model(const SourceLocation& here, const std::string& full, const std::string& base);

  /// An association names an action nobody declares. `inst.ACT_x` (TwinCAT: an action of a
  /// function block instance) whose instance the model does not declare is outside the model.
  void undeclared_action(const std::string& action, const SourceLocation& here,
                         const std::string& who);

  void check_association(const ActionAssociation& as);

  // ---------------------------------------------------------------------------- Grafcet extras

  void check_stored_action(const StoredAction& sa);

  void check_forcing_order(const ForcingOrder& fo);

  // ------------------------------------------------------------------------------------ types

  void expect_bool(const ExprPtr& e, const SourceLocation& fallback, std::string_view what);

  Ty type_of(const Expr& e, const SourceLocation& fallback);

  Ty arithmetic(ExprKind kind, Ty a, Ty b, const SourceLocation& here, const std::string& op);

  Ty resolve_name(const Expr& e, const SourceLocation& here);

  Ty resolve_member(const Expr& e, const SourceLocation& here);

  /// `parts` (>= 2) looked up in `scope`; `top` when `scope` is the POU being validated (steps
  /// and actions are only visible there).
  Ty resolve_path(const std::vector<std::string>& parts, const Pou& scope, bool top,
                  const SourceLocation& here, const std::string& full);

  // ------------------------------------------------------------------------------- statements

  /// The type an assignment target accepts; nullopt when it cannot be assigned (reported).
  std::optional<Ty> assignable(const std::string& target, const SourceLocation& here);

  void check_statements(const StmtList& body, const SourceLocation& fallback);

  void check_fb_call(const Stmt& s, const SourceLocation& here);

  /// The function block type of instance path `owner` ("a" or "a.b", user FB instances from
  /// the POU being validated), or nullptr when it names none. `unknown_type`: the last part is
  /// an instance of a type this model does not hold (the compiler reports it).
  const Pou* instance_type(const std::string& owner, bool& unknown_type) const;

  /// A VAR_GLOBAL named `name` in some POU of the project (a GVL, a program): CODESYS and
  /// TwinCAT let every POU use a global without declaring it VAR_EXTERNAL.
  const Variable* project_global(std::string_view name) const;
};

}  // namespace sfcv::model::detail

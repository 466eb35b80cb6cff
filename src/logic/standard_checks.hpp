#pragma once
// The standard checks every chart should pass (run by default when no property is given):
// their names, the selection parsed from --checks, and what they need from the chart (which
// observable is which step, which steps lie on a loop). Engines evaluate them; the formulas
// they use are built here so that every engine checks the same thing.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "logic/fwd.hpp"
#include "model/chart.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::logic {

enum class StandardCheck {
  Reachable,        ///< every step can become active: EF X
  DeadTransitions,  ///< every transition fires at least once
  Reentry,          ///< AG EF X for the steps of a loop (AG AF X too under fairness)
  GlobalDeadlock,   ///< no reachable situation from which no transition can ever fire
  LocalDeadlock,    ///< seed 002: AG (X -> EF !X) & AG (!X -> EF X)
  InitialReturn,    ///< AG EF init: the initial situation stays reachable
  Conflicts,        ///< alternative transitions enabled together with no priority
  StoredActions,    ///< S and R together, S while stored, S never reset
  OutputConflicts,  ///< one output written with different values in one cycle
  OrderDependence,  ///< two admissible action orders give different next situations (1.2a)
  Instability,      ///< Grafcet: endless transient evolutions (and range errors)
};

struct StandardCheckInfo {
  StandardCheck id;
  std::string_view name;         ///< as used in --checks
  std::string_view description;  ///< one line for --help and the report
};

const std::vector<StandardCheckInfo>& standard_checks();
std::string_view to_string(StandardCheck c);

/// "all", "none" or a comma-separated list of names; nullopt with `error` set on an unknown
/// name (the message lists the valid ones).
std::optional<std::vector<StandardCheck>> parse_check_selection(std::string_view text,
                                                                std::string* error);

/// Why standard check `c` has no meaning on `ts`, or nullopt when it has one (docs/semantics.md
/// 3.6): the step checks (reachable, reentry, local-deadlock) on a system without steps, the
/// transition checks (dead-transitions, global-deadlock) on one without transitions, and
/// conflicts on IEC 61131-3 under the standard priority (`priority_resolves_conflicts`), which
/// orders every set of alternatives. A fact of the system, the same for every engine; the
/// answer is Verdict::NotApplicable, never "not checked" (which counts as unknown).
std::optional<std::string> not_applicable(StandardCheck c, const semantics::TransitionSystem& ts,
                                          bool priority_resolves_conflicts);

/// The `order:<variable>` pseudo-inputs of `ts` (docs/semantics.md 1.2a), by input index: the
/// choice of a linearisation of a partial action order. None under a total order.
std::vector<bool> order_inputs(const semantics::TransitionSystem& ts);

/// A step of the chart and the observable that shows its activity.
struct StepRef {
  std::uint32_t observable = 0;
  std::string pou, chart, step;
  std::string instance;  ///< the POU instance whose step it is ("Main.v1"; `pou` without instances)
  bool on_loop = false;  ///< the step lies on a cycle of its chart's step/transition graph
  model::SourceLocation where;
  std::string display;  ///< the observable's name ("MAIN.FILL_A", "X12")
};

/// The step observables of `ts`, matched with the chart's steps when `project` is given
/// (names "INSTANCE.STEP" for each instance of the POU the system runs, else "POU.STEP", then
/// "STEP"); steps of the system that match no chart step are kept, with on_loop unknown (false)
/// and no location.
std::vector<StepRef> step_refs(const semantics::TransitionSystem& ts,
                               const model::Project* project);

/// The instances under which `ts` runs `pou`: one per instance ("Main.v1", "Main.v2"), a
/// program under its name; none when the system does not run it; the POU under its own name
/// where the system has no instances (Grafcet). The checks that read the chart (stored
/// actions, output conflicts) judge each instance apart.
std::vector<semantics::PouInstance> instances_of(const semantics::TransitionSystem& ts,
                                                 const model::Pou& pou);

/// Where the steps of `chart` of `instance` and the actions they control are named: the unit
/// path of an SFC action run as a unit ("Main.v1.ACT_Init"), else the instance's path.
std::string chart_scope(const semantics::PouInstance& instance, const std::string& chart);

/// The activity observables of action `action` of `instance`: the instance's own and those of
/// its units' copies.
std::vector<std::uint32_t> action_observables(const semantics::TransitionSystem& ts,
                                              const semantics::PouInstance& instance,
                                              const std::string& action);

/// Step `step` of `chart` of the instance at `path` among `steps` (step_refs), or null.
const StepRef* find_step(const std::vector<StepRef>& steps, const std::string& path,
                         const std::string& chart, const std::string& step);

/// An IEC 61131-3 stored action of one instance: the steps that set it (S, SD, DS, SL) and
/// reset it (R), in the scope where its copy and stored flag live (chart_scope).
struct StoredActionSteps {
  std::string scope;
  std::string action;           ///< upper case
  std::string first_set;        ///< the first S step, with its location
  bool reset_anywhere = false;  ///< some R in the chart, whether or not its step is observable
  std::vector<const StepRef*> sets, resets;
};

/// The stored actions of `instance` of `pou`; an association whose step has no observable is
/// named in `not_checked`.
std::vector<StoredActionSteps> stored_action_steps(const model::Pou& pou,
                                                   const semantics::PouInstance& instance,
                                                   const std::vector<StepRef>& steps,
                                                   std::vector<std::string>& not_checked);

/// The state field holding the stored flag of action `action` controlled in `scope`
/// (chart_scope).
std::optional<std::uint32_t> stored_flag_field(const semantics::TransitionSystem& ts,
                                               const std::string& scope, const std::string& action);

/// Formulas of the CTL-expressible checks, over a resolved step observable.
FormulaPtr reentry_formula(const semantics::TransitionSystem& ts, std::uint32_t step);
FormulaPtr reentry_fair_formula(const semantics::TransitionSystem& ts, std::uint32_t step);
FormulaPtr local_deadlock_formula(const semantics::TransitionSystem& ts, std::uint32_t step);
/// A resolved atom for observable `index`.
FormulaPtr observable_atom(const semantics::TransitionSystem& ts, std::uint32_t index);

/// "MAIN.FILL_A (plant.st:12:3)".
std::string describe_step(const StepRef& s);

/// One action's assignments to a variable (output-conflicts): the constant it assigns when it
/// assigns one unconditionally.
struct ActionWrite {
  std::string action;
  std::optional<std::int64_t> value;
  std::string shown() const;  ///< "A (:= 1)", or "A" when the value is not a known constant
};

/// Two actions of a POU whose ST bodies both assign `variable` and are not known to assign the
/// same constant: the pairs the output-conflicts check asks about, by variable (upper case),
/// then in action order. The one list every engine's check reads. Writes made through calls
/// count as the calling action's: `ACT();` (the called action's writes), a user FUNCTION
/// called anywhere in the action (the globals it assigns; needs `project`), and a call of an
/// instance `inst(...)` or `inst.ACT(...)` (a write of `inst` itself).
struct WriteConflict {
  std::string variable;
  ActionWrite first, second;
};
std::vector<WriteConflict> write_conflicts(const model::Pou& pou,
                                           const model::Project* project = nullptr);

/// A write conflict (write_conflicts) in one instance the system runs, as the engines ask it:
/// the pairs of activity observables (of the two actions, the instance's own or its units'
/// copies) that must never be active together. `what` names it ("variable OPEN of Main.v2 is
/// written by ACT_Close (:= 0) and ACT_Latch (:= 1)"); `not_checked` says why it cannot be
/// asked when the system shows no activity for an action.
struct InstanceWriteConflict {
  std::string what;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> together;
  std::string not_checked;
};
/// Every write conflict of every POU of `project`, per instance of it that `ts` runs.
std::vector<InstanceWriteConflict> instance_write_conflicts(const semantics::TransitionSystem& ts,
                                                            const model::Project& project);

/// A Boolean variable of a Grafcet written by both continuous and stored actions, which
/// IEC 60848 gives one mode only: the layout fields of its continuous assignation and of its
/// stored value (TransitionSystem::mixed_variables). output-conflicts reports the situations where
/// the two disagree. `what` names the writers ("Y is written by continuous actions (steps 2)
/// and stored actions (step 3)").
struct MixedWriter {
  std::string variable;
  std::uint32_t assigned = 0, stored = 0;
  std::string what;
};
std::vector<MixedWriter> grafcet_mixed_writers(const semantics::TransitionSystem& ts,
                                               const model::Project& project);

/// IEC 60848 stored actions of one POU, as stored-actions judges them (docs/semantics.md
/// 3.2): per variable they write, `never_reset` when every one stores the constant 1 (a
/// finding of the chart itself), and the pairs on activation that store different values (a
/// finding where one evolution activates both steps).
struct GrafcetStoredVariable {
  std::string variable;  ///< as the first action writes it
  const model::StoredAction* first = nullptr;
  bool never_reset = false;
  std::vector<std::pair<const model::StoredAction*, const model::StoredAction*>> different;
};
std::vector<GrafcetStoredVariable> grafcet_stored_variables(const model::Pou& pou);

/// The chart transition behind each transition of `ts`, matched by location (or name); empty
/// when some transition cannot be matched.
std::vector<const model::Transition*> chart_transitions(const semantics::TransitionSystem& ts,
                                                        const model::Project& project);

/// Grafcet conflicts (IEC 60848 clears every clearable transition at once): per transition of
/// `ts`, its upstream steps, qualified by chart ("G1.S2"); empty when the transitions cannot
/// be matched with the chart's (chart_transitions). Two transitions conflict when they share
/// one and are cleared by one evolution.
std::vector<std::vector<std::string>> grafcet_upstream_steps(const semantics::TransitionSystem& ts,
                                                             const model::Project& project);

/// The upstream steps `a` and `b` (grafcet_upstream_steps) have in common.
std::vector<std::string> common_steps(const std::vector<std::string>& a,
                                      const std::vector<std::string>& b);

}  // namespace sfcv::logic

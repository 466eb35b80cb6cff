#pragma once
// Results of model checking as data (like Storm's CheckResult): a verdict per property, with a
// counterexample or witness; renderers live in src/report.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "logic/big_count.hpp"
#include "logic/trace.hpp"
#include "model/source_location.hpp"

namespace sfcv::logic {

enum class Verdict {
  Holds,
  Violated,
  Unknown,     ///< a limit stopped exploration before the answer was certain
  NotChecked,  ///< a question this engine cannot evaluate (never "holds"; counts as unknown)
  /// A standard check that has no meaning on this system (no steps, no transitions, conflicts
  /// resolved by the standard priority; logic::not_applicable): neither holds nor unknown.
  NotApplicable,
};
std::string_view to_string(Verdict v);

/// What an engine decided of one target of a check judged target by target (reachable: a
/// step; dead-transitions: a transition): no defect (reached, fired), a defect proved (never
/// active, never fires), or nothing yet.
enum class TargetAnswer : std::uint8_t { Undecided, Clear, Defect };

struct PropertyResult {
  std::string name;           ///< property name, or the standard check's name
  std::string formula;        ///< CTL text; empty for checks that are not one formula
  std::string description;    ///< a pattern's requirement in English; empty otherwise
  std::string justification;  ///< a requirement file's justification; empty otherwise
  std::string check;          ///< standard check id ("reachable", ...); empty for user properties
  Verdict verdict = Verdict::Unknown;
  std::string message;                ///< one readable line (why unknown, what was found)
  std::vector<std::string> findings;  ///< standard checks: one located line per defect
  /// Every finding the check made; more than findings.size() when CheckTask::max_findings cut them.
  std::size_t findings_total = 0;
  /// reachable and dead-transitions: each target's answer, one per step of logic::step_refs or
  /// per transition of the system in its order, so that --engine auto can join what different
  /// engines decided (a step the explicit probe reached, another that BMC reached deeper);
  /// empty when the engine does not say.
  std::vector<TargetAnswer> target_answers;
  std::optional<Trace> trace;  ///< counterexample (Violated) or witness (Holds)
  /// SAT engines: the re-checked proof of a Holds (an inductive invariant as readable clauses
  /// over latch names, or a k-induction depth); empty otherwise.
  std::string certificate;
  /// AG (a -> f) that holds: whether `a` is never reachable (logic/vacuity.hpp), and the
  /// answer to the witness question EF a in one line; unset for other properties.
  std::optional<bool> vacuous;
  std::string vacuity;
  double seconds = 0;
  model::SourceLocation where;  ///< where the property was written
  /// --engine auto: the engine whose answer this is ("explicit", "bdd", "ic3"); empty when the
  /// report's own engine answered.
  std::string decided_by;
};

/// What the reachable state space visits (--coverage, explicit engine): steps active in some
/// reachable state, transitions fired on some edge, actions active in some reachable state.
struct Coverage {
  std::uint32_t steps = 0, steps_visited = 0;
  std::uint32_t transitions = 0, transitions_fired = 0;
  std::uint32_t actions = 0, actions_active = 0;
  std::vector<std::string> unvisited;  ///< "step MAIN.S3", "transition MAIN: S1 -> S2", "action A"
};

struct CheckReport {
  std::string engine;  ///< "explicit", "bdd"
  BigCount states;     ///< exact, also beyond 2^64 (symbolic engines)
  BigCount edges;
  bool states_known = true;  ///< false: the engine did not count states (SAT engines)
  bool edges_known = true;   ///< false: the engine did not count edges (reports leave them out)
  std::uint32_t depth = 0;   ///< BFS depth reached (the rings computed, less one)
  /// Every property was an invariant and each met a bad state before the reachable set was
  /// complete (bdd engine): states, edges and depth count the rings explored, edges unknown.
  bool stopped_early = false;
  bool complete = true;  ///< false when a limit stopped exploration
  std::string limit;     ///< "states", "time", "memory" when !complete
  double seconds = 0;    ///< exploration plus checking
  std::vector<PropertyResult> results;
  std::optional<Coverage> coverage;  ///< when asked for (CheckTask::coverage) and computed
};

/// The exit code of a check (README): 1 when some answer is Violated, else 3 when some answer is
/// Unknown or NotChecked (a question nobody decided is not a pass), else 0. NotApplicable
/// answers do not count: 0 means every question that has a meaning was decided and holds.
int exit_code(const CheckReport& r);

/// Whether no answer of `r` was decided by its engine although some question was asked and had
/// a meaning: every answer is NotChecked or NotApplicable, at least one NotChecked (the CLI
/// calls it a usage error: the engine cannot answer what was asked).
bool nothing_decided(const CheckReport& r);

}  // namespace sfcv::logic

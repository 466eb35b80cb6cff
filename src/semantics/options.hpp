#pragma once
// Options of the two semantics, as plain values filled in by the CLI (like mCRL2's
// explorer_options); the library reads no global state.

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/expr.hpp"
#include "model/source_location.hpp"

namespace sfcv::semantics {

/// How conflicting alternative transitions (a step with several enabled outgoing transitions)
/// are resolved.
enum class PriorityMode {
  Standard,  ///< explicit priority, then document order ("left to right"): only the first fires
  None,      ///< no order: each enabled alternative may fire (nondeterminism exposes conflicts)
};

enum class TimeMode {
  Abstract,  ///< a running timer may expire at any later cycle (sound over-approximation)
  Discrete,  ///< exact cycle counters with the given cycle time
};

/// Variables that the run reads and no POU of the run writes (docs/semantics.md 1.8).
enum class UnwrittenMode {
  Free,  ///< inputs: any value of their type each cycle (sound for "holds")
  Keep,  ///< held at their initial values (the reading before issue 53)
};

/// The order in which active actions execute within a cycle: seed 000's partial order on
/// actions (docs/semantics.md §1.2a). Declaration and Alphabetical are total orders; Partial is
/// the user's pairs (Iec61131Options::action_pairs, declaration order between the rest);
/// Unordered is the empty order. Under a partial order, actions that write a common variable
/// and that the order leaves unordered run in any order consistent with it, each cycle.
/// Vendor is CODESYS's and TwinCAT's (docs/semantics.md 1.4a): step actions (exit, entry, main,
/// by step), then the IEC actions alphabetically.
enum class ActionOrder { Declaration, Alphabetical, Partial, Unordered, Vendor };

/// Whose reading of the constructs where vendors differ from IEC 61131-3 (docs/semantics.md
/// 1.4a). Codesys and Twincat give every IEC action a final call in the cycle after it stops
/// being active; Iec, Siemens (S7-GRAPH) and Rockwell (SFCLastScan DontScan) give none.
enum class VendorDialect { Iec, Codesys, Twincat, Siemens, Rockwell };

/// One pair `before < after` of a user's action order (`--action-order FILE`), where it is
/// written (errors name it). Names are an action's ("Fill") or its full name ("Main.Fill").
struct ActionPair {
  std::string before, after;
  model::SourceLocation where;
};

struct Iec61131Options {
  PriorityMode priority = PriorityMode::Standard;
  TimeMode time = TimeMode::Abstract;
  std::int64_t cycle_ms = 10;  ///< TimeMode::Discrete only
  ActionOrder action_order = ActionOrder::Declaration;
  VendorDialect dialect = VendorDialect::Iec;
  std::vector<ActionPair> action_pairs;  ///< ActionOrder::Partial
  UnwrittenMode unwritten = UnwrittenMode::Free;
  /// POUs run one after the other in each cycle (a controller and plant models); empty = the
  /// single POU with an SFC body (PROGRAMs preferred), several candidates being an error.
  std::vector<std::string> pous;
  std::vector<model::ExprPtr> assumptions;  ///< constraints on inputs and state
  /// The run's deadline (model::Budget): compiling a chart of a million steps takes seconds,
  /// so the compiler polls it and throws LimitReached(Time).
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

struct GrafcetOptions {
  bool single_input_change = true;  ///< IEC 60848's hypothesis; false = --multi-input-change
  std::vector<model::ExprPtr> assumptions;
  std::size_t max_transient_steps = 10000;  ///< bound on one transient evolution's length
  /// The run's deadline (model::Budget): a transient evolution past it throws
  /// LimitReached(Time) (one evolution may take seconds on a long chain).
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

}  // namespace sfcv::semantics

#pragma once
// The IEC 61131-3 scan-cycle semantics (docs/semantics.md, Part 1) as a TransitionSystem.
//
// A state is the configuration after a cycle: ready steps, active and stored actions, variables,
// timer and function-block memory. The system is deterministic per input valuation: every
// nondeterministic choice of the semantics is an explicit pseudo-input (InputVariable::pseudo):
//   timeout:<timer>  Bool, abstract time: a running timer expires in this cycle;
//   elapse:<step>    Int,  abstract time: the region a step's .T moves to (see the docs);
//   choice:<step>    Int,  PriorityMode::None: which of the enabled alternatives leaving <step>
//                          fires (0 = the first enabled in document order; values beyond the
//                          last enabled one select the last).
// So the successor conditions partition the input valuations (minus those the assumptions
// exclude and those that raise an Anomaly).

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "model/errors.hpp"
#include "semantics/options.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics {

/// Thrown by successors() when an integer input must be enumerated value by value (it is copied
/// into the state or used in arithmetic) and its remaining range has more than
/// kMaxEnumeratedValues values: the engine reports it instead of hanging.
/// A LimitReached (Limit::Enumeration): the explicit engine answers unknown, or --engine auto
/// switches to the bdd engine.
class SemanticsLimitError : public LimitReached {
 public:
  explicit SemanticsLimitError(const std::string& message)
      : LimitReached(Limit::Enumeration, message) {}
};

inline constexpr std::int64_t kMaxEnumeratedValues = 4096;

/// A variable that the run reads and that no POU of the run writes (no assignment, output
/// binding, action variable, VAR_IN_OUT binding), neither CONSTANT nor a located output (%Q) nor
/// a duration: an input free each cycle under UnwrittenMode::Free, its initial value under Keep
/// (docs/semantics.md 1.8).
struct UnwrittenVariable {
  std::string name;  ///< "Main.B1", "Main.Crane.x" (an instance's), "GVL.x" (a global)
  model::Type type;
  model::SourceLocation declared;
  std::string read_in;  ///< the program, instance or function that reads it first
  model::SourceLocation read_at;
  bool free = true;  ///< read as an input (UnwrittenMode::Free)
};

/// The unwritten variables of a system made by make_iec61131_system (empty for any other).
std::vector<UnwrittenVariable> unwritten_variables(const TransitionSystem& system);

/// The one note that lists them (at most `shown` by name): empty when there are none.
std::string unwritten_note(const std::vector<UnwrittenVariable>& list, std::size_t shown = 6);

/// The dialect of the vendor whose tool wrote the project's file (model::vendor_of), Iec for
/// any other tool's.
VendorDialect file_dialect(const model::Project& project);

/// "iec", "codesys", "twincat", "siemens", "rockwell".
std::string_view to_string(VendorDialect dialect);
/// The dialect of one of those names (any case); nullopt for anything else.
std::optional<VendorDialect> parse_vendor_dialect(std::string_view text);

/// Reads the IEC 61131-3 constructs as `dialect` does: sets options.dialect, and for CODESYS and
/// TwinCAT the vendor's action order (ActionOrder::Vendor) in place of the declaration order.
void set_dialect(Iec61131Options& options, VendorDialect dialect);

/// Builds the scan-cycle semantics of the POUs `options.pous` of `project` (all run in one cycle,
/// in the given order). With `options.pous` empty: the single POU with an SFC body (PROGRAMs
/// preferred). Returns null, with Error diagnostics saying what and where, for anything the
/// semantics cannot model faithfully.
///
/// Not thread-safe: successors() uses scratch memory of the instance; use one instance per
/// thread.
TransitionSystemPtr make_iec61131_system(const model::Project& project,
                                         const Iec61131Options& options,
                                         model::Diagnostics& diagnostics);

}  // namespace sfcv::semantics

#pragma once
// Regression verification (`sfcv equiv OLD NEW`, docs/equivalence.md): two IEC 61131-3 projects
// composed into ONE project that every engine and export decides unchanged.
//
// The product runs, in each scan cycle, OLD's programs (renamed `Old_<name>`), then NEW's
// (`New_<name>`), then an observer program (`Equiv_Observer`) that sets one Boolean
// `differs_<signal>` per compared signal. The two sides read the same inputs: their VAR_INPUTs
// and the program variables that no POU of their run writes (free inputs, docs/semantics.md 1.8)
// become VAR_INPUTs of one name, and the scan cycle makes inputs of one name one input. The
// programs are equivalent iff `AG !differs_<s>` holds for every compared signal s.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "model/chart.hpp"
#include "semantics/options.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics {

inline constexpr const char* kEquivOldPrefix = "Old_";
inline constexpr const char* kEquivNewPrefix = "New_";
inline constexpr const char* kEquivObserver = "Equiv_Observer";

struct EquivalenceOptions {
  /// `--map old=new`: NEW's variable `new` is OLD's `old` (an input both read, or a compared
  /// signal); NEW's program variable is renamed to `old` in the product.
  using Map = std::vector<std::pair<std::string, std::string>>;
  Map map;
  /// `--outputs`: the signals compared; empty = every VAR_OUTPUT (and %Q variable) of OLD's
  /// programs that NEW's programs declare too.
  std::vector<std::string> outputs;
  std::vector<std::string> compare;  ///< `--compare`: internal variables compared as well
  std::vector<std::string> ignore;   ///< `--ignore`: signals left out
  /// `--within N`: at the end of every cycle t, NEW's value equals OLD's value at one of the
  /// cycles t, t-1, ..., t-N (before cycle 0: OLD's initial value).
  std::uint32_t within = 0;
  /// The semantics of each side (priority, time, unwritten, assumptions); `pous` must be empty.
  Iec61131Options semantics;
};

/// One compared signal and the names it has in the product.
struct ComparedSignal {
  std::string name;      ///< as OLD names it ("q")
  std::string new_name;  ///< as NEW names it (differs with --map)
  std::string old_ref;   ///< the product variable: "Old_Main.q"
  std::string new_ref;   ///< "New_Main.q"
  std::string differs;   ///< the observer's flag: "Equiv_Observer.differs_q"
  /// The observer's copies of the two values at the end of the cycle ("Equiv_Observer.old_q"):
  /// fields of the state even where a side never writes the signal (a free value), for traces.
  std::string old_seen, new_seen;
  model::Type type;       ///< OLD's
  model::Type new_type;   ///< NEW's (an integer's range may differ)
  bool internal = false;  ///< named by --compare (not an output)
};

struct EquivalenceProduct {
  model::Project project;
  Iec61131Options options;  ///< `pous`: OLD's programs, NEW's programs, the observer
  std::vector<std::string> old_programs, new_programs;  ///< their names in the product
  std::vector<ComparedSignal> compared;
  std::vector<std::string> shared_inputs;  ///< inputs both sides read (by OLD's names)
  std::vector<std::string> notes;          ///< what the reader should know (not compared, ...)
};

/// Builds the product. Throws UnsupportedConstruct for a Grafcet side or globals both declare,
/// InputError for a side the semantics cannot run, an input of different types on the two
/// sides, a compared signal missing or of different types; UsageError for bad options or nothing
/// to compare.
EquivalenceProduct make_equivalence_product(const model::Project& old_project,
                                            const model::Project& new_project,
                                            const EquivalenceOptions& options);

/// The note for a product that reads abstract time (`timeout:` or `elapse:` pseudo-inputs): each
/// side's timers expire independently, so a difference may come from time alone; empty when
/// the product has none.
std::string abstract_time_note(const TransitionSystem& product);

}  // namespace sfcv::semantics

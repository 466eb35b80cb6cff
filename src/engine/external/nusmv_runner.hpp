#pragma once
// `sfcv check --engine nusmv`: the NuSMV export of the properties, run by a NuSMV found on
// PATH (NuSMV is not packaged in Debian). NuSMV exits 0 whatever the verdict: the verdicts come
// from its `-- specification ... is true/false` and `-- invariant ... is true/false` lines.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/model_checker.hpp"

namespace sfcv::engine {

std::optional<std::string> find_nusmv();

/// The NuSMV commands the engine runs (`NuSMV -source FILE model.smv`): properties in file
/// order (NuSMV 2.6 orders them by cone of influence by default), CTL before invariants.
extern const char* const kNusmvCommands;

/// A trace NuSMV printed after a verdict line (`-> State: 1.k <-` / `-> Input: 1.k <-` blocks).
struct NusmvTrace {
  std::size_t states = 0;  ///< `-> State:` blocks
  /// Per `-> Input:` block (the inputs of the cycle into the next state): the value of every
  /// input identifier printed so far (NuSMV prints only the values that changed).
  std::vector<std::map<std::string, bool>> inputs;
  std::optional<std::size_t> loop_start;  ///< state index after `-- Loop starts here`
};

struct NusmvVerdicts {
  std::vector<bool> ctl;         ///< per `-- specification` line, in output order (CTLSPEC)
  std::vector<bool> invariants;  ///< per `-- invariant` line, in output order (INVARSPEC)
  std::vector<std::optional<NusmvTrace>> ctl_traces;        ///< parallel to ctl
  std::vector<std::optional<NusmvTrace>> invariant_traces;  ///< parallel to invariants
  /// NuSMV's error lines (`file model.smv: line 3: ...`, `ERROR: ...`), when it reported any.
  std::vector<std::string> errors;
};

/// Reads the verdict lines of NuSMV's output, each with the trace printed after it.
NusmvVerdicts parse_nusmv_output(const std::string& text);

/// An engine that exports the task's properties to NuSMV and runs `nusmv` (an absolute path)
/// on them. NuSMV's counterexamples are replayed through the chart (semantics::simulate) into
/// sfcv traces. IEC 61131-3 systems only; no fairness and no standard checks.
ModelCheckerPtr make_nusmv_model_checker(std::string nusmv);

}  // namespace sfcv::engine

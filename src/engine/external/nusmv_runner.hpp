#pragma once
// `sfcv check --engine nusmv`: the NuSMV export of the properties, run by a NuSMV found on
// PATH (NuSMV is not packaged in Debian). NuSMV exits 0 whatever the verdict: the verdicts come
// from its `-- specification ... is true/false` and `-- invariant ... is true/false` lines.

#include <optional>
#include <string>
#include <vector>

#include "engine/model_checker.hpp"

namespace sfcv::engine {

std::optional<std::string> find_nusmv();

struct NusmvVerdicts {
  std::vector<bool> ctl;         ///< per `-- specification` line, in file order (CTLSPEC)
  std::vector<bool> invariants;  ///< per `-- invariant` line, in file order (INVARSPEC)
};

/// Reads the verdict lines of NuSMV's output (traces and other lines are skipped).
NusmvVerdicts parse_nusmv_output(const std::string& text);

/// An engine that exports the task's properties to NuSMV and runs `nusmv` (an absolute path)
/// on them. Verdicts only: NuSMV's traces are not mapped back. IEC 61131-3 systems only; no
/// fairness and no standard checks.
ModelCheckerPtr make_nusmv_model_checker(std::string nusmv);

}  // namespace sfcv::engine

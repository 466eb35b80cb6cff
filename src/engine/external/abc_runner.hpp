#pragma once
// Confirmation by ABC (Debian package berkeley-abc): one invariant property at a time, on the
// binary AIGER export. ABC's exit code is always 0, so the verdict comes from its status lines.

#include <optional>
#include <string>
#include <vector>

#include "semantics/aig.hpp"

namespace sfcv::engine {

struct AbcVerdict {
  enum class Kind { Holds, Violated, Unknown } kind = Kind::Unknown;
  /// Violated: the input values per frame, frames[k][i] for AIGER input i (ABC's own order).
  std::vector<std::vector<bool>> frames;
  std::string log;  ///< ABC's output, for diagnostics
};

/// The ABC executable ("berkeley-abc" or "abc" on PATH).
std::optional<std::string> find_abc();

/// Checks bad-state property `bad_index` of `aig` with ABC's `command` ("pdr", "bmc3 -F 50",
/// "dprove"): writes an Aig with that single property, runs ABC, reads the verdict and, when it
/// is violated, the counterexample from `write_cex -n`. Throws std::invalid_argument when the
/// Aig has constraints (ABC would misread them; encode them as a validity latch).
AbcVerdict check_with_abc(const std::string& abc, const semantics::Aig& aig, std::size_t bad_index,
                          const std::string& command = "pdr", double timeout_seconds = 60);

}  // namespace sfcv::engine

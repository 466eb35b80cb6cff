#pragma once
// Confirmation by Spin (Debian package spin): the Promela export of one invariant, compiled to
// a pan verifier with the C compiler, run exhaustively; a violation's trail is replayed to read
// the inputs of each cycle back.

#include <optional>
#include <string>
#include <vector>

#include "engine/external/circuit_export.hpp"

namespace sfcv::engine {

struct SpinVerdict {
  enum class Kind { Holds, Violated, Unknown } kind = Kind::Unknown;
  /// Violated: the input values per cycle, frames[k][i] for circuit input i.
  std::vector<std::vector<bool>> frames;
  std::string log;
};

std::optional<std::string> find_spin();

/// Checks invariant `bad_index` of `model` with Spin; `cc` is the C compiler (found on PATH
/// when empty).
SpinVerdict check_with_spin(const std::string& spin, const CircuitExport& model,
                            std::size_t bad_index, double timeout_seconds = 120,
                            std::string cc = {});

}  // namespace sfcv::engine

#pragma once
// Writes an Aig in the AIGER 1.9 format: binary `.aig` (what Debian's ABC reads; it rejects
// ASCII) or ASCII `.aag` for people. Invariant properties become bad-state literals (B section),
// assumptions invariant constraints (C section).

#include <ostream>
#include <string>

#include "semantics/aig.hpp"

namespace sfcv::engine {

enum class AigerMode { Binary, Ascii };

/// Writes `aig` with a symbol table and `comment` (one or more lines) in the comment section.
/// Precondition (asserted): the Aig has at least one input, since ABC's `int` and `dprove` crash
/// on designs without one; callers add a dummy input when the system has none.
void write_aiger(std::ostream& out, const semantics::Aig& aig, AigerMode mode,
                 const std::string& comment = {});

}  // namespace sfcv::engine

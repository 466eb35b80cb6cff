#pragma once
// Writes an Aig in the AIGER 1.9 format: binary `.aig` (what Debian's ABC reads; it rejects
// ASCII) or ASCII `.aag` for people. Invariant properties become bad-state literals (B section),
// assumptions invariant constraints (C section).

#include <ostream>
#include <string>
#include <vector>

#include "semantics/aig.hpp"

namespace sfcv::engine {

enum class AigerMode { Binary, Ascii };

/// A name as the symbol table writes it: printable ASCII on one line (comment_text() of
/// identifiers.hpp, and bytes >= 0x80 as \xNN), so a name can neither start a new symbol
/// line nor end the table; reversible, so distinct names stay distinct. ABC's counterexample
/// names inputs this way (abc_runner.cpp).
std::string aiger_symbol(const std::string& name);

/// The symbol table's names, section by section: aiger_symbol() of each name, and where two
/// entries of the table would read alike (a TwinCAT Boolean action and the variable it drives,
/// an input and the variable that keeps it) the later one gets `#2`, `#3`: ABC refuses a file
/// whose inputs and latches repeat a name, and a name must say which bit it is.
struct AigerSymbols {
  std::vector<std::string> inputs, latches, outputs, bad, constraints;
};
AigerSymbols aiger_symbols(const semantics::Aig& aig);

/// Writes `aig` with a symbol table and `comment` (one or more lines) in the comment section.
/// Precondition (asserted): the Aig has at least one input, since ABC's `int` and `dprove` crash
/// on designs without one; callers add a dummy input when the system has none.
/// With `positional_names`, the symbol table says only `i<k> in<k>`, `l<k> la<k>` and so on:
/// what is given to ABC, whose counterexamples then name no chart name at all.
void write_aiger(std::ostream& out, const semantics::Aig& aig, AigerMode mode,
                 const std::string& comment = {}, bool positional_names = false);

}  // namespace sfcv::engine

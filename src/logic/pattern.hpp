#pragma once
// Requirement patterns: a template filled with propositional arguments, translated to the CTL
// the engines decide and rendered back as an English sentence.
//
//   implies(estop, !M)                      -- PLCverif-style cycle templates
//   response(start, V1, within 5 cycles)    -- bounded response (cycles, or time with a cycle time)
//   absence(V1 & V3, between s1 and s9)     -- Dwyer's patterns with a scope: globally,
//                                              before R, after Q, between Q and R, after Q until R
//
// The catalogue, each pattern's English and formula: docs/properties.md.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "logic/fwd.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::logic {

/// One entry of the catalogue, for listings and documentation.
struct PatternInfo {
  std::string_view name;
  std::string_view arguments;  ///< as written: "A, B"
  std::string_view english;    ///< with the arguments' letters in braces: "{A} is never true"
  std::string_view formula;    ///< the CTL, over the same letters
  bool scoped = false;         ///< takes an optional scope (Dwyer's patterns)
  bool bounded = false;        ///< takes an optional bound (`within N cycles`)
};

/// Every pattern, cycle templates first, then Dwyer's.
const std::vector<PatternInfo>& pattern_catalogue();

struct PatternOptions {
  /// The length of a cycle in ms when time is discrete (`--time discrete --cycle`); without
  /// it a bound in time (`within 2 s`) is an error.
  std::optional<std::int64_t> cycle_ms;
};

struct ParsedPattern {
  FormulaPtr formula;   ///< the CTL; null when there were errors
  std::string english;  ///< the requirement as a sentence
  model::Diagnostics diagnostics;
  bool ok() const { return formula != nullptr; }
};

/// Parses and translates one pattern. `source` names it in diagnostics; `line` and `column` say
/// where `text` starts in it (a spec file), so that every location points into that source.
ParsedPattern parse_pattern(std::string_view text, std::string source,
                            const PatternOptions& options = {}, int line = 1, int column = 1);

}  // namespace sfcv::logic

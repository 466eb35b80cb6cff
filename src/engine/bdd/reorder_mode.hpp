#pragma once
// How the BDD engine changes its variable order (`--reorder none|once|dynamic`).

#include <optional>
#include <string_view>

namespace sfcv::engine {

enum class ReorderMode {
  None,  ///< the static (FORCE) order throughout
  Once,  ///< one sifting pass, right after the transition relation is built
  /// Sifting when the BDDs blow up: first when a system's construction leaves
  /// kFirstReorderNodes live nodes or, once an IEC 61131-3 system is built, when an image's
  /// intermediate products dwarf its operand and result (below); then whenever the live nodes
  /// doubled since the last pass (BuDDy's rule, as NuSMV's -dynamic). A small chart never sifts.
  Dynamic,
};

/// Passes Dynamic does at most (NuSMV's -dynamic has no cap; a cap keeps a model whose BDDs
/// grow without bound from sifting forever).
inline constexpr int kMaxAutomaticReorderings = 12;
/// Dynamic, while a system is built: the first pass when a garbage collection leaves this
/// many live nodes (a relation whose conjuncts blow up under the static order: the counter
/// with reset of docs/benchmarks.md holds 68 000 nodes before its first pass, 1 000 after).
inline constexpr int kFirstReorderNodes = 1 << 16;
/// Dynamic, once an IEC 61131-3 system is built: the first pass when an image or pre-image
/// blows up (an intermediate product of at least kBlowupNodes nodes and kBlowupRatio times
/// its operand and its result), or, within one huge operation, when a collection leaves
/// kLateReorderNodes live nodes. The live nodes alone are no sign: a counter's thousands of
/// rings fill the table with small BDDs that sifting does not shrink, and random charts'
/// sets take about a node per state in any order (sifting cost them 10 times the rest).
inline constexpr int kBlowupNodes = 1 << 14;
inline constexpr int kBlowupRatio = 8;
inline constexpr int kLateReorderNodes = 1 << 20;
/// Dynamic stops after a pass that shrank the live nodes by less than this many percent.
inline constexpr int kMinReorderGainPercent = 10;

inline std::optional<ReorderMode> parse_reorder_mode(std::string_view text) {
  if (text == "none") return ReorderMode::None;
  if (text == "once") return ReorderMode::Once;
  if (text == "dynamic") return ReorderMode::Dynamic;
  return std::nullopt;
}

inline std::string_view to_string(ReorderMode mode) {
  switch (mode) {
    case ReorderMode::None:
      return "none";
    case ReorderMode::Once:
      return "once";
    case ReorderMode::Dynamic:
      return "dynamic";
  }
  return "none";
}

}  // namespace sfcv::engine
